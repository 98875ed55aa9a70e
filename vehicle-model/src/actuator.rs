//! Webots motor semantics as per-step rules, for any host that moves a car's joints: a
//! simulator, a firmware plant model, a hardware-in-the-loop bench.
//!
//! Webots drives every joint of a car through a `RotationalMotor` in one of three modes:
//!
//! * **velocity control** (`wb_motor_set_position(INFINITY)` + `wb_motor_set_velocity`): the
//!   commanded velocity moves toward the target by at most `acceleration·dt` per step
//!   ([`VelocityRamp`]), then the physics engine tracks it within `maxTorque`; a car wheel's
//!   `maxTorque`, [`WHEEL_MOTOR_MAX_TORQUE`], is never reached, so the ramped command is the
//!   wheel's speed;
//! * **position control** (`wb_motor_set_position`): each step the velocity command is
//!   `P·(target − position)` clamped to `maxVelocity` ([`PositionServo`]), reached within
//!   `maxTorque` against the load's inertia ([`SteeringMotor`] for the front wheels of an
//!   `AckermannVehicle`);
//! * **torque control** (`wb_motor_set_torque`): a torque about the joint axis; a car wheel in
//!   torque mode or rolling freely also loses speed to `wheelsDampingConstant`
//!   ([`WheelSpin`]).
//!
//! The brakes are dry friction ([`coulomb_torque`], from [`powertrain`]).
//!
//! Every rule is generic over [`Real`], allocates nothing and never panics; a NaN or infinite
//! command is ignored or replaced as each item documents, so it never reaches the state.
//!
//! ```
//! use vehicle_model::actuator::{PositionServo, SteeringMotor, SteeringState, VelocityRamp};
//!
//! // A wheel motor in speed mode: 4 rad/s² from rest, 0.5 s steps.
//! let mut ramp = VelocityRamp::<f32>::default();
//! assert_eq!(ramp.step(10.0, 4.0, 100.0, 0.5), 2.0); // rad/s
//!
//! // A steering motor of 10 N·m on a wheel of 2 kg·m² about its steering axis, 50 ms steps:
//! // the servo asks 10·(0.2 − 0) = 2 rad/s, the torque allows 10·0.05/2 = 0.25 rad/s of change.
//! let motor = SteeringMotor {
//!     servo: PositionServo::steering(-0.5, 0.5),
//!     max_torque: 10.0_f64,
//!     inertia: 2.0,
//! };
//! let next = motor.step(SteeringState::default(), 0.2, 0.05);
//! assert_eq!(next, SteeringState { angle: 0.0125, rate: 0.25 }); // rad, rad/s
//! ```

use ackermann::Real;

pub use powertrain::coulomb_torque;

/// Webots `maxTorque` of the car wheel motors (N·m): the speed-mode motors are practically
/// unlimited, so `time0To100` is reached whatever the car's mass, as long as the tyres grip.
pub const WHEEL_MOTOR_MAX_TORQUE: f64 = 1e8;

/// Webots default proportional gain of a motor's position controller (`controlPID 10 0 0`), 1/s.
pub const POSITION_P_GAIN: f64 = 10.0;

/// Webots default `maxVelocity` of a `RotationalMotor` (rad/s): the steering motors' speed cap.
pub const DEFAULT_MAX_VELOCITY: f64 = 10.0;

/// The commanded velocity of a Webots motor in velocity control with an `acceleration` limit.
///
/// Webots (`WbMotor`): each step the velocity sent to the physics engine moves toward the
/// target by at most `acceleration·dt`, never overshooting; an `acceleration` of −1 (or any
/// non-positive or non-finite value) means "no limit". The target is clamped to
/// `±maxVelocity` first (Webots prints `The requested velocity X exceeds 'maxVelocity' = M.`).
///
/// ```
/// use vehicle_model::actuator::VelocityRamp;
/// let mut ramp = VelocityRamp::default();
/// // Target 10 rad/s, 4 rad/s² limit, 0.5 s steps: 2 rad/s per step.
/// assert_eq!(ramp.step(10.0_f64, 4.0, 100.0, 0.5), 2.0);
/// assert_eq!(ramp.step(10.0, 4.0, 100.0, 0.5), 4.0);
/// // The clamp at maxVelocity applies to the target.
/// assert_eq!(ramp.step(10.0, -1.0, 5.0, 0.5), 5.0);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct VelocityRamp<T: Real> {
    command: T,
}

