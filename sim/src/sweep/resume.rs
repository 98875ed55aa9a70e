//! `vehicle-sim sweep --resume`: the whole, intact rows an earlier run of the same sweep and
//! shard left in its output directory are kept, anything after them is cut, and the run goes
//! on from the first case without a row.
//!
//! A run writes each case's `timings.csv` line before its `results.csv` line, each flushed:
//! however it was stopped (a signal, a batch system's time limit, a power cut), `results.csv`
//! ends with whole rows, possibly followed by a torn one, and `timings.csv` has at least as
//! many rows. The rows kept are those of `results.csv` up to the first torn one, each checked
//! for its case index and checksum; a damaged or edited row before the end is an error, not
//! something to cut, since the rows after it would be lost.

use std::fs::{File, OpenOptions};
use std::io::{BufReader, Read, Seek, SeekFrom};
use std::path::{Path, PathBuf};

use super::Sweep;
use super::error::{OutputError, io_at};
use super::manifest::{MANIFEST_JSON, Manifest};
use super::output::{RESULTS_CSV, TIMINGS_CSV};
use super::row::{ERROR_COLUMN, checksum_matches};
use super::shard::Shard;

/// What an earlier run left that a resumed run keeps.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Default)]
pub(crate) struct Kept {
    /// Whole rows kept: the run goes on from the shard's case at this position.
    pub rows: usize,
    /// Rows of failed cases among them.
    pub errors: usize,
}

/// Why an output directory cannot be resumed.
fn refuse(dir: &Path, reason: impl Into<String>) -> OutputError {
    OutputError::Resume {
        dir: dir.to_path_buf(),
        reason: reason.into(),
    }
}

/// Checks that `dir` holds an earlier run of `shard` of `sweep`, cuts its files after their
/// last whole row, and says what was kept. `None` when `dir` has no `sweep.json` (nothing to
/// resume: the run starts afresh).
///
/// # Errors
/// [`OutputError::Resume`] when the directory is another sweep's or shard's, or a row before
/// the end is damaged or edited; a file that cannot be read or cut.
pub(crate) fn prepare(
    sweep: &Sweep,
    shard: Shard,
    dir: &Path,
) -> Result<Option<Kept>, OutputError> {
    let manifest_path = dir.join(MANIFEST_JSON);
    if !manifest_path.exists() {
        return Ok(None);
    }
    let m = Manifest::read(dir).map_err(|e| refuse(dir, e))?;
    let fingerprint = sweep.fingerprint().to_string();
    if m.fingerprint != fingerprint {
        return Err(refuse(
            dir,
            format!(
                "it holds a run of another sweep (fingerprint {} where this one has \
                 {fingerprint}: the sweep file, its base world or vehicle-sim's version \
                 changed); run without --resume or into another directory",
                m.fingerprint
            ),
        ));
    }
    if (m.shard_index, m.shard_count) != (shard.index(), shard.count()) {
        return Err(refuse(
            dir,
            format!(
                "it holds shard {}/{} where shard {shard} was asked for",
                m.shard_index, m.shard_count
            ),
        ));
    }
    let results = dir.join(RESULTS_CSV);
    let timings = dir.join(TIMINGS_CSV);
    let header: Vec<&str> = sweep.columns().names();
    let (rows, results_end, errors) = whole_rows(&results, &header, shard, true)?;
    let (timing_rows, _, _) = whole_rows(&timings, &[], shard, false)?;
    if timing_rows.len() < rows.len() {
        return Err(refuse(
            dir,
            format!(
                "{TIMINGS_CSV} has {} rows where {RESULTS_CSV} has {} (a run writes the \
                 timing first: the files were edited)",
                timing_rows.len(),
                rows.len()
            ),
        ));
    }
    let timings_end = match rows.len() {
        0 => timing_rows.header_end,
        n => timing_rows.ends[n - 1],
    };
    cut(&results, results_end)?;
    cut(&timings, timings_end)?;
    Ok(Some(Kept {
        rows: rows.len(),
        errors,
    }))
}

/// The byte offsets where a file's header and its whole, intact rows end.
struct Rows {
    header_end: u64,
    ends: Vec<u64>,
}

impl Rows {
    fn len(&self) -> usize {
        self.ends.len()
    }
}

