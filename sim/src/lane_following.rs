//! The built-in lane-following driver (`follow_lane = true` in a `[[vehicle.programme]]`
//! step, [`crate::Simulation::follow_lane`]): each step before the car's driver library runs,
//! it measures where the car is on the road ([`crate::road::RoadNetwork::track_lane`]'s
//! station), picks the goal point on the target lane's centre one look-ahead ahead
//! ([`vehicle_model::PurePursuit::lookahead`]: 0.6 s of travel, at least 4 m), and sets the
//! steering angle of the pure-pursuit law ([`vehicle_model::PurePursuit`]), within the car's
//! `minSteeringAngle` and `maxSteeringAngle`.
//! * **Speed.** The speed is the programme's `cruising_speed` (speed mode), lowered where
//!   a curve ahead would need more than `max_lateral_acceleration` (default
//!   [`MAX_LATERAL_ACCELERATION`], 3 m/s²): at each station d metres ahead with lane
//!   curvature κ the speed allowed now is `√(a/|κ| + 2·b·d)`, b = [`CURVE_DECELERATION`], the
//!   smallest over the stretch the car needs to slow down in. Why: drivers keep within 3 to
//!   4 m/s² on urban curves (Reymond et al., *Role of lateral acceleration in curve
//!   driving*, Human Factors 43, 2001), and a lane follower taking a 25 m radius at 50 km/h
//!   (7.7 m/s², 0.8 g) runs at the tyres' limit, understeers and leaves its lane: no
//!   traffic does that. Set a larger `max_lateral_acceleration` to see it. In torque mode
//!   (throttle and brake) the speed is the programme's alone.
//!
//! * **Which lane.** `lane` picks one (1, 2, … left of the reference line, −1, −2, …
//!   right); without it the car keeps the lane it is in when it starts following. Lanes are
//!   driven in their travel direction ([`crate::road::travel_direction`]).
//! * **Lane change.** Asking for another lane while following moves the goal's lateral
//!   position from the old lane's centre to the new one's over `lane_change_time` (s,
//!   default [`LANE_CHANGE_TIME`]) along a half-cosine, so the commanded lateral velocity
//!   starts and ends at zero; its peak lateral acceleration is `π²·w / (2·T²)` (for a 3.5 m
//!   lane in 4 s, 1.1 m/s², a calm lane change). Only lanes of the same travel direction:
//!   a change across the centre line is refused.
//! * **Roads.** The car follows its road across direct road links (a closed road, a
//!   successor); when the point is beyond the road it re-finds the road under the car.
//!   A car off every road, or whose lane does not exist where it is, is not steered (the
//!   steering stays as it was) and [`LaneFollower::status`] says why, for the runner to
//!   report; steering resumes when the car is back on a road with that lane.

use proto_geom::nalgebra::Point2;
use vehicle_model::{CarParams, ControlMode, Driver, PurePursuit};

use crate::error::{ParamError, Rule};
use crate::road::{RoadNetwork, lane_centre, lane_curvature, travel_direction};
use crate::vehicle::VehicleState;

/// Default duration of a lane change (s): 4 s, within the 3 s to 6 s drivers take on
/// highways.
pub const LANE_CHANGE_TIME: f64 = 4.0;
/// Longest lane change (s).
pub const MAX_LANE_CHANGE_TIME: f64 = 60.0;
/// Shortest lane change (s): faster is a swerve, beyond a lane follower's brief.
pub const MIN_LANE_CHANGE_TIME: f64 = 1.0;
/// Default largest lateral acceleration (m/s²) the follower's speed allows in a curve.
pub const MAX_LATERAL_ACCELERATION: f64 = 3.0;
/// Deceleration (m/s²) the follower plans to slow down for a curve with: a calm brake, below
/// the 3.5 m/s² ISO 15622 allows an ACC.
pub const CURVE_DECELERATION: f64 = 2.0;
/// Station step (m) of the scan of curvatures ahead.
const SCAN_STEP: f64 = 1.0;
/// Most stations scanned: 500 m, the distance to slow from 160 km/h at
/// [`CURVE_DECELERATION`]; the bound keeps a step's cost fixed.
const MAX_SCAN: usize = 500;

/// What to follow: a lane, and how fast to change to it.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FollowLane {
    /// The lane (1, 2, … left, −1, −2, … right of the reference line); `None`: the lane the
    /// car is in when it starts following.
    pub lane: Option<i32>,
    /// How long a change to this lane takes (s, [`MIN_LANE_CHANGE_TIME`] to
    /// [`MAX_LANE_CHANGE_TIME`]).
    pub change_time: f64,
    /// Largest lateral acceleration in curves (m/s², 0.5 to 20) the speed allows.
    pub max_lateral_acceleration: f64,
}

