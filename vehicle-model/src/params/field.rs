//! The Car / AckermannVehicle fields by their Webots names, and setting them from generic values
//! (what a world file gives).

use core::fmt;

use proto_geom::{Plausible, plausible};

/// A field of [`CarParams`](crate::CarParams) that has a Webots name: the `AckermannVehicle` and
/// `Car` PROTO fields plus the car body's `Physics` fields (`mass`, `centerOfMass`,
/// `inertiaMatrix`). Wheel fields are addressed as `<slot>.<VehicleWheel field>`, see
/// [`CarParams::set_field`](crate::CarParams::set_field).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum CarField {
    /// Webots field `translation` (m): initial position of the car's origin (rear-axle centre) in the world.
    Translation,
    /// Webots field `rotation` (axis x, y, z; angle rad): initial orientation.
    Rotation,
    /// Webots field `trackFront` (m): distance between the front wheel centres.
    TrackFront,
    /// Webots field `trackRear` (m): distance between the rear wheel centres.
    TrackRear,
    /// Webots field `wheelbase` (m): distance between the axles.
    Wheelbase,
    /// Webots field `minSteeringAngle` (rad): lower limit of the steering motors.
    MinSteeringAngle,
    /// Webots field `maxSteeringAngle` (rad): upper limit of the steering motors.
    MaxSteeringAngle,
    /// Webots field `suspensionFrontSpringConstant` (N/m).
    SuspensionFrontSpringConstant,
    /// Webots field `suspensionFrontDampingConstant` (N·s/m).
    SuspensionFrontDampingConstant,
    /// Webots field `suspensionRearSpringConstant` (N/m).
    SuspensionRearSpringConstant,
    /// Webots field `suspensionRearDampingConstant` (N·s/m).
    SuspensionRearDampingConstant,
    /// Webots field `wheelsDampingConstant` (N·m·s/rad): viscous damping of each wheel axle.
    WheelsDampingConstant,
    /// Webots field `maxSteeringTorque` (N·m): torque limit of the steering motors.
    MaxSteeringTorque,
    /// Webots field `type`: `"traction"`, `"propulsion"` or `"4x4"`.
    Type,
    /// Webots field `engineType`: `"combustion"`, `"electric"`, `"parallel hybrid"`, `"power-split hybrid"`.
    EngineType,
    /// Webots field `engineSound`: sound file of the engine loop (`""` = none).
    EngineSound,
    /// Webots field `engineSoundRpmReference` (rpm): engine speed at which the sound plays at pitch 1.
    EngineSoundRpmReference,
    /// Webots field `brakeCoefficient` (N·m): brake torque per wheel at full intensity.
    BrakeCoefficient,
    /// Webots field `time0To100` (s): 0 to 100 km/h time, sets the speed-mode wheel acceleration.
    Time0To100,
    /// Webots field `maxVelocity` (m/s): top speed in speed mode.
    MaxVelocity,
    /// Webots field `engineMaxTorque` (N·m).
    EngineMaxTorque,
    /// Webots field `engineMaxPower` (W).
    EngineMaxPower,
    /// Webots field `engineMinRPM` (rpm).
    EngineMinRpm,
    /// Webots field `engineMaxRPM` (rpm).
    EngineMaxRpm,
    /// Webots field `engineFunctionCoefficients` (a, b, c of `a + b·rpm + c·rpm²`, N·m).
    EngineFunctionCoefficients,
    /// Webots field `gearRatio`: total engine-to-wheel ratios, reverse first.
    GearRatio,
    /// Webots field `hybridPowerSplitRatio` (dimensionless, [0, 1]).
    HybridPowerSplitRatio,
    /// Webots field `hybridPowerSplitRPM` (rpm).
    HybridPowerSplitRpm,
    /// Webots field `mass` (kg) of the car body's `Physics` node.
    Mass,
    /// Webots field `centerOfMass` (m) of the car body's `Physics` node.
    CenterOfMass,
    /// Webots field `inertiaMatrix` (kg·m²: Ixx, Iyy, Izz, Ixy, Ixz, Iyz) of the car body's `Physics` node.
    InertiaMatrix,
}

/// The sign rule of a number field ([`CarField::number_rule`]); NaN and ±∞ never pass.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum NumberRule {
    /// Any finite number.
    Finite,
    /// Finite and > 0.
    Positive,
    /// Finite and ≥ 0.
    NonNegative,
    /// Finite and in [0, 1].
    UnitInterval,
}

