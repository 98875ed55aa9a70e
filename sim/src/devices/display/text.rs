//! A display's text (Webots: `wb_display_set_font`, `wb_display_draw_text`), drawn with
//! `embedded-graphics`' monospaced ISO 8859-1 bitmap fonts.
//!
//! Webots renders TrueType fonts (13 named families, 8 px Lucida Console by default). Here every
//! family draws with the same bitmap font: the one whose character height is closest to the
//! size asked, scaled by a whole factor past 20 px, the tallest. A bitmap font's pixels are
//! either drawn or not, so `anti_aliasing` changes nothing; each drawn pixel takes the
//! context's colour, alpha and opacity as [`Display::draw_pixel`] does, so a text is drawn
//! exactly like the pixels of a line. Characters outside ISO 8859-1 draw as `?`.

use embedded_graphics::Pixel;
use embedded_graphics::mono_font::{MonoFont, MonoTextStyle, iso_8859_1 as fonts};
use embedded_graphics::pixelcolor::BinaryColor;
use embedded_graphics::prelude::{Dimensions, DrawTarget, Drawable, Point, Size};
use embedded_graphics::primitives::Rectangle;
use embedded_graphics::text::{Baseline, Text};

use super::{Display, MAX_SIDE};

/// The font families Webots knows (spec §10), any of which a display accepts.
pub const FONT_FAMILIES: [&str; 13] = [
    "Arial",
    "Arial Black",
    "Comic Sans MS",
    "Courier New",
    "Georgia",
    "Impact",
    "Lucida Console",
    "Lucida Sans Unicode",
    "Palatino Linotype",
    "Tahoma",
    "Times New Roman",
    "Trebuchet MS",
    "Verdana",
];

/// The bitmap fonts, by character height (px).
const BITMAPS: [&MonoFont<'static>; 13] = [
    &fonts::FONT_4X6,
    &fonts::FONT_5X7,
    &fonts::FONT_5X8,
    &fonts::FONT_6X9,
    &fonts::FONT_6X10,
    &fonts::FONT_6X12,
    &fonts::FONT_6X13,
    &fonts::FONT_7X13,
    &fonts::FONT_7X14,
    &fonts::FONT_8X13,
    &fonts::FONT_9X15,
    &fonts::FONT_9X18,
    &fonts::FONT_10X20,
];

/// Why a font is refused.
#[derive(Debug, Clone, PartialEq, Eq, thiserror::Error)]
#[non_exhaustive]
pub enum FontError {
    /// A family Webots does not know ([`FONT_FAMILIES`]).
    #[error("font '{0}' is not one of Webots' fonts ({families})", families = FONT_FAMILIES.join(", "))]
    UnknownFamily(String),
    /// A size (px) ≤ 0 or larger than a display can be.
    #[error("font size {0} must be > 0 and at most {MAX_SIDE} px")]
    Size(i32),
}

/// A display's font: its family, character height and the bitmap that draws it.
#[derive(Debug, Clone, Copy)]
pub(super) struct Font {
    bitmap: &'static MonoFont<'static>,
    /// Whole factor the bitmap is drawn at (1 up to 20 px).
    scale: u32,
}

impl Font {
    /// The font for `size` px (> 0): the bitmap of closest height at the smallest whole scale
    /// that keeps the tallest bitmap within reach of `size`.
    fn of_size(size: u32) -> Font {
        let tallest = BITMAPS[BITMAPS.len() - 1].character_size.height;
        let scale = size.div_ceil(tallest).max(1);
        let height = size as f64 / f64::from(scale);
        let bitmap = BITMAPS
            .iter()
            .min_by(|a, b| {
                let d = |f: &MonoFont<'_>| (f64::from(f.character_size.height) - height).abs();
                d(a).total_cmp(&d(b))
            })
            .copied()
            .unwrap_or(BITMAPS[0]);
        Font { bitmap, scale }
    }
}

impl Default for Font {
    /// Webots' default: Lucida Console, 8 px.
    fn default() -> Self {
        Font::of_size(8)
    }
}

/// The display seen as an `embedded-graphics` target: a font pixel at (x, y) is the
/// `scale`×`scale` block at `origin + scale·(x, y)`.
struct Target<'a> {
    display: &'a mut Display,
    origin: Point,
    scale: i32,
}

impl Dimensions for Target<'_> {
    fn bounding_box(&self) -> Rectangle {
        // Text is laid out from (0, 0) and clipped by the display itself, pixel by pixel.
        Rectangle::new(Point::zero(), Size::new(u32::MAX / 2, u32::MAX / 2))
    }
}

impl DrawTarget for Target<'_> {
    type Color = BinaryColor;
    type Error = core::convert::Infallible;

    fn draw_iter<I>(&mut self, pixels: I) -> Result<(), Self::Error>
    where
        I: IntoIterator<Item = Pixel<BinaryColor>>,
    {
        let (w, h) = (
            self.display.image.width as i64,
            self.display.image.height as i64,
        );
        let s = i64::from(self.scale);
        for Pixel(p, color) in pixels {
            if color != BinaryColor::On {
                continue;
            }
            let x0 = i64::from(self.origin.x) + s * i64::from(p.x);
            let y0 = i64::from(self.origin.y) + s * i64::from(p.y);
            // Only the part of the block on the image: a large scale costs nothing off it.
            for y in y0.max(0)..(y0 + s).min(h) {
                for x in x0.max(0)..(x0 + s).min(w) {
                    // Within the image, so within i32.
                    self.display.draw_pixel(x as i32, y as i32);
                }
            }
        }
        Ok(())
    }
}

