//! The camera functions of the Webots C API (`webots/camera.h`) for the Python `controller`
//! module. Scalar functions are the C entry points; the image and the recognised objects come
//! from the C API's Rust twins (`car::camera_values`), which print the same messages. The
//! rendering is the engine's (`sim::devices::camera`).

use pyo3::prelude::*;
use pyo3::types::PyBytes;

/// Renders every `period` ms (0 disables; negative: Webots' error).
#[pyfunction]
fn wb_camera_enable(tag: u16, period: i32) {
    car::wb_camera_enable(tag, period);
}

/// The camera's period (ms), 0 when disabled.
#[pyfunction]
fn wb_camera_get_sampling_period(tag: u16) -> i32 {
    car::wb_camera_get_sampling_period(tag)
}

/// The last image as BGRA bytes, `None` for a wrong tag or while disabled.
#[pyfunction]
fn wb_camera_get_image(py: Python<'_>, tag: u16) -> Option<Py<PyBytes>> {
    car::camera_values::wb_camera_get_image(tag).map(|b| PyBytes::new(py, &b).unbind())
}

/// Width, height (px); −1 for a wrong tag.
#[pyfunction]
fn wb_camera_get_size(tag: u16) -> (i32, i32) {
    (
        car::wb_camera_get_width(tag),
        car::wb_camera_get_height(tag),
    )
}

/// Field of view, its minimum and maximum (rad), near plane (m).
#[pyfunction]
fn wb_camera_get_optics(tag: u16) -> (f64, f64, f64, f64) {
    (
        car::wb_camera_get_fov(tag),
        car::wb_camera_get_min_fov(tag),
        car::wb_camera_get_max_fov(tag),
        car::wb_camera_get_near(tag),
    )
}

/// Saves the last image as a PNG file: 0, or −1 with Webots' error.
#[pyfunction]
fn wb_camera_save_image(tag: u16, filename: &str, quality: i32) -> i32 {
    let Ok(name) = std::ffi::CString::new(filename) else {
        return -1;
    };
    // SAFETY: `name` is a NUL-terminated string that outlives the call.
    #[allow(unsafe_code)]
    unsafe {
        car::wb_camera_save_image(tag, name.as_ptr(), quality)
    }
}

/// True if the camera has Recognition.
#[pyfunction]
fn wb_camera_has_recognition(tag: u16) -> bool {
    car::wb_camera_has_recognition(tag)
}

/// Recognises every `period` ms (0 disables).
#[pyfunction]
fn wb_camera_recognition_enable(tag: u16, period: i32) {
    car::wb_camera_recognition_enable(tag, period);
}

/// Recognition's period (ms).
#[pyfunction]
fn wb_camera_recognition_get_sampling_period(tag: u16) -> i32 {
    car::wb_camera_recognition_get_sampling_period(tag)
}

/// The number of objects recognised.
#[pyfunction]
fn wb_camera_recognition_get_number_of_objects(tag: u16) -> i32 {
    car::wb_camera_recognition_get_number_of_objects(tag)
}

/// One recognised object: id, position (m), orientation (axis–angle), size (m), position and
/// size on the image (px), colours, model.
type Object = (
    i32,
    [f64; 3],
    [f64; 4],
    [f64; 2],
    [i32; 2],
    [i32; 2],
    Vec<[f64; 3]>,
    String,
);

/// The recognised objects as tuples (empty, with Webots' error, when Recognition is off).
#[pyfunction]
fn wb_camera_recognition_get_objects(tag: u16) -> Vec<Object> {
    car::camera_values::wb_camera_recognition_get_objects(tag)
        .into_iter()
        .map(|o| {
            (
                o.id,
                o.position.into(),
                o.orientation,
                o.size,
                o.position_on_image,
                o.size_on_image,
                o.colors,
                o.model,
            )
        })
        .collect()
}

/// False: no segmentation image.
#[pyfunction]
fn wb_camera_recognition_has_segmentation(tag: u16) -> bool {
    car::wb_camera_recognition_has_segmentation(tag)
}

/// Adds the camera functions to the module.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(wb_camera_enable, m)?)?;
    m.add_function(wrap_pyfunction!(wb_camera_get_sampling_period, m)?)?;
    m.add_function(wrap_pyfunction!(wb_camera_get_image, m)?)?;
    m.add_function(wrap_pyfunction!(wb_camera_get_size, m)?)?;
    m.add_function(wrap_pyfunction!(wb_camera_get_optics, m)?)?;
    m.add_function(wrap_pyfunction!(wb_camera_save_image, m)?)?;
    m.add_function(wrap_pyfunction!(wb_camera_has_recognition, m)?)?;
    m.add_function(wrap_pyfunction!(wb_camera_recognition_enable, m)?)?;
    m.add_function(wrap_pyfunction!(
        wb_camera_recognition_get_sampling_period,
        m
    )?)?;
    m.add_function(wrap_pyfunction!(
        wb_camera_recognition_get_number_of_objects,
        m
    )?)?;
    m.add_function(wrap_pyfunction!(wb_camera_recognition_get_objects, m)?)?;
    m.add_function(wrap_pyfunction!(wb_camera_recognition_has_segmentation, m)?)?;
    Ok(())
}
