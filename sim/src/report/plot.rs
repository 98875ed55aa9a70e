//! Plots as standalone SVG documents, drawn with `plotters` (its SVG backend only).
//!
//! Every data series of a figure gets its own colour, dash pattern and marker shape, by its
//! name (a series in two panels is drawn alike and listed once in the legend), the markers of
//! different series placed at different points, so that a series lying on top of another
//! stays visible; the legend sits right of the plot area, never over the data, its names
//! wrapped to fit the column. Tick labels are tidy (`100`, not `100.0`), and a panel of
//! discrete quantities only (steps, e.g. the gear) has integer ticks.
//!
//! Text widths are estimated, as no font is at hand: [`CHAR_WIDTH`] em per character.

use plotters::coord::Shift;
use plotters::element::DashedPathElement;
use plotters::prelude::*;

/// How a series is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum SeriesKind {
    /// A measured line: its own colour, dash pattern and markers.
    Line,
    /// A measured discrete quantity (e.g. the gear): held until the next point.
    Steps,
    /// A grey dashed reference line (e.g. lane edges, the grip limit).
    Guide,
    /// Cone markers (orange triangles), one per point.
    Cones,
    /// Closed outlines seen from above (obstacles), filled grey.
    Outline,
    /// A scatter of measured points: small translucent dots, no line (e.g. the cases of a
    /// sweep against one axis).
    Points,
}

/// One named series of a plot; non-finite points break the line (and separate outlines).
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend text.
    pub name: String,
    /// The points, in drawing order.
    pub points: Vec<[f64; 2]>,
    /// How it is drawn.
    pub kind: SeriesKind,
}

impl Series {
    /// A measured line.
    pub fn line(name: impl Into<String>, points: Vec<[f64; 2]>) -> Self {
        Series {
            name: name.into(),
            points,
            kind: SeriesKind::Line,
        }
    }
}

/// A plot panel: a y axis and its series.
#[derive(Debug, Clone, PartialEq)]
pub struct Panel {
    /// Label of the y axis, with its unit.
    pub y_label: String,
    /// The series, drawn in order (outlines and guides first is best).
    pub series: Vec<Series>,
}

/// A figure: a title, one or more panels stacked vertically over a shared x axis, or one
/// panel with equal x and y scales (a map).
#[derive(Debug, Clone, PartialEq)]
pub struct Figure {
    /// Title above the first panel.
    pub title: String,
    /// Label of the x axis, with its unit.
    pub x_label: String,
    /// The panels, top to bottom.
    pub panels: Vec<Panel>,
    /// Same scale on both axes (for trajectories seen from above).
    pub equal_aspect: bool,
}

/// A plot that `plotters` could not draw.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[error("cannot draw the plot '{title}': {message}")]
pub struct PlotError {
    /// The figure's title.
    pub title: String,
    /// What plotters reported.
    pub message: String,
}

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
const GREY: RGBColor = RGBColor(0x88, 0x88, 0x88);
const CONE: RGBColor = RGBColor(0xF0, 0x80, 0x00);
/// Scatter dots: the palette's sky blue, translucent so that dense clouds show their density.
const SCATTER: RGBColor = RGBColor(0x56, 0xB4, 0xE9);
const SCATTER_ALPHA: f64 = 0.6;

