//! One environment of a gym task over a [`Simulation`] its caller owns: the action applied,
//! `frame_skip` basic time steps, the observation, the default reward and the end of the
//! episode. The one copy of these formulas: [`super::VecEnv`] runs a [`TaskEnv`] per copy,
//! and the Python package's single environments (`webots_vehicle.gym.LaneKeepEnv` ...) run
//! one on their `Simulation`.

use std::str::FromStr;

use crate::devices::Reading;
use crate::nalgebra::{Point3, Vector3};
use crate::{SimError, Simulation, VehicleId, rotation_from_axis_angle};

use super::VecEnvError;

/// Steering angle of a full steering action (rad).
pub const MAX_STEERING: f64 = 0.4;
/// Acceleration of a full throttle action (m/s²): the cruise target moves by it.
pub const MAX_ACCELERATION: f64 = 3.0;
/// Highest cruise-control target (m/s).
pub const MAX_SPEED: f64 = 40.0;
/// Radar targets in an ACC observation.
pub const RADAR_TARGETS: usize = 8;
/// Values in an action: steering, acceleration (each in −1 to 1).
pub const ACTION_LEN: usize = 2;
/// Values of the `car` part of every observation: speed (m/s), yaw rate (rad/s), lateral
/// velocity (m/s), steering angle (rad), cruise target (m/s).
const CAR_LEN: usize = 5;

/// Track-v0's circle: radius (m), centre (m) and the speed its reward asks for (m/s).
const TRACK_RADIUS: f64 = 30.0;
const TRACK_CENTRE: (f64, f64) = (0.0, 30.0);
const TRACK_SPEED: f64 = 10.0;

/// The environment a batch runs (`webots_vehicle.gym`'s ids).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Task {
    /// `WebotsVehicle/LaneKeep-v0`: car 0 with a RoadSensor; observation `car`, then `lane`
    /// (offset m, heading error rad, curvature and curvature ahead 1/m, lane width m, on-road
    /// flag).
    LaneKeep,
    /// `WebotsVehicle/ACC-v0`: car 1 follows car 0; observation `car`, then `radar` (8 targets
    /// × distance m, radial speed m/s, azimuth rad, power dBm), then `radar_mask` (8).
    Acc,
    /// `WebotsVehicle/Track-v0`: car 0 on a 30 m circle; observation `car`, then `track`
    /// (distance from the circle m, heading error rad).
    Track,
}

/// A task name other than `LaneKeep`, `ACC` and `Track`.
#[derive(Debug, thiserror::Error)]
#[error("task must be 'LaneKeep', 'ACC' or 'Track', not {0:?}")]
pub struct UnknownTask(pub String);

impl FromStr for Task {
    type Err = UnknownTask;

    /// The task of a gym id's name: `LaneKeep`, `ACC` or `Track`.
    fn from_str(name: &str) -> Result<Task, UnknownTask> {
        match name {
            "LaneKeep" => Ok(Task::LaneKeep),
            "ACC" => Ok(Task::Acc),
            "Track" => Ok(Task::Track),
            other => Err(UnknownTask(other.to_string())),
        }
    }
}

impl Task {
    /// Values in one observation row.
    pub fn observation_len(self) -> usize {
        CAR_LEN
            + match self {
                Task::LaneKeep => 6,
                Task::Acc => RADAR_TARGETS * 4 + RADAR_TARGETS,
                Task::Track => 2,
            }
    }

    /// The index of the agent's car in the world.
    pub fn car_index(self) -> usize {
        match self {
            Task::Acc => 1,
            Task::LaneKeep | Task::Track => 0,
        }
    }

