//! Parameter validation (invalid → default + warning) and setting fields by Webots name.

use proto_geom::WheelField;
use vehicle_model::{
    CarField, CarParams, DriveType, EngineType, FieldError, FieldKind, FieldPath, FieldValue,
    Model, ParamWarning, Wheel, WheelPhysics, WheelSetting, WheelSlot, WiperRange,
};

fn value(field: CarField, value: f64, used: f64) -> ParamWarning {
    ParamWarning::Value { field, value, used }
}

#[test]
fn each_scalar_rule_falls_back_with_a_warning() {
    let mut p = Model::BmwX5.params::<f64>();
    p.track_front = 0.0;
    p.track_rear = -1.0;
    p.wheels_damping_constant = 0.0;
    p.max_steering_torque = -5.0;
    p.suspension_rear_spring_constant = f64::INFINITY;
    p.engine_sound_rpm_reference = f64::NAN;
    p.time_0_to_100 = -7.0;
    p.max_velocity = 0.0;
    p.engine.hybrid_power_split_ratio = 1.5;
    p.engine.hybrid_power_split_rpm = 0.0;
    p.body.mass = -1.0;
    let report = p.validate();
    let expected = [
        value(CarField::TrackFront, 0.0, 1.7),
        value(CarField::TrackRear, -1.0, 1.7),
        value(
            CarField::SuspensionRearSpringConstant,
            f64::INFINITY,
            100_000.0,
        ),
        value(CarField::WheelsDampingConstant, 0.0, 5.0),
        value(CarField::MaxSteeringTorque, -5.0, 10_000.0),
        value(CarField::Time0To100, -7.0, 10.0),
        value(CarField::MaxVelocity, 0.0, 50.0),
        value(CarField::HybridPowerSplitRatio, 1.5, 0.25),
        value(CarField::HybridPowerSplitRpm, 0.0, 3000.0),
        value(CarField::Mass, -1.0, 1500.0),
    ];
    // The NaN reference is reported too (NaN ≠ NaN, so compared separately).
    assert_eq!(report.len(), expected.len() + 1);
    for w in &expected {
        assert!(report.iter().any(|r| r == w), "missing {w:?}");
    }
    assert!(matches!(
        report.get(CarField::EngineSoundRpmReference),
        Some(ParamWarning::Value { value, used: 1000.0, .. }) if value.is_nan()
    ));
    assert_eq!(p.track_front, 1.7);
    assert_eq!(p.max_steering_torque, 10_000.0);
    assert_eq!(p.engine_sound_rpm_reference, 1000.0);
    // Validating again finds nothing.
    assert!(p.validate().is_empty());
}

/// Found by the fuzzer: a plausible minimum whose fivefold, the fallback for a maximum not
/// above it, was not plausible, so a second validation refused what the first had set.
#[test]
fn engine_max_rpm_fallback_is_plausible() {
    let mut p = CarParams::<f64>::default();
    p.engine.min_rpm = 20_000.0; // the plausible limit: 5 × 20,000 rpm is the maximum's
    p.engine.max_rpm = 10.0;
    let report = p.validate();
    assert_eq!(
        report.as_slice(),
        &[value(CarField::EngineMaxRpm, 10.0, 100_000.0)]
    );
    assert!(p.validate().is_empty());

    let mut p = CarParams::<f32>::default();
    p.engine.min_rpm = 52_790.39;
    p.engine.max_rpm = 10.0;
    let report = p.validate();
    let r = report.as_slice();
    assert_eq!(r.len(), 2);
    assert!(matches!(
        r[0],
        ParamWarning::Implausible { field: CarField::EngineMinRpm, used, .. } if used == 1000.0
    ));
    // The default minimum is above 10 rpm, so the older rule gives 5 × 1000.
    assert_eq!(r[1], value(CarField::EngineMaxRpm, 10.0, 5000.0));
    assert!(p.validate().is_empty());
}

