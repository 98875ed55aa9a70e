//! Construction errors: which parameter was rejected, with its value.

use core::fmt;

use crate::MAX_GEAR_RATIOS;

/// A powertrain parameter, named after its Webots `Car` PROTO field where one exists.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Field {
    /// Peak engine torque (N·m); Webots field `engineMaxTorque`.
    EngineMaxTorque,
    /// Peak electric power (W); Webots field `engineMaxPower`.
    EngineMaxPower,
    /// Idle / engine-on threshold speed (rpm); Webots field `engineMinRPM`.
    EngineMinRpm,
    /// Maximum engine speed (rpm); Webots field `engineMaxRPM`.
    EngineMaxRpm,
    /// Combustion torque-curve coefficients `a`, `b`, `c` (N·m, N·m/rpm, N·m/rpm²);
    /// Webots field `engineFunctionCoefficients`.
    EngineFunctionCoefficients,
    /// Share of the combustion engine kept by the generator in a power-split hybrid
    /// (dimensionless, [0, 1]); Webots field `hybridPowerSplitRatio`.
    HybridPowerSplitRatio,
    /// Fixed combustion-engine speed of a power-split hybrid (rpm); Webots field
    /// `hybridPowerSplitRPM`.
    HybridPowerSplitRpm,
    /// Brake torque at full intensity (N·m); Webots field `brakeCoefficient`.
    BrakeCoefficient,
    /// Automatic gearbox up-shift engine speed (rpm); no Webots counterpart.
    UpshiftRpm,
    /// Automatic gearbox down-shift engine speed (rpm); no Webots counterpart.
    DownshiftRpm,
    /// Automatic gearbox minimum time between two shifts (s); no Webots counterpart.
    MinShiftInterval,
}

impl Field {
    /// The Webots PROTO field name (`"engineMaxTorque"`, …), or the Rust field name for the
    /// automatic-gearbox parameters, which Webots does not have.
    pub const fn name(self) -> &'static str {
        match self {
            Field::EngineMaxTorque => "engineMaxTorque",
            Field::EngineMaxPower => "engineMaxPower",
            Field::EngineMinRpm => "engineMinRPM",
            Field::EngineMaxRpm => "engineMaxRPM",
            Field::EngineFunctionCoefficients => "engineFunctionCoefficients",
            Field::HybridPowerSplitRatio => "hybridPowerSplitRatio",
            Field::HybridPowerSplitRpm => "hybridPowerSplitRPM",
            Field::BrakeCoefficient => "brakeCoefficient",
            Field::UpshiftRpm => "upshift_rpm",
            Field::DownshiftRpm => "downshift_rpm",
            Field::MinShiftInterval => "min_shift_interval",
        }
    }

    /// The unit of the field, as printed in error messages (empty when dimensionless).
    pub const fn unit(self) -> &'static str {
        match self {
            Field::EngineMaxTorque | Field::BrakeCoefficient => " N·m",
            Field::EngineMaxPower => " W",
            Field::EngineMinRpm
            | Field::EngineMaxRpm
            | Field::HybridPowerSplitRpm
            | Field::UpshiftRpm
            | Field::DownshiftRpm => " rpm",
            Field::MinShiftInterval => " s",
            Field::EngineFunctionCoefficients | Field::HybridPowerSplitRatio => "",
        }
    }
}

