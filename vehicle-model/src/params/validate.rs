//! Parameter validation: every invalid value falls back to its default, with a typed warning.

use core::fmt;

use ackermann::{PerWheel, Real, Wheel};
use proto_geom::plausible::Compact;
use proto_geom::{Plausible, WheelRule, WheelWarning};

use super::body::is_physical_inertia;
use super::field::CarField;
use super::{CarParams, DEFAULT_GEAR_RATIOS, gear_ratios};

/// Capacity of a [`ParamReport`]; further warnings are only counted.
pub const MAX_PARAM_WARNINGS: usize = 32;

/// One parameter that [`CarParams::validate`] replaced (or, for a wheel's information-only
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

/// The Webots name of a wheel slot field.
const fn slot_name(slot: Wheel) -> &'static str {
    match slot {
        Wheel::FrontRight => "wheelFrontRight",
        Wheel::FrontLeft => "wheelFrontLeft",
        Wheel::RearRight => "wheelRearRight",
        Wheel::RearLeft => "wheelRearLeft",
    }
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
                write!(f, "Warning: {}: {warning}", slot_name(slot))
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
                write!(f, "{}: {}", slot_name(slot), warning.requirement())
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

/// Replaces `v` by `default` unless it is finite, obeys `field`'s Webots rule
/// ([`CarField::number_rule`]) and lies in its plausible range ([`CarField::plausible`]),
/// reporting the replacement.
fn check<T: Real>(report: &mut ParamReport, field: CarField, v: &mut T, default: T) {
    let x = v.to_f64();
    if !field.number_rule().accepts(x) {
        report.push(ParamWarning::Value {
            field,
            value: x,
            used: default.to_f64(),
        });
        *v = default;
    } else if let Some(range) = field.plausible()
        && !range.contains(x)
    {
        report.push(ParamWarning::Implausible {
            field,
            value: x,
            used: default.to_f64(),
        });
        *v = default;
    }
}

/// The first bad element of a list field, if any: not finite (for `gearRatio`, also zero),
/// or outside the field's plausible range (for `gearRatio`, in magnitude).
fn list_warning<T: Real>(field: CarField, values: &[T]) -> Option<ParamWarning> {
    let range = field.plausible();
    let gear = field == CarField::GearRatio;
    values
        .iter()
        .map(|x| x.to_f64())
        .enumerate()
        .find_map(|(index, value)| {
            if !field.number_rule().accepts(value) || (gear && value == 0.0) {
                Some(ParamWarning::Element {
                    field,
                    index,
                    value,
                })
            } else if range.is_some_and(|r| !r.contains(if gear { value.abs() } else { value })) {
                Some(ParamWarning::ImplausibleElement {
                    field,
                    index,
                    value,
                })
            } else {
                None
            }
        })
}

/// Resets a fixed-size list to `default` if [`list_warning`] finds a bad element, reporting it;
/// returns false if it did.
fn check_list<T: Real, const N: usize>(
    report: &mut ParamReport,
    field: CarField,
    v: &mut [T; N],
    default: [T; N],
) -> bool {
    match list_warning(field, v) {
        Some(warning) => {
            report.push(warning);
            *v = default;
            false
        }
        None => true,
    }
}

