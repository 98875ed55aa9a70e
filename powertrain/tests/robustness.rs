//! Invariants under random and extreme inputs: no NaN or ∞ out of any runtime function,
//! limited-slip states in [−1, 1], split torques adding up to the output torque.

// Helpers outside `#[test]` functions build known-good fixtures.
#![allow(clippy::unwrap_used)]

use ackermann::{DifferentialRatios, DriveType, PerWheel, Real};
use powertrain::{
    AutoShift, AutoShiftParams, Brake, Engine, EngineParams, EngineType, Gear, Gearbox,
    LimitedSlip, Powertrain, acceleration_limit_factor, max_signed_acceleration, split_torque,
};

/// xorshift64*: a tiny deterministic generator, so failures reproduce.
struct Rng(u64);

impl Rng {
    fn next_u64(&mut self) -> u64 {
        self.0 ^= self.0 >> 12;
        self.0 ^= self.0 << 25;
        self.0 ^= self.0 >> 27;
        self.0.wrapping_mul(0x2545_f491_4f6c_dd1d)
    }
    /// Uniform in [lo, hi).
    fn uniform(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * (self.next_u64() >> 11) as f64 / (1u64 << 53) as f64
    }
    /// Mostly ordinary values, sometimes an extreme one.
    fn value(&mut self, scale: f64) -> f64 {
        if self.next_u64().is_multiple_of(8) {
            EXTREMES[(self.next_u64() % EXTREMES.len() as u64) as usize]
        } else {
            self.uniform(-scale, scale)
        }
    }
}

const EXTREMES: [f64; 14] = [
    0.0,
    -0.0,
    1.0,
    -1.0,
    1e-300,
    -1e-300,
    5e-324,
    1e300,
    -1e300,
    f64::MAX,
    f64::MIN,
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
];

fn engines<T: Real>() -> [Engine<T>; 4] {
    EngineType::ALL.map(|engine_type| {
        Engine::new(EngineParams {
            engine_type,
            ..EngineParams::default()
        })
        .unwrap()
    })
}

fn gears() -> [Gear; 8] {
    [
        Gear::REVERSE,
        Gear::NEUTRAL,
        Gear::FIRST,
        Gear::forward(2).unwrap(),
        Gear::forward(5).unwrap(),
        Gear::forward(6).unwrap(), // beyond the default table
        Gear::forward(15).unwrap(),
        Gear::default(),
    ]
}

fn run<T: Real>(seed: u64) {
    let mut rng = Rng(seed);
    let v = |rng: &mut Rng, scale: f64| T::from_f64(rng.value(scale));
    let brake = Brake::<T>::default();
    for engine in engines::<T>() {
        let pt = Powertrain::new(engine, Gearbox::default());
        let mut lsd = LimitedSlip::<T>::new();
        let mut auto = AutoShift::new(AutoShiftParams::for_engine(&engine), &engine).unwrap();
        for i in 0..5000 {
            let speeds = PerWheel::from_fn(|_| v(&mut rng, 300.0));
            let accelerations = PerWheel::from_fn(|_| v(&mut rng, 500.0));
            let gear = gears()[i % 8];
            let drive = DriveType::ALL[i % 3];

            let rpm = pt.rpm(&speeds, gear);
            assert!(rpm >= T::ZERO && rpm <= engine.max_rpm(), "rpm {rpm}");
            assert!(engine.torque(v(&mut rng, 10_000.0)).is_finite());

            let acc = max_signed_acceleration(&accelerations);
            let factor = acceleration_limit_factor(acc);
            assert!(factor >= T::ZERO && factor <= T::ONE);

            let throttle = v(&mut rng, 1.5);
            let out = pt.output_torque(rpm, throttle, gear, acc);
            assert!(out.is_finite(), "out {out}");
            // Arbitrary rpm as well, not only estimates.
            assert!(
                pt.output_torque(v(&mut rng, 1e4), throttle, gear, v(&mut rng, 100.0))
                    .is_finite()
            );

            lsd.set_enabled(i % 7 != 0);
            lsd.update(drive, &speeds);
            for s in [lsd.front(), lsd.rear(), lsd.central()] {
                assert!(s >= -T::ONE && s <= T::ONE, "slip {s}");
            }
            let geometric = DifferentialRatios::new(
                T::from_f64(rng.uniform(0.0, 1.0)),
                T::from_f64(rng.uniform(0.0, 1.0)),
                T::from_f64(rng.uniform(0.0, 1.0)),
            );
            let ratios = lsd.apply(&geometric);
            let torques = split_torque(out, drive, &ratios);
            assert!(torques.iter().all(|t| t.is_finite()));
            for wheel in ackermann::Wheel::ALL {
                if !drive.drives(wheel) {
                    assert_eq!(torques[wheel], T::ZERO);
                }
            }
            // The shares add up to 1 exactly in real arithmetic; each of the four products can
            // be off by a few ulps of the largest one (shares are at most 2 in magnitude); the
            // absolute floor covers subnormal outputs.
            let sum = torques.iter().fold(T::ZERO, |a, &t| a + t);
            let tolerance = T::from_f64(16.0) * T::EPSILON * out.abs()
                + T::from_f64(f64::from(f32::MIN_POSITIVE));
            assert!((sum - out).abs() <= tolerance, "{drive}: {sum} vs {out}");

            let cap = brake.torque(v(&mut rng, 2.0));
            assert!(cap >= T::ZERO && cap <= brake.coefficient());
            let held = brake.friction_torque(v(&mut rng, 2.0), v(&mut rng, 5000.0));
            assert!(held.is_finite() && held.abs() <= brake.coefficient());

            if let Some(next) = auto.update(v(&mut rng, 0.1), rpm, gear, pt.gearbox()) {
                assert!(next.is_forward() && pt.gearbox().has(next));
                assert_eq!((next.number() - gear.number()).abs(), 1);
            }
            if let Some(virtual_gear) = pt.speed_mode_virtual_gear(&speeds) {
                assert!(virtual_gear.rpm.is_finite() && virtual_gear.rpm >= T::ZERO);
                assert!(pt.gearbox().has(virtual_gear.gear) && !virtual_gear.gear.is_neutral());
            }
        }
    }
}

