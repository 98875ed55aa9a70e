//! The simulated robot behind the C API: the world named by `VEHICLE_WORLD`, its car (with the
//! driver and car libraries' state) or DifferentialWheels robot, and the simulation clock.

use std::env::{self, VarError};
use std::ffi::c_int;

use sim::world_file::{self, WorldDescription};
use sim::{RobotId, SimError, Simulation, VehicleId, World};
use vehicle_model::Driver;

use crate::abi::WbDeviceTag;
use crate::devices;

/// The environment variable that selects the world: a world file path or a shipped model name.
pub const WORLD_VARIABLE: &str = "VEHICLE_WORLD";

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
    /// The world and, for a car, its `vehicle_model::Driver`.
    pub(crate) simulation: Simulation,
    /// The car or robot.
    pub(crate) body: Body,
    /// The world's `duration` (s): stepping reports the end of the simulation from then on.
    duration: Option<f64>,
    /// Set when the physics failed: stepping reports the end of the simulation.
    stopped: bool,
}

impl Robot {
    /// Loads the world named by `VEHICLE_WORLD` (unset or empty: the default world, a BmwX5)
    /// and prints its warnings (fields replaced by their defaults) on stderr.
    ///
    /// # Errors
    /// What is wrong with the world, in one line naming the file, line, key and value.
    pub(crate) fn from_environment() -> Result<Robot, String> {
        let description = match env::var(WORLD_VARIABLE) {
            Ok(spec) if !spec.is_empty() => world_file::load(&spec)
                .map_err(|e| format!("cannot load the world {WORLD_VARIABLE}={spec}: {e}"))?,
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
        Robot::build(&description)
    }

    /// Builds the world of `description` with its car (on the world's tyres) or robot: one
    /// vehicle, the one the controller drives.
    fn build(description: &WorldDescription) -> Result<Robot, String> {
        let failed = |e: SimError| format!("cannot build the world {}: {e}", description.source);
        let mut simulation =
            Simulation::new(World::new(description.config.clone()).map_err(failed)?);
        let body = match (description.cars.as_slice(), &description.robot) {
            ([], Some(r)) => Body::DifferentialWheels(
                simulation
                    .world_mut()
                    .add_differential_wheels(r.params, r.mode, r.placement)
                    .map_err(failed)?,
            ),
            ([car], None) => {
                let (id, report) = simulation.add_described_car(car).map_err(failed)?;
                // The loader validated the fields already; anything left is still reported.
                for w in &report {
                    eprintln!("Warning: {}: {w}", description.source);
                }
                Body::Car {
                    id,
                    libraries: Libraries::None,
                }
            }
            _ => {
                return Err(format!(
                    "cannot drive the world {}: it holds {}, and a controller drives exactly \
                     one car or robot",
                    description.source,
                    description.vehicles_label()
                ));
            }
        };
        Ok(Robot {
            simulation,
            body,
            duration: description.duration,
            stopped: false,
        })
    }

    /// The world's `basicTimeStep` (ms).
    pub(crate) fn basic_time_step_ms(&self) -> u32 {
        self.simulation.world().config().basic_time_step_ms
    }

    /// Simulated time (s).
    pub(crate) fn time(&self) -> f64 {
        self.simulation.world().time()
    }

    /// True once the world's `duration` has elapsed or the physics has failed.
    pub(crate) fn is_over(&self) -> bool {
        let elapsed_ms = self.simulation.world().time_ms() as f64;
        // The duration is compared in ms with a margin far below one step, so that a duration
        // that is a whole number of steps ends exactly on that step.
        self.stopped
            || self
                .duration
                .is_some_and(|d| elapsed_ms >= d * 1000.0 - 1e-6)
    }

    /// The C return value of a step: -1 once the simulation is over, else 0.
    fn status(&self) -> c_int {
        if self.is_over() { -1 } else { 0 }
    }

    /// Records a physics failure: prints it once and ends the simulation.
    fn fail(&mut self, error: &SimError) {
        if !self.stopped {
            crate::message::error(format_args!("the simulation stopped: {error}."));
            self.stopped = true;
        }
    }

    /// Advances `steps` basic time steps with the commands in force (Webots: `wb_robot_step`),
    /// stopping early at the end of the simulation. Returns 0, or -1 once it is over.
    pub(crate) fn advance(&mut self, steps: u64) -> c_int {
        for _ in 0..steps {
            if self.is_over() {
                break;
            }
            if let Err(e) = self.simulation.world_mut().step() {
                self.fail(&e);
            }
        }
        self.status()
    }

    /// One driver step (Webots: `wbu_driver_step`): the driver library turns the sensor
    /// readings into commands, then the world advances one basic time step. Returns 0, or -1
    /// once the simulation is over (the driver does not run then).
    pub(crate) fn driver_step(&mut self) -> c_int {
        if !self.is_over()
            && let Err(e) = self.simulation.step()
        {
            self.fail(&e);
        }
        self.status()
    }

    /// The tag of the device `name`, 0 if the robot has none.
    pub(crate) fn device(&self, name: &str) -> WbDeviceTag {
        match self.body {
            Body::Car { id, .. } => self
                .simulation
                .driver(id)
                .map_or(0, |d| devices::car_device(d.params(), name)),
            Body::DifferentialWheels(_) => devices::differential_wheels_device(name),
        }
    }

    /// Sends the driver's commanded front-wheel angles to the steering motors at once, as
    /// Webots' libraries do (`wb_motor_set_position` in the setters), so that a steering
    /// command also acts when the controller steps with `wb_robot_step`.
    pub(crate) fn apply_steering(&mut self, id: VehicleId) {
        let Ok(angles) = self
            .simulation
            .driver(id)
            .map(Driver::commanded_wheel_angles)
        else {
            return;
        };
        if let Ok(vehicle) = self.simulation.world_mut().vehicle_mut(id)
            && let Some(mut commands) = vehicle.commands().copied()
        {
            commands.steering = angles;
            vehicle.set_commands(&commands);
        }
    }

    /// True if the robot is a car (Webots: its `customData` has the Car PROTO's fields).
    pub(crate) fn is_car(&self) -> bool {
        matches!(self.body, Body::Car { .. })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use vehicle_model::{TyreModel, WebotsContact};

    /// The front tyre of the car that `Robot::build` puts in the world of `text`.
    fn front_tyre(text: &str) -> TyreModel<f64> {
        let description = world_file::parse_str("w.toml", text).unwrap();
        let robot = Robot::build(&description).unwrap();
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
    fn a_controller_drives_one_vehicle() {
        let description = world_file::parse_str(
            "w.toml",
            "[[vehicle]]\n[[vehicle]]\ntranslation = [0, 10, 0]\n",
        )
        .unwrap();
        let Err(e) = Robot::build(&description) else {
            panic!("a world of two cars was accepted");
        };
        assert_eq!(
            e,
            "cannot drive the world w.toml: it holds 2 vehicles (Car-1, Car-2), and a \
             controller drives exactly one car or robot"
        );
    }
}