impl fmt::Display for Field {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// Why a powertrain component could not be built. Values are widened to `f64` (exact for
/// `f32`).
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum PowertrainError {
    /// The value is NaN or ±∞.
    NotFinite {
        /// The rejected parameter.
        field: Field,
        /// The rejected value (unit of `field`).
        value: f64,
    },
    /// The value must be strictly positive.
    NotPositive {
        /// The rejected parameter.
        field: Field,
        /// The rejected value (unit of `field`).
        value: f64,
    },
    /// The value must not be negative.
    Negative {
        /// The rejected parameter.
        field: Field,
        /// The rejected value (unit of `field`).
        value: f64,
    },
    /// The value lies outside the closed interval `[min, max]`.
    OutOfRange {
        /// The rejected parameter.
        field: Field,
        /// The rejected value (unit of `field`).
        value: f64,
        /// Smallest accepted value.
        min: f64,
        /// Largest accepted value.
        max: f64,
    },
    /// `field` must be strictly below `limit_field` (e.g. `engineMinRPM < engineMaxRPM`).
    NotBelow {
        /// The rejected parameter.
        field: Field,
        /// Its value (unit of `field`).
        value: f64,
        /// The parameter it must stay below.
        limit_field: Field,
        /// That parameter's value (same unit).
        limit: f64,
    },
    /// Webots field `gearRatio` has fewer than two entries (reverse plus at least one forward
    /// gear). Webots: `Error: Any car should have a minimum of two gear ratios.`
    TooFewGearRatios {
        /// Number of ratios given.
        count: usize,
    },
    /// Webots field `gearRatio` has more entries than the fixed capacity
    /// [`MAX_GEAR_RATIOS`].
    TooManyGearRatios {
        /// Number of ratios given.
        count: usize,
    },
    /// An entry of Webots field `gearRatio` is zero, NaN or ±∞.
    InvalidGearRatio {
        /// Position in the table (0 = reverse).
        index: usize,
        /// The rejected total ratio (dimensionless).
        value: f64,
    },
}

impl PowertrainError {
    /// The rejected parameter (`gearRatio` errors have no [`Field`]: `None`).
    pub const fn field(&self) -> Option<Field> {
        match *self {
            PowertrainError::NotFinite { field, .. }
            | PowertrainError::NotPositive { field, .. }
            | PowertrainError::Negative { field, .. }
            | PowertrainError::OutOfRange { field, .. }
            | PowertrainError::NotBelow { field, .. } => Some(field),
            PowertrainError::TooFewGearRatios { .. }
            | PowertrainError::TooManyGearRatios { .. }
            | PowertrainError::InvalidGearRatio { .. } => None,
        }
    }
}

impl fmt::Display for PowertrainError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            PowertrainError::NotFinite { field, value } => {
                write!(
                    f,
                    "invalid {field}: {value}{} (must be finite)",
                    field.unit()
                )
            }
            PowertrainError::NotPositive { field, value } => {
                write!(f, "invalid {field}: {value}{} (must be > 0)", field.unit())
            }
            PowertrainError::Negative { field, value } => {
                write!(f, "invalid {field}: {value}{} (must be >= 0)", field.unit())
            }
            PowertrainError::OutOfRange {
                field,
                value,
                min,
                max,
            } => write!(
                f,
                "invalid {field}: {value}{} (must be in [{min}, {max}])",
                field.unit()
            ),
            PowertrainError::NotBelow {
                field,
                value,
                limit_field,
                limit,
            } => write!(
                f,
                "invalid {field}: {value}{u} (must be < {limit_field} = {limit}{u})",
                u = field.unit()
            ),
            PowertrainError::TooFewGearRatios { count } => write!(
                f,
                "invalid gearRatio: {count} entries (at least 2 needed: reverse and one forward gear)"
            ),
            PowertrainError::TooManyGearRatios { count } => write!(
                f,
                "invalid gearRatio: {count} entries (at most {MAX_GEAR_RATIOS} supported)"
            ),
            PowertrainError::InvalidGearRatio { index, value } => write!(
                f,
                "invalid gearRatio[{index}]: {value} (must be finite and non-zero)"
            ),
        }
    }
}

impl core::error::Error for PowertrainError {}

/// Checks that `value` is finite and strictly positive.
pub(crate) fn positive<T: ackermann::Real>(field: Field, value: T) -> Result<T, PowertrainError> {
    if !value.is_finite() {
        Err(PowertrainError::NotFinite {
            field,
            value: value.to_f64(),
        })
    } else if value <= T::ZERO {
        Err(PowertrainError::NotPositive {
            field,
            value: value.to_f64(),
        })
    } else {
        Ok(value)
    }
}

/// Checks that `value` is finite.
pub(crate) fn finite<T: ackermann::Real>(field: Field, value: T) -> Result<T, PowertrainError> {
    if value.is_finite() {
        Ok(value)
    } else {
        Err(PowertrainError::NotFinite {
            field,
            value: value.to_f64(),
        })
    }
}

/// Checks that `value < limit` (both already known finite).
pub(crate) fn below<T: ackermann::Real>(
    field: Field,
    value: T,
    limit_field: Field,
    limit: T,
) -> Result<T, PowertrainError> {
    if value < limit {
        Ok(value)
    } else {
        Err(PowertrainError::NotBelow {
            field,
            value: value.to_f64(),
            limit_field,
            limit: limit.to_f64(),
        })
    }
}
