//! Lane departures of a car, from its recorded poses on a world's roads.
//!
//! **Definition** (after ISO 17361, lane departure warning systems): a car departs its lane
//! when the outer edge of a front tyre crosses one of the lane's lines, measured at the
//! lines' centres (the lane's edges, [`crate::road::LaneTracking`]). The car's lane is the
//! driving lane holding its front-axle centre; the tyre's outer edge is the point at the
//! front axle, half the front track plus half the tyre's thickness to the side (the wheel's
//! steering turn is neglected: it moves that point by under a centimetre). A departure is
//! counted when the edge goes from inside the line to beyond it, on the left or the right
//! (in the lane's travel direction); the side is counted again only after the tyre is back
//! inside. When the front-axle centre moves into another lane (the end of a lane change)
//! the tyres' state is taken afresh without counting. A signalled lane change is a lane
//! departure too (an LDW system would suppress its warning; this report does not).

use proto_geom::nalgebra::{Point2, Vector2};
use vehicle_model::{CarParams, Wheel};

use crate::road::{LaneKind, RoadNetwork};

use super::Metric;

/// Which line a tyre crossed, in the lane's travel direction.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Side {
    /// The lane's left line.
    Left,
    /// The lane's right line.
    Right,
}

impl Side {
    /// `"left"` or `"right"`.
    pub fn name(self) -> &'static str {
        match self {
            Side::Left => "left",
            Side::Right => "right",
        }
    }
}

/// One lane departure.
#[derive(Debug, Clone, PartialEq)]
pub struct LaneDeparture {
    /// When the tyre's edge was first seen beyond the line (s): the first recorded sample
    /// after the crossing.
    pub time: f64,
    /// Which line it crossed.
    pub side: Side,
    /// The road's id.
    pub road: String,
    /// The lane departed.
    pub lane: i32,
}

/// Counts a car's lane departures, fed its poses in time order.
#[derive(Debug, Clone)]
pub struct DepartureMeter {
    /// Wheelbase (m): the front axle's distance ahead of the car origin.
    wheelbase: f64,
    /// Lateral position (m, car frame) of the outer edges of the left and right front tyres.
    edges: [f64; 2],
    /// The road (index) and lane of the front-axle centre at the last sample.
    lane: Option<(usize, i32)>,
    /// Whether the left and right tyre edges were beyond their lines at the last sample.
    out: [bool; 2],
    departures: Vec<LaneDeparture>,
}

impl DepartureMeter {
    /// A meter for a car of parameters `params`.
    pub fn new(params: &CarParams<f64>) -> Self {
        let half = 0.5 * params.track_front;
        let edge = |w: Wheel| half + 0.5 * params.wheels[w].thickness;
        DepartureMeter {
            wheelbase: params.wheelbase,
            edges: [edge(Wheel::FrontLeft), -edge(Wheel::FrontRight)],
            lane: None,
            out: [false; 2],
            departures: Vec::new(),
        }
    }

    /// Takes the car origin's pose at `time` (s): `x`, `y` (m, world) and `yaw` (rad).
    pub fn push(&mut self, roads: &RoadNetwork, time: f64, x: f64, y: f64, yaw: f64) {
        let (sn, cs) = yaw.sin_cos();
        let front = Point2::new(x, y) + Vector2::new(cs, sn) * self.wheelbase;
        let lane = roads.locate(&front).filter(|(r, at)| {
            roads.roads[*r]
                .lane_at(at.s, at.t)
                .is_some_and(|(l, _, _)| l.kind == LaneKind::Driving)
        });
        let Some((road, at)) = lane else {
            self.lane = None;
            return;
        };
        let left = Vector2::new(-sn, cs);
        let mut out = [false; 2];
        for (k, edge) in self.edges.iter().enumerate() {
            let p = front + left * *edge;
            out[k] = roads
                .track_lane(road, at.lane, &p, yaw, 0.0)
                .is_some_and(|m| {
                    if k == 0 {
                        m.left_line < 0.0
                    } else {
                        m.right_line < 0.0
                    }
                });
        }
        if self.lane == Some((road, at.lane)) {
            for (k, side) in [Side::Left, Side::Right].into_iter().enumerate() {
                if out[k] && !self.out[k] {
                    self.departures.push(LaneDeparture {
                        time,
                        side,
                        road: roads.roads[road].id.clone(),
                        lane: at.lane,
                    });
                }
            }
        }
        self.lane = Some((road, at.lane));
        self.out = out;
    }

