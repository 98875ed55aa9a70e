//! `WebotsNative`, display part: `wb_display_*` for `com.cyberbotics.webots.controller.Display`.
//! Pixels (px) from the top-left corner, colours `0xRRGGBB`, alpha and opacity in [0, 1].
//!
//! Image references (`WbImageRef`) cross to Java as `long`s, the C pointer's value: the C API
//! hands out table keys, never memory, so a Java `ImageRef` holds nothing to free or misuse.
//! Java arrays and strings are copied into Rust buffers that live for the one C call.

use std::ffi::c_void;

use jni::JNIEnv;
use jni::objects::{JIntArray, JString};
use jni::sys::{jboolean, jdouble, jint, jlong};

use crate::{c_ptr, c_string, tag};

natives! { "com_cyberbotics_webots_controller_WebotsNative";
    /// `wb_display_get_width` (px; -1 for a wrong tag).
    fn displayGetWidth(env, device: jint) -> jint => car::wb_display_get_width(tag(device));
    /// `wb_display_get_height` (px; -1 for a wrong tag).
    fn displayGetHeight(env, device: jint) -> jint => car::wb_display_get_height(tag(device));
    /// `wb_display_set_color` (`0xRRGGBB`).
    fn displaySetColor(env, device: jint, color: jint) => car::wb_display_set_color(tag(device), color);
    /// `wb_display_set_alpha` (0 transparent to 1 opaque).
    fn displaySetAlpha(env, device: jint, alpha: jdouble) => car::wb_display_set_alpha(tag(device), alpha);
    /// `wb_display_set_opacity` (the weight of new pixels, 0 to 1).
    fn displaySetOpacity(env, device: jint, opacity: jdouble) => car::wb_display_set_opacity(tag(device), opacity);
    /// `wb_display_set_font`: family, character height (px), anti-aliasing.
    fn displaySetFont(env, device: jint, font: JString<'_>, size: jint, anti_aliasing: jboolean) => {
        let font = c_string(&mut env, &font);
        // SAFETY: NULL or a NUL-terminated string that lives until the call returns.
        unsafe { car::wb_display_set_font(tag(device), c_ptr(font.as_ref()), size, anti_aliasing != 0) }
    };
    /// `wb_display_draw_text`: `text` with its top-left corner at (x, y) (px).
    fn displayDrawText(env, device: jint, text: JString<'_>, x: jint, y: jint) => {
        let text = c_string(&mut env, &text);
        // SAFETY: NULL or a NUL-terminated string that lives until the call returns.
        unsafe { car::wb_display_draw_text(tag(device), c_ptr(text.as_ref()), x, y) }
    };
    /// `wb_display_draw_pixel` (px).
    fn displayDrawPixel(env, device: jint, x: jint, y: jint) => car::wb_display_draw_pixel(tag(device), x, y);
    /// `wb_display_draw_line` (px).
    fn displayDrawLine(env, device: jint, x1: jint, y1: jint, x2: jint, y2: jint) =>
        car::wb_display_draw_line(tag(device), x1, y1, x2, y2);
    /// `wb_display_draw_rectangle`: top-left corner, width, height (px).
    fn displayDrawRectangle(env, device: jint, x: jint, y: jint, width: jint, height: jint) =>
        car::wb_display_draw_rectangle(tag(device), x, y, width, height);
    /// `wb_display_fill_rectangle`: top-left corner, width, height (px).
    fn displayFillRectangle(env, device: jint, x: jint, y: jint, width: jint, height: jint) =>
        car::wb_display_fill_rectangle(tag(device), x, y, width, height);
    /// `wb_display_draw_oval`: centre and radii (px).
    fn displayDrawOval(env, device: jint, cx: jint, cy: jint, a: jint, b: jint) =>
        car::wb_display_draw_oval(tag(device), cx, cy, a, b);
    /// `wb_display_fill_oval`: centre and radii (px).
    fn displayFillOval(env, device: jint, cx: jint, cy: jint, a: jint, b: jint) =>
        car::wb_display_fill_oval(tag(device), cx, cy, a, b);
    /// `wb_display_draw_polygon` of the first `size` corners (px; `Display` checks the lengths).
    fn displayDrawPolygon(env, device: jint, x: JIntArray<'_>, y: JIntArray<'_>, size: jint) => {
        let (xs, ys) = (ints(&mut env, &x), ints(&mut env, &y));
        let size = corners(&xs, &ys, size);
        // SAFETY: both buffers hold at least `size` ints and live until the call returns.
        unsafe { car::wb_display_draw_polygon(tag(device), xs.as_ptr(), ys.as_ptr(), size) }
    };
    /// `wb_display_fill_polygon` of the first `size` corners (px; `Display` checks the lengths).
    fn displayFillPolygon(env, device: jint, x: JIntArray<'_>, y: JIntArray<'_>, size: jint) => {
        let (xs, ys) = (ints(&mut env, &x), ints(&mut env, &y));
        let size = corners(&xs, &ys, size);
        // SAFETY: both buffers hold at least `size` ints and live until the call returns.
        unsafe { car::wb_display_fill_polygon(tag(device), xs.as_ptr(), ys.as_ptr(), size) }
    };
    /// `wb_display_image_new` from one `int` per pixel: the format's bytes are the int's,
    /// most significant first (`ARGB`: `0xAARRGGBB`, a camera pixel; `RGB`: `0x00RRGGBB`);
    /// 0 (Java `null`) where C returns NULL. An unknown format reaches the C API, which refuses
    /// it with its error.
    fn displayImageNew(env, device: jint, width: jint, height: jint, data: JIntArray<'_>, format: jint) -> jlong => {
        let pixels = ints(&mut env, &data);
        let bytes = pixel_bytes(&pixels, format);
        // `Display.imageNew` throws before passing fewer than width · height pixels; should
        // any caller still do so, the C API gets NULL data (and returns NULL) rather than a
        // short buffer.
        let wanted = usize::try_from(width).unwrap_or(0).checked_mul(usize::try_from(height).unwrap_or(0));
        let data = if wanted.is_some_and(|n| pixels.len() >= n) {
            bytes.as_ptr().cast::<c_void>()
        } else {
            std::ptr::null()
        };
        // SAFETY: NULL, or `bytes`, which holds at least width · height pixels of `format`
        // (the C API reads nothing for an unknown format) and lives until the call returns.
        let image = unsafe { car::wb_display_image_new(tag(device), width, height, data, format) };
        image as jlong
    };
    /// `wb_display_image_copy` of a rectangle (px); 0 where C returns NULL.
    fn displayImageCopy(env, device: jint, x: jint, y: jint, width: jint, height: jint) -> jlong =>
        car::wb_display_image_copy(tag(device), x, y, width, height) as jlong;
    /// `wb_display_image_paste` with the image's top-left corner at (x, y) (px).
    fn displayImagePaste(env, device: jint, image: jlong, x: jint, y: jint, blend: jboolean) =>
        car::wb_display_image_paste(tag(device), image_ref(image), x, y, blend != 0);
    /// `wb_display_image_delete`.
    fn displayImageDelete(env, device: jint, image: jlong) =>
        car::wb_display_image_delete(tag(device), image_ref(image));
    /// `wb_display_image_save` as a PNG file (image 0: the display itself).
    fn displayImageSave(env, device: jint, image: jlong, filename: JString<'_>) => {
        let filename = c_string(&mut env, &filename);
        // SAFETY: NULL or a NUL-terminated string that lives until the call returns.
        unsafe { car::wb_display_image_save(tag(device), image_ref(image), c_ptr(filename.as_ref())) }
    };
    /// `wb_display_image_load` of a PNG file; 0 where C returns NULL.
    fn displayImageLoad(env, device: jint, filename: JString<'_>) -> jlong => {
        let filename = c_string(&mut env, &filename);
        // SAFETY: NULL or a NUL-terminated string that lives until the call returns.
        unsafe { car::wb_display_image_load(tag(device), c_ptr(filename.as_ref())) as jlong }
    };
}

