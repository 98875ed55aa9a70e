//! The display functions of the Webots C API (`webots/display.h`) for the Python `controller`
//! module: the C entry points themselves, image handles passed as integers.

use std::ffi::c_void;

use pyo3::prelude::*;

/// Width and height (px); −1 for a wrong tag.
#[pyfunction]
fn wb_display_get_size(tag: u16) -> (i32, i32) {
    (
        car::wb_display_get_width(tag),
        car::wb_display_get_height(tag),
    )
}

/// Sets the colour (`0xRRGGBB`).
#[pyfunction]
fn wb_display_set_color(tag: u16, color: i32) {
    car::wb_display_set_color(tag, color);
}

/// Sets the alpha (in [0, 1]).
#[pyfunction]
fn wb_display_set_alpha(tag: u16, alpha: f64) {
    car::wb_display_set_alpha(tag, alpha);
}

/// Sets the opacity (in [0, 1]).
#[pyfunction]
fn wb_display_set_opacity(tag: u16, opacity: f64) {
    car::wb_display_set_opacity(tag, opacity);
}

/// Draws `shape` ("pixel", "line", "rectangle", "fill_rectangle", "oval", "fill_oval") with
/// its integer arguments (2 for a pixel, 4 for the others).
#[pyfunction]
fn wb_display_draw(tag: u16, shape: &str, args: Vec<i32>) -> PyResult<()> {
    let bad = || {
        pyo3::exceptions::PyValueError::new_err(format!(
            "{shape} with {} arguments: not a drawing",
            args.len()
        ))
    };
    match (shape, args.as_slice()) {
        ("pixel", &[x, y]) => car::wb_display_draw_pixel(tag, x, y),
        ("line", &[a, b, c, d]) => car::wb_display_draw_line(tag, a, b, c, d),
        ("rectangle", &[a, b, c, d]) => car::wb_display_draw_rectangle(tag, a, b, c, d),
        ("fill_rectangle", &[a, b, c, d]) => car::wb_display_fill_rectangle(tag, a, b, c, d),
        ("oval", &[a, b, c, d]) => car::wb_display_draw_oval(tag, a, b, c, d),
        ("fill_oval", &[a, b, c, d]) => car::wb_display_fill_oval(tag, a, b, c, d),
        _ => return Err(bad()),
    }
    Ok(())
}

/// Draws (or with `fill` fills) the polygon of corners (`x[i]`, `y[i]`).
#[pyfunction]
fn wb_display_polygon(tag: u16, x: Vec<i32>, y: Vec<i32>, fill: bool) {
    let n = i32::try_from(x.len().min(y.len())).unwrap_or(i32::MAX);
    // SAFETY: both vectors hold at least `n` ints and outlive the call.
    #[allow(unsafe_code)]
    unsafe {
        if fill {
            car::wb_display_fill_polygon(tag, x.as_ptr(), y.as_ptr(), n);
        } else {
            car::wb_display_draw_polygon(tag, x.as_ptr(), y.as_ptr(), n);
        }
    }
}

/// A new image from `data` (`width · height` pixels of `format`); 0 (NULL) if refused.
#[pyfunction]
fn wb_display_image_new(tag: u16, width: i32, height: i32, data: Vec<u8>, format: i32) -> usize {
    let needed = usize::try_from(width).unwrap_or(0)
        * usize::try_from(height).unwrap_or(0)
        * if format == 3 { 3 } else { 4 };
    if data.len() < needed {
        return 0;
    }
    // SAFETY: `data` holds `width · height` pixels of `format` (checked above) and outlives
    // the call.
    #[allow(unsafe_code)]
    let image = unsafe {
        car::wb_display_image_new(tag, width, height, data.as_ptr().cast::<c_void>(), format)
    };
    image as usize
}

/// A copy of a rectangle of the display; 0 (NULL) off the display.
#[pyfunction]
fn wb_display_image_copy(tag: u16, x: i32, y: i32, width: i32, height: i32) -> usize {
    car::wb_display_image_copy(tag, x, y, width, height) as usize
}

