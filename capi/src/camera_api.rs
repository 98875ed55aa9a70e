//! `webots/camera.h` and `webots/camera_recognition_object.h`: the camera and its Recognition,
//! over the engine's cameras (`sim::devices::camera`).
//!
//! `wb_camera_get_image` points at the engine's own image, refreshed in place at each sample
//! (Webots: valid until the next step). The recognition objects point into the robot's
//! storage ([`crate::sensor::Buffers`]), rebuilt by each `wb_camera_recognition_get_objects`
//! call.

use std::ffi::{CStr, CString, c_char, c_int};
use std::path::Path;

use sim::devices::{
    CameraSettings, Device, DeviceKind, DeviceSettings, DisplayImage, PixelFormat,
    RecognitionObject, save_png,
};

use crate::abi::WbDeviceTag;
use crate::guard::call_pointer;
use crate::message;
use crate::robot::Robot;
use crate::sensor::{self, device, find};
use crate::session::with_robot;

/// Webots' `WbCameraRecognitionObject` (LP64: 120 bytes).
#[repr(C)]
#[derive(Debug, Clone, Copy)]
pub struct WbCameraRecognitionObject {
    /// The object's id.
    pub id: c_int,
    /// Its centre (m, camera frame: x forward, y left, z up).
    pub position: [f64; 3],
    /// Its orientation relative to the camera, axis–angle `[x, y, z, angle]` (rad).
    pub orientation: [f64; 4],
    /// Its extent along the camera's y and z (m).
    pub size: [f64; 2],
    /// The centre of its rectangle on the image (px).
    pub position_on_image: [c_int; 2],
    /// The width and height of its rectangle on the image (px).
    pub size_on_image: [c_int; 2],
    /// How many colours `colors` holds.
    pub number_of_colors: c_int,
    /// Its recognition colours, `3 · number_of_colors` values in [0, 1].
    pub colors: *const f64,
    /// Its `model` (NUL-terminated).
    pub model: *const c_char,
}

/// The storage the objects of one camera point into.
#[derive(Debug, Default)]
pub(crate) struct RecognitionStore {
    objects: Vec<WbCameraRecognitionObject>,
    colors: Vec<Box<[f64]>>,
    models: Vec<CString>,
}

// SAFETY: the raw pointers in `objects` point into `colors` and `models`, heap buffers owned
// by the same store and replaced together with `objects` in `fill`; Rust never dereferences
// them, and the store moves between threads only inside the session's mutex, so sending it
// shares nothing that another thread could reach.
unsafe impl Send for RecognitionStore {}

impl RecognitionStore {
    /// Rebuilds the storage from `objects`.
    fn fill(&mut self, objects: &[RecognitionObject]) {
        self.colors = objects
            .iter()
            .map(|o| o.colors.iter().flatten().copied().collect())
            .collect();
        // A NUL inside a model name would end it early in C: cut it there.
        self.models = objects
            .iter()
            .map(|o| {
                let text = o.model.split('\0').next().unwrap_or("");
                CString::new(text).unwrap_or_default()
            })
            .collect();
        self.objects = objects
            .iter()
            .zip(&self.colors)
            .zip(&self.models)
            .map(|((o, colors), model)| WbCameraRecognitionObject {
                id: o.id,
                position: o.position.into(),
                orientation: o.orientation,
                size: o.size,
                position_on_image: o.position_on_image,
                size_on_image: o.size_on_image,
                number_of_colors: c_int::try_from(o.colors.len()).unwrap_or(c_int::MAX),
                colors: colors.as_ptr(),
                model: model.as_ptr(),
            })
            .collect();
    }
}

/// The camera with `tag` for `function` (Webots' messages for a wrong tag).
fn camera<'r>(robot: &'r Robot, tag: WbDeviceTag, function: &str) -> Option<(usize, &'r Device)> {
    let found = find(robot, tag, DeviceKind::Camera, function, true)?;
    device(robot, found).map(|d| (found.1, d))
}

