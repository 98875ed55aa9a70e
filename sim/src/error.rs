//! Errors of the simulator: invalid parameters at construction, unknown handles, and a physics
//! state that stopped being finite.

use core::fmt;

use ackermann::Wheel;
use proto_geom::Plausible;
use proto_geom::plausible::Compact;

/// A parameter rejected at construction: the field (Webots field name where there is one) and
/// the offending value.
#[derive(Debug, Clone, Copy, PartialEq, thiserror::Error)]
#[error("invalid {field} = {}: must be {rule}", Compact(*value))]
pub struct ParamError {
    /// The field, e.g. `"basicTimeStep"`, `"ground.friction"`, `"wheelRadius"`.
    pub field: &'static str,
    /// The rejected value (NaN and ±∞ included).
    pub value: f64,
    /// What the field must satisfy.
    pub rule: Rule,
}

/// What a [`ParamError`]'s field must satisfy. `Display` completes "must be …".
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Rule {
    /// A rule in words, e.g. `"finite and > 0"`.
    Text(&'static str),
    /// A plausible physical range ([`proto_geom::plausible`]).
    Within(Plausible),
    /// A lower bound that depends on another field: at least `bound` (in the field's unit),
    /// `why` saying what the bound is and why it holds, e.g. `"m, half the wheel's
    /// thickness: …"`.
    AtLeast {
        /// The bound, in the field's unit.
        bound: f64,
        /// The unit, what the bound is and its reason.
        why: &'static str,
    },
}

impl fmt::Display for Rule {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Rule::Text(t) => f.write_str(t),
            Rule::Within(range) => write!(f, "within {range}"),
            Rule::AtLeast { bound, why } => write!(f, "at least {} {why}", Compact(*bound)),
        }
    }
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
            Err(ParamError {
                field,
                value,
                rule: Rule::Text(rule),
            })
        }
    }

    /// `value` must lie in the plausible `range` (finite, bounds included).
    pub(crate) fn within(
        field: &'static str,
        value: f64,
        range: Plausible,
    ) -> Result<f64, ParamError> {
        if range.contains(value) {
            Ok(value)
        } else {
            Err(ParamError {
                field,
                value,
                rule: Rule::Within(range),
            })
        }
    }

    /// `value` must be finite and at least `bound` (another field's consequence, see
    /// [`Rule::AtLeast`]).
    pub(crate) fn at_least(
        field: &'static str,
        value: f64,
        bound: f64,
        why: &'static str,
    ) -> Result<f64, ParamError> {
        if value.is_finite() && value >= bound {
            Ok(value)
        } else {
            Err(ParamError {
                field,
                value,
                rule: Rule::AtLeast { bound, why },
            })
        }
    }

    /// `value` must be a friction coefficient the physics honours: finite and ≥ 0, and within
    /// [`proto_geom::plausible::FRICTION`] (see there why).
    pub(crate) fn friction(field: &'static str, value: f64) -> Result<f64, ParamError> {
        Self::non_negative(field, value)?;
        Self::within(field, value, proto_geom::plausible::FRICTION)
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
    /// The body of a DifferentialWheels robot.
    RobotBody,
    /// The left wheel of a DifferentialWheels robot.
    LeftWheel,
    /// The right wheel of a DifferentialWheels robot.
    RightWheel,
    /// The `[[body]]` box with this index (0-based, in world-file order).
    Box(usize),
    /// A body that belongs to no vehicle or robot.
    Other,
}

impl fmt::Display for BodyPart {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let wheel = |w: &Wheel| match w {
            Wheel::FrontRight => "front-right",
            Wheel::FrontLeft => "front-left",
            Wheel::RearRight => "rear-right",
            Wheel::RearLeft => "rear-left",
        };
        match self {
            BodyPart::Chassis => f.write_str("chassis"),
            BodyPart::Wheel(w) => write!(f, "{} wheel", wheel(w)),
            BodyPart::RobotBody => f.write_str("body"),
            BodyPart::LeftWheel => f.write_str("left wheel"),
            BodyPart::RightWheel => f.write_str("right wheel"),
            BodyPart::Box(i) => write!(f, "box {}", i + 1),
            BodyPart::Other => f.write_str("a body"),
        }
    }
}

