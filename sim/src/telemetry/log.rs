//! A vehicle's samples over a run of any length, in bounded memory.
//!
//! A [`Sample`] in memory takes about 450 bytes (its `Option`s and tyre table); a run of a
//! million steps kept as samples needed close to a gigabyte. The log keeps each sample as its
//! [`SAMPLE_COLUMNS`] values (f64, NaN where a quantity does not exist: 304 bytes) and, past
//! [`MEMORY_ROWS`] rows, moves them to an unnamed temporary file, so that a run's memory stays
//! near 12 MB whatever its length. Reading the log back gives the same values bit for bit.

use std::fs::File;
use std::io::{self, BufReader, BufWriter, Read, Seek, SeekFrom, Write};
use std::sync::atomic::{AtomicU64, Ordering};

use super::{SAMPLE_COLUMNS, Sample};

/// Rows kept in memory before they move to the temporary file: 16,384 rows of 304 bytes,
/// 5 MB (twice that while they are written out).
pub const MEMORY_ROWS: usize = 16_384;

/// Bytes of one row.
const ROW_BYTES: usize = SAMPLE_COLUMNS * 8;

/// One sample's values as a row: NaN where a quantity does not exist.
pub type Row = [f64; SAMPLE_COLUMNS];

/// A vehicle's samples in time order, in memory and, past [`MEMORY_ROWS`], in a temporary file.
#[derive(Debug, Default)]
pub struct TelemetryLog {
    /// The newest rows, `SAMPLE_COLUMNS` values each.
    recent: Vec<f64>,
    /// The older rows, native-endian f64, created at the first spill.
    spilled: Option<File>,
    /// Rows in `spilled`.
    spilled_rows: usize,
    /// Why spilling stopped, if the temporary file could not be written (the rows then stay
    /// in memory).
    spill_error: Option<String>,
}

/// Numbers the temporary files of this process.
static NEXT_FILE: AtomicU64 = AtomicU64::new(0);

/// A new temporary file for reading and writing, removed from its directory at once where the
/// system allows it (Unix: the data lives until the file is closed).
pub(super) fn temporary_file() -> io::Result<File> {
    let n = NEXT_FILE.fetch_add(1, Ordering::Relaxed);
    let path = std::env::temp_dir().join(format!(
        "vehicle-sim-telemetry-{}-{n}.f64",
        std::process::id()
    ));
    let file = File::options()
        .read(true)
        .write(true)
        .create_new(true)
        .open(&path)?;
    // Where an open file cannot be removed the file stays behind in the temporary directory;
    // the log still works.
    let _ = std::fs::remove_file(&path);
    Ok(file)
}

impl TelemetryLog {
    /// An empty log.
    pub fn new() -> Self {
        TelemetryLog::default()
    }

    /// The number of samples.
    pub fn len(&self) -> usize {
        self.spilled_rows + self.recent.len() / SAMPLE_COLUMNS
    }

    /// True before the first sample.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// Why older samples could not be moved to a temporary file (they are kept in memory).
    pub fn spill_error(&self) -> Option<&str> {
        self.spill_error.as_deref()
    }

    /// Appends `sample`.
    pub fn push(&mut self, sample: &Sample) {
        self.recent
            .extend(sample.values().map(|v| v.unwrap_or(f64::NAN)));
        if self.recent.len() >= MEMORY_ROWS * SAMPLE_COLUMNS
            && self.spill_error.is_none()
            && let Err(e) = self.spill()
        {
            self.spill_error = Some(e.to_string());
        }
    }

    /// Moves the rows in memory to the end of the temporary file.
    fn spill(&mut self) -> io::Result<()> {
        let file = match &mut self.spilled {
            Some(f) => f,
            None => self.spilled.insert(temporary_file()?),
        };
        file.seek(SeekFrom::End(0))?;
        let mut out = BufWriter::new(&*file);
        for v in &self.recent {
            out.write_all(&v.to_ne_bytes())?;
        }
        out.flush()?;
        self.spilled_rows += self.recent.len() / SAMPLE_COLUMNS;
        self.recent.clear();
        Ok(())
    }

    /// Keeps the first `len` samples and drops the rest (nothing if the log holds no more):
    /// a restored [`crate::Snapshot`] puts the log back to its length then. Rows dropped from
    /// the temporary file go with the file's tail; rows still in memory past the file's end
    /// are dropped with it.
    ///
    /// # Errors
    /// The error of shortening the temporary file.
    pub(crate) fn truncate(&mut self, len: usize) -> io::Result<()> {
        if len >= self.spilled_rows {
            self.recent
                .truncate((len - self.spilled_rows) * SAMPLE_COLUMNS);
            return Ok(());
        }
        if let Some(file) = &self.spilled {
            file.set_len((len * ROW_BYTES) as u64)?;
        }
        self.spilled_rows = len;
        self.recent.clear();
        Ok(())
    }

