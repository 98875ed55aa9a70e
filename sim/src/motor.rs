//! Webots motor semantics, as per-step computations.
//!
//! Webots drives every joint through a `RotationalMotor` device in one of three modes:
//!
//! * **velocity control** (`wb_motor_set_position(INFINITY)` + `wb_motor_set_velocity`): the
//!   commanded velocity moves toward the target by at most `acceleration·dt` per step
//!   ([`VelocityRamp`]), then an ODE motor with `FMax = maxTorque` tracks it. A car wheel's
//!   spin is set to the ramped command (its `maxTorque`, [`WHEEL_MOTOR_MAX_TORQUE`], is never
//!   reached); a DifferentialWheels hinge gets a rigid rapier velocity motor (ForceBased,
//!   damping [`RIGID_DAMPING`]) whose `max_force` is the motor's maximum torque;
//! * **position control** (`wb_motor_set_position`): each step the velocity command is
//!   `P·(target − position)` clamped to `maxVelocity` ([`PositionServo`]), reached within
//!   `maxTorque` (the car's steering, the wipers);
//! * **torque control** (`wb_motor_set_torque`): a torque about the joint axis with the equal and
//!   opposite reaction on the parent body (a car wheel's drive torque).

use rapier3d::prelude::{GenericJoint, JointAxis, MotorModel};

/// Webots `maxTorque` of the car wheel motors (N·m): the speed-mode motors are practically
/// unlimited, so `time0To100` is reached whatever the car's mass, as long as the tyres grip.
pub const WHEEL_MOTOR_MAX_TORQUE: f64 = 1e8;

/// Webots default proportional gain of a motor's position controller (`controlPID 10 0 0`), 1/s.
pub const POSITION_P_GAIN: f64 = 10.0;

/// Webots default `maxVelocity` of a `RotationalMotor` (rad/s): the steering motors' speed cap.
pub const DEFAULT_MAX_VELOCITY: f64 = 10.0;

/// Damping (N·m·s/rad, ForceBased) that makes a rapier velocity motor rigid.
///
/// rapier solves a velocity motor as an implicit damper `τ = d·(ω_target − ω)` whose impulse is
/// clamped at `max_force·dt`. With `d = 1e9` the compliance `1/(d·dt)` is about 1e-7 (kg·m²)⁻¹,
/// negligible against the inverse inertia of any wheel, so the motor reaches its target in one
/// step whenever `max_force` allows: the behaviour of an ODE `dParamVel`/`dParamFMax` motor.
pub const RIGID_DAMPING: f32 = 1.0e9;

/// The commanded velocity of a Webots motor in velocity control with an `acceleration` limit.
///
/// Webots (`WbMotor`): each step the velocity sent to the physics engine moves toward the
/// target by at most `acceleration·dt`, never overshooting; an `acceleration` of −1 (or any
/// non-positive or non-finite value) means "no limit". The target is clamped to
/// `±maxVelocity` first (Webots prints `The requested velocity X exceeds 'maxVelocity' = M.`).
///
/// ```
/// use sim::motor::VelocityRamp;
/// let mut ramp = VelocityRamp::default();
/// // Target 10 rad/s, 4 rad/s² limit, 0.5 s steps: 2 rad/s per step.
/// assert_eq!(ramp.step(10.0, 4.0, 100.0, 0.5), 2.0);
/// assert_eq!(ramp.step(10.0, 4.0, 100.0, 0.5), 4.0);
/// // The clamp at maxVelocity applies to the target.
/// assert_eq!(ramp.step(10.0, -1.0, 5.0, 0.5), 5.0);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct VelocityRamp {
    command: f64,
}

impl VelocityRamp {
    /// A ramp whose current command is `velocity` (rad/s), e.g. the measured joint speed when a
    /// motor enters velocity control.
    pub const fn starting_at(velocity: f64) -> Self {
        VelocityRamp { command: velocity }
    }

    /// The velocity command of the last step (rad/s).
    pub const fn command(&self) -> f64 {
        self.command
    }

