//! The simulated robot behind the C API: the world named by `VEHICLE_WORLD`, its car (with the
//! driver and car libraries' state) or DifferentialWheels robot, and the simulation clock.

use std::env::{self, VarError};
use std::ffi::c_int;
use std::path::PathBuf;

use sim::battery_sensor::BatterySensor;
use sim::keyboard::Keyboard;
use sim::traffic::{Traffic, TrafficNote, driven_car};
use sim::world_file::{self, WorldDescription};
use sim::{RobotId, SimError, Simulation, VehicleId};

use crate::abi::WbDeviceTag;
use crate::devices::{self, CAR_TAGS, DeviceEntry};
use crate::display_api::Images;
use crate::sensor::Buffers;

/// The environment variable that selects the world: a world file path or a shipped model name.
pub const WORLD_VARIABLE: &str = "VEHICLE_WORLD";

/// The environment variable naming the directory a controller run writes its outputs into
/// (`telemetry.csv`, `metrics.json`, `replay.glb`), when the run ends or at cleanup.
pub const OUTPUT_VARIABLE: &str = "VEHICLE_OUT";

/// The name of a controller's run in its outputs (the `scenario` column of `telemetry.csv`).
pub const CONTROLLER_RUN: &str = "controller";

/// Which of the two libraries a controller has initialised on a car, in initialisation order
/// (the driver library includes the car library).
#[derive(Debug, Clone, Copy, PartialEq, Eq, PartialOrd, Ord)]
pub(crate) enum Libraries {
    /// Neither: `wbu_car_*` and `wbu_driver_*` functions warn and return neutral values.
    None,
    /// `wbu_car_init()` only.
    Car,
    /// `wbu_driver_init()` (which initialises the car library too).
    Driver,
}

/// What drives in the world.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Body {
    /// A car, driven through the driver library of the [`Simulation`].
    Car {
        /// The car in the simulation.
        id: VehicleId,
        /// The libraries initialised so far.
        libraries: Libraries,
    },
    /// A DifferentialWheels robot.
    DifferentialWheels(RobotId),
}

/// The robot a controller talks to (Webots: the controller's connection to its `Robot`).
pub(crate) struct Robot {
    /// The world and, for a car, its `vehicle_model::Driver`; it owns the `duration`, the
    /// failure state and the recording.
    pub(crate) simulation: Simulation,
    /// The car or robot.
    pub(crate) body: Body,
    /// Where the world came from, and its warnings, for `metrics.json`.
    source: String,
    warnings: Vec<String>,
    /// `VEHICLE_OUT`: where the run's outputs go, until they are written.
    outputs: Option<PathBuf>,
    /// The robot's devices in tag order (tag = index + 1), `None` for a car-library device
    /// the model lacks.
    devices: Vec<Option<DeviceEntry>>,
    /// Where the sensor functions' `const double *` results live.
    pub(crate) buffers: Buffers,
    /// The keyboard of a DifferentialWheels robot's controller: no programme presses its keys
    /// (a car's keyboard is the simulation's).
    pub(crate) robot_keyboard: Keyboard,
    /// The battery sensor of a DifferentialWheels robot's controller: its period only (the
    /// robot has no battery here; a car's sensor is the simulation's).
    pub(crate) robot_battery: BatterySensor,
    /// The images of `wb_display_image_*`, by handle.
    pub(crate) images: Images,
    /// The world's other cars, each running its programme.
    others: Traffic,
}

impl Robot {
    /// Loads the world named by `VEHICLE_WORLD` (unset or empty: the default world, a BmwX5)
    /// and prints its warnings (fields replaced by their defaults) on stderr. With
    /// `VEHICLE_OUT` set, the run is recorded for its outputs.
    ///
    /// # Errors
    /// What is wrong with the world: every error of a world file, one line each in file order,
    /// each naming the file, line, key and value.
    pub(crate) fn from_environment() -> Result<Robot, String> {
        let description = match env::var(WORLD_VARIABLE) {
            Ok(spec) if !spec.is_empty() => world_file::load_all(&spec).map_err(|all| {
                // Every error of the file in file order, one line each, so that one run
                // shows them all.
                all.errors
                    .iter()
                    .map(|e| format!("cannot load the world {WORLD_VARIABLE}={spec}: {e}"))
                    .collect::<Vec<_>>()
                    .join("\n")
            })?,
            Err(VarError::NotUnicode(raw)) => {
                return Err(format!(
                    "cannot load the world {WORLD_VARIABLE}={}: not valid UTF-8",
                    raw.to_string_lossy()
                ));
            }
            Ok(_) | Err(VarError::NotPresent) => world_file::default_world(),
        };
        for w in &description.warnings {
            eprintln!("Warning: {w}");
        }
        let outputs = env::var_os(OUTPUT_VARIABLE)
            .filter(|dir| !dir.is_empty())
            .map(PathBuf::from);
        Robot::build(&description, outputs)
    }

