//! `webots/lidar.h`: the lidar functions, over the engine's `Lidar` (`sim::devices`). The
//! point cloud is the range image converted, computed when asked for.

use std::ffi::c_int;

use sim::devices::{Device, DeviceKind, DeviceSettings, LidarPoint, LidarSettings, Reading};

use crate::abi::WbDeviceTag;
use crate::guard::call_pointer;
use crate::message;
use crate::robot::Robot;
use crate::sensor::{self, device, find};
use crate::session::with_robot;

const KIND: DeviceKind = DeviceKind::Lidar;

/// The lidar with `tag` (Webots' messages for a wrong tag), its index and fields.
fn lidar<'a>(
    robot: &'a Robot,
    function: &str,
    tag: WbDeviceTag,
) -> Option<(usize, &'a Device, &'a LidarSettings)> {
    let found = find(robot, tag, KIND, function, true)?;
    let d = device(robot, found)?;
    match d.settings() {
        DeviceSettings::Lidar(s) => Some((found.1, d, s)),
        _ => None,
    }
}

/// Webots' error for a getter of a disabled lidar.
fn disabled(function: &str) {
    message::error(format_args!(
        "{function}() called for a disabled device! Please use: wb_lidar_enable()."
    ));
}

/// The lidar's range image (m); a disabled lidar prints Webots' error and still gives it.
fn range_image(robot: &Robot, function: &str, tag: WbDeviceTag) -> Option<(usize, Vec<f32>)> {
    let (i, d, _) = lidar(robot, function, tag)?;
    if d.period_ms() == 0 {
        disabled(function);
    }
    match d.reading() {
        Reading::Lidar(r) => Some((i, r.range_image.clone())),
        _ => None,
    }
}

/// The checks of the layer getters: the lidar enabled, `layer` one of its layers. Returns the
/// lidar's index, device and fields.
fn layer_of<'a>(
    robot: &'a Robot,
    function: &str,
    tag: WbDeviceTag,
    layer: c_int,
) -> Option<(usize, &'a Device, &'a LidarSettings)> {
    let (i, d, s) = lidar(robot, function, tag)?;
    if d.period_ms() == 0 {
        disabled(function);
        return None;
    }
    let layers = s.number_of_layers;
    if layer < 0 {
        message::error(format_args!(
            "{function}() called with a negative 'layer' argument."
        ));
        return None;
    }
    if u32::try_from(layer).is_ok_and(|l| l >= layers) {
        message::error(format_args!(
            "{function}() called with a 'layer' argument ({layer}) bigger or equal to the number \
             of layers of this lidar ({layers})."
        ));
        return None;
    }
    Some((i, d, s))
}

/// The lidar's point cloud, after Webots' checks (cloud enabled, lidar enabled).
fn point_cloud(
    robot: &Robot,
    function: &str,
    tag: WbDeviceTag,
) -> Option<(usize, Vec<LidarPoint>)> {
    let (i, d, _) = lidar(robot, function, tag)?;
    if !d.point_cloud_enabled() {
        message::error(format_args!(
            "{function}() called for a lidar with point cloud disabled. Please use: \
             wb_lidar_enable_point_cloud()."
        ));
        return None;
    }
    if d.period_ms() == 0 {
        disabled(function);
        return None;
    }
    d.point_cloud().map(|c| (i, c))
}

/// The Rust twins of the pointer getters, for the Python package: the same checks and
/// messages, the values as vectors (`None` where C returns NULL).
pub mod lidar_values {
    use super::*;

    /// [`wb_lidar_get_range_image`](super::wb_lidar_get_range_image) (m).
    pub fn range_image(tag: WbDeviceTag) -> Option<Vec<f32>> {
        with_robot(|r| super::range_image(r, "wb_lidar_get_range_image", tag)).map(|(_, v)| v)
    }

    /// [`wb_lidar_get_layer_range_image`](super::wb_lidar_get_layer_range_image) (m).
    pub fn layer_range_image(tag: WbDeviceTag, layer: c_int) -> Option<Vec<f32>> {
        let function = "wb_lidar_get_layer_range_image";
        with_robot(|r| {
            let (_, d, s) = layer_of(r, function, tag, layer)?;
            let Reading::Lidar(reading) = d.reading() else {
                return None;
            };
            let hres = s.horizontal_resolution as usize;
            let start = usize::try_from(layer).ok()? * hres;
            reading
                .range_image
                .get(start..start + hres)
                .map(<[f32]>::to_vec)
        })
    }