/// Width of the plot column (px); the legend column follows it.
pub(crate) const PLOT_WIDTH: u32 = 760;
/// Width of the legend column (px).
const LEGEND_WIDTH: u32 = 200;
const TITLE_HEIGHT: u32 = 36;
const PANEL_HEIGHT: u32 = 300;
const MAP_HEIGHT: u32 = 560;
const MARGIN: u32 = 10;
const Y_LABEL_AREA: u32 = 64;
const X_LABEL_AREA: u32 = 44;
/// Most points drawn per series; longer series are thinned evenly (keeping the last point).
const MAX_POINTS: usize = 1000;
/// Markers per data series.
const MARKERS: usize = 12;
const FONT: &str = "sans-serif";
/// Font sizes (the SVG backend writes 0.81 of the size asked for: 15 gives 12 px).
const TEXT: f64 = 15.0;
const TITLE: f64 = 20.0;
/// The font size the SVG backend writes for a requested size (see [`TEXT`]).
const SVG_FONT_SCALE: f64 = 0.81;
/// Estimated width of a character (em): 0.6 em covers the average of DejaVu Sans and Arial
/// on mixed text (digits are 0.55–0.64 em, lower-case letters 0.5–0.6 em); wider capitals
/// are rare in labels.
pub(crate) const CHAR_WIDTH: f64 = 0.6;
/// Height of a legend row (px).
const LEGEND_ROW: i32 = 20;
/// Where a legend entry's text starts in the legend column (px), after its line sample.
const LEGEND_TEXT_X: i32 = 46;
/// Most tick labels on a discrete (integer) axis.
const MAX_INTEGER_TICKS: usize = 12;

/// A tick label without trailing zeros: `100`, `0.25`, `-3.5` (never `-0`).
pub(crate) fn tidy(v: f64) -> String {
    let s = format!("{v:.6}");
    let s = s.trim_end_matches('0').trim_end_matches('.');
    if s == "-0" {
        "0".to_string()
    } else {
        s.to_string()
    }
}

/// The characters of a legend line: what fits in the legend column at the estimated width.
fn legend_chars() -> usize {
    let px = f64::from(LEGEND_WIDTH) - f64::from(LEGEND_TEXT_X) - f64::from(MARGIN);
    (px / (CHAR_WIDTH * TEXT * SVG_FONT_SCALE)).floor() as usize
}

/// `text` broken at spaces into lines of at most `width` characters (a longer word is cut).
fn wrap(text: &str, width: usize) -> Vec<String> {
    let width = width.max(1);
    let mut lines: Vec<String> = Vec::new();
    let mut line = String::new();
    for word in text.split_whitespace() {
        let mut word: Vec<char> = word.chars().collect();
        loop {
            let used = line.chars().count();
            let sep = usize::from(used > 0);
            if used + sep + word.len() <= width {
                if sep == 1 {
                    line.push(' ');
                }
                line.extend(word.drain(..));
                break;
            }
            if used > 0 {
                lines.push(std::mem::take(&mut line));
                continue;
            }
            line = word.drain(..width).collect();
            lines.push(std::mem::take(&mut line));
        }
    }
    if !line.is_empty() || lines.is_empty() {
        lines.push(line);
    }
    lines
}

/// The dash pattern (dash, gap in px; `None` solid) and marker of the `k`-th data series.
pub(crate) fn style_of(k: usize) -> (Option<(u32, u32)>, Marker) {
    let dash = [None, Some((9, 4)), Some((3, 3)), Some((14, 4))][k % 4];
    let marker = [Marker::Circle, Marker::Triangle, Marker::Cross, Marker::Dot][(k / 4 + k) % 4];
    (dash, marker)
}

/// A marker shape.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub(crate) enum Marker {
    Circle,
    Triangle,
    Cross,
    Dot,
}

/// Evenly thinned points (at most [`MAX_POINTS`], first and last kept).
fn thin(points: &[[f64; 2]]) -> Vec<[f64; 2]> {
    if points.len() <= MAX_POINTS {
        return points.to_vec();
    }
    let stride = points.len().div_ceil(MAX_POINTS);
    let mut out: Vec<[f64; 2]> = points.iter().step_by(stride).copied().collect();
    if let (Some(last), Some(kept)) = (points.last(), out.last())
        && last != kept
    {
        out.push(*last);
    }
    out
}

/// The runs of finite points between non-finite ones.
fn pieces(points: &[[f64; 2]]) -> Vec<Vec<(f64, f64)>> {
    points
        .split(|p| !(p[0].is_finite() && p[1].is_finite()))
        .filter(|run| !run.is_empty())
        .map(|run| run.iter().map(|p| (p[0], p[1])).collect())
        .collect()
}

