//! The world behind the C API: the world named by `VEHICLE_WORLD`, the simulation clock, the
//! world's other cars running their programmes, the run's outputs, and the controllers that
//! drive its car(s) ([`Controller`]: per controller, the body, libraries, devices, buffers).
//!
//! A C, C++, Java or Python controller is the process's one controller, on the car chosen as
//! Webots' world would run it (the only car, or the one without a programme). A front-end
//! that serves several cars (the ROS node) adds one controller per car with [`Robot::select`]
//! (the project's extension, [`crate::controllers`]); every entry point then acts on the
//! current controller, and a step advances the one world once.

use std::env::{self, VarError};
use std::ffi::c_int;
use std::path::PathBuf;

use sim::traffic::{Traffic, TrafficNote, driven_car, refuse_cycles};
use sim::world_file::{self, WorldDescription};
use sim::{SimError, Simulation, VehicleId};

use crate::abi::WbDeviceTag;
pub(crate) use crate::controller::{Body, Controller, Libraries};
use crate::controllers::WorldCar;
use crate::devices::DeviceEntry;

/// The environment variable that selects the world: a world file path or a shipped model name.
pub const WORLD_VARIABLE: &str = "VEHICLE_WORLD";

/// The environment variable naming the directory a controller run writes its outputs into
/// (`telemetry.csv`, `metrics.json`, `replay.glb`), when the run ends or at cleanup.
pub const OUTPUT_VARIABLE: &str = "VEHICLE_OUT";

/// The name of a controller's run in its outputs (the `scenario` column of `telemetry.csv`).
pub const CONTROLLER_RUN: &str = "controller";

/// The world a process's controllers talk to (Webots: the simulation behind their
/// connections), with its controllers.
pub(crate) struct Robot {
    /// The world and, for each car, its `vehicle_model::Driver`; it owns the `duration`, the
    /// failure state and the recording.
    pub(crate) simulation: Simulation,
    /// Where the world came from, and its warnings, for `metrics.json`.
    source: String,
    warnings: Vec<String>,
    /// The world's cars in file order (name, whether it has a programme).
    cars: Vec<WorldCar>,
    /// `VEHICLE_OUT`: where the run's outputs go, until they are written.
    outputs: Option<PathBuf>,
    /// The controllers, never empty; the first is the one the world was loaded for.
    controllers: Vec<Controller>,
    /// The index in `controllers` of the one the entry points act on.
    current: usize,
    /// The world's cars no controller drives, each running its programme.
    others: Traffic,
}

/// The world description `VEHICLE_WORLD` names (unset or empty: the default world, a BmwX5).
///
/// # Errors
/// Every error of a world file, one line each in file order, each naming the file, line, key
/// and value.
pub(crate) fn description_from_environment() -> Result<WorldDescription, String> {
    match env::var(WORLD_VARIABLE) {
        Ok(spec) if !spec.is_empty() => world_file::load_all(&spec).map_err(|all| {
            // Every error of the file in file order, one line each, so that one run shows
            // them all.
            all.errors
                .iter()
                .map(|e| format!("cannot load the world {WORLD_VARIABLE}={spec}: {e}"))
                .collect::<Vec<_>>()
                .join("\n")
        }),
        Err(VarError::NotUnicode(raw)) => Err(format!(
            "cannot load the world {WORLD_VARIABLE}={}: not valid UTF-8",
            raw.to_string_lossy()
        )),
        Ok(_) | Err(VarError::NotPresent) => Ok(world_file::default_world()),
    }
}

impl Robot {
    /// Loads the world named by `VEHICLE_WORLD` (unset or empty: the default world, a BmwX5)
    /// and prints its warnings (fields replaced by their defaults) on stderr. Its controller
    /// drives the car named `car`, or with `None` the car (or robot) Webots' rule gives: the
    /// robot, the only car, or of several cars the one without a programme. With
    /// `VEHICLE_OUT` set, the run is recorded for its outputs.
    ///
    /// # Errors
    /// What is wrong with the world: every error of a world file, one line each in file order,
    /// each naming the file, line, key and value; a `car` the world does not have.
    pub(crate) fn from_environment(car: Option<&str>) -> Result<Robot, String> {
        let description = description_from_environment()?;
        for w in &description.warnings {
            eprintln!("Warning: {w}");
        }
        let outputs = env::var_os(OUTPUT_VARIABLE)
            .filter(|dir| !dir.is_empty())
            .map(PathBuf::from);
        Robot::build(&description, outputs, car)
    }