/// Pastes image `image` at (x, y).
#[pyfunction]
fn wb_display_image_paste(tag: u16, image: usize, x: i32, y: i32, blend: bool) {
    car::wb_display_image_paste(tag, image as car::WbImageRef, x, y, blend);
}

/// Deletes image `image`.
#[pyfunction]
fn wb_display_image_delete(tag: u16, image: usize) {
    car::wb_display_image_delete(tag, image as car::WbImageRef);
}

/// Saves image `image` (0: the display itself) as a PNG file.
#[pyfunction]
fn wb_display_image_save(tag: u16, image: usize, filename: &str) {
    let Ok(name) = std::ffi::CString::new(filename) else {
        return;
    };
    // SAFETY: `name` is a NUL-terminated string that outlives the call.
    #[allow(unsafe_code)]
    unsafe {
        car::wb_display_image_save(tag, image as car::WbImageRef, name.as_ptr());
    }
}

/// The image of a PNG file; 0 (NULL) with Webots' error if it cannot be read.
#[pyfunction]
fn wb_display_image_load(tag: u16, filename: &str) -> usize {
    let Ok(name) = std::ffi::CString::new(filename) else {
        return 0;
    };
    // SAFETY: `name` is a NUL-terminated string that outlives the call.
    #[allow(unsafe_code)]
    let image = unsafe { car::wb_display_image_load(tag, name.as_ptr()) };
    image as usize
}

/// `s` as a C string; a `ValueError` naming `what` if it holds a NUL character.
fn c_string(s: &str, what: &str) -> PyResult<std::ffi::CString> {
    std::ffi::CString::new(s).map_err(|_| {
        pyo3::exceptions::PyValueError::new_err(format!("{what} {s:?} holds a NUL character"))
    })
}

/// Sets the font (one of Webots' 13 families, size in px > 0); Webots' error otherwise.
#[pyfunction]
fn wb_display_set_font(tag: u16, font: &str, size: i32, anti_aliasing: bool) -> PyResult<()> {
    let font = c_string(font, "font")?;
    // SAFETY: `font` is a NUL-terminated string that outlives the call.
    #[allow(unsafe_code)]
    unsafe {
        car::wb_display_set_font(tag, font.as_ptr(), size, anti_aliasing);
    }
    Ok(())
}

/// Draws `text` with its top-left corner at (`x`, `y`) (px).
#[pyfunction]
fn wb_display_draw_text(tag: u16, text: &str, x: i32, y: i32) -> PyResult<()> {
    let text = c_string(text, "text")?;
    // SAFETY: `text` is a NUL-terminated string that outlives the call.
    #[allow(unsafe_code)]
    unsafe {
        car::wb_display_draw_text(tag, text.as_ptr(), x, y);
    }
    Ok(())
}

/// Adds the display functions to the module.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(wb_display_get_size, m)?)?;
    m.add_function(wrap_pyfunction!(wb_display_set_color, m)?)?;
    m.add_function(wrap_pyfunction!(wb_display_set_alpha, m)?)?;
    m.add_function(wrap_pyfunction!(wb_display_set_opacity, m)?)?;
    m.add_function(wrap_pyfunction!(wb_display_draw, m)?)?;
    m.add_function(wrap_pyfunction!(wb_display_polygon, m)?)?;
    m.add_function(wrap_pyfunction!(wb_display_set_font, m)?)?;
    m.add_function(wrap_pyfunction!(wb_display_draw_text, m)?)?;
    m.add_function(wrap_pyfunction!(wb_display_image_new, m)?)?;
    m.add_function(wrap_pyfunction!(wb_display_image_copy, m)?)?;
    m.add_function(wrap_pyfunction!(wb_display_image_paste, m)?)?;
    m.add_function(wrap_pyfunction!(wb_display_image_delete, m)?)?;
    m.add_function(wrap_pyfunction!(wb_display_image_save, m)?)?;
    m.add_function(wrap_pyfunction!(wb_display_image_load, m)?)?;
    Ok(())
}