/// `points` as steps: each value held until the next point's time.
fn steps(points: &[(f64, f64)]) -> Vec<(f64, f64)> {
    let mut out = Vec::with_capacity(2 * points.len());
    for (i, &(x, y)) in points.iter().enumerate() {
        if let Some(&(_, prev)) = i.checked_sub(1).and_then(|j| points.get(j)) {
            out.push((x, prev));
        }
        out.push((x, y));
    }
    out
}

/// `[min, max]` of the finite `values`, padded so that a flat line sits mid-panel.
fn range(values: impl Iterator<Item = f64>) -> [f64; 2] {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    if lo > hi {
        return [0.0, 1.0];
    }
    let pad = if hi > lo {
        0.04 * (hi - lo)
    } else {
        lo.abs().max(1.0) * 0.5
    };
    [lo - pad, hi + pad]
}

/// A legend entry: a series shown once, its style (index among the figure's data series),
/// its text lines and its first row.
struct Entry<'a> {
    series: &'a Series,
    style: usize,
    lines: Vec<String>,
    row: i32,
}

/// True for the series that get a style of their own (colour, dash, marker).
fn is_data(s: &Series) -> bool {
    matches!(s.kind, SeriesKind::Line | SeriesKind::Steps)
}

impl Figure {
    /// The names of the data series, in order of first appearance: a series' style index.
    fn styles(&self) -> Vec<&str> {
        let mut names: Vec<&str> = Vec::new();
        for s in self
            .panels
            .iter()
            .flat_map(|p| &p.series)
            .filter(|s| is_data(s))
        {
            if !names.contains(&s.name.as_str()) {
                names.push(&s.name);
            }
        }
        names
    }

