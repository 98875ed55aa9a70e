//! The kernel cases: the driver's control loop, the tyre, the steering geometry, the engine
//! curve and the limited slip, each a pure function of its inputs.

use std::hint::black_box;

use ackermann::{DriveType, Geometry, PerWheel, WheelAngles};
use benches::control::{ControlLoop, LoopMode};
use benches::fixtures;
use powertrain::{Engine, EngineType, LimitedSlip, split_torque};
use vehicle_model::{ContactVelocity, Linearised, MagicFormula, Real, TransientSlip, WheelDrive};

use super::WARM_UP_STEPS;

#[inline(never)]
fn cg_driver_step_f32(l: &mut ControlLoop<f32>) -> PerWheel<WheelDrive<f32>> {
    l.step().drive
}

#[inline(never)]
fn cg_driver_step_f64(l: &mut ControlLoop<f64>) -> PerWheel<WheelDrive<f64>> {
    l.step().drive
}

/// The counted step of a control loop in scalar type `T`.
pub(crate) trait CountedStep: Real {
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

pub(crate) fn run_driver<T: CountedStep, const TORQUE_MODE: bool>(steps: u64) {
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
pub(crate) trait CountedTyre: Real {
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
pub(crate) fn run_tyre<T: CountedTyre>(steps: u64) {
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

pub(crate) fn run_wheel_angles_f64(steps: u64) {
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

pub(crate) fn run_engine_torque_f64(steps: u64) {
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

pub(crate) fn run_torque_split_f32(steps: u64) {
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
