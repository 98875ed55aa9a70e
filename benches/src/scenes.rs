//! Simulation scenes of the `sim` benchmarks: worlds on flat ground at `basicTimeStep` 10 ms,
//! advanced by [`CarScene::step`] and [`RobotScene::step`], which re-command every car or robot
//! before each physics step, so that no island can fall asleep and a bench never measures an
//! idle world.

use core::fmt;

use sim::{
    DifferentialWheelsParams, Mounting, RobotBody, RobotId, RobotMode, RobotPlacement, SimError,
    Simulation, TyreChoice, VehicleId, VehiclePlacement, World, WorldConfig,
};
use vehicle_model::Model;

use crate::control::{InvalidModel, LoopMode};

/// The world's `basicTimeStep` (ms), the same as the peer's.
pub const BASIC_TIME_STEP_MS: u32 = 10;

/// The two alternating wheel-speed commands of the robot, left and right (speed units =
/// rad/s with the default `speedUnit` 1): a slight zig-zag, re-sent every step.
const ROBOT_SPEEDS: ([f64; 2], [f64; 2]) = ([6.0, 5.0], [5.0, 6.0]);

/// A flat, obstacle-free world at [`BASIC_TIME_STEP_MS`].
///
/// # Errors
/// [`SimError`] if `sim` rejects the configuration (never for these constants).
pub fn flat_world() -> Result<World, SimError> {
    World::new(WorldConfig {
        basic_time_step_ms: BASIC_TIME_STEP_MS,
        ..WorldConfig::default()
    })
}

/// [`flat_world`] with a closed ring road under the first car's circle: a right-turning arc
/// of the circle's radius (L/tan δ) through the origin heading +x, two 6 m lanes each side of
/// it, so that all four wheels of that car stand on the road's triangle meshes at every step.
///
/// # Errors
/// [`SimError`] if `sim` rejects the configuration (never for these constants).
pub fn ring_road_world() -> Result<World, SimError> {
    use sim::nalgebra::Point2;
    use sim::road::{Curve, Road, RoadNetwork};
    let radius = CAR_MODEL.params::<f64>().wheelbase / STEERING.tan();
    let circle = [(
        radius * core::f64::consts::TAU,
        Curve::Arc {
            curvature: -1.0 / radius,
        },
    )];
    let road = Road::two_way("ring", Point2::origin(), 0.0, &circle, 6.0)?;
    World::new(WorldConfig {
        basic_time_step_ms: BASIC_TIME_STEP_MS,
        roads: RoadNetwork {
            roads: vec![road],
            junctions: Vec::new(),
        },
        ..WorldConfig::default()
    })
}

/// The car of the simulation benches: Webots' BMW X5 (2000 kg, wheelbase 2.995 m, front-wheel
/// drive), the same size and mass as the peer.
pub const CAR_MODEL: Model = Model::BmwX5;
/// Cruising speed of every car (km/h): 10 m/s, the peer's speed.
pub const CRUISE_KMH: f64 = 36.0;
/// Constant steering command of every car (rad, to the right): a circle of radius about
/// L/tan δ = 2.995/0.1003 = 29.9 m.
pub const STEERING: f64 = 0.1;
/// Distance between neighbouring cars on the grid (m): their circles (60 m across) never meet.
const CAR_SPACING: f64 = 80.0;
/// Cars per grid row.
const GRID_COLUMNS: usize = 8;
/// Torque mode: throttle per km/h of speed error of the speed-holding controller.
const THROTTLE_GAIN: f64 = 0.1;

/// Why a scene could not be built.
#[derive(Debug, Clone, PartialEq)]
pub enum SceneError {
    /// `sim` rejected the world or a car.
    Sim(SimError),
    /// The car model's parameters did not validate.
    Model(InvalidModel),
}

impl fmt::Display for SceneError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            SceneError::Sim(e) => write!(f, "simulation: {e}"),
            SceneError::Model(e) => write!(f, "car model: {e}"),
        }
    }
}

impl std::error::Error for SceneError {}

impl From<SimError> for SceneError {
    fn from(e: SimError) -> Self {
        SceneError::Sim(e)
    }
}

/// `count` [`CAR_MODEL`] cars on a grid of a [`Simulation`] (each with its own Webots driver
/// library), all cruising at [`CRUISE_KMH`] on a circle: speed mode through the cruise
/// control, torque mode through a proportional throttle controller in first gear.
pub struct CarScene {
    sim: Simulation,
    cars: Vec<VehicleId>,
    mode: LoopMode,
}