    /// Builds the world of `description` with the controller of car `car` (see
    /// [`Robot::from_environment`]); the other cars run their programmes. Records the run if
    /// `outputs` names a directory.
    fn build(
        description: &WorldDescription,
        outputs: Option<PathBuf>,
        car: Option<&str>,
    ) -> Result<Robot, String> {
        let cars = &description.cars;
        // A car chosen by name skips `driven_car`, which refuses drive cycles: refuse them
        // here for every choice.
        refuse_cycles(description)?;
        let cars_list = crate::controllers::world_cars(description);
        // A robot alone is driven; otherwise the named car or the one the traffic rule leaves
        // free.
        let driven = match car {
            Some(name) => car_index(&cars_list, name, &description.source)?,
            None if cars.is_empty() && description.robot.is_some() => 0,
            None => driven_car(description)?,
        };
        let (mut simulation, reports) = Simulation::from_description(description)
            .map_err(|e| format!("cannot build the world {}: {e}", description.source))?;
        // A controller's devices start disabled, as in Webots: the world's `samplingPeriod`
        // keys are for runs without a controller.
        simulation.disable_devices();
        // The loader validated the fields already; anything left is still reported.
        for w in reports.iter().flatten() {
            eprintln!("Warning: {}: {w}", description.source);
        }
        // Nothing the world says is dropped silently: the driven vehicle's programme is
        // vehicle-sim's to run.
        let driven_programme = match cars_list.get(driven) {
            Some(car) => car.programmed,
            None => description
                .robot
                .as_ref()
                .is_some_and(|r| !r.programme.is_empty()),
        };
        if driven_programme {
            eprintln!(
                "Warning: {}: the world's programme is not run: the controller drives (vehicle-sim \
                 runs programmes).",
                description.source
            );
        }
        let ids: Vec<VehicleId> = simulation.car_ids().collect();
        let others = Traffic::new(description, &ids, driven);
        let body = match (ids.get(driven).copied(), simulation.robot_ids().next()) {
            (Some(id), _) => Body::Car {
                id,
                libraries: Libraries::None,
            },
            (None, Some(id)) => Body::DifferentialWheels(id),
            (None, None) => {
                return Err(format!("the world {} holds no vehicle", description.source));
            }
        };
        if outputs.is_some() {
            simulation.record(CONTROLLER_RUN);
        }
        let controller = Controller::new(&simulation, body)?;
        Ok(Robot {
            simulation,
            source: description.source.clone(),
            warnings: description
                .warnings
                .iter()
                .map(ToString::to_string)
                .collect(),
            cars: cars_list,
            outputs,
            controllers: vec![controller],
            current: 0,
            others,
        })
    }

    /// The world's cars in file order.
    pub(crate) fn cars(&self) -> &[WorldCar] {
        &self.cars
    }

    /// Makes the controller of the car named `name` the current one, adding it (no library
    /// initialised, its devices disabled) if the process has none for that car yet. A car
    /// that ran its programme stops running it, with a warning as at load: the controller
    /// drives it now.
    ///
    /// # Errors
    /// A name no car of the world has (the message lists the names), as text.
    pub(crate) fn select(&mut self, name: &str) -> Result<(), String> {
        let index = car_index(&self.cars, name, &self.source)?;
        let id = self
            .simulation
            .car_ids()
            .nth(index)
            .ok_or_else(|| format!("the world {} has no car {index}", self.source))?;
        if let Some(found) = self.controllers.iter().position(|c| c.car() == Some(id)) {
            self.current = found;
            return Ok(());
        }
        let controller = Controller::new(
            &self.simulation,
            Body::Car {
                id,
                libraries: Libraries::None,
            },
        )?;
        self.others.release(id);
        if self.cars[index].programmed {
            eprintln!(
                "Warning: {}: the programme of the car \"{name}\" is not run: a controller drives \
                 it.",
                self.source
            );
        }
        self.controllers.push(controller);
        self.current = self.controllers.len() - 1;
        Ok(())
    }

    /// The name of the car the current controller drives, `None` for a DifferentialWheels
    /// robot.
    pub(crate) fn current_car(&self) -> Option<&str> {
        let id = self.controller().car()?;
        self.simulation.car_name(id).ok()
    }

