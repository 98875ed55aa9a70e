//! Setting a field by its Webots name, e.g. from a world file.

use ackermann::{DriveType, PerWheel, Real};
use powertrain::EngineType;
use proto_geom::{WheelField, WheelParams, WheelPhysics};

use super::field::{CarField, FieldError, FieldKind, FieldValue};
use super::path::{FieldPath, WheelSetting, WheelSlot};
use super::sound_name::EngineSound;
use super::{CarParams, GearRatios};

/// The `webots_name()` of every element of a constant list, as a constant array.
macro_rules! webots_names {
    ($all:expr) => {{
        let mut names = [""; $all.len()];
        let mut i = 0;
        while i < names.len() {
            names[i] = $all[i].webots_name();
            i += 1;
        }
        names
    }};
}

impl<T: Real> CarParams<T> {
    /// The Webots names of every field [`CarParams::set_field`] accepts without a wheel
    /// prefix: the `AckermannVehicle` and `Car` fields, then the body `Physics` fields `mass`,
    /// `centerOfMass`, `inertiaMatrix`.
    pub const FIELD_NAMES: [&'static str; CarField::ALL.len()] = webots_names!(CarField::ALL);

    /// The wheel slot prefixes of [`CarParams::set_field`] ([`WheelSlot::ALL`]): the four
    /// `Car` slot fields, and `wheels` for all four at once.
    pub const WHEEL_SLOT_NAMES: [&'static str; WheelSlot::ALL.len()] =
        webots_names!(WheelSlot::ALL);

    /// The numeric `VehicleWheel` fields [`CarParams::set_field`] accepts after a slot prefix
    /// ([`WheelSetting::ALL`]; `mass` and `density` set the wheel's `Physics` node).
    pub const WHEEL_FIELD_NAMES: [&'static str; WheelSetting::ALL.len()] =
        webots_names!(WheelSetting::ALL);

    /// Sets the field with Webots name `name` (case-sensitive) to `value`, unvalidated (run
    /// [`CarParams::validate`] afterwards; [`Driver::new`](crate::Driver::new) does).
    ///
    /// Names are those of [`CarParams::FIELD_NAMES`], or `<slot>.<field>` with a slot of
    /// [`CarParams::WHEEL_SLOT_NAMES`] and a field of [`CarParams::WHEEL_FIELD_NAMES`]
    /// (e.g. `wheelRearLeft.tireRadius`, `wheels.mass`).
    ///
    /// ```
    /// use vehicle_model::{CarParams, FieldValue};
    /// let mut p = CarParams::<f64>::default();
    /// p.set_field("wheelbase", FieldValue::Number(2.9))?;
    /// p.set_field("gearRatio", FieldValue::Numbers(&[-10.0, 12.0, 8.0]))?;
    /// p.set_field("type", FieldValue::Text("4x4"))?;
    /// p.set_field("wheels.tireRadius", FieldValue::Number(0.35))?;
    /// assert_eq!(p.wheelbase, 2.9);
    /// assert_eq!(p.radius_rear(), 0.35);
    /// assert!(p.set_field("wheelBase", FieldValue::Number(1.0)).is_err());
    /// # Ok::<(), vehicle_model::FieldError>(())
    /// ```
    ///
    /// # Errors
    /// [`FieldError`] if the name is unknown or the value has the wrong form (kind, list
    /// length, spelling, integer); the params are then unchanged.
    pub fn set_field(&mut self, name: &str, value: FieldValue<'_, T>) -> Result<(), FieldError> {
        self.set(
            FieldPath::parse(name).ok_or(FieldError::UnknownField)?,
            value,
        )
    }

    /// Sets the field at `path` to `value`, unvalidated, as [`CarParams::set_field`] does
    /// for its name.
    ///
    /// # Errors
    /// As [`CarParams::set_field`]; [`FieldError::UnknownField`] for
    /// `WheelSetting::Field(WheelField::Physics)`, which names no value.
    pub fn set(&mut self, path: FieldPath, value: FieldValue<'_, T>) -> Result<(), FieldError> {
        let field = match path {
            FieldPath::Car(field) => field,
            FieldPath::Wheel(slot, setting) => {
                return set_wheel_field(&mut self.wheels, slot, setting, value);
            }
        };
        let field_name = field.webots_name();
        let kind = field.kind();
        match (kind, value) {
            (FieldKind::Number, FieldValue::Number(v)) => {
                if let Some(slot) = self.number_mut(field) {
                    *slot = v;
                }
                Ok(())
            }
            (FieldKind::Numbers { min, max }, FieldValue::Numbers(values)) => {
                let len = values.len();
                if len < min || len > max {
                    return Err(FieldError::WrongLength {
                        field: field_name,
                        expected: kind,
                        len,
                    });
                }
                self.set_list(field, values);
                Ok(())
            }
            (FieldKind::Text, FieldValue::Text(text)) => self.set_text(field, text),
            _ => Err(FieldError::WrongKind {
                field: field_name,
                expected: kind,
            }),
        }
    }

    /// The scalar field `field`, or `None` for list and text fields.
    fn number_mut(&mut self, field: CarField) -> Option<&mut T> {
        Some(match field {
            CarField::TrackFront => &mut self.track_front,
            CarField::TrackRear => &mut self.track_rear,
            CarField::Wheelbase => &mut self.wheelbase,
            CarField::MinSteeringAngle => &mut self.min_steering_angle,
            CarField::MaxSteeringAngle => &mut self.max_steering_angle,
            CarField::SuspensionFrontSpringConstant => &mut self.suspension_front_spring_constant,
            CarField::SuspensionFrontDampingConstant => &mut self.suspension_front_damping_constant,
            CarField::SuspensionRearSpringConstant => &mut self.suspension_rear_spring_constant,
            CarField::SuspensionRearDampingConstant => &mut self.suspension_rear_damping_constant,
            CarField::WheelsDampingConstant => &mut self.wheels_damping_constant,
            CarField::MaxSteeringTorque => &mut self.max_steering_torque,
            CarField::EngineSoundRpmReference => &mut self.engine_sound_rpm_reference,
            CarField::BrakeCoefficient => &mut self.brake_coefficient,
            CarField::Time0To100 => &mut self.time_0_to_100,
            CarField::MaxVelocity => &mut self.max_velocity,
            CarField::EngineMaxTorque => &mut self.engine.max_torque,
            CarField::EngineMaxPower => &mut self.engine.max_power,
            CarField::EngineMinRpm => &mut self.engine.min_rpm,
            CarField::EngineMaxRpm => &mut self.engine.max_rpm,
            CarField::HybridPowerSplitRatio => &mut self.engine.hybrid_power_split_ratio,
            CarField::HybridPowerSplitRpm => &mut self.engine.hybrid_power_split_rpm,
            CarField::Mass => &mut self.body.mass,
            CarField::Translation
            | CarField::Rotation
            | CarField::Type
            | CarField::EngineType
            | CarField::EngineSound
            | CarField::EngineFunctionCoefficients
            | CarField::GearRatio
            | CarField::CenterOfMass
            | CarField::InertiaMatrix => return None,
        })
    }

    /// Copies a list whose length was checked against `field.kind()`.
    fn set_list(&mut self, field: CarField, values: &[T]) {
        let copy = |dst: &mut [T]| {
            for (d, &v) in dst.iter_mut().zip(values) {
                *d = v;
            }
        };
        match field {
            CarField::Translation => copy(&mut self.translation),
            CarField::Rotation => copy(&mut self.rotation),
            CarField::CenterOfMass => copy(&mut self.body.center_of_mass),
            CarField::EngineFunctionCoefficients => copy(&mut self.engine.function_coefficients),
            CarField::InertiaMatrix => {
                let mut m = [T::ZERO; 6];
                copy(&mut m);
                self.body.inertia = Some(m);
            }
            CarField::GearRatio => {
                let mut table = GearRatios::new();
                for &r in values {
                    // The length was checked against the capacity.
                    let _ = table.push(r);
                }
                self.gear_ratios = table;
            }
            _ => {}
        }
    }

    fn set_text(&mut self, field: CarField, text: &str) -> Result<(), FieldError> {
        let invalid = FieldError::InvalidText {
            field: field.webots_name(),
            rule: field.rule(),
        };
        match field {
            CarField::Type => {
                self.drive_type = DriveType::from_webots_name(text).ok_or(invalid)?;
            }
            CarField::EngineType => {
                self.engine.engine_type = EngineType::from_webots_name(text).ok_or(invalid)?;
            }
            CarField::EngineSound => self.engine_sound = EngineSound::new(text).ok_or(invalid)?,
            _ => return Err(invalid),
        }
        Ok(())
    }
}

/// Sets one numeric `VehicleWheel` field of the wheels of `slot`.
fn set_wheel_field<T: Real>(
    wheels: &mut PerWheel<WheelParams<T>>,
    slot: WheelSlot,
    setting: WheelSetting,
    value: FieldValue<'_, T>,
) -> Result<(), FieldError> {
    let name = setting.webots_name();
    let FieldValue::Number(v) = value else {
        return Err(FieldError::WrongKind {
            field: name,
            expected: FieldKind::Number,
        });
    };
    let integer = || {
        let x = v.to_f64();
        if x.is_finite() && x == Real::trunc(x) && x.abs() <= f64::from(i32::MAX) {
            Ok(x as i32)
        } else {
            Err(FieldError::NotAnInteger {
                field: name,
                value: x,
            })
        }
    };
    let apply = |w: &mut WheelParams<T>| -> Result<(), FieldError> {
        use WheelField as F;
        match setting {
            WheelSetting::Field(field) => match field {
                F::Thickness => w.thickness = v,
                F::TireRadius => w.tire_radius = v,
                F::Subdivision => w.subdivision = integer()?,
                F::CurvatureFactor => w.curvature_factor = v,
                F::EdgeSubdivision => w.edge_subdivision = integer()?,
                F::RimRadius => w.rim_radius = v,
                F::RimBeamNumber => w.rim_beam_number = integer()?,
                F::RimBeamWidth => w.rim_beam_width = v,
                F::CentralInnerRadius => w.central_inner_radius = v,
                F::CentralOuterRadius => w.central_outer_radius = v,
                F::RimBeamThickness => w.rim_beam_thickness = v,
                F::RimBeamOffset => w.rim_beam_offset = v,
                F::Physics => return Err(FieldError::UnknownField),
            },
            WheelSetting::Mass => w.physics = WheelPhysics::Mass(v),
            WheelSetting::Density => w.physics = WheelPhysics::Density(v),
        }
        Ok(())
    };
    match slot {
        WheelSlot::One(wheel) => apply(&mut wheels[wheel]),
        WheelSlot::All => wheels.iter_mut().try_for_each(apply),
    }
}
