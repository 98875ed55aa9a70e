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

use std::hint::black_box;
use std::path::Path;
use std::process::{Command, ExitCode};

use ackermann::{DriveType, Geometry, PerWheel, WheelAngles};
use benches::control::{ControlLoop, LoopMode};
use benches::fixtures;
use benches::fmu::{FmuLoop, NativeLoop};
use benches::peer::{PeerParams, RayCastCar};
use benches::scenes::{CarScene, RobotScene, ring_road_world};
use powertrain::{Engine, EngineType, LimitedSlip, split_torque};
use sim::{Mounting, TyreChoice};
use vehicle_model::{ContactVelocity, Linearised, MagicFormula, Real, TransientSlip, WheelDrive};

/// Steps run natively in smoke mode.
const SMOKE_STEPS: u64 = 3;
/// Steps run (uncounted) before the counted ones, so that lazily initialised state and the
/// first-step paths are not what is measured.
const WARM_UP_STEPS: u64 = 50;

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
        name: "peer_raycast_car",
        function: "cg_peer_step",
        steps: 300,
        run: run_peer,
    },
];

const TORQUE: bool = true;
const SPEED: bool = false;

#[inline(never)]
fn cg_driver_step_f32(l: &mut ControlLoop<f32>) -> PerWheel<WheelDrive<f32>> {
    l.step().drive
}

#[inline(never)]
fn cg_driver_step_f64(l: &mut ControlLoop<f64>) -> PerWheel<WheelDrive<f64>> {
    l.step().drive
}

/// The counted step of a control loop in scalar type `T`.
trait CountedStep: Real {
    fn counted_step(l: &mut ControlLoop<Self>) -> PerWheel<WheelDrive<Self>>;
}

impl CountedStep for f32 {
    fn counted_step(l: &mut ControlLoop<f32>) -> PerWheel<WheelDrive<f32>> {
        cg_driver_step_f32(l)
    }
}

impl CountedStep for f64 {
    fn counted_step(l: &mut ControlLoop<f64>) -> PerWheel<WheelDrive<f64>> {
        cg_driver_step_f64(l)
    }
}

fn run_driver<T: CountedStep, const TORQUE_MODE: bool>(steps: u64) {
    let mode = if TORQUE_MODE {
        LoopMode::Torque
    } else {
        LoopMode::Speed
    };
    let mut l = ControlLoop::<T>::new(mode).unwrap();
    for _ in 0..WARM_UP_STEPS {
        black_box(l.step().drive);
    }
    for _ in 0..steps {
        black_box(T::counted_step(&mut l));
    }
}

#[inline(never)]
fn cg_tyre_force_f32(t: &MagicFormula<f32>, slip: [f32; 2], load: f32) -> [f32; 2] {
    t.force(slip, load, 1.0)
}

#[inline(never)]
fn cg_tyre_force_f64(t: &MagicFormula<f64>, slip: [f64; 2], load: f64) -> [f64; 2] {
    t.force(slip, load, 1.0)
}

#[inline(never)]
fn cg_tyre_linearise_f32(
    t: &MagicFormula<f32>,
    s: &TransientSlip<f32>,
    v: &ContactVelocity<f32>,
    load: f32,
) -> Linearised<f32> {
    t.linearise(s, v, load, 1.0, 0.01)
}

#[inline(never)]
fn cg_tyre_linearise_f64(
    t: &MagicFormula<f64>,
    s: &TransientSlip<f64>,
    v: &ContactVelocity<f64>,
    load: f64,
) -> Linearised<f64> {
    t.linearise(s, v, load, 1.0, 0.01)
}

/// The counted tyre evaluations in scalar type `T`.
trait CountedTyre: Real {
    fn force(t: &MagicFormula<Self>, slip: [Self; 2], load: Self) -> [Self; 2];
    fn linearise(
        t: &MagicFormula<Self>,
        s: &TransientSlip<Self>,
        v: &ContactVelocity<Self>,
        load: Self,
    ) -> Linearised<Self>;
}

