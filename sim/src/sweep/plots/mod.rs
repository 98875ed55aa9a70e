//! The summary plots of a sweep: for each axis, one SVG figure with a panel per numeric
//! metric and one legend for the figure. The form follows the axis's kind:
//!
//! * a **numeric** axis is the x axis of a scatter, every case a dot and, for an axis with
//!   few distinct values, the mean over the cases at each value as a line (integer ticks when
//!   every value is whole);
//! * a **categorical** axis (model names, tyre kinds, booleans, lists) has one column per
//!   value, in the order of first appearance: a strip of the cases' dots over a box of their
//!   quartiles and median.
//!
//! The cases are coloured by a second axis ([`ColorBy`]): one colour per value, the legend
//! headed by that axis and naming its values, the dots and means of each value in its
//! colour (side by side in a categorical column). By default ([`ColorBy::Auto`]) the second
//! axis is the first other axis, in file order, of 2 to [`MAX_COLOURS`] distinct values.
//!
//! They are drawn from `results.csv`, read twice as a stream (once for the axes' kinds and
//! values, once for the points), so `vehicle-sim sweep` and `sweep-merge` draw the same plots
//! of the same rows; a sample of at most [`MAX_POINTS`] cases per panel and colour (every
//! `2^k`-th row) keeps the memory flat for any number of cases, while the means take every
//! case.

use std::path::{Path, PathBuf};

use crate::report::{COLOURS, Figure, Panel, Series, SeriesKind, XAxis};

use super::color::{ColorBy, MAX_COLOURS};
use super::error::{OutputError, csv_at, io_at};
use super::row::NOTES_COLUMN;

/// Most dots kept per panel and colour: the plots draw 1000 at most anyway.
pub const MAX_POINTS: usize = 1000;
/// Most distinct values of an axis for which the mean line is drawn (beyond, e.g. random
/// draws, each value has one case and the dots say it all).
pub const MAX_LEVELS: usize = 50;
/// Most values of a categorical axis that get a plot: a column each, which a wider figure
/// would not fit.
pub const MAX_CATEGORIES: usize = 50;
// One colour each for the values of the axis the cases are coloured by, all distinct.
const _: () = assert!(MAX_COLOURS <= COLOURS);
/// Width of a categorical column's strip of dots, in columns (the next column's starts
/// 1 − this away).
const STRIP_WIDTH: f64 = 0.8;

/// One metric against one axis, for one colour, accumulated row by row.
#[derive(Debug, Clone, Default)]
struct Pair {
    /// A sample of the points: every `stride`-th one seen.
    points: Vec<[f64; 2]>,
    stride: usize,
    seen: usize,
    /// Sum and count of the metric at each distinct axis value, while they are few.
    levels: Option<Vec<(f64, f64, usize)>>,
}

impl Pair {
    fn new() -> Pair {
        Pair {
            points: Vec::new(),
            stride: 1,
            seen: 0,
            levels: Some(Vec::new()),
        }
    }

    fn add(&mut self, x: f64, y: f64) {
        if self.seen.is_multiple_of(self.stride) {
            self.points.push([x, y]);
            if self.points.len() > MAX_POINTS {
                // Keep every other point: the sample becomes every (2·stride)-th row.
                let mut k = 0;
                self.points.retain(|_| {
                    k += 1;
                    k % 2 == 1
                });
                self.stride *= 2;
            }
        }
        self.seen += 1;
        if let Some(levels) = &mut self.levels {
            match levels.iter().position(|(v, ..)| *v == x) {
                Some(i) => {
                    if let Some((_, sum, n)) = levels.get_mut(i) {
                        *sum += y;
                        *n += 1;
                    }
                }
                None if levels.len() < MAX_LEVELS => levels.push((x, y, 1)),
                None => self.levels = None,
            }
        }
    }

    /// The mean at each value, in increasing value order, when there are several values.
    fn means(&self) -> Option<Vec<[f64; 2]>> {
        let mut m: Vec<[f64; 2]> = self
            .levels
            .as_ref()?
            .iter()
            .map(|&(x, sum, n)| [x, sum / n as f64])
            .collect();
        m.sort_by(|a, b| a[0].total_cmp(&b[0]));
        (m.len() >= 2).then_some(m)
    }
}

