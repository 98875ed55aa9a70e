//! Webots' `Display` (spec §10): an image a controller draws into, for headless runs.
//!
//! Pixels are ARGB (`0xAARRGGBB`), `(0, 0)` top-left, opaque black at first. Every drawing
//! writes its pixels with the context's colour, alpha and opacity as Webots' simulator does
//! (integers): `c = ((255 − O)·c_old + O·c_draw) / 255` per RGB channel and
//! `a = ((255 − O)·a_old + O·A) / 255`, with `O = (u8)(opacity·255)` and `A = (u8)(alpha·255)`
//! (truncated); pixels off the image are skipped. Calls take effect at once (Webots queues
//! them until the next step: only a copy taken in the same step as a drawing differs).

mod text;

use crate::error::ParamError;
pub use text::{FONT_FAMILIES, FontError};

/// The largest display side (px).
pub const MAX_SIDE: u32 = 4096;

/// The fields of a `Display` node, with Webots' defaults ([`Default`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct DisplaySettings {
    /// `width` (px, 1 to [`MAX_SIDE`]; default 64).
    pub width: u32,
    /// `height` (px, 1 to [`MAX_SIDE`]; default 64).
    pub height: u32,
}

impl Default for DisplaySettings {
    fn default() -> Self {
        DisplaySettings {
            width: 64,
            height: 64,
        }
    }
}

impl DisplaySettings {
    /// Checks the sides.
    ///
    /// # Errors
    /// A [`ParamError`] naming `width` or `height`.
    pub fn validate(&self) -> Result<(), ParamError> {
        for (field, side) in [("width", self.width), ("height", self.height)] {
            ParamError::check(field, f64::from(side), "from 1 to 4096 px", |s| {
                (1.0..=f64::from(MAX_SIDE)).contains(&s)
            })?;
        }
        Ok(())
    }
}

/// The pixel formats of `wb_display_image_new` (`WB_IMAGE_*`).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum PixelFormat {
    /// `WB_IMAGE_RGB` (3): opaque.
    Rgb = 3,
    /// `WB_IMAGE_RGBA` (4).
    Rgba = 4,
    /// `WB_IMAGE_ARGB` (5).
    Argb = 5,
    /// `WB_IMAGE_BGRA` (6): the camera's.
    Bgra = 6,
    /// `WB_IMAGE_ABGR` (7).
    Abgr = 7,
}

impl PixelFormat {
    /// The format of Webots' code `code`.
    pub fn from_code(code: i32) -> Option<PixelFormat> {
        [
            PixelFormat::Rgb,
            PixelFormat::Rgba,
            PixelFormat::Argb,
            PixelFormat::Bgra,
            PixelFormat::Abgr,
        ]
        .into_iter()
        .find(|f| *f as i32 == code)
    }

    /// Bytes per pixel.
    pub fn bytes(self) -> usize {
        if self == PixelFormat::Rgb { 3 } else { 4 }
    }

    /// The ARGB of one pixel's bytes `p`.
    fn argb(self, p: &[u8]) -> u32 {
        let [r, g, b, a] = match self {
            PixelFormat::Rgb => [p[0], p[1], p[2], 255],
            PixelFormat::Rgba => [p[0], p[1], p[2], p[3]],
            PixelFormat::Argb => [p[1], p[2], p[3], p[0]],
            PixelFormat::Bgra => [p[2], p[1], p[0], p[3]],
            PixelFormat::Abgr => [p[3], p[2], p[1], p[0]],
        };
        u32::from_be_bytes([a, r, g, b])
    }
}

/// An image held apart from the display (`WbImageRef`): ARGB pixels, row-major.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct DisplayImage {
    /// Width (px).
    pub width: u32,
    /// Height (px).
    pub height: u32,
    /// ARGB pixels, row-major from the top-left.
    pub pixels: Vec<u32>,
}

impl DisplayImage {
    /// An image of `width` × `height` from `data` in `format`; `None` if `data` is shorter
    /// than that or a side is 0 or above [`MAX_SIDE`].
    pub fn from_bytes(width: u32, height: u32, data: &[u8], format: PixelFormat) -> Option<Self> {
        let n = usize::try_from(u64::from(width) * u64::from(height)).ok()?;
        if width == 0 || height == 0 || width > MAX_SIDE || height > MAX_SIDE {
            return None;
        }
        let bytes = data.get(..n * format.bytes())?;
        Some(DisplayImage {
            width,
            height,
            pixels: bytes
                .chunks_exact(format.bytes())
                .map(|p| format.argb(p))
                .collect(),
        })
    }

