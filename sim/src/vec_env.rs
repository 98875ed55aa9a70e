//! Many independent copies of one world stepped with one call: the core of the Python
//! package's `webots_vehicle.gym.VectorEnv`.
//!
//! A [`VecEnv`] holds `N` [`Simulation`]s of the same world description, each with its own
//! start snapshot, and runs the gymnasium environments' per-step work for all of them in
//! Rust: the action's steering and cruise-control target, `frame_skip` basic time steps,
//! the observation, the default reward and the end of the episode. It writes into caller
//! buffers (`N × k` actions in, `N × m` observations, `N` rewards and flags out) so that
//! a binding passes whole arrays and builds no per-environment object.
//!
//! Every formula is the one `webots_vehicle/gym.py` computes for a single environment, in
//! the same order of floating-point operations and through the same libm functions (`cos`,
//! `sin`, `atan2`, `pow`), so that an environment of the batch and a single environment given
//! the same start and actions agree to the last bit (the Python tests check it).
//!
//! Autoreset follows gymnasium's `NEXT_STEP` mode: the caller flags the environments whose
//! episode ended at the previous step; in the next [`VecEnv::step`] those are reset to the
//! [`Start`] given (their action is ignored) and report reward 0, not terminated and not
//! truncated.
//!
//! Units: m, m/s, rad, rad/s, s; the actions are shares of [`MAX_STEERING`] and
//! [`MAX_ACCELERATION`].

use crate::devices::Reading;
use crate::nalgebra::{Point3, Vector3};
use crate::world_file::WorldDescription;
use crate::{SimError, Simulation, Snapshot, SnapshotError, VehicleId, rotation_from_axis_angle};

/// Why a batch cannot be built, reset or stepped.
#[derive(Debug, thiserror::Error)]
pub enum VecEnvError {
    /// `num_envs` or `frame_skip` zero.
    #[error("{name} must be at least 1, not 0")]
    Zero {
        /// The argument.
        name: &'static str,
    },
    /// A buffer whose length does not fit the batch.
    #[error("{name} has {len} values where the batch needs {expected}")]
    Buffer {
        /// The buffer.
        name: &'static str,
        /// Its length.
        len: usize,
        /// The length the batch needs.
        expected: usize,
    },
    /// An action value that is not finite (nothing was stepped).
    #[error("actions[{env}][{index}] must be finite, not {value}")]
    Action {
        /// The environment.
        env: usize,
        /// The value's index in the action.
        index: usize,
        /// The value.
        value: f64,
    },
    /// A start value that is not finite.
    #[error("the start of environment {env}: {field} must be finite, not {value}")]
    Start {
        /// The environment.
        env: usize,
        /// The field of [`Start`].
        field: &'static str,
        /// The value.
        value: f64,
    },
    /// An environment index not below the batch's size.
    #[error("no environment {0} in this batch")]
    UnknownEnv(usize),
    /// The world lacks the task's car.
    #[error("the world has no car {0}, which the task drives")]
    NoCar(usize),
    /// The start snapshot could not be restored (a bug: it is this simulation's own).
    #[error("environment {env}: {source}")]
    Restore {
        /// The environment.
        env: usize,
        /// Why.
        source: SnapshotError,
    },
    /// A refused placement or a physics failure of environment `env`.
    #[error("environment {env}: {source}")]
    Sim {
        /// The environment.
        env: usize,
        /// The simulation's error.
        source: SimError,
    },
}

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

/// The buffers one [`VecEnv::step`] fills, each row-major with one row per environment.
pub struct StepOut<'a> {
    /// `N × observation_len` observations.
    pub observations: &'a mut [f32],
    /// `N` rewards.
    pub rewards: &'a mut [f64],
    /// `N` terminated flags.
    pub terminated: &'a mut [bool],
    /// `N` truncated flags (the world's duration elapsed).
    pub truncated: &'a mut [bool],
}