/// A file name for the plot of `axis`: its key with anything but letters, digits, `.`, `-`
/// and `_` replaced by `_`.
fn file_name(axis: &str) -> String {
    let stem: String = axis
        .chars()
        .map(|c| {
            if c.is_ascii_alphanumeric() || matches!(c, '.' | '-' | '_') {
                c
            } else {
                '_'
            }
        })
        .collect();
    format!("{stem}.svg")
}

/// A cell as a number: `None` for an empty cell, `Err` for text (a name, a list, `true`).
fn number(cell: &str) -> Result<Option<f64>, ()> {
    if cell.is_empty() {
        return Ok(None);
    }
    cell.parse::<f64>()
        .map(|x| x.is_finite().then_some(x))
        .map_err(|_| ())
}

/// What the first pass over the rows learns of an axis column.
#[derive(Debug, Clone)]
struct AxisScan {
    /// Every cell a finite number.
    numeric: bool,
    /// Every cell a whole number.
    integer: bool,
    /// The distinct cells in order of first appearance, while at most [`MAX_CATEGORIES`].
    values: Option<Vec<String>>,
}

impl AxisScan {
    fn new() -> AxisScan {
        AxisScan {
            numeric: true,
            integer: true,
            values: Some(Vec::new()),
        }
    }

    fn add(&mut self, cell: &str) {
        if cell.is_empty() {
            return;
        }
        match number(cell) {
            Ok(Some(x)) => self.integer &= x.fract() == 0.0,
            _ => {
                self.numeric = false;
                self.integer = false;
            }
        }
        if let Some(values) = &mut self.values
            && !values.iter().any(|v| v == cell)
        {
            if values.len() < MAX_CATEGORIES {
                values.push(cell.to_string());
            } else {
                self.values = None;
            }
        }
    }

    /// The distinct values, numbers in increasing order (a colour scale reads in order),
    /// text in order of first appearance; `None` past [`MAX_CATEGORIES`].
    fn levels(&self) -> Option<Vec<String>> {
        let mut v = self.values.clone()?;
        if self.numeric {
            v.sort_by(|a, b| {
                let x = |s: &str| s.parse::<f64>().unwrap_or(f64::NAN);
                x(a).total_cmp(&x(b))
            });
        }
        Some(v)
    }
}

/// The plot of one axis: its x axis, the axis it is coloured by (index and values) and the
/// accumulated points, `[metric][colour]`.
struct AxisPlot {
    axis: usize,
    categories: Option<Vec<String>>,
    integer: bool,
    color: Option<(usize, Vec<String>)>,
    pairs: Vec<Vec<Pair>>,
}

/// The colour axis of the plot against axis `i` under `color_by`.
fn color_axis(
    i: usize,
    axes: &[String],
    scans: &[AxisScan],
    color_by: &ColorBy,
) -> Result<Option<(usize, Vec<String>)>, OutputError> {
    let fits = |j: usize| {
        scans
            .get(j)
            .and_then(AxisScan::levels)
            .filter(|v| v.len() <= MAX_COLOURS)
    };
    match color_by {
        ColorBy::Off => Ok(None),
        ColorBy::Auto => Ok((0..axes.len())
            .filter(|&j| j != i)
            .find_map(|j| fits(j).filter(|v| v.len() >= 2).map(|v| (j, v)))),
        ColorBy::Axis(name) => {
            let Some(j) = axes.iter().position(|a| a == name) else {
                return Err(OutputError::ColorBy {
                    axis: name.clone(),
                    reason: format!("the sweep's axes are {}", axes.join(", ")),
                });
            };
            if j == i {
                return Ok(None);
            }
            match fits(j) {
                Some(v) => Ok(Some((j, v))),
                None => Err(OutputError::ColorBy {
                    axis: name.clone(),
                    reason: format!("it has more than {MAX_COLOURS} values, one colour each"),
                }),
            }
        }
    }
}

