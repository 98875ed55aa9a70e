//! A vehicle's samples over a run of any length, in bounded memory, all of them or the last
//! few ([`Retention`]).
//!
//! A [`Sample`] in memory takes about 450 bytes (its `Option`s and tyre table); a run of a
//! million steps kept as samples needed close to a gigabyte. The log keeps each sample as its
//! [`SAMPLE_COLUMNS`] values (f64, NaN where a quantity does not exist: 344 bytes) in a
//! [`Block`] that front-ends can share without a copy ([`TelemetryLog::shared_rows`]) and,
//! keeping all of a run, past [`MEMORY_ROWS`] rows, moves them to an unnamed temporary file,
//! so that a run's memory stays near 12 MB whatever its length. Reading the log back gives
//! the same values bit for bit. The last sample is kept apart: reading it costs the same
//! whatever the log holds.

use std::fs::File;
use std::io::{self, BufReader, BufWriter, Read, Seek, SeekFrom, Write};
use std::num::NonZeroUsize;
use std::sync::atomic::{AtomicU64, Ordering};

use super::rows::{Block, SharedRows};
use super::{SAMPLE_COLUMNS, Sample};

/// Rows kept in memory before they move to the temporary file: 16,384 rows of 344 bytes,
/// 5.6 MB (twice that while they are written out).
pub const MEMORY_ROWS: usize = 16_384;

/// Rows a log makes room for at its first sample; it doubles its room up to [`MEMORY_ROWS`]
/// (a short run, or many simulations side by side, need not take 5.6 MB each).
const FIRST_ROWS: usize = 64;

/// Bytes of one row.
const ROW_BYTES: usize = SAMPLE_COLUMNS * 8;

/// One sample's values as a row: NaN where a quantity does not exist.
pub type Row = [f64; SAMPLE_COLUMNS];

/// How much of a run a [`TelemetryLog`] keeps. Whatever it keeps, the last sample is there
/// ([`TelemetryLog::last`]).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub enum Retention {
    /// Every sample: in memory, then, past [`MEMORY_ROWS`], in a temporary file.
    #[default]
    All,
    /// The last `n` samples, in memory (a ring: 2 × 344 × `n` bytes).
    Last(NonZeroUsize),
    /// None but the last.
    Off,
}

/// How far a log had got, for [`TelemetryLog::rewind`].
#[derive(Debug, Clone, Copy)]
pub struct LogMark {
    recorded: usize,
    last: Option<Row>,
}

/// A vehicle's samples in time order, as many as its [`Retention`] keeps: see the module docs.
#[derive(Debug)]
pub struct TelemetryLog {
    retention: Retention,
    /// The rows in memory. Keeping all: rows `0..held` are the newest. Keeping the last `n`: a
    /// ring of `2n` slots, sample `k` written at slots `k % n` and `k % n + n`, so that the
    /// last `held` samples are always side by side, ending at slot `(recorded − 1) % n + n`.
    block: Block,
    /// Rows in `block`.
    held: usize,
    /// Samples pushed (less those a rewind took back).
    recorded: usize,
    last: Option<Row>,
    /// The older rows, native-endian f64, created at the first spill.
    spilled: Option<File>,
    /// Rows in `spilled`.
    spilled_rows: usize,
    /// Why spilling stopped, if the temporary file could not be written (the rows then stay
    /// in memory).
    spill_error: Option<String>,
    /// Rows read back from `spilled` so far.
    rows_read: AtomicU64,
}

impl Default for TelemetryLog {
    fn default() -> Self {
        TelemetryLog::with_retention(Retention::All)
    }
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
    /// An empty log keeping every sample.
    pub fn new() -> Self {
        TelemetryLog::default()
    }

    /// An empty log keeping what `retention` says.
    pub fn with_retention(retention: Retention) -> Self {
        let slots = match retention {
            Retention::Last(n) => 2 * n.get(),
            Retention::All | Retention::Off => 0,
        };
        TelemetryLog {
            retention,
            block: Block::new(slots),
            held: 0,
            recorded: 0,
            last: None,
            spilled: None,
            spilled_rows: 0,
            spill_error: None,
            rows_read: AtomicU64::new(0),
        }
    }

