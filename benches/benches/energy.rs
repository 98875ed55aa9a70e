//! Criterion benchmark of what the energy parts of issue #36 cost a car's step: a
//! TeslaModel3 accelerating in torque control as Webots has it (wheel damping, no air, no
//! accounting), with the road-load losses and its air, and with those and the energy
//! accounting. The target: the last within 10 % of the first, in the same run (the summary
//! prints the ratios). Beside it, what the drive cap of a hybrid whose pack limits its
//! machine costs (a search over the drive, each of its steps one power flow): a
//! ToyotaPrius's `EnergyParams::drive_cap` asking 60 kW at 30 rad/s in a gear of 9 at a
//! state of charge of 0.3, against one `EnergyParams::flow` of the same state; no target,
//! the summary prints how many flows a cap costs.
#![allow(
    clippy::unwrap_used,
    reason = "bench setup from constant, valid fixtures: a failure is a fixture bug and must stop the run"
)]

use benches::energy::{EnergyCase, SETTLE_STEPS, energy_scene};
use benches::report::{self, Medians, format_ns};
use criterion::{BenchmarkId, Criterion, criterion_group};
use std::hint::black_box;
use std::time::{Duration, Instant};

use vehicle_model::energy::{DriveState, EnergyParams};
use vehicle_model::{EngineParams, Model, RAD_PER_S_PER_RPM};

/// Steps per iteration (10 ms each).
const STEPS: usize = 10;

/// The step of the cap (s).
const CAP_DT: f64 = 0.01;

/// The ToyotaPrius's engine, its energy parameters, and a drive its pack limits.
fn pack_limited() -> (EngineParams<f64>, EnergyParams<f64>, DriveState<f64>) {
    let engine = Model::ToyotaPrius.params::<f64>().engine;
    let params = EnergyParams::of_engine(&engine);
    let spin = 30.0;
    let state = DriveState {
        rpm: spin * 9.0 / RAD_PER_S_PER_RPM,
        wheel_power: 60e3,
        brake_torque: 0.0,
        wheel_speed: spin,
        rim_speed: spin * 0.3,
        ratio: 9.0,
        soc: 0.3,
        electric_fraction: 1.0,
    };
    let cap = params.drive_cap(&engine, &state, CAP_DT);
    assert!(cap.torque_scale < 1.0, "the pack limits the drive: {cap:?}");
    (engine, params, state)
}

fn energy(c: &mut Criterion) {
    let mut g = c.benchmark_group("energy");
    for case in EnergyCase::ALL {
        // Every iteration steps from the same settled state (the restore is not timed):
        // left to run on, the car would be somewhere else in each case after the thousands
        // of iterations a measurement takes (faster, or, with the accounting, on a
        // draining pack), and the cases would not compare.
        let settle = if report::is_bench_run() {
            SETTLE_STEPS
        } else {
            1
        };
        let mut sim = energy_scene(case, settle).unwrap();
        let settled = sim.snapshot();
        g.bench_function(BenchmarkId::new("100ms", case.name()), |b| {
            b.iter_custom(|iterations| {
                let mut spent = Duration::ZERO;
                for _ in 0..iterations {
                    sim.restore(&settled).unwrap();
                    let start = Instant::now();
                    for _ in 0..STEPS {
                        sim.step().unwrap();
                    }
                    spent += start.elapsed();
                }
                spent
            })
        });
    }
    let (engine, params, state) = pack_limited();
    g.bench_function("hybrid_flow", |b| {
        b.iter(|| params.flow(black_box(&engine), black_box(&state)))
    });
    g.bench_function("hybrid_drive_cap", |b| {
        b.iter(|| params.drive_cap(black_box(&engine), black_box(&state), CAP_DT))
    });
    g.finish();
}

criterion_group! {
    name = benches;
    config = report::criterion_config();
    targets = energy
}

/// Each case's time and its ratio to Webots' car, and the cap's time in flows.
fn summary(medians: &Medians) {
    println!("\nenergy, 100 ms simulated per iteration (criterion medians, TeslaModel3):");
    let get = |case: EnergyCase| medians.get(&format!("energy/100ms/{}", case.name()));
    let base = get(EnergyCase::Webots);
    for case in EnergyCase::ALL {
        if let Some(ns) = get(case) {
            let ratio = base.map_or(String::new(), |b| format!(", {:.3}x Webots'", ns / b));
            println!("  {}: {}{ratio}", case.name(), format_ns(ns));
        }
    }
    if let (Some(flow), Some(cap)) = (
        medians.get("energy/hybrid_flow"),
        medians.get("energy/hybrid_drive_cap"),
    ) {
        println!(
            "  ToyotaPrius pack-limited drive cap: {} ({:.1} flows of {})",
            format_ns(cap),
            cap / flow,
            format_ns(flow)
        );
    }
}

fn main() {
    report::main_with_summary(benches, summary);
}
