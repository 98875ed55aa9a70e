//! One case's outcome as a row of `results.csv`: its index, its axis values, its metrics, its
//! notes, the error of a case that did not run, and a checksum of those cells.
//!
//! The checksum (FNV-1a, 64 bits, of the other cells each followed by the ASCII unit
//! separator 0x1F, as 16 lowercase hexadecimal digits) lets `sweep-merge` and
//! `sweep --resume` tell a row written by a run from one edited or damaged afterwards. It is
//! not a signature: anyone can recompute it; it catches accidents (a hand-edited value, a
//! file cut or spliced), not forgery.

use core::fmt;
use std::io::Write;

use crate::report::{METRIC_DIGITS, significant};
use crate::scenario::{RunReport, ScenarioError, Value};
use crate::world_file::WorldFileError;

use super::value::AxisValue;

/// The columns of `results.csv`: `case`, one per axis (its key), one per metric, `notes`,
/// `error`, `checksum`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct Columns {
    /// The axes' keys, in the sweep file's order.
    pub axes: Vec<String>,
    /// The metrics' names: the scenario's JSON keys (`stop_distance_m`), prefixed with the
    /// scenario's name when the run has several (`test-track`: `brake.stop_distance_m`) and
    /// with the vehicle's name for a vehicle's own metric (`programme`:
    /// `bmw.distance_m`); each result's `sim_seconds` last.
    pub metrics: Vec<String>,
}

/// The first column: the case's index.
pub const CASE_COLUMN: &str = "case";
/// The column of the scenario's notes (e.g. a lane change not completed), `; `-separated.
pub const NOTES_COLUMN: &str = "notes";
/// The column after the notes: why the case did not run, empty when it did.
pub const ERROR_COLUMN: &str = "error";
/// The last column: the checksum of the row's other cells (see the module's documentation).
pub const CHECKSUM_COLUMN: &str = "checksum";

/// The checksum of a row's cells (every cell but the checksum, in column order): 16 lowercase
/// hexadecimal digits.
pub fn checksum<I, S>(cells: I) -> String
where
    I: IntoIterator<Item = S>,
    S: AsRef<[u8]>,
{
    let mut bytes = Vec::new();
    for c in cells {
        bytes.extend_from_slice(c.as_ref());
        bytes.push(0x1F);
    }
    format!("{:016x}", super::draw::fnv1a(&bytes))
}

/// Whether a record of `results.csv` (every cell, the checksum last) carries the checksum of
/// its other cells.
pub fn checksum_matches(record: &csv::StringRecord) -> bool {
    let n = record.len();
    n > 1 && record.get(n - 1) == Some(checksum(record.iter().take(n - 1)).as_str())
}

impl Columns {
    /// Every column name, in order.
    pub fn names(&self) -> Vec<&str> {
        std::iter::once(CASE_COLUMN)
            .chain(self.axes.iter().map(String::as_str))
            .chain(self.metrics.iter().map(String::as_str))
            .chain([NOTES_COLUMN, ERROR_COLUMN, CHECKSUM_COLUMN])
            .collect()
    }

    /// The header line of `results.csv`, with its line end.
    pub fn csv_header(&self) -> String {
        csv_line(self.names())
    }
}

/// A metric's cell.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Cell {
    /// A number rounded to 6 significant digits, as in `metrics.json`.
    Number(f64),
    /// A yes/no outcome.
    Bool(bool),
    /// Not measured (the event did not happen in time), or the case did not run.
    Empty,
}

impl Cell {
    /// The cell of a metric's value: numbers rounded to [`METRIC_DIGITS`] significant digits,
    /// a non-finite number empty (as `null` in JSON).
    pub fn of(v: Value) -> Cell {
        match v {
            Value::Number(x) if x.is_finite() => Cell::Number(significant(x, METRIC_DIGITS)),
            Value::Bool(b) => Cell::Bool(b),
            Value::Number(_) | Value::Missing => Cell::Empty,
        }
    }
}

impl fmt::Display for Cell {
    /// As the CSV writes it: the number's shortest exact decimal form, `true`/`false`, or
    /// nothing.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            Cell::Number(x) => write!(f, "{x}"),
            Cell::Bool(b) => write!(f, "{b}"),
            Cell::Empty => Ok(()),
        }
    }
}