/// The fields of a camera.
fn settings(d: &Device) -> Option<&CameraSettings> {
    match d.settings() {
        DeviceSettings::Camera(s) => Some(s),
        _ => None,
    }
}

/// The camera with `tag` if it has Recognition; else Webots' error for `function`.
fn with_recognition<'r>(
    robot: &'r Robot,
    tag: WbDeviceTag,
    function: &str,
) -> Option<(usize, &'r Device)> {
    let (i, d) = camera(robot, tag, function)?;
    if settings(d)?.recognition.is_none() {
        message::error(format_args!(
            "{function}(): invalid call, the camera has no Recognition node."
        ));
        return None;
    }
    Some((i, d))
}

/// The image of the camera with `tag` (NULL with an error when disabled).
fn image(robot: &Robot, tag: WbDeviceTag) -> Option<*const u8> {
    let function = "wb_camera_get_image";
    let (_, d) = camera(robot, tag, function)?;
    if d.period_ms() == 0 {
        message::error(format_args!(
            "{function}() called for a disabled device! Please use: wb_camera_enable()."
        ));
        return None;
    }
    Some(d.camera()?.image().as_ptr())
}

/// The Rust twins of the getters whose C result is a pointer, for the Python package.
pub mod camera_values {
    use super::*;

    /// [`wb_camera_get_image`](super::wb_camera_get_image): the BGRA bytes (`None` where C
    /// returns NULL).
    pub fn wb_camera_get_image(tag: WbDeviceTag) -> Option<Vec<u8>> {
        with_robot(|r| {
            image(r, tag)?;
            camera(r, tag, "wb_camera_get_image")
                .and_then(|(_, d)| Some(d.camera()?.image().to_vec()))
        })
    }

    /// [`wb_camera_recognition_get_objects`](super::wb_camera_recognition_get_objects): the
    /// objects of the last sample (empty where C returns NULL).
    pub fn wb_camera_recognition_get_objects(tag: WbDeviceTag) -> Vec<RecognitionObject> {
        with_robot(|r| objects(r, tag, "wb_camera_recognition_get_objects").map(<[_]>::to_vec))
            .unwrap_or_default()
    }
}

/// The objects of the camera with `tag` (errors without Recognition or when disabled).
fn objects<'r>(
    robot: &'r Robot,
    tag: WbDeviceTag,
    function: &str,
) -> Option<&'r [RecognitionObject]> {
    let (_, d) = with_recognition(robot, tag, function)?;
    let state = d.camera()?;
    if state.recognition_period_ms() == 0 {
        message::error(format_args!(
            "{function}() called for a disabled device! Please use: \
             wb_camera_recognition_enable()."
        ));
        return None;
    }
    Some(state.objects())
}

/// Enables (or with 0 disables) the Recognition of the camera with `tag`.
fn enable_recognition(robot: &mut Robot, tag: WbDeviceTag, period_ms: c_int, function: &str) {
    let Some(period) = message::sampling_period(period_ms, function) else {
        return;
    };
    let Some(found) = find(robot, tag, DeviceKind::Camera, function, true) else {
        return;
    };
    if with_recognition(robot, tag, function).is_some() {
        // Found on this car, with Recognition: enabling cannot fail.
        let _ = robot
            .simulation
            .enable_recognition(found.0, found.1, period);
    }
}