/// The x of the `k`-th sampled point of colour `c` (of `colours`) in category `x`: its
/// colour's share of the column's strip, spread over it by the golden ratio's fractional
/// parts (evenly, and the same on every run).
fn strip_x(x: f64, c: usize, colours: usize, k: usize) -> f64 {
    let share = STRIP_WIDTH / colours.max(1) as f64;
    let centre = x - 0.5 * STRIP_WIDTH + (c as f64 + 0.5) * share;
    let spread = (k as f64 * 0.618_033_988_749_895).fract() - 0.5;
    centre + 0.6 * share * spread
}

/// Draws the plots of `results` (a `results.csv` whose axis columns are `axes`) into `dir`,
/// titled after `scenario`, the cases coloured as `color_by` says, after removing the SVG
/// files an earlier run left there. A numeric axis gets a scatter, a categorical one (any
/// non-numeric value, at most [`MAX_CATEGORIES`] distinct) a box and strip per value; a
/// categorical axis of more values has no plot, nor does a metric with a non-numeric value
/// (`true`/`false`). Returns the files written.
///
/// # Errors
/// The file that could not be read or written, a plot that could not be drawn, or a
/// [`ColorBy::Axis`] that is not one of `axes` or has more than [`MAX_COLOURS`] values.
pub fn write_plots(
    results: &Path,
    axes: &[String],
    scenario: &str,
    color_by: &ColorBy,
    dir: &Path,
) -> Result<Vec<PathBuf>, OutputError> {
    let open = || {
        csv::ReaderBuilder::new()
            .from_path(results)
            .map_err(csv_at(results))
    };
    let mut reader = open()?;
    let header = reader.headers().map_err(csv_at(results))?.clone();
    // case, the axes, the metrics, then notes, error and checksum.
    let metrics: Vec<String> = header
        .iter()
        .skip(1 + axes.len())
        .take_while(|&name| name != NOTES_COLUMN)
        .map(str::to_string)
        .collect();
    let mut scans = vec![AxisScan::new(); axes.len()];
    let mut numeric_metric = vec![true; metrics.len()];
    let mut rows = 0usize;
    for record in reader.records() {
        let record = record.map_err(csv_at(results))?;
        rows += 1;
        for (i, scan) in scans.iter_mut().enumerate() {
            scan.add(record.get(1 + i).unwrap_or(""));
        }
        for (j, ok) in numeric_metric.iter_mut().enumerate() {
            *ok &= number(record.get(1 + axes.len() + j).unwrap_or("")).is_ok();
        }
    }
    let mut plots: Vec<AxisPlot> = Vec::new();
    for (i, scan) in scans.iter().enumerate() {
        let categories = if scan.numeric {
            None
        } else {
            match scan.levels() {
                Some(v) => Some(v),
                None => continue,
            }
        };
        let color = color_axis(i, axes, &scans, color_by)?;
        let colours = color.as_ref().map_or(1, |(_, v)| v.len());
        plots.push(AxisPlot {
            axis: i,
            categories,
            integer: scan.integer,
            color,
            pairs: vec![vec![Pair::new(); colours]; metrics.len()],
        });
    }
    let mut reader = open()?;
    for record in reader.records() {
        let record = record.map_err(csv_at(results))?;
        let cell = |i: usize| record.get(1 + i).unwrap_or("");
        for plot in &mut plots {
            let x = match &plot.categories {
                Some(names) => names
                    .iter()
                    .position(|n| n == cell(plot.axis))
                    .map(|k| k as f64),
                None => number(cell(plot.axis)).ok().flatten(),
            };
            let Some(x) = x else { continue };
            let c = match &plot.color {
                Some((j, values)) => match values.iter().position(|v| v == cell(*j)) {
                    Some(c) => c,
                    None => continue,
                },
                None => 0,
            };
            for (j, pairs) in plot.pairs.iter_mut().enumerate() {
                if !numeric_metric.get(j).copied().unwrap_or(false) {
                    continue;
                }
                let y = number(record.get(1 + axes.len() + j).unwrap_or(""))
                    .ok()
                    .flatten();
                if let (Some(y), Some(pair)) = (y, pairs.get_mut(c)) {
                    pair.add(x, y);
                }
            }
        }
    }
    if dir.is_dir() {
        for entry in std::fs::read_dir(dir).map_err(io_at(dir))? {
            let path = entry.map_err(io_at(dir))?.path();
            if path.extension().is_some_and(|e| e == "svg") {
                std::fs::remove_file(&path).map_err(io_at(&path))?;
            }
        }
    }
    let mut written = Vec::new();
    for plot in &plots {
        let Some(axis) = axes.get(plot.axis) else {
            continue;
        };
        let Some(figure) = figure(plot, axis, axes, &metrics, scenario, rows) else {
            continue;
        };
        let svg = figure.to_svg()?;
        std::fs::create_dir_all(dir).map_err(io_at(dir))?;
        let path = dir.join(file_name(axis));
        std::fs::write(&path, svg).map_err(io_at(&path))?;
        written.push(path);
    }
    Ok(written)
}