    /// [`wb_lidar_get_point_cloud`](super::wb_lidar_get_point_cloud) (m).
    pub fn point_cloud(tag: WbDeviceTag) -> Option<Vec<LidarPoint>> {
        with_robot(|r| super::point_cloud(r, "wb_lidar_get_point_cloud", tag)).map(|(_, c)| c)
    }

    /// [`wb_lidar_get_layer_point_cloud`](super::wb_lidar_get_layer_point_cloud) (m).
    pub fn layer_point_cloud(tag: WbDeviceTag, layer: c_int) -> Option<Vec<LidarPoint>> {
        let function = "wb_lidar_get_layer_point_cloud";
        with_robot(|r| {
            let (_, _, s) = layer_of(r, function, tag, layer)?;
            let hres = s.horizontal_resolution as usize;
            let (_, cloud) = super::point_cloud(r, function, tag)?;
            let start = usize::try_from(layer).ok()? * hres;
            cloud.get(start..start + hres).map(<[LidarPoint]>::to_vec)
        })
    }
}

/// A field of the lidar with `tag` for `function`, `fallback` for a wrong tag.
fn field(
    tag: WbDeviceTag,
    function: &str,
    fallback: f64,
    get: impl Fn(&LidarSettings) -> f64,
) -> f64 {
    with_robot(|r| lidar(r, function, tag).map_or(fallback, |(_, _, s)| get(s)))
}

