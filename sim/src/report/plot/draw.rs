//! Drawing a figure: its panels over the shared x axis, their series, and the legend column.

use plotters::coord::Shift;
use plotters::prelude::*;

use super::legend::{draw_legend, is_data};
use super::style::{
    CHAR_WIDTH, CONE, FONT, GREY, LEGEND_ROW, LEGEND_WIDTH, MAP_HEIGHT, MARGIN, MARKERS,
    MAX_INTEGER_TICKS, MAX_POINTS, PANEL_HEIGHT, PLOT_WIDTH, SCATTER_ALPHA, SVG_FONT_SCALE, TEXT,
    TITLE, TITLE_HEIGHT, X_LABEL_AREA, Y_LABEL_AREA, color_of, marker_at, style_of, tidy,
};
use super::{Figure, Panel, SeriesKind, XAxis};

/// Least space between two category labels (px).
const LABEL_GAP: f64 = 8.0;

/// Half the width of a box on a categorical axis when its points share one x (category
/// widths: a category spans 1).
const MIN_BOX_HALF_WIDTH: f64 = 0.05;

/// Evenly thinned points (at most [`MAX_POINTS`], first and last kept).
pub(super) fn thin(points: &[[f64; 2]]) -> Vec<[f64; 2]> {
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
pub(super) fn pieces(points: &[[f64; 2]]) -> Vec<Vec<(f64, f64)>> {
    points
        .split(|p| !(p[0].is_finite() && p[1].is_finite()))
        .filter(|run| !run.is_empty())
        .map(|run| run.iter().map(|p| (p[0], p[1])).collect())
        .collect()
}

/// `points` as steps: each value held until the next point's time.
pub(super) fn steps(points: &[(f64, f64)]) -> Vec<(f64, f64)> {
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
    /// The figure's size in pixels: the panels' height, or the legend's when it is taller.
    fn size(&self) -> (u32, u32) {
        let n = u32::try_from(self.panels.len().max(1)).unwrap_or(1);
        let panel = if self.equal_aspect {
            MAP_HEIGHT
        } else {
            PANEL_HEIGHT
        };
        let rows = u32::try_from(self.legend().rows).unwrap_or(0);
        let legend = rows * LEGEND_ROW.unsigned_abs() + 2 * LEGEND_ROW.unsigned_abs();
        (
            PLOT_WIDTH + LEGEND_WIDTH,
            TITLE_HEIGHT + (n * panel).max(legend),
        )
    }

    pub(super) fn draw(&self, svg: &mut String) -> Result<(), String> {
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
        let x_range = match &self.x_axis {
            // Category i spans i ± 0.5.
            XAxis::Categories(names) => [-0.5, names.len().max(1) as f64 - 0.5],
            XAxis::Continuous | XAxis::Integer => range(
                self.panels
                    .iter()
                    .flat_map(|p| p.series.iter().flat_map(|s| s.points.iter().map(|q| q[0]))),
            ),
        };
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
        draw_legend(&legend, &self.legend()).map_err(|e| fail(&e))?;
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
        // An integer axis labels its whole ticks only; a categorical one names its categories
        // at their whole positions.
        let whole = |v: &f64| {
            if v.fract() == 0.0 {
                tidy(*v)
            } else {
                String::new()
            }
        };
        let category = |v: &f64| match &self.x_axis {
            XAxis::Categories(names) if v.fract() == 0.0 && *v >= 0.0 => {
                names.get(*v as usize).cloned().unwrap_or_default()
            }
            _ => String::new(),
        };
        mesh.y_label_formatter(&tick);
        match &self.x_axis {
            XAxis::Continuous => {
                mesh.x_label_formatter(&tick);
            }
            XAxis::Integer => {
                // At most one label per integer: plotters then steps by 1, 2, 5, …
                let span = (xr[1].ceil() - xr[0].floor()) as usize;
                mesh.x_label_formatter(&whole)
                    .x_labels(span.clamp(2, MAX_INTEGER_TICKS));
            }
            XAxis::Categories(names) => {
                // A label per category when the names fit side by side (plotters then steps
                // by 1 from category 0), else every 2nd, 5th, … rather than overlapping.
                let widest = names.iter().map(|n| n.chars().count()).max().unwrap_or(1);
                let label = widest as f64 * CHAR_WIDTH * TEXT * SVG_FONT_SCALE + LABEL_GAP;
                let fit = (f64::from(PLOT_WIDTH - Y_LABEL_AREA) / label).floor() as usize;
                mesh.x_label_formatter(&category)
                    .x_labels(names.len().min(fit).max(1));
            }
        }
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
                    let color = color_of(k);
                    if matches!(self.x_axis, XAxis::Categories(_)) {
                        for b in boxes(&thinned) {
                            chart.draw_series([
                                Rectangle::new(
                                    [(b.x - b.half, b.q[0]), (b.x + b.half, b.q[2])],
                                    color.mix(0.12).filled(),
                                ),
                                Rectangle::new(
                                    [(b.x - b.half, b.q[0]), (b.x + b.half, b.q[2])],
                                    color.stroke_width(1),
                                ),
                            ])?;
                            chart.draw_series(LineSeries::new(
                                [(b.x - b.half, b.q[1]), (b.x + b.half, b.q[1])],
                                color.stroke_width(2),
                            ))?;
                        }
                    }
                    chart.draw_series(
                        pieces(&thinned)
                            .into_iter()
                            .flatten()
                            .map(|p| Circle::new(p, 3, color.mix(SCATTER_ALPHA).filled())),
                    )?;
                }
                SeriesKind::Line | SeriesKind::Steps => {
                    let color = color_of(k);
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

/// A box of a categorical axis: its centre and half width along x, and the quartiles
/// (lower, median, upper) of its points' y.
#[derive(Debug, Clone, Copy, PartialEq)]
struct BoxPlot {
    x: f64,
    half: f64,
    q: [f64; 3],
}

/// The `p`-quantile of sorted `ys` (linear between the two nearest ranks; R's type 7).
fn quantile(ys: &[f64], p: f64) -> f64 {
    let h = p * (ys.len().saturating_sub(1)) as f64;
    let (lo, hi) = (h.floor() as usize, h.ceil() as usize);
    let (a, b) = (
        ys.get(lo).copied().unwrap_or(0.0),
        ys.get(hi).copied().unwrap_or(0.0),
    );
    a + (h - lo as f64) * (b - a)
}

/// The boxes of `points` on a categorical axis: one per category (the points whose x rounds
/// to it), spanning the points' x spread, in category order.
fn boxes(points: &[[f64; 2]]) -> Vec<BoxPlot> {
    let mut groups: Vec<(i64, Vec<[f64; 2]>)> = Vec::new();
    for p in points
        .iter()
        .filter(|p| p[0].is_finite() && p[1].is_finite())
    {
        let c = p[0].round() as i64;
        match groups.iter_mut().find(|(g, _)| *g == c) {
            Some((_, v)) => v.push(*p),
            None => groups.push((c, vec![*p])),
        }
    }
    groups.sort_by_key(|(c, _)| *c);
    groups
        .into_iter()
        .map(|(_, v)| {
            let (lo, hi) = v
                .iter()
                .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), p| {
                    (lo.min(p[0]), hi.max(p[0]))
                });
            let mut ys: Vec<f64> = v.iter().map(|p| p[1]).collect();
            ys.sort_by(f64::total_cmp);
            BoxPlot {
                x: 0.5 * (lo + hi),
                half: (0.5 * (hi - lo)).max(MIN_BOX_HALF_WIDTH),
                q: [0.25, 0.5, 0.75].map(|p| quantile(&ys, p)),
            }
        })
        .collect()
}

/// True for a panel whose data series are all steps (a discrete quantity, e.g. the gear).
fn is_discrete(panel: &Panel) -> bool {
    let mut data = panel.series.iter().filter(|s| is_data(s)).peekable();
    data.peek().is_some() && data.all(|s| s.kind == SeriesKind::Steps)
}
