//! Instruction counts per step under valgrind's callgrind: the stable number on a noisy shared
//! machine, where wall time moves by tens of percent.
//!
//! * `cargo bench -p benches --bench callgrind`: re-runs this binary under
//!   `valgrind --tool=callgrind --toggle-collect=<the case's step function>` for every case and
//!   prints the instructions per step (skips with a message if `valgrind` is not installed);
//! * `cargo test -p benches --benches` (no `--bench` argument): runs every case natively for a
//!   few steps, as a smoke test, and exits;
//! * `<this binary> --case NAME --steps N`: one case, as the valgrind child runs it.
//!
//! Only the calls of the case's `cg_*` function are counted (`--toggle-collect`, no client
//! requests in the code), after a warm-up outside it, so set-up and warm-up cost nothing.
#![allow(
    clippy::unwrap_used,
    reason = "bench setup from constant, valid fixtures: a failure is a fixture bug and must stop the run"
)]

use std::path::Path;
use std::process::{Command, ExitCode};

/// Steps run natively in smoke mode.
const SMOKE_STEPS: u64 = 3;
/// Steps run (uncounted) before the counted ones, so that lazily initialised state and the
/// first-step paths are not what is measured.
const WARM_UP_STEPS: u64 = 50;

mod kernels;
mod scenes;

use kernels::{
    run_driver, run_engine_torque_f64, run_torque_split_f32, run_tyre, run_wheel_angles_f64,
};
use scenes::{
    run_car, run_energy, run_fmu, run_fmu_native, run_joints_car, run_peer, run_road_car, run_robot,
};

/// `run_driver`'s and `run_car`'s mode: torque control.
const TORQUE: bool = true;
/// Speed control.
const SPEED: bool = false;

/// One measured case: its name, the `cg_*` function whose calls are counted, the number of
/// counted steps under valgrind, and the runner.
struct Case {
    name: &'static str,
    function: &'static str,
    steps: u64,
    run: fn(u64),
}

const CASES: &[Case] = &[
    Case {
        name: "driver_torque_4x4_lsd_f32",
        function: "cg_driver_step_f32",
        steps: 10_000,
        run: run_driver::<f32, { TORQUE }>,
    },
    Case {
        name: "driver_torque_4x4_lsd_f64",
        function: "cg_driver_step_f64",
        steps: 10_000,
        run: run_driver::<f64, { TORQUE }>,
    },
    Case {
        name: "driver_speed_f32",
        function: "cg_driver_step_f32",
        steps: 10_000,
        run: run_driver::<f32, { SPEED }>,
    },
    Case {
        name: "driver_speed_f64",
        function: "cg_driver_step_f64",
        steps: 10_000,
        run: run_driver::<f64, { SPEED }>,
    },
    Case {
        name: "wheel_angles_f64",
        function: "cg_wheel_angles_f64",
        steps: 10_000,
        run: run_wheel_angles_f64,
    },
    Case {
        name: "engine_torque_power_split_f64",
        function: "cg_engine_torque_f64",
        steps: 10_000,
        run: run_engine_torque_f64,
    },
    Case {
        name: "torque_split_lsd_4x4_f32",
        function: "cg_torque_split_f32",
        steps: 10_000,
        run: run_torque_split_f32,
    },
    Case {
        name: "tyre_force_f32",
        function: "cg_tyre_force_f32",
        steps: 10_000,
        run: run_tyre::<f32>,
    },
    Case {
        name: "tyre_force_f64",
        function: "cg_tyre_force_f64",
        steps: 10_000,
        run: run_tyre::<f64>,
    },
    Case {
        name: "tyre_linearise_f32",
        function: "cg_tyre_linearise_f32",
        steps: 10_000,
        run: run_tyre::<f32>,
    },
    Case {
        name: "tyre_linearise_f64",
        function: "cg_tyre_linearise_f64",
        steps: 10_000,
        run: run_tyre::<f64>,
    },
    Case {
        name: "sim_car_speed_1",
        function: "cg_car_step",
        steps: 100,
        run: run_car::<{ SPEED }>,
    },
    Case {
        name: "sim_car_torque_1",
        function: "cg_car_step",
        steps: 100,
        run: run_car::<{ TORQUE }>,
    },
    Case {
        name: "sim_car_speed_road_1",
        function: "cg_car_step",
        steps: 100,
        run: run_road_car,
    },
    Case {
        name: "sim_car_speed_joints_1",
        function: "cg_car_step",
        steps: 100,
        run: run_joints_car,
    },
    Case {
        name: "fmu_native_step",
        function: "cg_fmu_native_step",
        steps: 100,
        run: run_fmu_native,
    },
    Case {
        name: "fmu_do_step",
        function: "cg_fmu_do_step",
        steps: 100,
        run: run_fmu,
    },
    Case {
        name: "sim_differential_wheels_physics",
        function: "cg_robot_step",
        steps: 300,
        run: run_robot,
    },
    Case {
        name: "energy_webots",
        function: "cg_energy_step",
        steps: 100,
        run: run_energy::<0>,
    },
    Case {
        name: "energy_road_load_and_air",
        function: "cg_energy_step",
        steps: 100,
        run: run_energy::<1>,
    },
    Case {
        name: "energy_road_load_air_and_energy",
        function: "cg_energy_step",
        steps: 100,
        run: run_energy::<2>,
    },
    Case {
        name: "peer_raycast_car",
        function: "cg_peer_step",
        steps: 300,
        run: run_peer,
    },
];

