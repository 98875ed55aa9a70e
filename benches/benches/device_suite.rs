//! Criterion benchmark of a car carrying the whole device suite (issue #29): on the ACC world
//! (`sim/worlds/acc.toml`: a lead BmwX5 50 m ahead with `radarCrossSection` 10), the follower
//! BmwX5 carries the long-range radar, a SICK LMS 291 on its roof, a 128×64 camera on its
//! front slot, a GPS and an inertial unit, all sampled every 50 ms. One iteration is 5 steps
//! (50 ms simulated, one sample of every device), so the time per iteration gives the real-time
//! factor directly and the sampling step is not hidden by a median of cheap steps.
//!
//! Cases: the suite enabled; enabled and the run recorded (telemetry, replay keyframes and the
//! devices' readings for `devices.csv`); the same devices present but disabled; the follower
//! without devices. The summary prints the real-time factors and what enabling costs.
#![allow(
    clippy::unwrap_used,
    reason = "bench setup from constant, valid fixtures: a failure is a fixture bug and must stop the run"
)]

use benches::report::{self, Medians, format_ns};
use criterion::{BenchmarkId, Criterion, criterion_group};
use sim::{Simulation, world_file};

/// Steps per iteration: one sampling period of 50 ms at the world's 10 ms.
const STEPS: usize = 5;

/// The devices added to the follower after the ACC world's radar.
const SUITE: &str = r#"
[[vehicle.device]]
type = "Lidar"
name = "sick"
slot = "top"
preset = "SickLms291"
[[vehicle.device]]
type = "Camera"
slot = "front"
width = 128
height = 64
fieldOfView = 1.0
[[vehicle.device]]
type = "GPS"
slot = "top"
[[vehicle.device]]
type = "InertialUnit"
slot = "top"
"#;

/// The follower's devices: the radar and [`SUITE`].
const DEVICES: usize = 5;

/// What a case has of the suite.
#[derive(Clone, Copy)]
enum Case {
    Enabled,
    Recorded,
    Disabled,
    NoDevices,
}

impl Case {
    const ALL: [Case; 4] = [
        Case::Enabled,
        Case::Recorded,
        Case::Disabled,
        Case::NoDevices,
    ];

    fn name(self) -> &'static str {
        match self {
            Case::Enabled => "enabled",
            Case::Recorded => "enabled_recorded",
            Case::Disabled => "disabled",
            Case::NoDevices => "no_devices",
        }
    }
}

/// The ACC world as `case` has it, the cars driving for 2 s.
fn scene(case: Case) -> Simulation {
    let acc = include_str!("../../sim/worlds/acc.toml");
    let text = match case {
        // The ACC world's follower has the radar as its last table: cut it off.
        Case::NoDevices => acc[..acc.find("[[vehicle.device]]").unwrap()].to_string(),
        _ => format!("{acc}\n{SUITE}"),
    };
    let description = world_file::parse_str("acc.toml", &text).unwrap();
    let (mut sim, _) = Simulation::from_description(&description).unwrap();
    // Only the devices each case enables sample (the world's `samplingPeriod` keys aside).
    sim.disable_devices();
    let ids: Vec<_> = sim.car_ids().collect();
    for &id in &ids {
        sim.driver_mut(id).unwrap().set_cruising_speed(54.0);
    }
    if matches!(case, Case::Enabled | Case::Recorded) {
        for i in 0..DEVICES {
            sim.enable_device(ids[1], i, 50).unwrap();
        }
    }
    if matches!(case, Case::Recorded) {
        sim.record("bench");
    }
    let settle = if report::is_bench_run() { 200 } else { 1 };
    for _ in 0..settle {
        sim.step().unwrap();
    }
    sim
}

fn device_suite(c: &mut Criterion) {
    let mut g = c.benchmark_group("device_suite");
    for case in Case::ALL {
        let mut sim = scene(case);
        g.bench_function(BenchmarkId::new("50ms", case.name()), |b| {
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
    targets = device_suite
}

/// Real-time factors and the cost of enabling the suite.
fn summary(medians: &Medians) {
    println!("\ndevice suite, 50 ms simulated per iteration (criterion medians, ACC world):");
    let get = |case: Case| medians.get(&format!("device_suite/50ms/{}", case.name()));
    for case in Case::ALL {
        if let Some(ns) = get(case) {
            println!(
                "  {}: {} ({:.0}x real time)",
                case.name(),
                format_ns(ns),
                50e6 / ns
            );
        }
    }
    if let (Some(on), Some(off), Some(none)) = (
        get(Case::Enabled),
        get(Case::Disabled),
        get(Case::NoDevices),
    ) {
        println!(
            "  enabling the suite costs {} per 50 ms; devices present but disabled {}",
            format_ns(on - off),
            format_ns(off - none)
        );
    }
}

fn main() {
    report::main_with_summary(benches, summary);
}
