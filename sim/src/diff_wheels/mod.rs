//! The legacy Webots `DifferentialWheels` robot (deprecated in Webots R2018a): two wheels on an
//! axle, speed commands, incremental encoders, in kinematics or physics mode (spec §7).
//!
//! The robot lives in a [`World`](crate::World) ([`World::add_differential_wheels`](
//! crate::World::add_differential_wheels)); its controller-side API mirrors
//! `wb_differential_wheels_*` (spec §7.2) and takes effect at the next world step, as in Webots.
//!
//! Differences from Webots (also in `COMPATIBILITY.md`):
//! * wheel speeds are clamped to ±`maxSpeed` (Webots computes the clamp and drops the result);
//! * kinematics mode uses the FLU formulas of the newer `WbKinematicDifferentialWheels`
//!   (x forward, heading about +z) instead of the Y-up, forward = −z frame of the old node;
//! * kinematics mode has no collision response and no battery is simulated
//!   (`motorConsumption` is stored only);
//! * physics-mode encoders count the hinge rotation found with the measured wheel speed, so they
//!   stay correct above π rad per step where Webots' wrap into (−π, π] would alias;
//! * the noise comes from a seeded [`SplitMix64`](crate::rng::SplitMix64) per robot.

mod kinematic;
mod params;
mod physics;

use core::fmt;

use proto_geom::nalgebra::{Point3, Vector3};
use rapier3d::prelude::{PhysicsWorld, RigidBodyHandle};

pub use params::{DifferentialWheelsParams, RobotBody, RobotMode, RobotPlacement};

use crate::error::{BodyOwner, BodyPart, ParamError, SimError};
use crate::rng::SplitMix64;
use physics::PhysicsParts;

/// Handle of a DifferentialWheels robot in a [`World`](crate::World).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct RobotId(pub(crate) usize);

impl RobotId {
    /// The robot's index in its world (0 for the first robot added).
    pub const fn index(self) -> usize {
        self.0
    }
}

/// The planar pose of a robot.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RobotPose {
    /// Position of the robot origin (the ground projection of the axle midpoint), m, world
    /// frame.
    pub position: Point3<f64>,
    /// Continuous heading (rad, counter-clockwise about +z, not wrapped): the direction of
    /// forward motion.
    pub heading: f64,
}

/// What the Webots controller library would print for a DifferentialWheels call.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum RobotWarning {
    /// A NaN argument: the call was ignored.
    InvalidNan {
        /// The Webots function, e.g. `"wb_differential_wheels_set_speed"`.
        function: &'static str,
    },
    /// A speed command above `maxSpeed/speedUnit`: Webots prints this and still sends the
    /// command; the simulator then clamps the wheel speed to ±`maxSpeed`.
    SpeedOverflow {
        /// Commanded left speed (speed units).
        left: f64,
        /// Commanded right speed (speed units).
        right: f64,
        /// `maxSpeed` (rad/s).
        max_speed: f64,
        /// `speedUnit` (rad/s per unit).
        speed_unit: f64,
    },
    /// An infinite argument: the call was ignored, as the driver library's setters ignore
    /// one (Webots checks for NaN only and would pass ±∞ on to the motors).
    Infinite {
        /// The Webots function, e.g. `"wb_differential_wheels_set_speed"`.
        function: &'static str,
        /// The argument, `"left"` or `"right"`.
        argument: &'static str,
        /// The refused value (±∞).
        value: f64,
    },
    /// A negative encoder sampling period: the call was ignored.
    NegativePeriod {
        /// The rejected period (ms).
        period_ms: i32,
    },
}

/// The warning for a `(left, right)` pair of `function` that is not finite: Webots' NaN error,
/// or the refusal of ±∞ naming the argument; `None` when both are finite.
fn refuse_non_finite(function: &'static str, left: f64, right: f64) -> Option<RobotWarning> {
    if left.is_nan() || right.is_nan() {
        return Some(RobotWarning::InvalidNan { function });
    }
    [("left", left), ("right", right)]
        .into_iter()
        .find(|(_, v)| v.is_infinite())
        .map(|(argument, value)| RobotWarning::Infinite {
            function,
            argument,
            value,
        })
}