    /// What it keeps.
    pub fn retention(&self) -> Retention {
        self.retention
    }

    /// The number of samples it holds (all recorded, the last `n`, or none).
    pub fn len(&self) -> usize {
        self.spilled_rows + self.held
    }

    /// True while it holds no sample.
    pub fn is_empty(&self) -> bool {
        self.len() == 0
    }

    /// The number of samples recorded, held or not.
    pub fn recorded(&self) -> usize {
        self.recorded
    }

    /// Rows read back from the temporary file so far (the cost of reading a long log).
    pub fn rows_read(&self) -> u64 {
        self.rows_read.load(Ordering::Relaxed)
    }

    /// Why older samples could not be moved to a temporary file (they are kept in memory).
    pub fn spill_error(&self) -> Option<&str> {
        self.spill_error.as_deref()
    }

    /// Appends `sample`.
    pub fn push(&mut self, sample: &Sample) {
        let row: Row = sample.values().map(|v| v.unwrap_or(f64::NAN));
        self.last = Some(row);
        self.recorded += 1;
        match self.retention {
            Retention::Off => {}
            Retention::All => {
                if self.held == self.block.capacity() {
                    self.make_room();
                }
                self.block.write(self.held, &row);
                self.held += 1;
            }
            Retention::Last(n) => {
                let n = n.get();
                if self.block.is_shared() {
                    // The slots about to be written may be on show.
                    self.block = self.block.copied(2 * n, 0, 2 * n, 0);
                }
                let slot = (self.recorded - 1) % n;
                self.block.write(slot, &row);
                self.block.write(slot + n, &row);
                self.held = (self.held + 1).min(n);
            }
        }
    }

    /// Keeping all, with the block full: spills it past [`MEMORY_ROWS`] rows, else (or if
    /// the file fails) moves to a block twice the size.
    fn make_room(&mut self) {
        let capacity = self.block.capacity();
        if capacity >= MEMORY_ROWS && self.spill_error.is_none() {
            match self.spill() {
                Ok(()) => return,
                Err(e) => self.spill_error = Some(e.to_string()),
            }
        }
        let rows = (2 * capacity).max(FIRST_ROWS);
        self.block = self.block.copied(rows, 0, self.held, 0);
    }

    /// Moves the rows in memory to the end of the temporary file.
    fn spill(&mut self) -> io::Result<()> {
        let file = match &mut self.spilled {
            Some(f) => f,
            None => self.spilled.insert(temporary_file()?),
        };
        file.seek(SeekFrom::End(0))?;
        let mut out = BufWriter::new(&*file);
        for slot in 0..self.held {
            for v in self.block.read(slot) {
                out.write_all(&v.to_ne_bytes())?;
            }
        }
        out.flush()?;
        self.spilled_rows += self.held;
        self.held = 0;
        if self.block.is_shared() {
            self.block = Block::new(self.block.capacity());
        }
        Ok(())
    }

    /// How far it has got, for [`TelemetryLog::rewind`].
    pub fn mark(&self) -> LogMark {
        LogMark {
            recorded: self.recorded,
            last: self.last,
        }
    }

    /// Takes the log back to `mark` (nothing if it has not recorded more since): the samples
    /// recorded since are dropped; a restored [`crate::Snapshot`] does it. Rows dropped from
    /// the temporary file go with the file's tail. Keeping the last `n`, the samples still in
    /// the ring stay, those overwritten since are gone.
    ///
    /// # Errors
    /// The error of shortening the temporary file.
    pub fn rewind(&mut self, mark: &LogMark) -> io::Result<()> {
        if mark.recorded >= self.recorded {
            return Ok(());
        }
        let dropped = self.recorded - mark.recorded;
        match self.retention {
            Retention::Off => {}
            Retention::Last(_) => self.held = self.held.saturating_sub(dropped),
            Retention::All => {
                let len = mark.recorded;
                if len >= self.spilled_rows {
                    let held = len - self.spilled_rows;
                    if self.block.is_shared() {
                        // The rows about to be written again may be on show.
                        self.block = self.block.copied(self.block.capacity(), 0, held, 0);
                    }
                    self.held = held;
                } else {
                    if let Some(file) = &self.spilled {
                        file.set_len((len * ROW_BYTES) as u64)?;
                    }
                    self.spilled_rows = len;
                    self.held = 0;
                    if self.block.is_shared() {
                        self.block = Block::new(self.block.capacity());
                    }
                }
            }
        }
        self.recorded = mark.recorded;
        self.last = mark.last;
        Ok(())
    }

