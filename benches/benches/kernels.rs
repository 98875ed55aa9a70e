//! Criterion benchmarks of the numeric kernels under the control loop and the plant: Ackermann
//! wheel angles, engine torque per engine type, the torque split through the limited-slip
//! differential, and the slip-based tyre.
#![allow(
    clippy::unwrap_used,
    reason = "bench setup from constant, valid fixtures: a failure is a fixture bug and must stop the run"
)]

use std::hint::black_box;

use ackermann::{DriveType, Real};
use benches::fixtures;
use criterion::measurement::WallTime;
use criterion::{BenchmarkGroup, BenchmarkId, Criterion, criterion_group, criterion_main};
use powertrain::{EngineType, LimitedSlip, split_torque};

fn wheel_angles<T: Real>(g: &mut BenchmarkGroup<'_, WallTime>, name: &str) {
    let geometry = fixtures::bmw_x5::<T>().unwrap();
    let delta = T::from_f64(0.2);
    g.bench_function(BenchmarkId::new("wheel_angles", name), |b| {
        b.iter(|| black_box(&geometry).wheel_angles(black_box(delta)))
    });
}

fn engine_torque(g: &mut BenchmarkGroup<'_, WallTime>) {
    for t in EngineType::ALL {
        let engine = fixtures::engine::<f64>(t).unwrap();
        let rpm = fixtures::bench_rpm::<f64>();
        let id = BenchmarkId::new("engine_torque", t.webots_name().replace(' ', "_"));
        g.bench_function(id, |b| b.iter(|| black_box(&engine).torque(black_box(rpm))));
    }
}

fn torque_split<T: Real>(g: &mut BenchmarkGroup<'_, WallTime>, name: &str) {
    let ratios = fixtures::turning_ratios::<T>().unwrap();
    let speeds = fixtures::turning_wheel_speeds::<T>();
    let output = T::from_f64(1500.0);
    let mut lsd = LimitedSlip::<T>::new();
    g.bench_function(BenchmarkId::new("torque_split_lsd_4x4", name), |b| {
        b.iter(|| {
            lsd.update(DriveType::FourByFour, black_box(&speeds));
            let r = lsd.apply(black_box(&ratios));
            split_torque(black_box(output), DriveType::FourByFour, &r)
        })
    });
}

/// One tyre evaluation: the combined-slip force of a passenger tyre at its nominal load, and
/// the linearisation a simulator asks for each wheel each step (transient slip predicted over
/// 10 ms, force and slope per unit load), at a braking slip with a slip angle.
fn tyre<T: Real>(g: &mut BenchmarkGroup<'_, WallTime>, name: &str) {
    let c = fixtures::tyre_case::<T>().unwrap();
    let one = T::ONE;
    g.bench_function(BenchmarkId::new("tyre_force", name), |b| {
        b.iter(|| black_box(&c.tyre).force(black_box(c.slip), black_box(c.load), one))
    });
    g.bench_function(BenchmarkId::new("tyre_linearise", name), |b| {
        b.iter(|| {
            black_box(&c.tyre).linearise(
                black_box(&c.state),
                black_box(&c.velocity),
                black_box(c.load),
                one,
                T::from_f64(0.01),
            )
        })
    });
}

fn kernels(c: &mut Criterion) {
    let mut g = c.benchmark_group("kernels");
    wheel_angles::<f32>(&mut g, "f32");
    wheel_angles::<f64>(&mut g, "f64");
    engine_torque(&mut g);
    torque_split::<f32>(&mut g, "f32");
    torque_split::<f64>(&mut g, "f64");
    tyre::<f32>(&mut g, "f32");
    tyre::<f64>(&mut g, "f64");
    g.finish();
}

criterion_group! {
    name = benches;
    config = benches::report::criterion_config();
    targets = kernels
}
criterion_main!(benches);