    /// The current controller.
    pub(crate) fn controller(&self) -> &Controller {
        &self.controllers[self.current]
    }

    /// The current controller, to change.
    pub(crate) fn controller_mut(&mut self) -> &mut Controller {
        &mut self.controllers[self.current]
    }

    /// Every controller, the current one among them.
    pub(crate) fn controllers(&self) -> &[Controller] {
        &self.controllers
    }

    /// What the current controller drives.
    pub(crate) fn body(&self) -> Body {
        self.controller().body
    }

    /// Puts the other cars' programmes back to their start, for a simulation reset to time 0.
    pub(crate) fn rewind_programmes(&mut self) {
        self.others.rewind();
    }

    /// Gives the other cars' drivers the commands of their programmes due now; the driver
    /// library's warnings as a controller's own, a refused `follow_lane` as a warning.
    fn run_programmes(&mut self) {
        for note in self.others.issue_due(&mut self.simulation) {
            match note {
                TrafficNote::Driver { warning, .. } => crate::message::warning(&warning),
                TrafficNote::FollowLane { error, .. } => {
                    eprintln!("Warning: follow_lane: {error}");
                }
            }
        }
    }

    /// The world's `basicTimeStep` (ms).
    pub(crate) fn basic_time_step_ms(&self) -> u32 {
        self.simulation.world().config().basic_time_step_ms
    }

    /// Simulated time (s).
    pub(crate) fn time(&self) -> f64 {
        self.simulation.world().time()
    }

    /// The C return value of a step: -1 once the simulation is over, else 0. The run's
    /// outputs are written when it ends.
    fn status(&mut self) -> c_int {
        if self.simulation.is_over() {
            self.write_outputs();
            -1
        } else if self.controller_stopped() {
            -1
        } else {
            0
        }
    }

    /// True once the current controller's car's Webots battery is empty
    /// (`sim::Simulation::controller_stopped`): Webots then ends the controller, so every
    /// step returns -1 and advances nothing.
    pub(crate) fn controller_stopped(&self) -> bool {
        self.stopped(self.controller())
    }

    /// True if `controller`'s car's battery is empty.
    fn stopped(&self, controller: &Controller) -> bool {
        controller
            .car()
            .is_some_and(|id| self.simulation.controller_stopped(id).unwrap_or(false))
    }

    /// True if the world steps no more: it is over, or every controller is stopped (the one
    /// controller of a C programme; a world served for several cars goes on while one of
    /// them can drive).
    fn halted(&self) -> bool {
        self.simulation.is_over() || self.controllers.iter().all(|c| self.stopped(c))
    }

    /// Prints a physics failure (once: the simulation is over from then on).
    fn fail(error: &SimError) {
        crate::message::error(format_args!("the simulation stopped: {error}."));
    }

    /// The cars of the controllers whose libraries are below `libraries`: their drivers do
    /// not run in a step (their commands hold).
    fn held_cars(&self, libraries: Libraries) -> Vec<VehicleId> {
        self.controllers
            .iter()
            .filter(|c| c.libraries() < libraries)
            .filter_map(Controller::car)
            .collect()
    }

    /// Advances `steps` basic time steps with the commands in force (Webots: `wb_robot_step`),
    /// stopping early at the end of the simulation. Returns 0, or -1 once it is over.
    pub(crate) fn advance(&mut self, steps: u64) -> c_int {
        // Every controller's car moves by its commands only; the other cars' drivers run.
        let held: Vec<VehicleId> = self
            .controllers
            .iter()
            .filter_map(Controller::car)
            .collect();
        for _ in 0..steps {
            if self.halted() {
                break;
            }
            self.run_programmes();
            let stepped = if held.is_empty() || self.others.is_empty() {
                self.simulation.step_physics()
            } else {
                self.simulation.step_except(&held)
            };
            if let Err(e) = stepped {
                Robot::fail(&e);
            }
        }
        self.status()
    }

    /// One driver step (Webots: `wbu_driver_step`): the driver library turns the sensor
    /// readings into commands, then the world advances one basic time step. Returns 0, or -1
    /// once the simulation is over (the driver does not run then). With several controllers
    /// it is the world's one step: every controller that initialised the driver library has
    /// its driver run (the others' commands hold).
    pub(crate) fn driver_step(&mut self) -> c_int {
        if !self.halted() {
            self.run_programmes();
            let held = self.held_cars(Libraries::Driver);
            if let Err(e) = self.simulation.step_except(&held) {
                Robot::fail(&e);
            }
        }
        self.status()
    }

