//! Sweeps on every core: the cases per second of a `brake` sweep (`sim::sweep::run`, the rows
//! turned into their CSV lines in case order) on 1 and 2 threads, and the parallel efficiency
//! (cases/s on 2 threads ÷ (2 × on 1 thread), target ≥ 90 %).
//!
//! The cases are those of `examples/sweeps/brake-10000.toml`, the first `CASES` of them (its
//! shard 0 of 10000 / `CASES`): random road friction and brake torque, a BmwX5 braking from
//! 100 km/h. The whole 10,000 cases and the memory are measured with the command (see
//! `benches/README.md`).
#![allow(
    clippy::unwrap_used,
    reason = "bench setup from constant, valid fixtures: a failure is a fixture bug and must stop the run"
)]

use std::hint::black_box;
use std::path::Path;
use std::time::{Duration, SystemTime};

use benches::report;
use criterion::{BenchmarkId, Criterion, Throughput, criterion_group};
use sim::sweep::{self, Shard, Sweep};

/// Cases per iteration: about a second of work on one thread.
const CASES: usize = 100;

fn bench_sweep() -> (Sweep, Shard) {
    let file = Path::new(env!("CARGO_MANIFEST_DIR")).join("../examples/sweeps/brake-10000.toml");
    let sweep = Sweep::load(file).unwrap();
    let shard = Shard::new(0, sweep.len() / CASES).unwrap();
    (sweep, shard)
}

/// Runs `shard` of `sweep` on `threads` threads; the CSV bytes of its rows.
fn run(sweep: &Sweep, shard: Shard, threads: usize) -> usize {
    let mut bytes = 0;
    sweep::run(sweep, shard, Some(threads), &mut |row, _| {
        bytes += row.csv_line().len();
        Ok(())
    })
    .unwrap();
    bytes
}

fn bench(c: &mut Criterion) {
    let (sweep, shard) = bench_sweep();
    let mut g = c.benchmark_group("sweep");
    // An iteration takes about a second: ten samples, as few warm-up iterations.
    g.sample_size(10)
        .warm_up_time(Duration::from_secs(1))
        .measurement_time(Duration::from_secs(12));
    g.throughput(Throughput::Elements(shard.len(sweep.len()) as u64));
    for threads in [1, 2] {
        g.bench_function(
            BenchmarkId::new("brake", format!("{threads}-threads")),
            |b| b.iter(|| black_box(run(&sweep, shard, threads))),
        );
    }
    g.finish();
}

criterion_group! {
    name = benches;
    config = report::criterion_config();
    targets = bench
}

/// Cases per second on each thread count and the parallel efficiency, from this run's medians.
fn summary(since: SystemTime) {
    let dir = report::criterion_dir();
    let median = |t: usize| report::median_ns(&dir, &format!("sweep/brake/{t}-threads"), since);
    let (Some(one), Some(two)) = (median(1), median(2)) else {
        println!("\nsweep summary: missing results in {}", dir.display());
        return;
    };
    let rate = |ns: f64| CASES as f64 / (ns * 1e-9);
    let (r1, r2) = (rate(one), rate(two));
    println!("\nsweep summary (criterion medians, {CASES} brake cases per iteration):");
    println!("  1 thread: {r1:.1} cases/s; 2 threads: {r2:.1} cases/s");
    println!(
        "  parallel efficiency {:.1} % (target >= 90 %; {} cores here)",
        100.0 * r2 / (2.0 * r1),
        std::thread::available_parallelism().map_or(1, usize::from)
    );
}

fn main() {
    let since = SystemTime::now();
    benches();
    Criterion::default().configure_from_args().final_summary();
    if report::is_bench_run() {
        summary(since);
    }
}
