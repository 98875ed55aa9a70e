//! `webots/display.h`: drawing into a car's `Display` (`sim::devices::display`).
//!
//! Images (`WbImageRef`) are handles into the robot's table of images, never dereferenced
//! memory: a handle is its key, cast to a pointer, so a stale or forged one finds nothing.
//! Images are saved to and loaded from PNG files. Text draws with a bitmap font
//! (`sim::devices::display`'s `text`); camera attachment is not available (the crate README).

use std::ffi::{CStr, c_char, c_int, c_void};
use std::path::Path;

use sim::devices::{DeviceKind, Display, DisplayImage, PixelFormat, load_png, save_png};

use crate::abi::WbDeviceTag;
use crate::message;
use crate::robot::Robot;
use crate::sensor::find;
use crate::session::with_robot;

/// `WbImageRef`: an opaque handle.
pub type WbImageRef = *mut c_void;

/// The robot's images by handle.
#[derive(Debug, Default)]
pub(crate) struct Images {
    next: usize,
    held: Vec<(usize, DisplayImage)>,
}

impl Images {
    /// Holds `image`; its handle (never 0, so never NULL as a pointer).
    fn insert(&mut self, image: DisplayImage) -> usize {
        self.next += 1;
        self.held.push((self.next, image));
        self.next
    }

    fn get(&self, handle: usize) -> Option<&DisplayImage> {
        self.held.iter().find(|(k, _)| *k == handle).map(|(_, i)| i)
    }

    fn remove(&mut self, handle: usize) -> bool {
        let before = self.held.len();
        self.held.retain(|(k, _)| *k != handle);
        self.held.len() != before
    }
}

/// The display with `tag`, for `function` (Webots' messages for a wrong tag).
fn display<'r>(robot: &'r mut Robot, tag: WbDeviceTag, function: &str) -> Option<&'r mut Display> {
    let (car, index) = find(robot, tag, DeviceKind::Display, function, true)?;
    robot.simulation.display_mut(car, index).ok()
}

/// Runs `draw` on the display with `tag`.
fn draw(tag: WbDeviceTag, function: &str, draw: impl FnOnce(&mut Display)) {
    with_robot(|r| {
        if let Some(d) = display(r, tag, function) {
            draw(d);
        }
    });
}

/// `count` ints at `p` (none if null or `count` ≤ 0).
///
/// # Safety
/// `p` is null or points to `count` readable ints.
unsafe fn ints<'a>(p: *const c_int, count: c_int) -> &'a [c_int] {
    match usize::try_from(count) {
        // SAFETY: non-null, and the caller guarantees `count` readable ints.
        Ok(n) if !p.is_null() && n > 0 => unsafe { std::slice::from_raw_parts(p, n) },
        _ => &[],
    }
}