impl Display {
    /// Sets the font: `family` one of [`FONT_FAMILIES`], `size` the character height (px, > 0);
    /// Webots' `anti_aliasing` flag is accepted and changes nothing (module documentation).
    ///
    /// # Errors
    /// [`FontError::UnknownFamily`] naming the family; [`FontError::Size`] naming a size ≤ 0
    /// or above [`MAX_SIDE`].
    pub fn set_font(
        &mut self,
        family: &str,
        size: i32,
        _anti_aliasing: bool,
    ) -> Result<(), FontError> {
        if !FONT_FAMILIES.contains(&family) {
            return Err(FontError::UnknownFamily(family.to_string()));
        }
        let size = u32::try_from(size)
            .ok()
            .filter(|s| (1..=MAX_SIDE).contains(s))
            .ok_or(FontError::Size(size))?;
        self.font = Font::of_size(size);
        Ok(())
    }

    /// Draws `text` with its top-left corner at (`x`, `y`) (px), in the font and the context's
    /// colour, alpha and opacity; a `\n` starts a new line below.
    pub fn draw_text(&mut self, text: &str, x: i32, y: i32) {
        let Font { bitmap, scale } = self.font;
        let style = MonoTextStyle::new(bitmap, BinaryColor::On);
        let mut target = Target {
            display: self,
            origin: Point::new(x, y),
            scale: scale as i32,
        };
        let Ok(_) =
            Text::with_baseline(text, Point::zero(), style, Baseline::Top).draw(&mut target);
    }

    /// The width and height (px) of a character in the font.
    pub fn font_character_size(&self) -> (u32, u32) {
        let c = self.font.bitmap.character_size;
        (c.width * self.font.scale, c.height * self.font.scale)
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::devices::DisplaySettings;

    fn display(width: u32, height: u32) -> Display {
        Display::new(&DisplaySettings { width, height })
    }

    /// The pixels of `d` in the rectangle at (`x`, `y`) of `w`×`h`, one string per row: `#`
    /// drawn (white), `.` untouched (opaque black), `-` off the image.
    fn art(d: &Display, x: i32, y: i32, w: i32, h: i32) -> Vec<String> {
        (y..y + h)
            .map(|j| {
                (x..x + w)
                    .map(|i| match d.pixel(i, j) {
                        Some(0xFFFF_FFFF) => '#',
                        Some(0xFF00_0000) => '.',
                        None => '-',
                        other => panic!("pixel ({i}, {j}): {other:?}"),
                    })
                    .collect()
            })
            .collect()
    }

    /// The 6×10 font's `A` (X11 misc-fixed), the bitmap of a 10 px font.
    const A_6X10: [&str; 10] = [
        "......", "..#...", ".#.#..", "#...#.", "#...#.", "#####.", "#...#.", "#...#.", "......",
        "......",
    ];

    #[test]
    fn a_glyph_is_drawn_with_its_top_left_corner_at_x_y() {
        let mut d = display(20, 16);
        d.set_font("Arial", 10, true).unwrap();
        d.draw_text("A", 7, 3);
        assert_eq!(art(&d, 7, 3, 6, 10), A_6X10);
        // Nothing else is touched.
        let drawn = d
            .image()
            .pixels
            .iter()
            .filter(|&&p| p != 0xFF00_0000)
            .count();
        let in_glyph: usize = A_6X10.iter().map(|r| r.matches('#').count()).sum();
        assert_eq!(drawn, in_glyph);
    }

    #[test]
    fn text_off_the_image_is_clipped() {
        let mut d = display(20, 16);
        d.set_font("Courier New", 10, false).unwrap();
        d.draw_text("A", -2, -1);
        let visible: Vec<String> = A_6X10[1..].iter().map(|r| r[2..].to_string()).collect();
        assert_eq!(art(&d, 0, 0, 4, 9), visible);
        d.draw_text("AAAA", 1_000_000, i32::MIN);
    }

    #[test]
    fn a_second_line_starts_one_character_height_below() {
        let mut d = display(20, 24);
        d.set_font("Verdana", 10, true).unwrap();
        d.draw_text("\nA", 0, 0);
        assert_eq!(art(&d, 0, 10, 6, 10), A_6X10);
    }

    #[test]
    fn sizes_above_the_tallest_bitmap_scale_it_by_whole_factors() {
        let mut d = display(64, 64);
        assert_eq!(d.font_character_size(), (5, 8)); // Webots' default: 8 px
        d.set_font("Impact", 20, true).unwrap();
        assert_eq!(d.font_character_size(), (10, 20));
        d.draw_text("A", 0, 0);
        let single = art(&d, 0, 0, 10, 20);
        let mut big = display(64, 64);
        big.set_font("Impact", 40, true).unwrap();
        assert_eq!(big.font_character_size(), (20, 40));
        big.draw_text("A", 3, 2);
        // Every pixel of the 20 px glyph is a 2×2 block of the 40 px one.
        let doubled: Vec<String> = single
            .iter()
            .flat_map(|r| {
                let row: String = r.chars().flat_map(|c| [c, c]).collect();
                [row.clone(), row]
            })
            .collect();
        assert_eq!(art(&big, 3, 2, 20, 40), doubled);
    }

    #[test]
    fn unknown_families_and_bad_sizes_are_refused() {
        let mut d = display(8, 8);
        assert_eq!(
            d.set_font("Comic Sans", 8, true),
            Err(FontError::UnknownFamily("Comic Sans".into()))
        );
        assert_eq!(d.set_font("Arial", 0, true), Err(FontError::Size(0)));
        assert_eq!(d.set_font("Arial", -3, true), Err(FontError::Size(-3)));
        assert_eq!(d.set_font("Arial", 5000, true), Err(FontError::Size(5000)));
        // A refused font leaves the font as it was.
        assert_eq!(d.font_character_size(), (5, 8));
    }
}