impl NumberRule {
    /// True if `value` obeys the rule.
    pub fn accepts(self, value: f64) -> bool {
        value.is_finite()
            && match self {
                NumberRule::Finite => true,
                NumberRule::Positive => value > 0.0,
                NumberRule::NonNegative => value >= 0.0,
                NumberRule::UnitInterval => (0.0..=1.0).contains(&value),
            }
    }
}

/// What kind of value a field takes.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum FieldKind {
    /// One number.
    Number,
    /// A list of `min..=max` numbers.
    Numbers {
        /// Fewest values accepted.
        min: usize,
        /// Most values accepted.
        max: usize,
    },
    /// A string.
    Text,
}

impl fmt::Display for FieldKind {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            FieldKind::Number => f.write_str("a number"),
            FieldKind::Numbers { min, max } if min == max => write!(f, "a list of {min} numbers"),
            FieldKind::Numbers { min, max } => write!(f, "a list of {min} to {max} numbers"),
            FieldKind::Text => f.write_str("a string"),
        }
    }
}

impl CarField {
    /// Every field, in [`CarParams`](crate::CarParams) order.
    pub const ALL: [CarField; 31] = [
        CarField::Translation,
        CarField::Rotation,
        CarField::TrackFront,
        CarField::TrackRear,
        CarField::Wheelbase,
        CarField::MinSteeringAngle,
        CarField::MaxSteeringAngle,
        CarField::SuspensionFrontSpringConstant,
        CarField::SuspensionFrontDampingConstant,
        CarField::SuspensionRearSpringConstant,
        CarField::SuspensionRearDampingConstant,
        CarField::WheelsDampingConstant,
        CarField::MaxSteeringTorque,
        CarField::Type,
        CarField::EngineType,
        CarField::EngineSound,
        CarField::EngineSoundRpmReference,
        CarField::BrakeCoefficient,
        CarField::Time0To100,
        CarField::MaxVelocity,
        CarField::EngineMaxTorque,
        CarField::EngineMaxPower,
        CarField::EngineMinRpm,
        CarField::EngineMaxRpm,
        CarField::EngineFunctionCoefficients,
        CarField::GearRatio,
        CarField::HybridPowerSplitRatio,
        CarField::HybridPowerSplitRpm,
        CarField::Mass,
        CarField::CenterOfMass,
        CarField::InertiaMatrix,
    ];