    /// Writes the recorded run into the `VEHICLE_OUT` directory, once: when the run ends, or
    /// at cleanup ([`Drop`]). A failure is printed, as Webots prints a controller's errors.
    fn write_outputs(&mut self) {
        let Some(dir) = self.outputs.take() else {
            return;
        };
        match self.simulation.save(&self.source, &self.warnings, &dir) {
            Ok(_) => {}
            Err(e) => crate::message::error(format_args!(
                "cannot write the run's outputs into {OUTPUT_VARIABLE}={}: {e}.",
                dir.display()
            )),
        }
    }

    /// The tag of the current controller's device `name`, 0 if its robot has none.
    pub(crate) fn device(&self, name: &str) -> WbDeviceTag {
        self.controller().device(name)
    }

    /// The number of the current controller's tags (the robot's own, 0, excluded).
    pub(crate) fn device_count(&self) -> usize {
        self.controller().device_count()
    }

    /// The current controller's device of `tag` (see [`Controller::device_entry`]).
    pub(crate) fn device_entry(&self, tag: WbDeviceTag) -> Option<&DeviceEntry> {
        self.controller().device_entry(tag)
    }

    /// The car and the index among its sensors of the current controller's sensor with
    /// `tag`, if it is one.
    pub(crate) fn sensor_of(&self, tag: WbDeviceTag) -> Option<(VehicleId, usize)> {
        self.controller().sensor_of(tag)
    }

    /// True if the current controller's robot is a car (Webots: its `customData` has the Car
    /// PROTO's fields).
    pub(crate) fn is_car(&self) -> bool {
        self.controller().car().is_some()
    }
}

/// The index of the car `name` among `cars`.
fn car_index(cars: &[WorldCar], name: &str, source: &str) -> Result<usize, String> {
    cars.iter().position(|c| c.name == name).ok_or_else(|| {
        let names: Vec<&str> = cars.iter().map(|c| c.name.as_str()).collect();
        format!(
            "the world {source} has no car named \"{name}\" (its cars: {})",
            if names.is_empty() {
                "none".to_string()
            } else {
                names.join(", ")
            }
        )
    })
}

impl Drop for Robot {
    /// `wb_robot_cleanup` (and the end of the process' robot): the outputs of a run that did
    /// not reach its end are written now.
    fn drop(&mut self) {
        self.write_outputs();
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use vehicle_model::{TyreModel, WebotsContact};

    /// The front tyre of the car that `Robot::build` puts in the world of `text`.
    fn front_tyre(text: &str) -> TyreModel<f64> {
        let description = world_file::parse_str("w.toml", text).unwrap();
        let robot = Robot::build(&description, None, None).unwrap();
        let Body::Car { id, .. } = robot.body() else {
            panic!("expected a car");
        };
        robot
            .simulation
            .world()
            .vehicle(id)
            .unwrap()
            .spec()
            .tyres
            .front
    }

    #[test]
    fn the_car_rolls_on_the_world_s_tyres() {
        // A truck's default tyre is the commercial set: 10 F_z per rad of cornering stiffness.
        let TyreModel::MagicFormula(truck) = front_tyre("[vehicle]\nmodel = \"Truck\"\n") else {
            panic!("expected the slip-based tyre");
        };
        assert_eq!(truck.params().lateral.stiffness, 10.0);
        let webots = front_tyre(
            "[vehicle]\n[vehicle.tyre]\nmodel = \"webots\"\nforce_dependent_slip = 0.002\n",
        );
        assert_eq!(
            webots,
            TyreModel::Webots(WebotsContact {
                force_dependent_slip: [0.002; 2]
            })
        );
    }

    #[test]
    fn a_controller_drives_the_one_car_without_a_programme() {
        let two = "[[vehicle]]\n[[vehicle]]\ntranslation = [0, 10, 0]\n";
        let description = world_file::parse_str("w.toml", two).unwrap();
        let Err(e) = Robot::build(&description, None, None) else {
            panic!("a world of two cars without programmes was accepted");
        };
        assert_eq!(
            e,
            "cannot drive the world w.toml: of its 2 cars 2 have no programme, and a controller \
             drives the one car without a programme (the others run theirs)"
        );
        let programme = "[[vehicle.programme]]\nat = 0\ncruising_speed = 20\n";
        let description = world_file::parse_str("w.toml", &format!("{two}{programme}")).unwrap();
        let mut robot = Robot::build(&description, None, None).unwrap();
        let ids: Vec<VehicleId> = robot.simulation.car_ids().collect();
        assert!(matches!(robot.body(), Body::Car { id, .. } if id == ids[0]));
        // The other car runs its programme (20 km/h) even through physics-only steps.
        robot.advance(200);
        let speed = robot.simulation.telemetry(ids[1]).unwrap().speed;
        assert!(speed > 2.0, "{speed} m/s");
        assert!(robot.simulation.telemetry(ids[0]).unwrap().speed.abs() < 0.1);
    }
}

#[cfg(test)]
mod several_controllers {
    use super::*;