impl CountedTyre for f32 {
    fn force(t: &MagicFormula<f32>, slip: [f32; 2], load: f32) -> [f32; 2] {
        cg_tyre_force_f32(t, slip, load)
    }
    fn linearise(
        t: &MagicFormula<f32>,
        s: &TransientSlip<f32>,
        v: &ContactVelocity<f32>,
        load: f32,
    ) -> Linearised<f32> {
        cg_tyre_linearise_f32(t, s, v, load)
    }
}

impl CountedTyre for f64 {
    fn force(t: &MagicFormula<f64>, slip: [f64; 2], load: f64) -> [f64; 2] {
        cg_tyre_force_f64(t, slip, load)
    }
    fn linearise(
        t: &MagicFormula<f64>,
        s: &TransientSlip<f64>,
        v: &ContactVelocity<f64>,
        load: f64,
    ) -> Linearised<f64> {
        cg_tyre_linearise_f64(t, s, v, load)
    }
}

/// The kernels bench's tyre (a passenger tyre at 4.2 kN, combined slip κ −0.08, tan α 0.05;
/// the linearisation over 10 ms from a transient slip): both counted functions are called
/// each step, and each case counts only its own.
fn run_tyre<T: CountedTyre>(steps: u64) {
    let c = fixtures::tyre_case::<T>().unwrap();
    let (one, dt) = (T::ONE, T::from_f64(0.01));
    for i in 0..WARM_UP_STEPS + steps {
        if i < WARM_UP_STEPS {
            black_box(c.tyre.force(black_box(c.slip), black_box(c.load), one));
            black_box(
                c.tyre
                    .linearise(&c.state, &c.velocity, black_box(c.load), one, dt),
            );
        } else {
            black_box(T::force(
                black_box(&c.tyre),
                black_box(c.slip),
                black_box(c.load),
            ));
            black_box(T::linearise(
                black_box(&c.tyre),
                &c.state,
                &c.velocity,
                black_box(c.load),
            ));
        }
    }
}

#[inline(never)]
fn cg_wheel_angles_f64(g: &Geometry<f64>, delta: f64) -> WheelAngles<f64> {
    g.wheel_angles(delta)
}

fn run_wheel_angles_f64(steps: u64) {
    let g = fixtures::bmw_x5::<f64>().unwrap();
    for i in 0..WARM_UP_STEPS + steps {
        // A slowly changing angle, as a driver's steering wheel.
        let delta = 0.2 + (i % 100) as f64 * 1e-3;
        if i < WARM_UP_STEPS {
            black_box(g.wheel_angles(black_box(delta)));
        } else {
            black_box(cg_wheel_angles_f64(black_box(&g), black_box(delta)));
        }
    }
}

#[inline(never)]
fn cg_engine_torque_f64(engine: &Engine<f64>, rpm: f64) -> f64 {
    engine.torque(rpm)
}

fn run_engine_torque_f64(steps: u64) {
    let engine = fixtures::engine::<f64>(EngineType::PowerSplitHybrid).unwrap();
    let rpm = fixtures::bench_rpm::<f64>();
    for i in 0..WARM_UP_STEPS + steps {
        if i < WARM_UP_STEPS {
            black_box(engine.torque(black_box(rpm)));
        } else {
            black_box(cg_engine_torque_f64(black_box(&engine), black_box(rpm)));
        }
    }
}

#[inline(never)]
fn cg_torque_split_f32(
    lsd: &mut LimitedSlip<f32>,
    speeds: &PerWheel<f32>,
    ratios: &ackermann::DifferentialRatios<f32>,
) -> PerWheel<f32> {
    lsd.update(DriveType::FourByFour, speeds);
    split_torque(1500.0, DriveType::FourByFour, &lsd.apply(ratios))
}