impl Default for FollowLane {
    fn default() -> Self {
        FollowLane {
            lane: None,
            change_time: LANE_CHANGE_TIME,
            max_lateral_acceleration: MAX_LATERAL_ACCELERATION,
        }
    }
}

impl FollowLane {
    /// Checks `change_time` and that `lane` is not 0 (the centre lane has no width).
    pub fn validate(&self) -> Result<(), ParamError> {
        ParamError::check(
            "lane_change_time",
            self.change_time,
            "from 1 to 60 s",
            |t| (MIN_LANE_CHANGE_TIME..=MAX_LANE_CHANGE_TIME).contains(&t),
        )?;
        ParamError::check(
            "max_lateral_acceleration",
            self.max_lateral_acceleration,
            "from 0.5 to 20 m/s²",
            |a| (0.5..=20.0).contains(&a),
        )?;
        if self.lane == Some(0) {
            return Err(ParamError {
                field: "lane",
                value: 0.0,
                rule: Rule::Text("a lane id other than 0 (the centre lane has no width)"),
            });
        }
        Ok(())
    }
}

/// A programme command of the lane follower (`[[vehicle.programme]]` keys `follow_lane`,
/// `lane`, `lane_change_time`, `max_lateral_acceleration`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum FollowCommand {
    /// Follow (or, while following, retarget: another lane is a lane change).
    Follow(FollowLane),
    /// Stop following (`follow_lane = false`): the steering stays where it was.
    Stop,
}

/// Why the follower did not steer at its last step.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum FollowStatus {
    /// It steered.
    Following,
    /// The car is on no road's lanes.
    OffRoad,
    /// The road under the car has no such lane there.
    NoLane(i32),
}

/// A lane change under way.
#[derive(Debug, Clone, Copy, PartialEq)]
struct LaneChange {
    from: i32,
    start: f64,
    duration: f64,
}

/// The state of a car's lane-following driver.
#[derive(Debug, Clone, PartialEq)]
pub struct LaneFollower {
    law: PurePursuit<f64>,
    road: Option<usize>,
    lane: Option<i32>,
    change: Option<LaneChange>,
    status: FollowStatus,
    max_lateral_acceleration: f64,
    /// The cruising speed the programme asked for (km/h), and the one the follower set last.
    cruise: Option<(f64, f64)>,
}

impl LaneFollower {
    /// The follower of a car with parameters `params`, following `request`.
    ///
    /// # Errors
    /// A [`ParamError`] for a request out of range or a car without a steering range.
    pub fn new(params: &CarParams<f64>, request: FollowLane) -> Result<Self, ParamError> {
        request.validate()?;
        let geometry = params.geometry().map_err(|e| ParamError {
            field: "wheelbase",
            value: e.value,
            rule: Rule::Text("a car geometry the lane follower can steer (finite, > 0)"),
        })?;
        let law = PurePursuit::new(
            geometry,
            params.min_steering_angle,
            params.max_steering_angle,
        )
        .map_err(|e| ParamError {
            field: "maxSteeringAngle",
            value: e.max,
            rule: Rule::Text("a steering range around 0 for the lane follower"),
        })?;
        Ok(LaneFollower {
            law,
            road: None,
            lane: request.lane,
            change: None,
            status: FollowStatus::Following,
            max_lateral_acceleration: request.max_lateral_acceleration,
            cruise: None,
        })
    }

    /// Takes a new request at time `t` (s): another lane starts a lane change from the one
    /// followed.
    ///
    /// # Errors
    /// A [`ParamError`] for a request out of range or a lane of the other travel direction.
    pub fn request(&mut self, request: FollowLane, t: f64) -> Result<(), ParamError> {
        request.validate()?;
        self.max_lateral_acceleration = request.max_lateral_acceleration;
        let Some(to) = request.lane else {
            return Ok(());
        };
        let Some(from) = self.lane.filter(|&from| from != to) else {
            self.lane = Some(to);
            return Ok(());
        };
        if travel_direction(to) != travel_direction(from) {
            return Err(ParamError {
                field: "lane",
                value: f64::from(to),
                rule: Rule::Text(
                    "a lane of the same travel direction as the one followed (a lane change \
                     does not cross the centre line)",
                ),
            });
        }
        self.change = Some(LaneChange {
            from,
            start: t,
            duration: request.change_time,
        });
        self.lane = Some(to);
        Ok(())
    }

    /// The lane followed (the target of a lane change under way), once known.
    pub fn lane(&self) -> Option<i32> {
        self.lane
    }

