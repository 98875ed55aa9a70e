//! Triangle meshes of a road's surface, one per lane of each lane section (what the world
//! turns into rapier colliders and the replay into nodes), and strips for its painted lines.

use proto_geom::nalgebra::Point3;

use super::{LaneKind, LineStyle, Road};

/// Largest distance (m) between two cross-sections of a mesh.
const MAX_STEP: f64 = 1.0;
/// Largest height error (m) of the flat triangles against the curved surface, and largest
/// plan-view chord error: the step shrinks as √(8·tolerance/curvature).
const TOLERANCE: f64 = 1e-3;

/// The surface of one lane of one lane section, as triangles.
#[derive(Debug, Clone, PartialEq)]
pub struct LaneMesh {
    /// Index of the lane section in its road.
    pub section: usize,
    /// The lane's id.
    pub lane: i32,
    /// The lane's kind (what the camera and the replay colour it by).
    pub kind: LaneKind,
    /// Its Coulomb friction (dimensionless): the lane's, else the road's.
    pub friction: f64,
    /// The vertices (m, world).
    pub vertices: Vec<Point3<f64>>,
    /// The triangles (indices into `vertices`, counter-clockwise seen from above).
    pub triangles: Vec<[u32; 3]>,
}

/// A painted line's surface: a strip of quads (two triangles each) in its colour.
#[derive(Debug, Clone, PartialEq)]
pub struct MarkStrip {
    /// Its colour (red, green, blue, 0 to 1).
    pub colour: [f64; 3],
    /// The vertices (m, world), lifted `lift` above the road surface.
    pub vertices: Vec<Point3<f64>>,
    /// The triangles (indices into `vertices`).
    pub triangles: Vec<[u32; 3]>,
}

impl Road {
    /// The stations (m) from `from` to `to` at which a mesh has cross-sections: at most
    /// 1 m apart, closer where the plan or the height profiles curve.
    pub fn stations(&self, from: f64, to: f64) -> Vec<f64> {
        let mut out = vec![from];
        let mut s = from;
        // A bound on the stations a 10⁷ m road could need at the finest step.
        while s < to && out.len() < 10_000_000 {
            let k = self.plan_at(s).curvature.abs()
                + self.elevation.eval(s).2.abs()
                + self.superelevation.eval(s).2.abs() * 10.0;
            let step = if k > 0.0 {
                (8.0 * TOLERANCE / k).sqrt().min(MAX_STEP)
            } else {
                MAX_STEP
            }
            .max(0.05);
            s = (s + step).min(to);
            if to - s < 0.25 * step {
                s = to;
            }
            out.push(s);
        }
        out
    }

    /// The surface of each lane of each lane section (skipping lanes of no width), lifted
    /// `lift` (m) above the profiles' heights.
    pub fn lane_meshes(&self, lift: f64) -> Vec<LaneMesh> {
        let length = self.length();
        let mut out = Vec::new();
        for (k, sec) in self.sections.iter().enumerate() {
            let end = self.sections.get(k + 1).map_or(length, |n| n.s);
            if end <= sec.s {
                continue;
            }
            let stations = self.stations(sec.s, end);
            for lane in sec.lanes() {
                let mut vertices = Vec::with_capacity(2 * stations.len());
                for &s in &stations {
                    let Some((_, inner, outer)) = self
                        .lane_edges(s)
                        .1
                        .into_iter()
                        .find(|(l, _, _)| l.id == lane.id)
                    else {
                        continue;
                    };
                    // Left lanes: the inner edge is on the right; keep right-then-left order.
                    let (right, left) = if lane.id > 0 {
                        (inner, outer)
                    } else {
                        (outer, inner)
                    };
                    for t in [right, left] {
                        let mut p = self.surface_point(s, t);
                        p.z += lift;
                        vertices.push(p);
                    }
                }
                if vertices
                    .iter()
                    .skip(1)
                    .step_by(2)
                    .zip(vertices.iter().step_by(2))
                    .all(|(l, r)| (l - r).norm() < 1e-9)
                {
                    continue;
                }
                let triangles = strip(vertices.len() / 2);
                out.push(LaneMesh {
                    section: k,
                    lane: lane.id,
                    kind: lane.kind,
                    friction: lane.friction.unwrap_or(self.friction),
                    vertices,
                    triangles,
                });
            }
        }
        out
    }

    /// The painted lines of the road as strips, `lift` (m) above the surface; a dashed line
    /// is one strip per dash.
    pub fn mark_strips(&self, lift: f64) -> Vec<MarkStrip> {
        let length = self.length();
        let mut out = Vec::new();
        for (k, sec) in self.sections.iter().enumerate() {
            let end = self.sections.get(k + 1).map_or(length, |n| n.s);
            let lanes = sec.lanes().map(|l| (Some(l.id), &l.marks));
            for (lane, marks) in lanes.chain(core::iter::once((None, &sec.centre_marks))) {
                for (i, m) in marks.iter().enumerate() {
                    let from = sec.s + m.s_offset.max(0.0);
                    let to = marks
                        .get(i + 1)
                        .map_or(end, |n| sec.s + n.s_offset)
                        .min(end);
                    let (dash, gap) = if m.style.is_dashed() {
                        LineStyle::DASH
                    } else {
                        (f64::INFINITY, 0.0)
                    };
                    let offsets: &[f64] = if m.style.is_double() {
                        &[-1.0, 1.0]
                    } else {
                        &[0.0]
                    };
                    let mut a = from;
                    while a < to && out.len() < 10_000_000 {
                        let b = (a + dash).min(to);
                        for &o in offsets {
                            let edge = |s: f64| -> f64 {
                                let (t0, edges) = self.lane_edges(s);
                                lane.and_then(|id| edges.iter().find(|e| e.0.id == id).map(|e| e.2))
                                    .unwrap_or(t0)
                            };
                            let mut vertices = Vec::new();
                            for s in self.stations(a, b) {
                                let t = edge(s) + o * m.width;
                                for dt in [-0.5 * m.width, 0.5 * m.width] {
                                    let mut p = self.surface_point(s, t + dt);
                                    p.z += lift;
                                    vertices.push(p);
                                }
                            }
                            let triangles = strip(vertices.len() / 2);
                            out.push(MarkStrip {
                                colour: m.colour,
                                vertices,
                                triangles,
                            });
                        }
                        a = b + gap;
                    }
                }
            }
        }
        out
    }
}

/// The triangles of a strip of `n` cross-sections of two vertices (right, left) each,
/// counter-clockwise seen from above when the strip runs forwards.
fn strip(n: usize) -> Vec<[u32; 3]> {
    (0..n.saturating_sub(1) as u32)
        .flat_map(|i| {
            let (r0, l0, r1, l1) = (2 * i, 2 * i + 1, 2 * i + 2, 2 * i + 3);
            [[r0, r1, l1], [r0, l1, l0]]
        })
        .collect()
}
