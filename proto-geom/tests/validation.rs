//! The `VehicleWheel` parameter checks of spec §4.4, one rule at a time, and robustness.
// Test helpers outside #[test] functions unwrap too: a failed lookup is a failed test.
#![allow(clippy::unwrap_used, clippy::expect_used)]

use proto_geom::{
    TriMesh, WheelField, WheelParams, WheelPhysics, WheelPreset, WheelRule, WheelShape, WheelSide,
};

type P = WheelParams<f64>;

/// Validates `p` and returns the single warning it must produce.
fn single(p: P) -> proto_geom::WheelWarning {
    let (_, w) = p.validate();
    assert_eq!(w.len(), 1, "{w:?}");
    w.as_slice()[0]
}

#[test]
fn defaults_are_vehicle_wheel_r2023b() {
    let d = P::default();
    assert_eq!((d.thickness, d.tire_radius, d.subdivision), (0.3, 0.4, 36));
    assert_eq!(
        (d.curvature_factor, d.edge_subdivision, d.rim_radius),
        (0.35, 3, 0.28)
    );
    assert_eq!((d.rim_beam_number, d.rim_beam_width), (5, 0.1));
    assert_eq!(
        (d.central_inner_radius, d.central_outer_radius),
        (0.09, 0.13)
    );
    assert_eq!((d.rim_beam_thickness, d.rim_beam_offset), (0.2, 0.03));
    assert_eq!((d.name, d.contact_material), ("vehicle wheel", "default"));
    assert_eq!(d.physics, WheelPhysics::Density(1000.0));
    assert!(d.bounding_object);
    assert_eq!(
        (d.side, d.shape),
        (WheelSide::Right, WheelShape::VehicleWheel)
    );
    let old = P::automobile_wheel_2014();
    assert_eq!((old.subdivision, old.edge_subdivision), (24, 1));
    assert!(d.validate().1.is_empty() && old.validate().1.is_empty());
}

#[test]
fn every_preset_validates_cleanly_and_round_trips_its_name() {
    for p in WheelPreset::ALL {
        let (_, w) = p.params::<f64>().validate();
        assert!(w.is_empty(), "{p:?}: {w:?}");
        assert_eq!(WheelPreset::from_proto_name(p.proto_name()), Some(p));
    }
    assert_eq!(WheelPreset::from_proto_name("bmwx5wheel"), None);
    assert_eq!(
        WheelPreset::TeslaModel3Wheel.shape(),
        WheelShape::CustomMesh
    );
    assert_eq!(WheelPreset::TractorRearWheel.shape(), WheelShape::Cylinder);
}

#[test]
fn integer_fields() {
    // subdivision ≤ 8 → 8, and 8 itself is reported as in Webots.
    for s in [-3, 5, 8] {
        let w = single(P {
            subdivision: s,
            ..P::default()
        });
        assert_eq!(
            (w.field, w.rule),
            (WheelField::Subdivision, WheelRule::SubdivisionTooLow)
        );
        assert_eq!((w.value, w.replacement), (f64::from(s), 8.0));
    }
    let ok = P {
        subdivision: 9,
        ..P::default()
    };
    assert!(ok.validate().1.is_empty());
    // > 200 → information only, value kept.
    let (v, w) = P {
        subdivision: 201,
        ..P::default()
    }
    .validate();
    assert_eq!(v.subdivision(), 201);
    assert!(w.as_slice()[0].is_info() && !w.has_errors());
    // Beyond this crate's limit → the limit.
    let (v, w) = P {
        subdivision: i32::MAX,
        ..P::default()
    }
    .validate();
    assert_eq!(v.subdivision(), 10_000);
    assert_eq!(w.as_slice()[0].rule, WheelRule::AboveLimit);
    // edgeSubdivision < 1 → default 3; > 24 → info.
    let w = single(P {
        edge_subdivision: 0,
        ..P::default()
    });
    assert_eq!(
        (w.rule, w.replacement),
        (WheelRule::EdgeSubdivisionTooLow, 3.0)
    );
    let w = single(P {
        edge_subdivision: 25,
        ..P::default()
    });
    assert_eq!(
        (w.field, w.rule),
        (WheelField::EdgeSubdivision, WheelRule::HighValue)
    );
    // rimBeamNumber < 3 → 3.
    let w = single(P {
        rim_beam_number: 2,
        ..P::default()
    });
    assert_eq!(
        (w.rule, w.replacement),
        (WheelRule::RimBeamNumberTooLow, 3.0)
    );
}