    /// The pixels as RGBA bytes (for a PNG).
    pub fn rgba(&self) -> Vec<u8> {
        self.pixels
            .iter()
            .flat_map(|p| {
                let [a, r, g, b] = p.to_be_bytes();
                [r, g, b, a]
            })
            .collect()
    }
}

/// A display's image and drawing context.
#[derive(Debug, Clone)]
pub struct Display {
    image: DisplayImage,
    /// `0xRRGGBB`.
    color: u32,
    /// `O`: opacity·255, truncated.
    opacity: u8,
    /// `A`: alpha·255, truncated.
    alpha: u8,
    /// The font of [`Display::draw_text`].
    font: text::Font,
}

impl Display {
    /// A display of `settings`: opaque black, colour white, alpha and opacity 1.
    pub fn new(settings: &DisplaySettings) -> Self {
        let n = settings.width as usize * settings.height as usize;
        Display {
            image: DisplayImage {
                width: settings.width,
                height: settings.height,
                pixels: vec![0xFF00_0000; n],
            },
            color: 0xFF_FFFF,
            opacity: 255,
            alpha: 255,
            font: text::Font::default(),
        }
    }

    /// The image.
    pub fn image(&self) -> &DisplayImage {
        &self.image
    }

    /// The ARGB pixel at (`x`, `y`), `None` off the image.
    pub fn pixel(&self, x: i32, y: i32) -> Option<u32> {
        self.index(x, y).map(|k| self.image.pixels[k])
    }

    fn index(&self, x: i32, y: i32) -> Option<usize> {
        let (x, y) = (u32::try_from(x).ok()?, u32::try_from(y).ok()?);
        (x < self.image.width && y < self.image.height)
            .then(|| y as usize * self.image.width as usize + x as usize)
    }

    /// Sets the colour (`0xRRGGBB`).
    ///
    /// # Errors
    /// A [`ParamError`] naming `color` outside 0 to 0xFFFFFF.
    pub fn set_color(&mut self, color: i64) -> Result<(), ParamError> {
        ParamError::check("color", color as f64, "from 0 to 0xFFFFFF", |c| {
            (0.0..=f64::from(0xFF_FFFF)).contains(&c)
        })?;
        self.color = color as u32;
        Ok(())
    }

    /// Sets the alpha (in [0, 1]; 0: transparent).
    ///
    /// # Errors
    /// A [`ParamError`] naming `alpha` outside [0, 1].
    pub fn set_alpha(&mut self, alpha: f64) -> Result<(), ParamError> {
        ParamError::check("alpha", alpha, "in [0, 1]", |a| (0.0..=1.0).contains(&a))?;
        self.alpha = (alpha * 255.0) as u8;
        Ok(())
    }

    /// Sets the opacity (in [0, 1]: the weight of what is drawn against what was there).
    ///
    /// # Errors
    /// A [`ParamError`] naming `opacity` outside [0, 1].
    pub fn set_opacity(&mut self, opacity: f64) -> Result<(), ParamError> {
        ParamError::check("opacity", opacity, "in [0, 1]", |o| {
            (0.0..=1.0).contains(&o)
        })?;
        self.opacity = (opacity * 255.0) as u8;
        Ok(())
    }

    /// Draws pixel (`x`, `y`) with the context.
    pub fn draw_pixel(&mut self, x: i32, y: i32) {
        let Some(k) = self.index(x, y) else {
            return;
        };
        let o = u32::from(self.opacity);
        let blend = |old: u32, new: u32| ((255 - o) * old + o * new) / 255;
        let [a0, r0, g0, b0] = self.image.pixels[k].to_be_bytes().map(u32::from);
        let [_, r, g, b] = self.color.to_be_bytes().map(u32::from);
        let channels = [
            blend(a0, u32::from(self.alpha)),
            blend(r0, r),
            blend(g0, g),
            blend(b0, b),
        ];
        // Each blend of two bytes with weights summing to 255, divided by 255, is a byte.
        self.image.pixels[k] = u32::from_be_bytes(channels.map(|c| c as u8));
    }

