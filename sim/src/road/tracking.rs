//! Where a car is in its lane: the one measurement of "where am I on the road" that the
//! `RoadSensor` device and the built-in lane-following driver (`follow_lane`) both read.
//!
//! Everything is measured in the lane's **direction of travel**, right-hand traffic: the
//! right lanes (ids −1, −2, …) drive along increasing s, the left lanes (1, 2, …) against it
//! (a Webots `Road`'s forward lanes are its right ones). In that direction's frame (x along
//! the travel direction, y to its left, z up):
//!
//! * the lateral offset (m) is positive when the point is **left** of the lane centre;
//! * the heading error (rad, in (−π, π]) is the car's yaw minus the travel direction's
//!   heading: positive when the car points to the left of the lane;
//! * curvatures (1/m) are those of the lane's centre line in the plan view, positive where
//!   the lane turns left as one drives it;
//! * the distances to the left and right lane lines and road edges (m) are measured across
//!   the road surface to the lines' centres (the lane edges), positive while the point is
//!   inside them, negative beyond;
//! * the road edges are the outer edges of the outermost lanes of any kind (borders and
//!   shoulders included: the paved surface).
//!
//! Looking ahead follows direct road links (a closed road's end to its own start, a
//! successor's start, a predecessor's end when driving against s); at a junction or an
//! unlinked end the look-ahead stops at the end.

use proto_geom::nalgebra::{Point2, Vector2};

use super::{ContactPoint, Road, RoadLink, RoadNetwork};

/// Most road links a look-ahead crosses: more than any look-ahead of a few hundred metres
/// needs on roads of a metre or more, and a bound against a cycle of zero-length links.
const MAX_LINKS: usize = 16;

/// A car's place in a lane, in the lane's direction of travel (see the module doc).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LaneTracking {
    /// The road's index in the network.
    pub road: usize,
    /// The lane (1, 2, … left of the reference line; −1, −2, … right).
    pub lane: i32,
    /// Station along the road's reference line (m).
    pub s: f64,
    /// +1 when the lane drives along increasing s (right lanes), −1 against it.
    pub direction: f64,
    /// Offset of the point from the lane centre (m, positive left of it).
    pub lateral_offset: f64,
    /// The car's yaw minus the lane's direction of travel (rad, in (−π, π], positive when
    /// pointing left of it).
    pub heading_error: f64,
    /// The curvature of the lane's centre line at s (1/m, plan view, positive turning left
    /// as driven).
    pub curvature: f64,
    /// The curvature of the lane's centre line `lookahead` metres ahead (1/m, plan view,
    /// positive turning left as driven).
    pub curvature_ahead: f64,
    /// Distance from the point to the lane's left line (m, positive inside the lane).
    pub left_line: f64,
    /// Distance from the point to the lane's right line (m, positive inside the lane).
    pub right_line: f64,
    /// Distance from the point to the road's left edge (m, positive on the road).
    pub left_edge: f64,
    /// Distance from the point to the road's right edge (m, positive on the road).
    pub right_edge: f64,
    /// The lane's width at s (m).
    pub lane_width: f64,
}

/// Travel direction of lane `lane`: +1 along s for the right lanes, −1 for the left ones.
pub fn travel_direction(lane: i32) -> f64 {
    if lane > 0 { -1.0 } else { 1.0 }
}

/// `a` wrapped to (−π, π] (rad).
fn wrap(a: f64) -> f64 {
    let w = a.rem_euclid(core::f64::consts::TAU);
    if w > core::f64::consts::PI {
        w - core::f64::consts::TAU
    } else {
        w
    }
}

impl RoadNetwork {
    /// Where the point `p` (m, world x and y) with yaw `yaw` (rad) is in the lane that holds
    /// it, with the curvature `lookahead` (m, ≥ 0) ahead; `None` off every road's lanes.
    ///
    /// ```
    /// use sim::road::{Curve, Road, RoadNetwork};
    /// use sim::nalgebra::Point2;
    /// let road = Road::two_way("r", Point2::origin(), 0.0, &[(100.0, Curve::Line)], 3.5)?;
    /// let net = RoadNetwork { roads: vec![road], junctions: vec![] };
    /// let at = net.track(&Point2::new(40.0, -1.5), 0.1, 10.0).unwrap();
    /// assert_eq!(at.lane, -1);
    /// assert!((at.lateral_offset - 0.25).abs() < 1e-12); // m, left of the lane centre
    /// assert!((at.heading_error - 0.1).abs() < 1e-12); // rad, pointing left
    /// # Ok::<(), sim::road::RoadError>(())
    /// ```
    pub fn track(&self, p: &Point2<f64>, yaw: f64, lookahead: f64) -> Option<LaneTracking> {
        let (road, at) = self.locate(p)?;
        self.track_lane(road, at.lane, p, yaw, lookahead)
    }