    /// The task's default reward for `observation` (one row, [`Task::observation_len`]
    /// values), the clipped `action` that led to it, and whether the agent's car `touching`
    /// another (ACC); and whether the task ends the episode there (not counting a roll-over,
    /// which [`TaskEnv::step`] adds):
    ///
    /// * LaneKeep: the speed along the lane (m/s, up to 30) over 30, less the lateral offset
    ///   (m) squared, less a tenth of the steering action squared; −10 off the road. Ends off
    ///   the road or more than a lane width from the lane centre.
    /// * ACC: −(time gap − 2 s)² (the nearest target's distance over the car's speed, at least
    ///   0.5 m/s, the gap capped at 5 s), less a tenth of the acceleration action squared; −1
    ///   with no target in sight, −100 touching. Ends touching.
    /// * Track: 1 less the distance from the circle (m), less the speed error to 10 m/s (m/s)
    ///   over 10. Ends more than 10 m off the circle.
    ///
    /// # Errors
    /// [`VecEnvError::Buffer`] for an `observation` of another length.
    pub fn reward(
        self,
        observation: &[f32],
        action: [f64; ACTION_LEN],
        touching: bool,
    ) -> Result<(f64, bool), VecEnvError> {
        let expected = self.observation_len();
        if observation.len() != expected {
            return Err(VecEnvError::Buffer {
                name: "observation",
                len: observation.len(),
                expected,
            });
        }
        let f = |k: usize| f64::from(observation[k]);
        Ok(match self {
            Task::LaneKeep => {
                let (offset, heading, width, on_road) = (f(5), f(6), f(9), f(10));
                let reward = if on_road < 0.5 {
                    -10.0
                } else {
                    (f(0) * heading.cos()).min(30.0) / 30.0
                        - offset * offset
                        - 0.1 * action[0] * action[0]
                };
                (reward, on_road < 0.5 || offset.abs() > width)
            }
            Task::Acc => {
                let mask0 = f(CAR_LEN + RADAR_TARGETS * 4);
                let reward = if touching {
                    -100.0
                } else if mask0 < 0.5 {
                    -1.0
                } else {
                    let gap = (f(CAR_LEN) / f(0).max(0.5)).min(5.0);
                    -(gap - 2.0) * (gap - 2.0) - 0.1 * action[1] * action[1]
                };
                (reward, touching)
            }
            Task::Track => {
                let off = f(5);
                let reward = 1.0 - off.abs() - (f(0) - TRACK_SPEED).abs() / 10.0;
                (reward, off.abs() > 10.0)
            }
        })
    }
}

/// Where an episode starts: the agent's car at `x`, `y` (m, at the height the world file put
/// it) heading `yaw` (rad) at `speed` (m/s, forward), and for ACC the lead's `lead_speed`
/// (m/s; unused otherwise).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Start {
    /// x (m).
    pub x: f64,
    /// y (m).
    pub y: f64,
    /// Heading (rad, counter-clockwise from x).
    pub yaw: f64,
    /// Forward speed (m/s).
    pub speed: f64,
    /// The ACC lead's speed (m/s).
    pub lead_speed: f64,
}

/// What one [`TaskEnv::step`] gives besides the observation.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Outcome {
    /// The task's default reward ([`Task::reward`]).
    pub reward: f64,
    /// The episode ended in the task's terms or the car rolled over (up axis more than 60°
    /// from vertical).
    pub terminated: bool,
    /// The world's duration has elapsed.
    pub truncated: bool,
}

/// The task's state of one environment (its agent car, the cruise target) over a
/// [`Simulation`] the caller owns and passes to each call; see the module docs. A reset is
/// the caller restoring the simulation's start (a snapshot) and calling [`TaskEnv::start`].
#[derive(Debug, Clone)]
pub struct TaskEnv {
    task: Task,
    frame_skip: u32,
    /// Simulated time per step (s).
    dt: f64,
    /// The index named in errors (its place in a batch; 0 alone).
    pub(super) index: usize,
    car: VehicleId,
    /// Every car, the agent's included (world order).
    cars: Vec<VehicleId>,
    /// The agent car's height as loaded (m): starts put it down there.
    rest_height: f64,
    /// The cruise-control target (m/s).
    target: f64,
}