entry_points! {
    /// The display's width (px); −1 for a wrong tag. Webots: `wb_display_get_width`.
    fn wb_display_get_width(tag: WbDeviceTag) -> c_int {
        with_robot(|r| {
            display(r, tag, "wb_display_get_width")
                .map_or(-1, |d| c_int::try_from(d.image().width).unwrap_or(c_int::MAX))
        })
    }

    /// The display's height (px); −1 for a wrong tag. Webots: `wb_display_get_height`.
    fn wb_display_get_height(tag: WbDeviceTag) -> c_int {
        with_robot(|r| {
            display(r, tag, "wb_display_get_height")
                .map_or(-1, |d| c_int::try_from(d.image().height).unwrap_or(c_int::MAX))
        })
    }

    /// The drawing colour, `0xRRGGBB` (refused with an error outside 0 to 0xFFFFFF). Webots:
    /// `wb_display_set_color`.
    fn wb_display_set_color(tag: WbDeviceTag, color: c_int) {
        draw(tag, "wb_display_set_color", |d| {
            if d.set_color(i64::from(color)).is_err() {
                message::error("wb_display_set_color(): color must be in [0, 0xFFFFFF].");
            }
        })
    }

    /// The alpha of what is drawn, in [0, 1] (0: transparent). Webots: `wb_display_set_alpha`.
    fn wb_display_set_alpha(tag: WbDeviceTag, alpha: f64) {
        draw(tag, "wb_display_set_alpha", |d| {
            if d.set_alpha(alpha).is_err() {
                message::error("wb_display_set_alpha(): alpha must be in [0, 1].");
            }
        })
    }

    /// The opacity of what is drawn, in [0, 1]. Webots: `wb_display_set_opacity`.
    fn wb_display_set_opacity(tag: WbDeviceTag, opacity: f64) {
        draw(tag, "wb_display_set_opacity", |d| {
            if d.set_opacity(opacity).is_err() {
                message::error("wb_display_set_opacity(): opacity must be in [0, 1].");
            }
        })
    }

    /// Draws pixel (x, y). Webots: `wb_display_draw_pixel`.
    fn wb_display_draw_pixel(tag: WbDeviceTag, x: c_int, y: c_int) {
        draw(tag, "wb_display_draw_pixel", |d| d.draw_pixel(x, y))
    }

    /// Draws a line (Bresenham). Webots: `wb_display_draw_line`.
    fn wb_display_draw_line(tag: WbDeviceTag, x1: c_int, y1: c_int, x2: c_int, y2: c_int) {
        draw(tag, "wb_display_draw_line", |d| d.draw_line(x1, y1, x2, y2))
    }

    /// Draws a rectangle's outline, top-left (x, y). Webots: `wb_display_draw_rectangle`.
    fn wb_display_draw_rectangle(tag: WbDeviceTag, x: c_int, y: c_int, width: c_int, height: c_int) {
        draw(tag, "wb_display_draw_rectangle", |d| d.draw_rectangle(x, y, width, height))
    }

    /// Fills a rectangle, top-left (x, y). Webots: `wb_display_fill_rectangle`.
    fn wb_display_fill_rectangle(tag: WbDeviceTag, x: c_int, y: c_int, width: c_int, height: c_int) {
        draw(tag, "wb_display_fill_rectangle", |d| d.fill_rectangle(x, y, width, height))
    }

    /// Draws an ellipse's outline of centre (cx, cy), radii a, b. Webots: `wb_display_draw_oval`.
    fn wb_display_draw_oval(tag: WbDeviceTag, cx: c_int, cy: c_int, a: c_int, b: c_int) {
        draw(tag, "wb_display_draw_oval", |d| d.draw_oval(cx, cy, a, b))
    }

    /// Fills an ellipse of centre (cx, cy), radii a, b. Webots: `wb_display_fill_oval`.
    fn wb_display_fill_oval(tag: WbDeviceTag, cx: c_int, cy: c_int, a: c_int, b: c_int) {
        draw(tag, "wb_display_fill_oval", |d| d.fill_oval(cx, cy, a, b))
    }
}

/// A handle as the C pointer type.
fn as_ref(handle: usize) -> WbImageRef {
    handle as WbImageRef
}

/// A copy of a rectangle of the display; NULL if it is off the display. Webots:
/// `wb_display_image_copy`.
#[unsafe(no_mangle)]
pub extern "C" fn wb_display_image_copy(
    tag: WbDeviceTag,
    x: c_int,
    y: c_int,
    width: c_int,
    height: c_int,
) -> WbImageRef {
    let handle = crate::guard::call("wb_display_image_copy", move || {
        with_robot(|r| {
            let copy = display(r, tag, "wb_display_image_copy")?.copy(x, y, width, height)?;
            Some(r.controller_mut().images.insert(copy))
        })
        .unwrap_or(0)
    });
    as_ref(handle)
}

/// Draws the closed polygon of the `size` corners (`x[i]`, `y[i]`). Webots:
/// `wb_display_draw_polygon`.
///
/// # Safety
/// `x` and `y` are null or point to `size` readable ints.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn wb_display_draw_polygon(
    tag: WbDeviceTag,
    x: *const c_int,
    y: *const c_int,
    size: c_int,
) {
    // SAFETY: the caller's guarantee, passed on.
    let (xs, ys) = unsafe { (ints(x, size), ints(y, size)) };
    crate::guard::call("wb_display_draw_polygon", move || {
        draw(tag, "wb_display_draw_polygon", |d| d.draw_polygon(xs, ys))
    })
}

