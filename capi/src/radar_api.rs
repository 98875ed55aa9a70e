//! `webots/radar.h`: the radar functions, over the engine's `Radar` (`sim::devices`).

use std::ffi::c_int;

use sim::devices::{DeviceKind, DeviceSettings, RadarSettings, Reading};

use crate::abi::WbDeviceTag;
use crate::guard::call_pointer;
use crate::robot::Robot;
use crate::sensor::{self, WbRadarTarget, device, find, read};
use crate::session::with_robot;

const KIND: DeviceKind = DeviceKind::Radar;

/// The fields of the radar with `tag`, for `function`.
fn settings<'a>(robot: &'a Robot, function: &str, tag: WbDeviceTag) -> Option<&'a RadarSettings> {
    let found = find(robot, tag, KIND, function, true)?;
    match device(robot, found)?.settings() {
        DeviceSettings::Radar(s) => Some(s),
        _ => None,
    }
}

/// The radar's last targets (`None` before the first sample or for a wrong tag), with its
/// index; a disabled radar prints Webots' error and still gives them.
fn targets(robot: &Robot, function: &str, tag: WbDeviceTag) -> Option<(usize, Vec<WbRadarTarget>)> {
    match read(robot, KIND, function, tag, true)? {
        (i, Reading::Radar(Some(t))) => Some((
            i,
            t.iter()
                .map(|t| WbRadarTarget {
                    distance: t.distance,
                    received_power: t.received_power,
                    speed: t.speed,
                    azimuth: t.azimuth,
                })
                .collect(),
        )),
        _ => None,
    }
}

/// The Rust twin of [`wb_radar_get_targets`] for the Python package: the targets (empty
/// before the first sample and for a wrong tag).
pub fn radar_targets(tag: WbDeviceTag) -> Vec<WbRadarTarget> {
    with_robot(|r| {
        targets(r, "wb_radar_get_targets", tag)
            .map(|(_, t)| t)
            .unwrap_or_default()
    })
}

entry_points! {
    /// Samples the radar every `sampling_period` ms. Webots: `wb_radar_enable`.
    fn wb_radar_enable(tag: WbDeviceTag, sampling_period: c_int) {
        with_robot(|r| sensor::enable(r, KIND, "wb_radar_enable", tag, sampling_period))
    }

    /// Stops sampling the radar. Webots: `wb_radar_disable`.
    fn wb_radar_disable(tag: WbDeviceTag) {
        with_robot(|r| sensor::enable(r, KIND, "wb_radar_disable", tag, 0))
    }

    /// The radar's period (ms), 0 when disabled. Webots: `wb_radar_get_sampling_period`.
    fn wb_radar_get_sampling_period(tag: WbDeviceTag) -> c_int {
        with_robot(|r| sensor::sampling_period(r, KIND, tag))
    }

    /// The number of targets of the last sample; 0 before the first and for a wrong tag.
    /// Webots: `wb_radar_get_number_of_targets`.
    fn wb_radar_get_number_of_targets(tag: WbDeviceTag) -> c_int {
        with_robot(|r| {
            let n = targets(r, "wb_radar_get_number_of_targets", tag).map_or(0, |(_, t)| t.len());
            c_int::try_from(n).unwrap_or(c_int::MAX)
        })
    }

    /// `minRange` (m); 0 for a wrong tag. Webots: `wb_radar_get_min_range`.
    fn wb_radar_get_min_range(tag: WbDeviceTag) -> f64 {
        with_robot(|r| settings(r, "wb_radar_get_min_range", tag).map_or(0.0, |s| s.min_range))
    }

    /// `maxRange` (m); 0 for a wrong tag. Webots: `wb_radar_get_max_range`.
    fn wb_radar_get_max_range(tag: WbDeviceTag) -> f64 {
        with_robot(|r| settings(r, "wb_radar_get_max_range", tag).map_or(0.0, |s| s.max_range))
    }

    /// `horizontalFieldOfView` (rad); 0 for a wrong tag. Webots: `wb_radar_get_horizontal_fov`.
    fn wb_radar_get_horizontal_fov(tag: WbDeviceTag) -> f64 {
        with_robot(|r| {
            settings(r, "wb_radar_get_horizontal_fov", tag)
                .map_or(0.0, |s| s.horizontal_field_of_view)
        })
    }

    /// `verticalFieldOfView` (rad); 0 for a wrong tag. Webots: `wb_radar_get_vertical_fov`.
    fn wb_radar_get_vertical_fov(tag: WbDeviceTag) -> f64 {
        with_robot(|r| {
            settings(r, "wb_radar_get_vertical_fov", tag).map_or(0.0, |s| s.vertical_field_of_view)
        })
    }
}

/// The targets of the last sample, in library storage valid until the next call; NULL before
/// the first sample, when there are none, and for a wrong tag. Webots: `wb_radar_get_targets`.
#[unsafe(no_mangle)]
pub extern "C" fn wb_radar_get_targets(tag: WbDeviceTag) -> *const WbRadarTarget {
    call_pointer("wb_radar_get_targets", || {
        with_robot(|r| {
            let (i, t) = targets(r, "wb_radar_get_targets", tag)?;
            let slot = r.controller_mut().buffers.slot(i)?;
            slot.targets = t;
            (!slot.targets.is_empty()).then_some(slot.targets.as_ptr())
        })
    })
}