    /// As [`RoadNetwork::track`], measured against lane `lane` of road `road` (by index)
    /// wherever the point is across the road (in another lane, or off the road: the
    /// distances are then negative); `None` for a road or lane that does not exist at the
    /// point's station, or a point beyond the road's ends.
    pub fn track_lane(
        &self,
        road: usize,
        lane: i32,
        p: &Point2<f64>,
        yaw: f64,
        lookahead: f64,
    ) -> Option<LaneTracking> {
        let r = self.roads.get(road)?;
        let (s, t, _) = r.station_of(p);
        let pose = r.plan_at(s);
        // Beyond either end the nearest point is the end itself with p off its normal.
        let along = (p - pose.point).dot(&Vector2::new(pose.heading.cos(), pose.heading.sin()));
        if along.abs() > 1e-6 * (1.0 + r.length()) {
            return None;
        }
        let (centre, width) = lane_centre(r, s, lane)?;
        let (lo, hi) = road_extent(r, s);
        let dir = travel_direction(lane);
        // u: the lateral coordinate across the road in the travel direction (m, left > 0).
        let u = dir * t;
        let (lane_lo, lane_hi) = (dir * centre - 0.5 * width, dir * centre + 0.5 * width);
        let (edge_lo, edge_hi) = if dir > 0.0 { (lo, hi) } else { (-hi, -lo) };
        let travel = if dir > 0.0 {
            pose.heading
        } else {
            pose.heading + core::f64::consts::PI
        };
        let (ahead_road, ahead_s) = self.advance(road, s, dir * lookahead.max(0.0));
        let curvature_ahead = self
            .roads
            .get(ahead_road)
            .map_or(0.0, |a| lane_curvature(a, ahead_s, lane));
        Some(LaneTracking {
            road,
            lane,
            s,
            direction: dir,
            lateral_offset: u - dir * centre,
            heading_error: wrap(yaw - travel),
            curvature: dir * lane_curvature(r, s, lane),
            curvature_ahead: dir * curvature_ahead,
            left_line: lane_hi - u,
            right_line: u - lane_lo,
            left_edge: edge_hi - u,
            right_edge: u - edge_lo,
            lane_width: width,
        })
    }

    /// The road (index) and station (m) `distance` m from station `s` of road `road` along
    /// it (negative: against s), following direct road links (see the module doc) and
    /// stopping at an end without one.
    pub fn advance(&self, road: usize, s: f64, distance: f64) -> (usize, f64) {
        let (mut road, mut s, mut left) = (road, s, distance);
        for _ in 0..MAX_LINKS {
            let Some(r) = self.roads.get(road) else {
                return (road, s);
            };
            let target = s + left;
            let length = r.length();
            if (0.0..=length).contains(&target) {
                return (road, target);
            }
            // The link in the direction of travel must continue in the same direction: a
            // successor's start going forwards, a predecessor's end going backwards.
            let (link, end, want) = if target > length {
                (&r.successor, length, ContactPoint::Start)
            } else {
                (&r.predecessor, 0.0, ContactPoint::End)
            };
            let next = match link {
                Some(RoadLink::Road { id, contact }) if *contact == want => self
                    .roads
                    .iter()
                    .position(|o| o.id == *id)
                    .map(|i| (i, &self.roads[i])),
                _ => None,
            };
            let Some((i, o)) = next else {
                return (road, end);
            };
            left = target - end;
            road = i;
            s = match want {
                ContactPoint::Start => 0.0,
                ContactPoint::End => o.length(),
            };
        }
        (road, s)
    }

    /// The world point (m, x and y) `distance` m ahead of station `s` of road `road` in the
    /// direction of lane `lane`'s travel, at the lateral position `t_of(road, s)` (m) of the
    /// road and station reached: the point a path follower steers for.
    pub fn point_ahead(
        &self,
        road: usize,
        s: f64,
        lane: i32,
        distance: f64,
        t_of: impl Fn(&Road, f64) -> Option<f64>,
    ) -> Option<Point2<f64>> {
        let (i, s2) = self.advance(road, s, travel_direction(lane) * distance.max(0.0));
        let r = self.roads.get(i)?;
        let t = t_of(r, s2)?;
        let q = r.surface_point(s2, t);
        Some(Point2::new(q.x, q.y))
    }
}

/// The centre (m, t) and width (m) of lane `lane` of road `r` at station `s`, if it has one
/// of non-zero width there.
pub fn lane_centre(r: &Road, s: f64, lane: i32) -> Option<(f64, f64)> {
    r.lane_edges(s)
        .1
        .into_iter()
        .find(|(l, a, b)| l.id == lane && a != b)
        .map(|(_, a, b)| (0.5 * (a + b), (b - a).abs()))
}

/// The plan-view curvature (1/m, positive turning left along s) of lane `lane`'s centre
/// line of road `r` at station `s`: a line offset by t from a reference line of curvature κ
/// has curvature κ / (1 − κ·t); the reference line's where the lane does not exist.
pub fn lane_curvature(r: &Road, s: f64, lane: i32) -> f64 {
    let k = r.plan_at(s).curvature;
    let t = lane_centre(r, s, lane).map_or(0.0, |(t, _)| t);
    let d = 1.0 - k * t;
    // A lane centre beyond the centre of curvature (d ≤ 0) is not a lane; validated roads
    // have none, but the reference line's curvature stands for it rather than a division.
    if d > 0.0 { k / d } else { k }
}

/// The lowest and highest t (m) of the road surface at `s`: its outermost lane edges (the
/// lane offset alone on a road without lanes).
fn road_extent(r: &Road, s: f64) -> (f64, f64) {
    let (t0, edges) = r.lane_edges(s);
    edges.iter().fold((t0, t0), |(lo, hi), &(_, a, b)| {
        (lo.min(a.min(b)), hi.max(a.max(b)))
    })
}

#[cfg(test)]
#[path = "tracking_tests.rs"]
mod tests;