/// One environment of the batch.
struct Env {
    /// Its index in the batch (for errors).
    index: usize,
    sim: Simulation,
    start: Snapshot,
    car: VehicleId,
    /// Every car, the agent's included (world order).
    cars: Vec<VehicleId>,
    /// The agent car's height as loaded (m): resets put it down there.
    rest_height: f64,
    /// The cruise-control target (m/s).
    target: f64,
}

/// `N` independent simulations of one world: see the module docs.
pub struct VecEnv {
    task: Task,
    frame_skip: u32,
    /// Simulated time per step (s).
    dt: f64,
    envs: Vec<Env>,
}

impl VecEnv {
    /// `n` copies of the world of `description` for `task`, each advanced `frame_skip` basic
    /// time steps per action. Call [`VecEnv::reset`] on each before stepping it.
    ///
    /// # Errors
    /// [`VecEnvError::Zero`] for `n` or `frame_skip` zero; [`VecEnvError::NoCar`] if the
    /// world lacks the task's car; [`VecEnvError::Sim`] for an error building the world.
    pub fn new(
        description: &WorldDescription,
        task: Task,
        n: usize,
        frame_skip: u32,
    ) -> Result<VecEnv, VecEnvError> {
        if n == 0 {
            return Err(VecEnvError::Zero { name: "num_envs" });
        }
        if frame_skip == 0 {
            return Err(VecEnvError::Zero { name: "frame_skip" });
        }
        let envs = (0..n)
            .map(|index| {
                let fail = |source| VecEnvError::Sim { env: index, source };
                let (sim, _reports) = Simulation::from_description(description).map_err(fail)?;
                let cars: Vec<VehicleId> = sim.car_ids().collect();
                let car = *cars
                    .get(task.car_index())
                    .ok_or(VecEnvError::NoCar(task.car_index()))?;
                let rest_height = sim.world().vehicle_placement(car).map_err(fail)?.position.z;
                let start = sim.snapshot();
                Ok(Env {
                    index,
                    sim,
                    start,
                    car,
                    cars,
                    rest_height,
                    target: 0.0,
                })
            })
            .collect::<Result<Vec<_>, VecEnvError>>()?;
        let step_ms = envs[0].sim.world().config().basic_time_step_ms * frame_skip;
        Ok(VecEnv {
            task,
            frame_skip,
            dt: f64::from(step_ms) / 1000.0,
            envs,
        })
    }

    /// The number of environments.
    pub fn len(&self) -> usize {
        self.envs.len()
    }

    /// Always false: a batch has at least one environment.
    pub fn is_empty(&self) -> bool {
        self.envs.is_empty()
    }

    /// The task.
    pub fn task(&self) -> Task {
        self.task
    }

    /// Simulated time per step (s).
    pub fn dt(&self) -> f64 {
        self.dt
    }

    /// Simulated time of environment `i` (s).
    ///
    /// # Panics
    /// If `i` is not below [`VecEnv::len`].
    pub fn time(&self, i: usize) -> f64 {
        self.envs[i].sim.world().time()
    }

    /// Starts a new episode of environment `i` from `start` and writes its first observation
    /// into `observation` (`observation_len` values): the world's snapshot as loaded restored,
    /// the car placed and set moving, its cruise control at the start speed, one basic time
    /// step for the devices' first sample.
    ///
    /// # Errors
    /// [`VecEnvError::UnknownEnv`] for `i` out of range; [`VecEnvError::Buffer`] for an
    /// `observation` of another length; [`VecEnvError::Start`] or [`VecEnvError::Sim`] for a
    /// start out of range (not finite, beyond the world, too fast); a physics failure.
    pub fn reset(
        &mut self,
        i: usize,
        start: &Start,
        observation: &mut [f32],
    ) -> Result<(), VecEnvError> {
        let expected = self.task.observation_len();
        if observation.len() != expected {
            return Err(VecEnvError::Buffer {
                name: "observation",
                len: observation.len(),
                expected,
            });
        }
        let task = self.task;
        let env = self.envs.get_mut(i).ok_or(VecEnvError::UnknownEnv(i))?;
        env.reset(task, start)?;
        env.observe(task, observation)
    }