/// The figure of `plot` (against `axis`), a panel per metric with points; `None` when no
/// metric has any.
fn figure(
    plot: &AxisPlot,
    axis: &str,
    axes: &[String],
    metrics: &[String],
    scenario: &str,
    rows: usize,
) -> Option<Figure> {
    let colour_names: Vec<String> = match &plot.color {
        Some((_, values)) => values.clone(),
        None => vec!["cases".to_string()],
    };
    let colours = colour_names.len();
    let panels: Vec<Panel> = metrics
        .iter()
        .zip(&plot.pairs)
        .filter_map(|(name, pairs)| {
            let mut series = Vec::new();
            for (c, (pair, label)) in pairs.iter().zip(&colour_names).enumerate() {
                if pair.points.is_empty() {
                    continue;
                }
                let points = match plot.categories {
                    Some(_) => (0..)
                        .zip(&pair.points)
                        .map(|(k, p)| [strip_x(p[0], c, colours, k), p[1]])
                        .collect(),
                    None => pair.points.clone(),
                };
                series.push(Series {
                    name: label.clone(),
                    points,
                    kind: SeriesKind::Points,
                });
                if plot.categories.is_none()
                    && let Some(means) = pair.means()
                {
                    // The mean in the dots' colour (same name) when coloured; its own entry
                    // otherwise.
                    let mean_name = match plot.color {
                        Some(_) => label.clone(),
                        None => "mean at each value".to_string(),
                    };
                    series.push(Series::line(mean_name, means));
                }
            }
            (!series.is_empty()).then(|| Panel {
                y_label: name.clone(),
                series,
            })
        })
        .collect();
    if panels.is_empty() {
        return None;
    }
    let has_means = panels
        .iter()
        .any(|p| p.series.iter().any(|s| s.kind == SeriesKind::Line));
    let how = match (&plot.categories, has_means) {
        (Some(_), _) => "boxes: quartiles, median",
        (None, true) => "lines: the mean at each value",
        (None, false) => "",
    };
    // Uncoloured, the means have an entry of their own: only the boxes need a word.
    let legend_title = match (&plot.color, how) {
        (Some((j, _)), "") => axes.get(*j).cloned(),
        (Some((j, _)), how) => axes.get(*j).map(|c| format!("{c} ({how})")),
        (None, _) if plot.categories.is_none() => None,
        (None, how) => Some(how.to_string()),
    };
    let (x_axis, verb) = match &plot.categories {
        Some(names) => (XAxis::Categories(names.clone()), "for each"),
        None if plot.integer => (XAxis::Integer, "against"),
        None => (XAxis::Continuous, "against"),
    };
    Some(Figure {
        title: format!("{scenario}: each metric {verb} {axis} ({rows} cases)"),
        x_label: axis.to_string(),
        x_axis,
        panels,
        equal_aspect: false,
        legend_title,
    })
}

#[cfg(test)]
mod tests;