/// Why a case has no metrics: its `error` cell. A failing case never stops a sweep.
#[derive(Debug, Clone, PartialEq, thiserror::Error)]
#[non_exhaustive]
pub enum CaseError {
    /// The case's world is invalid: the world file's message, naming the key (without the
    /// file and line, which are the base world's: the value is in the row).
    #[error("{}", .0.message())]
    World(WorldFileError),
    /// A value of the case that a world file would replace by its default with a warning (as
    /// Webots does): a sweep runs a case with its own values or not at all.
    #[error("invalid '{key}': a world file would replace the value: {message}")]
    Replaced {
        /// The key, e.g. `vehicle.mass`.
        key: String,
        /// The world file's warning.
        message: String,
    },
    /// The scenario cannot run on the case's world, or the simulation failed.
    #[error(transparent)]
    Scenario(ScenarioError),
    /// The case reports metrics that the base world does not (an axis changed what the world
    /// drives, e.g. a vehicle's name): the columns are the base world's.
    #[error(
        "the case reports metrics that are not columns of the sweep ({}): its world drives \
         other vehicles than the base world",
        .0.join(", ")
    )]
    Columns(Vec<String>),
    /// The case panicked (a bug: please report it with the case's values).
    #[error("the case panicked: {0}")]
    Panic(String),
}

/// One case's row.
#[derive(Debug, Clone, PartialEq)]
pub struct Row {
    /// The case's index.
    pub case: usize,
    /// Its axis values, in the axes' order.
    pub values: Vec<AxisValue>,
    /// Its metrics, one per [`Columns::metrics`]; all empty when it failed.
    pub metrics: Vec<Cell>,
    /// The scenario's notes.
    pub notes: Vec<String>,
    /// Why it did not run.
    pub error: Option<CaseError>,
}

impl Row {
    /// The row of a case whose run produced `report`, with the metrics of `columns`.
    pub(crate) fn of_report(
        case: usize,
        values: Vec<AxisValue>,
        columns: &Columns,
        report: &RunReport,
    ) -> Row {
        let measured = metric_cells(report);
        let unknown: Vec<String> = measured
            .iter()
            .filter(|(name, _)| !columns.metrics.contains(name))
            .map(|(name, _)| name.clone())
            .collect();
        if !unknown.is_empty() {
            return Row::failed(case, values, columns, CaseError::Columns(unknown));
        }
        let metrics = columns
            .metrics
            .iter()
            .map(|c| {
                measured
                    .iter()
                    .find(|(name, _)| name == c)
                    .map_or(Cell::Empty, |&(_, cell)| cell)
            })
            .collect();
        Row {
            case,
            values,
            metrics,
            notes: report
                .results
                .iter()
                .flat_map(|r| r.notes.clone())
                .collect(),
            error: None,
        }
    }

    /// The row of a case that did not run.
    pub(crate) fn failed(
        case: usize,
        values: Vec<AxisValue>,
        columns: &Columns,
        error: CaseError,
    ) -> Row {
        Row {
            case,
            values,
            metrics: vec![Cell::Empty; columns.metrics.len()],
            notes: Vec::new(),
            error: Some(error),
        }
    }

    /// The row's cells as the CSV writes them, in column order, its checksum last.
    pub fn cells(&self) -> Vec<String> {
        let mut cells: Vec<String> = std::iter::once(self.case.to_string())
            .chain(self.values.iter().map(ToString::to_string))
            .chain(self.metrics.iter().map(ToString::to_string))
            .chain([
                self.notes.join("; "),
                self.error
                    .as_ref()
                    .map(ToString::to_string)
                    .unwrap_or_default(),
            ])
            .collect();
        cells.push(checksum(&cells));
        cells
    }

    /// The row's checksum (its last cell).
    pub fn checksum(&self) -> String {
        self.cells().pop().unwrap_or_default()
    }

    /// The row's line of `results.csv`, with its line end: what the `vehicle-sim sweep`
    /// command writes for this case, byte for byte.
    pub fn csv_line(&self) -> String {
        csv_line(self.cells())
    }
}

/// The metrics of a run by column name (see [`Columns::metrics`]).
pub(crate) fn metric_cells(report: &RunReport) -> Vec<(String, Cell)> {
    let several = report.results.len() > 1;
    let mut out = Vec::new();
    for r in &report.results {
        let prefix = if several {
            format!("{}.", r.name)
        } else {
            String::new()
        };
        for m in &r.metrics {
            let vehicle = m
                .vehicle
                .as_ref()
                .map(|v| format!("{v}."))
                .unwrap_or_default();
            out.push((format!("{prefix}{vehicle}{}", m.key), Cell::of(m.value)));
        }
        out.push((
            format!("{prefix}sim_seconds"),
            Cell::of(Value::Number(r.sim_seconds)),
        ));
    }
    out
}