    /// The departures so far, in time order.
    pub fn departures(&self) -> &[LaneDeparture] {
        &self.departures
    }

    /// The metrics: `lane_departures` (count), `lane_departures_left`,
    /// `lane_departures_right`, `first_lane_departure_s` (null without one).
    pub fn metrics(&self) -> Vec<Metric> {
        let count = |side: Option<Side>| {
            self.departures
                .iter()
                .filter(|d| side.is_none_or(|s| d.side == s))
                .count() as f64
        };
        vec![
            Metric::number("lane_departures", "lane departures", "", count(None)),
            Metric::number(
                "lane_departures_left",
                "lane departures to the left",
                "",
                count(Some(Side::Left)),
            ),
            Metric::number(
                "lane_departures_right",
                "lane departures to the right",
                "",
                count(Some(Side::Right)),
            ),
            Metric::maybe(
                "first_lane_departure_s",
                "first lane departure",
                "s",
                self.departures.first().map(|d| d.time),
            ),
        ]
    }

    /// One note per departure of car `name`: time, side, road and lane.
    pub fn notes(&self, name: &str) -> Vec<String> {
        self.departures
            .iter()
            .map(|d| {
                format!(
                    "{name}: lane departure to the {} at {:.2} s (lane {} of road '{}')",
                    d.side.name(),
                    d.time,
                    d.lane,
                    d.road
                )
            })
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::road::{Curve, Road};
    use vehicle_model::Model;

    #[test]
    fn a_car_drifting_left_departs_when_its_left_tyre_edge_crosses_the_centre_line() {
        let road = Road::two_way("r", Point2::origin(), 0.0, &[(500.0, Curve::Line)], 3.5).unwrap();
        let roads = RoadNetwork {
            roads: vec![road],
            junctions: Vec::new(),
        };
        let params = Model::BmwX5.params::<f64>();
        let mut meter = DepartureMeter::new(&params);
        // A straight drift: 20 m/s along x, 0.5 m/s to the left, from the right lane's centre.
        let (vx, vy) = (20.0, 0.5);
        let yaw = f64::atan2(vy, vx);
        let w = 0.5 * params.track_front + 0.5 * params.wheels[Wheel::FrontLeft].thickness;
        // The left tyre edge's y: −1.75 + vy·t + wheelbase·sin ψ + w·cos ψ, zero (the centre
        // line) at t*.
        let t_star = (1.75 - params.wheelbase * yaw.sin() - w * yaw.cos()) / vy;
        let dt = 0.01;
        for k in 0..400 {
            let t = k as f64 * dt;
            meter.push(&roads, t, 10.0 + vx * t, -1.75 + vy * t, yaw);
        }
        let d = meter.departures();
        assert_eq!(d.len(), 1, "{d:?}");
        assert_eq!((d[0].side, d[0].lane), (Side::Left, -1));
        // Seen at the first sample at or after the crossing: within one sample period.
        assert!(
            d[0].time >= t_star && d[0].time < t_star + dt,
            "{} vs {t_star}",
            d[0].time
        );
        assert_eq!(meter.metrics()[1].value.as_f64(), Some(1.0));
        assert!(meter.notes("car")[0].contains("to the left at"));
    }

    #[test]
    fn a_full_lane_change_counts_once_and_the_new_lane_is_taken_afresh() {
        // Three lanes to the right (−1, −2, −3): a drift from −3 to −2 crosses one line.
        let mut road =
            Road::two_way("r", Point2::origin(), 0.0, &[(500.0, Curve::Line)], 3.5).unwrap();
        let mut lanes = road.sections[0].right.clone();
        for id in [-2, -3] {
            let mut l = lanes[0].clone();
            l.id = id;
            lanes.push(l);
        }
        road.sections[0].right = lanes;
        let roads = RoadNetwork {
            roads: vec![road],
            junctions: Vec::new(),
        };
        let mut meter = DepartureMeter::new(&Model::ToyotaPrius.params::<f64>());
        for k in 0..=1000 {
            let t = k as f64 * 0.01;
            // From y = −8.75 (lane −3's centre) to −5.25 (lane −2's) over 10 s, then straight.
            let y = -8.75 + 3.5 * (t / 8.0).min(1.0);
            meter.push(&roads, t, 10.0 + 20.0 * t, y, 0.0);
        }
        let d = meter.departures();
        assert_eq!(d.len(), 1, "{d:?}");
        assert_eq!((d[0].side, d[0].lane), (Side::Left, -3));
    }
}