    /// Two cars without a programme, 10 m apart, loaded for `first`.
    fn two(first: &str) -> Robot {
        let text =
            "[[vehicle]]\nname = \"a\"\n[[vehicle]]\nname = \"b\"\ntranslation = [0, 10, 0]\n";
        let description = world_file::parse_str("w.toml", text).unwrap();
        Robot::build(&description, None, Some(first)).unwrap()
    }

    /// Commands car `name`'s controller (the driver library) to cruise at 20 km/h.
    fn cruise(robot: &mut Robot, name: &str, libraries: Libraries) {
        robot.select(name).unwrap();
        let Body::Car { id, .. } = robot.body() else {
            panic!("a car");
        };
        robot.controller_mut().body = Body::Car { id, libraries };
        robot.simulation.start_car_library(id).unwrap();
        // 20 km/h is within the driver library's range: no warning.
        let warning = robot
            .simulation
            .driver_mut(id)
            .unwrap()
            .set_cruising_speed(20.0);
        assert!(warning.is_none(), "{warning:?}");
    }

    fn speed(robot: &Robot, name: &str) -> f64 {
        let sim = &robot.simulation;
        let id = sim
            .car_ids()
            .find(|&id| sim.car_name(id) == Ok(name))
            .unwrap();
        sim.telemetry(id).unwrap().speed
    }

    #[test]
    fn a_driver_step_runs_the_drivers_of_the_controllers_with_the_driver_library() {
        let mut robot = two("b");
        assert_eq!(robot.current_car(), Some("b"));
        cruise(&mut robot, "a", Libraries::Driver);
        // b's controller only initialised the car library: its driver does not run, the
        // wheels stay held at 0 rad/s although its driver was told 20 km/h.
        cruise(&mut robot, "b", Libraries::Car);
        assert_eq!(robot.controllers().len(), 2);
        for _ in 0..200 {
            assert_eq!(robot.driver_step(), 0);
        }
        // 2 s at the world's 10 ms: one world step per call, not one per controller.
        assert!((robot.time() - 2.0).abs() < 1e-9);
        assert!(
            speed(&robot, "a") > 3.0,
            "a cruises: {} m/s",
            speed(&robot, "a")
        );
        assert!(
            speed(&robot, "b").abs() < 0.1,
            "b is held: {} m/s",
            speed(&robot, "b")
        );
        // Selecting a car again returns to its controller (with its libraries).
        robot.select("a").unwrap();
        assert_eq!(robot.controllers().len(), 2);
        assert_eq!(robot.current_car(), Some("a"));
        assert_eq!(robot.controller().libraries(), Libraries::Driver);
    }

    #[test]
    fn a_robot_step_runs_no_controller_s_driver() {
        let mut robot = two("a");
        cruise(&mut robot, "a", Libraries::Driver);
        cruise(&mut robot, "b", Libraries::Driver);
        robot.advance(100);
        assert!((robot.time() - 1.0).abs() < 1e-9);
        // Held at 0 rad/s by the car library since neither driver ran.
        assert!(speed(&robot, "a").abs() < 0.1 && speed(&robot, "b").abs() < 0.1);
    }

    #[test]
    fn an_unknown_car_is_refused_with_the_world_s_names() {
        let mut robot = two("a");
        assert_eq!(
            robot.select("c"),
            Err("the world w.toml has no car named \"c\" (its cars: a, b)".to_string())
        );
        assert_eq!(robot.current_car(), Some("a"));
    }
}