impl fmt::Display for BodyOwner {
    /// `car 1`, `robot 1` (1-based, as in a world file), `the world`.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            BodyOwner::Vehicle(i) => write!(f, "car {}", i + 1),
            BodyOwner::Robot(i) => write!(f, "robot {}", i + 1),
            BodyOwner::World => f.write_str("the world"),
        }
    }
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
    /// A road of the world's configuration is not a road (see [`RoadNetwork::validate`](crate::road::RoadNetwork::validate)),
    /// or its surface could not be made a collider; nothing was created.
    #[error("{0}")]
    Road(#[from] crate::road::RoadError),
    /// A vehicle handle that this world did not issue.
    #[error("no vehicle with index {0} in this world")]
    UnknownVehicle(usize),
    /// A robot handle that this world did not issue.
    #[error("no robot with index {0} in this world")]
    UnknownRobot(usize),
    /// A dynamic body (`[[body]]`) index that this world does not have.
    #[error("no dynamic body with index {0} in this world")]
    UnknownBody(usize),
    /// A body's pose or velocity stopped being finite (or rapier quarantined it) during the step
    /// that ended at `time_ms`. The world refuses to step any further.
    #[error(
        "the simulation diverged at t = {time_ms} ms: the pose or velocity of the {part} of \
         {owner} stopped being finite"
    )]
    NonFinite {
        /// The owner of the body.
        owner: BodyOwner,
        /// The body.
        part: BodyPart,
        /// Simulated time at the end of the failed step (ms).
        time_ms: u64,
    },
    /// A panic interrupted the step that began at `time_ms` (an assertion of rapier or
    /// parry on a shape or number this crate did not foresee: a bug to report), while
    /// `owner`'s part of the step ran (a vehicle's or robot's own, or rapier's step of the
    /// whole world). The world refuses to step any further.
    #[error("the step at t = {time_ms} ms failed in {owner}'s part of it (a bug): {message}")]
    Panic {
        /// Whose part of the step was running.
        owner: BodyOwner,
        /// Simulated time at the start of the failed step (ms).
        time_ms: u64,
        /// The panic's message.
        message: String,
    },
    /// A panic interrupted the building of `owner`'s bodies and joints (a bug to report, as
    /// for [`SimError::Panic`]). Its bodies may be half in the world, so the world refuses to
    /// step any further.
    #[error("adding {owner} to the world failed (a bug): {message}")]
    PanicWhileAdding {
        /// The car or robot being added.
        owner: BodyOwner,
        /// The panic's message.
        message: String,
    },
    /// rapier refused a joint of a car on joints (it refuses joints that close a loop, which a
    /// car's tree of joints never does); nothing usable was created.
    #[error("rapier refused a joint of {0}")]
    JointRefused(BodyOwner),
    /// A car's brake balance gives a front share outside [0, 1]; nothing was created.
    #[error("{0}")]
    BrakeBalance(vehicle_model::BrakeBalanceError),
    /// A vehicle was added under a name another vehicle of the simulation has; nothing was
    /// created.
    #[error("a vehicle named '{0}' is already in this simulation: names must be unique")]
    DuplicateName(String),
    /// A vehicle was added while the simulation records (a recording follows the vehicles it
    /// started with); nothing was created.
    #[error(
        "cannot add '{0}' while the simulation records: add every vehicle before recording starts"
    )]
    Recording(String),
    /// A car's sensor devices cannot be built (nothing was created), or a device index the
    /// car does not have.
    #[error("{0}")]
    Device(crate::devices::DeviceError),
}
/// The message of a caught panic's `payload` (its `&str` or `String`), for the errors that
/// report it.
pub(crate) fn panic_message(payload: &(dyn core::any::Any + Send)) -> String {
    payload
        .downcast_ref::<&str>()
        .map(|s| (*s).to_string())
        .or_else(|| payload.downcast_ref::<String>().cloned())
        .unwrap_or_else(|| "no message".to_string())
}

impl SimError {
    /// The [`SimError::NonFinite`] of a part of `owner` in the step ending at `time_ms`.
    pub(crate) fn diverged(owner: BodyOwner, time_ms: u64) -> impl Fn(BodyPart) -> SimError {
        move |part| SimError::NonFinite {
            owner,
            part,
            time_ms,
        }
    }
}
