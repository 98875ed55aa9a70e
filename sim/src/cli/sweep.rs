//! `vehicle-sim sweep` and `vehicle-sim sweep-merge`: a sweep file's cases on every core (or
//! one shard of them), and the shards' outputs merged.

use std::io::Write;
use std::path::PathBuf;
use std::str::FromStr;
use std::sync::atomic::{AtomicBool, Ordering};

use clap::Args;
use indicatif::{ProgressBar, ProgressDrawTarget, ProgressStyle};

use crate::sweep::{self, MAX_THREADS, Shard, ShardError, Sweep};

use super::{EXIT_FAILURE, EXIT_OK, EXIT_USAGE};

/// The exit status of a sweep stopped by SIGINT or SIGTERM (128 + SIGINT, as shells report an
/// interrupted command).
pub const EXIT_INTERRUPTED: i32 = 130;

/// Set by the SIGINT/SIGTERM handler: the sweep stops starting cases and writes what it has.
static STOP: AtomicBool = AtomicBool::new(false);

/// Installs the handler once per process: the first signal asks the sweep to stop after the
/// cases running (their rows are written and `sweep.json` records them); a second one ends
/// the process at once (the files still end with whole rows, which `--resume` keeps).
fn stop_on_signal() -> Option<&'static AtomicBool> {
    static INSTALLED: std::sync::OnceLock<bool> = std::sync::OnceLock::new();
    let installed = *INSTALLED.get_or_init(|| {
        ctrlc::set_handler(|| {
            if STOP.swap(true, Ordering::SeqCst) {
                std::process::exit(EXIT_INTERRUPTED);
            }
        })
        .is_ok()
    });
    installed.then_some(&STOP)
}

/// The default output directory of a sweep.
pub const DEFAULT_SWEEP_DIR: &str = "vehicle-sim-sweep";

/// `--shard`: a shard by its index and count, or from the batch engine's environment.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum ShardChoice {
    /// `I/N`.
    Fixed(Shard),
    /// `auto`: Slurm's or Kubernetes' variables.
    Auto,
}

impl FromStr for ShardChoice {
    type Err = ShardError;

    fn from_str(s: &str) -> Result<Self, ShardError> {
        if s == "auto" {
            Ok(ShardChoice::Auto)
        } else {
            s.parse().map(ShardChoice::Fixed)
        }
    }
}

/// A count of at least 1.
fn positive(text: &str) -> Result<usize, String> {
    match text.parse::<usize>() {
        Ok(n) if n >= 1 => Ok(n),
        _ => Err(format!("'{text}' is not an integer >= 1")),
    }
}

/// A number of threads: from 1 to [`MAX_THREADS`].
fn thread_count(text: &str) -> Result<usize, String> {
    match text.parse::<usize>() {
        Ok(n) if (1..=MAX_THREADS).contains(&n) => Ok(n),
        _ => Err(format!(
            "'{text}' is not a number of threads from 1 to {MAX_THREADS}"
        )),
    }
}

/// The options of `vehicle-sim sweep`.
#[derive(Debug, Clone, PartialEq, Eq, Args)]
#[command(after_help = SWEEP_HELP)]
pub struct SweepOptions {
    /// The sweep file (TOML: world, scenario, the set and axes tables; see sim/README.md)
    #[arg(value_name = "FILE")]
    pub file: PathBuf,
    /// Output directory: results.csv, timings.csv, sweep.json, plots/
    #[arg(long, value_name = "DIR", default_value = DEFAULT_SWEEP_DIR)]
    pub out: PathBuf,
    /// Threads running cases, at most 1024 (default: every core)
    #[arg(long, value_name = "N", value_parser = thread_count)]
    pub threads: Option<usize>,
    /// Run one shard only: I/N runs the cases whose index is I modulo N; `auto` takes the
    /// shard from a Slurm job array (SLURM_ARRAY_TASK_ID, SLURM_ARRAY_TASK_COUNT) or a
    /// Kubernetes Indexed Job (JOB_COMPLETION_INDEX, with --shards)
    #[arg(long, value_name = "I/N|auto")]
    pub shard: Option<ShardChoice>,
    /// The number of shards for --shard auto in a Kubernetes Indexed Job (the Job's
    /// completions); with Slurm, a check of SLURM_ARRAY_TASK_COUNT
    #[arg(long, value_name = "N", value_parser = positive, requires = "shard")]
    pub shards: Option<usize>,
    /// Keep the whole rows an earlier run of this sweep and shard left in the output
    /// directory and run only the cases after them (a directory without sweep.json starts
    /// afresh)
    #[arg(long)]
    pub resume: bool,
    /// Print nothing but errors: no progress bar, warnings or summary
    #[arg(short, long)]
    pub quiet: bool,
}

const SWEEP_HELP: &str = "\
Every case's row goes to DIR/results.csv in case order as soon as it is done: case, the axis \
values, the metrics, notes, error (a failing case has its error there and the sweep goes on). \
Wall times go to DIR/timings.csv. Shards' outputs are merged with `vehicle-sim sweep-merge`. \
Ctrl-C (SIGINT) or SIGTERM stops the sweep after the cases running, with DIR/sweep.json \
saying how many rows were written; `--resume` goes on from there.

Exit status: 0 when every case has its row (failed cases included), 1 when the sweep file or \
its world cannot be loaded or the outputs cannot be written, 2 usage error, 130 when stopped \
by a signal.";

