//! What a parameter validation reports: typed warnings naming the Webots field and the value,
//! collected without allocation.

use core::fmt;

use ackermann::Wheel;
use proto_geom::plausible::Compact;
use proto_geom::{Plausible, WheelRule, WheelWarning};

use super::field::CarField;
use super::path::wheel_slot_name;

/// Capacity of a [`ParamReport`]; further warnings are only counted.
pub const MAX_PARAM_WARNINGS: usize = 32;

/// One parameter that [`CarParams::validate`](super::CarParams::validate) replaced (or, for a wheel's information-only
/// message, merely reported). Values are widened to `f64` (exact for `f32`).
///
/// `Display` prints a one-line message naming the Webots field and the value.
#[derive(Debug, Clone, Copy, PartialEq)]
#[non_exhaustive]
pub enum ParamWarning {
    /// A number broke its rule ([`CarField::rule`]) and `used` was taken instead.
    Value {
        /// The field.
        field: CarField,
        /// The rejected value.
        value: f64,
        /// The value used instead.
        used: f64,
    },
    /// A number obeyed its rule but lay outside its plausible range ([`CarField::plausible`]);
    /// `used` was taken instead. A world file refuses such a value.
    Implausible {
        /// The field.
        field: CarField,
        /// The rejected value.
        value: f64,
        /// The value used instead.
        used: f64,
    },
    /// Element `index` of a list field lay outside the field's plausible range (for
    /// `gearRatio`, in magnitude); the whole field was reset to its default (for
    /// `inertiaMatrix`: derived). A world file refuses such a value.
    ImplausibleElement {
        /// The field.
        field: CarField,
        /// Position of the first implausible element.
        index: usize,
        /// Its value.
        value: f64,
    },
    /// Element `index` of a list field was NaN, infinite or (for `gearRatio`) zero; the whole
    /// field was reset to its default.
    Element {
        /// The field.
        field: CarField,
        /// Position of the first bad element.
        index: usize,
        /// Its value.
        value: f64,
    },
    /// A list field had too few values (`gearRatio` needs 2); reset to its default.
    Length {
        /// The field.
        field: CarField,
        /// Number of values it had.
        len: usize,
    },
    /// A list field broke a rule relating its elements (`rotation` with a zero axis,
    /// `inertiaMatrix` not physical); reset to its default (for `inertiaMatrix`: derived).
    List {
        /// The field.
        field: CarField,
    },
    /// A `VehicleWheel` field of one slot, checked by [`proto_geom::WheelParams::validate`].
    Wheel {
        /// The slot.
        slot: Wheel,
        /// The wheel's own warning.
        warning: WheelWarning,
    },
    /// The wiper range was not finite with `min < max`; the wipers were removed.
    WiperRange {
        /// The given minimum (rad).
        min: f64,
        /// The given maximum (rad).
        max: f64,
    },
    /// The world's `basicTimeStep` was 0 ms; `used` ms was taken instead.
    TimeStep {
        /// The given step (ms).
        value: u32,
        /// The step used (ms).
        used: u32,
    },
}

/// The plausible range of `field` for a message (every field that can be implausible has one).
fn plausible_text(field: CarField) -> Plausible {
    field.plausible().unwrap_or(Plausible {
        min: f64::MIN,
        max: f64::MAX,
        unit: "",
    })
}

impl ParamWarning {
    /// The field the warning is about (`None` for a wheel, the wipers or the time step).
    pub fn field(&self) -> Option<CarField> {
        match *self {
            ParamWarning::Value { field, .. }
            | ParamWarning::Implausible { field, .. }
            | ParamWarning::ImplausibleElement { field, .. }
            | ParamWarning::Element { field, .. }
            | ParamWarning::Length { field, .. }
            | ParamWarning::List { field } => Some(field),
            ParamWarning::Wheel { .. }
            | ParamWarning::WiperRange { .. }
            | ParamWarning::TimeStep { .. } => None,
        }
    }

    /// The broken rule of an implausible value ([`ParamWarning::is_implausible`]), without the
    /// replacement: what a world file that refuses the value says (`implausible 'mass' value
    /// 1e300 (must be within 0.001 to 1000000 kg)`).
    pub fn refusal(&self) -> Refusal<'_> {
        Refusal(self)
    }

    /// True for a value outside its plausible range (of the car or of a wheel): a world file
    /// refuses it, where it accepts the Webots fallbacks with a warning.
    pub fn is_implausible(&self) -> bool {
        match *self {
            ParamWarning::Implausible { .. } | ParamWarning::ImplausibleElement { .. } => true,
            ParamWarning::Wheel { warning, .. } => warning.rule == WheelRule::Implausible,
            _ => false,
        }
    }
}