/// Reads the whole rows of `path` (a file of the run: its first cell the case, which must be
/// the shard's cases in order; with `checked`, the header must be `header` and each row must
/// carry its checksum). Returns the rows, the offset after the last one kept, and the rows
/// whose error cell is not empty.
fn whole_rows(
    path: &Path,
    header: &[&str],
    shard: Shard,
    checked: bool,
) -> Result<(Rows, u64, usize), OutputError> {
    let dir = path.parent().unwrap_or(Path::new("."));
    let mut file = File::open(path).map_err(io_at(path))?;
    let whole = last_line_end(&mut file).map_err(io_at(path))?;
    file.seek(SeekFrom::Start(0)).map_err(io_at(path))?;
    // Only `\n` ends a line, as the run writes them (`row::csv_writer`): the csv crate's
    // default also takes a lone `\r`, so a `\n` damaged into `\r` would read as the same
    // rows and be kept in the file.
    let mut reader = csv::ReaderBuilder::new()
        .has_headers(false)
        .flexible(true)
        .terminator(csv::Terminator::Any(b'\n'))
        .from_reader(BufReader::new(file).take(whole));
    let mut record = csv::StringRecord::new();
    let name = path
        .file_name()
        .map_or_else(String::new, |n| n.to_string_lossy().into_owned());
    // An unreadable header (not UTF-8, say) is damage like a wrong one.
    let has_header = reader.read_record(&mut record).unwrap_or(false);
    if !has_header || (checked && !record.iter().eq(header.iter().copied())) {
        return Err(refuse(
            dir,
            format!("{name}: its header is not this sweep's columns"),
        ));
    }
    let error_at = header.iter().position(|&c| c == ERROR_COLUMN);
    let mut rows = Rows {
        header_end: reader.position().byte(),
        ends: Vec::new(),
    };
    let mut errors = 0;
    let mut bad: Option<(u64, String)> = None;
    loop {
        let line = reader.position().line();
        let read = reader.read_record(&mut record);
        if let Some((line, why)) = bad.take() {
            // A bad row followed by anything is damage in the middle; the last one is torn.
            if !matches!(read, Ok(false)) {
                return Err(refuse(dir, format!("{name} line {line}: {why}")));
            }
            break;
        }
        match read {
            Ok(false) => break,
            Err(e) => bad = Some((line, format!("unreadable row ({e})"))),
            Ok(true) => {
                let k = rows.len();
                let expected = shard.case_at(k).to_string();
                if record.get(0) != Some(expected.as_str()) {
                    bad = Some((line, format!("row {k} should be case {expected}")));
                } else if checked && (record.len() != header.len() || !checksum_matches(&record)) {
                    bad = Some((
                        line,
                        format!(
                            "case {expected}'s checksum does not match its cells (the row was \
                             edited or damaged)"
                        ),
                    ));
                } else {
                    errors += usize::from(
                        error_at
                            .and_then(|i| record.get(i))
                            .is_some_and(|e| !e.is_empty()),
                    );
                    rows.ends.push(reader.position().byte());
                }
            }
        }
    }
    let end = rows.ends.last().copied().unwrap_or(rows.header_end);
    Ok((rows, end, errors))
}

/// The offset just after the file's last `\n` (0 if it has none): what follows was being
/// written when the run stopped.
fn last_line_end(file: &mut File) -> std::io::Result<u64> {
    const CHUNK: u64 = 4096;
    let len = file.seek(SeekFrom::End(0))?;
    let mut end = len;
    let mut buf = vec![0u8; CHUNK as usize];
    while end > 0 {
        let start = end.saturating_sub(CHUNK);
        file.seek(SeekFrom::Start(start))?;
        let n = usize::try_from(end - start)
            .unwrap_or(buf.len())
            .min(buf.len());
        file.read_exact(&mut buf[..n])?;
        if let Some(i) = buf[..n].iter().rposition(|&b| b == b'\n') {
            return Ok(start + i as u64 + 1);
        }
        end = start;
    }
    Ok(0)
}

/// Cuts `path` at `len` bytes.
fn cut(path: &PathBuf, len: u64) -> Result<(), OutputError> {
    OpenOptions::new()
        .write(true)
        .open(path)
        .and_then(|f| f.set_len(len))
        .map_err(io_at(path))
}