    /// Why the last [`LaneFollower::drive`] did not steer, or that it did.
    pub fn status(&self) -> FollowStatus {
        self.status
    }

    /// Sets `driver`'s steering angle and, in speed mode, its cruising speed for the car in
    /// `state` at time `t` (s) on `roads`; leaves them when it cannot follow (see
    /// [`LaneFollower::status`]).
    pub fn drive(
        &mut self,
        roads: &RoadNetwork,
        state: &VehicleState,
        t: f64,
        driver: &mut Driver<f64>,
    ) {
        let Some((angle, road, s, lane)) = self.steering(roads, state, t) else {
            return;
        };
        // Within the car's steering range: the driver has nothing to warn of.
        driver.set_steering_angle(angle);
        if driver.control_mode() != ControlMode::Speed {
            self.cruise = None;
            return;
        }
        let target = driver.target_cruising_speed();
        // A target the follower did not set is the programme's (or a controller's) request.
        let asked = match self.cruise {
            Some((asked, set)) if set == target => asked,
            _ => target,
        };
        let limit = 3.6 * self.speed_limit(roads, road, s, lane, state.forward_speed);
        let set = asked.min(limit);
        driver.set_cruising_speed(set);
        self.cruise = Some((asked, driver.target_cruising_speed()));
    }

    /// The highest speed (m/s) from which the car, at `speed` (m/s) at station `s` of lane
    /// `lane` of road `road`, can slow at [`CURVE_DECELERATION`] for every curve of the
    /// stretch ahead it needs to, keeping within the lateral-acceleration limit.
    fn speed_limit(&self, roads: &RoadNetwork, road: usize, s: f64, lane: i32, speed: f64) -> f64 {
        let b = CURVE_DECELERATION;
        let a = self.max_lateral_acceleration;
        let reach = speed * speed / (2.0 * b) + PurePursuit::<f64>::lookahead(speed);
        let n = ((reach / SCAN_STEP).ceil() as usize).clamp(1, MAX_SCAN);
        let dir = travel_direction(lane);
        (0..=n)
            .map(|i| {
                let d = i as f64 * SCAN_STEP;
                let (r, at) = roads.advance(road, s, dir * d);
                let k = roads
                    .roads
                    .get(r)
                    .map_or(0.0, |r| lane_curvature(r, at, lane));
                (a / k.abs().max(1e-9) + 2.0 * b * d).sqrt()
            })
            .fold(f64::INFINITY, f64::min)
    }

    /// The steering angle (rad, positive right) for the car in `state` at time `t` (s) on
    /// `roads`, with the road, station (m) and lane it follows; `None` when it cannot follow.
    fn steering(
        &mut self,
        roads: &RoadNetwork,
        state: &VehicleState,
        t: f64,
    ) -> Option<(f64, usize, f64, i32)> {
        let p = Point2::new(state.position.x, state.position.y);
        let yaw = state.roll_pitch_yaw.yaw;
        // The road followed while the car is within its ends, else the one under the car.
        let on_road = self
            .road
            .zip(self.lane)
            .and_then(|(r, l)| roads.track_lane(r, l, &p, yaw, 0.0).map(|_| r));
        let road = match on_road {
            Some(r) => r,
            None => match roads.locate(&p) {
                Some((r, at)) => {
                    self.lane.get_or_insert(at.lane);
                    r
                }
                None => {
                    self.status = FollowStatus::OffRoad;
                    return None;
                }
            },
        };
        self.road = Some(road);
        let lane = self.lane?;
        let blend = match self.change {
            Some(c) => {
                let u = ((t - c.start) / c.duration).clamp(0.0, 1.0);
                if u >= 1.0 {
                    self.change = None;
                }
                Some((c.from, 0.5 * (1.0 - (core::f64::consts::PI * u).cos())))
            }
            None => None,
        };
        let (s, _, _) = roads.roads.get(road)?.station_of(&p);
        let reach = PurePursuit::<f64>::lookahead(state.forward_speed);
        let goal = roads.point_ahead(road, s, lane, reach, |r, s| {
            let (to, _) = lane_centre(r, s, lane)?;
            match blend {
                Some((from, b)) => lane_centre(r, s, from).map(|(f, _)| f + b * (to - f)),
                None => Some(to),
            }
        });
        let Some(goal) = goal else {
            self.status = FollowStatus::NoLane(lane);
            return None;
        };
        self.status = FollowStatus::Following;
        let d = goal - p;
        let (sn, cs) = yaw.sin_cos();
        let angle = self.law.steering(d.x * cs + d.y * sn, -d.x * sn + d.y * cs);
        Some((angle, road, s, lane))
    }
}
