//! Geometric invariants of the wheel meshes: no degenerate triangle, consistent outward
//! winding, exact volumes, radii and widths, normals.
// Test helpers outside #[test] functions unwrap too: a failed lookup is a failed test.
#![allow(clippy::unwrap_used, clippy::expect_used)]

mod common;

use common::{
    boundary_edges, double_areas, polygonal_revolution_volume, radial, vehicle_wheels,
    welded_boundary_edges,
};
use proto_geom::nalgebra::Vector3;
use proto_geom::{
    CylinderMesh, TriMesh, ValidWheel, WheelField, WheelParams, WheelPhysics, WheelPreset,
    WheelRule,
};

#[test]
fn no_degenerate_triangles() {
    for (name, w) in vehicle_wheels() {
        for (part, areas) in [
            ("tyre", double_areas(&w.tyre())),
            ("rim", double_areas(&w.rim_contour())),
            ("hub", double_areas(&w.rim_centre())),
        ] {
            let min = areas.iter().copied().fold(f64::INFINITY, f64::min);
            // The smallest faces are the hub fan wedges, ≈ 1e-3 m² for these wheels.
            assert!(
                min > 1e-6,
                "{name} {part}: degenerate triangle, 2·area = {min}"
            );
        }
    }
}

#[test]
fn winding_is_consistent_and_boundaries_are_as_designed() {
    for (name, w) in vehicle_wheels() {
        let (s, e, n) = (
            w.subdivision() as usize,
            w.edge_subdivision() as usize,
            w.rim_beam_number() as usize,
        );
        // Tyre: open along the two rim rings (S edges each) and, by index, along the texture
        // seam (2E + 3 strips on each of the two seam columns).
        assert_eq!(boundary_edges(&w.tyre()), 2 * s + 2 * (2 * e + 3), "{name}");
        // Rim contour: the two outer rings and the seam (3 strips × 2 columns).
        assert_eq!(boundary_edges(&w.rim_contour()), 2 * s + 6, "{name}");
        // Welded by position: the tyre is open only along its two rim rings, the rim contour
        // along its two outer rings, and together they are closed when S is even (their ring
        // points coincide).
        let (tyre, rim, hub) = (w.tyre(), w.rim_contour(), w.rim_centre());
        assert_eq!(welded_boundary_edges(&[&tyre]), 2 * s, "{name}");
        assert_eq!(welded_boundary_edges(&[&rim]), 2 * s, "{name}");
        if s % 2 == 0 {
            assert_eq!(welded_boundary_edges(&[&tyre, &rim]), 0, "{name}");
        }
        // Rim centre: closed except the N beam tips (hidden in the rim), each bounded by 5
        // edges: two on the front face (either side of the beam's centre line), one on each
        // side wall, one on the back.
        assert_eq!(welded_boundary_edges(&[&hub]), 5 * n, "{name}");
    }
}

/// The tyre profile (x, r) of ring `r`, read back from the mesh (column 0, angle 0 ⇒ y = −r).
fn profile(w: &ValidWheel<f64>) -> Vec<(f64, f64)> {
    let m = w.tyre();
    let len = w.subdivision() as usize + 1;
    (0..m.vertex_count() / len)
        .map(|r| {
            let p = m.position(r * len).unwrap();
            (p.x, -p.y)
        })
        .collect()
}

#[test]
fn closed_tyre_has_the_exact_positive_volume() {
    for (name, w) in vehicle_wheels() {
        let tyre = w.tyre();
        let len = w.subdivision() as usize + 1;
        let last = tyre.vertex_count() - len;
        // Close the tyre with the seat cylinder at rimRadius, wound like the other strips
        // (ring D → ring A).
        let mut closing = 0.0;
        for i in 0..len - 1 {
            let [a, b, c, d] =
                [last + i, last + i + 1, i + 1, i].map(|v| tyre.position(v).unwrap().coords);
            closing += a.dot(&b.cross(&c)) + c.dot(&d.cross(&a));
        }
        let volume = tyre.signed_volume() + closing / 6.0;
        let expected = polygonal_revolution_volume(&profile(&w), w.subdivision());
        assert!(volume > 0.0, "{name}: inward winding");
        assert!(
            (volume - expected).abs() < 1e-12 * expected.max(1.0),
            "{name}: {volume} vs {expected}"
        );
    }
}

