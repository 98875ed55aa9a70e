//! Roads: reference lines of straight, arc, clothoid and parametric-cubic segments, lanes
//! with polynomial widths and painted lines, elevation (grade) and superelevation (banking),
//! per-road and per-lane friction, and the conversions between a world point and a road's
//! station and lateral offset (s, t). The geometry is f64 and closed-form; no rapier here
//! (the world builds its road colliders from [`Road::lane_meshes`]).
//!
//! Conventions are OpenDRIVE's: s (m) runs along the reference line measured in the xy
//! plane; t (m) is across it, positive to the left, measured in the banked road surface;
//! lane ids are 1, 2, … on the left and −1, −2, … on the right; the superelevation φ (rad)
//! rolls the surface about the reference line, positive lifting the left side: the surface
//! point at (s, t) is the reference point plus t·cos φ to the left and
//! elevation(s) + t·sin φ up.
//!
//! ```
//! use sim::road::{Road, Segment, Curve};
//! use sim::nalgebra::Point2;
//! let road = Road::two_way("r", Point2::origin(), 0.0, &[(100.0, Curve::Line)], 3.5)?;
//! let p = road.surface_point(40.0, -1.75); // the centre of the right lane
//! assert!((p.x - 40.0).abs() < 1e-12 && (p.y + 1.75).abs() < 1e-12);
//! let at = road.locate(&Point2::new(40.0, -1.75)).unwrap();
//! assert_eq!(at.lane, -1);
//! # Ok::<(), sim::road::RoadError>(())
//! ```

mod fresnel;
mod lanes;
mod mesh;
mod network;
pub mod opendrive;
mod plan;
mod profile;
mod tracking;

use core::fmt;

use proto_geom::nalgebra::{Point2, Point3, Vector2};

pub use lanes::{Lane, LaneKind, LaneSection, LineStyle, RoadMark};
pub use mesh::{LaneMesh, MarkStrip};
pub use network::{
    ContactPoint, Junction, JunctionConnection, LINK_TOLERANCE, RoadLink, RoadNetwork,
};
pub use plan::{Curve, ParamRange, PlanPose, Segment};
pub use profile::{Cubic, Profile};
pub use tracking::{LaneTracking, lane_centre, lane_curvature, travel_direction};

pub(crate) use plan::cubic_length;

/// Sharpest curvature a road segment may have (1/m): a 0.5 m radius, tighter than any lane.
pub const MAX_CURVATURE: f64 = 2.0;
/// Steepest superelevation (rad): 60°, beyond which no surface is a road.
pub const MAX_SUPERELEVATION: f64 = core::f64::consts::FRAC_PI_3;
/// Widest lane (m).
pub const MAX_LANE_WIDTH: f64 = 100.0;
/// Largest Coulomb friction of a road or lane (dimensionless), as for the ground.
pub const MAX_FRICTION: f64 = 100.0;
/// Longest segment of a reference line (m): 100 km.
pub const MAX_SEGMENT_LENGTH: f64 = 1e5;
/// Farthest a segment may start from the origin (m): 10,000 km.
pub const MAX_COORDINATE: f64 = 1e7;
/// Widest painted line (m).
pub const MAX_MARK_WIDTH: f64 = 2.0;

/// A road whose description is not a road: which road, which field, and why.
#[derive(Debug, Clone, PartialEq)]
pub struct RoadError {
    /// The road's id.
    pub road: String,
    /// The field at fault (e.g. `segment 3 length`).
    pub field: String,
    /// What is wrong with its value.
    pub message: String,
}

impl fmt::Display for RoadError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "road '{}': {}: {}", self.road, self.field, self.message)
    }
}

impl std::error::Error for RoadError {}

/// A road: a reference line, its height and banking profiles, its lanes, its friction and
/// its links to the roads before and after it.
#[derive(Debug, Clone, PartialEq)]
pub struct Road {
    /// Its id (unique in a network).
    pub id: String,
    /// Its reference line, segments in station order, each starting where the last ended.
    pub segments: Vec<Segment>,
    /// Height of the reference line (m) by station.
    pub elevation: Profile,
    /// Roll of the surface about the reference line (rad, positive lifting the left side).
    pub superelevation: Profile,
    /// Lateral shift of the lanes' centre from the reference line (m, positive left).
    pub lane_offset: Profile,
    /// Its lane sections, by start; the first starts at 0.
    pub sections: Vec<LaneSection>,
    /// Coulomb friction of its surface (dimensionless) where a lane has none of its own.
    pub friction: f64,
    /// The road or junction before its start, if any.
    pub predecessor: Option<RoadLink>,
    /// The road or junction after its end, if any.
    pub successor: Option<RoadLink>,
    /// The junction this road belongs to (a connecting road), if any.
    pub junction: Option<String>,
}