impl fmt::Display for RobotWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            RobotWarning::InvalidNan { function } => {
                write!(f, "{function}(): invalid NaN value passed as argument.")
            }
            RobotWarning::Infinite {
                function,
                argument,
                value,
            } => write!(
                f,
                "{function}() called with an invalid '{argument}' argument ({value})"
            ),
            RobotWarning::SpeedOverflow {
                left,
                right,
                max_speed,
                speed_unit,
            } => write!(
                f,
                "wb_differential_wheels_set_speed({left},{right}) overflows maxSpeed/speedUnit: \
                 {max_speed}/{speed_unit}={}.",
                max_speed / speed_unit
            ),
            RobotWarning::NegativePeriod { period_ms } => write!(
                f,
                "wb_differential_wheels_enable_encoders(): invalid negative sampling period \
                 {period_ms}."
            ),
        }
    }
}

impl std::error::Error for RobotWarning {}

#[derive(Debug, Clone)]
enum ModeState {
    /// Kinematics mode with the actual (acceleration-limited) wheel speeds, rad/s.
    Kinematics {
        actual: [f64; 2],
    },
    Physics(PhysicsParts),
}

/// A DifferentialWheels robot: node state (wheel speeds, pose, encoder accumulators) and the
/// controller-side state of `differential_wheels.c` (last commands, sampled encoders).
#[derive(Debug, Clone)]
pub struct DifferentialWheels {
    id: RobotId,
    params: DifferentialWheelsParams,
    state: ModeState,
    rng: SplitMix64,
    /// Last commanded speeds (speed units), NaN before the first command.
    command: [f64; 2],
    pending_encoders: Option<[f64; 2]>,
    encoder_period_ms: u32,
    last_sample_ms: u64,
    encoders: [f64; 2],
    sampled_encoders: [f64; 2],
    targets: [f64; 2],
    wheel_speeds: [f64; 2],
    wheel_angles: [f64; 2],
    pose: RobotPose,
    time_ms: u64,
    /// Webots' `radarCrossSection` of the robot's solid (m², ≥ 0; 0: radars do not see it).
    radar_cross_section: f64,
}

impl DifferentialWheels {
    pub(crate) fn new(
        id: RobotId,
        world: &mut PhysicsWorld,
        params: DifferentialWheelsParams,
        mode: RobotMode,
        placement: RobotPlacement,
        time_ms: u64,
    ) -> Result<Self, SimError> {
        params.validate()?;
        placement.validate()?;
        let state = match mode {
            RobotMode::Kinematics => ModeState::Kinematics { actual: [0.0; 2] },
            RobotMode::Physics(body) => {
                body.validate()?;
                ModeState::Physics(physics::build(world, &params, &body, &placement))
            }
        };
        Ok(DifferentialWheels {
            id,
            params,
            state,
            rng: SplitMix64::new(params.seed),
            command: [f64::NAN; 2],
            pending_encoders: None,
            encoder_period_ms: 0,
            last_sample_ms: time_ms,
            encoders: [0.0; 2],
            sampled_encoders: [0.0; 2],
            targets: [0.0; 2],
            wheel_speeds: [0.0; 2],
            wheel_angles: [0.0; 2],
            pose: RobotPose {
                position: Point3::new(placement.x, placement.y, placement.z),
                heading: placement.heading,
            },
            time_ms,
            radar_cross_section: 0.0,
        })
    }

    /// Its `radarCrossSection` (m², ≥ 0; 0, the default: radars do not see it).
    pub fn radar_cross_section(&self) -> f64 {
        self.radar_cross_section
    }

    /// Sets its `radarCrossSection` (m²).
    ///
    /// # Errors
    /// [`ParamError`] if `rcs` is negative or not finite (nothing changes).
    pub fn set_radar_cross_section(&mut self, rcs: f64) -> Result<(), ParamError> {
        self.radar_cross_section = ParamError::non_negative("radarCrossSection", rcs)?;
        Ok(())
    }

    /// Its rapier bodies (none in kinematics mode).
    pub(crate) fn bodies(&self) -> Vec<RigidBodyHandle> {
        match &self.state {
            ModeState::Physics(parts) => parts.bodies().to_vec(),
            ModeState::Kinematics { .. } => Vec::new(),
        }
    }

    /// The velocity of its origin (m/s, world): its body's in physics mode; in kinematics
    /// mode the one its wheels' last speeds give, `r·(ω_l + ω_r)/2` along its heading (before
    /// the slip noise, which moves the pose but is no speed of the robot's).
    pub(crate) fn velocity(&self, world: &PhysicsWorld) -> Vector3<f64> {
        match &self.state {
            ModeState::Physics(parts) => world
                .bodies
                .get(parts.bodies()[0])
                .map_or_else(Vector3::zeros, |b| crate::geom::to_vector(b.linvel())),
            ModeState::Kinematics { .. } => {
                let [l, r] = self.wheel_speeds;
                let v = self.params.wheel_radius * (l + r) / 2.0;
                let h = self.pose.heading;
                Vector3::new(v * h.cos(), v * h.sin(), 0.0)
            }
        }
    }