/// Wraps a [`SimError`] of environment `env`.
fn sim_failure(env: usize) -> impl Fn(SimError) -> VecEnvError {
    move |source| VecEnvError::Sim { env, source }
}

/// `v` as an observation value: NaN as 0, within ±`bound` (the space's limits), rounded to
/// `f32`.
fn value(v: f64, bound: f64) -> f32 {
    let v = if v.is_nan() { 0.0 } else { v };
    v.clamp(-bound, bound) as f32
}

/// The heading (rad) of a Webots axis-angle rotation: its x axis projected on the ground
/// (the first column of the rotation matrix, Rodrigues' formula).
fn yaw_of([x, y, z, angle]: [f64; 4]) -> f64 {
    let (c, s) = (angle.cos(), angle.sin());
    let fx = c + x * x * (1.0 - c);
    let fy = y * x * (1.0 - c) + z * s;
    fy.atan2(fx)
}

impl TaskEnv {
    /// `task` on `sim` as loaded (its cars where the world file put them: the agent car's
    /// height is kept for the starts), advanced `frame_skip` basic time steps per action.
    ///
    /// # Errors
    /// [`VecEnvError::Zero`] for `frame_skip` zero; [`VecEnvError::NoCar`] if the world lacks
    /// the task's car.
    pub fn new(sim: &Simulation, task: Task, frame_skip: u32) -> Result<TaskEnv, VecEnvError> {
        if frame_skip == 0 {
            return Err(VecEnvError::Zero { name: "frame_skip" });
        }
        let cars: Vec<VehicleId> = sim.car_ids().collect();
        let car = *cars
            .get(task.car_index())
            .ok_or(VecEnvError::NoCar(task.car_index()))?;
        let rest_height = sim
            .world()
            .vehicle_placement(car)
            .map_err(sim_failure(0))?
            .position
            .z;
        let step_ms = sim.world().config().basic_time_step_ms * frame_skip;
        Ok(TaskEnv {
            task,
            frame_skip,
            dt: f64::from(step_ms) / 1000.0,
            index: 0,
            car,
            cars,
            rest_height,
            target: 0.0,
        })
    }

    /// The task.
    pub fn task(&self) -> Task {
        self.task
    }

    /// Simulated time per step (s).
    pub fn dt(&self) -> f64 {
        self.dt
    }

    /// The cruise-control target (m/s): the start's speed, then moved by each action.
    pub fn target(&self) -> f64 {
        self.target
    }

    /// Starts an episode on `sim` (which the caller has just restored to its start) and
    /// writes its first observation into `observation` ([`Task::observation_len`] values):
    /// the car placed and set moving, its cruise control at the start speed (at most
    /// [`MAX_SPEED`]), its steering straight, for ACC the lead car at `lead_speed`; then one
    /// basic time step for the devices' first sample.
    ///
    /// # Errors
    /// [`VecEnvError::Buffer`] for an `observation` of another length; [`VecEnvError::Start`]
    /// for a start value that is not finite; [`VecEnvError::Sim`] for a start the world
    /// refuses (beyond it, too fast) or a physics failure.
    pub fn start(
        &mut self,
        sim: &mut Simulation,
        start: &Start,
        observation: &mut [f32],
    ) -> Result<(), VecEnvError> {
        self.check_len(observation)?;
        self.check_start(start)?;
        let fail = sim_failure(self.index);
        let q = rotation_from_axis_angle([0.0, 0.0, 1.0, start.yaw])
            .map_err(|e| fail(SimError::Param(e)))?;
        let world = sim.world_mut();
        world
            .set_vehicle_pose(
                self.car,
                &Point3::new(start.x, start.y, self.rest_height),
                &q,
            )
            .map_err(&fail)?;
        let v = Vector3::new(
            start.speed * start.yaw.cos(),
            start.speed * start.yaw.sin(),
            0.0,
        );
        world
            .set_vehicle_velocity(self.car, &v, &Vector3::zeros())
            .map_err(&fail)?;
        self.target = start.speed.clamp(0.0, MAX_SPEED);
        let driver = sim.driver_mut(self.car).map_err(&fail)?;
        driver.set_cruising_speed(self.target * 3.6);
        driver.set_steering_angle(0.0);
        if self.task == Task::Acc {
            let lead = self.cars[0];
            sim.world_mut()
                .set_vehicle_velocity(
                    lead,
                    &Vector3::new(start.lead_speed, 0.0, 0.0),
                    &Vector3::zeros(),
                )
                .map_err(&fail)?;
            sim.driver_mut(lead)
                .map_err(&fail)?
                .set_cruising_speed(start.lead_speed * 3.6);
        }
        sim.step().map_err(&fail)?;
        self.observe(sim, observation)
    }

