//! Criterion benchmark of the FMU's overhead (issue #32): one `fmi2DoStep` of 10 ms with the
//! inputs a tool sets and the outputs it reads around it, against the native step a
//! controller makes through the Rust API with the same commands and reads
//! (`benches::fmu`). The target: the FMU costs at most 20 % more. The instruction counts of
//! the same two loops are in the `callgrind` bench (`fmu_native_step`, `fmu_do_step`), stable
//! where wall time moves with the machine's load.
#![allow(
    clippy::unwrap_used,
    reason = "bench setup from constant, valid fixtures: a failure is a fixture bug and must stop the run"
)]

use benches::fmu::{FmuLoop, NativeLoop};
use benches::report::{self, Medians, format_ns};
use criterion::{Criterion, criterion_group};

/// Steps before measuring (2 s); one in test mode.
fn settle() -> usize {
    if report::is_bench_run() { 200 } else { 1 }
}

/// Both cases in one group, so they are measured in the same run.
fn overhead(c: &mut Criterion) {
    let mut g = c.benchmark_group("fmu");
    let mut native = NativeLoop::new().unwrap();
    for _ in 0..settle() {
        native.step().unwrap();
    }
    g.bench_function("native_step_10ms", |b| b.iter(|| native.step().unwrap()));
    let mut fmu = FmuLoop::new().unwrap();
    for _ in 0..settle() {
        fmu.step().unwrap();
    }
    g.bench_function("fmi2_do_step_10ms", |b| b.iter(|| fmu.step().unwrap()));
    g.finish();
}

criterion_group! {
    name = benches;
    config = report::criterion_config();
    targets = overhead
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
