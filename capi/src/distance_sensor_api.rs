//! `webots/distance_sensor.h`: the distance sensor functions, over the engine's
//! `DistanceSensor` (`sim::devices`).

use std::ffi::c_int;

use sim::devices::{DeviceKind, DeviceSettings, DistanceSensorSettings, Reading};

use crate::abi::WbDeviceTag;
use crate::guard::call_pointer;
use crate::robot::Robot;
use crate::sensor::{self, device, find, read};
use crate::session::with_robot;

const KIND: DeviceKind = DeviceKind::DistanceSensor;

/// The fields of the distance sensor with `tag`, for `function` (Webots' messages for a wrong
/// tag), with its index.
fn settings<'a>(
    robot: &'a Robot,
    function: &str,
    tag: WbDeviceTag,
) -> Option<(usize, &'a DistanceSensorSettings)> {
    let found = find(robot, tag, KIND, function, true)?;
    match device(robot, found)?.settings() {
        DeviceSettings::DistanceSensor(s) => Some((found.1, s)),
        _ => None,
    }
}

/// The sensor's lookup table (row-major), `None` if empty or a wrong tag.
fn lookup_table<'a>(robot: &'a Robot, function: &str, tag: WbDeviceTag) -> Option<&'a [f64]> {
    let (index, _) = settings(robot, function, tag)?;
    Some(robot.controller().buffers.table(index)).filter(|t| !t.is_empty())
}

/// The Rust twin of [`wb_distance_sensor_get_lookup_table`] for the Python package: the rows
/// one after the other (`None` if empty or a wrong tag).
pub fn distance_sensor_lookup_table(tag: WbDeviceTag) -> Option<Vec<f64>> {
    with_robot(|r| lookup_table(r, "wb_distance_sensor_get_lookup_table", tag).map(<[f64]>::to_vec))
}

entry_points! {
    /// Samples the sensor every `sampling_period` ms. Webots: `wb_distance_sensor_enable`.
    fn wb_distance_sensor_enable(tag: WbDeviceTag, sampling_period: c_int) {
        with_robot(|r| sensor::enable(r, KIND, "wb_distance_sensor_enable", tag, sampling_period))
    }

    /// Stops sampling the sensor. Webots: `wb_distance_sensor_disable`.
    fn wb_distance_sensor_disable(tag: WbDeviceTag) {
        with_robot(|r| sensor::enable(r, KIND, "wb_distance_sensor_disable", tag, 0))
    }

    /// The sensor's period (ms), 0 when disabled. Webots:
    /// `wb_distance_sensor_get_sampling_period`.
    fn wb_distance_sensor_get_sampling_period(tag: WbDeviceTag) -> c_int {
        with_robot(|r| sensor::sampling_period(r, KIND, tag))
    }

    /// The sensor's value (its lookup table's unit); NaN before the first sample and for a
    /// wrong tag. Webots: `wb_distance_sensor_get_value`.
    fn wb_distance_sensor_get_value(tag: WbDeviceTag) -> f64 {
        with_robot(|r| match read(r, KIND, "wb_distance_sensor_get_value", tag, true) {
            Some((_, Reading::Distance(v))) => v,
            _ => f64::NAN,
        })
    }

    /// The largest value of the lookup table (0 if empty); NaN for a wrong tag. Webots:
    /// `wb_distance_sensor_get_max_value`.
    fn wb_distance_sensor_get_max_value(tag: WbDeviceTag) -> f64 {
        with_robot(|r| {
            settings(r, "wb_distance_sensor_get_max_value", tag)
                .map_or(f64::NAN, |(_, s)| s.max_value())
        })
    }

    /// The smallest value of the lookup table (0 if empty); NaN for a wrong tag. Webots:
    /// `wb_distance_sensor_get_min_value`.
    fn wb_distance_sensor_get_min_value(tag: WbDeviceTag) -> f64 {
        with_robot(|r| {
            settings(r, "wb_distance_sensor_get_min_value", tag)
                .map_or(f64::NAN, |(_, s)| s.min_value())
        })
    }

    /// The `aperture` (rad); NaN for a wrong tag. Webots: `wb_distance_sensor_get_aperture`.
    fn wb_distance_sensor_get_aperture(tag: WbDeviceTag) -> f64 {
        with_robot(|r| {
            settings(r, "wb_distance_sensor_get_aperture", tag).map_or(f64::NAN, |(_, s)| s.aperture)
        })
    }

    /// The rows of the lookup table (0 if empty or a wrong tag). Webots:
    /// `wb_distance_sensor_get_lookup_table_size`.
    fn wb_distance_sensor_get_lookup_table_size(tag: WbDeviceTag) -> c_int {
        with_robot(|r| {
            let f = "wb_distance_sensor_get_lookup_table_size";
            let rows = lookup_table(r, f, tag).map_or(0, |t| t.len() / 3);
            c_int::try_from(rows).unwrap_or(c_int::MAX)
        })
    }

    /// The `type` (`WbDistanceSensorType`: GENERIC 0, INFRA_RED 1, SONAR 2, LASER 3); GENERIC
    /// for a wrong tag. Webots: `wb_distance_sensor_get_type`.
    fn wb_distance_sensor_get_type(tag: WbDeviceTag) -> c_int {
        with_robot(|r| {
            settings(r, "wb_distance_sensor_get_type", tag)
                .map_or(0, |(_, s)| s.sensor_type.webots_value())
        })
    }
}

/// The lookup table, rows `[distance, value, noise]` one after the other; NULL if empty or a
/// wrong tag. Webots: `wb_distance_sensor_get_lookup_table`.
#[unsafe(no_mangle)]
pub extern "C" fn wb_distance_sensor_get_lookup_table(tag: WbDeviceTag) -> *const f64 {
    call_pointer("wb_distance_sensor_get_lookup_table", || {
        with_robot(|r| {
            lookup_table(r, "wb_distance_sensor_get_lookup_table", tag).map(<[f64]>::as_ptr)
        })
    })
}