    /// The last sample's row, if any: kept apart, so this costs the same whatever the log's
    /// length or retention.
    pub fn last(&self) -> Option<Row> {
        self.last
    }

    /// The rows held, in memory side by side, shared: what a front-end shows without a copy
    /// (see [`SharedRows`]); `None` once some have moved to the temporary file.
    pub fn shared_rows(&self) -> Option<SharedRows> {
        (self.spilled_rows == 0).then(|| self.block.share(self.first_slot(), self.held))
    }

    /// The slot of the oldest row in memory.
    fn first_slot(&self) -> usize {
        match self.retention {
            Retention::Last(n) if self.held > 0 => {
                let n = n.get();
                (self.recorded - 1) % n + n + 1 - self.held
            }
            _ => 0,
        }
    }

    /// Calls `f` on every row held, in time order.
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
                self.rows_read.fetch_add(1, Ordering::Relaxed);
                f(&row_of_bytes(&bytes));
            }
        }
        let first = self.first_slot();
        for slot in first..first + self.held {
            f(&self.block.read(slot));
        }
        Ok(())
    }

    /// Every sample held, in time order.
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
        assert_eq!(log.held, 17);
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
    fn a_log_spills_when_its_memory_is_full_and_a_row_comes() {
        let mut log = TelemetryLog::new();
        for i in 0..MEMORY_ROWS {
            log.push(&sample(i));
        }
        assert_eq!((log.held, log.spilled_rows), (MEMORY_ROWS, 0));
        log.push(&sample(MEMORY_ROWS));
        assert_eq!((log.held, log.spilled_rows), (1, MEMORY_ROWS));
        assert_eq!(
            log.last().map(|r| Sample::from_row(&r)),
            Some(sample(MEMORY_ROWS))
        );
    }

    #[test]
    fn rewinding_into_the_file_or_memory_keeps_the_first_rows() {
        let n = MEMORY_ROWS + 40;
        for keep in [MEMORY_ROWS + 5, 100, 0] {
            let mut log = TelemetryLog::new();
            let mut mark = log.mark();
            for i in 0..n {
                if i == keep {
                    mark = log.mark();
                }
                log.push(&sample(i));
            }
            // Shown rows must not change under a rewind.
            let shown = log.shared_rows();
            log.rewind(&mark).unwrap();
            assert_eq!(log.len(), keep);
            assert_eq!(
                log.last().map(|r| Sample::from_row(&r)),
                keep.checked_sub(1).map(sample)
            );
            // Appending goes on after the kept rows, in the file too.
            for i in keep..n {
                log.push(&sample(i + 1000));
            }
            let back = log.samples().unwrap();
            assert_eq!(back.len(), n, "keep {keep}");
            for (i, s) in back.iter().enumerate() {
                let expected = if i < keep {
                    sample(i)
                } else {
                    sample(i + 1000)
                };
                assert_eq!(*s, expected, "keep {keep}, row {i}");
            }
            assert!(
                shown.is_none(),
                "past MEMORY_ROWS the rows are not all in memory"
            );
        }
    }

    /// Row `i` of `rows` as a sample.
    fn shown(rows: &SharedRows, i: usize) -> Sample {
        Sample::from_row(&rows.row(i).unwrap())
    }

    #[test]
    fn shared_rows_keep_their_values_while_the_log_goes_on() {
        let mut log = TelemetryLog::new();
        for i in 0..10 {
            log.push(&sample(i));
        }
        let mark = log.mark();
        for i in 10..20 {
            log.push(&sample(i));
        }
        let rows = log.shared_rows().unwrap();
        assert_eq!(rows.rows(), 20);
        // Growing past the first block (64 rows), then rewinding and writing over rows 10..:
        // the shown rows are copied away from, never written.
        for i in 20..100 {
            log.push(&sample(i));
        }
        log.rewind(&mark).unwrap();
        for i in 10..30 {
            log.push(&sample(i + 500));
        }
        for i in 0..20 {
            assert_eq!(shown(&rows, i), sample(i), "row {i}");
        }
        let now = log.shared_rows().unwrap();
        assert_eq!(now.rows(), 30);
        assert_eq!(shown(&now, 10), sample(510));
        // Two reads with nothing recorded between them show the same memory.
        assert!(now.same_memory(&log.shared_rows().unwrap()));
        // A rewind under a shown block copies it before writing again.
        log.rewind(&mark).unwrap();
        log.push(&sample(999));
        assert_eq!(shown(&now, 10), sample(510));
        assert_eq!(log.samples().unwrap()[10], sample(999));
        assert_eq!(log.rows_read(), 0);
    }

    #[test]
    fn a_ring_holds_the_last_n_side_by_side() {
        let n = NonZeroUsize::new(5).unwrap();
        let mut log = TelemetryLog::with_retention(Retention::Last(n));
        for i in 0..3 {
            log.push(&sample(i));
        }
        assert_eq!(
            log.samples().unwrap(),
            (0..3).map(sample).collect::<Vec<_>>()
        );
        let early = log.shared_rows().unwrap();
        let mark = log.mark();
        for i in 3..13 {
            log.push(&sample(i));
        }
        assert_eq!((log.len(), log.recorded()), (5, 13));
        assert_eq!(
            log.samples().unwrap(),
            (8..13).map(sample).collect::<Vec<_>>()
        );
        let rows = log.shared_rows().unwrap();
        for i in 0..5 {
            assert_eq!(shown(&rows, i), sample(8 + i));
        }
        // The ring wrote over the slots `early` shows, in a copy.
        for i in 0..3 {
            assert_eq!(shown(&early, i), sample(i));
        }
        // Rewinding 2 samples keeps the 3 before them that are still in the ring.
        let late = log.mark();
        log.push(&sample(13));
        log.push(&sample(14));
        log.rewind(&late).unwrap();
        assert_eq!(
            log.samples().unwrap(),
            (10..13).map(sample).collect::<Vec<_>>()
        );
        // Rewinding past what the ring holds leaves it empty, with the mark's last sample.
        log.rewind(&mark).unwrap();
        assert_eq!((log.len(), log.recorded()), (0, 3));
        assert_eq!(log.last().map(|r| Sample::from_row(&r)), Some(sample(2)));
        log.push(&sample(3));
        assert_eq!(log.samples().unwrap(), vec![sample(3)]);
    }

    #[test]
    fn off_keeps_only_the_last_sample() {
        let mut log = TelemetryLog::with_retention(Retention::Off);
        for i in 0..1000 {
            log.push(&sample(i));
        }
        assert_eq!((log.len(), log.recorded()), (0, 1000));
        assert_eq!(log.samples().unwrap(), Vec::new());
        assert_eq!(log.shared_rows().map(|r| r.rows()), Some(0));
        assert_eq!(log.last().map(|r| Sample::from_row(&r)), Some(sample(999)));
    }

    #[test]
    fn the_last_sample_reads_nothing_back_whatever_the_length() {
        // Two spills (the third block is still in memory): most rows are in the file.
        // Reading the last sample a thousand times reads no row back (the work does not grow
        // with the log), reading all reads each spilled row once.
        let n = 3 * MEMORY_ROWS;
        let mut log = TelemetryLog::new();
        for i in 0..n {
            log.push(&sample(i));
        }
        for _ in 0..1000 {
            assert_eq!(
                log.last().map(|r| Sample::from_row(&r)),
                Some(sample(n - 1))
            );
        }
        assert_eq!(log.rows_read(), 0);
        log.for_each(|_| {}).unwrap();
        assert_eq!(log.rows_read(), (2 * MEMORY_ROWS) as u64);
    }
}