    /// The Webots field name, e.g. `"trackFront"`, `"engineMinRPM"`.
    pub const fn webots_name(self) -> &'static str {
        match self {
            CarField::Translation => "translation",
            CarField::Rotation => "rotation",
            CarField::TrackFront => "trackFront",
            CarField::TrackRear => "trackRear",
            CarField::Wheelbase => "wheelbase",
            CarField::MinSteeringAngle => "minSteeringAngle",
            CarField::MaxSteeringAngle => "maxSteeringAngle",
            CarField::SuspensionFrontSpringConstant => "suspensionFrontSpringConstant",
            CarField::SuspensionFrontDampingConstant => "suspensionFrontDampingConstant",
            CarField::SuspensionRearSpringConstant => "suspensionRearSpringConstant",
            CarField::SuspensionRearDampingConstant => "suspensionRearDampingConstant",
            CarField::WheelsDampingConstant => "wheelsDampingConstant",
            CarField::MaxSteeringTorque => "maxSteeringTorque",
            CarField::Type => "type",
            CarField::EngineType => "engineType",
            CarField::EngineSound => "engineSound",
            CarField::EngineSoundRpmReference => "engineSoundRpmReference",
            CarField::BrakeCoefficient => "brakeCoefficient",
            CarField::Time0To100 => "time0To100",
            CarField::MaxVelocity => "maxVelocity",
            CarField::EngineMaxTorque => "engineMaxTorque",
            CarField::EngineMaxPower => "engineMaxPower",
            CarField::EngineMinRpm => "engineMinRPM",
            CarField::EngineMaxRpm => "engineMaxRPM",
            CarField::EngineFunctionCoefficients => "engineFunctionCoefficients",
            CarField::GearRatio => "gearRatio",
            CarField::HybridPowerSplitRatio => "hybridPowerSplitRatio",
            CarField::HybridPowerSplitRpm => "hybridPowerSplitRPM",
            CarField::Mass => "mass",
            CarField::CenterOfMass => "centerOfMass",
            CarField::InertiaMatrix => "inertiaMatrix",
        }
    }

    /// The field with Webots name `name` (exact, case-sensitive), or `None`.
    pub fn from_webots_name(name: &str) -> Option<CarField> {
        CarField::ALL.into_iter().find(|f| f.webots_name() == name)
    }

    /// The kind of value the field takes.
    pub const fn kind(self) -> FieldKind {
        match self {
            CarField::Translation | CarField::CenterOfMass => FieldKind::Numbers { min: 3, max: 3 },
            CarField::EngineFunctionCoefficients => FieldKind::Numbers { min: 3, max: 3 },
            CarField::Rotation => FieldKind::Numbers { min: 4, max: 4 },
            CarField::InertiaMatrix => FieldKind::Numbers { min: 6, max: 6 },
            CarField::GearRatio => FieldKind::Numbers {
                min: 2,
                max: powertrain::MAX_GEAR_RATIOS,
            },
            CarField::Type | CarField::EngineType | CarField::EngineSound => FieldKind::Text,
            _ => FieldKind::Number,
        }
    }

    /// The sign rule a number (or each number of a list) obeys before its plausible range.
    pub const fn number_rule(self) -> NumberRule {
        match self {
            CarField::Translation
            | CarField::Rotation
            | CarField::MinSteeringAngle
            | CarField::MaxSteeringAngle
            | CarField::EngineFunctionCoefficients
            | CarField::GearRatio
            | CarField::CenterOfMass
            | CarField::InertiaMatrix
            | CarField::Type
            | CarField::EngineType
            | CarField::EngineSound => NumberRule::Finite,
            CarField::SuspensionFrontSpringConstant
            | CarField::SuspensionFrontDampingConstant
            | CarField::SuspensionRearSpringConstant
            | CarField::SuspensionRearDampingConstant
            | CarField::MaxSteeringTorque => NumberRule::NonNegative,
            CarField::HybridPowerSplitRatio => NumberRule::UnitInterval,
            CarField::TrackFront
            | CarField::TrackRear
            | CarField::Wheelbase
            | CarField::WheelsDampingConstant
            | CarField::EngineSoundRpmReference
            | CarField::BrakeCoefficient
            | CarField::Time0To100
            | CarField::MaxVelocity
            | CarField::EngineMaxTorque
            | CarField::EngineMaxPower
            | CarField::EngineMinRpm
            | CarField::EngineMaxRpm
            | CarField::HybridPowerSplitRpm
            | CarField::Mass => NumberRule::Positive,
        }
    }

    /// The plausible range of the field's numbers (each element of a list; the magnitude of
    /// each `gearRatio`), from [`proto_geom::plausible`]; `None` for `rotation` (any angle),
    /// `hybridPowerSplitRatio` (its rule is already a range) and the text fields.
    pub const fn plausible(self) -> Option<Plausible> {
        Some(match self {
            CarField::Translation => plausible::POSITION,
            CarField::TrackFront | CarField::TrackRear | CarField::Wheelbase => plausible::LENGTH,
            CarField::MinSteeringAngle | CarField::MaxSteeringAngle => plausible::STEERING_ANGLE,
            CarField::SuspensionFrontSpringConstant | CarField::SuspensionRearSpringConstant => {
                plausible::SPRING
            }
            CarField::SuspensionFrontDampingConstant | CarField::SuspensionRearDampingConstant => {
                plausible::DAMPER
            }
            CarField::WheelsDampingConstant => plausible::ROTATIONAL_DAMPING,
            CarField::MaxSteeringTorque
            | CarField::BrakeCoefficient
            | CarField::EngineMaxTorque => plausible::TORQUE,
            CarField::EngineSoundRpmReference
            | CarField::EngineMaxRpm
            | CarField::HybridPowerSplitRpm => plausible::ENGINE_SPEED,
            CarField::Time0To100 => plausible::TIME_0_TO_100,
            CarField::MaxVelocity => plausible::SPEED,
            CarField::EngineMinRpm => plausible::ENGINE_MIN_SPEED,
            CarField::EngineMaxPower => plausible::POWER,
            CarField::EngineFunctionCoefficients => plausible::COEFFICIENT,
            CarField::GearRatio => plausible::GEAR_RATIO,
            CarField::Mass => plausible::MASS,
            CarField::CenterOfMass => plausible::OFFSET,
            CarField::InertiaMatrix => plausible::INERTIA,
            CarField::Rotation
            | CarField::HybridPowerSplitRatio
            | CarField::Type
            | CarField::EngineType
            | CarField::EngineSound => return None,
        })
    }

    /// The validation rule, as printed in warnings (e.g. `"must be > 0"`).
    pub const fn rule(self) -> &'static str {
        match self {
            CarField::Translation
            | CarField::CenterOfMass
            | CarField::EngineFunctionCoefficients => "must be finite",
            CarField::Rotation => "must be finite with a non-zero axis",
            CarField::MinSteeringAngle => "must be finite and below maxSteeringAngle",
            CarField::MaxSteeringAngle => "must be finite and above minSteeringAngle",
            CarField::SuspensionFrontSpringConstant
            | CarField::SuspensionFrontDampingConstant
            | CarField::SuspensionRearSpringConstant
            | CarField::SuspensionRearDampingConstant
            | CarField::MaxSteeringTorque => "must be finite and >= 0",
            CarField::EngineMaxRpm => "must be > 0 and above engineMinRPM",
            CarField::GearRatio => "needs 2 to 16 finite, non-zero ratios",
            CarField::HybridPowerSplitRatio => "must be in [0, 1]",
            CarField::InertiaMatrix => {
                "must be finite with positive principal moments satisfying the triangle inequality"
            }
            CarField::Type => "must be \"traction\", \"propulsion\" or \"4x4\"",
            CarField::EngineType => {
                "must be \"combustion\", \"electric\", \"parallel hybrid\" or \"power-split hybrid\""
            }
            CarField::EngineSound => "must be at most 63 bytes",
            _ => "must be > 0",
        }
    }
}

