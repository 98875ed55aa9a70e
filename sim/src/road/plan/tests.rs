use super::*;
use core::f64::consts::{FRAC_PI_2, PI};

fn segment(length: f64, curve: Curve) -> Segment {
    Segment {
        s: 0.0,
        start: Point2::new(10.0, -5.0),
        heading: 0.3,
        length,
        curve,
    }
}

/// ∫₀ˢ (cos θ, sin θ) dt for θ = h + k₀t + ct²/2 by 5-point Gauss–Legendre on 2000 panels:
/// an independent reference, exact to ~1e-12 m over a few hundred metres.
fn quadrature(h: f64, k0: f64, c: f64, s: f64) -> Vector2<f64> {
    let nodes = [
        (0.0, 128.0 / 225.0),
        (-0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
        (0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
        (-0.906_179_845_938_664, 0.236_926_885_056_189_1),
        (0.906_179_845_938_664, 0.236_926_885_056_189_1),
    ];
    let n = 2000;
    let dh = s / n as f64;
    let mut sum = Vector2::zeros();
    for i in 0..n {
        let mid = (i as f64 + 0.5) * dh;
        for (x, w) in nodes {
            let t = mid + x * dh / 2.0;
            let th = h + k0 * t + 0.5 * c * t * t;
            sum += Vector2::new(th.cos(), th.sin()) * (w * dh / 2.0);
        }
    }
    sum
}

#[test]
fn a_line_and_an_arc_are_exact() {
    let g = segment(50.0, Curve::Line);
    let p = g.pose_at(20.0);
    assert!(
        (p.point - Point2::new(10.0 + 20.0 * 0.3_f64.cos(), -5.0 + 20.0 * 0.3_f64.sin())).norm()
            < 1e-12
    );
    // An arc of radius 25 m turning left: its centre is 25 m to the left of the start.
    let r = 25.0;
    let g = segment(r * FRAC_PI_2, Curve::Arc { curvature: 1.0 / r });
    let centre = g.start + Vector2::new(-0.3_f64.sin(), 0.3_f64.cos()) * r;
    for ds in [0.0, 1.0, 13.7, r * FRAC_PI_2] {
        let p = g.pose_at(ds);
        // Every point at r from the centre, at the angle swept so far.
        assert!(((p.point - centre).norm() - r).abs() < 1e-12);
        assert!((p.heading - (0.3 + ds / r)).abs() < 1e-15);
    }
    let end = g.end().point - centre;
    let expected = Vector2::new((0.3_f64).cos(), (0.3_f64).sin()) * r; // quarter turn from −left
    assert!((end - expected).norm() < 1e-12, "{end:?}");
}

#[test]
fn a_clothoid_from_zero_curvature_is_the_fresnel_integrals() {
    // κ = s/A²: x = A√π·C(s/(A√π)), y = A√π·S(s/(A√π)) in the segment's frame.
    let a2: f64 = 400.0; // A² (m²)
    let length = 60.0;
    let g = Segment {
        s: 0.0,
        start: Point2::origin(),
        heading: 0.0,
        length,
        curve: Curve::Spiral {
            curvature_start: 0.0,
            curvature_end: length / a2,
        },
    };
    let scale = (a2 * PI).sqrt();
    for s in [0.5, 10.0, 33.3, 60.0] {
        let (c, sn) = fresnel(s / scale);
        let p = g.pose_at(s);
        assert!((p.point - Point2::new(scale * c, scale * sn)).norm() < 1e-12);
        assert!((p.heading - s * s / (2.0 * a2)).abs() < 1e-15);
        assert!((p.curvature - s / a2).abs() < 1e-15);
    }
}

#[test]
fn clothoids_of_any_curvatures_agree_with_quadrature() {
    // Curvature rising, falling, changing sign, and one that barely changes (the near-arc
    // branch: κ₀²/c = 10⁸ > π·10⁶).
    for (k0, k1, length) in [
        (0.01, 0.05, 80.0),
        (0.05, -0.02, 120.0),
        (-0.03, -0.001, 40.0),
        (0.1, 0.1 + 1e-10 * 50.0, 50.0),
        (-0.1, -0.1 - 1e-10 * 50.0, 50.0),
    ] {
        let g = segment(
            length,
            Curve::Spiral {
                curvature_start: k0,
                curvature_end: k1,
            },
        );
        let c = (k1 - k0) / length;
        for ds in [0.0, 0.37 * length, length] {
            let p = g.pose_at(ds);
            let q = g.start + quadrature(0.3, k0, c, ds);
            // The quadrature's own error bounds the agreement: 1e-9 m.
            assert!(
                (p.point - q).norm() < 1e-9,
                "{k0} {k1} {ds}: {:?} {:?}",
                p.point,
                q
            );
        }
    }
}

#[test]
fn a_param_poly3_is_its_polynomial() {
    let (u, v) = ([0.0, 30.0, -2.0, 0.5], [0.0, 0.0, 4.0, -1.5]);
    for range in [ParamRange::Normalized, ParamRange::ArcLength] {
        let length = 29.0;
        let g = segment(length, Curve::ParamPoly3 { u, v, range });
        for ds in [0.0, 7.0, 29.0] {
            let p = match range {
                ParamRange::Normalized => ds / length,
                ParamRange::ArcLength => ds,
            };
            let (pu, du, _) = cubic(&u, p);
            let (pv, dv, _) = cubic(&v, p);
            let (sn, cs) = 0.3_f64.sin_cos();
            let expected = Point2::new(10.0 + cs * pu - sn * pv, -5.0 + sn * pu + cs * pv);
            let pose = g.pose_at(ds);
            assert!((pose.point - expected).norm() < 1e-12);
            assert!((pose.heading - (0.3 + dv.atan2(du))).abs() < 1e-14);
        }
    }
    // The arc length of a straight cubic u = 3p: 3.
    assert!((cubic_length(&[0.0, 3.0, 0.0, 0.0], &[0.0; 4], 1.0) - 3.0).abs() < 1e-12);
    // Of v = p² over p in 0..1: (2√5 + asinh 2)/4.
    let exact = (2.0 * 5.0_f64.sqrt() + 2.0_f64.asinh()) / 4.0;
    assert!(
        (cubic_length(&[0.0, 1.0, 0.0, 0.0], &[0.0, 0.0, 1.0, 0.0], 1.0) - exact).abs() < 1e-12
    );
}

#[test]
fn nearest_finds_the_foot_of_the_normal() {
    for curve in [
        Curve::Line,
        Curve::Arc { curvature: 0.02 },
        Curve::Spiral {
            curvature_start: -0.01,
            curvature_end: 0.03,
        },
        Curve::ParamPoly3 {
            u: [0.0, 40.0, 0.0, 0.0],
            v: [0.0, 0.0, 5.0, -2.0],
            range: ParamRange::Normalized,
        },
    ] {
        let g = segment(40.0, curve);
        for (ds, off) in [(3.0, 2.5), (20.0, -4.0), (39.0, 1.0)] {
            let pose = g.pose_at(ds);
            let p = pose.point + pose.left() * off;
            let (found, d2) = nearest(&g, &p);
            assert!((found - ds).abs() < 1e-7, "{curve:?} {ds}: {found}");
            assert!((d2.sqrt() - off.abs()).abs() < 1e-7);
        }
    }
}