#[test]
fn tyre_plus_rim_contour_encloses_the_tyre_and_rim_ring() {
    // Default wheel, S = 36 (even, so the tyre and rim rings share their points).
    let (w, _) = WheelParams::<f64>::default().validate();
    let volume = w.tyre().signed_volume() + w.rim_contour().signed_volume();
    // Profile: tyre rings A … D, then the rim's inner cylinder (0.9·0.28 = 0.252 m).
    let mut p = profile(&w);
    p.push((-0.15, 0.252));
    p.push((0.15, 0.252));
    let expected = polygonal_revolution_volume(&p, 36);
    assert!(volume > 0.0);
    assert!((volume - expected).abs() < 1e-12, "{volume} vs {expected}");
    // Sanity against the smooth solid: π·T·(R² − 0.252²) = 0.090945 m³ minus two shoulder
    // spandrels (side a = T·c/2 = 0.0525 m, area a²(1 − π/4), centroid radius
    // R − a + 2a/(3(4 − π))): 2·2π·0.38826·0.0005915 = 0.002886 m³, so 0.088059 m³; the
    // 36-gon keeps S·sin(2π/S)/2π = 99.49 % of it, the 3-segment shoulders lose another ~0.5 %.
    let pi = std::f64::consts::PI;
    let a = 0.3 * 0.35 / 2.0;
    let spandrel = a * a * (1.0 - pi / 4.0);
    let centroid = 0.4 - a + 2.0 * a / (3.0 * (4.0 - pi));
    let smooth = pi * 0.3 * (0.16 - 0.252 * 0.252) - 2.0 * 2.0 * pi * centroid * spandrel;
    let faceted = smooth * 36.0 * (std::f64::consts::TAU / 36.0).sin() / std::f64::consts::TAU;
    assert!(
        (volume / faceted - 1.0).abs() < 0.01,
        "{volume} vs {faceted}"
    );
}

#[test]
fn radii_and_widths() {
    for (name, w) in vehicle_wheels() {
        let p = *w.params();
        let tyre: Vec<_> = w.tyre().positions().collect();
        let max_r = tyre.iter().map(|v| radial(*v)).fold(0.0, f64::max);
        let min_r = tyre
            .iter()
            .map(|v| radial(*v))
            .fold(f64::INFINITY, f64::min);
        let min_x = tyre.iter().map(|v| v.x).fold(f64::INFINITY, f64::min);
        let max_x = tyre.iter().map(|v| v.x).fold(f64::NEG_INFINITY, f64::max);
        assert!(
            (max_r - p.tire_radius).abs() < 1e-12,
            "{name}: tread radius {max_r}"
        );
        assert!(
            (min_r - p.rim_radius).abs() < 1e-12,
            "{name}: seat radius {min_r}"
        );
        assert!((max_x - min_x - p.thickness).abs() < 1e-12, "{name}: width");
        // The tread rings (B_E and C_0) lie exactly on tireRadius.
        let len = w.subdivision() as usize + 1;
        let e = w.edge_subdivision() as usize;
        for ring in [e + 1, e + 2] {
            for i in 0..len {
                let r = radial(tyre[ring * len + i]);
                assert!((r - p.tire_radius).abs() < 1e-12, "{name}: ring {ring}");
            }
        }

        let rim: Vec<_> = w.rim_contour().positions().collect();
        let rim_max = rim.iter().map(|v| radial(*v)).fold(0.0, f64::max);
        let rim_min = rim.iter().map(|v| radial(*v)).fold(f64::INFINITY, f64::min);
        assert!((rim_max - p.rim_radius).abs() < 1e-12, "{name}");
        assert!((rim_min - 0.9 * p.rim_radius).abs() < 1e-12, "{name}");

        let hub: Vec<_> = w.rim_centre().positions().collect();
        let hub_max = hub.iter().map(|v| radial(*v)).fold(0.0, f64::max);
        assert!(
            (hub_max - p.rim_radius).abs() < 1e-12,
            "{name}: beams reach the rim"
        );
        let b = p.rim_beam_thickness;
        let off = p.rim_beam_offset;
        let hub_min_x = hub.iter().map(|v| v.x).fold(f64::INFINITY, f64::min);
        let hub_max_x = hub.iter().map(|v| v.x).fold(f64::NEG_INFINITY, f64::max);
        assert!((hub_min_x - (-b / 2.0 - off / 2.0)).abs() < 1e-15, "{name}");
        assert!((hub_max_x - (b / 2.0 - off / 2.0)).abs() < 1e-15, "{name}");
        // The hub stays inside the wheel (validated rimBeamOffset).
        assert!(hub_min_x >= -p.thickness / 2.0 - 1e-15 && hub_max_x <= p.thickness / 2.0);
    }
}

