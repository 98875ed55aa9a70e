//! Running a shard's cases on every core, the rows handed over in case order.
//!
//! Each worker of a rayon pool takes the next case from a shared counter (one atomic
//! increment per case: no lock on the way), runs it and sends its row to the calling thread,
//! which hands the rows over in case order, holding those that finished early in a reorder
//! window. A worker waits before starting a case more than the window ahead of the last row
//! handed over, so the rows held never exceed the window, however many cases the sweep has:
//! memory stays flat. A slow case holds the others back by the window at most.

use std::collections::BTreeMap;
use std::sync::atomic::{AtomicBool, AtomicUsize, Ordering};
use std::sync::{Condvar, Mutex, PoisonError, mpsc};
use std::time::{Duration, Instant};

use super::Sweep;
use super::row::Row;
use super::shard::Shard;

/// Cases a worker may run ahead of the first row not yet handed over, per thread. A case
/// usually takes milliseconds and its row a few hundred bytes: the window holds a few
/// seconds of work, while one slow case lets the other threads go on.
pub const WINDOW_PER_THREAD: usize = 32;

/// Most threads a sweep runs on: 1024. More than the cores of any single machine the runner
/// targets (a sweep spreads further as shards); each thread holds a world while it runs a
/// case and 32 rows (`WINDOW_PER_THREAD`) of reorder window, and starting thousands of threads
/// takes seconds before the first case (10,000 took 12 s to fail). A larger count is refused,
/// not lowered.
pub const MAX_THREADS: usize = 1024;

/// Why a run stopped.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum RunError {
    /// The thread pool could not be built.
    #[error("cannot start {threads} threads: {message}")]
    Threads {
        /// The number asked for.
        threads: usize,
        /// What rayon reported.
        message: String,
    },
    /// More threads than [`MAX_THREADS`] were asked for; nothing ran.
    #[error("cannot run on {0} threads: a sweep runs on at most {MAX_THREADS}")]
    TooManyThreads(usize),
    /// The row's consumer failed (e.g. a full disk); the run stopped.
    #[error(transparent)]
    Sink(#[from] std::io::Error),
}

/// Where the run is: set by the calling thread, read by the workers.
struct Gate<'a> {
    /// The caller's stop flag: set by someone who cannot wake the waiting workers (a signal
    /// handler), so they look at it every [`STOP_POLL`].
    external: Option<&'a AtomicBool>,
    /// Rows handed over so far (the shard's `k`-th case is the next).
    handed: AtomicUsize,
    /// Set when the consumer failed: the workers stop.
    stop: AtomicBool,
    lock: Mutex<()>,
    moved: Condvar,
}

/// How often a worker waiting for its turn looks at the caller's stop flag.
const STOP_POLL: Duration = Duration::from_millis(50);

impl Gate<'_> {
    /// Whether the run stopped: the consumer failed or the caller asked.
    fn stopped(&self) -> bool {
        self.stop.load(Ordering::Acquire)
            || self.external.is_some_and(|s| s.load(Ordering::Relaxed))
    }

    /// Blocks while case `k` is `window` or more ahead of the rows handed over; false when
    /// the run stopped.
    fn wait_for(&self, k: usize, window: usize) -> bool {
        let ahead = |g: &Gate<'_>| k >= g.handed.load(Ordering::Acquire) + window;
        if ahead(self) {
            let mut guard = self.lock.lock().unwrap_or_else(PoisonError::into_inner);
            while ahead(self) && !self.stopped() {
                guard = self
                    .moved
                    .wait_timeout(guard, STOP_POLL)
                    .unwrap_or_else(PoisonError::into_inner)
                    .0;
            }
        }
        !self.stopped()
    }

    /// Records progress (or the stop) and wakes the waiting workers.
    fn advance(&self, handed: usize, stop: bool) {
        {
            let _guard = self.lock.lock().unwrap_or_else(PoisonError::into_inner);
            self.handed.store(handed, Ordering::Release);
            if stop {
                self.stop.store(true, Ordering::Release);
            }
        }
        self.moved.notify_all();
    }
}

/// The threads to use: `threads`, or every core when `None` (at most [`MAX_THREADS`]).
pub(crate) fn thread_count(threads: Option<usize>) -> usize {
    threads.filter(|&n| n > 0).unwrap_or_else(|| {
        std::thread::available_parallelism().map_or(1, |n| usize::from(n).min(MAX_THREADS))
    })
}

