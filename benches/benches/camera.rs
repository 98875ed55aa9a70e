//! Criterion benchmarks of the camera: one `Simulation::step` of a small ACC-like world (a
//! follower BMW X5 with a camera on its front slot, a lead car 30 m ahead, boxes, a ramp and a
//! dynamic box) with the camera sampling at every step, beside the same step without the
//! camera; the summary prints the camera's share. A last case puts the road of
//! `sim/worlds/highway.toml` under the scene: what drawing its lanes and lines costs.
#![allow(
    clippy::unwrap_used,
    reason = "bench setup from constant, valid fixtures: a failure is a fixture bug and must stop the run"
)]

use benches::report::{self, Medians, format_ns};
use criterion::{BenchmarkId, Criterion, criterion_group};
use sim::{Simulation, VehicleId, world_file};

/// The image sizes measured (px) and their targets per image (ms, issue #29).
const SIZES: [(u32, u32, f64); 2] = [(128, 64, 2.0), (256, 128, 8.0)];

/// The world, with a camera of `width` × `height` px.
/// The road of `sim/worlds/highway.toml` (840 m: three 3.75 m lanes, hard shoulders, two
/// dashed lines), laid from the origin along +x under the scene of [`world`].
const HIGHWAY: &str = r#"
[[road]]
id = "highway"
numberOfLanes = 3
numberOfForwardLanes = 3
laneWidths = [3.75, 3.75, 3.75]
rightBorder = true
leftBorder = true
roadBorderWidth = 2.5
[[road.line]]
type = "dashed"
color = [1, 1, 1]
[[road.line]]
type = "dashed"
color = [1, 1, 1]
[[road.segment]]
type = "straight"
length = 600
[[road.segment]]
type = "clothoid"
length = 120
curvatureStart = 0
curvatureEnd = 0.0016666666666666668
[[road.segment]]
type = "arc"
radius = 600
angle = 0.3
[[road.segment]]
type = "clothoid"
length = 120
curvatureStart = 0.0016666666666666668
curvatureEnd = 0
"#;

fn world(width: u32, height: u32) -> (Simulation, VehicleId) {
    world_with(width, height, "")
}

/// The scene of [`world`] with `extra` (world-file text) before it.
fn world_with(width: u32, height: u32, extra: &str) -> (Simulation, VehicleId) {
    let text = format!(
        r#"{extra}
[[vehicle]]
model = "BmwX5"
name = "follower"
[[vehicle.device]]
type = "Camera"
slot = "front"
width = {width}
height = {height}
fieldOfView = 1.0
recognition = {{ maxRange = 100 }}

[[vehicle]]
model = "BmwX5"
name = "lead"
translation = [30, 0, 0]
recognitionColors = [[1, 0, 0]]

[[box]]
translation = [20, 6, 1]
size = [2, 2, 2]
recognitionColors = [[0, 0, 1]]

[[box]]
translation = [40, -7, 1.5]
size = [4, 1, 3]

[[ramp]]
start = [50, 4]
length = 10
width = 4
height = 1

[[body]]
translation = [15, -3, 0.25]
size = [0.5, 0.5, 0.5]
mass = 20
"#
    );
    let description = world_file::parse_str("camera_bench.toml", &text).unwrap();
    let (sim, _) = Simulation::from_description(&description).unwrap();
    let id = sim.car_ids().next().unwrap();
    (sim, id)
}

fn camera(c: &mut Criterion) {
    let mut g = c.benchmark_group("camera");
    let (mut sim, _) = world(128, 64);
    g.bench_function(BenchmarkId::new("step_without_camera", 1), |b| {
        b.iter(|| sim.step().unwrap())
    });
    for (w, h, _) in SIZES {
        let (mut sim, id) = world(w, h);
        // Every 10 ms step, image and Recognition: each step renders once.
        sim.enable_device(id, 0, 10).unwrap();
        sim.enable_recognition(id, 0, 10).unwrap();
        g.bench_function(
            BenchmarkId::new("step_with_camera", format!("{w}x{h}")),
            |b| b.iter(|| sim.step().unwrap()),
        );
    }
    // The same 128 x 64 camera with the highway's lanes and lines under the scene.
    let (mut sim, id) = world_with(128, 64, HIGHWAY);
    sim.enable_device(id, 0, 10).unwrap();
    sim.enable_recognition(id, 0, 10).unwrap();
    g.bench_function(
        BenchmarkId::new("step_with_camera_on_road", "128x64"),
        |b| b.iter(|| sim.step().unwrap()),
    );
    g.finish();
}

criterion_group! {
    name = benches;
    config = report::criterion_config();
    targets = camera
}

/// Prints each image's cost: the step with the camera less the step without.
fn summary(medians: &Medians) {
    println!("\ncamera summary (criterion medians):");
    let Some(base) = medians.get("camera/step_without_camera/1") else {
        println!("  no result in {}", medians.dir().display());
        return;
    };
    println!("  step without camera: {}", format_ns(base));
    for (w, h, target) in SIZES {
        if let Some(t) = medians.get(&format!("camera/step_with_camera/{w}x{h}")) {
            println!(
                "  {w} x {h} image + recognition: step {} , image {} (target <= {target} ms)",
                format_ns(t),
                format_ns(t - base)
            );
        }
    }
    if let (Some(flat), Some(road)) = (
        medians.get("camera/step_with_camera/128x64"),
        medians.get("camera/step_with_camera_on_road/128x64"),
    ) {
        println!(
            "  128 x 64 on the highway's road: step {}, the road's lanes and lines {}",
            format_ns(road),
            format_ns(road - flat)
        );
    }
}

fn main() {
    report::main_with_summary(benches, summary);
}