    /// Draws the segment from (`x1`, `y1`) to (`x2`, `y2`) (Bresenham, both ends included).
    pub fn draw_line(&mut self, x1: i32, y1: i32, x2: i32, y2: i32) {
        let (x1, y1, x2, y2) = (i64::from(x1), i64::from(y1), i64::from(x2), i64::from(y2));
        let (dx, dy) = ((x2 - x1).abs(), -(y2 - y1).abs());
        let (sx, sy) = (if x1 < x2 { 1 } else { -1 }, if y1 < y2 { 1 } else { -1 });
        let (mut x, mut y, mut err) = (x1, y1, dx + dy);
        loop {
            if let (Ok(px), Ok(py)) = (i32::try_from(x), i32::try_from(y)) {
                self.draw_pixel(px, py);
            }
            if x == x2 && y == y2 {
                break;
            }
            let e2 = 2 * err;
            if e2 >= dy {
                err += dy;
                x += sx;
            }
            if e2 <= dx {
                err += dx;
                y += sy;
            }
        }
    }

    /// Draws the outline of the `width` × `height` rectangle whose top-left pixel is
    /// (`x`, `y`).
    pub fn draw_rectangle(&mut self, x: i32, y: i32, width: i32, height: i32) {
        if width <= 0 || height <= 0 {
            return;
        }
        let (x2, y2) = (x.saturating_add(width - 1), y.saturating_add(height - 1));
        self.draw_line(x, y, x2, y);
        if y2 != y {
            self.draw_line(x, y2, x2, y2);
        }
        if height > 2 {
            self.draw_line(x, y + 1, x, y2 - 1);
            if x2 != x {
                self.draw_line(x2, y + 1, x2, y2 - 1);
            }
        }
    }

    /// Fills the `width` × `height` rectangle whose top-left pixel is (`x`, `y`).
    pub fn fill_rectangle(&mut self, x: i32, y: i32, width: i32, height: i32) {
        let (w, h) = (self.image.width as i32, self.image.height as i32);
        let (x0, y0) = (x.max(0), y.max(0));
        let (x1, y1) = (
            x.saturating_add(width).min(w),
            y.saturating_add(height).min(h),
        );
        for py in y0..y1 {
            for px in x0..x1 {
                self.draw_pixel(px, py);
            }
        }
    }

    /// The pixels (`x`, `y`) of the ellipse of centre (`cx`, `cy`) and radii `a`, `b` whose
    /// row spans are inside it: for each row, the first and last column.
    fn oval_rows(cx: i32, cy: i32, a: i32, b: i32) -> Vec<(i32, i32, i32)> {
        if a < 0 || b < 0 {
            return Vec::new();
        }
        let (a, b) = (f64::from(a), f64::from(b));
        let mut rows = Vec::new();
        for dy in -(b as i32)..=(b as i32) {
            // Half-width of the row: x²/a² + y²/b² ≤ 1.
            let t = if b == 0.0 {
                1.0
            } else {
                1.0 - (f64::from(dy) / b).powi(2)
            };
            let half = (a * t.max(0.0).sqrt()).round() as i32;
            rows.push((cy + dy, cx - half, cx + half));
        }
        rows
    }

    /// Draws the outline of the ellipse of centre (`cx`, `cy`) and radii `a` (x), `b` (y)
    /// (px).
    pub fn draw_oval(&mut self, cx: i32, cy: i32, a: i32, b: i32) {
        let rows = Self::oval_rows(cx, cy, a, b);
        // Join each row's ends to the next row's, so that the outline has no gaps.
        for pair in rows.windows(2) {
            let ((y0, l0, r0), (y1, l1, r1)) = (pair[0], pair[1]);
            self.draw_line(l0, y0, l1, y1);
            self.draw_line(r0, y0, r1, y1);
        }
        if let (Some(&(y, l, r)), Some(&(y_last, l_last, r_last))) = (rows.first(), rows.last()) {
            self.draw_line(l, y, r, y);
            if y_last != y {
                self.draw_line(l_last, y_last, r_last, y_last);
            }
        }
    }

    /// Fills the ellipse of centre (`cx`, `cy`) and radii `a` (x), `b` (y) (px).
    pub fn fill_oval(&mut self, cx: i32, cy: i32, a: i32, b: i32) {
        for (y, l, r) in Self::oval_rows(cx, cy, a, b) {
            for x in l..=r {
                self.draw_pixel(x, y);
            }
        }
    }

    /// Draws the closed polygon of corners (`xs[i]`, `ys[i]`).
    pub fn draw_polygon(&mut self, xs: &[i32], ys: &[i32]) {
        let n = xs.len().min(ys.len());
        for i in 0..n {
            let j = (i + 1) % n;
            self.draw_line(xs[i], ys[i], xs[j], ys[j]);
        }
    }