    /// One step: `action` (steering, acceleration; each clipped to −1 to 1) sets the steering
    /// angle and moves the cruise target, `frame_skip` basic time steps run (fewer if the
    /// world's duration ends first), the observation is written into `observation`.
    ///
    /// # Errors
    /// [`VecEnvError::Buffer`] for an `observation` of another length, [`VecEnvError::Action`]
    /// for an action value that is not finite (nothing is stepped then); [`VecEnvError::Sim`]
    /// for a physics failure.
    pub fn step(
        &mut self,
        sim: &mut Simulation,
        action: [f64; ACTION_LEN],
        observation: &mut [f32],
    ) -> Result<Outcome, VecEnvError> {
        self.check_len(observation)?;
        if let Some((index, &value)) = action.iter().enumerate().find(|(_, a)| !a.is_finite()) {
            return Err(VecEnvError::Action {
                env: self.index,
                index,
                value,
            });
        }
        let a = action.map(|a| a.clamp(-1.0, 1.0));
        let fail = sim_failure(self.index);
        let driver = sim.driver_mut(self.car).map_err(&fail)?;
        driver.set_steering_angle(a[0] * MAX_STEERING);
        self.target = (self.target + a[1] * MAX_ACCELERATION * self.dt).clamp(0.0, MAX_SPEED);
        driver.set_cruising_speed(self.target * 3.6);
        for _ in 0..self.frame_skip {
            if sim.is_over() {
                break;
            }
            sim.step().map_err(&fail)?;
        }
        self.observe(sim, observation)?;
        let touching = self.task == Task::Acc && self.touching(sim).map_err(&fail)?;
        let (reward, ended) = self.task.reward(observation, a, touching)?;
        let rolled = self.rolled_over(sim).map_err(fail)?;
        Ok(Outcome {
            reward,
            terminated: rolled || ended,
            truncated: sim.is_over(),
        })
    }

    /// True while the agent's car touches another car.
    ///
    /// # Errors
    /// [`SimError`] if `sim` lacks this environment's cars.
    pub fn touching(&self, sim: &Simulation) -> Result<bool, SimError> {
        let world = sim.world();
        for &other in self.cars.iter().filter(|&&c| c != self.car) {
            if world.vehicles_in_contact(self.car, other)? {
                return Ok(true);
            }
        }
        Ok(false)
    }

    /// [`VecEnvError::Start`] for a start value that is not finite.
    pub(super) fn check_start(&self, start: &Start) -> Result<(), VecEnvError> {
        for (name, v) in [
            ("start.x", start.x),
            ("start.y", start.y),
            ("start.yaw", start.yaw),
            ("start.speed", start.speed),
            ("start.lead_speed", start.lead_speed),
        ] {
            if !v.is_finite() {
                return Err(VecEnvError::Start {
                    env: self.index,
                    field: name,
                    value: v,
                });
            }
        }
        Ok(())
    }