impl<T: Real> CarParams<T> {
    /// Applies the Webots PROTO checks, replacing every invalid value by its default (the
    /// plain `Car` PROTO value, or the rule's own fallback) and reporting each replacement.
    /// Never fails and never panics; afterwards [`CarParams::geometry`],
    /// [`CarParams::engine`], [`CarParams::gearbox`] and [`CarParams::brake`] succeed.
    ///
    /// Webots rules (`Car` / `AckermannVehicle` / `VehicleWheel` PROTOs): `trackFront`,
    /// `trackRear`, `wheelbase`, `wheelsDampingConstant`, `engineSoundRpmReference`,
    /// `brakeCoefficient`, `time0To100`, `engineMaxTorque`, `engineMaxPower`, `engineMinRPM`,
    /// `engineMaxRPM`, `hybridPowerSplitRPM` ≤ 0 → default; `maxSteeringTorque` < 0 →
    /// default; `hybridPowerSplitRatio` ∉ [0, 1] → default; `engineMaxRPM` ≤ `engineMinRPM` →
    /// 5 × `engineMinRPM` (the older Webots rule); fewer than 2 `gearRatio` values → default
    /// (Webots stops with an error); the wheels through
    /// [`proto_geom::WheelParams::validate`].
    ///
    /// Additions (listed in `COMPATIBILITY.md`): NaN and ±∞ are invalid everywhere;
    /// `maxVelocity` and the body `mass` must be > 0; the suspension constants ≥ 0;
    /// `minSteeringAngle < maxSteeringAngle` (else both reset); `gearRatio` entries non-zero;
    /// `rotation` needs a non-zero axis; an `inertiaMatrix` must be physical (else derived);
    /// a wiper range needs `min < max` (else no wipers); and every number must lie in its
    /// plausible range ([`CarField::plausible`], e.g. a mass of 1 g to 1,000 t), else it is
    /// reported as [`ParamWarning::Implausible`] (a world file refuses it) and replaced.
    ///
    /// ```
    /// use vehicle_model::{CarField, CarParams, ParamWarning};
    /// let mut p = CarParams::<f32>::default();
    /// p.brake_coefficient = -5.0;
    /// let report = p.validate();
    /// assert_eq!(p.brake_coefficient, 700.0);
    /// assert_eq!(
    ///     report.as_slice(),
    ///     &[ParamWarning::Value { field: CarField::BrakeCoefficient, value: -5.0, used: 700.0 }]
    /// );
    /// assert_eq!(
    ///     report.as_slice()[0].to_string(),
    ///     "Warning: invalid 'brakeCoefficient' value -5 (must be > 0), used 700 instead."
    /// );
    /// ```
    pub fn validate(&mut self) -> ParamReport {
        let d = CarParams::<T>::default();
        let mut r = ParamReport::new();

        check_list(
            &mut r,
            CarField::Translation,
            &mut self.translation,
            d.translation,
        );
        if check_list(&mut r, CarField::Rotation, &mut self.rotation, d.rotation) {
            let [x, y, z, _] = self.rotation;
            if x == T::ZERO && y == T::ZERO && z == T::ZERO {
                r.push(ParamWarning::List {
                    field: CarField::Rotation,
                });
                self.rotation = d.rotation;
            }
        }
        let e = &mut self.engine;
        let de = &d.engine;
        let numbers = [
            (CarField::TrackFront, &mut self.track_front, d.track_front),
            (CarField::TrackRear, &mut self.track_rear, d.track_rear),
            (CarField::Wheelbase, &mut self.wheelbase, d.wheelbase),
            (
                CarField::MinSteeringAngle,
                &mut self.min_steering_angle,
                d.min_steering_angle,
            ),
            (
                CarField::MaxSteeringAngle,
                &mut self.max_steering_angle,
                d.max_steering_angle,
            ),
            (
                CarField::SuspensionFrontSpringConstant,
                &mut self.suspension_front_spring_constant,
                d.suspension_front_spring_constant,
            ),
            (
                CarField::SuspensionFrontDampingConstant,
                &mut self.suspension_front_damping_constant,
                d.suspension_front_damping_constant,
            ),
            (
                CarField::SuspensionRearSpringConstant,
                &mut self.suspension_rear_spring_constant,
                d.suspension_rear_spring_constant,
            ),
            (
                CarField::SuspensionRearDampingConstant,
                &mut self.suspension_rear_damping_constant,
                d.suspension_rear_damping_constant,
            ),
            (
                CarField::WheelsDampingConstant,
                &mut self.wheels_damping_constant,
                d.wheels_damping_constant,
            ),
            (
                CarField::MaxSteeringTorque,
                &mut self.max_steering_torque,
                d.max_steering_torque,
            ),
            (
                CarField::EngineSoundRpmReference,
                &mut self.engine_sound_rpm_reference,
                d.engine_sound_rpm_reference,
            ),
            (
                CarField::BrakeCoefficient,
                &mut self.brake_coefficient,
                d.brake_coefficient,
            ),
            (
                CarField::Time0To100,
                &mut self.time_0_to_100,
                d.time_0_to_100,
            ),
            (
                CarField::MaxVelocity,
                &mut self.max_velocity,
                d.max_velocity,
            ),
            (CarField::EngineMaxTorque, &mut e.max_torque, de.max_torque),
            (CarField::EngineMaxPower, &mut e.max_power, de.max_power),
            (CarField::EngineMinRpm, &mut e.min_rpm, de.min_rpm),
            (CarField::EngineMaxRpm, &mut e.max_rpm, de.max_rpm),
            (
                CarField::HybridPowerSplitRatio,
                &mut e.hybrid_power_split_ratio,
                de.hybrid_power_split_ratio,
            ),
            (
                CarField::HybridPowerSplitRpm,
                &mut e.hybrid_power_split_rpm,
                de.hybrid_power_split_rpm,
            ),
            (CarField::Mass, &mut self.body.mass, d.body.mass),
        ];
        for (field, value, default) in numbers {
            check(&mut r, field, value, default);
        }
        self.check_relations(&mut r, &d);
        check_list(
            &mut r,
            CarField::EngineFunctionCoefficients,
            &mut self.engine.function_coefficients,
            d.engine.function_coefficients,
        );
        self.wheels = validate_wheels(&mut r, &self.wheels);
        self.validate_gear_ratios(&mut r);
        self.validate_body(&mut r);
        if let Some(range) = self.wipers
            && !range.is_valid()
        {
            r.push(ParamWarning::WiperRange {
                min: range.min.to_f64(),
                max: range.max.to_f64(),
            });
            self.wipers = None;
        }
        r
    }