#[test]
fn real_fields() {
    let d = P::default();
    let cases: [(P, WheelField, WheelRule, f64); 14] = [
        (
            P {
                thickness: -1.0,
                ..d
            },
            WheelField::Thickness,
            WheelRule::NotPositive,
            0.3,
        ),
        (
            P {
                thickness: f64::NAN,
                ..d
            },
            WheelField::Thickness,
            WheelRule::NotFinite,
            0.3,
        ),
        (
            P {
                rim_beam_thickness: 0.0,
                ..d
            },
            WheelField::RimBeamThickness,
            WheelRule::NotPositive,
            0.2,
        ),
        // 0.25 > thickness 0.2 → 0.2 (offset 0 so that the offset maximum (0.2 − 0.2)/2 = 0
        // does not fire as well).
        (
            P {
                rim_beam_thickness: 0.25,
                rim_beam_offset: 0.0,
                thickness: 0.2,
                rim_radius: 0.2,
                central_outer_radius: 0.13,
                ..d
            },
            WheelField::RimBeamThickness,
            WheelRule::RimBeamThicknessAboveThickness,
            0.2,
        ),
        (
            P {
                tire_radius: 0.0,
                ..d
            },
            WheelField::TireRadius,
            WheelRule::NotPositive,
            0.4,
        ),
        (
            P {
                curvature_factor: 1.5,
                ..d
            },
            WheelField::CurvatureFactor,
            WheelRule::CurvatureOutOfRange,
            0.35,
        ),
        (
            P {
                curvature_factor: f64::INFINITY,
                ..d
            },
            WheelField::CurvatureFactor,
            WheelRule::NotFinite,
            0.35,
        ),
        // rimRadius > R − (T/2)·c = 0.4 − 0.15·0.35 = 0.3475 → R/2 = 0.2.
        (
            P {
                rim_radius: 0.35,
                ..d
            },
            WheelField::RimRadius,
            WheelRule::RimRadiusTooLarge,
            0.2,
        ),
        (
            P {
                rim_radius: -0.1,
                ..d
            },
            WheelField::RimRadius,
            WheelRule::NotPositive,
            0.2,
        ),
        (
            P {
                rim_beam_width: 0.28,
                ..d
            },
            WheelField::RimBeamWidth,
            WheelRule::RimBeamWidthTooLarge,
            0.1,
        ),
        (
            P {
                central_inner_radius: 0.0,
                ..d
            },
            WheelField::CentralInnerRadius,
            WheelRule::NotPositive,
            0.09,
        ),
        (
            P {
                central_outer_radius: 0.05,
                ..d
            },
            WheelField::CentralOuterRadius,
            WheelRule::CentralOuterNotAboveInner,
            0.09,
        ),
        (
            P {
                central_outer_radius: 0.3,
                ..d
            },
            WheelField::CentralOuterRadius,
            WheelRule::CentralOuterNotBelowRim,
            0.28,
        ),
        // rimBeamOffset > (0.3 − 0.2)/2 = 0.05 → 0.05.
        (
            P {
                rim_beam_offset: 0.06,
                ..d
            },
            WheelField::RimBeamOffset,
            WheelRule::RimBeamOffsetTooLarge,
            0.05,
        ),
    ];
    for (p, field, rule, replacement) in cases {
        let w = single(p);
        assert_eq!((w.field, w.rule), (field, rule), "{p:?}");
        assert!((w.replacement - replacement).abs() < 1e-15, "{w:?}");
    }
}

#[test]
fn relations_use_corrected_values() {
    // thickness −1 → 0.3 first, so rimBeamThickness 0.25 is then valid (≤ 0.3).
    let (v, w) = P {
        thickness: -1.0,
        rim_beam_thickness: 0.25,
        rim_beam_offset: 0.0,
        ..P::default()
    }
    .validate();
    assert_eq!(w.len(), 1);
    assert_eq!(v.params().rim_beam_thickness, 0.25);
    // tireRadius 0 → 0.4, then rimRadius 0.39 > 0.3475 → tireRadius/2 = 0.2, then
    // rimBeamWidth 0.25 ≥ 0.2 → 0.1: three warnings, in the PROTO's order.
    let (v, w) = P {
        tire_radius: 0.0,
        rim_radius: 0.39,
        rim_beam_width: 0.25,
        ..P::default()
    }
    .validate();
    let fields: Vec<_> = w.iter().map(|w| w.field).collect();
    assert_eq!(
        fields,
        [
            WheelField::TireRadius,
            WheelField::RimRadius,
            WheelField::RimBeamWidth
        ]
    );
    assert_eq!(
        (v.params().rim_radius, v.params().rim_beam_width),
        (0.2, 0.1)
    );
    // Like Webots, a fallback is not re-checked: rimBeamThickness 0 → 0.2 stays above a
    // 0.1 m thickness, and the offset maximum (0.1 − 0.2)/2 = −0.05 then applies.
    let (v, w) = P {
        thickness: 0.1,
        rim_beam_thickness: 0.0,
        ..P::default()
    }
    .validate();
    assert_eq!(v.params().rim_beam_thickness, 0.2);
    assert!((v.params().rim_beam_offset + 0.05).abs() < 1e-15);
    assert_eq!(w.len(), 2);
}