impl fmt::Display for CarField {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.webots_name())
    }
}

/// A value for [`CarParams::set_field`](crate::CarParams::set_field).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FieldValue<'a, T> {
    /// One number (an integer field takes an integral number).
    Number(T),
    /// A list of numbers (`translation`, `gearRatio`, …).
    Numbers(&'a [T]),
    /// A string (`type`, `engineType`, `engineSound`).
    Text(&'a str),
}

/// Why [`CarParams::set_field`](crate::CarParams::set_field) refused a value. The params are
/// unchanged.
///
/// Only the form of the value is checked here; whether a number is acceptable (e.g.
/// `wheelbase > 0`) is decided by [`CarParams::validate`](crate::CarParams::validate), which
/// falls back to the default with a warning.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum FieldError {
    /// No field has that name (see [`CarParams::FIELD_NAMES`](crate::CarParams::FIELD_NAMES)
    /// and [`CarParams::WHEEL_FIELD_NAMES`](crate::CarParams::WHEEL_FIELD_NAMES)).
    UnknownField,
    /// The value is not of the field's kind.
    WrongKind {
        /// The field's Webots name.
        field: &'static str,
        /// What it takes.
        expected: FieldKind,
    },
    /// A list has the wrong number of values.
    WrongLength {
        /// The field's Webots name.
        field: &'static str,
        /// What it takes.
        expected: FieldKind,
        /// Number of values given.
        len: usize,
    },
    /// The string is not one of the accepted spellings, or too long.
    InvalidText {
        /// The field's Webots name.
        field: &'static str,
        /// The rule, e.g. `must be "traction", "propulsion" or "4x4"`.
        rule: &'static str,
    },
    /// An integer field got a non-integral or out-of-range number.
    NotAnInteger {
        /// The field's Webots name.
        field: &'static str,
        /// The value given, widened to `f64`.
        value: f64,
    },
}

impl fmt::Display for FieldError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            FieldError::UnknownField => f.write_str("unknown field"),
            FieldError::WrongKind { field, expected } => {
                write!(f, "field '{field}' takes {expected}")
            }
            FieldError::WrongLength {
                field,
                expected,
                len,
            } => write!(f, "field '{field}' takes {expected}, got {len}"),
            FieldError::InvalidText { field, rule } => write!(f, "field '{field}' {rule}"),
            FieldError::NotAnInteger { field, value } => {
                write!(f, "field '{field}' takes an integer, got {value}")
            }
        }
    }
}

impl core::error::Error for FieldError {}
