//! How a figure looks: colours, sizes, fonts, dash patterns, markers and tick labels.

use plotters::prelude::*;

/// Line colours, distinct for colour-blind readers (Okabe–Ito).
const PALETTE: [RGBColor; 7] = [
    RGBColor(0x00, 0x72, 0xB2),
    RGBColor(0xD5, 0x5E, 0x00),
    RGBColor(0x00, 0x9E, 0x73),
    RGBColor(0xCC, 0x79, 0xA7),
    RGBColor(0xE6, 0x9F, 0x00),
    RGBColor(0x56, 0xB4, 0xE9),
    RGBColor(0x00, 0x00, 0x00),
];
pub(super) const GREY: RGBColor = RGBColor(0x88, 0x88, 0x88);
pub(super) const CONE: RGBColor = RGBColor(0xF0, 0x80, 0x00);
/// Opacity of scatter dots: translucent, so that dense clouds show their density.
pub(super) const SCATTER_ALPHA: f64 = 0.6;

/// Width of the plot column (px); the legend column follows it.
pub(super) const PLOT_WIDTH: u32 = 760;
/// Width of the legend column (px).
pub(super) const LEGEND_WIDTH: u32 = 200;
pub(super) const TITLE_HEIGHT: u32 = 36;
pub(super) const PANEL_HEIGHT: u32 = 300;
pub(super) const MAP_HEIGHT: u32 = 560;
pub(super) const MARGIN: u32 = 10;
pub(super) const Y_LABEL_AREA: u32 = 64;
pub(super) const X_LABEL_AREA: u32 = 44;
/// Most points drawn per series; longer series are thinned evenly (keeping the last point).
pub(super) const MAX_POINTS: usize = 1000;
/// Markers per data series.
pub(super) const MARKERS: usize = 12;
pub(super) const FONT: &str = "sans-serif";
/// Font sizes (the SVG backend writes 0.81 of the size asked for: 15 gives 12 px).
pub(super) const TEXT: f64 = 15.0;
pub(super) const TITLE: f64 = 20.0;
/// The font size the SVG backend writes for a requested size (see [`TEXT`]).
pub(super) const SVG_FONT_SCALE: f64 = 0.81;
/// Estimated width of a character (em): 0.6 em covers the average of DejaVu Sans and Arial
/// on mixed text (digits are 0.55–0.64 em, lower-case letters 0.5–0.6 em); wider capitals
/// are rare in labels.
pub(super) const CHAR_WIDTH: f64 = 0.6;
/// Height of a legend row (px).
pub(super) const LEGEND_ROW: i32 = 20;
/// Where a legend entry's text starts in the legend column (px), after its line sample.
pub(super) const LEGEND_TEXT_X: i32 = 46;
/// Most tick labels on a discrete (integer) axis.
pub(super) const MAX_INTEGER_TICKS: usize = 12;

/// A tick label without trailing zeros: `100`, `0.25`, `-3.5` (never `-0`).
pub(super) fn tidy(v: f64) -> String {
    let s = format!("{v:.6}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".to_string()
    } else {
        s.to_string()
    }
}

/// The colour of the `k`-th data series (the palette repeats after 7: the dash pattern and
/// marker still tell series apart).
pub(super) fn color_of(k: usize) -> RGBColor {
    PALETTE[k % PALETTE.len()]
}

/// Most series with a colour of their own: beyond, colours repeat.
pub(crate) const COLOURS: usize = PALETTE.len();

/// The dash pattern (dash, gap in px; `None` solid) and marker of the `k`-th data series.
pub(super) fn style_of(k: usize) -> (Option<(u32, u32)>, Marker) {
    let dash = [None, Some((9, 4)), Some((3, 3)), Some((14, 4))][k % 4];
    let marker = [Marker::Circle, Marker::Triangle, Marker::Cross, Marker::Dot][(k / 4 + k) % 4];
    (dash, marker)
}

/// A marker shape.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(super) enum Marker {
    Circle,
    Triangle,
    Cross,
    Dot,
}

/// A marker of `shape` at `p`.
pub(super) fn marker_at<'b>(
    shape: Marker,
    p: (f64, f64),
    color: RGBColor,
) -> DynElement<'static, SVGBackend<'b>, (f64, f64)> {
    let style = color.stroke_width(2);
    match shape {
        Marker::Circle => Circle::new(p, 3, style).into_dyn(),
        Marker::Triangle => TriangleMarker::new(p, 4, style).into_dyn(),
        Marker::Cross => Cross::new(p, 4, style).into_dyn(),
        Marker::Dot => Circle::new(p, 3, color.filled()).into_dyn(),
    }
}
