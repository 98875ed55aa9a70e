//! A sweep's output directory: `results.csv` streamed one row per case in case order,
//! `timings.csv` (the wall times, apart so that `results.csv` is the same on every run),
//! the manifest `sweep.json` and the summary plots.

use std::fs::{File, OpenOptions};
use std::io::{BufWriter, Write};
use std::path::{Path, PathBuf};
use std::sync::atomic::AtomicBool;
use std::time::{Duration, Instant};

use crate::report::{TIMING_DIGITS, significant};

use super::Sweep;
use super::error::{OutputError, csv_at, io_at};
use super::manifest::Manifest;
use super::plots::write_plots;
use super::resume;
use super::row::{CASE_COLUMN, csv_writer};
use super::runner::{self, Ended, RunError, RunFrom};
use super::shard::Shard;

/// The results: one row per case, in case order.
pub const RESULTS_CSV: &str = "results.csv";
/// The wall time of each case (s), in case order.
pub const TIMINGS_CSV: &str = "timings.csv";
/// The directory of the summary plots (each metric against or for each value of each axis).
pub const PLOTS_DIR: &str = "plots";
/// The column of `timings.csv` after `case`.
pub(crate) const WALL_COLUMN: &str = "wall_seconds";

/// How [`write_sweep`] treats what is already in the directory, and what stops it.
#[derive(Debug, Clone, Copy, Default)]
pub struct WriteOptions<'a> {
    /// Keep the whole rows of an earlier run of the same sweep and shard in the directory and
    /// run only the cases after them (`vehicle-sim sweep --resume`); a directory without a
    /// `sweep.json` starts afresh. Without it, the files are written anew.
    pub resume: bool,
    /// Set (by a signal handler) to stop early: the cases running finish, their rows are
    /// written, and the manifest says how many rows there are and that the run is not
    /// complete.
    pub stop: Option<&'a AtomicBool>,
}

/// What a sweep run did.
#[derive(Debug, Clone, PartialEq)]
pub struct RunSummary {
    /// The shard run.
    pub shard: Shard,
    /// Rows in `results.csv`, those kept from an earlier run included.
    pub rows: usize,
    /// Rows kept from an earlier run (`--resume`); the run started after them.
    pub resumed: usize,
    /// True when every case of the shard has its row; false when the run was stopped.
    pub complete: bool,
    /// Rows of failed cases among them.
    pub errors: usize,
    /// Threads used.
    pub threads: usize,
    /// Wall time of the run (s).
    pub wall_seconds: f64,
    /// The files written, `results.csv` first.
    pub files: Vec<PathBuf>,
}