/// Fills the polygon of the `size` corners (`x[i]`, `y[i]`). Webots: `wb_display_fill_polygon`.
///
/// # Safety
/// `x` and `y` are null or point to `size` readable ints.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn wb_display_fill_polygon(
    tag: WbDeviceTag,
    x: *const c_int,
    y: *const c_int,
    size: c_int,
) {
    // SAFETY: the caller's guarantee, passed on.
    let (xs, ys) = unsafe { (ints(x, size), ints(y, size)) };
    crate::guard::call("wb_display_fill_polygon", move || {
        draw(tag, "wb_display_fill_polygon", |d| d.fill_polygon(xs, ys))
    })
}

/// A new image of `width` × `height` from `data` in `format` (`WB_IMAGE_RGB` … `ABGR`); NULL
/// with an error for an unknown format or a null `data`. Webots: `wb_display_image_new`.
///
/// # Safety
/// `data` is null or points to `width · height` pixels of `format`.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn wb_display_image_new(
    tag: WbDeviceTag,
    width: c_int,
    height: c_int,
    data: *const c_void,
    format: c_int,
) -> WbImageRef {
    let Some(f) = PixelFormat::from_code(format) else {
        crate::guard::call("wb_display_image_new", || {
            message::error(format_args!(
                "wb_display_image_new(): unknown image format {format}."
            ));
        });
        return std::ptr::null_mut();
    };
    let (Ok(w), Ok(h)) = (u32::try_from(width), u32::try_from(height)) else {
        return std::ptr::null_mut();
    };
    let bytes = (w as usize)
        .checked_mul(h as usize)
        .and_then(|n| n.checked_mul(f.bytes()))
        .unwrap_or(0);
    if data.is_null() || bytes == 0 {
        return std::ptr::null_mut();
    }
    // SAFETY: non-null, and the caller guarantees `width · height` pixels of `format`.
    let data = unsafe { std::slice::from_raw_parts(data.cast::<u8>(), bytes) };
    let handle = crate::guard::call("wb_display_image_new", move || {
        with_robot(|r| {
            display(r, tag, "wb_display_image_new")?;
            let image = DisplayImage::from_bytes(w, h, data, f)?;
            Some(r.controller_mut().images.insert(image))
        })
        .unwrap_or(0)
    });
    as_ref(handle)
}

/// Pastes `image` with its top-left pixel at (x, y), over what is there by its alpha if
/// `blend`. Webots: `wb_display_image_paste`.
#[unsafe(no_mangle)]
pub extern "C" fn wb_display_image_paste(
    tag: WbDeviceTag,
    image: WbImageRef,
    x: c_int,
    y: c_int,
    blend: bool,
) {
    let handle = image as usize;
    crate::guard::call("wb_display_image_paste", move || {
        with_robot(|r| {
            let Some(image) = r.controller().images.get(handle).cloned() else {
                message::error("wb_display_image_paste(): invalid image reference.");
                return;
            };
            if let Some(d) = display(r, tag, "wb_display_image_paste") {
                d.paste(&image, x, y, blend);
            }
        })
    })
}

/// Frees `image`. Webots: `wb_display_image_delete`.
#[unsafe(no_mangle)]
pub extern "C" fn wb_display_image_delete(tag: WbDeviceTag, image: WbImageRef) {
    let handle = image as usize;
    crate::guard::call("wb_display_image_delete", move || {
        with_robot(|r| {
            if display(r, tag, "wb_display_image_delete").is_some()
                && !r.controller_mut().images.remove(handle)
            {
                message::error("wb_display_image_delete(): invalid image reference.");
            }
        })
    })
}