/// Where a run starts and what stops it early.
#[derive(Debug, Clone, Copy, Default)]
pub struct RunFrom<'a> {
    /// The first of the shard's cases to run, by its position in the shard (0: all of
    /// them; `k`: a resumed run whose first `k` rows are written).
    pub first: usize,
    /// Set (e.g. by a signal handler) to stop: no case starts after it is seen, the cases
    /// running finish and their rows are handed over, then [`run`] returns
    /// `Ok(Ended::Stopped)`.
    pub stop: Option<&'a AtomicBool>,
}

/// How a run ended.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Ended {
    /// Every case from the first has its row.
    Complete,
    /// The stop flag was set: the rows handed over are whole and in case order, and the
    /// others were not started or are lost.
    Stopped,
}

/// Runs the cases of `shard` of `sweep` on `threads` threads (every core when `None`) and
/// hands each row with its wall time to `sink`, in case order, on the calling thread. A
/// failing case is a row with its error; the run stops only when `sink` fails.
///
/// # Errors
/// [`RunError::TooManyThreads`] past [`MAX_THREADS`], [`RunError::Threads`] when the pool
/// cannot start, [`RunError::Sink`] with the sink's
/// error.
pub fn run(
    sweep: &Sweep,
    shard: Shard,
    threads: Option<usize>,
    sink: &mut dyn FnMut(Row, Duration) -> std::io::Result<()>,
) -> Result<(), RunError> {
    run_from(sweep, shard, threads, RunFrom::default(), sink).map(|_| ())
}

/// [`run`] from the shard's case `from.first`, stopping early when `from.stop` is set.
///
/// # Errors
/// As [`run`].
pub fn run_from(
    sweep: &Sweep,
    shard: Shard,
    threads: Option<usize>,
    from: RunFrom<'_>,
    sink: &mut dyn FnMut(Row, Duration) -> std::io::Result<()>,
) -> Result<Ended, RunError> {
    let threads = thread_count(threads);
    if threads > MAX_THREADS {
        return Err(RunError::TooManyThreads(threads));
    }
    let pool = rayon::ThreadPoolBuilder::new()
        .num_threads(threads)
        .thread_name(|i| format!("sweep-{i}"))
        .build()
        .map_err(|e| RunError::Threads {
            threads,
            message: e.to_string(),
        })?;
    let total = shard.len(sweep.len());
    let window = WINDOW_PER_THREAD * threads;
    let first = from.first.min(total);
    let next = AtomicUsize::new(first);
    let gate = Gate {
        external: from.stop,
        handed: AtomicUsize::new(first),
        stop: AtomicBool::new(false),
        lock: Mutex::new(()),
        moved: Condvar::new(),
    };
    let (tx, rx) = mpsc::sync_channel::<(usize, Row, Duration)>(window);
    let mut failure = None;
    pool.in_place_scope(|scope| {
        for _ in 0..threads {
            let tx = tx.clone();
            let (next, gate) = (&next, &gate);
            scope.spawn(move |_| {
                loop {
                    let k = next.fetch_add(1, Ordering::Relaxed);
                    if k >= total || !gate.wait_for(k, window) {
                        break;
                    }
                    let start = Instant::now();
                    // `case_at(k)` is below the sweep's length: the row always comes.
                    let Ok(row) = sweep.run_case(shard.case_at(k)) else {
                        break;
                    };
                    if tx.send((k, row, start.elapsed())).is_err() {
                        break;
                    }
                }
            });
        }
        drop(tx);
        // The rows that came before their turn, by their position in the shard.
        let mut early: BTreeMap<usize, (Row, Duration)> = BTreeMap::new();
        let mut handed = first;
        for (k, row, wall) in rx {
            early.insert(k, (row, wall));
            while let Some((row, wall)) = early.remove(&handed) {
                if let Err(e) = sink(row, wall) {
                    failure = Some(e);
                    break;
                }
                handed += 1;
            }
            gate.advance(handed, failure.is_some());
            if failure.is_some() {
                // Leaving the loop drops the receiver: a worker's next send fails, and the
                // stop flag ends those waiting for their turn.
                break;
            }
        }
    });
    match failure {
        Some(e) => Err(RunError::Sink(e)),
        // A case not run leaves `handed` short of the total: only a stop does that.
        None if gate.handed.load(Ordering::Acquire) < total && gate.stopped() => Ok(Ended::Stopped),
        None => Ok(Ended::Complete),
    }
}