    /// Builds the world of `description` with its car or robot, the one the controller
    /// drives: the robot, the only car, or, of several cars, the one without a programme (the
    /// others run theirs); records it if `outputs` names a directory.
    fn build(description: &WorldDescription, outputs: Option<PathBuf>) -> Result<Robot, String> {
        let cars = &description.cars;
        // A robot alone is driven; otherwise the car the traffic rule leaves free.
        let driven = if cars.is_empty() && description.robot.is_some() {
            0
        } else {
            driven_car(description)?
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
        let driven_programme = match cars.get(driven) {
            Some(car) => !car.programme.is_empty() || !car.lanes.is_empty(),
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
        let (devices, buffers) = match body {
            Body::Car { id, .. } => {
                let sensors = simulation.devices(id).map_err(|e| e.to_string())?;
                let params = simulation.driver(id).map_err(|e| e.to_string())?.params();
                let named = sensors.iter().map(|d| (d.name().to_string(), d.kind()));
                (devices::car_table(params, named), Buffers::new(sensors))
            }
            Body::DifferentialWheels(_) => {
                (devices::differential_wheels_table(), Buffers::new(&[]))
            }
        };
        Ok(Robot {
            simulation,
            body,
            source: description.source.clone(),
            warnings: description
                .warnings
                .iter()
                .map(ToString::to_string)
                .collect(),
            outputs,
            devices,
            buffers,
            robot_keyboard: Keyboard::default(),
            robot_battery: BatterySensor::default(),
            images: Images::default(),
            others,
        })
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

    /// True once the car's Webots battery is empty (`sim::Simulation::controller_stopped`):
    /// Webots then ends the controller, so every step returns -1 and advances nothing.
    pub(crate) fn controller_stopped(&self) -> bool {
        match self.body {
            Body::Car { id, .. } => self.simulation.controller_stopped(id).unwrap_or(false),
            Body::DifferentialWheels(_) => false,
        }
    }

    /// Prints a physics failure (once: the simulation is over from then on).
    fn fail(error: &SimError) {
        crate::message::error(format_args!("the simulation stopped: {error}."));
    }

    /// Advances `steps` basic time steps with the commands in force (Webots: `wb_robot_step`),
    /// stopping early at the end of the simulation. Returns 0, or -1 once it is over.
    pub(crate) fn advance(&mut self, steps: u64) -> c_int {
        for _ in 0..steps {
            if self.simulation.is_over() || self.controller_stopped() {
                break;
            }
            self.run_programmes();
            // The other cars' drivers run; the controller's car only moves by its commands.
            let stepped = match (&self.body, self.others.is_empty()) {
                (Body::Car { id, .. }, false) => self.simulation.step_others(*id),
                _ => self.simulation.step_physics(),
            };
            if let Err(e) = stepped {
                Robot::fail(&e);
            }
        }
        self.status()
    }

    /// One driver step (Webots: `wbu_driver_step`): the driver library turns the sensor
    /// readings into commands, then the world advances one basic time step. Returns 0, or -1
    /// once the simulation is over (the driver does not run then).
    pub(crate) fn driver_step(&mut self) -> c_int {
        if !self.simulation.is_over() && !self.controller_stopped() {
            self.run_programmes();
            if let Err(e) = self.simulation.step() {
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

    /// The tag of the device `name`, 0 if the robot has none.
    pub(crate) fn device(&self, name: &str) -> WbDeviceTag {
        devices::tag_of(&self.devices, name)
    }

    /// The number of tags (the robot's own, 0, excluded).
    pub(crate) fn device_count(&self) -> usize {
        self.devices.len()
    }

    /// The device of `tag`, `None` for 0, a tag past the last or a hole of the car's table.
    pub(crate) fn device_entry(&self, tag: WbDeviceTag) -> Option<&DeviceEntry> {
        let index = usize::from(tag).checked_sub(1)?;
        self.devices.get(index)?.as_ref()
    }

    /// The car and the index among its sensors of the sensor with `tag`, if it is one.
    pub(crate) fn sensor_of(&self, tag: WbDeviceTag) -> Option<(VehicleId, usize)> {
        match self.body {
            Body::Car { id, .. } => {
                let index = usize::from(tag).checked_sub(CAR_TAGS + 1)?;
                (index < self.devices.len() - CAR_TAGS).then_some((id, index))
            }
            Body::DifferentialWheels(_) => None,
        }
    }

    /// True if the robot is a car (Webots: its `customData` has the Car PROTO's fields).
    pub(crate) fn is_car(&self) -> bool {
        matches!(self.body, Body::Car { .. })
    }
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
        let robot = Robot::build(&description, None).unwrap();
        let Body::Car { id, .. } = robot.body else {
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
        let Err(e) = Robot::build(&description, None) else {
            panic!("a world of two cars without programmes was accepted");
        };
        assert_eq!(
            e,
            "cannot drive the world w.toml: of its 2 cars 2 have no programme, and a controller \
             drives the one car without a programme (the others run theirs)"
        );
        let programme = "[[vehicle.programme]]\nat = 0\ncruising_speed = 20\n";
        let description = world_file::parse_str("w.toml", &format!("{two}{programme}")).unwrap();
        let mut robot = Robot::build(&description, None).unwrap();
        let ids: Vec<VehicleId> = robot.simulation.car_ids().collect();
        assert!(matches!(robot.body, Body::Car { id, .. } if id == ids[0]));
        // The other car runs its programme (20 km/h) even through physics-only steps.
        robot.advance(200);
        let speed = robot.simulation.telemetry(ids[1]).unwrap().speed;
        assert!(speed > 2.0, "{speed} m/s");
        assert!(robot.simulation.telemetry(ids[0]).unwrap().speed.abs() < 0.1);
    }
}