/// Sets the font: `font` one of Webots' 13 families (all draw with the same bitmap font),
/// `size` the character height (px, > 0); `anti_aliasing` changes nothing on a bitmap font.
/// A null or unknown family or a size ≤ 0 is refused with an error. Webots:
/// `wb_display_set_font`.
///
/// # Safety
/// `font` is null or points to a NUL-terminated string valid during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn wb_display_set_font(
    tag: WbDeviceTag,
    font: *const c_char,
    size: c_int,
    anti_aliasing: bool,
) {
    // SAFETY: the caller's guarantee, passed on.
    let font = unsafe { text(font) };
    crate::guard::call("wb_display_set_font", move || {
        draw(tag, "wb_display_set_font", |d| {
            let set = match &font {
                Some(f) => d
                    .set_font(f, size, anti_aliasing)
                    .map_err(|e| e.to_string()),
                None => Err("NULL font".to_string()),
            };
            if let Err(e) = set {
                message::error(format!("wb_display_set_font(): {e}."));
            }
        })
    })
}

/// Draws `text` with its top-left corner at (`x`, `y`) in the font and the drawing colour,
/// alpha and opacity (nothing for a null `text`). Webots: `wb_display_draw_text`.
///
/// # Safety
/// `text` is null or points to a NUL-terminated string valid during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn wb_display_draw_text(
    tag: WbDeviceTag,
    text: *const c_char,
    x: c_int,
    y: c_int,
) {
    // SAFETY: the caller's guarantee, passed on.
    let text = unsafe { self::text(text) };
    crate::guard::call("wb_display_draw_text", move || {
        draw(tag, "wb_display_draw_text", |d| {
            if let Some(t) = &text {
                d.draw_text(t, x, y);
            }
        })
    })
}

/// The string at `p` (`None` if null).
///
/// # Safety
/// `p` is null or points to a NUL-terminated string valid during the call.
unsafe fn text(p: *const c_char) -> Option<String> {
    // SAFETY: non-null, and the caller guarantees a NUL-terminated string; it is only read.
    (!p.is_null()).then(|| unsafe { CStr::from_ptr(p) }.to_string_lossy().into_owned())
}

/// Saves `image` (NULL: the display itself) as the PNG file `filename`; an error for another
/// extension or a file that cannot be written. Webots: `wb_display_image_save`.
///
/// # Safety
/// `filename` is null or points to a NUL-terminated string valid during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn wb_display_image_save(
    tag: WbDeviceTag,
    image: WbImageRef,
    filename: *const c_char,
) {
    let handle = image as usize;
    // SAFETY: the caller's guarantee, passed on.
    let name = unsafe { text(filename) };
    crate::guard::call("wb_display_image_save", move || {
        with_robot(|r| {
            let function = "wb_display_image_save";
            let Some(whole) = display(r, tag, function).map(|d| d.image().clone()) else {
                return;
            };
            let picture = if handle == 0 {
                whole
            } else if let Some(i) = r.controller().images.get(handle) {
                i.clone()
            } else {
                message::error("wb_display_image_save(): invalid image reference.");
                return;
            };
            let Some(name) = name else {
                message::error("wb_display_image_save(): NULL filename.");
                return;
            };
            if let Err(e) = save_png(Path::new(&name), &picture) {
                message::error(format_args!("{function}(): {e}."));
            }
        })
    })
}

/// The image of the PNG file `filename`; NULL with an error if it cannot be read. Webots:
/// `wb_display_image_load`.
///
/// # Safety
/// `filename` is null or points to a NUL-terminated string valid during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn wb_display_image_load(
    tag: WbDeviceTag,
    filename: *const c_char,
) -> WbImageRef {
    // SAFETY: the caller's guarantee, passed on.
    let name = unsafe { text(filename) };
    let handle = crate::guard::call("wb_display_image_load", move || {
        with_robot(|r| {
            let function = "wb_display_image_load";
            display(r, tag, function)?;
            let Some(name) = name else {
                message::error("wb_display_image_load(): NULL filename.");
                return None;
            };
            match load_png(Path::new(&name)) {
                Ok(image) => Some(r.controller_mut().images.insert(image)),
                Err(e) => {
                    message::error(format_args!("{function}(): {e}."));
                    None
                }
            }
        })
        .unwrap_or(0)
    });
    as_ref(handle)
}