    /// The legend: each series once (by name, and kind for courses), panel by panel with a gap row
    /// between panels, names wrapped to the legend column.
    fn legend(&self) -> (Vec<Entry<'_>>, i32) {
        let styles = self.styles();
        let mut entries: Vec<Entry<'_>> = Vec::new();
        let mut row = 0;
        for panel in &self.panels {
            let before = entries.len();
            for s in &panel.series {
                // A data series keeps its style by name in every panel, as a line or steps.
                let same = |e: &Entry<'_>| {
                    e.series.name == s.name
                        && (e.series.kind == s.kind || is_data(e.series) && is_data(s))
                };
                if entries.iter().any(same) {
                    continue;
                }
                let lines = wrap(&s.name, legend_chars());
                let height = i32::try_from(lines.len()).unwrap_or(1);
                entries.push(Entry {
                    series: s,
                    style: styles.iter().position(|n| *n == s.name).unwrap_or(0),
                    lines,
                    row,
                });
                row += height;
            }
            if entries.len() > before {
                row += 1;
            }
        }
        (entries, row)
    }

    /// The figure's size in pixels: the panels' height, or the legend's when it is taller.
    fn size(&self) -> (u32, u32) {
        let n = u32::try_from(self.panels.len().max(1)).unwrap_or(1);
        let panel = if self.equal_aspect {
            MAP_HEIGHT
        } else {
            PANEL_HEIGHT
        };
        let rows = u32::try_from(self.legend().1).unwrap_or(0);
        let legend = rows * LEGEND_ROW.unsigned_abs() + 2 * LEGEND_ROW.unsigned_abs();
        (
            PLOT_WIDTH + LEGEND_WIDTH,
            TITLE_HEIGHT + (n * panel).max(legend),
        )
    }

    /// The SVG document.
    ///
    /// # Errors
    /// [`PlotError`] when plotters refuses to draw (it never does for finite data).
    pub fn to_svg(&self) -> Result<String, PlotError> {
        let mut svg = String::new();
        self.draw(&mut svg).map_err(|message| PlotError {
            title: self.title.clone(),
            message,
        })?;
        Ok(svg)
    }

    fn draw(&self, svg: &mut String) -> Result<(), String> {
        let fail = |e: &dyn std::fmt::Display| e.to_string();
        let root = SVGBackend::with_string(svg, self.size()).into_drawing_area();
        root.fill(&WHITE).map_err(|e| fail(&e))?;
        let (title, body) = root.split_vertically(TITLE_HEIGHT);
        title
            .draw_text(
                &self.title,
                &(FONT, TITLE)
                    .into_font()
                    .style(FontStyle::Bold)
                    .color(&BLACK),
                (Y_LABEL_AREA as i32 + MARGIN as i32, 10),
            )
            .map_err(|e| fail(&e))?;
        let (plots, legend) = body.split_horizontally(PLOT_WIDTH);
        let areas = plots.split_evenly((self.panels.len().max(1), 1));
        let x_range = range(
            self.panels
                .iter()
                .flat_map(|p| p.series.iter().flat_map(|s| s.points.iter().map(|q| q[0]))),
        );
        let styles = self.styles();
        for (i, (panel, area)) in self.panels.iter().zip(&areas).enumerate() {
            let last = i + 1 == self.panels.len();
            let mut xr = x_range;
            let mut yr = range(
                panel
                    .series
                    .iter()
                    .flat_map(|s| s.points.iter().map(|q| q[1])),
            );
            if self.equal_aspect {
                equalise(area, &mut xr, &mut yr);
            }
            if is_discrete(panel) {
                yr = [yr[0].floor() - 0.5, yr[1].ceil() + 0.5];
            }
            self.draw_panel(area, panel, xr, yr, last, &styles)
                .map_err(|e| fail(&e))?;
        }
        for entry in &self.legend().0 {
            draw_entry(&legend, entry).map_err(|e| fail(&e))?;
        }
        root.present().map_err(|e| fail(&e))?;
        Ok(())
    }

    fn draw_panel(
        &self,
        area: &DrawingArea<SVGBackend<'_>, Shift>,
        panel: &Panel,
        xr: [f64; 2],
        yr: [f64; 2],
        last: bool,
        styles: &[&str],
    ) -> Result<(), DrawingAreaErrorKind<std::io::Error>> {
        let mut chart = ChartBuilder::on(area)
            .margin(MARGIN)
            .x_label_area_size(if last { X_LABEL_AREA } else { 12 })
            .y_label_area_size(Y_LABEL_AREA)
            .build_cartesian_2d(xr[0]..xr[1], yr[0]..yr[1])?;
        let mut mesh = chart.configure_mesh();
        let tick = |v: &f64| tidy(*v);
        mesh.x_label_formatter(&tick).y_label_formatter(&tick);
        if is_discrete(panel) {
            // One tick per integer (or per 2, 5, … past MAX_INTEGER_TICKS): the ticks of a
            // gear are gears.
            let span = (yr[1] - yr[0]).round() as usize;
            mesh.y_labels(span.clamp(2, MAX_INTEGER_TICKS));
        }
        mesh.y_desc(panel.y_label.as_str())
            .label_style((FONT, TEXT))
            .axis_desc_style((FONT, TEXT))
            .light_line_style(WHITE.mix(0.0))
            .bold_line_style(BLACK.mix(0.12));
        if last {
            mesh.x_desc(self.x_label.as_str());
        } else {
            mesh.x_labels(0);
        }
        mesh.draw()?;
        for s in &panel.series {
            let k = styles.iter().position(|n| *n == s.name).unwrap_or(0);
            let thinned = thin(&s.points);
            match s.kind {
                SeriesKind::Outline => {
                    for poly in pieces(&s.points) {
                        chart.draw_series(std::iter::once(Polygon::new(
                            poly.clone(),
                            GREY.mix(0.25).filled(),
                        )))?;
                        let mut closed = poly.clone();
                        closed.extend(poly.first().copied());
                        chart.draw_series(LineSeries::new(closed, GREY.stroke_width(1)))?;
                    }
                }
                SeriesKind::Guide => {
                    for piece in pieces(&thinned) {
                        chart.draw_series(DashedLineSeries::new(
                            piece,
                            5,
                            4,
                            GREY.stroke_width(1),
                        ))?;
                    }
                }
                SeriesKind::Cones => {
                    chart.draw_series(
                        pieces(&s.points)
                            .into_iter()
                            .flatten()
                            .map(|p| TriangleMarker::new(p, 4, CONE.filled())),
                    )?;
                }
                SeriesKind::Points => {
                    chart.draw_series(
                        pieces(&thinned)
                            .into_iter()
                            .flatten()
                            .map(|p| Circle::new(p, 3, SCATTER.mix(SCATTER_ALPHA).filled())),
                    )?;
                }
                SeriesKind::Line | SeriesKind::Steps => {
                    let color = PALETTE[k % PALETTE.len()];
                    let (dash, marker) = style_of(k);
                    let style = color.stroke_width(2);
                    for piece in pieces(&thinned) {
                        let piece = if s.kind == SeriesKind::Steps {
                            steps(&piece)
                        } else {
                            piece
                        };
                        match dash {
                            None => {
                                chart.draw_series(LineSeries::new(piece, style))?;
                            }
                            Some((on, off)) => {
                                chart.draw_series(DashedLineSeries::new(piece, on, off, style))?;
                            }
                        }
                    }
                    // Markers spread along the series, each series starting at its own
                    // offset so that markers of coinciding series do not overlap.
                    let finite: Vec<(f64, f64)> = pieces(&s.points).into_iter().flatten().collect();
                    let every = (finite.len() / MARKERS).max(1);
                    let offset = every * k / styles.len().max(1);
                    let at = finite
                        .iter()
                        .skip(offset)
                        .step_by(every)
                        .take(MARKERS)
                        .copied();
                    chart.draw_series(at.map(|p| marker_at(marker, p, color)))?;
                }
            }
        }
        Ok(())
    }
}