impl<T: Real> VelocityRamp<T> {
    /// A ramp whose current command is `velocity` (rad/s), e.g. the measured joint speed when a
    /// motor enters velocity control.
    pub const fn starting_at(velocity: T) -> Self {
        VelocityRamp { command: velocity }
    }

    /// The velocity command of the last step (rad/s).
    pub const fn command(&self) -> T {
        self.command
    }

    /// Advances one step of `dt` seconds toward `target` (rad/s) with the acceleration limit
    /// `acceleration` (rad/s²; non-positive or non-finite = unlimited) and the clamp
    /// `max_velocity` (rad/s, applied as `±|max_velocity|`; non-finite = no clamp), and returns
    /// the new command (rad/s).
    ///
    /// A non-finite target leaves the command unchanged, so NaN never enters the state; an
    /// update that overflows (both near the largest float) takes the target.
    pub fn step(&mut self, target: T, acceleration: T, max_velocity: T, dt: T) -> T {
        if !target.is_finite() {
            return self.command;
        }
        let target = if max_velocity.is_finite() {
            let m = max_velocity.abs();
            target.clamp(-m, m)
        } else {
            target
        };
        self.command = if acceleration.is_finite() && acceleration > T::ZERO && dt > T::ZERO {
            let max_step = acceleration * dt;
            // Only commands and steps near the largest float overflow; then go to the target.
            (self.command + (target - self.command).clamp(-max_step, max_step)).finite_or(target)
        } else {
            target
        };
        self.command
    }
}

/// The position controller of a Webots motor: a proportional velocity command toward a target
/// clamped to the motor's position range, then clamped to the motor's `maxVelocity`.
///
/// ```
/// use vehicle_model::actuator::PositionServo;
/// let servo = PositionServo::steering(-0.5, 0.5);
/// // 10·(0.2 − 0) = 2 rad/s toward the target.
/// assert_eq!(servo.velocity(0.2_f64, 0.0), 2.0);
/// // The target is clamped to maxPosition 0.5 and the speed to 10 rad/s.
/// assert_eq!(servo.velocity(3.0, -1.0), 10.0);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PositionServo<T: Real> {
    /// Proportional gain (1/s). Webots: `controlPID` P.
    pub gain: T,
    /// Speed cap (rad/s, ≥ 0). Webots: `maxVelocity`.
    pub max_velocity: T,
    /// Lowest reachable position (rad). Webots: `minPosition`.
    pub min_position: T,
    /// Highest reachable position (rad, ≥ `min_position`). Webots: `maxPosition`.
    pub max_position: T,
}

impl<T: Real> PositionServo<T> {
    /// The Webots steering motor of an `AckermannVehicle`: P = [`POSITION_P_GAIN`] (10 1/s),
    /// [`DEFAULT_MAX_VELOCITY`] (10 rad/s), limits `[min_steering_angle, max_steering_angle]`
    /// (rad).
    pub fn steering(min_steering_angle: T, max_steering_angle: T) -> Self {
        PositionServo {
            gain: T::from_f64(POSITION_P_GAIN),
            max_velocity: T::from_f64(DEFAULT_MAX_VELOCITY),
            min_position: min_steering_angle,
            max_position: max_steering_angle,
        }
    }

    /// The target (rad) clamped to the position range (rad); a non-finite target maps to
    /// `position` (rad, hold), so NaN never reaches the joint.
    pub fn clamp_target(&self, target: T, position: T) -> T {
        if target.is_finite() {
            target.clamp(self.min_position, self.max_position)
        } else {
            position
        }
    }

    /// The velocity command (rad/s) that moves `position` (rad) toward `target` (rad); 0 when
    /// the product `gain·error` is not finite.
    pub fn velocity(&self, target: T, position: T) -> T {
        let error = self.clamp_target(target, position) - position;
        let v = self.gain * error;
        if v.is_finite() {
            v.clamp(-self.max_velocity, self.max_velocity)
        } else {
            T::ZERO
        }
    }
}

/// The angle and rate of a steering joint (Webots: the `Hinge2Joint` of a front wheel).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct SteeringState<T: Real> {
    /// Steering angle (rad, positive = right).
    pub angle: T,
    /// Steering rate (rad/s, positive = turning right).
    pub rate: T,
}

