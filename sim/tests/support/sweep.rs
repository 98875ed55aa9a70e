//! What the sweep tests share: scratch directories, parsing, running and reading sweeps.

// Each test file uses some of these.
#![allow(dead_code, clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::{Path, PathBuf};

use sim::sweep::{self, Row, Shard, Sweep, SweepError, WriteOptions};

/// A fresh scratch directory for one test.
pub fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("sim-sweep-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

pub fn parse(text: &str) -> Result<Sweep, SweepError> {
    Sweep::parse("s.toml", text, Path::new("."))
}

/// Runs `shard` of `sweep` into `dir` on `threads` threads.
pub fn write(sweep: &Sweep, shard: Shard, threads: usize, dir: &Path) {
    sweep::write_sweep(
        sweep,
        shard,
        Some(threads),
        dir,
        WriteOptions::default(),
        &mut |_, _| {},
    )
    .unwrap();
}

pub fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap()
}

/// Every row of the sweep, run one by one.
pub fn rows(sweep: &Sweep) -> Vec<Row> {
    (0..sweep.len())
        .map(|i| sweep.run_case(i).unwrap())
        .collect()
}

/// The number in metric column `name` of `row`.
pub fn metric(sweep: &Sweep, row: &Row, name: &str) -> f64 {
    let j = sweep
        .columns()
        .metrics
        .iter()
        .position(|m| m == name)
        .unwrap();
    match row.metrics[j] {
        sweep::Cell::Number(x) => x,
        other => panic!("{name} of case {} is {other:?}: {:?}", row.case, row.error),
    }
}

/// A short sweep of every axis shape: 2 × 3 × 2 = 12 cases of 2 s of `accel-speed`, one of
/// which (ground friction −1) fails.
pub const SHORT: &str = "\
world = \"ToyotaPrius\"
scenario = \"accel-speed\"
[set]
duration = 2
[axes]
\"ground.friction\" = [0.8, -1]
\"vehicle.time0To100\" = { from = 8, to = 12, steps = 3 }
\"vehicle.mass\" = { normal = [1400, 100], count = 2, seed = 11 }
";