    /// Advances one step of `dt` seconds toward `target` (rad/s) with the acceleration limit
    /// `acceleration` (rad/s²; non-positive or non-finite = unlimited) and the clamp
    /// `max_velocity` (rad/s, applied as `±|max_velocity|`; non-finite = no clamp), and returns
    /// the new command (rad/s).
    ///
    /// A non-finite target leaves the command unchanged, so NaN never enters the state.
    pub fn step(&mut self, target: f64, acceleration: f64, max_velocity: f64, dt: f64) -> f64 {
        if !target.is_finite() {
            return self.command;
        }
        let target = if max_velocity.is_finite() {
            let m = max_velocity.abs();
            target.clamp(-m, m)
        } else {
            target
        };
        self.command = if acceleration.is_finite() && acceleration > 0.0 && dt > 0.0 {
            let max_step = acceleration * dt;
            self.command + (target - self.command).clamp(-max_step, max_step)
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
/// use sim::motor::PositionServo;
/// let servo = PositionServo::steering(-0.5, 0.5);
/// // 10·(0.2 − 0) = 2 rad/s toward the target.
/// assert_eq!(servo.velocity(0.2, 0.0), 2.0);
/// // The target is clamped to maxPosition 0.5 and the speed to 10 rad/s.
/// assert_eq!(servo.velocity(3.0, -1.0), 10.0);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PositionServo {
    /// Proportional gain (1/s). Webots: `controlPID` P.
    pub gain: f64,
    /// Speed cap (rad/s). Webots: `maxVelocity`.
    pub max_velocity: f64,
    /// Lowest reachable position (rad). Webots: `minPosition`.
    pub min_position: f64,
    /// Highest reachable position (rad). Webots: `maxPosition`.
    pub max_position: f64,
}

impl PositionServo {
    /// The Webots steering motor of an `AckermannVehicle`: P = 10, 10 rad/s, limits
    /// `[min_steering_angle, max_steering_angle]` (rad).
    pub const fn steering(min_steering_angle: f64, max_steering_angle: f64) -> Self {
        PositionServo {
            gain: POSITION_P_GAIN,
            max_velocity: DEFAULT_MAX_VELOCITY,
            min_position: min_steering_angle,
            max_position: max_steering_angle,
        }
    }

    /// The target clamped to the position range (rad); a non-finite target maps to `position`
    /// (hold), so NaN never reaches the joint.
    pub fn clamp_target(&self, target: f64, position: f64) -> f64 {
        if target.is_finite() {
            target.clamp(self.min_position, self.max_position)
        } else {
            position
        }
    }

    /// The velocity command (rad/s) that moves `position` (rad) toward `target` (rad).
    pub fn velocity(&self, target: f64, position: f64) -> f64 {
        let error = self.clamp_target(target, position) - position;
        let v = self.gain * error;
        if v.is_finite() {
            v.clamp(-self.max_velocity, self.max_velocity)
        } else {
            0.0
        }
    }
}

/// Sets `axis` of `joint` to a rigid velocity motor: target `velocity` (rad/s or m/s) with at
/// most `max_force` (N·m or N, clamped to ≥ 0).
pub(crate) fn set_rigid_velocity_motor(
    joint: &mut GenericJoint,
    axis: JointAxis,
    velocity: f64,
    max_force: f64,
) {
    joint
        .set_motor_model(axis, MotorModel::ForceBased)
        .set_motor(axis, 0.0, velocity as f32, 0.0, RIGID_DAMPING)
        .set_motor_max_force(axis, max_force.max(0.0) as f32);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ramp_reaches_target_without_overshoot() {
        let mut r = VelocityRamp::default();
        // 10.61 rad/s² (BmwX5) × 0.01 s = 0.1061 rad/s per step.
        let a = 27.777_777_777_777_78 / 7.0 / 0.374;
        let target = 100.0 / 3.6 / 0.374; // 74.27 rad/s
        let mut steps = 0;
        while r.command() < target {
            r.step(target, a, 133.69, 0.01);
            steps += 1;
            assert!(r.command() <= target);
        }
        // 74.27 / 0.1061 = 700.0 steps: 7 s.
        assert!((699..=701).contains(&steps), "{steps}");
        assert_eq!(r.command(), target);
    }

    #[test]
    fn ramp_ignores_nan_and_goes_down() {
        let mut r = VelocityRamp::starting_at(5.0);
        assert_eq!(r.step(f64::NAN, 1.0, 10.0, 0.1), 5.0);
        assert_eq!(r.step(-5.0, 10.0, 10.0, 0.1), 4.0);
        assert_eq!(r.step(-20.0, f64::INFINITY, 10.0, 0.1), -10.0);
    }

    #[test]
    fn servo_clamps_and_holds_on_nan() {
        let s = PositionServo::steering(-0.6, 0.4);
        assert_eq!(s.velocity(f64::NAN, 0.3), 0.0);
        // Target clamped to −0.6: 10·(−0.6 − 0) = −6 rad/s.
        assert_eq!(s.velocity(-2.0, 0.0), -6.0);
        assert_eq!(s.clamp_target(0.5, 0.0), 0.4);
    }
}