/// Widens the ranges so that a metre is as long on both axes of `area`'s plot.
fn equalise(area: &DrawingArea<SVGBackend<'_>, Shift>, xr: &mut [f64; 2], yr: &mut [f64; 2]) {
    let (w, h) = area.dim_in_pixel();
    let pw = f64::from(w.saturating_sub(2 * MARGIN + Y_LABEL_AREA).max(1));
    let ph = f64::from(h.saturating_sub(2 * MARGIN + X_LABEL_AREA).max(1));
    let s = ((xr[1] - xr[0]) / pw).max((yr[1] - yr[0]) / ph);
    for (r, px) in [(xr, pw), (yr, ph)] {
        let mid = 0.5 * (r[0] + r[1]);
        *r = [mid - 0.5 * s * px, mid + 0.5 * s * px];
    }
}

/// A marker of `shape` at `p`.
fn marker_at<'b>(
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

/// True for a panel whose data series are all steps (a discrete quantity, e.g. the gear).
fn is_discrete(panel: &Panel) -> bool {
    let mut data = panel.series.iter().filter(|s| is_data(s)).peekable();
    data.peek().is_some() && data.all(|s| s.kind == SeriesKind::Steps)
}

/// Draws one legend entry in the legend column.
fn draw_entry(
    legend: &DrawingArea<SVGBackend<'_>, Shift>,
    entry: &Entry<'_>,
) -> Result<(), DrawingAreaErrorKind<std::io::Error>> {
    let s = entry.series;
    let y = LEGEND_ROW + LEGEND_ROW * entry.row;
    let (x0, x1) = (8, 38);
    let mid = ((x0 + x1) / 2, y);
    match s.kind {
        SeriesKind::Line | SeriesKind::Steps => {
            let k = entry.style;
            let color = PALETTE[k % PALETTE.len()];
            let (dash, marker) = style_of(k);
            let style = color.stroke_width(2);
            match dash {
                None => legend.draw(&PathElement::new(vec![(x0, y), (x1, y)], style))?,
                Some((on, off)) => legend.draw(&DashedPathElement::new(
                    vec![(x0, y), (x1, y)],
                    on,
                    off,
                    style,
                ))?,
            }
            match marker {
                Marker::Circle => legend.draw(&Circle::new(mid, 3, style))?,
                Marker::Triangle => legend.draw(&TriangleMarker::new(mid, 4, style))?,
                Marker::Cross => legend.draw(&Cross::new(mid, 4, style))?,
                Marker::Dot => legend.draw(&Circle::new(mid, 3, color.filled()))?,
            }
        }
        SeriesKind::Guide => legend.draw(&DashedPathElement::new(
            vec![(x0, y), (x1, y)],
            5,
            4,
            GREY.stroke_width(1),
        ))?,
        SeriesKind::Cones => legend.draw(&TriangleMarker::new(mid, 4, CONE.filled()))?,
        SeriesKind::Points => {
            for dx in [-8, 0, 8] {
                legend.draw(&Circle::new(
                    (mid.0 + dx, mid.1),
                    2,
                    SCATTER.mix(SCATTER_ALPHA).filled(),
                ))?;
            }
        }
        SeriesKind::Outline => legend.draw(&Rectangle::new(
            [(x0 + 6, y - 6), (x1 - 6, y + 6)],
            GREY.mix(0.25).filled(),
        ))?,
    }
    for (i, line) in (0..).zip(&entry.lines) {
        legend.draw_text(
            line,
            &(FONT, TEXT).into_font().color(&BLACK),
            (LEGEND_TEXT_X, y - 6 + LEGEND_ROW * i),
        )?;
    }
    Ok(())
}

