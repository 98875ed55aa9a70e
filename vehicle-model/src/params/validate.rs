//! Parameter validation: every invalid value falls back to its default, with a typed warning.

use ackermann::{PerWheel, Real};

use super::body::is_physical_inertia;
use super::field::CarField;
use super::warning::{ParamReport, ParamWarning};
use super::{CarParams, DEFAULT_GEAR_RATIOS, gear_ratios};

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