/// Where a point is on a road.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoadPosition {
    /// Station (m).
    pub s: f64,
    /// Lateral offset from the reference line (m, in the surface, positive left).
    pub t: f64,
    /// The lane it is in (1, 2, … left; −1, −2, … right).
    pub lane: i32,
    /// The lateral offset of that lane's centre (m).
    pub lane_centre: f64,
    /// That lane's width (m).
    pub lane_width: f64,
    /// The reference line's heading there (rad).
    pub heading: f64,
    /// The reference line's curvature there (1/m).
    pub curvature: f64,
}

impl Road {
    /// A flat road with one lane each way of width `lane_width` (m), white dashed centre
    /// line, along the segments `(length m, curve)` from `start` (m) heading `heading` (rad),
    /// friction 1: the shortest way to a road in code and doc tests.
    pub fn two_way(
        id: &str,
        start: Point2<f64>,
        heading: f64,
        segments: &[(f64, Curve)],
        lane_width: f64,
    ) -> Result<Road, RoadError> {
        let lane = |id| Lane {
            id,
            kind: LaneKind::Driving,
            width: Profile::constant(lane_width),
            friction: None,
            marks: Vec::new(),
        };
        let road = Road {
            id: id.to_owned(),
            segments: chain(start, heading, segments),
            elevation: Profile::default(),
            superelevation: Profile::default(),
            lane_offset: Profile::default(),
            sections: vec![LaneSection {
                s: 0.0,
                left: vec![lane(1)],
                centre_marks: vec![RoadMark {
                    s_offset: 0.0,
                    style: LineStyle::Dashed,
                    colour: [1.0; 3],
                    width: 0.12,
                }],
                right: vec![lane(-1)],
            }],
            friction: 1.0,
            predecessor: None,
            successor: None,
            junction: None,
        };
        road.validate()?;
        Ok(road)
    }

    /// Its length along the reference line (m).
    pub fn length(&self) -> f64 {
        self.segments.last().map_or(0.0, |g| g.s + g.length)
    }

    /// The segment in force at `s`.
    fn segment_index(&self, s: f64) -> usize {
        self.segments
            .partition_point(|g| g.s <= s)
            .saturating_sub(1)
    }

    /// The reference line at station `s` (m, clamped to the road).
    pub fn plan_at(&self, s: f64) -> PlanPose {
        let s = s.clamp(0.0, self.length());
        match self.segments.get(self.segment_index(s)) {
            Some(g) => g.pose_at((s - g.s).clamp(0.0, g.length)),
            None => PlanPose {
                point: Point2::origin(),
                heading: 0.0,
                curvature: 0.0,
            },
        }
    }

    /// The lane section in force at `s` (m).
    pub fn section_at(&self, s: f64) -> Option<&LaneSection> {
        let i = self.sections.partition_point(|l| l.s <= s);
        self.sections.get(i.saturating_sub(1))
    }

    /// The surface point (m, world) at station `s` and lateral offset `t` (m).
    pub fn surface_point(&self, s: f64, t: f64) -> Point3<f64> {
        let pose = self.plan_at(s);
        let phi = self.superelevation.value(s);
        let (sn, cs) = phi.sin_cos();
        let p = pose.point + pose.left() * (t * cs);
        Point3::new(p.x, p.y, self.elevation.value(s) + t * sn)
    }

    /// The outer edges' lateral offsets (m) of the lanes at `s`: left lanes by id 1, 2, …
    /// then right lanes by id −1, −2, …, each with its lane; and the lane offset (the
    /// centre lane's t).
    pub fn lane_edges(&self, s: f64) -> (f64, Vec<(&Lane, f64, f64)>) {
        let t0 = self.lane_offset.value(s);
        let Some(sec) = self.section_at(s) else {
            return (t0, Vec::new());
        };
        let ds = s - sec.s;
        let mut out = Vec::with_capacity(sec.left.len() + sec.right.len());
        let mut inner = t0;
        for (lane, outer) in sec
            .left
            .iter()
            .zip(LaneSection::edges(&sec.left, ds, t0, 1.0))
        {
            out.push((lane, inner, outer));
            inner = outer;
        }
        inner = t0;
        for (lane, outer) in sec
            .right
            .iter()
            .zip(LaneSection::edges(&sec.right, ds, t0, -1.0))
        {
            out.push((lane, inner, outer));
            inner = outer;
        }
        (t0, out)
    }