/// Corner normals are unit vectors on the outer side of their (non-degenerate) face.
fn check_normals<M: TriMesh<f64>>(name: &str, m: &M) {
    for t in 0..m.triangle_count() {
        let [a, b, c] = m.triangle_positions(t).unwrap();
        let Some(face) = (b - a).cross(&(c - a)).try_normalize(0.0) else {
            continue;
        };
        for n in m.corner_normals(t).unwrap() {
            assert!((n.norm() - 1.0).abs() < 1e-12, "{name}: normal length");
            // Smooth normals lean at most half a facet plus a shoulder step off the face.
            assert!(
                n.dot(&face) > 0.6,
                "{name}: triangle {t}: {n:?} vs {face:?}"
            );
        }
    }
}

#[test]
fn normals_are_unit_and_outward() {
    for (name, w) in vehicle_wheels() {
        check_normals(name, &w.tyre());
        check_normals(name, &w.rim_contour());
        check_normals(name, &w.rim_centre());
    }
    check_normals("cylinder", &CylinderMesh::new(0.38, 0.19, 24));
}

#[test]
fn normals_smooth_where_webots_smooths() {
    let (w, _) = WheelParams::<f64>::default().validate();
    let tyre = w.tyre();
    // Tyre (creaseAngle 1.5 rad): one normal per vertex, shared by all its corners; the seam
    // columns (i = 0 and i = S) carry the same normal.
    assert_eq!(tyre.normal_count(), tyre.vertex_count());
    for ring in 0..10 {
        let (a, b) = (
            tyre.normal(ring * 37).unwrap(),
            tyre.normal(ring * 37 + 36).unwrap(),
        );
        assert!((a - b).norm() < 1e-12);
    }
    // Sidewall ring A: +x; tread rings: radial.
    assert_eq!(tyre.normal(0), Some(Vector3::new(1.0, 0.0, 0.0)));
    let tread = tyre.normal(4 * 37).unwrap();
    assert!((tread - Vector3::new(0.0, -1.0, 0.0)).norm() < 1e-12);

    // Rim contour (creaseAngle 2π/S + 0.01): the inner-cylinder corners of one vertex differ
    // from its annulus corners (a 90° crease), while around the axle the cylinder is smooth.
    let rim = w.rim_contour();
    assert!((rim.crease_angle() - (std::f64::consts::TAU / 36.0 + 0.01)).abs() < 1e-15);
    let annulus = rim.corner_normals(0).unwrap(); // strip 0, at x = −T/2
    assert!(annulus.iter().all(|n| *n == Vector3::new(-1.0, 0.0, 0.0)));
    let back = rim.corner_normals(2 * 2 * 36).unwrap(); // strip 2, at x = +T/2
    assert!(back.iter().all(|n| *n == Vector3::new(1.0, 0.0, 0.0)));
    let cyl = rim.corner_normals(2 * 36).unwrap(); // strip 1, first triangle
    let [v0, ..] = rim.triangle(2 * 36).unwrap();
    let p = rim.position(v0 as usize).unwrap();
    // Inward radial normal at that corner.
    assert!((cyl[0] + Vector3::new(0.0, p.y, p.z) * (1.0 / radial(p))).norm() < 1e-12);

    // Rim centre (creaseAngle 0): flat, one normal per triangle; the front hub fan faces −x.
    let hub = w.rim_centre();
    assert_eq!(hub.normal_count(), hub.triangle_count());
    for t in 0..5 {
        let n = hub.normal(t).unwrap();
        // A shallow pyramid: the centre sits b/10 = 0.02 m behind the inner circle, whose
        // chords are 0.09·cos(π/5) = 0.0728 m from the axle, so each face leans
        // atan(0.02/0.0728) = 15.4° off −x.
        let expected = -(0.02_f64 / (0.09 * (std::f64::consts::PI / 5.0).cos()))
            .atan()
            .cos();
        assert!((n.x - expected).abs() < 1e-12, "fan {t}: {n:?}");
    }
}

#[test]
fn flat_curvature_gives_webots_zero_area_shoulders() {
    // curvatureFactor 0 is valid: every shoulder ring collapses onto the sidewall/tread
    // corner, as in Webots, and the normals keep the sharp corner.
    let (w, warnings) = WheelParams::<f64> {
        curvature_factor: 0.0,
        ..Default::default()
    }
    .validate();
    assert!(warnings.is_empty());
    let areas = double_areas(&w.tyre());
    // E = 3 shoulder strips per side, 2S triangles each: 2·3·72 = 432 zero-area triangles.
    assert_eq!(areas.iter().filter(|a| **a < 1e-15).count(), 432);
    let tyre = w.tyre();
    assert_eq!(tyre.normal(37), Some(Vector3::new(1.0, 0.0, 0.0))); // B_0: sidewall side
    let b3 = tyre.normal(4 * 37).unwrap(); // B_3: tread side
    assert!((b3 - Vector3::new(0.0, -1.0, 0.0)).norm() < 1e-12);
}

