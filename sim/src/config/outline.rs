//! The footprints of a world's obstacles, boxes and roads seen from above, for the plots.

use proto_geom::nalgebra::Point2;

use super::{Obstacle, WorldConfig};
use crate::road::Lane;

/// What an [`Outline`] is.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum OutlineKind {
    /// A static `[[box]]`.
    Box,
    /// A `[[ramp]]`.
    Ramp,
    /// A `[[cone]]`'s base.
    Cone,
    /// A dynamic `[[body]]` box, where it starts.
    Body,
    /// A road's outer edge (an open line along the road).
    RoadEdge,
    /// A line between two lanes of a road (an open line along the road).
    LaneLine,
}

impl OutlineKind {
    /// The legend text.
    pub const fn legend(self) -> &'static str {
        match self {
            OutlineKind::Box => "boxes",
            OutlineKind::Ramp => "ramps",
            OutlineKind::Cone => "cones",
            OutlineKind::Body => "dynamic boxes (start)",
            OutlineKind::RoadEdge => "road edges",
            OutlineKind::LaneLine => "lane lines",
        }
    }
}

/// An obstacle's footprint seen from above (m, world frame), a closed polygon; or a road's
/// edge or lane line, an open line.
#[derive(Debug, Clone, PartialEq)]
pub struct Outline {
    /// What it is.
    pub kind: OutlineKind,
    /// The corners, in order.
    pub points: Vec<[f64; 2]>,
}

impl Outline {
    /// The footprints of the boxes, ramps and dynamic boxes (at their start) of `config`,
    /// then its roads' edges and lane lines (sampled at most 2,000 times along a road).
    pub fn of_world(config: &WorldConfig) -> Vec<Outline> {
        let outline = |kind, corners: [Point2<f64>; 4]| Outline {
            kind,
            points: corners.iter().map(|p| [p.x, p.y]).collect(),
        };
        let obstacles = config.obstacles.iter().map(|o| match o {
            Obstacle::Box { .. } => outline(OutlineKind::Box, o.footprint()),
            Obstacle::Ramp { .. } => outline(OutlineKind::Ramp, o.footprint()),
            // A 16-gon: round to a plot's eye at any zoom that shows a cone.
            Obstacle::Cone { cone, .. } => Outline {
                kind: OutlineKind::Cone,
                points: cone.base_polygon(16).iter().map(|p| [p.x, p.y]).collect(),
            },
        });
        let bodies = config
            .bodies
            .iter()
            .map(|b| outline(OutlineKind::Body, b.footprint()));
        let mut out: Vec<Outline> = obstacles.chain(bodies).collect();
        for road in &config.roads.roads {
            let length = road.length();
            let stations = road.stations(0.0, length);
            let keep = stations.len().div_ceil(2000).max(1);
            let mut lines: Vec<Outline> = Vec::new();
            for (i, s) in stations.iter().enumerate() {
                if i % keep != 0 && i + 1 != stations.len() {
                    continue;
                }
                let (t0, edges) = road.lane_edges(*s);
                let (left, right): (Vec<&(&Lane, f64, f64)>, Vec<_>) =
                    edges.iter().partition(|e| e.0.id > 0);
                // The reference line between the two directions, each lane's outer edge; the
                // outermost of each side is the road's edge.
                let mut ts = vec![(OutlineKind::LaneLine, t0)];
                for side in [&left, &right] {
                    for (k, e) in side.iter().enumerate() {
                        let kind = if k + 1 == side.len() {
                            OutlineKind::RoadEdge
                        } else {
                            OutlineKind::LaneLine
                        };
                        ts.push((kind, e.2));
                    }
                }
                if left.is_empty() || right.is_empty() {
                    ts[0].0 = OutlineKind::RoadEdge;
                }
                if lines.len() != ts.len() {
                    // Another number of lanes: the lines so far end here.
                    out.append(&mut lines);
                    lines = ts
                        .iter()
                        .map(|&(kind, _)| Outline {
                            kind,
                            points: Vec::new(),
                        })
                        .collect();
                }
                for (line, (_, t)) in lines.iter_mut().zip(&ts) {
                    let p = road.surface_point(*s, *t);
                    line.points.push([p.x, p.y]);
                }
            }
            out.extend(lines);
        }
        out
    }
}