/// Value of the `--name VALUE` argument.
fn arg(args: &[String], name: &str) -> Option<String> {
    args.iter()
        .position(|a| a == name)
        .and_then(|i| args.get(i + 1).cloned())
}

/// Runs `case` under callgrind and returns the instructions per counted step.
fn count(exe: &Path, case: &Case, out_dir: &Path) -> Result<f64, String> {
    let out_file = out_dir.join(format!("callgrind.{}.out", case.name));
    let status = Command::new("valgrind")
        .arg("--tool=callgrind")
        .arg(format!("--toggle-collect=*{}*", case.function))
        .arg("--dump-instr=no")
        .arg(format!("--callgrind-out-file={}", out_file.display()))
        .arg(exe)
        .args(["--case", case.name, "--steps", &case.steps.to_string()])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::null())
        .status()
        .map_err(|e| format!("cannot start valgrind: {e}"))?;
    if !status.success() {
        return Err(format!("valgrind exited with {status}"));
    }
    let text = std::fs::read_to_string(&out_file)
        .map_err(|e| format!("cannot read {}: {e}", out_file.display()))?;
    let total: u64 = text
        .lines()
        .find_map(|l| {
            l.strip_prefix("summary:")
                .or_else(|| l.strip_prefix("totals:"))
        })
        .and_then(|v| v.split_whitespace().next()?.parse().ok())
        .ok_or_else(|| format!("no instruction total in {}", out_file.display()))?;
    if total == 0 {
        return Err(format!("no instruction counted in `{}`", case.function));
    }
    Ok(total as f64 / case.steps as f64)
}

fn bench_all() -> ExitCode {
    let valgrind = Command::new("valgrind").arg("--version").output();
    if !valgrind.is_ok_and(|o| o.status.success()) {
        println!("callgrind: `valgrind` not found, instruction counts skipped");
        return ExitCode::SUCCESS;
    }
    let exe = match std::env::current_exe() {
        Ok(exe) => exe,
        Err(e) => {
            eprintln!("callgrind: cannot locate this executable: {e}");
            return ExitCode::FAILURE;
        }
    };
    let out_dir = benches::report::criterion_dir()
        .parent()
        .map_or_else(std::env::temp_dir, |t| t.join("callgrind"));
    if let Err(e) = std::fs::create_dir_all(&out_dir) {
        eprintln!("callgrind: cannot create {}: {e}", out_dir.display());
        return ExitCode::FAILURE;
    }
    println!(
        "instructions per step (callgrind, Ir), outputs in {}",
        out_dir.display()
    );
    let mut failed = false;
    let mut counts = Vec::new();
    for case in CASES {
        match count(&exe, case, &out_dir) {
            Ok(ir) => {
                println!("  {:<36} {:>12.0}", case.name, ir);
                counts.push((case.name, ir));
            }
            Err(e) => {
                println!("  {:<36} error: {e}", case.name);
                failed = true;
            }
        }
    }
    let ir = |name: &str| counts.iter().find(|(n, _)| *n == name).map(|(_, ir)| *ir);
    if let Some(peer) = ir("peer_raycast_car") {
        for car in ["sim_car_speed_1", "sim_car_torque_1"] {
            if let Some(c) = ir(car) {
                println!(
                    "  {car} / peer_raycast_car = {:.2}x (target <= 6x)",
                    c / peer
                );
            }
        }
    }
    if let Some(webots) = ir("energy_webots") {
        for case in [
            "energy_road_load_and_air",
            "energy_road_load_air_and_energy",
        ] {
            if let Some(c) = ir(case) {
                println!(
                    "  {case} / energy_webots = {:.3}x (target <= 1.1x)",
                    c / webots
                );
            }
        }
    }
    if let (Some(fmu), Some(native)) = (ir("fmu_do_step"), ir("fmu_native_step")) {
        println!(
            "  fmu_do_step / fmu_native_step = {:.3}x (target <= 1.2x)",
            fmu / native
        );
    }
    if failed {
        ExitCode::FAILURE
    } else {
        ExitCode::SUCCESS
    }
}

fn main() -> ExitCode {
    let args: Vec<String> = std::env::args().collect();
    if let Some(name) = arg(&args, "--case") {
        let Some(case) = CASES.iter().find(|c| c.name == name) else {
            eprintln!("callgrind: unknown case `{name}`");
            return ExitCode::FAILURE;
        };
        let steps = arg(&args, "--steps")
            .and_then(|s| s.parse().ok())
            .unwrap_or(case.steps);
        (case.run)(steps);
        return ExitCode::SUCCESS;
    }
    if args.iter().any(|a| a == "--bench") {
        return bench_all();
    }
    for case in CASES {
        (case.run)(SMOKE_STEPS);
    }
    println!("callgrind: {} cases ran natively (smoke test)", CASES.len());
    ExitCode::SUCCESS
}
