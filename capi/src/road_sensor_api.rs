//! `webots/vehicle/road_sensor.h`: the RoadSensor, a project extension with no Webots
//! counterpart (`sim::devices::RoadSensorReading`). Its functions carry the project prefix
//! `vehicle_road_sensor_`; enabling and the sampling period work as for every Webots sensor
//! (a negative period is refused with the same error, a disabled sensor's read prints the
//! same error and gives its last sample).

use std::ffi::c_int;

use sim::devices::{DeviceKind, DeviceSettings, Reading, RoadSensorReading};

use crate::abi::WbDeviceTag;
use crate::robot::Robot;
use crate::sensor::{self, device, find, read};
use crate::session::with_robot;

const KIND: DeviceKind = DeviceKind::RoadSensor;

/// The last sample of the road sensor with `tag`, for the getter `function`; `None` for a
/// wrong tag.
fn sample(robot: &Robot, function: &str, tag: WbDeviceTag) -> Option<RoadSensorReading> {
    match read(robot, KIND, function, tag, true)? {
        (_, Reading::Road(r)) => Some(r),
        _ => None,
    }
}

/// The Rust twin of the getters for the Python package: the whole last sample (`None` for a
/// wrong tag), with the messages of `function`.
pub fn road_sensor_reading(function: &str, tag: WbDeviceTag) -> Option<RoadSensorReading> {
    with_robot(|r| sample(r, function, tag))
}

/// One number of the last sample: NaN for a wrong tag.
fn number(function: &str, tag: WbDeviceTag, f: impl Fn(&RoadSensorReading) -> f64) -> f64 {
    road_sensor_reading(function, tag).map_or(f64::NAN, |r| f(&r))
}

entry_points! {
    /// Samples the road sensor every `sampling_period` ms (negative: refused).
    fn vehicle_road_sensor_enable(tag: WbDeviceTag, sampling_period: c_int) {
        with_robot(|r| sensor::enable(r, KIND, "vehicle_road_sensor_enable", tag, sampling_period))
    }

    /// Stops sampling the road sensor; its last sample stays readable (with an error).
    fn vehicle_road_sensor_disable(tag: WbDeviceTag) {
        with_robot(|r| sensor::enable(r, KIND, "vehicle_road_sensor_disable", tag, 0))
    }

    /// The sampling period (ms), 0 when disabled or for a wrong tag.
    fn vehicle_road_sensor_get_sampling_period(tag: WbDeviceTag) -> c_int {
        with_robot(|r| sensor::sampling_period(r, KIND, tag))
    }

    /// The `lookahead` field (m); NaN for a wrong tag.
    fn vehicle_road_sensor_get_lookahead(tag: WbDeviceTag) -> f64 {
        with_robot(|r| {
            let found = find(r, tag, KIND, "vehicle_road_sensor_get_lookahead", true);
            match found.and_then(|f| device(r, f)).map(|d| d.settings()) {
                Some(DeviceSettings::RoadSensor(s)) => s.lookahead,
                _ => f64::NAN,
            }
        })
    }

    /// The index of the road the device is on (0 for the world's first `[[road]]`); −1 off
    /// the roads, before the first sample and for a wrong tag.
    fn vehicle_road_sensor_get_road(tag: WbDeviceTag) -> c_int {
        road_sensor_reading("vehicle_road_sensor_get_road", tag)
            .and_then(|r| r.road)
            .map_or(-1, |i| c_int::try_from(i).unwrap_or(c_int::MAX))
    }

    /// The lane the device is in (1, 2, … left of the reference line, −1, −2, … right); 0
    /// off the roads, before the first sample and for a wrong tag.
    fn vehicle_road_sensor_get_lane(tag: WbDeviceTag) -> c_int {
        road_sensor_reading("vehicle_road_sensor_get_lane", tag)
            .and_then(|r| r.lane)
            .unwrap_or(0)
    }

    /// The station along the road (m); NaN off the roads.
    fn vehicle_road_sensor_get_station(tag: WbDeviceTag) -> f64 {
        number("vehicle_road_sensor_get_station", tag, |r| r.s)
    }

    /// The offset from the lane centre (m, positive left of it in the travel direction).
    fn vehicle_road_sensor_get_lateral_offset(tag: WbDeviceTag) -> f64 {
        number("vehicle_road_sensor_get_lateral_offset", tag, |r| r.lateral_offset)
    }

    /// The device heading minus the lane's travel direction (rad, positive left).
    fn vehicle_road_sensor_get_heading_error(tag: WbDeviceTag) -> f64 {
        number("vehicle_road_sensor_get_heading_error", tag, |r| r.heading_error)
    }

    /// The lane's curvature at the device (1/m, positive turning left).
    fn vehicle_road_sensor_get_curvature(tag: WbDeviceTag) -> f64 {
        number("vehicle_road_sensor_get_curvature", tag, |r| r.curvature)
    }

    /// The lane's curvature `lookahead` metres ahead (1/m, positive turning left).
    fn vehicle_road_sensor_get_curvature_ahead(tag: WbDeviceTag) -> f64 {
        number("vehicle_road_sensor_get_curvature_ahead", tag, |r| r.curvature_ahead)
    }

    /// The distance to the lane's left line (m, positive inside the lane).
    fn vehicle_road_sensor_get_left_line_distance(tag: WbDeviceTag) -> f64 {
        number("vehicle_road_sensor_get_left_line_distance", tag, |r| r.left_line)
    }

    /// The distance to the lane's right line (m, positive inside the lane).
    fn vehicle_road_sensor_get_right_line_distance(tag: WbDeviceTag) -> f64 {
        number("vehicle_road_sensor_get_right_line_distance", tag, |r| r.right_line)
    }

    /// The distance to the road's left edge (m, positive on the road).
    fn vehicle_road_sensor_get_left_edge_distance(tag: WbDeviceTag) -> f64 {
        number("vehicle_road_sensor_get_left_edge_distance", tag, |r| r.left_edge)
    }

    /// The distance to the road's right edge (m, positive on the road).
    fn vehicle_road_sensor_get_right_edge_distance(tag: WbDeviceTag) -> f64 {
        number("vehicle_road_sensor_get_right_edge_distance", tag, |r| r.right_edge)
    }

    /// The lane's width (m).
    fn vehicle_road_sensor_get_lane_width(tag: WbDeviceTag) -> f64 {
        number("vehicle_road_sensor_get_lane_width", tag, |r| r.lane_width)
    }
}