#[test]
fn engine_rpm_range_and_lists() {
    let mut p = CarParams::<f64>::default();
    p.engine.min_rpm = 2000.0;
    p.engine.max_rpm = 1500.0; // ≤ min: older Webots rule, 5 × min
    p.engine.function_coefficients = [1.0, f64::NAN, 0.0];
    p.gear_ratios.clear();
    p.gear_ratios.push(-5.0).unwrap();
    let report = p.validate();
    let r = report.as_slice();
    assert_eq!(r.len(), 3);
    assert_eq!(r[0], value(CarField::EngineMaxRpm, 1500.0, 10_000.0));
    assert!(matches!(
        r[1],
        ParamWarning::Element { field: CarField::EngineFunctionCoefficients, index: 1, value }
            if value.is_nan()
    ));
    assert_eq!(
        r[2],
        ParamWarning::Length {
            field: CarField::GearRatio,
            len: 1
        }
    );
    assert_eq!(p.engine.max_rpm, 10_000.0);
    assert_eq!(p.engine.function_coefficients, [150.0, 0.1, 0.0]);
    assert_eq!(p.gear_ratios.len(), 6);

    let mut p = CarParams::<f64>::default();
    p.gear_ratios[2] = 0.0;
    let report = p.validate();
    assert_eq!(
        report.as_slice(),
        &[ParamWarning::Element {
            field: CarField::GearRatio,
            index: 2,
            value: 0.0
        }]
    );
    assert_eq!(
        report.as_slice()[0].to_string(),
        "Warning: invalid 'gearRatio' element 2 value 0 (needs 2 to 16 finite, non-zero ratios), \
         used the default instead."
    );
}

#[test]
fn steering_limits_rotation_inertia_wipers_and_wheels() {
    let mut p = Model::BmwX5.params::<f64>();
    p.min_steering_angle = 0.5;
    p.max_steering_angle = 0.2;
    p.rotation = [0.0, 0.0, 0.0, 1.0];
    p.translation[1] = f64::NEG_INFINITY;
    p.body.inertia = Some([1.0, 1.0, 5.0, 0.0, 0.0, 0.0]);
    p.body.center_of_mass[2] = f64::NAN;
    p.wipers = Some(WiperRange { min: 1.0, max: 1.0 });
    p.wheels[Wheel::FrontLeft].tire_radius = -0.3;
    let report = p.validate();
    assert_eq!((p.min_steering_angle, p.max_steering_angle), (-1.0, 1.0));
    assert_eq!(p.rotation, [0.0, 0.0, 1.0, 0.0]);
    assert_eq!(p.translation, [0.0, 0.0, 0.4]);
    assert_eq!(p.body.inertia, None);
    assert_eq!(p.body.center_of_mass, [2.995 / 2.0, 0.0, 0.0]);
    assert_eq!(p.wipers, None);
    assert_eq!(p.wheels[Wheel::FrontLeft].tire_radius, 0.4);
    assert!(report.get(CarField::Rotation).is_some());
    assert!(report.get(CarField::InertiaMatrix).is_some());
    assert!(
        report
            .iter()
            .any(|w| matches!(w, ParamWarning::WiperRange { .. }))
    );
    let wheel = report
        .iter()
        .find(|w| matches!(w, ParamWarning::Wheel { .. }))
        .unwrap();
    assert!(matches!(
        wheel,
        ParamWarning::Wheel {
            slot: Wheel::FrontLeft,
            ..
        }
    ));
    assert!(
        wheel
            .to_string()
            .starts_with("Warning: wheelFrontLeft: 'tireRadius'")
    );
}

#[test]
fn report_capacity_counts_the_overflow() {
    let mut p = CarParams::<f32>::default();
    for w in p.wheels.iter_mut() {
        w.thickness = -1.0;
        w.tire_radius = -1.0;
        w.curvature_factor = 7.0;
        w.rim_beam_width = -1.0;
        w.central_inner_radius = -1.0;
        w.central_outer_radius = -1.0;
        w.rim_beam_thickness = -1.0;
        w.subdivision = 0;
        w.edge_subdivision = 0;
        w.rim_beam_number = 0;
    }
    let report = p.validate();
    assert_eq!(report.len(), vehicle_model::MAX_PARAM_WARNINGS);
    assert!(report.dropped() > 0);
    assert_eq!(report.total(), report.len() + report.dropped());
    assert!(!report.is_empty());
    // Like Webots, a `subdivision` of 8 (the fallback) still triggers its message; nothing
    // else is left to repair.
    let again = p.validate();
    assert_eq!(again.len(), 4);
    assert!(
        again
            .iter()
            .all(|w| w.to_string().contains("'subdivision'"))
    );
}