    /// The last sample's row, if any.
    pub fn last(&self) -> Option<Row> {
        let n = self.recent.len();
        if n >= SAMPLE_COLUMNS {
            return row_of(&self.recent[n - SAMPLE_COLUMNS..]);
        }
        // Only after a spill that emptied memory: the file's last row, read alone (Python's
        // `state` asks for it every step).
        let mut file = self.spilled.as_ref()?;
        let last = self.spilled_rows.checked_sub(1)?;
        file.seek(SeekFrom::Start((last * ROW_BYTES) as u64)).ok()?;
        let mut bytes = [0u8; ROW_BYTES];
        file.read_exact(&mut bytes).ok()?;
        Some(row_of_bytes(&bytes))
    }

    /// Calls `f` on every row in time order.
    ///
    /// # Errors
    /// The error of reading the temporary file back.
    pub fn for_each(&self, mut f: impl FnMut(&Row)) -> io::Result<()> {
        if let Some(file) = &self.spilled {
            let mut file = file;
            file.seek(SeekFrom::Start(0))?;
            let mut reader = BufReader::new(file).take((self.spilled_rows * ROW_BYTES) as u64);
            let mut bytes = [0u8; ROW_BYTES];
            for _ in 0..self.spilled_rows {
                reader.read_exact(&mut bytes)?;
                f(&row_of_bytes(&bytes));
            }
        }
        for chunk in self.recent.chunks_exact(SAMPLE_COLUMNS) {
            if let Some(row) = row_of(chunk) {
                f(&row);
            }
        }
        Ok(())
    }

    /// Every sample, in time order.
    ///
    /// # Errors
    /// The error of reading the temporary file back.
    pub fn samples(&self) -> io::Result<Vec<Sample>> {
        let mut out = Vec::with_capacity(self.len());
        self.for_each(|r| out.push(Sample::from_row(r)))?;
        Ok(out)
    }
}

/// A row as the temporary file holds it (native-endian f64).
fn row_of_bytes(bytes: &[u8; ROW_BYTES]) -> Row {
    let mut row = [0.0; SAMPLE_COLUMNS];
    for (v, b) in row.iter_mut().zip(bytes.chunks_exact(8)) {
        let mut ne = [0u8; 8];
        ne.copy_from_slice(b);
        *v = f64::from_ne_bytes(ne);
    }
    row
}

/// A slice of `SAMPLE_COLUMNS` values as a row.
fn row_of(values: &[f64]) -> Option<Row> {
    values.try_into().ok()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::vehicle::TyreTelemetry;
    use vehicle_model::PerWheel;

    fn sample(i: usize) -> Sample {
        let t = i as f64;
        Sample {
            time: 0.01 * t,
            x: t / 3.0,
            gear: i.is_multiple_of(3).then_some(2),
            rpm: Some(1000.0 + t),
            tyres: i.is_multiple_of(2).then(|| {
                PerWheel::splat(TyreTelemetry {
                    fz: 4000.0 + t,
                    ..TyreTelemetry::default()
                })
            }),
            ..Sample::default()
        }
    }

    #[test]
    fn a_long_log_spills_and_reads_back_bit_for_bit() {
        let n = 2 * MEMORY_ROWS + 17;
        let mut log = TelemetryLog::new();
        for i in 0..n {
            log.push(&sample(i));
        }
        assert_eq!(log.len(), n);
        assert_eq!(log.spill_error(), None);
        // Two spills: what stays in memory is the last 17 rows.
        assert_eq!(log.recent.len(), 17 * SAMPLE_COLUMNS);
        let back = log.samples().unwrap();
        assert_eq!(back.len(), n);
        for (i, s) in back.iter().enumerate() {
            assert_eq!(*s, sample(i), "row {i}");
        }
        assert_eq!(
            log.last().map(|r| Sample::from_row(&r)),
            Some(sample(n - 1))
        );
        // Reading does not disturb appending.
        log.push(&sample(n));
        assert_eq!(log.samples().unwrap().last(), Some(&sample(n)));
    }

    #[test]
    fn a_log_just_spilled_still_has_its_last_row() {
        let mut log = TelemetryLog::new();
        for i in 0..MEMORY_ROWS {
            log.push(&sample(i));
        }
        assert!(log.recent.is_empty());
        assert_eq!(
            log.last().map(|r| Sample::from_row(&r)),
            Some(sample(MEMORY_ROWS - 1))
        );
    }

    #[test]
    fn truncating_into_the_file_or_memory_keeps_the_first_rows() {
        let n = MEMORY_ROWS + 40;
        for keep in [MEMORY_ROWS + 5, 100, 0] {
            let mut log = TelemetryLog::new();
            for i in 0..n {
                log.push(&sample(i));
            }
            log.truncate(keep).unwrap();
            assert_eq!(log.len(), keep);
            // Appending goes on after the kept rows, in the file too.
            for i in keep..n {
                log.push(&sample(i));
            }
            let back = log.samples().unwrap();
            assert_eq!(back.len(), n, "keep {keep}");
            for (i, s) in back.iter().enumerate() {
                assert_eq!(*s, sample(i), "keep {keep}, row {i}");
            }
        }
    }
}