/// A Java `long` back as the C API's image reference (a table key, never dereferenced).
fn image_ref(image: jlong) -> car::WbImageRef {
    image as car::WbImageRef
}

/// A copy of a Java `int[]` (empty for `null`).
fn ints(env: &mut JNIEnv<'_>, array: &JIntArray<'_>) -> Vec<jint> {
    if array.is_null() {
        return Vec::new();
    }
    let len = env
        .get_array_length(array)
        .ok()
        .and_then(|n| usize::try_from(n).ok())
        .unwrap_or(0);
    let mut values = vec![0; len];
    if env.get_int_array_region(array, 0, &mut values).is_err() {
        values.clear();
    }
    values
}

/// The corners the C API may read: `size`, or fewer if an array is shorter (never past a
/// buffer's end; `Display` throws before that happens).
fn corners(xs: &[jint], ys: &[jint], size: jint) -> jint {
    let held = jint::try_from(xs.len().min(ys.len())).unwrap_or(jint::MAX);
    size.min(held)
}

/// The bytes of `pixels` in `format` (`WB_IMAGE_RGB` 3 bytes a pixel, `RGBA` … `ABGR` 4):
/// each int's bytes most significant first, its top byte dropped for RGB; none for an unknown
/// format.
fn pixel_bytes(pixels: &[jint], format: jint) -> Vec<u8> {
    const RGB: jint = 3;
    const ABGR: jint = 7;
    match format {
        RGB => pixels
            .iter()
            .flat_map(|p| {
                let [_, r, g, b] = p.to_be_bytes();
                [r, g, b]
            })
            .collect(),
        f if f > RGB && f <= ABGR => pixels.iter().flat_map(|p| p.to_be_bytes()).collect(),
        _ => Vec::new(),
    }
}
