//! The replay's own shapes, which are no Webots geometry: the ground patch and its grid, ramps
//! and traffic cones, as flat-shaded triangle meshes and line sets (m).

use proto_geom::RenderMesh;
use proto_geom::RenderVertex;

use crate::config::ramp_corners;

/// Base radius of a traffic cone (m).
pub(crate) const CONE_RADIUS: f64 = 0.15;
/// Height of a traffic cone (m): the ISO 3888 course's cones are 0.5 to 0.75 m tall.
pub(crate) const CONE_HEIGHT: f64 = 0.5;
/// Facets around a cone.
const CONE_FACETS: usize = 12;

/// An axis-aligned rectangle of the ground, `[x_min, y_min, x_max, y_max]` (m).
pub(crate) type Rect = [f64; 4];

/// Appends the flat polygon `corners` (counter-clockwise seen from outside, so its normal is
/// outward) as a fan of triangles with its own vertices.
pub(crate) fn push_face(mesh: &mut RenderMesh, corners: &[[f64; 3]]) {
    let [Some(a), Some(b), Some(c)] = [0, 1, 2].map(|i| corners.get(i)) else {
        return;
    };
    let sub = |p: &[f64; 3], q: &[f64; 3]| [p[0] - q[0], p[1] - q[1], p[2] - q[2]];
    let (u, v) = (sub(b, a), sub(c, a));
    let n = [
        u[1] * v[2] - u[2] * v[1],
        u[2] * v[0] - u[0] * v[2],
        u[0] * v[1] - u[1] * v[0],
    ];
    let length = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
    if length.is_nan() || length <= 0.0 {
        return;
    }
    let normal = n.map(|c| (c / length) as f32);
    let base = u32::try_from(mesh.vertices.len()).unwrap_or(u32::MAX);
    for p in corners {
        mesh.vertices.push(RenderVertex {
            position: p.map(|c| c as f32),
            normal,
            tex_coord: [0.0; 2],
        });
    }
    for k in 1..corners.len().saturating_sub(1) as u32 {
        mesh.indices.extend([base, base + k, base + k + 1]);
    }
}

/// The ground patch `rect` as one upward-facing rectangle at height `z` (m).
pub(crate) fn ground(rect: Rect, z: f64) -> RenderMesh {
    let [x0, y0, x1, y1] = rect;
    let mut mesh = RenderMesh::default();
    push_face(
        &mut mesh,
        &[[x0, y0, z], [x1, y0, z], [x1, y1, z], [x0, y1, z]],
    );
    mesh
}

/// Longest grid segment, in grid steps: a line that passes behind the camera may be dropped
/// whole by a renderer (Chromium's software WebGL does), so long lines are cut into pieces.
const GRID_PIECE_STEPS: f64 = 2.0;

/// The grid lines of `rect` every `step` metres (lines on the multiples of `step`, the edges
/// included), at height `z` (m), as segment end points, each line cut into pieces of at most
/// [`GRID_PIECE_STEPS`] steps.
pub(crate) fn grid(rect: Rect, step: f64, z: f64) -> Vec<[f32; 3]> {
    let [x0, y0, x1, y1] = rect;
    let mut points = Vec::new();
    if step.is_nan() || step <= 0.0 {
        return points;
    }
    let lines = |lo: f64, hi: f64| {
        let first = (lo / step).ceil() as i64;
        let last = (hi / step).floor() as i64;
        (first..=last).map(move |k| k as f64 * step)
    };
    let pieces = |lo: f64, hi: f64| {
        let n = ((hi - lo) / (GRID_PIECE_STEPS * step)).ceil().max(1.0) as usize;
        (0..n).map(move |k| {
            let f = |k: usize| lo + (hi - lo) * k as f64 / n as f64;
            (f(k), f(k + 1))
        })
    };
    let f = |x: f64, y: f64| [x as f32, y as f32, z as f32];
    for x in lines(x0, x1) {
        for (a, b) in pieces(y0, y1) {
            points.extend([f(x, a), f(x, b)]);
        }
    }
    for y in lines(y0, y1) {
        for (a, b) in pieces(x0, x1) {
            points.extend([f(a, y), f(b, y)]);
        }
    }
    points
}

/// A grid step (m) of 1, 2 or 5 times a power of ten giving at most `max_lines` lines across
/// `span` (m).
pub(crate) fn grid_step(span: f64, max_lines: f64) -> f64 {
    let raw = (span / max_lines).max(1e-3);
    let decade = 10f64.powf(raw.log10().floor());
    [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * decade)
        .find(|s| *s >= raw)
        .unwrap_or(10.0 * decade)
}