entry_points! {
    /// Renders an image every `sampling_period` ms. Webots: `wb_camera_enable`.
    fn wb_camera_enable(tag: WbDeviceTag, sampling_period: c_int) {
        with_robot(|r| {
            sensor::enable(r, DeviceKind::Camera, "wb_camera_enable", tag, sampling_period)
        })
    }

    /// Stops rendering. Webots: `wb_camera_disable`.
    fn wb_camera_disable(tag: WbDeviceTag) {
        with_robot(|r| sensor::enable(r, DeviceKind::Camera, "wb_camera_disable", tag, 0))
    }

    /// The camera's period (ms), 0 when disabled. Webots: `wb_camera_get_sampling_period`.
    fn wb_camera_get_sampling_period(tag: WbDeviceTag) -> c_int {
        with_robot(|r| sensor::sampling_period(r, DeviceKind::Camera, tag))
    }

    /// The image width (px); −1 for a wrong tag. Webots: `wb_camera_get_width`.
    fn wb_camera_get_width(tag: WbDeviceTag) -> c_int {
        with_robot(|r| {
            camera(r, tag, "wb_camera_get_width")
                .and_then(|(_, d)| settings(d))
                .map_or(-1, |s| c_int::try_from(s.width).unwrap_or(c_int::MAX))
        })
    }

    /// The image height (px); −1 for a wrong tag. Webots: `wb_camera_get_height`.
    fn wb_camera_get_height(tag: WbDeviceTag) -> c_int {
        with_robot(|r| {
            camera(r, tag, "wb_camera_get_height")
                .and_then(|(_, d)| settings(d))
                .map_or(-1, |s| c_int::try_from(s.height).unwrap_or(c_int::MAX))
        })
    }

    /// The horizontal field of view (rad); NaN for a wrong tag. Webots: `wb_camera_get_fov`.
    fn wb_camera_get_fov(tag: WbDeviceTag) -> f64 {
        with_robot(|r| field(r, tag, "wb_camera_get_fov", |s| s.field_of_view))
    }

    /// The smallest field of view (rad): the field of view, there being no Zoom. Webots:
    /// `wb_camera_get_min_fov`.
    fn wb_camera_get_min_fov(tag: WbDeviceTag) -> f64 {
        with_robot(|r| field(r, tag, "wb_camera_get_min_fov", |s| s.field_of_view))
    }

    /// The largest field of view (rad): the field of view, there being no Zoom. Webots:
    /// `wb_camera_get_max_fov`.
    fn wb_camera_get_max_fov(tag: WbDeviceTag) -> f64 {
        with_robot(|r| field(r, tag, "wb_camera_get_max_fov", |s| s.field_of_view))
    }

    /// The near plane (m); NaN for a wrong tag. Webots: `wb_camera_get_near`.
    fn wb_camera_get_near(tag: WbDeviceTag) -> f64 {
        with_robot(|r| field(r, tag, "wb_camera_get_near", |s| s.near))
    }

    /// True if the camera has a Recognition node. Webots: `wb_camera_has_recognition`.
    fn wb_camera_has_recognition(tag: WbDeviceTag) -> bool {
        with_robot(|r| {
            camera(r, tag, "wb_camera_has_recognition")
                .and_then(|(_, d)| settings(d))
                .is_some_and(|s| s.recognition.is_some())
        })
    }

    /// Recognises objects every `sampling_period` ms (the camera need not be enabled).
    /// Webots: `wb_camera_recognition_enable`.
    fn wb_camera_recognition_enable(tag: WbDeviceTag, sampling_period: c_int) {
        with_robot(|r| enable_recognition(r, tag, sampling_period, "wb_camera_recognition_enable"))
    }

    /// Stops recognising. Webots: `wb_camera_recognition_disable`.
    fn wb_camera_recognition_disable(tag: WbDeviceTag) {
        with_robot(|r| enable_recognition(r, tag, 0, "wb_camera_recognition_disable"))
    }

    /// Recognition's period (ms), 0 when disabled or without Recognition. Webots:
    /// `wb_camera_recognition_get_sampling_period`.
    fn wb_camera_recognition_get_sampling_period(tag: WbDeviceTag) -> c_int {
        with_robot(|r| {
            with_recognition(r, tag, "wb_camera_recognition_get_sampling_period")
                .and_then(|(_, d)| d.camera())
                .map_or(0, |c| c_int::try_from(c.recognition_period_ms()).unwrap_or(c_int::MAX))
        })
    }

    /// How many objects the last sample recognised; 0 with an error without Recognition or
    /// when disabled. Webots: `wb_camera_recognition_get_number_of_objects`.
    fn wb_camera_recognition_get_number_of_objects(tag: WbDeviceTag) -> c_int {
        with_robot(|r| {
            objects(r, tag, "wb_camera_recognition_get_number_of_objects")
                .map_or(0, |o| c_int::try_from(o.len()).unwrap_or(c_int::MAX))
        })
    }

    /// False: no segmentation image is rendered. Webots:
    /// `wb_camera_recognition_has_segmentation`.
    fn wb_camera_recognition_has_segmentation(tag: WbDeviceTag) -> bool {
        with_robot(|r| {
            with_recognition(r, tag, "wb_camera_recognition_has_segmentation");
            false
        })
    }
}