#[test]
fn physics_and_mass() {
    let w = single(P {
        physics: WheelPhysics::Mass(-5.0),
        ..P::default()
    });
    assert_eq!(
        (w.field, w.rule, w.replacement),
        (WheelField::Physics, WheelRule::NotPositive, 1000.0)
    );
    // Physics {}: 1000 kg/m³ × π·0.4²·0.3 m³ = 150.796 kg.
    let (d, _) = P::default().validate();
    assert!((d.mass().unwrap() - 1000.0 * std::f64::consts::PI * 0.16 * 0.3).abs() < 1e-9);
    // BmwX5: 30 kg; axial inertia m r²/2 = 30·0.374²/2 = 2.09814 kg·m²; transverse
    // m(3r² + h²)/12 = 30·(0.419628 + 0.0625)/12 = 1.20532 kg·m².
    let (b, _) = WheelPreset::BmwX5Wheel.params::<f64>().validate();
    let m = b.mass_properties().unwrap();
    assert_eq!(m.mass, 30.0);
    assert!((m.axial - 2.09814).abs() < 1e-9);
    assert!((m.transverse - 1.20532).abs() < 1e-9);
    // No physics, or no bounding object: no mass.
    let (n, _) = P {
        physics: WheelPhysics::None,
        ..P::default()
    }
    .validate();
    assert_eq!(n.mass(), None);
    let (n, _) = P {
        bounding_object: false,
        ..P::default()
    }
    .validate();
    assert_eq!((n.mass(), n.bounding_cylinder()), (None, None));
}

#[test]
fn messages_follow_webots() {
    let w = single(P {
        subdivision: 5,
        ..P::default()
    });
    assert_eq!(
        w.to_string(),
        "'subdivision' must be greater or equal to 8. Value reset to 8."
    );
    let w = single(P {
        thickness: -1.0,
        ..P::default()
    });
    assert_eq!(
        w.to_string(),
        "'thickness' must be strictly positive. Value reset to 0.3."
    );
    let w = single(P {
        subdivision: 300,
        ..P::default()
    });
    assert_eq!(
        w.to_string(),
        "High value for 'subdivision'. This can slow down the simulation."
    );
}

#[test]
fn hostile_input_never_panics_and_never_yields_non_finite_geometry() {
    let reals = [
        f64::NAN,
        f64::INFINITY,
        f64::NEG_INFINITY,
        -1.0,
        0.0,
        1e-9,
        0.1,
        0.3,
        5.0,
        1e12,
    ];
    let ints = [i32::MIN, -1, 0, 1, 3, 9, 40];
    let mut checked = 0;
    for (k, &a) in reals.iter().enumerate() {
        for (j, &b) in reals.iter().enumerate() {
            let p = P {
                thickness: a,
                tire_radius: b,
                curvature_factor: reals[(k + j) % reals.len()],
                rim_radius: reals[(k * 3 + j) % reals.len()],
                rim_beam_width: reals[(k + 2 * j) % reals.len()],
                central_inner_radius: reals[(2 * k + j) % reals.len()],
                central_outer_radius: b,
                rim_beam_thickness: a,
                rim_beam_offset: reals[(k + 5 * j) % reals.len()],
                subdivision: ints[k % ints.len()],
                edge_subdivision: ints[j % ints.len()],
                rim_beam_number: ints[(k + j) % ints.len()],
                physics: WheelPhysics::Mass(b),
                ..P::default()
            };
            let (v, _) = p.validate();
            let q = v.params();
            for x in [
                q.thickness,
                q.tire_radius,
                q.curvature_factor,
                q.rim_radius,
                q.rim_beam_width,
                q.central_inner_radius,
                q.central_outer_radius,
                q.rim_beam_thickness,
                q.rim_beam_offset,
            ] {
                assert!(x.is_finite(), "{p:?} -> {q:?}");
            }
            for m in [
                &v.tyre() as &dyn TriMesh<f64>,
                &v.rim_contour(),
                &v.rim_centre(),
            ] {
                for i in 0..m.vertex_count() {
                    assert!(m.position(i).unwrap().iter().all(|c| c.is_finite()));
                }
                for i in 0..m.normal_count() {
                    assert!(m.normal(i).unwrap().iter().all(|c| c.is_finite()));
                }
            }
            checked += 1;
        }
    }
    assert_eq!(checked, 100);
}

#[test]
fn f32_validation_matches_f64() {
    let (v, w) = WheelParams::<f32> {
        rim_radius: 0.35,
        ..Default::default()
    }
    .validate();
    assert_eq!(v.params().rim_radius, 0.2);
    assert_eq!(w.as_slice()[0].field, WheelField::RimRadius);
}
