//! Criterion benchmark of the FMU's overhead (issue #32): one `fmi2DoStep` of 10 ms (one basic
//! step of the TeslaModel3's default world) with the inputs a tool sets and the outputs it
//! reads around it, against the native step a controller makes through the Rust API with the
//! same commands and reads. The target: the FMU costs at most 20 % more.
//!
//! Both cruise at 50 km/h on the same world, settled for 2 s; each iteration sets the cruising
//! speed and steering angle, steps 10 ms and reads x, y, yaw, speed, yaw rate and engine speed.
#![allow(
    unsafe_code,
    clippy::unwrap_used,
    reason = "bench setup from constant, valid fixtures: a failure is a fixture bug and must stop the run; the FMU is called through its C entry points"
)]

use std::ffi::CString;
use std::hint::black_box;

use benches::report::{self, Medians, format_ns};
use criterion::{BenchmarkId, Criterion, criterion_group};
use sim::{Simulation, world_file};
use vehicle_fmu::fmi2::{
    fmi2DoStep, fmi2EnterInitializationMode, fmi2ExitInitializationMode, fmi2FreeInstance,
    fmi2GetReal, fmi2Instantiate, fmi2SetInteger, fmi2SetReal,
};
use vehicle_fmu::model_description::guid;
use vehicle_fmu::variables::{CONTROL_MODE, CRUISING_SPEED, STEERING_ANGLE};

const WORLD: &str = "basicTimeStep = 10\n[vehicle]\nmodel = \"TeslaModel3\"\n";
/// Steps before measuring (2 s); one in test mode.
fn settle() -> usize {
    if report::is_bench_run() { 200 } else { 1 }
}
/// 50 km/h.
const CRUISE_MS: f64 = 50.0 / 3.6;
/// The outputs read after each step: x, y, yaw, speed, yaw rate, engine speed.
const OUTPUTS: [u32; 6] = [100, 101, 105, 106, 109, 116];

fn native(c: &mut Criterion) {
    let description = world_file::parse_str("bench.toml", WORLD).unwrap();
    let (mut sim, _) = Simulation::from_description(&description).unwrap();
    let id = sim.car_ids().next().unwrap();
    let mut step = |sim: &mut Simulation| {
        let d = sim.driver_mut(id).unwrap();
        d.set_cruising_speed(black_box(CRUISE_MS * 3.6));
        d.set_steering_angle(black_box(0.0));
        sim.step().unwrap();
        let t = sim.telemetry(id).unwrap();
        black_box((
            t.state.position.x,
            t.state.position.y,
            t.state.roll_pitch_yaw.yaw,
            t.speed,
            t.state.yaw_rate,
            t.rpm,
        ));
    };
    for _ in 0..settle() {
        step(&mut sim);
    }
    c.bench_function(BenchmarkId::new("fmu", "native_step_10ms"), |b| {
        b.iter(|| step(&mut sim))
    });
}

fn fmu(c: &mut Criterion) {
    let dir = std::env::temp_dir().join(format!("vehicle-fmu-bench-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(dir.join("world.toml"), WORLD).unwrap();
    let uri = CString::new(format!("file://{}", dir.display())).unwrap();
    let (name, token) = (
        CString::new("bench").unwrap(),
        CString::new(guid()).unwrap(),
    );
    // SAFETY: valid C strings; NULL callbacks (nothing logged).
    let fmu = unsafe {
        fmi2Instantiate(
            name.as_ptr(),
            1,
            token.as_ptr(),
            uri.as_ptr(),
            std::ptr::null(),
            0,
            0,
        )
    };
    assert!(!fmu.is_null());
    assert_eq!(fmi2EnterInitializationMode(fmu), 0);
    assert_eq!(fmi2ExitInitializationMode(fmu), 0);
    // SAFETY: one reference, one value.
    assert_eq!(unsafe { fmi2SetInteger(fmu, &CONTROL_MODE, 1, &0) }, 0);
    let mut t = 0.0;
    let inputs = [CRUISING_SPEED, STEERING_ANGLE];
    let mut outputs = [0.0; OUTPUTS.len()];
    let mut step = |t: &mut f64| {
        let values = [black_box(CRUISE_MS), black_box(0.0)];
        // SAFETY: arrays of the lengths passed.
        unsafe {
            assert_eq!(fmi2SetReal(fmu, inputs.as_ptr(), 2, values.as_ptr()), 0);
            assert_eq!(fmi2DoStep(fmu, *t, 0.01, 1), 0);
            assert_eq!(
                fmi2GetReal(fmu, OUTPUTS.as_ptr(), OUTPUTS.len(), outputs.as_mut_ptr()),
                0
            );
        }
        *t += 0.01;
        black_box(outputs);
    };
    for _ in 0..settle() {
        step(&mut t);
    }
    c.bench_function(BenchmarkId::new("fmu", "fmi2_do_step_10ms"), |b| {
        b.iter(|| step(&mut t))
    });
    // SAFETY: freed once.
    unsafe { fmi2FreeInstance(fmu) };
    let _ = std::fs::remove_dir_all(&dir);
}

criterion_group! {
    name = benches;
    config = report::criterion_config();
    targets = native, fmu
}

/// The FMU's overhead against the target.
fn summary(medians: &Medians) {
    let (Some(native), Some(fmu)) = (
        medians.get("fmu/native_step_10ms"),
        medians.get("fmu/fmi2_do_step_10ms"),
    ) else {
        return;
    };
    println!(
        "\nFMU doStep of 10 ms: {} against the native step's {}: {:+.1} % (target ≤ +20 %)",
        format_ns(fmu),
        format_ns(native),
        100.0 * (fmu / native - 1.0)
    );
}

fn main() {
    report::main_with_summary(benches, summary);
}