fn run_torque_split_f32(steps: u64) {
    let ratios = fixtures::turning_ratios::<f32>().unwrap();
    let speeds = fixtures::turning_wheel_speeds::<f32>();
    let mut lsd = LimitedSlip::new();
    for _ in 0..WARM_UP_STEPS {
        lsd.update(DriveType::FourByFour, black_box(&speeds));
    }
    for _ in 0..steps {
        black_box(cg_torque_split_f32(
            &mut lsd,
            black_box(&speeds),
            black_box(&ratios),
        ));
    }
}

/// Steps run (uncounted) before the counted ones in the simulation cases: 8 s, so the cars
/// cruise on their circles (speed mode reaches 10 m/s in 3 s, the torque-mode throttle
/// controller about 9.7 m/s in 8 s).
const SETTLE_STEPS: u64 = 800;

#[inline(never)]
fn cg_car_step(scene: &mut CarScene) {
    scene.step().unwrap();
}

fn run_car<const TORQUE_MODE: bool>(steps: u64) {
    let mode = if TORQUE_MODE {
        LoopMode::Torque
    } else {
        LoopMode::Speed
    };
    let mut scene = CarScene::new(1, mode).unwrap();
    for _ in 0..SETTLE_STEPS {
        scene.step().unwrap();
    }
    for _ in 0..steps {
        cg_car_step(&mut scene);
    }
}

/// The speed-mode car of `run_car` on the ring road of `scenes::ring_road_world`: all four
/// wheels on the road's lane meshes at every step (compare with `sim_car_speed_1`).
fn run_road_car(steps: u64) {
    let mut scene = CarScene::in_world(
        ring_road_world().unwrap(),
        1,
        LoopMode::Speed,
        &TyreChoice::default(),
        Mounting::Cast,
    )
    .unwrap();
    for _ in 0..SETTLE_STEPS {
        scene.step().unwrap();
    }
    for _ in 0..steps {
        cg_car_step(&mut scene);
    }
}

/// The speed-mode car of `run_car` with its wheels on rapier joints.
fn run_joints_car(steps: u64) {
    let mut scene =
        CarScene::mounted(1, LoopMode::Speed, &TyreChoice::default(), Mounting::Joints).unwrap();
    for _ in 0..SETTLE_STEPS {
        scene.step().unwrap();
    }
    for _ in 0..steps {
        cg_car_step(&mut scene);
    }
}

#[inline(never)]
fn cg_fmu_native_step(l: &mut NativeLoop) {
    l.step().unwrap();
}

/// A controller's 10 ms step on the TeslaModel3's default world (`benches::fmu`): compare
/// with `fmu_do_step`.
fn run_fmu_native(steps: u64) {
    let mut l = NativeLoop::new().unwrap();
    for _ in 0..200 {
        l.step().unwrap();
    }
    for _ in 0..steps {
        cg_fmu_native_step(&mut l);
    }
}

#[inline(never)]
fn cg_fmu_do_step(l: &mut FmuLoop) {
    l.step().unwrap();
}

/// The same step through the FMU's entry points.
fn run_fmu(steps: u64) {
    let mut l = FmuLoop::new().unwrap();
    for _ in 0..200 {
        l.step().unwrap();
    }
    for _ in 0..steps {
        cg_fmu_do_step(&mut l);
    }
}

#[inline(never)]
fn cg_robot_step(scene: &mut RobotScene) {
    scene.step().unwrap();
}

fn run_robot(steps: u64) {
    let mut scene = RobotScene::physics().unwrap();
    for _ in 0..SETTLE_STEPS {
        scene.step().unwrap();
    }
    for _ in 0..steps {
        cg_robot_step(&mut scene);
    }
}

#[inline(never)]
fn cg_peer_step(car: &mut RayCastCar, steering: f32) {
    let force = car.cruise_force(10.0);
    car.step(force, steering);
}

fn run_peer(steps: u64) {
    let mut car = RayCastCar::new(&PeerParams::default());
    // Settle and reach cruise speed before counting.
    for _ in 0..SETTLE_STEPS {
        let force = car.cruise_force(10.0);
        car.step(force, 0.1);
    }
    for _ in 0..steps {
        cg_peer_step(&mut car, black_box(0.1));
    }
}

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
