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
//!
//! The rules themselves are defined once, for every host, in [`vehicle_model::actuator`]; this
//! module names them in f64, the simulator's scalar, and adds what only rapier needs.

use rapier3d::prelude::{GenericJoint, JointAxis, MotorModel};

pub use vehicle_model::actuator::{DEFAULT_MAX_VELOCITY, POSITION_P_GAIN, WHEEL_MOTOR_MAX_TORQUE};

/// [`vehicle_model::actuator::VelocityRamp`] in f64: the commanded velocity of a Webots motor in
/// velocity control with an `acceleration` limit.
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
pub type VelocityRamp = vehicle_model::actuator::VelocityRamp<f64>;

/// [`vehicle_model::actuator::PositionServo`] in f64: the position controller of a Webots
/// motor.
///
/// ```
/// use sim::motor::PositionServo;
/// let servo = PositionServo::steering(-0.5, 0.5);
/// // 10·(0.2 − 0) = 2 rad/s toward the target.
/// assert_eq!(servo.velocity(0.2, 0.0), 2.0);
/// // The target is clamped to maxPosition 0.5 and the speed to 10 rad/s.
/// assert_eq!(servo.velocity(3.0, -1.0), 10.0);
/// ```
pub type PositionServo = vehicle_model::actuator::PositionServo<f64>;

/// Damping (N·m·s/rad, ForceBased) that makes a rapier velocity motor rigid.
///
/// rapier solves a velocity motor as an implicit damper `τ = d·(ω_target − ω)` whose impulse is
/// clamped at `max_force·dt`. With `d = 1e9` the compliance `1/(d·dt)` is about 1e-7 (kg·m²)⁻¹,
/// negligible against the inverse inertia of any wheel, so the motor reaches its target in one
/// step whenever `max_force` allows: the behaviour of an ODE `dParamVel`/`dParamFMax` motor.
pub const RIGID_DAMPING: f32 = 1.0e9;

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