    fn check_len(&self, observation: &[f32]) -> Result<(), VecEnvError> {
        let expected = self.task.observation_len();
        if observation.len() == expected {
            Ok(())
        } else {
            Err(VecEnvError::Buffer {
                name: "observation",
                len: observation.len(),
                expected,
            })
        }
    }

    /// The car's up axis tilted more than 60° from vertical.
    fn rolled_over(&self, sim: &Simulation) -> Result<bool, SimError> {
        let [_, _, z, angle] = sim.world().vehicle_placement(self.car)?.axis_angle();
        let c = angle.cos();
        Ok(c + z * z * (1.0 - c) < 0.5)
    }

    /// Writes the observation (see [`Task`]) into `obs`.
    fn observe(&self, sim: &Simulation, obs: &mut [f32]) -> Result<(), VecEnvError> {
        let fail = sim_failure(self.index);
        let p = sim.world().vehicle_placement(self.car).map_err(&fail)?;
        let yaw = yaw_of(p.axis_angle());
        let (vx, vy) = (p.velocity.x, p.velocity.y);
        let forward = vx * yaw.cos() + vy * yaw.sin();
        let lateral = -vx * yaw.sin() + vy * yaw.cos();
        let steering = sim.driver(self.car).map_err(&fail)?.steering_angle();
        let car = [
            forward,
            p.angular_velocity.z,
            lateral,
            steering,
            self.target,
        ];
        for (o, v) in obs.iter_mut().zip(car) {
            *o = value(v, 100.0);
        }
        let rest = &mut obs[CAR_LEN..];
        let devices = sim.devices(self.car).map_err(fail)?;
        rest.fill(0.0);
        match self.task {
            Task::LaneKeep => {
                let road = devices.iter().find_map(|d| match d.reading() {
                    Reading::Road(r) => Some(r),
                    _ => None,
                });
                if let Some(r) = road.filter(|r| r.road.is_some() && r.lateral_offset.is_finite()) {
                    let lane = [
                        r.lateral_offset,
                        r.heading_error,
                        r.curvature,
                        r.curvature_ahead,
                        r.lane_width,
                        1.0,
                    ];
                    for (o, v) in rest.iter_mut().zip(lane) {
                        *o = value(v, 100.0);
                    }
                }
            }
            Task::Acc => {
                let (radar, mask) = rest.split_at_mut(RADAR_TARGETS * 4);
                let mut targets: Vec<[f64; 4]> = devices
                    .iter()
                    .find_map(|d| match d.reading() {
                        Reading::Radar(t) => Some(
                            t.iter()
                                .flatten()
                                .map(|t| [t.distance, t.received_power, t.speed, t.azimuth])
                                .collect(),
                        ),
                        _ => None,
                    })
                    .unwrap_or_default();
                // The nearest first (ties by received power, speed, azimuth), at most
                // RADAR_TARGETS, into rows of [distance, speed, azimuth, power].
                targets.sort_by(|a, b| a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal));
                for (i, [distance, power, speed, azimuth]) in
                    targets.into_iter().take(RADAR_TARGETS).enumerate()
                {
                    for (k, v) in [distance, speed, azimuth, power].into_iter().enumerate() {
                        radar[i * 4 + k] = value(v, 1000.0);
                    }
                    mask[i] = 1.0;
                }
            }
            Task::Track => {
                let dx = p.position.x - TRACK_CENTRE.0;
                let dy = p.position.y - TRACK_CENTRE.1;
                let off = dx.hypot(dy) - TRACK_RADIUS;
                // Counter-clockwise round the centre: the tangent is the radius turned by +90°.
                let tangent = dy.atan2(dx) + std::f64::consts::FRAC_PI_2;
                let error = (yaw - tangent + std::f64::consts::PI)
                    .rem_euclid(2.0 * std::f64::consts::PI)
                    - std::f64::consts::PI;
                rest[0] = value(off, 1000.0);
                rest[1] = value(error, 1000.0);
            }
        }
        Ok(())
    }
}