/// A ramp (the wedge of [`Obstacle::Ramp`](crate::Obstacle)) in its own frame, on the corners
/// of [`ramp_corners`]: x along the climb from its low edge at x = 0 to its vertical back face
/// at x = `length`, y across, z up.
pub(crate) fn ramp(length: f64, width: f64, height: f64) -> RenderMesh {
    let [low_r, low_l, foot_r, foot_l, top_r, top_l] = ramp_corners(length, width, height);
    let mut mesh = RenderMesh::default();
    // Slope, back, two sides and the bottom.
    push_face(&mut mesh, &[low_r, top_r, top_l, low_l]);
    push_face(&mut mesh, &[foot_r, foot_l, top_l, top_r]);
    push_face(&mut mesh, &[low_r, foot_r, top_r]);
    push_face(&mut mesh, &[low_l, top_l, foot_l]);
    push_face(&mut mesh, &[low_r, low_l, foot_l, foot_r]);
    mesh
}

/// A traffic cone standing on z = 0: [`CONE_RADIUS`], [`CONE_HEIGHT`], flat facets.
pub(crate) fn cone() -> RenderMesh {
    let mut mesh = RenderMesh::default();
    let top = [0.0, 0.0, CONE_HEIGHT];
    let rim: Vec<[f64; 3]> = (0..CONE_FACETS)
        .map(|i| {
            let a = core::f64::consts::TAU * i as f64 / CONE_FACETS as f64;
            [CONE_RADIUS * a.cos(), CONE_RADIUS * a.sin(), 0.0]
        })
        .collect();
    for (i, p) in rim.iter().enumerate() {
        let q = rim[(i + 1) % CONE_FACETS];
        push_face(&mut mesh, &[*p, q, top]);
    }
    let base: Vec<[f64; 3]> = rim.iter().rev().copied().collect();
    push_face(&mut mesh, &base);
    mesh
}

/// A triangle mesh of `vertices` (m) and `triangles` (indices, counter-clockwise seen from
/// above), flat-shaded, lifted by `lift` (m).
pub(crate) fn surface(
    vertices: &[proto_geom::nalgebra::Point3<f64>],
    triangles: &[[u32; 3]],
    lift: f64,
) -> RenderMesh {
    let mut mesh = RenderMesh::default();
    for tri in triangles {
        let corners = tri.map(|i| {
            vertices
                .get(i as usize)
                .map_or([0.0; 3], |p| [p.x, p.y, p.z + lift])
        });
        push_face(&mut mesh, &corners);
    }
    mesh
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Every normal is unit and points away from the centroid of the solid.
    fn outward(mesh: &RenderMesh, inside: [f32; 3]) {
        for t in mesh.indices.chunks_exact(3) {
            let v = [t[0], t[1], t[2]].map(|i| mesh.vertices[i as usize]);
            let n = v[0].normal;
            let len = (n[0] * n[0] + n[1] * n[1] + n[2] * n[2]).sqrt();
            assert!((len - 1.0).abs() < 1e-6);
            let c: [f32; 3] = core::array::from_fn(|k| {
                (v[0].position[k] + v[1].position[k] + v[2].position[k]) / 3.0
            });
            let d: f32 = (0..3).map(|k| (c[k] - inside[k]) * n[k]).sum();
            assert!(d > 0.0, "face at {c:?} faces inwards");
        }
    }

    #[test]
    fn solids_are_closed_outward_and_sized() {
        let r = ramp(12.0, 4.0, 1.2);
        // 3 quads (2 triangles each) and 2 triangles.
        assert_eq!(r.triangle_count(), 8);
        outward(&r, [8.0, 0.0, 0.3]);
        assert_eq!(r.bounds(), ([0.0, -2.0, 0.0], [12.0, 2.0, 1.2]));
        let c = cone();
        assert_eq!(c.triangle_count(), CONE_FACETS + CONE_FACETS - 2);
        outward(&c, [0.0, 0.0, 0.1]);
        let g = ground([-1.0, -2.0, 3.0, 4.0], -0.01);
        assert_eq!(g.vertices[0].normal, [0.0, 0.0, 1.0]);
    }

    #[test]
    fn grid_lines_sit_on_multiples_of_the_step() {
        // x lines at 0 and 5, a y line at 0 across [-1, 8] × [-4, 4], each in one piece.
        let g = grid([-1.0, -4.0, 8.0, 4.0], 5.0, 0.0);
        assert_eq!(g.len(), 2 * 3);
        assert_eq!(g[0], [0.0, -4.0, 0.0]);
        assert_eq!(g[5], [8.0, 0.0, 0.0]);
        // A line 10 steps long comes in five pieces of two steps.
        let g = grid([0.0, 0.0, 10.0, 0.5], 1.0, 0.0);
        assert_eq!(g.len(), 2 * (11 + 5));
        assert_eq!(g[2 * 11..2 * 11 + 2], [[0.0; 3], [2.0, 0.0, 0.0]]);
        assert_eq!(grid_step(120.0, 60.0), 2.0);
        assert_eq!(grid_step(0.9, 60.0), 0.02);
        assert_eq!(grid_step(5000.0, 60.0), 100.0);
    }
}