/// Runs the cases of `shard` of `sweep` on `threads` threads (every core when `None`) and
/// writes into `dir` (created if needed): `results.csv` (each row as soon as the cases
/// before it are written, flushed, so a stopped run leaves the rows done), `timings.csv`
/// (each case's line flushed before its `results.csv` line), `sweep.json` (marked complete
/// at the end; a run stopped through `options.stop` records its rows and stays incomplete)
/// and, once complete, the plots (`plots/`, whose earlier SVG files are removed first).
/// `progress` is told the rows written and the shard's total after each.
///
/// # Errors
/// The first file that could not be written, [`OutputError::Resume`] when `options.resume`
/// finds another run in `dir`, or [`OutputError::Run`].
pub fn write_sweep(
    sweep: &Sweep,
    shard: Shard,
    threads: Option<usize>,
    dir: &Path,
    options: WriteOptions<'_>,
    progress: &mut dyn FnMut(usize, usize),
) -> Result<RunSummary, OutputError> {
    let start = Instant::now();
    std::fs::create_dir_all(dir).map_err(io_at(dir))?;
    let total = shard.len(sweep.len());
    let kept = if options.resume {
        resume::prepare(sweep, shard, dir)?
    } else {
        None
    };
    let mut manifest = Manifest {
        sweep: sweep.file().to_string(),
        fingerprint: sweep.fingerprint().to_string(),
        version: env!("CARGO_PKG_VERSION").to_string(),
        scenario: sweep.scenario().name().to_string(),
        cases: sweep.len(),
        shard_index: shard.index(),
        shard_count: shard.count(),
        axes: sweep.columns().axes.clone(),
        columns: sweep
            .columns()
            .names()
            .iter()
            .map(|s| s.to_string())
            .collect(),
        rows: kept.map_or(0, |k| k.rows),
        errors: kept.map_or(0, |k| k.errors),
        complete: false,
        color_by: sweep.color_by().key().map(str::to_string),
    };
    let manifest_path = dir.join(super::MANIFEST_JSON);
    manifest.write(dir).map_err(io_at(&manifest_path))?;
    let results_path = dir.join(RESULTS_CSV);
    let timings_path = dir.join(TIMINGS_CSV);
    // A resumed run appends to the files `resume::prepare` cut after their last whole row.
    let open = |path: &Path| {
        let file = match kept {
            Some(_) => OpenOptions::new().append(true).open(path),
            None => File::create(path),
        };
        file.map(|f| csv_writer(BufWriter::new(f)))
            .map_err(io_at(path))
    };
    let mut results = open(&results_path)?;
    let mut timings = open(&timings_path)?;
    if kept.is_none() {
        results
            .write_record(sweep.columns().names())
            .map_err(csv_at(&results_path))?;
        timings
            .write_record([CASE_COLUMN, WALL_COLUMN])
            .map_err(csv_at(&timings_path))?;
    }
    let resumed = kept.map_or(0, |k| k.rows);
    let (mut rows, mut errors) = (resumed, manifest.errors);
    let mut sink = |row: super::Row, wall: Duration| -> std::io::Result<()> {
        // The timing first, then the row, each flushed: a run stopped anywhere (a batch
        // task at its time limit, a signal) leaves whole rows, and at least as many timings,
        // which `--resume` relies on.
        let seconds = significant(wall.as_secs_f64(), TIMING_DIGITS);
        timings.write_record([row.case.to_string(), seconds.to_string()])?;
        timings.flush()?;
        results.write_record(row.cells())?;
        results.flush()?;
        rows += 1;
        errors += usize::from(row.error.is_some());
        progress(rows, total);
        Ok(())
    };
    let threads = runner::thread_count(threads);
    let from = RunFrom {
        first: resumed,
        stop: options.stop,
    };
    let ended =
        runner::run_from(sweep, shard, Some(threads), from, &mut sink).map_err(|e| match e {
            RunError::Sink(source) => OutputError::Io {
                path: results_path.clone(),
                source,
            },
            other => OutputError::Run(other),
        })?;
    results.flush().map_err(io_at(&results_path))?;
    timings.flush().map_err(io_at(&timings_path))?;
    drop((results, timings));
    manifest.rows = rows;
    manifest.errors = errors;
    manifest.complete = ended == Ended::Complete;
    manifest.write(dir).map_err(io_at(&manifest_path))?;
    let mut files = vec![results_path.clone(), timings_path, manifest_path];
    if manifest.complete {
        files.extend(write_plots(
            &results_path,
            &sweep.columns().axes,
            sweep.scenario().name(),
            sweep.color_by(),
            &dir.join(PLOTS_DIR),
        )?);
    }
    Ok(RunSummary {
        shard,
        rows,
        resumed,
        complete: manifest.complete,
        errors,
        threads,
        wall_seconds: start.elapsed().as_secs_f64(),
        files,
    })
}

/// Flushes a CSV writer's buffer to its file and the file's buffer to the disk's cache.
pub(crate) fn finish<W: Write>(w: csv::Writer<W>, path: &Path) -> Result<(), OutputError> {
    let mut inner = w
        .into_inner()
        .map_err(|e| io_at(path)(std::io::Error::other(e.to_string())))?;
    inner.flush().map_err(io_at(path))
}