/// Reading the text of a drawn SVG back, for tests: every `<text>` element's content and its
/// estimated box.
#[cfg(test)]
pub(crate) mod svg_text {
    use super::CHAR_WIDTH;

    /// The value of attribute `name` in the tag `tag`.
    fn attr<'a>(tag: &'a str, name: &str) -> Option<&'a str> {
        tag.split(&format!(" {name}=\"")).nth(1)?.split('"').next()
    }

    /// The canvas size of `svg` (px).
    pub(crate) fn canvas(svg: &str) -> [f64; 2] {
        let head = &svg[..svg.find('>').unwrap()];
        [attr(head, "width"), attr(head, "height")].map(|v| v.unwrap().parse().unwrap())
    }

    /// Every text element of `svg`: its content (entities decoded) and its box
    /// `[x0, y0, x1, y1]` (px), the width estimated as [`CHAR_WIDTH`] em per character and the
    /// height one em, placed by its anchor and baseline shift, rotated with it.
    pub(crate) fn boxes(svg: &str) -> Vec<(String, [f64; 4])> {
        let mut out = Vec::new();
        for part in svg.split("<text").skip(1) {
            let (tag, rest) = part.split_once('>').unwrap();
            let content = rest.split("</text>").next().unwrap().trim();
            let content = content
                .replace("&lt;", "<")
                .replace("&gt;", ">")
                .replace("&quot;", "\"")
                .replace("&apos;", "'")
                .replace("&amp;", "&");
            let num = |name: &str| attr(tag, name).unwrap().parse::<f64>().unwrap();
            let (x, y, size) = (num("x"), num("y"), num("font-size"));
            let w = CHAR_WIDTH * size * content.chars().count() as f64;
            // Along the text: where the anchor puts it.
            let (a0, a1) = match attr(tag, "text-anchor") {
                Some("middle") => (-0.5 * w, 0.5 * w),
                Some("end") => (-w, 0.0),
                _ => (0.0, w),
            };
            // Across: the em box below the anchor point (0.76em: y is the top), centred
            // (0.5ex) or above it (-0.5ex: y is the bottom).
            let (c0, c1) = match attr(tag, "dy") {
                Some("0.76em") => (0.0, size),
                Some("-0.5ex") => (-size, 0.0),
                _ => (-0.5 * size, 0.5 * size),
            };
            let rotated = attr(tag, "transform").is_some_and(|t| t.starts_with("rotate(270"));
            let b = if rotated {
                // rotate(270) turns the text's direction up and its "down" to the right.
                [x + c0, y - a1, x + c1, y - a0]
            } else {
                [x + a0, y + c0, x + a1, y + c1]
            };
            out.push((content, b));
        }
        out
    }

    /// Panics unless every text element of `svg` lies inside its canvas.
    pub(crate) fn assert_inside(svg: &str) {
        let [w, h] = canvas(svg);
        for (text, b) in boxes(svg) {
            assert!(
                b[0] >= 0.0 && b[1] >= 0.0 && b[2] <= w && b[3] <= h,
                "'{text}' at {b:?} leaves the {w} × {h} canvas"
            );
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The x coordinate of the `<text>` element whose content is `label`.
    fn text_x(svg: &str, label: &str) -> f64 {
        let end = svg
            .find(&format!(">\n{label}\n</text>"))
            .unwrap_or_else(|| panic!("no text {label} in {svg}"));
        let start = svg[..end].rfind("<text").unwrap();
        let tag = &svg[start..end];
        let x = tag.split("x=\"").nth(1).unwrap().split('"').next().unwrap();
        x.parse().unwrap()
    }

    fn two_equal_lines() -> Figure {
        let points: Vec<[f64; 2]> = (0..200)
            .map(|i| [f64::from(i), f64::from(i % 50)])
            .collect();
        Figure {
            title: "speed <km/h> & rpm".into(),
            x_label: "time (s)".into(),
            panels: vec![Panel {
                y_label: "speed (km/h)".into(),
                series: vec![
                    Series {
                        name: "lane edges".into(),
                        points: vec![[0.0, -5.0], [200.0, -5.0]],
                        kind: SeriesKind::Guide,
                    },
                    Series::line("accel-speed", points.clone()),
                    Series::line("brake", points),
                    Series {
                        name: "cones".into(),
                        points: vec![[10.0, 1.0], [20.0, 1.0]],
                        kind: SeriesKind::Cones,
                    },
                ],
            }],
            equal_aspect: false,
        }
    }

    #[test]
    fn coinciding_series_stay_visible() {
        // Two identical series: the second has its own dash pattern and marker, and the
        // markers of each are drawn at their own points.
        assert_ne!(style_of(0), style_of(1));
        let all: Vec<_> = (0..8).map(style_of).collect();
        for (i, a) in all.iter().enumerate() {
            assert!(all.iter().skip(i + 1).all(|b| b != a), "{all:?}");
        }
        let svg = two_equal_lines().to_svg().unwrap();
        // Markers of the first series (circles, blue) and of the second (triangles, orange,
        // drawn as polygons): MARKERS of each plus one in the legend.
        assert_eq!(svg.matches("<circle").count(), MARKERS + 1, "{svg}");
        assert!(svg.matches("#0072B2").count() > MARKERS);
        assert!(svg.matches("#D55E00").count() > MARKERS);
    }

    #[test]
    fn legend_sits_right_of_the_plot_area() {
        let svg = two_equal_lines().to_svg().unwrap();
        assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
        for label in ["accel-speed", "brake", "lane edges", "cones"] {
            let x = text_x(&svg, label);
            assert!(x > f64::from(PLOT_WIDTH), "{label} at x = {x}");
        }
        // The title is escaped.
        assert!(svg.contains("speed &lt;km/h&gt; &amp; rpm"), "{svg}");
    }

    #[test]
    fn ticks_are_tidy_and_text_stays_on_the_canvas() {
        assert_eq!(tidy(100.0), "100");
        assert_eq!(tidy(5000.0), "5000");
        assert_eq!(tidy(0.1 + 0.2), "0.3");
        assert_eq!(tidy(-2.5), "-2.5");
        assert_eq!(tidy(-1e-9), "0");
        let mut f = two_equal_lines();
        // A name longer than the legend column: wrapped, not cut (before: "lane-change
        // (commanded" and the rest past the edge).
        f.panels[0].series[1].name = "lane-change: ToyotaPrius-1 (commanded)".into();
        let svg = f.to_svg().unwrap();
        svg_text::assert_inside(&svg);
        let texts: Vec<String> = svg_text::boxes(&svg).into_iter().map(|t| t.0).collect();
        // 19 characters a line: (200 − 46 − 10) px / (0.6 × 12.15 px).
        for line in ["lane-change:", "ToyotaPrius-1", "(commanded)"] {
            assert!(texts.contains(&line.to_string()), "{texts:?}");
        }
        assert!(texts.iter().all(|t| !t.ends_with(".0")), "{texts:?}");
        assert_eq!(wrap("abcdefgh", 3), ["abc", "def", "gh"]);
        assert_eq!(wrap("a bc d", 4), ["a bc", "d"]);
        assert_eq!(wrap("", 4), [""]);
    }

    #[test]
    fn a_series_in_two_panels_is_one_legend_entry_and_gears_tick_in_integers() {
        let rpm: Vec<[f64; 2]> = (0..100)
            .map(|i| [f64::from(i), 1000.0 + 40.0 * f64::from(i)])
            .collect();
        let gear: Vec<[f64; 2]> = (0..100)
            .map(|i| [f64::from(i), f64::from(1 + i / 25)])
            .collect();
        let figure = Figure {
            title: "rpm and gear".into(),
            x_label: "time (s)".into(),
            panels: vec![
                Panel {
                    y_label: "engine speed (rpm)".into(),
                    series: vec![Series::line("accel-torque", rpm)],
                },
                Panel {
                    y_label: "gear".into(),
                    series: vec![Series {
                        name: "accel-torque".into(),
                        points: gear,
                        kind: SeriesKind::Steps,
                    }],
                },
            ],
            equal_aspect: false,
        };
        let svg = figure.to_svg().unwrap();
        svg_text::assert_inside(&svg);
        let boxes = svg_text::boxes(&svg);
        let legend: Vec<&str> = boxes
            .iter()
            .filter(|(_, b)| b[0] > f64::from(PLOT_WIDTH))
            .map(|(t, _)| t.as_str())
            .collect();
        assert_eq!(legend, ["accel-torque"]);
        // The gear panel is the lower half: its y tick labels (right-aligned at the axis)
        // are whole numbers, the gears 1 to 4 among them.
        let [_, h] = svg_text::canvas(&svg);
        let gear_ticks: Vec<f64> = boxes
            .iter()
            .filter(|(_, b)| {
                b[2] <= f64::from(Y_LABEL_AREA) + 1.0 && b[1] > 0.55 * h && b[3] < h - 30.0
            })
            .filter_map(|(t, _)| t.parse().ok())
            .collect();
        assert!(gear_ticks.len() >= 4, "{boxes:?}");
        assert!(
            gear_ticks.iter().all(|g| g.fract() == 0.0),
            "{gear_ticks:?}"
        );
        for g in [1.0, 2.0, 3.0, 4.0] {
            assert!(gear_ticks.contains(&g), "{gear_ticks:?}");
        }
    }

    #[test]
    fn thinning_and_steps() {
        let long: Vec<[f64; 2]> = (0..5000).map(|i| [f64::from(i), 1.0]).collect();
        let t = thin(&long);
        assert!(t.len() <= MAX_POINTS + 1);
        assert_eq!(t.last(), long.last());
        assert_eq!(
            steps(&[(0.0, 1.0), (1.0, 2.0)]),
            [(0.0, 1.0), (1.0, 1.0), (1.0, 2.0)]
        );
        assert_eq!(
            pieces(&[[0.0, 0.0], [f64::NAN, 1.0], [2.0, 5.0]]),
            [vec![(0.0, 0.0)], vec![(2.0, 5.0)]]
        );
    }
}