#[test]
fn tyre_texture_coordinates_follow_webots() {
    let (w, _) = WheelPreset::ToyotaPriusWheel.params::<f64>().validate();
    let tyre = w.tyre();
    // E = 2, S = 36. Ring 2 = B_1: u = 0.125 + 0.125·1/2 = 0.1875; column 9: v = 10·9/36 = 2.5.
    assert_eq!(tyre.tex_coord(2 * 37 + 9), Some([0.1875, 2.5]));
    // Ring 5 = C_1: u = 0.75 + 0.0625 = 0.8125.
    assert_eq!(tyre.tex_coord(5 * 37), Some([0.8125, 0.0]));
    assert!(!w.rim_contour().has_tex_coords());
}

#[test]
fn cylinder_mesh_is_closed_and_exact() {
    // Tractor front wheel: r 0.38 m, width 0.19 m, S 24.
    let (w, _) = WheelPreset::TractorFrontWheel.params::<f64>().validate();
    let c = w.bounding_cylinder().unwrap();
    assert_eq!((c.radius, c.height, c.subdivision), (0.38, 0.19, 24));
    let m = c.mesh();
    assert_eq!((m.vertex_count(), m.triangle_count()), (100, 96));
    // Side and caps have their own vertices (sharp edges); welded, the cylinder is closed.
    assert_eq!(boundary_edges(&m), 4 * 24 + 2);
    assert_eq!(welded_boundary_edges(&[&m]), 0);
    // Volume of the inscribed 24-gon prism: (S/2)·r²·sin(2π/S)·h.
    let expected = 12.0 * 0.38 * 0.38 * (std::f64::consts::TAU / 24.0).sin() * 0.19;
    assert!((m.signed_volume() - expected).abs() < 1e-14);
}

#[test]
fn implausible_sizes_are_refused_and_the_largest_plausible_wheel_is_finite() {
    // A 1e20 m tyre (π·r²·h = 9.4e39 m³, beyond f32::MAX) is outside the plausible lengths
    // (1 mm to 1 km): it falls back to the default radius 0.4 m like a radius ≤ 0 does.
    let (w, warnings) = WheelParams::<f32> {
        tire_radius: 1e20,
        ..Default::default()
    }
    .validate();
    let warning = warnings.get(WheelField::TireRadius).unwrap();
    assert_eq!(
        (warning.rule, warning.value, warning.replacement),
        (WheelRule::Implausible, 1e20_f32 as f64, 0.4_f32 as f64)
    );
    assert_eq!(
        warning.to_string(),
        "'tireRadius' must be within 0.001 to 1000 m (value 1.0000000200408773e20). Value reset to \
         0.4000000059604645."
    );
    assert_eq!(w.params().tire_radius, 0.4);
    // A 1e7 kg wheel is refused too (plausible masses: 1 g to 1,000 t), and so is a density
    // of 1e6 kg/m³; both become the default `Physics {}`.
    for physics in [WheelPhysics::Mass(1e7), WheelPhysics::Density(1e6)] {
        let (w, warnings) = WheelParams::<f64> {
            physics,
            ..Default::default()
        }
        .validate();
        assert_eq!(
            warnings.get(WheelField::Physics).unwrap().rule,
            WheelRule::Implausible
        );
        assert_eq!(w.params().physics, WheelPhysics::Density(1000.0));
    }

    // The largest plausible wheel (1 km radius, 1 km wide) still has finite measures in f32:
    // π·(1e3)²·1e3 = 3.1e9 m³ and 1000 kg/m³ give 3.1e12 kg, far below f32::MAX.
    let (w, warnings) = WheelParams::<f32> {
        tire_radius: 1e3,
        thickness: 1e3,
        ..Default::default()
    }
    .validate();
    assert!(warnings.iter().all(|w| w.rule != WheelRule::Implausible));
    let volume = w.bounding_cylinder().unwrap().volume();
    assert!((volume / (std::f32::consts::PI * 1e9) - 1.0).abs() < 1e-6);
    let tyre = w.tyre();
    for m in [
        &tyre as &dyn TriMesh<f32>,
        &w.rim_contour(),
        &w.rim_centre(),
    ] {
        assert!(m.area().is_finite() && m.signed_volume().is_finite());
    }

    // Ordinary wheels keep the direct computation: the default tyre's area is unchanged by
    // the fallback (the sum of the triangle areas, computed here independently).
    let (w, _) = WheelParams::<f64>::default().validate();
    let expected: f64 = double_areas(&w.tyre()).iter().sum::<f64>() / 2.0;
    assert_eq!(w.tyre().area(), expected);
}