entry_points! {
    /// Samples the lidar every `sampling_period` ms. Webots: `wb_lidar_enable`.
    fn wb_lidar_enable(tag: WbDeviceTag, sampling_period: c_int) {
        with_robot(|r| sensor::enable(r, KIND, "wb_lidar_enable", tag, sampling_period))
    }

    /// Stops sampling the lidar. Webots: `wb_lidar_disable`.
    fn wb_lidar_disable(tag: WbDeviceTag) {
        with_robot(|r| sensor::enable(r, KIND, "wb_lidar_disable", tag, 0))
    }

    /// The lidar's period (ms), 0 when disabled. Webots: `wb_lidar_get_sampling_period`.
    fn wb_lidar_get_sampling_period(tag: WbDeviceTag) -> c_int {
        with_robot(|r| sensor::sampling_period(r, KIND, tag))
    }

    /// Turns the point cloud on (computed from each range image while the lidar is enabled).
    /// Webots: `wb_lidar_enable_point_cloud`.
    fn wb_lidar_enable_point_cloud(tag: WbDeviceTag) {
        with_robot(|r| set_point_cloud(r, "wb_lidar_enable_point_cloud", tag, true))
    }

    /// Turns the point cloud off. Webots: `wb_lidar_disable_point_cloud`.
    fn wb_lidar_disable_point_cloud(tag: WbDeviceTag) {
        with_robot(|r| set_point_cloud(r, "wb_lidar_disable_point_cloud", tag, false))
    }

    /// True if the point cloud is on; false for a wrong tag. Webots:
    /// `wb_lidar_is_point_cloud_enabled`.
    fn wb_lidar_is_point_cloud_enabled(tag: WbDeviceTag) -> bool {
        with_robot(|r| {
            lidar(r, "wb_lidar_is_point_cloud_enabled", tag)
                .is_some_and(|(_, d, _)| d.point_cloud_enabled())
        })
    }

    /// `horizontalResolution · numberOfLayers` while the lidar and its point cloud are
    /// enabled; else Webots' error and 0. Webots: `wb_lidar_get_number_of_points`.
    fn wb_lidar_get_number_of_points(tag: WbDeviceTag) -> c_int {
        with_robot(|r| {
            let f = "wb_lidar_get_number_of_points";
            let Some((_, d, s)) = lidar(r, f, tag) else {
                return 0;
            };
            if !d.point_cloud_enabled() {
                message::error(format_args!(
                    "{f}() called for a lidar with point cloud disabled! Please use: \
                     wb_lidar_enable_point_cloud()."
                ));
                return 0;
            }
            if d.period_ms() == 0 {
                disabled(f);
                return 0;
            }
            c_int::try_from(s.number_of_points()).unwrap_or(c_int::MAX)
        })
    }

    /// `horizontalResolution`; 0 for a wrong tag (Webots converts a NaN, undefined in C).
    /// Webots: `wb_lidar_get_horizontal_resolution`.
    fn wb_lidar_get_horizontal_resolution(tag: WbDeviceTag) -> c_int {
        with_robot(|r| {
            lidar(r, "wb_lidar_get_horizontal_resolution", tag).map_or(0, |(_, _, s)| {
                c_int::try_from(s.horizontal_resolution).unwrap_or(c_int::MAX)
            })
        })
    }

    /// `numberOfLayers`; 0 for a wrong tag. Webots: `wb_lidar_get_number_of_layers`.
    fn wb_lidar_get_number_of_layers(tag: WbDeviceTag) -> c_int {
        with_robot(|r| {
            lidar(r, "wb_lidar_get_number_of_layers", tag).map_or(0, |(_, _, s)| {
                c_int::try_from(s.number_of_layers).unwrap_or(c_int::MAX)
            })
        })
    }

    /// The frequency (Hz): `defaultFrequency` until set; NaN for a wrong tag. Webots:
    /// `wb_lidar_get_frequency`.
    fn wb_lidar_get_frequency(tag: WbDeviceTag) -> f64 {
        with_robot(|r| {
            let index = lidar(r, "wb_lidar_get_frequency", tag).map(|(i, _, _)| i);
            index
                .and_then(|i| r.controller_mut().buffers.slot(i))
                .map_or(f64::NAN, |s| s.frequency)
        })
    }

    /// Sets the frequency (Hz) within [`minFrequency`, `maxFrequency`]; outside, Webots' error
    /// and nothing changes. A fixed lidar samples at its sampling period whatever the
    /// frequency. Webots: `wb_lidar_set_frequency`.
    fn wb_lidar_set_frequency(tag: WbDeviceTag, frequency: f64) {
        with_robot(|r| {
            let f = "wb_lidar_set_frequency";
            let Some((i, _, s)) = lidar(r, f, tag) else {
                return;
            };
            let (lo, hi) = (s.min_frequency, s.max_frequency);
            if !(frequency >= lo && frequency <= hi) {
                message::error(format_args!("{f}() out of frequency range [{lo:.6}, {hi:.6}]."));
                return;
            }
            if let Some(slot) = r.controller_mut().buffers.slot(i) {
                slot.frequency = frequency;
            }
        })
    }

    /// `minFrequency` (Hz); NaN for a wrong tag. Webots: `wb_lidar_get_min_frequency`.
    fn wb_lidar_get_min_frequency(tag: WbDeviceTag) -> f64 {
        field(tag, "wb_lidar_get_min_frequency", f64::NAN, |s| s.min_frequency)
    }

    /// `maxFrequency` (Hz); NaN for a wrong tag. Webots: `wb_lidar_get_max_frequency`.
    fn wb_lidar_get_max_frequency(tag: WbDeviceTag) -> f64 {
        field(tag, "wb_lidar_get_max_frequency", f64::NAN, |s| s.max_frequency)
    }

    /// `fieldOfView` (rad); NaN for a wrong tag. Webots: `wb_lidar_get_fov`.
    fn wb_lidar_get_fov(tag: WbDeviceTag) -> f64 {
        field(tag, "wb_lidar_get_fov", f64::NAN, |s| s.field_of_view)
    }

    /// `verticalFieldOfView` (rad); NaN for a wrong tag. Webots: `wb_lidar_get_vertical_fov`.
    fn wb_lidar_get_vertical_fov(tag: WbDeviceTag) -> f64 {
        field(tag, "wb_lidar_get_vertical_fov", f64::NAN, |s| s.vertical_field_of_view)
    }

    /// `minRange` (m); NaN for a wrong tag. Webots: `wb_lidar_get_min_range`.
    fn wb_lidar_get_min_range(tag: WbDeviceTag) -> f64 {
        field(tag, "wb_lidar_get_min_range", f64::NAN, |s| s.min_range)
    }

    /// `maxRange` (m); NaN for a wrong tag. Webots: `wb_lidar_get_max_range`.
    fn wb_lidar_get_max_range(tag: WbDeviceTag) -> f64 {
        field(tag, "wb_lidar_get_max_range", f64::NAN, |s| s.max_range)
    }
}