    /// The lane at (`s`, `t`) (m) with its inner and outer edges, if `t` is on the road.
    pub fn lane_at(&self, s: f64, t: f64) -> Option<(&Lane, f64, f64)> {
        self.lane_edges(s)
            .1
            .into_iter()
            .find(|&(_, a, b)| (a.min(b)..=a.max(b)).contains(&t) && a != b)
    }

    /// The Coulomb friction (dimensionless) at (`s`, `t`): its lane's, else the road's.
    pub fn friction_at(&self, s: f64, t: f64) -> f64 {
        self.lane_at(s, t)
            .and_then(|(l, _, _)| l.friction)
            .unwrap_or(self.friction)
    }

    /// The station and lateral offset (m) of the road point nearest `p` (m, world x and y)
    /// in the plan view, with the horizontal distance's square (m²).
    pub fn station_of(&self, p: &Point2<f64>) -> (f64, f64, f64) {
        let mut best = (0.0, 0.0, f64::INFINITY);
        for g in &self.segments {
            // Every point of a segment lies within half its length of its middle point.
            let mid = g.pose_at(0.5 * g.length).point;
            let reach = (p - mid).norm() - 0.5 * g.length;
            if reach > 0.0 && reach * reach > best.2 {
                continue;
            }
            let (ds, d2) = plan::nearest(g, p);
            if d2 < best.2 {
                let pose = g.pose_at(ds);
                let lateral = (p - pose.point).dot(&pose.left());
                best = (g.s + ds, lateral, d2);
            }
        }
        let (s, lateral, d2) = best;
        let cos = self.superelevation.value(s).cos();
        (s, lateral / cos, d2)
    }

    /// Where `p` (m, world x and y) is on this road: `None` off its lanes or beyond its ends.
    pub fn locate(&self, p: &Point2<f64>) -> Option<RoadPosition> {
        let (s, t, _) = self.station_of(p);
        let pose = self.plan_at(s);
        // Beyond either end the nearest point is the end itself with p off its normal.
        let along = (p - pose.point).dot(&Vector2::new(pose.heading.cos(), pose.heading.sin()));
        if along.abs() > 1e-6 * (1.0 + self.length()) {
            return None;
        }
        let (lane, a, b) = self.lane_at(s, t)?;
        Some(RoadPosition {
            s,
            t,
            lane: lane.id,
            lane_centre: 0.5 * (a + b),
            lane_width: (b - a).abs(),
            heading: pose.heading,
            curvature: pose.curvature,
        })
    }

