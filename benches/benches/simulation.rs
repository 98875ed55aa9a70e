//! Criterion benchmarks of one physics step of the `sim` world (cars, the DifferentialWheels
//! robot) beside rapier's own ray-cast car, with a summary of the ratios printed at the end.
#![allow(
    clippy::unwrap_used,
    reason = "bench setup from constant, valid fixtures: a failure is a fixture bug and must stop the run"
)]

use std::hint::black_box;

use benches::control::LoopMode;
use benches::peer::{PeerParams, RayCastCar};
use benches::report::{self, Medians, format_ns};
use benches::scenes::{BASIC_TIME_STEP_MS, CarScene, RobotScene};
use criterion::measurement::WallTime;
use criterion::{BenchmarkGroup, BenchmarkId, Criterion, criterion_group};
use sim::{Mounting, RobotMode, TyreChoice};
use vehicle_model::WebotsContact;

const PEER: &str = "simulation/peer_raycast_car/1";

fn peer(g: &mut BenchmarkGroup<'_, WallTime>) {
    let mut car = RayCastCar::new(&PeerParams::default());
    g.bench_function(BenchmarkId::new("peer_raycast_car", 1), |b| {
        b.iter(|| {
            let f = car.cruise_force(10.0);
            car.step(black_box(f), black_box(0.1));
        })
    });
}

/// Steps run before measuring, so the cars cruise on their circles (8 s: speed mode reaches
/// 10 m/s in 3 s, the torque-mode throttle controller about 9.7 m/s in 8 s).
const SETTLE_STEPS: usize = 800;
/// Car counts of the scaling benchmarks.
const CAR_COUNTS: [usize; 3] = [1, 8, 64];

/// Runs `scene` for [`SETTLE_STEPS`] before it is measured; test mode (`cargo test
/// --benches`) runs each benchmark once and does not settle.
fn settle(scene: &mut CarScene) {
    if report::is_bench_run() {
        for _ in 0..SETTLE_STEPS {
            scene.step().unwrap();
        }
    }
}

fn mode_name(mode: LoopMode) -> &'static str {
    match mode {
        LoopMode::Speed => "car_speed",
        LoopMode::Torque => "car_torque",
    }
}

fn cars(g: &mut BenchmarkGroup<'_, WallTime>) {
    for mode in [LoopMode::Speed, LoopMode::Torque] {
        for n in CAR_COUNTS {
            let mut scene = CarScene::new(n, mode).unwrap();
            settle(&mut scene);
            g.bench_function(BenchmarkId::new(mode_name(mode), n), |b| {
                b.iter(|| scene.step().unwrap())
            });
        }
    }
}

/// One car in speed mode on Webots' contact (`tyre = "webots"`), beside the slip-based tyre.
fn webots_contact(g: &mut BenchmarkGroup<'_, WallTime>) {
    let mut scene = CarScene::on(1, LoopMode::Speed, &webots_tyre()).unwrap();
    settle(&mut scene);
    g.bench_function(BenchmarkId::new("car_speed_webots_contact", 1), |b| {
        b.iter(|| scene.step().unwrap())
    });
}

/// Car counts of the joints mounting's benchmarks: one car, and the scaling at 64.
const JOINTS_CAR_COUNTS: [usize; 2] = [1, 64];

/// Cars on rapier joints (`mounting = "joints"`) in speed mode, on the same circle.
fn joints(g: &mut BenchmarkGroup<'_, WallTime>) {
    for n in JOINTS_CAR_COUNTS {
        let mut scene =
            CarScene::mounted(n, LoopMode::Speed, &TyreChoice::default(), Mounting::Joints)
                .unwrap();
        settle(&mut scene);
        g.bench_function(BenchmarkId::new("car_speed_joints", n), |b| {
            b.iter(|| scene.step().unwrap())
        });
    }
}

fn webots_tyre() -> TyreChoice {
    TyreChoice::Webots(WebotsContact::default())
}

fn robots(g: &mut BenchmarkGroup<'_, WallTime>) {
    for (mode, mut scene) in [
        (
            "kinematics",
            RobotScene::new(RobotMode::Kinematics).unwrap(),
        ),
        ("physics", RobotScene::physics().unwrap()),
    ] {
        g.bench_function(BenchmarkId::new("differential_wheels", mode), |b| {
            b.iter(|| scene.step().unwrap())
        });
    }
}

fn simulation(c: &mut Criterion) {
    let mut g = c.benchmark_group("simulation");
    peer(&mut g);
    cars(&mut g);
    webots_contact(&mut g);
    joints(&mut g);
    robots(&mut g);
    g.finish();
}

criterion_group! {
    name = benches;
    config = report::criterion_config();
    targets = simulation
}

/// Prints the ratios the README tracks, from the medians criterion just wrote.
fn summary(medians: &Medians) {
    let median = |id: &str| medians.get(id);
    println!("\nsimulation summary (criterion medians, basicTimeStep {BASIC_TIME_STEP_MS} ms):");
    let Some(peer) = median(PEER) else {
        println!("  no result for {PEER} in {}", medians.dir().display());
        return;
    };
    println!("  peer ray-cast car step: {}", format_ns(peer));
    let step_ns = f64::from(BASIC_TIME_STEP_MS) * 1e6;
    for mode in [LoopMode::Speed, LoopMode::Torque] {
        let name = mode_name(mode);
        let Some(one) = median(&format!("simulation/{name}/1")) else {
            continue;
        };
        println!(
            "  {name}, 1 car: {} = {:.0}x real time (target >= 1000x), {:.2}x the peer (target <= 2.5x)",
            format_ns(one),
            step_ns / one,
            one / peer
        );
        for n in CAR_COUNTS.into_iter().skip(1) {
            if let Some(t) = median(&format!("simulation/{name}/{n}")) {
                println!(
                    "  {name}, {n} cars: {} = {} per car, {:.2}x of {n} x 1 car (target <= 1)",
                    format_ns(t),
                    format_ns(t / n as f64),
                    t / (n as f64 * one)
                );
            }
        }
    }
    if let Some(t) = median("simulation/car_speed_webots_contact/1") {
        println!(
            "  car_speed on Webots' contact, 1 car: {} = {:.0}x real time, {:.2}x the peer",
            format_ns(t),
            step_ns / t,
            t / peer
        );
    }
    if let Some(one) = median("simulation/car_speed_joints/1") {
        println!(
            "  car_speed on joints, 1 car: {} = {:.0}x real time (target >= 300x), {:.2}x the peer",
            format_ns(one),
            step_ns / one,
            one / peer
        );
        if let Some(t) = median("simulation/car_speed_joints/64") {
            println!(
                "  car_speed on joints, 64 cars: {} per car, {:.2}x of 64 x 1 car (target <= 1)",
                format_ns(t / 64.0),
                t / (64.0 * one)
            );
        }
    }
    for mode in ["kinematics", "physics"] {
        if let Some(t) = median(&format!("simulation/differential_wheels/{mode}")) {
            println!("  differential_wheels, {mode}: {}", format_ns(t));
        }
    }
}

fn main() {
    report::main_with_summary(benches, summary);
}
