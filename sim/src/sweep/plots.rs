//! The summary plots of a sweep: for each numeric axis, one SVG figure with a panel per
//! numeric metric, every case a dot and, for an axis with few distinct values, the mean over
//! the cases at each value as a line.
//!
//! They are drawn from `results.csv`, read as a stream, so `vehicle-sim sweep` and
//! `sweep-merge` draw the same plots of the same rows; a sample of at most
//! [`MAX_POINTS`] cases per panel (every `2^k`-th row) keeps the memory flat for any
//! number of cases, while the means take every case.

use std::path::{Path, PathBuf};

use crate::report::{Figure, Panel, Series, SeriesKind};

use super::error::{OutputError, csv_at, io_at};
use super::row::NOTES_COLUMN;

/// Most dots kept per panel: the plots draw 1000 at most anyway.
pub const MAX_POINTS: usize = 1000;
/// Most distinct values of an axis for which the mean line is drawn (beyond, e.g. random
/// draws, each value has one case and the dots say it all).
pub const MAX_LEVELS: usize = 50;

/// One metric against one axis, accumulated row by row.
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

/// Draws the plots of `results` (a `results.csv` whose axis columns are `axes`) into `dir`,
/// titled after `scenario`, after removing the SVG files an earlier run left there. Axes and
/// metrics with any non-numeric value (a model name, a list, `true`/`false`) have no plot.
/// Returns the files written.
///
/// # Errors
/// The file that could not be read or written, or a plot that could not be drawn.
pub fn write_plots(
    results: &Path,
    axes: &[String],
    scenario: &str,
    dir: &Path,
) -> Result<Vec<PathBuf>, OutputError> {
    let mut reader = csv::ReaderBuilder::new()
        .from_path(results)
        .map_err(csv_at(results))?;
    let header = reader.headers().map_err(csv_at(results))?.clone();
    // case, the axes, the metrics, then notes, error and checksum.
    let metrics: Vec<String> = header
        .iter()
        .skip(1 + axes.len())
        .take_while(|&name| name != NOTES_COLUMN)
        .map(str::to_string)
        .collect();
    let mut pairs = vec![vec![Pair::new(); metrics.len()]; axes.len()];
    let mut numeric_axis = vec![true; axes.len()];
    let mut numeric_metric = vec![true; metrics.len()];
    let mut rows = 0usize;
    let mut xs: Vec<Option<f64>> = Vec::with_capacity(axes.len());
    for record in reader.records() {
        let record = record.map_err(csv_at(results))?;
        rows += 1;
        xs.clear();
        for (i, ok) in numeric_axis.iter_mut().enumerate() {
            let x = number(record.get(1 + i).unwrap_or("")).unwrap_or_else(|()| {
                *ok = false;
                None
            });
            xs.push(x.filter(|_| *ok));
        }
        for (j, ok) in numeric_metric.iter_mut().enumerate() {
            let cell = record.get(1 + axes.len() + j).unwrap_or("");
            let Some(y) = number(cell).unwrap_or_else(|()| {
                *ok = false;
                None
            }) else {
                continue;
            };
            if !*ok {
                continue;
            }
            for (i, x) in xs.iter().enumerate() {
                if let (Some(x), Some(pair)) = (x, pairs.get_mut(i).and_then(|p| p.get_mut(j))) {
                    pair.add(*x, y);
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
    for (i, axis) in axes.iter().enumerate() {
        if !numeric_axis.get(i).copied().unwrap_or(false) {
            continue;
        }
        let panels: Vec<Panel> = metrics
            .iter()
            .enumerate()
            .filter(|&(j, _)| numeric_metric.get(j).copied().unwrap_or(false))
            .filter_map(|(j, name)| {
                let pair = pairs.get(i)?.get(j)?;
                if pair.points.is_empty() {
                    return None;
                }
                let mut series = vec![Series {
                    name: "cases".to_string(),
                    points: pair.points.clone(),
                    kind: SeriesKind::Points,
                }];
                if let Some(means) = pair.means() {
                    series.push(Series::line("mean at each value", means));
                }
                Some(Panel {
                    y_label: name.clone(),
                    series,
                })
            })
            .collect();
        if panels.is_empty() {
            continue;
        }
        let figure = Figure {
            title: format!("{scenario}: each metric against {axis} ({rows} cases)"),
            x_label: axis.clone(),
            panels,
            equal_aspect: false,
        };
        let svg = figure.to_svg()?;
        std::fs::create_dir_all(dir).map_err(io_at(dir))?;
        let path = dir.join(file_name(axis));
        std::fs::write(&path, svg).map_err(io_at(&path))?;
        written.push(path);
    }
    Ok(written)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_sample_stays_small_and_the_means_exact() {
        let mut p = Pair::new();
        for k in 0..10_000 {
            p.add(f64::from(k % 3), f64::from(k));
        }
        assert!(p.points.len() <= MAX_POINTS, "{}", p.points.len());
        assert!(p.points.len() > MAX_POINTS / 2);
        // Every kept point is a row of the sample: a multiple of the stride.
        assert!(
            p.points
                .iter()
                .all(|q| (q[1] as usize).is_multiple_of(p.stride))
        );
        // Rows 0, 3, 6, … 9999 have x = 0: their mean is 4999.5.
        assert_eq!(p.means().unwrap()[0], [0.0, 4999.5]);
        let mut many = Pair::new();
        for k in 0..=MAX_LEVELS {
            many.add(k as f64, 1.0);
        }
        assert_eq!(many.means(), None);
        assert_eq!(file_name("box[1].friction"), "box_1_.friction.svg");
        assert_eq!(number("1.5"), Ok(Some(1.5)));
        assert_eq!(number(""), Ok(None));
        assert_eq!(number("true"), Err(()));
    }
}
