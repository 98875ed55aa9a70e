//! Helpers shared by the integration tests.
#![allow(dead_code)]

use std::collections::HashMap;

use proto_geom::nalgebra::Point3;
use proto_geom::{TriMesh, ValidWheel, WheelPreset, WheelShape};

/// The default `VehicleWheel`, the 2014 `AutomobileWheel` and every shipped `VehicleWheel`.
pub fn vehicle_wheels() -> Vec<(&'static str, ValidWheel<f64>)> {
    WheelPreset::ALL
        .into_iter()
        .filter(|p| p.shape() == WheelShape::VehicleWheel)
        .map(|p| {
            let (w, warnings) = p.params::<f64>().validate();
            assert!(warnings.is_empty(), "{}: {warnings:?}", p.proto_name());
            (p.proto_name(), w)
        })
        .collect()
}

/// Twice the area of each triangle (m²).
pub fn double_areas<M: TriMesh<f64>>(m: &M) -> Vec<f64> {
    (0..m.triangle_count())
        .map(|t| {
            let [a, b, c] = m.triangle_positions(t).unwrap();
            (b - a).cross(&(c - a)).norm()
        })
        .collect()
}

/// Directed edge multiplicities by vertex index; panics if an edge is used twice in the same
/// direction (inconsistent winding or a non-manifold edge). Returns the number of boundary
/// edges (edges whose reverse is missing).
pub fn boundary_edges<M: TriMesh<f64>>(m: &M) -> usize {
    let mut edges: HashMap<(u32, u32), usize> = HashMap::new();
    for t in 0..m.triangle_count() {
        let [a, b, c] = m.triangle(t).unwrap();
        for e in [(a, b), (b, c), (c, a)] {
            *edges.entry(e).or_default() += 1;
        }
    }
    for (e, n) in &edges {
        assert_eq!(*n, 1, "directed edge {e:?} used {n} times");
    }
    edges
        .keys()
        .filter(|(a, b)| !edges.contains_key(&(*b, *a)))
        .count()
}

/// Radius of a point from the wheel axle (the x axis), m.
pub fn radial(p: Point3<f64>) -> f64 {
    p.y.hypot(p.z)
}

/// Volume of the solid swept by the closed profile polygon `(x, r)` around the x axis when the
/// revolution is approximated by a regular S-gon (as the meshes are): S·sin(2π/S)·∫ r dA.
pub fn polygonal_revolution_volume(profile: &[(f64, f64)], s: u32) -> f64 {
    let n = profile.len();
    let mut moment = 0.0; // ∫ r dA, signed by the polygon orientation.
    for i in 0..n {
        let (x0, r0) = profile[i];
        let (x1, r1) = profile[(i + 1) % n];
        moment += (x0 * r1 - x1 * r0) * (r0 + r1) / 6.0;
    }
    let s = f64::from(s);
    (s * (std::f64::consts::TAU / s).sin() * moment).abs()
}

/// Like [`boundary_edges`], but over several meshes with vertices welded by position (1 µm),
/// so texture seams and parts that meet (tyre and rim) are joined. Skips zero-length edges.
pub fn welded_boundary_edges(meshes: &[&dyn TriMesh<f64>]) -> usize {
    let key = |p: Point3<f64>| {
        let q = |c: f64| (c * 1e6).round() as i64;
        (q(p.x), q(p.y), q(p.z))
    };
    type Key = (i64, i64, i64);
    let mut edges: HashMap<(Key, Key), usize> = HashMap::new();
    for m in meshes {
        for t in 0..m.triangle_count() {
            let [a, b, c] = m.triangle_positions(t).unwrap().map(key);
            for e in [(a, b), (b, c), (c, a)] {
                if e.0 != e.1 {
                    *edges.entry(e).or_default() += 1;
                }
            }
        }
    }
    for (e, n) in &edges {
        assert_eq!(*n, 1, "directed edge {e:?} used {n} times");
    }
    edges
        .keys()
        .filter(|(a, b)| !edges.contains_key(&(*b, *a)))
        .count()
}
