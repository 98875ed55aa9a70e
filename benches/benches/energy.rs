//! Criterion benchmark of what the energy parts of issue #36 cost a car's step: a
//! TeslaModel3 accelerating in torque control as Webots has it (wheel damping, no air, no
//! accounting), with the road-load losses and its air, and with those and the energy
//! accounting. The target: the last within 10 % of the first, in the same run (the summary
//! prints the ratios).
#![allow(
    clippy::unwrap_used,
    reason = "bench setup from constant, valid fixtures: a failure is a fixture bug and must stop the run"
)]

use benches::report::{self, Medians, format_ns};
use criterion::{BenchmarkId, Criterion, criterion_group};
use sim::{CarBuilder, Simulation, World, WorldConfig};
use vehicle_model::energy::EnergyParams;
use vehicle_model::{Model, RoadLoad};

/// Steps per iteration (10 ms each).
const STEPS: usize = 10;

/// What a case adds to Webots' car.
#[derive(Clone, Copy)]
enum Case {
    Webots,
    RoadLoad,
    Energy,
}

impl Case {
    const ALL: [Case; 3] = [Case::Webots, Case::RoadLoad, Case::Energy];

    fn name(self) -> &'static str {
        match self {
            Case::Webots => "webots",
            Case::RoadLoad => "road_load_and_air",
            Case::Energy => "road_load_air_and_energy",
        }
    }
}

/// A TeslaModel3 of `case` at half throttle, run for 2 s.
fn scene(case: Case) -> Simulation {
    let model = Model::TeslaModel3;
    let mut sim = Simulation::new(World::new(WorldConfig::default()).unwrap());
    let mut car = CarBuilder::of_model(model);
    if !matches!(case, Case::Webots) {
        car = car
            .aero(Some(model.aero()))
            .road_load(Some(RoadLoad::default()));
    }
    if matches!(case, Case::Energy) {
        let engine = model.params::<f64>().engine;
        car = car.energy(Some(EnergyParams::of_engine(&engine)), 0.9);
    }
    let (id, _) = sim.add_car(car).unwrap();
    let d = sim.driver_mut(id).unwrap();
    d.set_gear(1);
    d.set_throttle(0.5);
    let settle = if report::is_bench_run() { 200 } else { 1 };
    for _ in 0..settle {
        sim.step().unwrap();
    }
    sim
}

fn energy(c: &mut Criterion) {
    let mut g = c.benchmark_group("energy");
    for case in Case::ALL {
        let mut sim = scene(case);
        g.bench_function(BenchmarkId::new("100ms", case.name()), |b| {
            b.iter(|| {
                for _ in 0..STEPS {
                    sim.step().unwrap();
                }
            })
        });
    }
    g.finish();
}

criterion_group! {
    name = benches;
    config = report::criterion_config();
    targets = energy
}

/// Each case's time and its ratio to Webots' car.
fn summary(medians: &Medians) {
    println!("\nenergy, 100 ms simulated per iteration (criterion medians, TeslaModel3):");
    let get = |case: Case| medians.get(&format!("energy/100ms/{}", case.name()));
    let base = get(Case::Webots);
    for case in Case::ALL {
        if let Some(ns) = get(case) {
            let ratio = base.map_or(String::new(), |b| format!(", {:.3}x Webots'", ns / b));
            println!("  {}: {}{ratio}", case.name(), format_ns(ns));
        }
    }
}

fn main() {
    report::main_with_summary(benches, summary);
}
