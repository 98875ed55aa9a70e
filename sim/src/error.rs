//! Errors of the simulator: invalid parameters at construction, unknown handles, and a physics
//! state that stopped being finite.

use ackermann::Wheel;

/// A parameter rejected at construction: the field (Webots field name where there is one) and
/// the offending value.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[error("invalid {field} = {value}: must be {rule}")]
pub struct ParamError {
    /// The field, e.g. `"basicTimeStep"`, `"ground.friction"`, `"wheelRadius"`.
    pub field: &'static str,
    /// The rejected value (NaN and ±∞ included).
    pub value: f64,
    /// What the field must satisfy, e.g. `"> 0"`.
    pub rule: &'static str,
}

impl ParamError {
    /// Checks `value` with `ok`, returning it or a [`ParamError`] naming `field`.
    pub(crate) fn check(
        field: &'static str,
        value: f64,
        rule: &'static str,
        ok: impl FnOnce(f64) -> bool,
    ) -> Result<f64, ParamError> {
        if ok(value) {
            Ok(value)
        } else {
            Err(ParamError { field, value, rule })
        }
    }

    /// `value` must be finite and > 0.
    pub(crate) fn positive(field: &'static str, value: f64) -> Result<f64, ParamError> {
        Self::check(field, value, "finite and > 0", |v| v.is_finite() && v > 0.0)
    }

    /// `value` must be finite and ≥ 0.
    pub(crate) fn non_negative(field: &'static str, value: f64) -> Result<f64, ParamError> {
        Self::check(field, value, "finite and >= 0", |v| {
            v.is_finite() && v >= 0.0
        })
    }

    /// `value` must be finite.
    pub(crate) fn finite(field: &'static str, value: f64) -> Result<f64, ParamError> {
        Self::check(field, value, "finite", f64::is_finite)
    }
}

/// A part of a simulated object, named in [`SimError::NonFinite`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BodyPart {
    /// A car's chassis body.
    Chassis,
    /// A car wheel.
    Wheel(Wheel),
    /// The steering knuckle of a front wheel of a car on joints.
    Knuckle(Wheel),
    /// The body of a DifferentialWheels robot.
    RobotBody,
    /// The left wheel of a DifferentialWheels robot.
    LeftWheel,
    /// The right wheel of a DifferentialWheels robot.
    RightWheel,
    /// A body that belongs to no vehicle or robot.
    Other,
}

/// What owns a body named in [`SimError::NonFinite`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum BodyOwner {
    /// The car with this index ([`crate::VehicleId::index`]).
    Vehicle(usize),
    /// The DifferentialWheels robot with this index ([`crate::RobotId::index`]).
    Robot(usize),
    /// Nothing the simulator created on behalf of a vehicle or robot.
    World,
}

/// A simulator error.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum SimError {
    /// A parameter was rejected; nothing was created.
    #[error("{0}")]
    Param(#[from] ParamError),
    /// A vehicle handle that this world did not issue.
    #[error("no vehicle with index {0} in this world")]
    UnknownVehicle(usize),
    /// A robot handle that this world did not issue.
    #[error("no robot with index {0} in this world")]
    UnknownRobot(usize),
    /// A body's pose or velocity stopped being finite (or rapier quarantined it) during the step
    /// that ended at `time_ms`. The world refuses to step any further.
    #[error(
        "non-finite physics state of {part:?} of {owner:?} at t = {time_ms} ms: the simulation \
         diverged"
    )]
    NonFinite {
        /// The owner of the body.
        owner: BodyOwner,
        /// The body.
        part: BodyPart,
        /// Simulated time at the end of the failed step (ms).
        time_ms: u64,
    },
    /// rapier refused a joint of a car on joints (it refuses joints that close a loop, which a
    /// car's tree of joints never does); nothing usable was created.
    #[error("rapier refused a joint of {0:?}")]
    JointRefused(BodyOwner),
}
