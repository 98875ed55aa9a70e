//! Criterion benchmarks of the ray devices (issue #29) on the ACC world (`sim/worlds/acc.toml`):
//! one `Simulation::step` with no device enabled, then with one device sampling at every step
//! (its period the world's 10 ms): the long-range radar, the SICK LMS 291 (180 rays) and a
//! 16-layer lidar of 1800 rays per layer (28 800 rays). The summary gives each device's cost
//! per sample: its step's median minus the bare step's.
#![allow(
    clippy::unwrap_used,
    reason = "bench setup from constant, valid fixtures: a failure is a fixture bug and must stop the run"
)]

use benches::report::{self, Medians, format_ns};
use criterion::{BenchmarkId, Criterion, criterion_group};
use sim::{Simulation, world_file};

/// The ACC world with the follower (its last car) carrying, after the long-range radar, a SICK
/// LMS 291 on its roof and a 16-layer VLP-16 of 1800 rays per layer (0.2°, its 20 Hz mode).
fn world() -> String {
    let acc = include_str!("../../sim/worlds/acc.toml");
    format!(
        "{acc}\n[[vehicle.device]]\ntype = \"Lidar\"\nname = \"sick\"\nslot = \"top\"\npreset = \"SickLms291\"\n\
         [[vehicle.device]]\ntype = \"Lidar\"\nname = \"vlp16\"\nslot = \"top\"\npreset = \"VelodyneVlp16\"\nhorizontalResolution = 1800\n"
    )
}

/// The devices measured, by their index on the follower.
const DEVICES: [(&str, usize); 3] = [("radar", 0), ("sick_lms_291", 1), ("lidar_16x1800", 2)];

/// The simulation of the ACC world with device `enabled` of the follower sampling every step,
/// after 2 s so that the cars drive.
fn scene(enabled: Option<usize>) -> Simulation {
    let description = world_file::parse_str("acc.toml", &world()).unwrap();
    let (mut sim, _) = Simulation::from_description(&description).unwrap();
    // Only the devices each case enables sample (the world's `samplingPeriod` keys aside).
    sim.disable_devices();
    let ids: Vec<_> = sim.car_ids().collect();
    for &id in &ids {
        sim.driver_mut(id).unwrap().set_cruising_speed(54.0);
    }
    let follower = ids[1];
    if let Some(i) = enabled {
        sim.enable_device(follower, i, 10).unwrap();
    }
    let settle = if report::is_bench_run() { 200 } else { 1 };
    for _ in 0..settle {
        sim.step().unwrap();
    }
    sim
}

fn ray_devices(c: &mut Criterion) {
    let mut g = c.benchmark_group("ray_devices");
    let mut bare = scene(None);
    g.bench_function(BenchmarkId::new("step", "no_device"), |b| {
        b.iter(|| bare.step().unwrap())
    });
    for (name, index) in DEVICES {
        let mut sim = scene(Some(index));
        g.bench_function(BenchmarkId::new("step", name), |b| {
            b.iter(|| sim.step().unwrap())
        });
    }
    g.finish();
}

criterion_group! {
    name = benches;
    config = report::criterion_config();
    targets = ray_devices
}

/// Each device's cost per sample: its step's median minus the bare step's.
fn summary(medians: &Medians) {
    println!("\nray devices per sample (criterion medians, ACC world):");
    let Some(bare) = medians.get("ray_devices/step/no_device") else {
        println!("  no result in {}", medians.dir().display());
        return;
    };
    println!("  step without devices: {}", format_ns(bare));
    for (name, _) in DEVICES {
        if let Some(step) = medians.get(&format!("ray_devices/step/{name}")) {
            println!("  {name}: {} per sample", format_ns(step - bare));
        }
    }
}

fn main() {
    report::main_with_summary(benches, summary);
}