#[test]
fn set_field_by_webots_name() {
    let mut p = CarParams::<f64>::default();
    p.set_field("trackFront", FieldValue::Number(1.5)).unwrap();
    p.set_field("engineMinRPM", FieldValue::Number(900.0))
        .unwrap();
    p.set_field("engineType", FieldValue::Text("parallel hybrid"))
        .unwrap();
    p.set_field("type", FieldValue::Text("propulsion")).unwrap();
    p.set_field("engineSound", FieldValue::Text("")).unwrap();
    p.set_field("translation", FieldValue::Numbers(&[1.0, 2.0, 0.5]))
        .unwrap();
    p.set_field(
        "inertiaMatrix",
        FieldValue::Numbers(&[1.0, 2.0, 2.5, 0.0, 0.0, 0.0]),
    )
    .unwrap();
    p.set_field("wheelRearLeft.mass", FieldValue::Number(12.0))
        .unwrap();
    p.set_field("wheels.subdivision", FieldValue::Number(48.0))
        .unwrap();
    assert_eq!(p.track_front, 1.5);
    assert_eq!(p.engine.min_rpm, 900.0);
    assert_eq!(p.engine.engine_type, EngineType::ParallelHybrid);
    assert_eq!(p.drive_type, DriveType::Propulsion);
    assert!(p.engine_sound.is_none());
    assert_eq!(p.translation, [1.0, 2.0, 0.5]);
    assert_eq!(p.body.inertia, Some([1.0, 2.0, 2.5, 0.0, 0.0, 0.0]));
    assert_eq!(p.wheels[Wheel::RearLeft].physics, WheelPhysics::Mass(12.0));
    assert!(p.wheels.iter().all(|w| w.subdivision == 48));
    assert!(p.clone().validate().is_empty());

    // Every listed name is accepted with a value of its kind.
    for field in CarField::ALL {
        let name = field.webots_name();
        assert!(CarParams::<f64>::FIELD_NAMES.contains(&name));
        let mut q = CarParams::<f64>::default();
        let numbers = [1.0, 2.0, 2.5, 0.0, 0.0, 0.0];
        let v = match field.kind() {
            FieldKind::Number => FieldValue::Number(1.0),
            FieldKind::Numbers { min, .. } => FieldValue::Numbers(&numbers[..min]),
            FieldKind::Text => FieldValue::Text(match field {
                CarField::Type => "4x4",
                CarField::EngineType => "electric",
                _ => "a.wav",
            }),
        };
        assert_eq!(q.set_field(name, v), Ok(()), "{name}");
    }
    for name in CarParams::<f64>::WHEEL_FIELD_NAMES {
        let mut q = CarParams::<f64>::default();
        assert_eq!(
            q.set_field(&format!("wheelFrontRight.{name}"), FieldValue::Number(9.0)),
            Ok(())
        );
    }
}