    /// One step of every environment: environment `i` takes row `i` of `actions`
    /// (`N × ACTION_LEN`, each clipped to −1 to 1), or is reset to `starts[i]` where
    /// `reset[i]` (autoreset, `NEXT_STEP` mode). Fills `out`.
    ///
    /// # Errors
    /// [`VecEnvError::Buffer`] naming the buffer whose length does not fit, or
    /// [`VecEnvError::Action`] for an action value that is not finite (nothing is stepped
    /// then); a refused start or a physics failure (the environments before it have stepped).
    pub fn step(
        &mut self,
        actions: &[f64],
        reset: &[bool],
        starts: &[Start],
        out: StepOut<'_>,
    ) -> Result<(), VecEnvError> {
        let n = self.envs.len();
        let m = self.task.observation_len();
        for (name, len, want) in [
            ("actions", actions.len(), n * ACTION_LEN),
            ("reset", reset.len(), n),
            ("starts", starts.len(), n),
            ("observations", out.observations.len(), n * m),
            ("rewards", out.rewards.len(), n),
            ("terminated", out.terminated.len(), n),
            ("truncated", out.truncated.len(), n),
        ] {
            if len != want {
                return Err(VecEnvError::Buffer {
                    name,
                    len,
                    expected: want,
                });
            }
        }
        if let Some((k, &value)) = actions.iter().enumerate().find(|(_, a)| !a.is_finite()) {
            return Err(VecEnvError::Action {
                env: k / ACTION_LEN,
                index: k % ACTION_LEN,
                value,
            });
        }
        let (task, frame_skip, dt) = (self.task, self.frame_skip, self.dt);
        for (i, env) in self.envs.iter_mut().enumerate() {
            let obs = &mut out.observations[i * m..(i + 1) * m];
            if reset[i] {
                env.reset(task, &starts[i])?;
                env.observe(task, obs)?;
                out.rewards[i] = 0.0;
                out.terminated[i] = false;
                out.truncated[i] = false;
                continue;
            }
            let a = [
                actions[i * ACTION_LEN].clamp(-1.0, 1.0),
                actions[i * ACTION_LEN + 1].clamp(-1.0, 1.0),
            ];
            let (reward, terminated, truncated) = env.step(task, frame_skip, dt, a, obs)?;
            out.rewards[i] = reward;
            out.terminated[i] = terminated;
            out.truncated[i] = truncated;
        }
        Ok(())
    }
}

/// `v` as an observation value: NaN as 0, within ±`bound` (the space's limits), rounded to
/// `f32` (numpy's `nan_to_num`, `clip` and `astype(float32)`).
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

/// Python's `x ** 2` on floats: C's `pow`, which `powi` (a multiplication) need not equal
/// to the last bit.
fn square(x: f64) -> f64 {
    x.powf(2.0)
}

/// Wraps a [`SimError`] of environment `env`.
fn sim_failure(env: usize) -> impl Fn(SimError) -> VecEnvError {
    move |source| VecEnvError::Sim { env, source }
}

impl Env {
    fn reset(&mut self, task: Task, start: &Start) -> Result<(), VecEnvError> {
        let fail = sim_failure(self.index);
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
        self.sim
            .restore(&self.start)
            .map_err(|source| VecEnvError::Restore {
                env: self.index,
                source,
            })?;
        let q = rotation_from_axis_angle([0.0, 0.0, 1.0, start.yaw])
            .map_err(|e| fail(SimError::Param(e)))?;
        let world = self.sim.world_mut();
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
        let driver = self.sim.driver_mut(self.car).map_err(&fail)?;
        driver.set_cruising_speed(self.target * 3.6);
        driver.set_steering_angle(0.0);
        if task == Task::Acc {
            let lead = self.cars[0];
            self.sim
                .world_mut()
                .set_vehicle_velocity(
                    lead,
                    &Vector3::new(start.lead_speed, 0.0, 0.0),
                    &Vector3::zeros(),
                )
                .map_err(&fail)?;
            self.sim
                .driver_mut(lead)
                .map_err(&fail)?
                .set_cruising_speed(start.lead_speed * 3.6);
        }
        self.sim.step().map_err(fail)
    }

