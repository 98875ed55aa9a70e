//! Criterion benchmarks of one driver control-loop step ([`vehicle_model::Driver::step`] plus
//! a steering command), in torque mode (4x4, limited slip) and in speed mode, f32 and f64,
//! against the fixed, advancing sensor frame of [`benches::control`].
#![allow(
    clippy::unwrap_used,
    reason = "bench setup from constant, valid fixtures: a failure is a fixture bug and must stop the run"
)]

use std::hint::black_box;

use benches::control::{ControlLoop, LoopMode};
use criterion::measurement::WallTime;
use criterion::{BenchmarkGroup, BenchmarkId, Criterion, criterion_group, criterion_main};
use vehicle_model::Real;

fn driver_step<T: Real>(g: &mut BenchmarkGroup<'_, WallTime>, mode: LoopMode, scalar: &str) {
    let name = match mode {
        LoopMode::Torque => "torque_4x4_lsd",
        LoopMode::Speed => "speed",
    };
    let mut l = ControlLoop::<T>::new(mode).unwrap();
    g.bench_function(BenchmarkId::new(name, scalar), |b| {
        b.iter(|| black_box(l.step().drive))
    });
}

fn control_loop(c: &mut Criterion) {
    let mut g = c.benchmark_group("control_loop");
    driver_step::<f32>(&mut g, LoopMode::Torque, "f32");
    driver_step::<f64>(&mut g, LoopMode::Torque, "f64");
    driver_step::<f32>(&mut g, LoopMode::Speed, "f32");
    driver_step::<f64>(&mut g, LoopMode::Speed, "f64");
    g.finish();
}

criterion_group! {
    name = benches;
    config = benches::report::criterion_config();
    targets = control_loop
}
criterion_main!(benches);
