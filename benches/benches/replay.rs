//! What the replay (`replay.glb`) adds to a `vehicle-sim` run: the whole default run
//! (`test-track` on the default world, recording included), one recorded frame, and writing the
//! file; the summary prints the share of the run's wall time the replay takes (target < 10 %).
#![allow(
    clippy::unwrap_used,
    reason = "bench setup from constant, valid fixtures: a failure is a fixture bug and must stop the run"
)]

use std::hint::black_box;
use std::time::Duration;

use benches::report::{self, Medians, format_ns};
use criterion::{BatchSize, BenchmarkId, Criterion, criterion_group};
use sim::replay::{self, Recorder};
use sim::scenario::{self, RunReport, Scenario};
use sim::world_file;
use sim::{Simulation, VehiclePlacement, World, WorldConfig};
use vehicle_model::Model;

const RUN: &str = "replay/run/test-track";
const FRAME: &str = "replay/frame/bmw_x5";
const WRITE: &str = "replay/write/test-track";

/// `vehicle-sim`'s default run: `test-track` on the default world.
fn default_run() -> RunReport {
    let world = world_file::default_world();
    scenario::run(&world, Scenario::TestTrack, &mut |_| {}).unwrap()
}

/// A BmwX5 cruising for a second, with a recorder started then and two steps (one keyframe
/// period at 10 ms) later: its next `sample` keeps a frame.
fn due_recorder() -> (Simulation, Recorder) {
    let mut sim = Simulation::new(World::new(WorldConfig::default()).unwrap());
    let (car, _) = sim
        .add_car(sim::CarBuilder::new(Model::BmwX5.params()).placement(VehiclePlacement::default()))
        .unwrap();
    sim.driver_mut(car).unwrap().set_cruising_speed(30.0);
    for _ in 0..100 {
        sim.step().unwrap();
    }
    let recorder = Recorder::for_simulation(&sim);
    for _ in 0..2 {
        sim.step().unwrap();
    }
    (sim, recorder)
}

fn bench(c: &mut Criterion) {
    let mut g = c.benchmark_group("replay");
    // A whole run takes a few hundred ms: ten samples.
    g.sample_size(10).measurement_time(Duration::from_secs(8));
    g.bench_function(BenchmarkId::new("run", "test-track"), |b| {
        b.iter(|| black_box(default_run()))
    });
    g.finish();

    let mut g = c.benchmark_group("replay");
    let (sim, recorder) = due_recorder();
    g.bench_function(BenchmarkId::new("frame", "bmw_x5"), |b| {
        b.iter_batched_ref(
            || recorder.clone(),
            |r| r.sample(black_box(sim.world())),
            BatchSize::SmallInput,
        )
    });
    let report = default_run();
    g.bench_function(BenchmarkId::new("write", "test-track"), |b| {
        b.iter(|| replay::to_glb(black_box(&report.replay_parts())).unwrap())
    });
    g.finish();
}

criterion_group! {
    name = benches;
    config = report::criterion_config();
    targets = bench
}

/// The replay's share of a run: recording (frames × the cost of one) plus writing the file,
/// over the run without them.
fn summary(medians: &Medians) {
    let median = |id: &str| medians.get(id);
    let (Some(run), Some(frame), Some(write)) = (median(RUN), median(FRAME), median(WRITE)) else {
        println!(
            "\nreplay summary: missing results in {}",
            medians.dir().display()
        );
        return;
    };
    let report = default_run();
    let frames: usize = report.results.iter().map(|r| r.replay.frames.len()).sum();
    let bytes = replay::to_glb(&report.replay_parts()).unwrap().len();
    let recording = frames as f64 * frame;
    let bare = run - recording;
    println!("\nreplay summary (criterion medians, test-track on the default world):");
    println!(
        "  run {} ({:.1} s simulated), {frames} frames of {} = {} recording, writing {} ({bytes} bytes)",
        format_ns(run),
        report.sim_seconds,
        format_ns(frame),
        format_ns(recording),
        format_ns(write),
    );
    println!(
        "  the replay adds {:.1} % to the run's wall time (target < 10 %)",
        100.0 * (recording + write) / bare
    );
}

fn main() {
    report::main_with_summary(benches, summary);
}