impl CarScene {
    /// Builds the world and the cars (at rest, wheels on the ground) on the model's default
    /// slip-based tyres.
    ///
    /// # Errors
    /// [`SceneError`] if the model or `sim` rejects something (never for these constants).
    pub fn new(count: usize, mode: LoopMode) -> Result<Self, SceneError> {
        Self::on(count, mode, &TyreChoice::default())
    }

    /// As [`CarScene::new`], on `tyre`.
    ///
    /// # Errors
    /// [`SceneError`] if the model or `sim` rejects something (never for these constants).
    pub fn on(count: usize, mode: LoopMode, tyre: &TyreChoice) -> Result<Self, SceneError> {
        Self::mounted(count, mode, tyre, Mounting::Cast)
    }

    /// As [`CarScene::on`], with the wheels mounted as `mounting` says.
    ///
    /// # Errors
    /// [`SceneError`] if the model or `sim` rejects something (never for these constants).
    pub fn mounted(
        count: usize,
        mode: LoopMode,
        tyre: &TyreChoice,
        mounting: Mounting,
    ) -> Result<Self, SceneError> {
        Self::in_world(flat_world()?, count, mode, tyre, mounting)
    }

    /// As [`CarScene::mounted`], in `world` (e.g. [`ring_road_world`]).
    ///
    /// # Errors
    /// [`SceneError`] if the model or `sim` rejects something (never for these constants).
    pub fn in_world(
        world: World,
        count: usize,
        mode: LoopMode,
        tyre: &TyreChoice,
        mounting: Mounting,
    ) -> Result<Self, SceneError> {
        let mut sim = Simulation::new(world);
        let mut cars = Vec::with_capacity(count);
        for i in 0..count {
            let placement = VehiclePlacement {
                x: (i % GRID_COLUMNS) as f64 * CAR_SPACING,
                y: (i / GRID_COLUMNS) as f64 * CAR_SPACING,
                ..VehiclePlacement::default()
            };
            let (id, report) = sim.add_car(
                sim::CarBuilder::new(CAR_MODEL.params())
                    .tyre(tyre.clone())
                    .mounting(mounting)
                    .placement(placement),
            )?;
            if !report.is_empty() {
                return Err(SceneError::Model(InvalidModel {
                    total: report.total(),
                    first: report.iter().next().copied(),
                }));
            }
            let driver = sim.driver_mut(id)?;
            driver.set_steering_angle(STEERING);
            match mode {
                LoopMode::Speed => {
                    driver.set_cruising_speed(CRUISE_KMH);
                }
                LoopMode::Torque => {
                    driver.set_gear(1);
                    driver.set_throttle(1.0);
                }
            }
            cars.push(id);
        }
        Ok(CarScene { sim, cars, mode })
    }

    /// One step of the simulation: in torque mode each driver first gets its new throttle,
    /// then every driver reads its car's sensors and re-sends all its commands, then the
    /// world steps.
    ///
    /// # Errors
    /// [`SimError`] if the world reports a failure (a non-finite body state).
    pub fn step(&mut self) -> Result<(), SimError> {
        if self.mode == LoopMode::Torque {
            for id in &self.cars {
                let driver = self.sim.driver_mut(*id)?;
                let error = CRUISE_KMH - driver.current_speed();
                driver.set_throttle((THROTTLE_GAIN * error).clamp(0.0, 1.0));
            }
        }
        self.sim.step()
    }

    /// The simulation, to read the cars and their drivers back.
    pub fn simulation(&self) -> &Simulation {
        &self.sim
    }

    /// The cars, in grid order.
    pub fn cars(&self) -> &[VehicleId] {
        &self.cars
    }
}

/// One Webots `DifferentialWheels` robot (default fields, no slip noise) alone on flat ground.
pub struct RobotScene {
    world: World,
    robot: RobotId,
    step: usize,
}

impl RobotScene {
    /// The robot at the origin in `mode`: [`RobotMode::Kinematics`] or
    /// [`RobotMode::Physics`] with the default [`RobotBody`] (see [`RobotScene::physics`]).
    ///
    /// # Errors
    /// [`SimError`] if `sim` rejects the world or the robot (never for these constants).
    pub fn new(mode: RobotMode) -> Result<Self, SimError> {
        let mut world = flat_world()?;
        let params = DifferentialWheelsParams {
            slip_noise: 0.0,
            ..DifferentialWheelsParams::default()
        };
        let robot = world.add_differential_wheels(params, mode, RobotPlacement::default())?;
        Ok(RobotScene {
            world,
            robot,
            step: 0,
        })
    }