    /// Checks every value: finite, contiguous segments of positive length, curvature within
    /// [`MAX_CURVATURE`], lanes not negative nor wider than [`MAX_LANE_WIDTH`], banking within
    /// [`MAX_SUPERELEVATION`], friction 0 to [`MAX_FRICTION`], marks 0 to [`MAX_MARK_WIDTH`].
    pub fn validate(&self) -> Result<(), RoadError> {
        let err = |field: String, message: String| RoadError {
            road: self.id.clone(),
            field,
            message,
        };
        if self.segments.is_empty() {
            return Err(err("plan view".into(), "has no segment".into()));
        }
        let mut s = 0.0;
        for (i, g) in self.segments.iter().enumerate() {
            let field = |k: &str| format!("segment {} {k}", i + 1);
            if !(g.length.is_finite() && g.length > 0.0) {
                return Err(err(
                    field("length"),
                    format!("{} m: must be finite and > 0", g.length),
                ));
            }
            if g.length > MAX_SEGMENT_LENGTH {
                return Err(err(
                    field("length"),
                    format!("{} m: must be at most {MAX_SEGMENT_LENGTH} m", g.length),
                ));
            }
            if g.start.x.abs().max(g.start.y.abs()) > MAX_COORDINATE {
                return Err(err(
                    field("start"),
                    format!("must be within ±{MAX_COORDINATE} m of the origin"),
                ));
            }
            if !(g.start.x.is_finite() && g.start.y.is_finite() && g.heading.is_finite()) {
                return Err(err(field("start"), "must be finite".into()));
            }
            if (g.s - s).abs() > 1e-3 + 1e-9 * s {
                return Err(err(
                    field("s"),
                    format!("{} m: must be {s} m, where the last segment ends", g.s),
                ));
            }
            s = g.s + g.length;
            let curvatures = match g.curve {
                Curve::Line => [0.0, 0.0],
                Curve::Arc { curvature } => [curvature; 2],
                Curve::Spiral {
                    curvature_start,
                    curvature_end,
                } => [curvature_start, curvature_end],
                Curve::ParamPoly3 { u, v, .. } => {
                    if !u.iter().chain(&v).all(|c| c.is_finite()) {
                        return Err(err(field("coefficients"), "must be finite".into()));
                    }
                    [0.0, 0.0]
                }
            };
            for k in curvatures {
                if !(k.is_finite() && k.abs() <= MAX_CURVATURE) {
                    return Err(err(
                        field("curvature"),
                        format!(
                            "{k} 1/m: must be finite and within ±{MAX_CURVATURE} (a radius of 0.5 m or more)"
                        ),
                    ));
                }
            }
        }
        for (name, p) in [
            ("elevation", &self.elevation),
            ("superelevation", &self.superelevation),
            ("lane offset", &self.lane_offset),
        ] {
            if !p.is_finite() {
                return Err(err(name.into(), "must be finite".into()));
            }
        }
        if !(self.friction.is_finite() && (0.0..=MAX_FRICTION).contains(&self.friction)) {
            return Err(err(
                "friction".into(),
                format!(
                    "{}: must be finite and from 0 to {MAX_FRICTION}",
                    self.friction
                ),
            ));
        }
        let length = self.length();
        if self.sections.first().is_none_or(|l| l.s != 0.0) {
            return Err(err(
                "lane sections".into(),
                "the first must start at s = 0".into(),
            ));
        }
        // Sampled every metre and at each piece's ends: where a profile is out of range.
        let samples = |from: f64, to: f64| {
            let n = ((to - from) / 1.0).ceil().clamp(1.0, 1e7) as usize;
            (0..=n).map(move |i| from + (to - from) * i as f64 / n as f64)
        };
        for s in samples(0.0, length) {
            let phi = self.superelevation.value(s);
            if phi.abs() > MAX_SUPERELEVATION {
                return Err(err(
                    "superelevation".into(),
                    format!(
                        "{phi} rad at s = {s} m: must be within ±{MAX_SUPERELEVATION:.4} rad (60°)"
                    ),
                ));
            }
        }
        for (k, sec) in self.sections.iter().enumerate() {
            let end = self.sections.get(k + 1).map_or(length, |n| n.s);
            if !(sec.s.is_finite() && sec.s <= end) {
                return Err(err(
                    format!("lane section {}", k + 1),
                    format!("s = {} m: must be finite and in order", sec.s),
                ));
            }
            for lane in sec.lanes() {
                let field = |f: &str| format!("lane section {} lane {} {f}", k + 1, lane.id);
                if !lane.width.is_finite() {
                    return Err(err(field("width"), "must be finite".into()));
                }
                for ds in samples(0.0, end - sec.s) {
                    let w = lane.width.value(ds);
                    if !(-1e-9..=MAX_LANE_WIDTH).contains(&w) {
                        return Err(err(
                            field("width"),
                            format!(
                                "{w} m at s = {} m: must be from 0 to {MAX_LANE_WIDTH} m",
                                sec.s + ds
                            ),
                        ));
                    }
                }
                if let Some(mu) = lane.friction
                    && !(mu.is_finite() && (0.0..=MAX_FRICTION).contains(&mu))
                {
                    return Err(err(
                        field("friction"),
                        format!("{mu}: must be finite and from 0 to {MAX_FRICTION}"),
                    ));
                }
                check_marks(&lane.marks).map_err(|m| err(field("road mark"), m))?;
            }
            check_marks(&sec.centre_marks)
                .map_err(|m| err(format!("lane section {} centre road mark", k + 1), m))?;
        }
        Ok(())
    }
}

/// Why a list of marks is out of range, if it is.
fn check_marks(marks: &[RoadMark]) -> Result<(), String> {
    for m in marks {
        if !(m.width.is_finite() && m.width > 0.0 && m.width <= MAX_MARK_WIDTH) {
            return Err(format!(
                "width {} m: must be > 0 and at most {MAX_MARK_WIDTH} m",
                m.width
            ));
        }
        if !m.colour.iter().all(|c| (0.0..=1.0).contains(c)) {
            return Err(format!(
                "colour {:?}: each component must be from 0 to 1",
                m.colour
            ));
        }
        if !m.s_offset.is_finite() {
            return Err("sOffset must be finite".into());
        }
    }
    Ok(())
}

/// The segments `(length m, curve)` laid end to end from `start` (m) heading `heading` (rad).
pub fn chain(start: Point2<f64>, heading: f64, parts: &[(f64, Curve)]) -> Vec<Segment> {
    let mut out: Vec<Segment> = Vec::with_capacity(parts.len());
    let (mut at, mut hdg, mut s) = (start, heading, 0.0);
    for &(length, curve) in parts {
        let g = Segment {
            s,
            start: at,
            heading: hdg,
            length,
            curve,
        };
        let end = g.end();
        (at, hdg, s) = (end.point, end.heading, s + length);
        out.push(g);
    }
    out
}

#[cfg(test)]
mod tests;
