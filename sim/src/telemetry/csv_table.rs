//! The telemetry CSV table: written row by row ([`CsvWriter`], [`write_csv`]) and read back
//! ([`read_csv`]) for plotting earlier runs.

use std::io::Write;

use super::{CSV_HEADER, ENERGY_COLUMN, SAMPLE_COLUMNS, Sample, Telemetry, VehicleKind};

/// Decimal places of the CSV cells: six are below any quantity's measurement noise here (the
/// physics runs in f32, about seven significant digits).
const CSV_DECIMALS: i32 = 6;

/// A CSV cell: `v` rounded to [`CSV_DECIMALS`] places, empty for a missing or non-finite value;
/// a value that rounds to zero is `0`, never `-0`.
fn cell(v: Option<f64>) -> String {
    match v.filter(|v| v.is_finite()) {
        Some(v) => {
            let scale = 10f64.powi(CSV_DECIMALS);
            // Adding +0.0 turns the −0.0 of a tiny negative value into 0.0.
            format!("{}", (v * scale).round() / scale + 0.0)
        }
        None => String::new(),
    }
}

/// A telemetry CSV table being written row by row: the header ([`CSV_HEADER`]) first, then
/// one row per sample, the scenario and vehicle names in the first two columns; missing and
/// non-finite values are empty cells.
pub struct CsvWriter<W: Write> {
    out: csv::Writer<W>,
    row: Vec<String>,
}

impl<W: Write> CsvWriter<W> {
    /// Writes the header to `out`.
    ///
    /// # Errors
    /// The write error.
    pub fn new(out: W) -> Result<Self, csv::Error> {
        let mut out = csv::WriterBuilder::new()
            .has_headers(false)
            .from_writer(out);
        out.write_record(CSV_HEADER.split(','))?;
        Ok(CsvWriter {
            out,
            row: Vec::with_capacity(2 + SAMPLE_COLUMNS),
        })
    }

    /// Writes one row: a sample's [`Sample::values`] (or a [`Row`](super::Row), NaN for missing).
    ///
    /// # Errors
    /// The write error.
    pub fn write(
        &mut self,
        scenario: &str,
        vehicle: &str,
        values: impl IntoIterator<Item = Option<f64>>,
    ) -> Result<(), csv::Error> {
        self.row.clear();
        self.row.push(scenario.to_string());
        self.row.push(vehicle.to_string());
        self.row.extend(values.into_iter().map(cell));
        self.out.write_record(&self.row)
    }

    /// Flushes what is written.
    ///
    /// # Errors
    /// The write error.
    pub fn finish(mut self) -> Result<(), csv::Error> {
        self.out.flush()?;
        Ok(())
    }
}

/// Writes `runs` as one CSV table ([`CsvWriter`]) to `out`.
///
/// # Errors
/// The first write error.
pub fn write_csv<'a>(
    out: impl Write,
    runs: impl IntoIterator<Item = &'a Telemetry>,
) -> Result<(), csv::Error> {
    let mut w = CsvWriter::new(out)?;
    for run in runs {
        for s in &run.samples {
            w.write(&run.scenario, &run.vehicle, s.values())?;
        }
    }
    w.finish()
}

/// Why a telemetry CSV cannot be read back.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum ReadError {
    /// The file cannot be read or is no CSV.
    #[error("{0}")]
    Csv(#[from] csv::Error),
    /// The header is neither [`CSV_HEADER`] nor the one before the energy columns: not a
    /// telemetry file of this version or the previous one.
    #[error("the header is not that of a telemetry file (scenario,car,time_s,...)")]
    Header,
    /// A cell is not a number.
    #[error("line {line}, column '{column}': '{value}' is not a number")]
    Cell {
        /// The line (1-based, the header is line 1).
        line: u64,
        /// The column's name.
        column: String,
        /// The cell.
        value: String,
    },
}

/// Reads a telemetry CSV ([`write_csv`]'s table) back: one [`Telemetry`] per run of
/// consecutive rows of the same scenario and vehicle, in file order. A vehicle with a
/// commanded steering is a car, else a robot. A file written before the five energy columns
/// existed (its header [`CSV_HEADER`] without them) reads with them empty, so that earlier
/// runs' directories still plot.
///
/// # Errors
/// The first [`ReadError`].
pub fn read_csv(input: impl std::io::Read) -> Result<Vec<Telemetry>, ReadError> {
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .from_reader(input);
    let mut records = reader.records();
    let header = records.next().transpose()?.ok_or(ReadError::Header)?;
    let columns: Vec<&str> = CSV_HEADER.split(',').collect();
    let before_energy = &columns[..2 + ENERGY_COLUMN];
    if header.iter().ne(columns.iter().copied()) && header.iter().ne(before_energy.iter().copied())
    {
        return Err(ReadError::Header);
    }
    let mut out: Vec<Telemetry> = Vec::new();
    for record in records {
        let record = record?;
        let line = record.position().map_or(0, |p| p.line());
        let mut row = [f64::NAN; SAMPLE_COLUMNS];
        for (i, (v, cell)) in row.iter_mut().zip(record.iter().skip(2)).enumerate() {
            if !cell.is_empty() {
                *v = cell.parse().map_err(|_| ReadError::Cell {
                    line,
                    column: columns[i + 2].to_string(),
                    value: cell.to_string(),
                })?;
            }
        }
        let (scenario, vehicle) = (record.get(0).unwrap_or(""), record.get(1).unwrap_or(""));
        let sample = Sample::from_row(&row);
        match out.last_mut() {
            Some(t) if t.scenario == scenario && t.vehicle == vehicle => t.samples.push(sample),
            _ => out.push(Telemetry {
                scenario: scenario.to_string(),
                vehicle: vehicle.to_string(),
                kind: VehicleKind::Robot,
                samples: vec![sample],
            }),
        }
    }
    for t in &mut out {
        if t.samples.iter().any(|s| s.steering_command.is_some()) {
            t.kind = VehicleKind::Car;
        }
    }
    Ok(out)
}

/// [`write_csv`] into a string.
pub fn to_csv<'a>(runs: impl IntoIterator<Item = &'a Telemetry>) -> String {
    let mut out = Vec::new();
    // Writing to memory cannot fail.
    let _ = write_csv(&mut out, runs);
    String::from_utf8_lossy(&out).into_owned()
}
