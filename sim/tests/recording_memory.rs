//! A run recorded with [`Retention::Off`] keeps its memory whatever its length (issue #33: a
//! million steps recorded in full once peaked at 991 MB).
//!
//! The only test of this binary: the peak resident set (`VmHWM` of /proc/self/status) is
//! this process's alone.

use sim::telemetry::Retention;
use sim::{CarBuilder, Mounting, Simulation, World, WorldConfig};
use vehicle_model::Model;

/// The peak resident set of this process (bytes), from /proc (Linux).
fn peak_rss() -> Option<u64> {
    let status = std::fs::read_to_string("/proc/self/status").ok()?;
    let line = status.lines().find(|l| l.starts_with("VmHWM:"))?;
    let kib: u64 = line.split_whitespace().nth(1)?.parse().ok()?;
    Some(kib * 1024)
}

#[test]
fn a_million_steps_unrecorded_stay_under_50_mb() {
    let Some(before) = peak_rss() else {
        eprintln!("no /proc/self/status: the memory bound is checked on Linux only");
        return;
    };
    let mut sim = Simulation::new(World::new(WorldConfig::default()).unwrap());
    let (id, _) = sim
        .add_car(CarBuilder::of_model(Model::BmwX5).mounting(Mounting::Cast))
        .unwrap();
    sim.driver_mut(id).unwrap().set_cruising_speed(30.0);
    sim.record_with("long", Retention::Off);
    let steps = 1_000_000;
    for _ in 0..steps {
        sim.step().unwrap();
    }
    let log = sim.car_log(id).unwrap();
    // The t = 0 sample and one per step were recorded; none is held but the last, at
    // 10⁶ × 10 ms.
    assert_eq!((log.recorded(), log.len()), (steps + 1, 0));
    assert_eq!(log.last().unwrap()[0], 10_000.0);
    let peak = peak_rss().unwrap();
    // 50 MB is the bound for the whole process (the test harness, the world and the
    // car take a few MB before the run: `before`); recorded in full the run's rows alone
    // would be 304 MB.
    eprintln!(
        "peak RSS {} MB (before the run {} MB)",
        peak >> 20,
        before >> 20
    );
    assert!(peak < 50 << 20, "peak RSS {peak} bytes");
}