/// A field of the camera with `tag`; NaN for a wrong tag.
fn field(robot: &Robot, tag: WbDeviceTag, function: &str, get: fn(&CameraSettings) -> f64) -> f64 {
    camera(robot, tag, function)
        .and_then(|(_, d)| settings(d))
        .map_or(f64::NAN, get)
}

/// The last image: BGRA, 4 bytes a pixel, row-major from the top-left; NULL for a wrong tag
/// and (with an error) while disabled. Valid until the next step. Webots:
/// `wb_camera_get_image`.
#[unsafe(no_mangle)]
pub extern "C" fn wb_camera_get_image(tag: WbDeviceTag) -> *const u8 {
    call_pointer("wb_camera_get_image", || with_robot(|r| image(r, tag)))
}

/// The objects of Recognition's last sample (`wb_camera_recognition_get_number_of_objects`
/// of them); NULL with an error without Recognition or when disabled. Valid until the next
/// call. Webots: `wb_camera_recognition_get_objects`.
#[unsafe(no_mangle)]
pub extern "C" fn wb_camera_recognition_get_objects(
    tag: WbDeviceTag,
) -> *const WbCameraRecognitionObject {
    call_pointer("wb_camera_recognition_get_objects", || {
        with_robot(|r| {
            let function = "wb_camera_recognition_get_objects";
            let (index, _) = with_recognition(r, tag, function)?;
            let objects = objects(r, tag, function)?.to_vec();
            let store = r.controller_mut().buffers.recognition(index)?;
            store.fill(&objects);
            Some(store.objects.as_ptr())
        })
    })
}

/// Saves the last image of the camera with `tag` as the PNG file `filename`; returns 0, or −1
/// with an error (a wrong tag, a disabled camera, another extension than `.png`, a file that
/// cannot be written). `quality` is for JPEG, which is not written here. Webots:
/// `wb_camera_save_image`.
///
/// # Safety
/// `filename` is null or points to a NUL-terminated string valid during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn wb_camera_save_image(
    tag: WbDeviceTag,
    filename: *const c_char,
    quality: c_int,
) -> c_int {
    let name = if filename.is_null() {
        None
    } else {
        // SAFETY: non-null, and the caller guarantees a NUL-terminated string valid for the
        // duration of the call; it is only read.
        Some(
            unsafe { CStr::from_ptr(filename) }
                .to_string_lossy()
                .into_owned(),
        )
    };
    crate::guard::call("wb_camera_save_image", move || {
        let _ = quality;
        with_robot(|r| save_image(r, tag, name.as_deref()))
    })
}

/// [`wb_camera_save_image`]'s work: 0 or −1.
pub(crate) fn save_image(robot: &Robot, tag: WbDeviceTag, filename: Option<&str>) -> c_int {
    let function = "wb_camera_save_image";
    let Some((_, d)) = camera(robot, tag, function) else {
        return -1;
    };
    let (Some(s), Some(state)) = (settings(d), d.camera()) else {
        return -1;
    };
    if d.period_ms() == 0 {
        message::error(format_args!(
            "{function}() called for a disabled device! Please use: wb_camera_enable()."
        ));
        return -1;
    }
    let Some(filename) = filename else {
        message::error(format_args!("{function}(): NULL filename."));
        return -1;
    };
    let image = DisplayImage::from_bytes(s.width, s.height, state.image(), PixelFormat::Bgra);
    match image.map(|i| save_png(Path::new(filename), &i)) {
        Some(Ok(())) => 0,
        Some(Err(e)) => {
            message::error(format_args!("{function}(): {e}."));
            -1
        }
        None => -1,
    }
}
