//! The roads as a camera sees them: each lane's surface (asphalt, a lighter grey for borders
//! and shoulders) and each painted line in its colour, as patches of flat triangles in world
//! coordinates. Built once per simulation (the roads do not move), drawn at every render.

use proto_geom::nalgebra::{Point3, Vector3};

use super::raster::{bytes, shade};
use crate::appearance::lane_color;
use crate::road::RoadNetwork;
use crate::world::ROAD_LIFT;

/// Height (m) of the painted lines above the lane surfaces they lie on: above the two
/// surfaces' chord errors (1 mm each, `road::mesh`), so that the depth test always puts the
/// paint in front, and far below what a camera resolves.
const MARK_LIFT: f64 = 5e-3;

/// Triangles per patch: a patch wholly behind the camera or past its far plane is skipped
/// whole, so that a long road costs little where it is out of view.
const PATCH_TRIANGLES: usize = 64;

/// A piece of a road's surface or of one of its lines: triangles of one colour, drawn from
/// both sides and recognised as nothing (as the ground).
#[derive(Debug, Clone)]
pub(crate) struct Patch {
    /// The centre of a sphere around its triangles (m, world).
    pub centre: Point3<f64>,
    /// That sphere's radius (m).
    pub radius: f64,
    /// Its triangles (m, world), each with its colour's bytes under the default light
    /// ([`shade`] of its upward normal).
    pub triangles: Vec<([Point3<f64>; 3], [u8; 3])>,
}

/// The patches of every road of `roads`: the lane surfaces first, then the lines above them.
pub(crate) fn patches(roads: &RoadNetwork) -> Vec<Patch> {
    let mut out = Vec::new();
    for road in &roads.roads {
        for m in road.lane_meshes(ROAD_LIFT) {
            split(lane_color(m.kind), &m.vertices, &m.triangles, &mut out);
        }
        for strip in road.mark_strips(ROAD_LIFT + MARK_LIFT) {
            split(strip.colour, &strip.vertices, &strip.triangles, &mut out);
        }
    }
    out
}

/// Appends the triangles `triangles` (indices into `vertices`, m, world) of colour `colour`
/// to `out` as patches of at most [`PATCH_TRIANGLES`]; degenerate triangles are dropped.
fn split(colour: [f64; 3], vertices: &[Point3<f64>], triangles: &[[u32; 3]], out: &mut Vec<Patch>) {
    for chunk in triangles.chunks(PATCH_TRIANGLES) {
        let triangles: Vec<([Point3<f64>; 3], [u8; 3])> = chunk
            .iter()
            .filter_map(|t| {
                let p = t.map(|k| vertices.get(k as usize).copied());
                let [Some(a), Some(b), Some(c)] = p else {
                    return None;
                };
                let n = (b - a).cross(&(c - a)).try_normalize(1e-12)?;
                // Seen from above, whichever way the strip winds.
                let up = if n.z < 0.0 { -n } else { n };
                Some(([a, b, c], bytes(&colour, shade(&up))))
            })
            .collect();
        if triangles.is_empty() {
            continue;
        }
        let (mut lo, mut hi) = (
            Vector3::repeat(f64::INFINITY),
            Vector3::repeat(-f64::INFINITY),
        );
        for p in triangles.iter().flat_map(|(t, _)| t) {
            lo = lo.inf(&p.coords);
            hi = hi.sup(&p.coords);
        }
        out.push(Patch {
            centre: Point3::from((lo + hi) / 2.0),
            radius: (hi - lo).norm() / 2.0,
            triangles,
        });
    }
}