    /// Fills the polygon of corners (`xs[i]`, `ys[i]`): the pixels whose centres are inside
    /// it (even–odd rule).
    pub fn fill_polygon(&mut self, xs: &[i32], ys: &[i32]) {
        let n = xs.len().min(ys.len());
        if n < 3 {
            return;
        }
        let lo = ys[..n].iter().copied().min().unwrap_or(0).max(0);
        let hi = ys[..n]
            .iter()
            .copied()
            .max()
            .unwrap_or(-1)
            .min(self.image.height as i32 - 1);
        for y in lo..=hi {
            let yc = f64::from(y) + 0.5;
            let mut crossings: Vec<f64> = Vec::new();
            for i in 0..n {
                let j = (i + 1) % n;
                let (x0, y0, x1, y1) = (
                    f64::from(xs[i]) + 0.5,
                    f64::from(ys[i]) + 0.5,
                    f64::from(xs[j]) + 0.5,
                    f64::from(ys[j]) + 0.5,
                );
                if (y0 <= yc) != (y1 <= yc) {
                    crossings.push(x0 + (yc - y0) * (x1 - x0) / (y1 - y0));
                }
            }
            crossings.sort_by(f64::total_cmp);
            for pair in crossings.chunks_exact(2) {
                // Pixel x is inside when its centre x + 0.5 is within the span.
                let first = (pair[0] - 0.5).ceil() as i32;
                let last = (pair[1] - 0.5).floor() as i32;
                for x in first..=last {
                    self.draw_pixel(x, y);
                }
            }
        }
    }

    /// A copy of the `width` × `height` rectangle whose top-left pixel is (`x`, `y`), clipped
    /// to the display; `None` if nothing of it is on the display.
    pub fn copy(&self, x: i32, y: i32, width: i32, height: i32) -> Option<DisplayImage> {
        let (w, h) = (self.image.width as i32, self.image.height as i32);
        let (x0, y0) = (x.max(0), y.max(0));
        let (x1, y1) = (
            x.saturating_add(width).min(w),
            y.saturating_add(height).min(h),
        );
        if x0 >= x1 || y0 >= y1 {
            return None;
        }
        let mut pixels = Vec::with_capacity(((x1 - x0) * (y1 - y0)) as usize);
        for py in y0..y1 {
            for px in x0..x1 {
                pixels.push(self.pixel(px, py)?);
            }
        }
        Some(DisplayImage {
            width: (x1 - x0) as u32,
            height: (y1 - y0) as u32,
            pixels,
        })
    }