#[test]
fn random_and_extreme_inputs_f64() {
    run::<f64>(0x9e37_79b9_7f4a_7c15);
}

#[test]
fn random_and_extreme_inputs_f32() {
    run::<f32>(0xdead_beef_cafe_f00d);
}

#[test]
fn limited_slip_saturates_under_sustained_imbalance() {
    // A right wheel spinning 3× faster adds 2·3/4 − 1 = 0.5 per step: saturated after 2 steps,
    // and stays there.
    let mut lsd = LimitedSlip::<f32>::new();
    for _ in 0..1000 {
        lsd.update(
            DriveType::FourByFour,
            &PerWheel::new(30.0, 10.0, 30.0, 10.0),
        );
    }
    assert_eq!((lsd.front(), lsd.rear(), lsd.central()), (1.0, 1.0, 0.0));
}

#[test]
fn every_gear_table_from_two_to_sixteen_ratios_is_usable() {
    for n in 2..=16 {
        let table: Vec<f64> = (0..n)
            .map(|i| if i == 0 { -10.0 } else { 20.0 / i as f64 })
            .collect();
        let gb = Gearbox::new(&table).unwrap();
        assert_eq!(gb.gear_count(), n);
        assert_eq!(gb.highest_gear().number(), n as i32 - 1);
        for requested in -3..=20 {
            let s = gb.select(requested);
            assert!(gb.has(s.gear));
            assert_eq!(s.warning.is_some(), !(-1..n as i32).contains(&requested));
        }
    }
}

#[test]
fn saturation_speed_of_a_near_zero_ratio_is_finite() {
    // f32: 4500 rpm · 2π/60 / 1e-38 = 4.7e40 rad/s overflows f32 (max 3.4e38): saturated.
    let pt = Powertrain::new(
        Engine::<f32>::default(),
        Gearbox::new(&[-1e-38, 1e-38]).unwrap(),
    );
    assert_eq!(pt.saturation_wheel_speed(Gear::FIRST), Some(f32::MAX));
    assert_eq!(pt.saturation_wheel_speed(Gear::REVERSE), Some(f32::MAX));
    // f64, smallest subnormal ratio: saturated as well.
    let pt = Powertrain::new(
        Engine::<f64>::default(),
        Gearbox::new(&[-5e-324, 5e-324]).unwrap(),
    );
    assert_eq!(pt.saturation_wheel_speed(Gear::FIRST), Some(f64::MAX));
}

#[test]
fn auto_shift_defaults_for_an_unrepresentably_narrow_engine_are_reported() {
    // 1000 and the next f32 above 1000.0001: 1000 + 0.85·6.1e-5 rounds to engineMaxRPM itself.
    let engine = Engine::new(EngineParams {
        min_rpm: 1000.0_f32,
        max_rpm: 1000.0001,
        ..EngineParams::default()
    })
    .unwrap();
    let err = AutoShift::new(AutoShiftParams::for_engine(&engine), &engine).unwrap_err();
    assert_eq!(err.field(), Some(powertrain::Field::UpshiftRpm));
}