/// A CSV writer of `results.csv`'s dialect (the `csv` crate's defaults: `,`, `"` quoting
/// only where needed, `\n` line ends), shared by every writer of sweep outputs so that they
/// agree byte for byte.
pub(crate) fn csv_writer<W: Write>(out: W) -> csv::Writer<W> {
    csv::WriterBuilder::new()
        .has_headers(false)
        .terminator(csv::Terminator::Any(b'\n'))
        .from_writer(out)
}

/// One CSV record as a line.
fn csv_line<I, S>(cells: I) -> String
where
    I: IntoIterator<Item = S>,
    S: AsRef<[u8]>,
{
    let mut w = csv_writer(Vec::new());
    // Writing to memory cannot fail.
    let _ = w.write_record(cells);
    let bytes = w.into_inner().unwrap_or_default();
    String::from_utf8(bytes).unwrap_or_default()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::{Metric, ScenarioResult};

    fn columns() -> Columns {
        Columns {
            axes: vec!["ground.friction".into()],
            metrics: vec![
                "stop_distance_m".into(),
                "at_rest".into(),
                "sim_seconds".into(),
            ],
        }
    }

    fn report(metrics: Vec<Metric>) -> RunReport {
        RunReport {
            results: vec![ScenarioResult {
                name: "brake".into(),
                metrics,
                sim_seconds: 12.345_678_9,
                notes: vec!["a, note".into()],
                ..ScenarioResult::default()
            }],
            ..RunReport::default()
        }
    }

    #[test]
    fn a_row_in_column_order_rounded() {
        let r = report(vec![
            Metric::flag("at_rest", "", true),
            Metric::number("stop_distance_m", "", "m", 47.219_512_3),
        ]);
        let row = Row::of_report(3, vec![AxisValue::Float(0.6)], &columns(), &r);
        assert_eq!(
            columns().csv_header(),
            "case,ground.friction,stop_distance_m,at_rest,sim_seconds,notes,error,checksum\n"
        );
        // The checksums are FNV-1a of the cells each followed by 0x1F, computed independently.
        assert_eq!(
            row.csv_line(),
            "3,0.6,47.2195,true,12.3457,\"a, note\",,5191c35b5f99ed44\n"
        );
        // A missing metric is an empty cell; an error row has only its values and the error.
        let r = report(vec![Metric::maybe("stop_distance_m", "", "m", None)]);
        let row = Row::of_report(0, vec![AxisValue::Integer(1)], &columns(), &r);
        assert_eq!(
            row.csv_line(),
            "0,1,,,12.3457,\"a, note\",,24216758be777354\n"
        );
        let failed = Row::failed(
            1,
            vec![AxisValue::Integer(1)],
            &columns(),
            CaseError::Panic("x".into()),
        );
        assert_eq!(
            failed.csv_line(),
            "1,1,,,,,the case panicked: x,3ff5605deea30b4e\n"
        );
    }

    #[test]
    fn an_edited_cell_breaks_the_checksum() {
        let record = |cells: &[&str]| csv::StringRecord::from(cells.to_vec());
        let written = [
            "3",
            "0.6",
            "47.2195",
            "true",
            "12.3457",
            "a, note",
            "",
            "5191c35b5f99ed44",
        ];
        assert!(checksum_matches(&record(&written)));
        let mut edited = written;
        edited[2] = "47.2196";
        assert!(!checksum_matches(&record(&edited)));
        // A cell moved across a separator changes the hash: "a" + "bc" is not "ab" + "c".
        assert_ne!(checksum(["a", "bc"]), checksum(["ab", "c"]));
        assert!(!checksum_matches(&record(&["5191c35b5f99ed44"])));
    }

    #[test]
    fn metrics_that_are_no_column_fail_the_case() {
        let r = report(vec![Metric::number("distance_m", "", "m", 1.0).of("bmw")]);
        let row = Row::of_report(0, vec![AxisValue::Integer(1)], &columns(), &r);
        assert_eq!(
            row.error.map(|e| e.to_string()).as_deref(),
            Some(
                "the case reports metrics that are not columns of the sweep (bmw.distance_m): \
                 its world drives other vehicles than the base world"
            )
        );
    }
}