    /// This robot's handle.
    pub fn id(&self) -> RobotId {
        self.id
    }

    /// The node fields.
    pub fn params(&self) -> &DifferentialWheelsParams {
        &self.params
    }

    /// True in physics mode, false in kinematics mode.
    pub fn is_physics(&self) -> bool {
        matches!(self.state, ModeState::Physics(_))
    }

    /// Commands both wheel speeds (speed units: `speedUnit` rad/s each), applied from the next
    /// step. Webots: `wb_differential_wheels_set_speed(left, right)`.
    ///
    /// Returns the message Webots would print, if any: a NaN argument ignores the call; a speed
    /// above `maxSpeed/speedUnit` is still applied (and then clamped to `maxSpeed`).
    pub fn set_speed(&mut self, left: f64, right: f64) -> Option<RobotWarning> {
        if let Some(w) = refuse_non_finite("wb_differential_wheels_set_speed", left, right) {
            return Some(w);
        }
        self.command = [left, right];
        let p = &self.params;
        // Webots checks the positive side only, with a 0.99999 tolerance.
        let over = |s: f64| s * p.speed_unit * 0.99999 > p.max_speed;
        (over(left) || over(right)).then_some(RobotWarning::SpeedOverflow {
            left,
            right,
            max_speed: p.max_speed,
            speed_unit: p.speed_unit,
        })
    }

    /// The last commanded left speed (speed units), NaN before the first command.
    /// Webots: `wb_differential_wheels_get_left_speed`.
    pub fn left_speed(&self) -> f64 {
        self.command[0]
    }

    /// The last commanded right speed (speed units), NaN before the first command.
    /// Webots: `wb_differential_wheels_get_right_speed`.
    pub fn right_speed(&self) -> f64 {
        self.command[1]
    }

    /// `maxSpeed` (rad/s). Webots: `wb_differential_wheels_get_max_speed`.
    pub fn max_speed(&self) -> f64 {
        self.params.max_speed
    }

    /// `speedUnit` (rad/s per unit). Webots: `wb_differential_wheels_get_speed_unit`.
    pub fn speed_unit(&self) -> f64 {
        self.params.speed_unit
    }

    /// Enables the encoder readings every `period_ms` ms (0 disables them); the first reading
    /// arrives once the first period has elapsed. Webots:
    /// `wb_differential_wheels_enable_encoders`. A negative period is ignored with a warning.
    pub fn enable_encoders(&mut self, period_ms: i32) -> Option<RobotWarning> {
        match u32::try_from(period_ms) {
            Ok(p) => {
                self.encoder_period_ms = p;
                self.last_sample_ms = self.time_ms;
                None
            }
            Err(_) => Some(RobotWarning::NegativePeriod { period_ms }),
        }
    }

    /// Stops the encoder readings. Webots: `wb_differential_wheels_disable_encoders`.
    pub fn disable_encoders(&mut self) {
        self.encoder_period_ms = 0;
    }

    /// The encoder sampling period (ms), 0 when disabled. Webots:
    /// `wb_differential_wheels_get_encoders_sampling_period`.
    pub fn encoders_sampling_period(&self) -> u32 {
        self.encoder_period_ms
    }

    /// The last sampled left encoder value (increments). Webots prints an error when the
    /// encoders are disabled ([`Self::encoders_sampling_period`] = 0) and still returns the
    /// cached value, as this does. Webots: `wb_differential_wheels_get_left_encoder`.
    pub fn left_encoder(&self) -> f64 {
        self.sampled_encoders[0]
    }

    /// The last sampled right encoder value (increments). Webots:
    /// `wb_differential_wheels_get_right_encoder`.
    pub fn right_encoder(&self) -> f64 {
        self.sampled_encoders[1]
    }

    /// Overwrites both encoder accumulators at the next step (before that step's increment).
    /// Webots: `wb_differential_wheels_set_encoders`. NaN ignores the call with a warning.
    pub fn set_encoders(&mut self, left: f64, right: f64) -> Option<RobotWarning> {
        if let Some(w) = refuse_non_finite("wb_differential_wheels_set_encoders", left, right) {
            return Some(w);
        }
        self.pending_encoders = Some([left, right]);
        None
    }