    /// The step of `gym.py`'s `VehicleEnv.step`: returns reward, terminated, truncated.
    fn step(
        &mut self,
        task: Task,
        frame_skip: u32,
        dt: f64,
        a: [f64; ACTION_LEN],
        obs: &mut [f32],
    ) -> Result<(f64, bool, bool), VecEnvError> {
        let fail = sim_failure(self.index);
        let driver = self.sim.driver_mut(self.car).map_err(&fail)?;
        driver.set_steering_angle(a[0] * MAX_STEERING);
        self.target = (self.target + a[1] * MAX_ACCELERATION * dt).clamp(0.0, MAX_SPEED);
        driver.set_cruising_speed(self.target * 3.6);
        for _ in 0..frame_skip {
            if self.sim.is_over() {
                break;
            }
            self.sim.step().map_err(&fail)?;
        }
        self.observe(task, obs)?;
        let f = |k: usize| f64::from(obs[k]);
        let touching = task == Task::Acc && self.touching().map_err(&fail)?;
        let (reward, ended) = match task {
            Task::LaneKeep => {
                let (offset, heading, width, on_road) = (f(5), f(6), f(9), f(10));
                let reward = if on_road < 0.5 {
                    -10.0
                } else {
                    (f(0) * heading.cos()).min(30.0) / 30.0 - offset * offset - 0.1 * square(a[0])
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
                    -square(gap - 2.0) - 0.1 * square(a[1])
                };
                (reward, touching)
            }
            Task::Track => {
                let off = f(5);
                let reward = 1.0 - off.abs() - (f(0) - TRACK_SPEED).abs() / 10.0;
                (reward, off.abs() > 10.0)
            }
        };
        let rolled = self.rolled_over().map_err(fail)?;
        Ok((reward, rolled || ended, self.sim.is_over()))
    }

    /// True while the agent's car touches another car.
    fn touching(&self) -> Result<bool, SimError> {
        let world = self.sim.world();
        for &other in self.cars.iter().filter(|&&c| c != self.car) {
            if world.vehicles_in_contact(self.car, other)? {
                return Ok(true);
            }
        }
        Ok(false)
    }

    /// The car's up axis tilted more than 60° from vertical.
    fn rolled_over(&self) -> Result<bool, SimError> {
        let [_, _, z, angle] = self.sim.world().vehicle_placement(self.car)?.axis_angle();
        let c = angle.cos();
        Ok(c + z * z * (1.0 - c) < 0.5)
    }

    /// Writes the observation of `gym.py`'s `_observation` into `obs`.
    fn observe(&self, task: Task, obs: &mut [f32]) -> Result<(), VecEnvError> {
        let fail = sim_failure(self.index);
        let p = self
            .sim
            .world()
            .vehicle_placement(self.car)
            .map_err(&fail)?;
        let rotation = p.axis_angle();
        let yaw = yaw_of(rotation);
        let (vx, vy) = (p.velocity.x, p.velocity.y);
        let forward = vx * yaw.cos() + vy * yaw.sin();
        let lateral = -vx * yaw.sin() + vy * yaw.cos();
        let steering = self.sim.driver(self.car).map_err(&fail)?.steering_angle();
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
        let devices = self.sim.devices(self.car).map_err(fail)?;
        match task {
            Task::LaneKeep => {
                let road = devices.iter().find_map(|d| match d.reading() {
                    Reading::Road(r) => Some(r),
                    _ => None,
                });
                rest.fill(0.0);
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
                // Python's `sorted` of the rows: lexicographic, stable.
                targets.sort_by(|a, b| a.partial_cmp(b).unwrap_or(std::cmp::Ordering::Equal));
                rest.fill(0.0);
                let (radar, mask) = rest.split_at_mut(RADAR_TARGETS * 4);
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

/// Track-v0's circle: radius (m), centre (m) and the speed its reward asks for (m/s).
const TRACK_RADIUS: f64 = 30.0;
const TRACK_CENTRE: (f64, f64) = (0.0, 30.0);
const TRACK_SPEED: f64 = 10.0;
