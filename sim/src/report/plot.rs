//! Plots as standalone SVG documents, drawn with `plotters` (its SVG backend only).
//!
//! Every data series of a panel gets its own colour, dash pattern and marker shape, the
//! markers of different series placed at different points, so that a series lying on top of
//! another stays visible; the legend sits right of the plot area, never over the data.

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

impl Figure {
    /// The figure's size in pixels.
    fn size(&self) -> (u32, u32) {
        let n = u32::try_from(self.panels.len().max(1)).unwrap_or(1);
        let panel = if self.equal_aspect {
            MAP_HEIGHT
        } else {
            PANEL_HEIGHT
        };
        (PLOT_WIDTH + LEGEND_WIDTH, TITLE_HEIGHT + n * panel)
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
        let mut legend_row = 0;
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
            self.draw_panel(area, panel, xr, yr, last)
                .map_err(|e| fail(&e))?;
            draw_legend(&legend, panel, &mut legend_row).map_err(|e| fail(&e))?;
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
    ) -> Result<(), DrawingAreaErrorKind<std::io::Error>> {
        let mut chart = ChartBuilder::on(area)
            .margin(MARGIN)
            .x_label_area_size(if last { X_LABEL_AREA } else { 12 })
            .y_label_area_size(Y_LABEL_AREA)
            .build_cartesian_2d(xr[0]..xr[1], yr[0]..yr[1])?;
        let mut mesh = chart.configure_mesh();
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
        let data: Vec<&Series> = panel
            .series
            .iter()
            .filter(|s| matches!(s.kind, SeriesKind::Line | SeriesKind::Steps))
            .collect();
        let mut k = 0;
        for s in &panel.series {
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
                    let offset = every * k / data.len().max(1);
                    let at = finite
                        .iter()
                        .skip(offset)
                        .step_by(every)
                        .take(MARKERS)
                        .copied();
                    chart.draw_series(at.map(|p| marker_at(marker, p, color)))?;
                    k += 1;
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

/// Draws the legend entries of `panel` in the legend column, from row `row` on.
fn draw_legend(
    legend: &DrawingArea<SVGBackend<'_>, Shift>,
    panel: &Panel,
    row: &mut i32,
) -> Result<(), DrawingAreaErrorKind<std::io::Error>> {
    let mut k = 0;
    for s in &panel.series {
        let y = 20 + 20 * *row;
        let (x0, x1) = (8, 38);
        let mid = ((x0 + x1) / 2, y);
        match s.kind {
            SeriesKind::Line | SeriesKind::Steps => {
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
                k += 1;
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
        legend.draw_text(
            &s.name,
            &(FONT, TEXT).into_font().color(&BLACK),
            (x1 + 8, y - 6),
        )?;
        *row += 1;
    }
    // A gap between the entries of two panels.
    *row += 1;
    Ok(())
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