/// Turns the point cloud of the lidar with `tag` on or off.
fn set_point_cloud(robot: &mut Robot, function: &str, tag: WbDeviceTag, on: bool) {
    if let Some((car, index)) = find(robot, tag, KIND, function, true) {
        // The lidar was found on this car: the call cannot fail.
        let _ = robot.simulation.enable_point_cloud(car, index, on);
    }
}

/// The range image (m, `horizontalResolution · numberOfLayers` values, layer 0 first), in
/// library storage valid until the next call; NULL for a wrong tag. Webots:
/// `wb_lidar_get_range_image`.
#[unsafe(no_mangle)]
pub extern "C" fn wb_lidar_get_range_image(tag: WbDeviceTag) -> *const f32 {
    call_pointer("wb_lidar_get_range_image", || {
        with_robot(|r| {
            let (i, image) = range_image(r, "wb_lidar_get_range_image", tag)?;
            let slot = r.controller_mut().buffers.slot(i)?;
            slot.range_image = image;
            Some(slot.range_image.as_ptr())
        })
    })
}

/// The range image of `layer` (m, `horizontalResolution` values); NULL with Webots' error if
/// the lidar is disabled or has no such layer. Webots: `wb_lidar_get_layer_range_image`.
#[unsafe(no_mangle)]
pub extern "C" fn wb_lidar_get_layer_range_image(tag: WbDeviceTag, layer: c_int) -> *const f32 {
    let function = "wb_lidar_get_layer_range_image";
    call_pointer(function, || {
        with_robot(|r| {
            let (i, d, s) = layer_of(r, function, tag, layer)?;
            let Reading::Lidar(reading) = d.reading() else {
                return None;
            };
            let image = reading.range_image.clone();
            let offset = usize::try_from(layer).ok()? * s.horizontal_resolution as usize;
            let slot = r.controller_mut().buffers.slot(i)?;
            slot.range_image = image;
            slot.range_image.get(offset..).map(<[f32]>::as_ptr)
        })
    })
}

/// The point cloud (`WbLidarPoint`s, layer 0 first), in library storage valid until the next
/// call; NULL with Webots' error if the lidar or its cloud is disabled. Webots:
/// `wb_lidar_get_point_cloud`.
#[unsafe(no_mangle)]
pub extern "C" fn wb_lidar_get_point_cloud(tag: WbDeviceTag) -> *const LidarPoint {
    call_pointer("wb_lidar_get_point_cloud", || {
        with_robot(|r| {
            let (i, cloud) = point_cloud(r, "wb_lidar_get_point_cloud", tag)?;
            let slot = r.controller_mut().buffers.slot(i)?;
            slot.point_cloud = cloud;
            Some(slot.point_cloud.as_ptr())
        })
    })
}

/// The points of `layer`; NULL with Webots' error as [`wb_lidar_get_point_cloud`] and for a
/// layer the lidar does not have. Webots: `wb_lidar_get_layer_point_cloud`.
#[unsafe(no_mangle)]
pub extern "C" fn wb_lidar_get_layer_point_cloud(
    tag: WbDeviceTag,
    layer: c_int,
) -> *const LidarPoint {
    let function = "wb_lidar_get_layer_point_cloud";
    call_pointer(function, || {
        with_robot(|r| {
            let (_, _, s) = layer_of(r, function, tag, layer)?;
            let offset = usize::try_from(layer).ok()? * s.horizontal_resolution as usize;
            let (i, cloud) = point_cloud(r, function, tag)?;
            let slot = r.controller_mut().buffers.slot(i)?;
            slot.point_cloud = cloud;
            slot.point_cloud.get(offset..).map(<[LidarPoint]>::as_ptr)
        })
    })
}