#[test]
fn field_paths_parse_once_and_name_what_they_set() {
    // Every name parses to the path that prints it back, and setting by path is setting by
    // name.
    let wheel_paths = WheelSlot::ALL
        .into_iter()
        .flat_map(|slot| WheelSetting::ALL.map(|setting| FieldPath::Wheel(slot, setting)));
    let paths: Vec<FieldPath> = CarField::ALL
        .map(FieldPath::Car)
        .into_iter()
        .chain(wheel_paths)
        .collect();
    assert_eq!(paths.len(), 31 + 5 * 14);
    for path in paths {
        let name = path.to_string();
        assert_eq!(FieldPath::parse(&name), Some(path), "{name}");
        if path.kind() == FieldKind::Number {
            let (mut by_name, mut by_path) = (Model::BmwX5.params(), Model::BmwX5.params());
            // 9 is an integer, a length, a mass and a density, and no number of the BmwX5.
            assert_eq!(
                by_name.set_field(&name, FieldValue::Number(9.0)),
                Ok(()),
                "{name}"
            );
            assert_eq!(by_path.set(path, FieldValue::Number(9.0)), Ok(()), "{name}");
            assert_eq!(by_name, by_path, "{name}");
            assert_ne!(by_name, Model::BmwX5.params(), "{name} changed nothing");
        }
    }
    // The names lists are the enums' names.
    assert_eq!(
        CarParams::<f64>::WHEEL_SLOT_NAMES,
        [
            "wheelFrontRight",
            "wheelFrontLeft",
            "wheelRearRight",
            "wheelRearLeft",
            "wheels"
        ]
    );
    assert_eq!(
        CarParams::<f64>::WHEEL_FIELD_NAMES,
        WheelSetting::ALL.map(|s| s.webots_name())
    );
    // A setting names the VehicleWheel field its warnings name: itself, or `physics` for the
    // mass and the density of the Physics node.
    for setting in WheelSetting::ALL {
        let field = setting.field();
        assert_ne!(setting, WheelSetting::Field(WheelField::Physics));
        match setting {
            WheelSetting::Mass | WheelSetting::Density => assert_eq!(field, WheelField::Physics),
            _ => assert_eq!(field.webots_name(), setting.webots_name()),
        }
    }
    // `physics` itself holds no number: refused, the params unchanged.
    assert_eq!(FieldPath::parse("wheels.physics"), None);
    let mut p = CarParams::<f64>::default();
    let physics = FieldPath::Wheel(WheelSlot::All, WheelSetting::Field(WheelField::Physics));
    assert_eq!(
        p.set(physics, FieldValue::Number(3.0)),
        Err(FieldError::UnknownField)
    );
    assert_eq!(p, CarParams::default());
    for bad in [
        "",
        ".",
        "wheels.",
        ".mass",
        "wheels.mass.x",
        "wheel.mass",
        "Wheelbase",
    ] {
        assert_eq!(FieldPath::parse(bad), None, "{bad}");
    }
}

#[test]
fn set_field_errors_leave_params_unchanged() {
    let mut p = CarParams::<f64>::default();
    let before = p.clone();
    assert_eq!(
        p.set_field("wheelBase", FieldValue::Number(1.0)),
        Err(FieldError::UnknownField)
    );
    assert_eq!(
        p.set_field("", FieldValue::Number(1.0)),
        Err(FieldError::UnknownField)
    );
    assert_eq!(
        p.set_field("wheelMiddle.tireRadius", FieldValue::Number(1.0)),
        Err(FieldError::UnknownField)
    );
    assert_eq!(
        p.set_field("wheels.color", FieldValue::Number(1.0)),
        Err(FieldError::UnknownField)
    );
    assert_eq!(
        p.set_field("wheelbase", FieldValue::Text("long")),
        Err(FieldError::WrongKind {
            field: "wheelbase",
            expected: FieldKind::Number
        })
    );
    assert_eq!(
        p.set_field("gearRatio", FieldValue::Numbers(&[1.0])),
        Err(FieldError::WrongLength {
            field: "gearRatio",
            expected: FieldKind::Numbers { min: 2, max: 16 },
            len: 1
        })
    );
    assert!(
        p.set_field("gearRatio", FieldValue::Numbers(&[1.0; 17]))
            .is_err()
    );
    assert!(
        p.set_field("translation", FieldValue::Numbers(&[1.0, 2.0]))
            .is_err()
    );
    assert_eq!(
        p.set_field("type", FieldValue::Text("4X4")),
        Err(FieldError::InvalidText {
            field: "type",
            rule: CarField::Type.rule()
        })
    );
    assert!(
        p.set_field("engineType", FieldValue::Text("diesel"))
            .is_err()
    );
    assert!(
        p.set_field("engineSound", FieldValue::Text(&"x".repeat(64)))
            .is_err()
    );
    assert_eq!(
        p.set_field("wheels.subdivision", FieldValue::Number(10.5)),
        Err(FieldError::NotAnInteger {
            field: "subdivision",
            value: 10.5
        })
    );
    assert!(
        p.set_field("wheels.rimBeamNumber", FieldValue::Number(f64::NAN))
            .is_err()
    );
    assert!(
        p.set_field("wheels.edgeSubdivision", FieldValue::Number(1e12))
            .is_err()
    );
    assert!(
        p.set_field("wheels.mass", FieldValue::Numbers(&[1.0]))
            .is_err()
    );
    assert_eq!(p, before);
    // Numbers are stored unvalidated; `validate` repairs them.
    p.set_field("wheelbase", FieldValue::Number(f64::NAN))
        .unwrap();
    assert!(p.wheelbase.is_nan());
    assert_eq!(p.validate().len(), 1);
    assert_eq!(
        FieldError::WrongLength {
            field: "rotation",
            expected: FieldKind::Numbers { min: 4, max: 4 },
            len: 3
        }
        .to_string(),
        "field 'rotation' takes a list of 4 numbers, got 3"
    );
}