/// A steering motor of an `AckermannVehicle` turning one front wheel: the Webots position
/// controller's velocity command, reached within `maxSteeringTorque` against the wheel's
/// inertia about the steering axis, the angle kept within the motor's limits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SteeringMotor<T: Real> {
    /// The position controller; its limits are `[minSteeringAngle, maxSteeringAngle]` (rad).
    pub servo: PositionServo<T>,
    /// Torque of the motor (N·m, ≥ 0; +∞ = reaches any rate at once). Webots:
    /// `maxSteeringTorque`.
    pub max_torque: T,
    /// Inertia of the wheel about its steering axis (kg·m², > 0).
    pub inertia: T,
}

impl<T: Real> SteeringMotor<T> {
    /// One step of `dt` seconds from `state` toward `target` (rad).
    ///
    /// The rate (rad/s) moves toward the servo's velocity command by at most
    /// `max_torque·dt/inertia`; the angle advances by `rate·dt` and is clamped to the servo's
    /// limits, where the rate drops to 0 (the joint stop absorbs it). A non-finite target holds
    /// the angle (the servo commands 0 rad/s). A NaN torque limit (0/0) or a negative one
    /// counts as 0: the rate cannot change. A non-finite or non-positive `dt` leaves the state
    /// unchanged.
    pub fn step(&self, state: SteeringState<T>, target: T, dt: T) -> SteeringState<T> {
        if !(dt.is_finite() && dt > T::ZERO) {
            return state;
        }
        let command = self.servo.velocity(target, state.angle);
        let max_change = (self.max_torque * dt / self.inertia).max(T::ZERO);
        let mut rate = state.rate + (command - state.rate).clamp(-max_change, max_change);
        let next = state.angle + rate * dt;
        let angle = next.clamp(self.servo.min_position, self.servo.max_position);
        if angle != next {
            rate = T::ZERO;
        }
        SteeringState { angle, rate }
    }
}

/// The spin of a car wheel in torque mode or rolling freely, before the tyre and brake forces:
/// the drive torque (Webots `wb_motor_set_torque`) and the wheel joint's viscous damping
/// (Webots `wheelsDampingConstant`).
///
/// ```
/// use vehicle_model::actuator::WheelSpin;
/// let wheel = WheelSpin { inertia: 2.0_f64, damping: 4.0 };
/// // (10 + 8·0.5/2) / (1 + 4·0.5/2) = 12 / 2 = 6 rad/s.
/// assert_eq!(wheel.step(10.0, 8.0, 0.5), 6.0);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelSpin<T: Real> {
    /// Inertia of the wheel about its axle (kg·m², > 0).
    pub inertia: T,
    /// Viscous damping of the wheel joint (N·m·s/rad, ≥ 0). Webots: `wheelsDampingConstant`.
    pub damping: T,
}

impl<T: Real> WheelSpin<T> {
    /// The spin (rad/s) after one step of `dt` seconds from `omega` (rad/s) under
    /// `drive_torque` (N·m, positive = forward): `(ω + τ·dt/I) / (1 + c·dt/I)`.
    ///
    /// The damping is implicit (evaluated at the end of the step), so even a large
    /// `c·dt/I` slows the wheel toward 0 without reversing it. The torque is clamped to
    /// ±[`WHEEL_MOTOR_MAX_TORQUE`] (the motor's `maxTorque`); a non-finite torque counts as 0.
    /// A negative or NaN damping counts as 0. With a non-positive or NaN inertia, a
    /// non-positive or non-finite `dt`, or a result that is not finite, `omega` is returned.
    pub fn step(&self, omega: T, drive_torque: T, dt: T) -> T {
        if !(self.inertia > T::ZERO && dt.is_finite() && dt > T::ZERO) {
            return omega;
        }
        let max = T::from_f64(WHEEL_MOTOR_MAX_TORQUE);
        let torque = if drive_torque.is_finite() {
            drive_torque.clamp(-max, max)
        } else {
            T::ZERO
        };
        let damping = self.damping.max(T::ZERO);
        let next = (omega + torque * dt / self.inertia) / (T::ONE + damping * dt / self.inertia);
        next.finite_or(omega)
    }
}

#[cfg(test)]
mod tests;