    /// The node's encoder accumulators right now (increments, `[left, right]`), whatever the
    /// sampling period: ground truth for tests and telemetry.
    pub fn raw_encoders(&self) -> [f64; 2] {
        self.encoders
    }

    /// The wheel speed targets of the last step (rad/s, `[left, right]`): the commands times
    /// `speedUnit`, clamped to ±`maxSpeed`.
    pub fn targets(&self) -> [f64; 2] {
        self.targets
    }

    /// The wheel speeds of the last step (rad/s, `[left, right]`): in kinematics mode the
    /// acceleration-limited speeds before slip noise, in physics mode the measured hinge speeds.
    pub fn wheel_speeds(&self) -> [f64; 2] {
        self.wheel_speeds
    }

    /// The continuous wheel rotation angles since the start (rad, `[left, right]`, positive =
    /// rolling forward).
    pub fn wheel_angles(&self) -> [f64; 2] {
        self.wheel_angles
    }

    /// The largest wheel rotation (rad) of the last step in physics mode (0 in kinematics
    /// mode, which has no contacts).
    pub(crate) fn max_wheel_rotation(&self, dt: f64) -> f64 {
        if self.is_physics() {
            self.wheel_speeds[0].abs().max(self.wheel_speeds[1].abs()) * dt
        } else {
            0.0
        }
    }

    /// The robot pose after the last step.
    pub fn pose(&self) -> RobotPose {
        self.pose
    }

    /// Applies the controller's messages and, in kinematics mode, moves the robot; in physics
    /// mode, commands the hinge motors. Called by the world before the physics step.
    pub(crate) fn pre_step(&mut self, world: &mut PhysicsWorld, dt: f64) {
        if let Some(e) = self.pending_encoders.take() {
            self.encoders = e;
        }
        let p = self.params;
        self.targets = self.command.map(|c| {
            let t = if c.is_finite() {
                c * p.speed_unit
            } else if c.is_nan() {
                0.0
            } else {
                c.signum() * p.max_speed
            };
            t.clamp(-p.max_speed, p.max_speed)
        });
        match &mut self.state {
            ModeState::Kinematics { actual } => {
                let n = kinematic::step(
                    actual,
                    self.targets,
                    p.max_acceleration,
                    p.slip_noise,
                    p.wheel_radius,
                    p.axle_length,
                    dt,
                    &mut self.pose,
                    &mut self.rng,
                );
                self.wheel_speeds = *actual;
                self.count(n.map(|s| s * dt));
            }
            ModeState::Physics(parts) => physics::command(world, parts, self.targets, p.max_force),
        }
    }

    /// Which part of this robot the rapier body `handle` is, if any (kinematic robots have no
    /// bodies).
    pub(crate) fn part_of(&self, handle: RigidBodyHandle) -> Option<BodyPart> {
        match &self.state {
            ModeState::Physics(parts) => parts.part_of(handle),
            _ => None,
        }
    }

    /// Reads the physics-mode results and samples the encoders. Called by the world after the
    /// physics step, with the time at the end of the step.
    pub(crate) fn post_step(
        &mut self,
        world: &PhysicsWorld,
        dt: f64,
        time_ms: u64,
    ) -> Result<(), SimError> {
        self.time_ms = time_ms;
        if let ModeState::Physics(parts) = &mut self.state {
            let m = physics::measure(world, parts, self.pose.heading, dt)
                .map_err(SimError::diverged(BodyOwner::Robot(self.id.0), time_ms))?;
            self.wheel_speeds = m.speeds;
            self.pose = m.pose;
            self.count(m.deltas);
        }
        if self.encoder_period_ms > 0
            && time_ms.saturating_sub(self.last_sample_ms) >= u64::from(self.encoder_period_ms)
        {
            self.sampled_encoders = self.encoders;
            self.last_sample_ms = time_ms;
        }
        Ok(())
    }

    /// Adds one step's wheel rotations (rad) to the wheel angles and, if the node has encoders,
    /// to the encoder accumulators with the encoder noise.
    fn count(&mut self, deltas: [f64; 2]) {
        for (angle, d) in self.wheel_angles.iter_mut().zip(deltas) {
            *angle += d;
        }
        let p = self.params;
        if p.has_encoders() {
            for (e, d) in self.encoders.iter_mut().zip(deltas) {
                let d = if p.encoder_noise != 0.0 {
                    d * self.rng.noise_factor(p.encoder_noise)
                } else {
                    d
                };
                *e += p.encoder_resolution * d;
            }
        }
    }
}