/// The options of `vehicle-sim sweep-merge`.
#[derive(Debug, Clone, PartialEq, Eq, Args)]
pub struct MergeOptions {
    /// The output directories of the shards (`vehicle-sim sweep --shard I/N --out DIR`)
    #[arg(value_name = "DIR", required = true)]
    pub dirs: Vec<PathBuf>,
    /// Output directory of the merged sweep
    #[arg(long, value_name = "DIR")]
    pub out: PathBuf,
    /// Print nothing but errors
    #[arg(short, long)]
    pub quiet: bool,
}

/// The file names of `files` relative to `dir`, for the summary.
fn names(files: &[PathBuf], dir: &std::path::Path) -> String {
    files
        .iter()
        .map(|f| f.strip_prefix(dir).unwrap_or(f).display().to_string())
        .collect::<Vec<_>>()
        .join(", ")
}

/// Runs `vehicle-sim sweep`.
pub(super) fn sweep_main(
    o: &SweepOptions,
    out: &mut dyn Write,
    err: &mut dyn Write,
    err_is_terminal: bool,
) -> i32 {
    let shard = match o.shard {
        None => Shard::WHOLE,
        Some(ShardChoice::Fixed(s)) => match o.shards {
            Some(n) if n != s.count() => {
                let _ = writeln!(
                    err,
                    "vehicle-sim: error: --shard {s} and --shards {n} disagree\n\
                     For more information, try '--help'."
                );
                return EXIT_USAGE;
            }
            _ => s,
        },
        Some(ShardChoice::Auto) => match Shard::from_env(|k| std::env::var(k).ok(), o.shards) {
            Ok(s) => s,
            Err(e) => {
                let _ = writeln!(err, "vehicle-sim: error: {e}");
                return EXIT_USAGE;
            }
        },
    };
    let sweep = match Sweep::load_all(&o.file) {
        Ok(s) => s,
        Err(e) => {
            // Every error of the sweep file, each with its line (each starts with "error: ").
            let _ = writeln!(err, "vehicle-sim: {e}");
            return EXIT_FAILURE;
        }
    };
    if !o.quiet {
        for w in sweep.warnings() {
            let _ = writeln!(err, "vehicle-sim: warning: {w}");
        }
    }
    let total = shard.len(sweep.len());
    let threads = sweep::thread_count(o.threads);
    if !o.quiet {
        let part = if shard == Shard::WHOLE {
            String::new()
        } else {
            format!(", shard {shard}: {total} of them")
        };
        let _ = writeln!(
            out,
            "vehicle-sim: sweep {}: {} cases of {} on {}{part}, {threads} thread{}",
            sweep.file(),
            sweep.len(),
            sweep.scenario(),
            sweep.world_source(),
            if threads == 1 { "" } else { "s" }
        );
    }
    let target = if err_is_terminal && !o.quiet {
        ProgressDrawTarget::stderr()
    } else {
        ProgressDrawTarget::hidden()
    };
    let bar = ProgressBar::with_draw_target(Some(total as u64), target);
    if let Ok(style) = ProgressStyle::with_template(
        "[{bar:30}] {pos}/{len} cases  {per_sec:.1}  {elapsed_precise} elapsed, ETA {eta}",
    ) {
        bar.set_style(style.progress_chars("#>-"));
    }
    let options = sweep::WriteOptions {
        resume: o.resume,
        stop: stop_on_signal(),
    };
    let result = sweep::write_sweep(
        &sweep,
        shard,
        Some(threads),
        &o.out,
        options,
        &mut |done, _| {
            bar.set_position(done as u64);
        },
    );
    bar.finish_and_clear();
    let summary = match result {
        Ok(s) => s,
        Err(e) => {
            let _ = writeln!(err, "vehicle-sim: error: cannot write the outputs: {e}");
            return EXIT_FAILURE;
        }
    };
    if !summary.complete {
        let _ = writeln!(
            err,
            "vehicle-sim: stopped: {} of {total} cases written to {}; `vehicle-sim sweep {} \
             --out {} --resume` runs the others",
            summary.rows,
            o.out.display(),
            o.file.display(),
            o.out.display()
        );
        return EXIT_INTERRUPTED;
    }
    if !o.quiet {
        let run = summary.rows - summary.resumed;
        let rate = run as f64 / summary.wall_seconds.max(1e-9);
        let failed = match summary.errors {
            0 => "none failed".to_string(),
            n => format!("{n} failed (see their error column)"),
        };
        let kept = match summary.resumed {
            0 => String::new(),
            n => format!(" after the {n} kept from the earlier run"),
        };
        let _ = writeln!(
            out,
            "{run} cases in {:.1} s ({rate:.1} cases/s){kept}, {failed}\noutputs in {}: {}",
            summary.wall_seconds,
            o.out.display(),
            names(&summary.files, &o.out)
        );
    }
    EXIT_OK
}

/// Runs `vehicle-sim sweep-merge`.
pub(super) fn merge_main(o: &MergeOptions, out: &mut dyn Write, err: &mut dyn Write) -> i32 {
    match sweep::merge(&o.dirs, &o.out) {
        Ok(m) => {
            if !o.quiet {
                let _ = writeln!(
                    out,
                    "vehicle-sim: merged {} shard{}: {} cases, {} failed\noutputs in {}: {}",
                    m.shards,
                    if m.shards == 1 { "" } else { "s" },
                    m.rows,
                    m.errors,
                    o.out.display(),
                    names(&m.files, &o.out)
                );
            }
            EXIT_OK
        }
        Err(e) => {
            let _ = writeln!(err, "vehicle-sim: error: {e}");
            EXIT_FAILURE
        }
    }
}