    /// Pastes `image` with its top-left pixel at (`x`, `y`): copied as it is, or with `blend`
    /// laid over what is there by its alpha (`c = (a·c_img + (255 − a)·c_old) / 255`, the
    /// result's alpha `a + (255 − a)·a_old / 255`).
    pub fn paste(&mut self, image: &DisplayImage, x: i32, y: i32, blend: bool) {
        for iy in 0..image.height as i32 {
            for ix in 0..image.width as i32 {
                let Some(k) = self.index(x.saturating_add(ix), y.saturating_add(iy)) else {
                    continue;
                };
                let src = image.pixels[(iy * image.width as i32 + ix) as usize];
                self.image.pixels[k] = if blend {
                    let [a, r, g, b] = src.to_be_bytes().map(u32::from);
                    let [a0, r0, g0, b0] = self.image.pixels[k].to_be_bytes().map(u32::from);
                    let mix = |c: u32, c0: u32| ((a * c + (255 - a) * c0) / 255) as u8;
                    let alpha = (a + (255 - a) * a0 / 255) as u8;
                    u32::from_be_bytes([alpha, mix(r, r0), mix(g, g0), mix(b, b0)])
                } else {
                    src
                };
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn display(w: u32, h: u32) -> Display {
        Display::new(&DisplaySettings {
            width: w,
            height: h,
        })
    }

    /// The pixels of `d` equal to `argb`, as (x, y).
    fn lit(d: &Display, argb: u32) -> Vec<(i32, i32)> {
        let w = d.image().width as i32;
        (0..d.image().pixels.len() as i32)
            .filter(|k| d.image().pixels[*k as usize] == argb)
            .map(|k| (k % w, k / w))
            .collect()
    }

    const WHITE: u32 = 0xFFFF_FFFF;

    #[test]
    fn starts_black_and_draws_pixels_lines_and_rectangles() {
        let mut d = display(8, 6);
        assert_eq!(d.pixel(0, 0), Some(0xFF00_0000));
        d.draw_pixel(2, 3);
        d.draw_pixel(-1, 0); // off the image: skipped
        d.draw_pixel(8, 0);
        assert_eq!(lit(&d, WHITE), vec![(2, 3)]);
        let mut d = display(8, 6);
        // Bresenham: one pixel per column, the ideal line y = x/3 rounded (no ties here).
        d.draw_line(0, 0, 6, 2);
        let mut got = lit(&d, WHITE);
        got.sort();
        let expected: Vec<(i32, i32)> = (0..=6)
            .map(|x| (x, (f64::from(x) / 3.0).round() as i32))
            .collect();
        assert_eq!(got, expected);
        let mut d = display(8, 6);
        d.fill_rectangle(1, 1, 3, 2);
        assert_eq!(lit(&d, WHITE).len(), 6);
        let mut d = display(8, 6);
        d.draw_rectangle(1, 1, 4, 3); // perimeter of 4 × 3: 2·4 + 2·1 = 10 pixels
        assert_eq!(lit(&d, WHITE).len(), 10);
        assert_eq!(d.pixel(2, 2), Some(0xFF00_0000));
    }

    #[test]
    fn colour_alpha_and_opacity_blend_as_webots() {
        let mut d = display(2, 1);
        d.set_color(0x00FF_8000).unwrap();
        d.set_opacity(0.5).unwrap(); // O = 127
        d.set_alpha(0.5).unwrap(); // A = 127
        d.draw_pixel(0, 0);
        // Over opaque black: r = 127·255/255 = 127, g = 127·128/255 = 63 (truncated), b = 0;
        // a = (128·255 + 127·127)/255 = 191.
        assert_eq!(d.pixel(0, 0), Some(u32::from_be_bytes([191, 127, 63, 0])));
        assert!(d.set_color(0x100_0000).is_err());
        assert!(d.set_alpha(1.5).is_err());
        assert!(d.set_opacity(f64::NAN).is_err());
    }

    #[test]
    fn ovals_and_polygons_cover_their_areas() {
        let mut d = display(21, 21);
        d.fill_oval(10, 10, 10, 10);
        let area = lit(&d, WHITE).len() as f64;
        // π·10² = 314.2: the pixel count of a digital disc is within a perimeter's worth.
        assert!((area - std::f64::consts::PI * 100.0).abs() < 2.0 * std::f64::consts::PI * 10.0);
        let mut d = display(21, 21);
        d.draw_oval(10, 10, 6, 4);
        assert!(lit(&d, WHITE).contains(&(16, 10)) && lit(&d, WHITE).contains(&(10, 14)));
        assert_eq!(d.pixel(10, 10), Some(0xFF00_0000));
        let mut d = display(10, 10);
        // The square with corners at pixel centres (1,1)-(5,5): pixels 1..=5 hold centres on
        // its left/top edges; the even–odd rule on centres takes 1..=4 or 1..=5 per row.
        d.fill_polygon(&[1, 5, 5, 1], &[1, 1, 5, 5]);
        let n = lit(&d, WHITE).len();
        assert!((16..=25).contains(&n), "{n}");
        let mut d = display(10, 10);
        d.draw_polygon(&[0, 4, 0], &[0, 0, 4]);
        assert!(lit(&d, WHITE).contains(&(4, 0)) && lit(&d, WHITE).contains(&(2, 2)));
    }

    #[test]
    fn images_copy_paste_and_blend() {
        let mut d = display(4, 4);
        d.fill_rectangle(0, 0, 2, 2);
        let copy = d.copy(0, 0, 2, 2).unwrap();
        assert_eq!(copy.pixels, vec![WHITE; 4]);
        d.paste(&copy, 2, 2, false);
        assert_eq!(d.pixel(3, 3), Some(WHITE));
        assert!(d.copy(5, 5, 2, 2).is_none());
        // A half-transparent red RGBA pixel blended over black.
        let red = DisplayImage::from_bytes(1, 1, &[255, 0, 0, 128], PixelFormat::Rgba).unwrap();
        d.paste(&red, 0, 3, true);
        // r = 128·255/255 = 128, alpha 128 + 127·255/255 = 255.
        assert_eq!(d.pixel(0, 3), Some(u32::from_be_bytes([255, 128, 0, 0])));
        assert!(DisplayImage::from_bytes(2, 2, &[0; 11], PixelFormat::Rgb).is_none());
        let bgra = DisplayImage::from_bytes(1, 1, &[1, 2, 3, 4], PixelFormat::Bgra).unwrap();
        assert_eq!(bgra.rgba(), vec![3, 2, 1, 4]);
    }
}