impl fmt::Display for ParamWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self {
            ParamWarning::Value { field, value, used } => write!(
                f,
                "Warning: invalid '{field}' value {} ({}), used {} instead.",
                Compact(value),
                field.rule(),
                Compact(used)
            ),
            ParamWarning::Implausible { used, .. } => {
                write!(
                    f,
                    "Warning: {}, used {} instead.",
                    self.refusal(),
                    Compact(used)
                )
            }
            ParamWarning::ImplausibleElement { .. } => {
                write!(f, "Warning: {}, used the default instead.", self.refusal())
            }
            ParamWarning::Element {
                field,
                index,
                value,
            } => write!(
                f,
                "Warning: invalid '{field}' element {index} value {} ({}), used the default \
                 instead.",
                Compact(value),
                field.rule()
            ),
            ParamWarning::Length { field, len } => write!(
                f,
                "Warning: '{field}' has {len} values ({}), used the default instead.",
                field.rule()
            ),
            ParamWarning::List { field } => write!(
                f,
                "Warning: invalid '{field}' ({}), used the default instead.",
                field.rule()
            ),
            ParamWarning::Wheel { slot, warning } => {
                write!(f, "Warning: {}: {warning}", wheel_slot_name(slot))
            }
            ParamWarning::WiperRange { min, max } => write!(
                f,
                "Warning: invalid wiper range [{}, {}] rad (must be finite with min < max), \
                 wipers removed.",
                Compact(min),
                Compact(max)
            ),
            ParamWarning::TimeStep { value, used } => write!(
                f,
                "Warning: invalid 'basicTimeStep' {value} ms (must be > 0), used {used} instead."
            ),
        }
    }
}

/// What an implausible value broke, without its replacement ([`ParamWarning::refusal`]).
#[derive(Debug, Clone, Copy)]
pub struct Refusal<'a>(&'a ParamWarning);

impl fmt::Display for Refusal<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match *self.0 {
            ParamWarning::Implausible { field, value, .. } => write!(
                f,
                "implausible '{field}' value {} (must be within {})",
                Compact(value),
                plausible_text(field)
            ),
            ParamWarning::ImplausibleElement {
                field,
                index,
                value,
            } => write!(
                f,
                "implausible '{field}' element {index} value {} ({}must be within {})",
                Compact(value),
                if field == CarField::GearRatio {
                    "its magnitude "
                } else {
                    ""
                },
                plausible_text(field)
            ),
            ParamWarning::Wheel { slot, warning } => {
                write!(f, "{}: {}", wheel_slot_name(slot), warning.requirement())
            }
            // Not a refusal: the warning itself.
            ref w => write!(f, "{w}"),
        }
    }
}

/// The warnings of a validation, in checking order (fixed capacity [`MAX_PARAM_WARNINGS`], no
/// allocation; warnings beyond it are counted in [`ParamReport::dropped`]).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ParamReport {
    warnings: heapless::Vec<ParamWarning, MAX_PARAM_WARNINGS>,
    dropped: usize,
}

impl ParamReport {
    /// No warnings.
    pub const fn new() -> Self {
        ParamReport {
            warnings: heapless::Vec::new(),
            dropped: 0,
        }
    }

    pub(crate) fn push(&mut self, warning: ParamWarning) {
        if self.warnings.push(warning).is_err() {
            self.dropped = self.dropped.saturating_add(1);
        }
    }

    /// The kept warnings.
    pub fn as_slice(&self) -> &[ParamWarning] {
        &self.warnings
    }

    /// Iterates over the kept warnings.
    pub fn iter(&self) -> core::slice::Iter<'_, ParamWarning> {
        self.warnings.iter()
    }

    /// Number of kept warnings.
    pub fn len(&self) -> usize {
        self.warnings.len()
    }

    /// True if nothing was reported (not even dropped warnings).
    pub fn is_empty(&self) -> bool {
        self.warnings.is_empty() && self.dropped == 0
    }

    /// Number of warnings that did not fit.
    pub fn dropped(&self) -> usize {
        self.dropped
    }

    /// Total number of warnings raised (kept + dropped).
    pub fn total(&self) -> usize {
        self.warnings.len().saturating_add(self.dropped)
    }

    /// The first kept warning about `field`, if any.
    pub fn get(&self, field: CarField) -> Option<&ParamWarning> {
        self.warnings.iter().find(|w| w.field() == Some(field))
    }
}

impl<'a> IntoIterator for &'a ParamReport {
    type Item = &'a ParamWarning;
    type IntoIter = core::slice::Iter<'a, ParamWarning>;
    fn into_iter(self) -> Self::IntoIter {
        self.warnings.iter()
    }
}