    /// The physics-mode robot of [`RobotScene::new`].
    ///
    /// # Errors
    /// As [`RobotScene::new`].
    pub fn physics() -> Result<Self, SimError> {
        Self::new(RobotMode::Physics(RobotBody::default()))
    }

    /// Re-commands both wheels (alternating between two speed pairs) and steps the world.
    ///
    /// # Errors
    /// [`SimError`] if the world reports a failure (a non-finite body state).
    pub fn step(&mut self) -> Result<(), SimError> {
        let [left, right] = if self.step.is_multiple_of(2) {
            ROBOT_SPEEDS.0
        } else {
            ROBOT_SPEEDS.1
        };
        self.world.robot_mut(self.robot)?.set_speed(left, right);
        self.step += 1;
        self.world.step()
    }

    /// The world, to read the robot back.
    pub fn world(&self) -> &World {
        &self.world
    }

    /// The robot's handle.
    pub fn robot(&self) -> RobotId {
        self.robot
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use vehicle_model::KMH_PER_MS;

    #[test]
    fn a_car_cruises_on_its_circle_in_both_modes() {
        for mode in [LoopMode::Speed, LoopMode::Torque] {
            let mut scene = CarScene::new(1, mode).unwrap();
            for _ in 0..800 {
                scene.step().unwrap();
            }
            let id = scene.cars()[0];
            let sim = scene.simulation();
            let state = *sim.world().vehicle(id).unwrap().state();
            let driver = sim.driver(id).unwrap();
            let v = state.forward_speed;
            match mode {
                // The cruise control holds 10 m/s.
                LoopMode::Speed => assert!((v - 10.0).abs() < 0.3, "speed {v}"),
                // The proportional throttle controller settles a little below its target,
                // where 0.1 per km/h of error holds the car against its resistances (at the
                // time of writing 9.7 m/s after these 8 s; it passes 9 m/s after about 6.5 s).
                LoopMode::Torque => assert!(v > 9.0 && v < 10.1, "speed {v}"),
            }
            // The driver's estimate from the wheel encoders agrees with the body's speed.
            assert!((driver.current_speed() / KMH_PER_MS - v).abs() < 0.1 * v.max(1.0));
            // Right turn: yaw rate ≈ −v·tan δ/L (= −10·0.1003/2.995 = −0.335 rad/s at 10 m/s),
            // give or take what tyre slip and the steering servo make of it (at the time of
            // writing both cars turn within 0.3 % of this kinematic rate).
            let kinematic = -v * STEERING.tan() / 2.995;
            let r = state.yaw_rate;
            assert!(
                r < 0.9 * kinematic && r > 1.1 * kinematic,
                "{mode:?}: yaw rate {r}"
            );
            // One rapier step per basicTimeStep: car wheels never split a step.
            assert_eq!(sim.world().last_substeps(), 1);
        }
    }

    #[test]
    fn cars_on_the_grid_drive_alike() {
        let mut scene = CarScene::new(9, LoopMode::Speed).unwrap();
        for _ in 0..300 {
            scene.step().unwrap();
        }
        let speeds: Vec<f64> = scene
            .cars()
            .iter()
            .map(|id| scene.simulation().telemetry(*id).unwrap().speed)
            .collect();
        // Same car, same commands: the same motion wherever it sits, to within what the f32
        // rounding of positions up to 160 m away (10⁻⁵ m) grows into through the contacts.
        for v in &speeds {
            assert!((v - speeds[0]).abs() < 0.02 * speeds[0], "{speeds:?}");
        }
        assert!(speeds[0] > 5.0);
    }

    #[test]
    fn both_robot_modes_move_forward() {
        for mut scene in [
            RobotScene::new(RobotMode::Kinematics).unwrap(),
            RobotScene::physics().unwrap(),
        ] {
            for _ in 0..200 {
                scene.step().unwrap();
            }
            assert_eq!(scene.world().time_ms(), 2000);
            let robot = scene.world().robot(scene.robot()).unwrap();
            // Mean wheel speed 5.5 rad/s · r 0.01 m = 0.055 m/s: about 0.11 m in 2 s (less the
            // acceleration phase and, in physics mode, the wheel slip).
            let x = robot.pose().position.x;
            assert!(x > 0.05 && x < 0.115, "x = {x}");
        }
    }
}