    /// [`CarParams::validate`] by value: the corrected params and the report.
    pub fn validated(mut self) -> (Self, ParamReport) {
        let report = self.validate();
        (self, report)
    }

    /// The rules relating two fields, on values that each passed their own rule.
    fn check_relations(&mut self, r: &mut ParamReport, d: &Self) {
        if self.min_steering_angle >= self.max_steering_angle {
            r.push(ParamWarning::Value {
                field: CarField::MinSteeringAngle,
                value: self.min_steering_angle.to_f64(),
                used: d.min_steering_angle.to_f64(),
            });
            r.push(ParamWarning::Value {
                field: CarField::MaxSteeringAngle,
                value: self.max_steering_angle.to_f64(),
                used: d.max_steering_angle.to_f64(),
            });
            self.min_steering_angle = d.min_steering_angle;
            self.max_steering_angle = d.max_steering_angle;
        }
        let e = &mut self.engine;
        if e.max_rpm <= e.min_rpm {
            let used = T::from_f64(5.0) * e.min_rpm;
            r.push(ParamWarning::Value {
                field: CarField::EngineMaxRpm,
                value: e.max_rpm.to_f64(),
                used: used.to_f64(),
            });
            e.max_rpm = used;
        }
    }

    fn validate_gear_ratios(&mut self, r: &mut ParamReport) {
        let len = self.gear_ratios.len();
        let warning = if len < 2 {
            Some(ParamWarning::Length {
                field: CarField::GearRatio,
                len,
            })
        } else {
            list_warning(CarField::GearRatio, &self.gear_ratios)
        };
        if let Some(warning) = warning {
            r.push(warning);
            self.gear_ratios = gear_ratios(&DEFAULT_GEAR_RATIOS);
        }
    }

    fn validate_body(&mut self, r: &mut ParamReport) {
        let b = &mut self.body;
        let mid_wheelbase = [self.wheelbase * T::HALF, T::ZERO, T::ZERO];
        check_list(
            r,
            CarField::CenterOfMass,
            &mut b.center_of_mass,
            mid_wheelbase,
        );
        if let Some(m) = b.inertia {
            let warning = list_warning(CarField::InertiaMatrix, &m)
                .filter(|w| matches!(w, ParamWarning::ImplausibleElement { .. }))
                .or((!is_physical_inertia(&m)).then_some(ParamWarning::List {
                    field: CarField::InertiaMatrix,
                }));
            if let Some(warning) = warning {
                r.push(warning);
                b.inertia = None;
            }
        }
    }
}

/// Runs the `VehicleWheel` checks on each slot.
fn validate_wheels<T: Real>(
    r: &mut ParamReport,
    wheels: &PerWheel<proto_geom::WheelParams<T>>,
) -> PerWheel<proto_geom::WheelParams<T>> {
    wheels.map_with_wheel(|slot, w| {
        let (valid, warnings) = w.validate();
        for &warning in &warnings {
            r.push(ParamWarning::Wheel { slot, warning });
        }
        valid.into_params()
    })
}
