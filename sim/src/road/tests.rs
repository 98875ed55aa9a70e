use super::*;
use core::f64::consts::PI;

/// A road of one arc of radius `r` (m) turning left through a half turn, two lanes each way
/// of 3.5 m, from the origin heading +x.
fn arc_road(r: f64) -> Road {
    let mut road = Road::two_way(
        "arc",
        Point2::origin(),
        0.0,
        &[(PI * r, Curve::Arc { curvature: 1.0 / r })],
        3.5,
    )
    .unwrap();
    let sec = &mut road.sections[0];
    let mut outer = sec.left[0].clone();
    outer.id = 2;
    sec.left.push(outer);
    let mut outer = sec.right[0].clone();
    outer.id = -2;
    outer.friction = Some(0.4);
    sec.right.push(outer);
    road.validate().unwrap();
    road
}

#[test]
fn arc_and_straight_lane_centres_are_exact() {
    let r = 50.0;
    let road = arc_road(r);
    let centre = Point2::new(0.0, r);
    for s in [0.0, 12.5, 80.0, PI * r] {
        let (_, edges) = road.lane_edges(s);
        for (lane, a, b) in edges {
            let t = 0.5 * (a + b);
            let p = road.surface_point(s, t);
            // A lane centre at t lies on the circle of radius r − t about the arc's centre.
            let d = (Point2::new(p.x, p.y) - centre).norm();
            assert!((d - (r - t)).abs() < 1e-3, "lane {}: {d}", lane.id);
            assert!((d - (r - t)).abs() < 1e-12);
            let expected = [-5.25, -1.75, 1.75, 5.25];
            assert!(expected.iter().any(|e| (t - e).abs() < 1e-12));
        }
    }
    let straight = Road::two_way(
        "s",
        Point2::new(1.0, 2.0),
        PI / 2.0,
        &[(100.0, Curve::Line)],
        3.0,
    )
    .unwrap();
    let p = straight.surface_point(30.0, -1.5);
    assert!((p - Point3::new(2.5, 32.0, 0.0)).norm() < 1e-12);
}

#[test]
fn elevation_and_superelevation_lift_the_surface() {
    let mut road = Road::two_way("h", Point2::origin(), 0.0, &[(200.0, Curve::Line)], 3.5).unwrap();
    // A crest: z = 2 + 0.1·s − 0.0005·s², and a bank rising from 0 to 0.1 rad.
    road.elevation = Profile::new(vec![Cubic {
        s: 0.0,
        coefficients: [2.0, 0.1, -0.0005, 0.0],
    }]);
    road.superelevation = Profile::new(vec![Cubic {
        s: 0.0,
        coefficients: [0.0, 0.0005, 0.0, 0.0],
    }]);
    road.validate().unwrap();
    for (s, t) in [(0.0, 0.0), (100.0, 3.0), (150.0, -2.0)] {
        let z = 2.0 + 0.1 * s - 0.0005 * s * s;
        let phi: f64 = 0.0005 * s;
        let p = road.surface_point(s, t);
        assert!((p.z - (z + t * phi.sin())).abs() < 1e-12);
        assert!((p.y - t * phi.cos()).abs() < 1e-12);
        // The round trip through the plan view gives t back in the banked surface.
        let (s2, t2, _) = road.station_of(&Point2::new(p.x, p.y));
        assert!((s2 - s).abs() < 1e-9 && (t2 - t).abs() < 1e-9);
    }
    // The vertical curvature of the crest: z'' = −0.001 1/m (a radius of 1 km).
    assert!((road.elevation.eval(50.0).2 + 0.001).abs() < 1e-15);
}

#[test]
fn station_and_position_round_trip_with_lane_lookup() {
    let segments = [
        (30.0, Curve::Line),
        (
            40.0,
            Curve::Spiral {
                curvature_start: 0.0,
                curvature_end: 0.02,
            },
        ),
        (60.0, Curve::Arc { curvature: 0.02 }),
        (
            40.0,
            Curve::Spiral {
                curvature_start: 0.02,
                curvature_end: 0.0,
            },
        ),
        (
            25.0,
            Curve::ParamPoly3 {
                u: [0.0, 25.0, 0.0, 0.0],
                v: [0.0, 0.0, 1.0, -0.5],
                range: ParamRange::Normalized,
            },
        ),
    ];
    let road = Road::two_way("mixed", Point2::new(-20.0, 7.0), 1.0, &segments, 3.5).unwrap();
    for s in [1.0, 29.9, 30.1, 55.0, 100.0, 150.0, 180.0, 194.0] {
        for t in [-3.0, -0.5, 0.5, 3.4] {
            let p = road.surface_point(s, t);
            let at = road.locate(&Point2::new(p.x, p.y)).unwrap();
            assert!(
                (at.s - s).abs() < 1e-6 && (at.t - t).abs() < 1e-6,
                "{s} {t}: {at:?}"
            );
            assert_eq!(at.lane, if t > 0.0 { 1 } else { -1 });
            assert!((at.lane_centre - 1.75 * t.signum()).abs() < 1e-12);
            assert_eq!(at.lane_width, 3.5);
        }
    }
    // Off the lanes and beyond the ends: nowhere.
    let p = road.surface_point(50.0, 4.0);
    assert!(road.locate(&Point2::new(p.x, p.y)).is_none());
    assert!(road.locate(&Point2::new(-25.0, 7.0)).is_none());
}

#[test]
fn friction_per_road_and_per_lane() {
    let road = arc_road(40.0);
    assert_eq!(road.friction_at(10.0, 1.0), 1.0);
    assert_eq!(road.friction_at(10.0, -6.0), 0.4);
    let meshes = road.lane_meshes(0.0);
    assert_eq!(meshes.len(), 4);
    assert_eq!(meshes.iter().find(|m| m.lane == -2).unwrap().friction, 0.4);
}

#[test]
fn implausible_values_are_refused() {
    let mut road = arc_road(40.0);
    road.sections[0].right[0].width = Profile::new(vec![Cubic {
        s: 0.0,
        coefficients: [3.0, -0.1, 0.0, 0.0],
    }]);
    let e = road.validate().unwrap_err();
    assert!(
        e.field.contains("lane -1 width") && e.message.contains("m at s = 30.9"),
        "{e}"
    );
    let bad = Road::two_way(
        "tight",
        Point2::origin(),
        0.0,
        &[(1.0, Curve::Arc { curvature: 3.0 })],
        3.0,
    )
    .unwrap_err();
    assert_eq!(bad.field, "segment 1 curvature");
    let bad = Road::two_way("zero", Point2::origin(), 0.0, &[(0.0, Curve::Line)], 3.0).unwrap_err();
    assert_eq!(
        bad.to_string(),
        "road 'zero': segment 1 length: 0 m: must be finite and > 0"
    );
    let long =
        Road::two_way("long", Point2::origin(), 0.0, &[(1e6, Curve::Line)], 3.0).unwrap_err();
    assert_eq!(long.message, "1000000 m: must be at most 100000 m");
    let mut road = arc_road(40.0);
    road.superelevation = Profile::constant(1.2);
    assert_eq!(road.validate().unwrap_err().field, "superelevation");
}
