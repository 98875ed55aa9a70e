//! `RoadSensor`, a project extension (no Webots device measures roads; BeamNG's roads sensor
//! is the model): where the device point is on the world's roads, from the one tracking
//! measurement [`RoadNetwork::track`] that the lane follower uses too.
//!
//! It measures at the device point (its mount on the chassis; the car origin, the
//! rear-axle centre, without a slot or translation) with the device's heading (its x axis
//! projected on the ground), in the lane holding that point and in that lane's travel
//! direction: lateral offset positive left of the lane centre, heading error positive
//! pointing left, curvature positive turning left, distances to the lines and edges
//! positive inside them ([`crate::road::LaneTracking`]). It has no noise: the geometry is
//! exact. Off every road's lanes, and before the first sample, every number is NaN and the
//! road and lane are `None`.

use proto_geom::nalgebra::{Point2, Vector3};

use crate::error::ParamError;
use crate::road::{LaneTracking, RoadNetwork};

use super::DevicePoint;

/// Default `lookahead` (m): where the curvature ahead is read, about 0.7 s ahead at 50 km/h.
pub const DEFAULT_LOOKAHEAD: f64 = 10.0;
/// Largest `lookahead` (m).
pub const MAX_LOOKAHEAD: f64 = 500.0;

/// The fields of a `RoadSensor` node.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoadSensorSettings {
    /// `lookahead` (m, 0 to [`MAX_LOOKAHEAD`]; default [`DEFAULT_LOOKAHEAD`]): how far ahead
    /// along the lane the curvature ahead is read.
    pub lookahead: f64,
}

impl Default for RoadSensorSettings {
    fn default() -> Self {
        RoadSensorSettings {
            lookahead: DEFAULT_LOOKAHEAD,
        }
    }
}

impl RoadSensorSettings {
    /// Checks `lookahead`.
    ///
    /// # Errors
    /// A [`ParamError`] naming the field and the value.
    pub fn validate(&self) -> Result<(), ParamError> {
        ParamError::check("lookahead", self.lookahead, "from 0 to 500 m", |d| {
            (0.0..=MAX_LOOKAHEAD).contains(&d)
        })
        .map(|_| ())
    }
}

/// A `RoadSensor` sample (see the module doc for the signs).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoadSensorReading {
    /// The road's index in the world's road network; `None` off the roads.
    pub road: Option<usize>,
    /// The lane (1, 2, … left of the reference line, −1, −2, … right); `None` off the roads.
    pub lane: Option<i32>,
    /// Station along the road (m).
    pub s: f64,
    /// Offset from the lane centre (m, positive left).
    pub lateral_offset: f64,
    /// Device heading minus the lane's travel direction (rad, positive left).
    pub heading_error: f64,
    /// The lane's curvature at the device (1/m, positive turning left).
    pub curvature: f64,
    /// The lane's curvature `lookahead` ahead (1/m).
    pub curvature_ahead: f64,
    /// Distance to the lane's left line (m, positive inside).
    pub left_line: f64,
    /// Distance to the lane's right line (m, positive inside).
    pub right_line: f64,
    /// Distance to the road's left edge (m, positive on the road).
    pub left_edge: f64,
    /// Distance to the road's right edge (m, positive on the road).
    pub right_edge: f64,
    /// The lane's width (m).
    pub lane_width: f64,
}

impl RoadSensorReading {
    /// The reading before the first sample, and off the roads: NaN, no road, no lane.
    pub fn unsampled() -> Self {
        RoadSensorReading {
            road: None,
            lane: None,
            s: f64::NAN,
            lateral_offset: f64::NAN,
            heading_error: f64::NAN,
            curvature: f64::NAN,
            curvature_ahead: f64::NAN,
            left_line: f64::NAN,
            right_line: f64::NAN,
            left_edge: f64::NAN,
            right_edge: f64::NAN,
            lane_width: f64::NAN,
        }
    }

    fn of(t: &LaneTracking) -> Self {
        RoadSensorReading {
            road: Some(t.road),
            lane: Some(t.lane),
            s: t.s,
            lateral_offset: t.lateral_offset,
            heading_error: t.heading_error,
            curvature: t.curvature,
            curvature_ahead: t.curvature_ahead,
            left_line: t.left_line,
            right_line: t.right_line,
            left_edge: t.left_edge,
            right_edge: t.right_edge,
            lane_width: t.lane_width,
        }
    }
}

/// The sample of a road sensor at `point` on `roads`.
pub(super) fn measure(
    s: &RoadSensorSettings,
    roads: &RoadNetwork,
    point: &DevicePoint,
) -> RoadSensorReading {
    let forward = point.rotation * Vector3::x();
    let yaw = forward.y.atan2(forward.x);
    let p = Point2::new(point.position.x, point.position.y);
    roads
        .track(&p, yaw, s.lookahead)
        .map_or_else(RoadSensorReading::unsampled, |t| RoadSensorReading::of(&t))
}
