//! Line plots as standalone SVG documents, written by hand (no plotting dependency).

use std::fmt::Write as _;

/// One line of a plot.
#[derive(Debug, Clone, PartialEq)]
pub struct Series {
    /// Legend text.
    pub name: String,
    /// The points, in drawing order; non-finite points break the line.
    pub points: Vec<[f64; 2]>,
}

/// A plot panel: axes, labels and lines.
#[derive(Debug, Clone, PartialEq)]
pub struct Panel {
    /// Label of the y axis, with its unit.
    pub y_label: String,
    /// The lines.
    pub series: Vec<Series>,
    /// Draw steps (hold each value until the next point) instead of straight segments, for
    /// discrete quantities such as the gear.
    pub steps: bool,
    /// Grey dashed lines under the series, without legend (e.g. the edges of a course).
    pub guides: Vec<Vec<[f64; 2]>>,
}

impl Panel {
    /// Every point of the series and guides.
    fn points(&self) -> impl Iterator<Item = &[f64; 2]> {
        self.series
            .iter()
            .flat_map(|s| s.points.iter())
            .chain(self.guides.iter().flatten())
    }
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

/// Line colours, chosen to stay distinct for colour-blind readers (Okabe–Ito).
const PALETTE: [&str; 8] = [
    "#0072B2", "#D55E00", "#009E73", "#CC79A7", "#E69F00", "#56B4E9", "#000000", "#F0E442",
];

const WIDTH: f64 = 820.0;
const PANEL_HEIGHT: f64 = 300.0;
const MARGIN_LEFT: f64 = 72.0;
const MARGIN_RIGHT: f64 = 20.0;
const MARGIN_TOP: f64 = 40.0;
const PANEL_GAP: f64 = 24.0;
const MARGIN_BOTTOM: f64 = 50.0;
/// Most points drawn per series; longer series are thinned evenly (keeping the last point).
const MAX_POINTS: usize = 1000;

/// Escapes text for SVG.
fn escape(s: &str) -> String {
    s.replace('&', "&amp;")
        .replace('<', "&lt;")
        .replace('>', "&gt;")
}

/// Round tick positions covering `[lo, hi]`: steps of 1, 2 or 5 × 10ⁿ, about 6 ticks.
pub(crate) fn ticks(lo: f64, hi: f64) -> Vec<f64> {
    let span = hi - lo;
    if !(span.is_finite() && span > 0.0) {
        return vec![lo];
    }
    let raw = span / 6.0;
    let mag = 10f64.powf(raw.log10().floor());
    let step = [1.0, 2.0, 5.0, 10.0]
        .into_iter()
        .map(|m| m * mag)
        .find(|s| *s >= raw)
        .unwrap_or(10.0 * mag);
    // The tolerance keeps ends that land on a tick despite rounding (−0.3/0.1 = −2.9999…).
    let first = (lo / step - 1e-9).ceil() as i64;
    let last = (hi / step + 1e-9).floor() as i64;
    (first..=last).map(|k| k as f64 * step).collect()
}

/// A tick label with no more decimals than the tick spacing needs.
fn label(v: f64, step: f64) -> String {
    let decimals = if step >= 1.0 {
        0
    } else {
        (-step.log10().floor()) as usize
    };
    let s = format!("{v:.decimals$}");
    if s.starts_with('-') && s.trim_start_matches(['-', '0', '.']).is_empty() {
        s.trim_start_matches('-').to_string()
    } else {
        s
    }
}

/// `[min, max]` of the finite values of `values`, padded so that a flat line sits mid-panel;
/// `None` when there are none.
fn range(values: impl Iterator<Item = f64>) -> Option<[f64; 2]> {
    let (lo, hi) = values
        .filter(|v| v.is_finite())
        .fold((f64::INFINITY, f64::NEG_INFINITY), |(lo, hi), v| {
            (lo.min(v), hi.max(v))
        });
    if lo > hi {
        return None;
    }
    let pad = if hi > lo {
        0.04 * (hi - lo)
    } else {
        lo.abs().max(1.0) * 0.5
    };
    Some([lo - pad, hi + pad])
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

impl Figure {
    /// The SVG document.
    pub fn to_svg(&self) -> String {
        let n = self.panels.len().max(1) as f64;
        let plot_w = WIDTH - MARGIN_LEFT - MARGIN_RIGHT;
        let x_range =
            range(self.panels.iter().flat_map(Panel::points).map(|p| p[0])).unwrap_or([0.0, 1.0]);
        let mut panel_h = PANEL_HEIGHT;
        let mut x_range = x_range;
        let mut y_ranges: Vec<[f64; 2]> = self
            .panels
            .iter()
            .map(|p| range(p.points().map(|q| q[1])).unwrap_or([0.0, 1.0]))
            .collect();
        if self.equal_aspect
            && let Some(y) = y_ranges.first_mut()
        {
            // Same metres per pixel on both axes: widen the narrower range.
            let sx = (x_range[1] - x_range[0]) / plot_w;
            panel_h = (plot_w * 0.75).clamp(240.0, 620.0);
            let sy = (y[1] - y[0]) / panel_h;
            let s = sx.max(sy);
            let widen = |r: &mut [f64; 2], px: f64| {
                let mid = 0.5 * (r[0] + r[1]);
                *r = [mid - 0.5 * s * px, mid + 0.5 * s * px];
            };
            widen(&mut x_range, plot_w);
            widen(y, panel_h);
        }
        let height = MARGIN_TOP + n * panel_h + (n - 1.0) * PANEL_GAP + MARGIN_BOTTOM;
        let mut svg = String::new();
        let _ = write!(
            svg,
            "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"{WIDTH}\" height=\"{height}\" \
             viewBox=\"0 0 {WIDTH} {height}\" font-family=\"Helvetica, Arial, sans-serif\" \
             font-size=\"12\">\n<rect width=\"100%\" height=\"100%\" fill=\"white\"/>\n\
             <text x=\"{}\" y=\"24\" font-size=\"15\" font-weight=\"bold\">{}</text>\n",
            MARGIN_LEFT,
            escape(&self.title)
        );
        let x_ticks = ticks(x_range[0], x_range[1]);
        let x_step = x_ticks
            .get(1)
            .zip(x_ticks.first())
            .map_or(1.0, |(b, a)| b - a);
        for (i, (panel, y_range)) in self.panels.iter().zip(&y_ranges).enumerate() {
            let top = MARGIN_TOP + i as f64 * (panel_h + PANEL_GAP);
            let map_x =
                |x: f64| MARGIN_LEFT + (x - x_range[0]) / (x_range[1] - x_range[0]) * plot_w;
            let map_y =
                |y: f64| top + panel_h - (y - y_range[0]) / (y_range[1] - y_range[0]) * panel_h;
            let _ = writeln!(
                svg,
                "<rect x=\"{MARGIN_LEFT}\" y=\"{top}\" width=\"{plot_w}\" height=\"{panel_h}\" \
                 fill=\"none\" stroke=\"#444\"/>"
            );
            let mut y_ticks = ticks(y_range[0], y_range[1]);
            if panel.steps {
                // A discrete quantity (the gear) has whole-number ticks only.
                y_ticks.retain(|t| t.fract() == 0.0);
            }
            let y_step = y_ticks
                .get(1)
                .zip(y_ticks.first())
                .map_or(1.0, |(b, a)| b - a);
            for &t in &y_ticks {
                let y = map_y(t);
                let _ = writeln!(
                    svg,
                    "<line x1=\"{MARGIN_LEFT}\" x2=\"{:.1}\" y1=\"{y:.1}\" y2=\"{y:.1}\" \
                     stroke=\"#ddd\"/><text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"end\">{}</text>",
                    MARGIN_LEFT + plot_w,
                    MARGIN_LEFT - 6.0,
                    y + 4.0,
                    label(t, y_step)
                );
            }
            for &t in &x_ticks {
                let x = map_x(t);
                let _ = writeln!(
                    svg,
                    "<line x1=\"{x:.1}\" x2=\"{x:.1}\" y1=\"{top}\" y2=\"{:.1}\" stroke=\"#ddd\"/>",
                    top + panel_h
                );
                if i + 1 == self.panels.len() {
                    let _ = writeln!(
                        svg,
                        "<text x=\"{x:.1}\" y=\"{:.1}\" text-anchor=\"middle\">{}</text>",
                        top + panel_h + 16.0,
                        label(t, x_step)
                    );
                }
            }
            let _ = writeln!(
                svg,
                "<text transform=\"translate(16,{:.1}) rotate(-90)\" text-anchor=\"middle\">{}</text>",
                top + panel_h / 2.0,
                escape(&panel.y_label)
            );
            for guide in &panel.guides {
                let d: String = guide
                    .iter()
                    .filter(|p| p[0].is_finite() && p[1].is_finite())
                    .enumerate()
                    .map(|(i, p)| {
                        format!(
                            "{}{:.1},{:.1}",
                            if i == 0 { 'M' } else { 'L' },
                            map_x(p[0]),
                            map_y(p[1])
                        )
                    })
                    .collect();
                let _ = writeln!(
                    svg,
                    "<path d=\"{d}\" fill=\"none\" stroke=\"#888\" stroke-width=\"1\" \
                     stroke-dasharray=\"4 3\"/>"
                );
            }
            // The legend goes over the lines, in the top-right corner.
            let named = panel.series.len() > 1 || panel.series.iter().any(|s| !s.name.is_empty());
            let longest = panel
                .series
                .iter()
                .map(|s| s.name.chars().count())
                .max()
                .unwrap_or(0);
            let legend_w = 34.0 + 7.0 * longest as f64;
            let legend_x = MARGIN_LEFT + plot_w - legend_w - 6.0;
            let mut legend = String::new();
            if named {
                let _ = writeln!(
                    legend,
                    "<rect x=\"{legend_x:.1}\" y=\"{:.1}\" width=\"{legend_w:.1}\" height=\"{:.1}\" \
                     fill=\"white\" fill-opacity=\"0.85\" stroke=\"#bbb\"/>",
                    top + 6.0,
                    8.0 + 16.0 * panel.series.len() as f64
                );
            }
            for (k, s) in panel.series.iter().enumerate() {
                let color = PALETTE.get(k % PALETTE.len()).copied().unwrap_or("#000");
                let mut d = String::new();
                let mut pen_down = false;
                let mut last_y = 0.0;
                for p in thin(&s.points) {
                    if !(p[0].is_finite() && p[1].is_finite()) {
                        pen_down = false;
                        continue;
                    }
                    let (x, y) = (map_x(p[0]), map_y(p[1]));
                    if !pen_down {
                        let _ = write!(d, "M{x:.1},{y:.1}");
                    } else if panel.steps {
                        let _ = write!(d, "L{x:.1},{last_y:.1}L{x:.1},{y:.1}");
                    } else {
                        let _ = write!(d, "L{x:.1},{y:.1}");
                    }
                    pen_down = true;
                    last_y = y;
                }
                let _ = writeln!(
                    svg,
                    "<path d=\"{d}\" fill=\"none\" stroke=\"{color}\" stroke-width=\"1.6\" \
                     stroke-linejoin=\"round\"/>"
                );
                if named {
                    let ly = top + 24.0 + 16.0 * k as f64;
                    let lx = legend_x + 6.0;
                    let _ = writeln!(
                        legend,
                        "<line x1=\"{lx:.1}\" x2=\"{:.1}\" y1=\"{:.1}\" y2=\"{:.1}\" stroke=\"{color}\" \
                         stroke-width=\"3\"/><text x=\"{:.1}\" y=\"{ly:.1}\">{}</text>",
                        lx + 18.0,
                        ly - 4.0,
                        ly - 4.0,
                        lx + 24.0,
                        escape(&s.name)
                    );
                }
            }
            svg.push_str(&legend);
        }
        let _ = writeln!(
            svg,
            "<text x=\"{:.1}\" y=\"{:.1}\" text-anchor=\"middle\">{}</text>\n</svg>",
            MARGIN_LEFT + plot_w / 2.0,
            height - 12.0,
            escape(&self.x_label)
        );
        svg
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn ticks_are_round() {
        assert_eq!(ticks(0.0, 10.0), vec![0.0, 2.0, 4.0, 6.0, 8.0, 10.0]);
        let t = ticks(-0.3, 0.3);
        let want = [-0.3, -0.2, -0.1, 0.0, 0.1, 0.2, 0.3];
        assert_eq!(t.len(), want.len());
        assert!(
            t.iter().zip(want).all(|(a, b)| (a - b).abs() < 1e-12),
            "{t:?}"
        );
        assert_eq!(
            ticks(13.0, 1013.0),
            vec![200.0, 400.0, 600.0, 800.0, 1000.0]
        );
        assert_eq!(ticks(3.0, 3.0), vec![3.0]);
        assert_eq!(label(0.30000000000000004, 0.1), "0.3");
        assert_eq!(label(-0.0, 0.1), "0.0");
    }

    #[test]
    fn figure_has_one_path_per_series_and_escapes_text() {
        let fig = Figure {
            title: "speed <km/h> & rpm".into(),
            x_label: "time (s)".into(),
            panels: vec![Panel {
                y_label: "speed (km/h)".into(),
                series: vec![
                    Series {
                        name: "a".into(),
                        points: vec![[0.0, 0.0], [1.0, 10.0], [f64::NAN, 1.0], [2.0, 5.0]],
                    },
                    Series {
                        name: "b".into(),
                        points: (0..5000).map(|i| [f64::from(i), 1.0]).collect(),
                    },
                ],
                steps: false,
                guides: vec![vec![[0.0, -5.0], [2.0, -5.0]]],
            }],
            equal_aspect: false,
        };
        let svg = fig.to_svg();
        assert!(svg.starts_with("<svg") && svg.trim_end().ends_with("</svg>"));
        // Two series and a guide; the guide widens the y range below the data.
        assert_eq!(svg.matches("<path").count(), 3);
        assert_eq!(svg.matches("stroke-dasharray").count(), 1);
        assert!(svg.contains("speed &lt;km/h&gt; &amp; rpm"));
        // The NaN point lifts the pen: series "a" has two moves.
        let a = svg.split("<path d=\"").nth(2).unwrap();
        assert_eq!(a.split('"').next().unwrap().matches('M').count(), 2);
        // Series "b" is thinned to at most MAX_POINTS + 1 points.
        let b = svg
            .split("<path d=\"")
            .nth(3)
            .unwrap()
            .split('"')
            .next()
            .unwrap();
        assert!(b.matches('L').count() <= MAX_POINTS);
    }
}
