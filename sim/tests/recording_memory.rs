//! A run recorded with [`Retention::Off`] keeps its memory whatever its length (issue #33: a
//! million steps recorded in full once peaked at 991 MB).
//!
//! The peak resident set (`VmHWM` of /proc/self/status) is this process's: the tests of this
//! binary run one at a time (a mutex), so that one's peak is not the other's. The million
//! steps take about 195 s in a debug build, so that test is opt-in:
//! `cargo test -p sim --release --test recording_memory -- --include-ignored`.
//! The default test runs 20,000 steps and bounds what they add.

use std::sync::Mutex;

use sim::telemetry::{Retention, SAMPLE_COLUMNS};
use sim::{CarBuilder, Mounting, Simulation, World, WorldConfig};
use vehicle_model::Model;

/// One test at a time: see the module docs.
static ONE_AT_A_TIME: Mutex<()> = Mutex::new(());

/// The peak resident set of this process (bytes), from /proc (Linux).
fn peak_rss() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib * 1024)
}

/// Runs a BmwX5 at 30 km/h for `steps` 10 ms steps recorded with [`Retention::Off`], after
/// 100 steps that let the physics make its caches; returns the peak resident set before the
/// recorded steps and after them (bytes), None where /proc is missing.
// The tests' own code (clippy allows unwrap in #[test] functions, not in their helpers).
#[allow(clippy::unwrap_used)]
fn unrecorded_run(steps: usize) -> Option<(u64, u64)> {
    let _one = ONE_AT_A_TIME.lock().unwrap_or_else(|e| e.into_inner());
    peak_rss()?;
    let mut sim = Simulation::new(World::new(WorldConfig::default()).unwrap());
    let (id, _) = sim
        .add_car(CarBuilder::of_model(Model::BmwX5).mounting(Mounting::Cast))
        .unwrap();
    sim.driver_mut(id).unwrap().set_cruising_speed(30.0);
    for _ in 0..100 {
        sim.step().unwrap();
    }
    sim.record_with("long", Retention::Off);
    let before = peak_rss()?;
    for _ in 0..steps {
        sim.step().unwrap();
    }
    let log = sim.car_log(id).unwrap();
    // The sample at the start of the recording and one per step were recorded; none is held
    // but the last, at (100 + steps) × 10 ms.
    assert_eq!((log.recorded(), log.len()), (steps + 1, 0));
    assert_eq!(log.last().unwrap()[0], (100 + steps) as f64 * 0.01);
    let peak = peak_rss()?;
    eprintln!(
        "{steps} steps: peak RSS {} MB (before them {} MB)",
        peak >> 20,
        before >> 20
    );
    Some((before, peak))
}

#[test]
fn unrecorded_steps_add_no_memory() {
    let steps = 20_000;
    let Some((before, peak)) = unrecorded_run(steps) else {
        eprintln!("no /proc/self/status: the memory bound is checked on Linux only");
        return;
    };
    // Holding the steps' rows would take 20,000 × 344 B = 6.9 MB; the bound is half of that,
    // so a leak of one row per step fails it, and leaves room for the allocator's slack.
    let rows = (steps * SAMPLE_COLUMNS * 8) as u64;
    assert!(
        peak - before < rows / 2,
        "the steps added {} bytes",
        peak - before
    );
}

#[test]
#[ignore = "195 s in a debug build: cargo test -p sim --release --test recording_memory -- --include-ignored"]
fn a_million_steps_unrecorded_stay_under_50_mb() {
    let Some((_, peak)) = unrecorded_run(1_000_000) else {
        eprintln!("no /proc/self/status: the memory bound is checked on Linux only");
        return;
    };
    // 50 MB is the bound for the whole process (the test harness, the world and the
    // car take a few MB before the run); recorded in full the run's rows alone would be
    // 344 MB.
    assert!(peak < 50 << 20, "peak RSS {peak} bytes");
}