#[test]
fn every_number_outside_its_plausible_range_is_replaced() {
    // Each field set through its Webots name to a value just beyond its plausible range (or,
    // for lists, with one element beyond it): exactly one implausible warning for that field,
    // and the value is replaced by a plausible one (validating twice finds nothing more).
    for field in CarField::ALL {
        let (Some(range), FieldKind::Number | FieldKind::Numbers { .. }) =
            (field.plausible(), field.kind())
        else {
            continue;
        };
        let beyond = if range.max > 0.0 {
            range.max * 10.0
        } else {
            range.min * 10.0
        };
        let mut p = Model::BmwX5.params::<f64>();
        let set = match field.kind() {
            FieldKind::Number => p.set_field(field.webots_name(), FieldValue::Number(beyond)),
            _ => {
                let mut list = [1.0, 2.0, 3.0, 0.5, 0.2, 0.1];
                list[1] = beyond;
                let n = match field.kind() {
                    FieldKind::Numbers { max, .. } => max.min(6),
                    _ => unreachable!(),
                };
                p.set_field(field.webots_name(), FieldValue::Numbers(&list[..n]))
            }
        };
        set.unwrap_or_else(|e| panic!("{field}: {e}"));
        let report = p.validate();
        let implausible: Vec<_> = report.iter().filter(|w| w.is_implausible()).collect();
        assert_eq!(implausible.len(), 1, "{field}: {:?}", report.as_slice());
        assert_eq!(implausible[0].field(), Some(field), "{field}");
        assert!(p.validate().is_empty(), "{field}");
        if let ParamWarning::Implausible { value, used, .. } = *implausible[0] {
            assert_eq!(value, beyond, "{field}");
            assert!(range.contains(used), "{field}: {used}");
        }
    }
}

#[test]
fn the_fuzzed_implausible_values_are_refused() {
    // The values of the hardening review that loaded silently and failed (or produced a stop
    // distance of −2682 m) later.
    let cases: [(&str, FieldValue<'_, f64>); 8] = [
        ("mass", FieldValue::Number(1e300)),
        ("mass", FieldValue::Number(1e-300)),
        ("wheelbase", FieldValue::Number(1e-9)),
        ("trackFront", FieldValue::Number(1e300)),
        ("suspensionFrontSpringConstant", FieldValue::Number(1e300)),
        ("centerOfMass", FieldValue::Numbers(&[1e300, 0.0, 0.0])),
        ("gearRatio", FieldValue::Numbers(&[-12.5, 1e6])),
        ("wheelFrontLeft.tireRadius", FieldValue::Number(1e300)),
    ];
    for (name, value) in cases {
        let mut p = Model::BmwX5.params::<f64>();
        p.set_field(name, value).unwrap();
        let report = p.validate();
        assert!(
            report.len() == 1 && report.as_slice()[0].is_implausible(),
            "{name}: {:?}",
            report.as_slice()
        );
    }
    let mut p = Model::BmwX5.params::<f64>();
    p.set_field("gearRatio", FieldValue::Numbers(&[-12.5, 1e6]))
        .unwrap();
    assert_eq!(
        p.validate().as_slice()[0].to_string(),
        "Warning: implausible 'gearRatio' element 1 value 1000000 (its magnitude must be within 0.1 \
         to 100), used the default instead."
    );
}
