//! Golden values of the engine models and the torque pipeline, worked out independently from
//! the formulas of spec §2.3–§2.4 (python3, double precision; the arithmetic is in the
//! comments). Parameters are those of the shipped Webots models (spec §5).

// Helpers outside `#[test]` functions build known-good fixtures.
#![allow(clippy::unwrap_used)]

use ackermann::{DifferentialRatios, DriveType, PerWheel, Real};
use powertrain::{Engine, EngineParams, EngineType, Gear, Gearbox, Powertrain, split_torque};

fn prius<T: Real>() -> Engine<T> {
    Engine::new(EngineParams {
        engine_type: EngineType::PowerSplitHybrid,
        max_torque: T::from_f64(350.0),
        max_power: T::from_f64(33_000.0),
        min_rpm: T::from_f64(1200.0),
        max_rpm: T::from_f64(6500.0),
        function_coefficients: [
            T::from_f64(65.0),
            T::from_f64(0.0225),
            T::from_f64(-0.000_002_5),
        ],
        hybrid_power_split_ratio: T::from_f64(0.2778),
        hybrid_power_split_rpm: T::from_f64(3000.0),
    })
    .unwrap()
}

fn bmw_x5<T: Real>() -> Engine<T> {
    Engine::new(EngineParams {
        min_rpm: T::from_f64(1000.0),
        max_rpm: T::from_f64(6500.0),
        function_coefficients: [
            T::from_f64(34.11),
            T::from_f64(0.136),
            T::from_f64(-0.000_014_61),
        ],
        ..EngineParams::default()
    })
    .unwrap()
}

fn tesla<T: Real>() -> Engine<T> {
    Engine::new(EngineParams {
        engine_type: EngineType::Electric,
        max_torque: T::from_f64(639.0),
        max_power: T::from_f64(147_000.0),
        max_rpm: T::from_f64(25_000.0),
        ..EngineParams::default()
    })
    .unwrap()
}

/// The Car PROTO default engine turned into a parallel hybrid: curve 150 + 0.1·rpm, electric
/// 250 N·m / 50 kW, 1000 to 4500 rpm.
fn parallel<T: Real>() -> Engine<T> {
    Engine::new(EngineParams {
        engine_type: EngineType::ParallelHybrid,
        ..EngineParams::default()
    })
    .unwrap()
}

/// Checks `engine.torque(rpm)` against `(rpm, expected N·m)` pairs with a relative tolerance.
fn check<T: Real>(engine: &Engine<T>, cases: &[(f64, f64)], rel: f64) {
    for &(rpm, expected) in cases {
        let got = engine.torque(T::from_f64(rpm)).to_f64();
        assert!(
            (got - expected).abs() <= rel * expected.abs().max(1.0),
            "{:?} at {rpm} rpm: got {got}, expected {expected}",
            engine.engine_type()
        );
    }
}

// Power-split hybrid (ToyotaPrius): f(x) = 65 + 0.0225·x − 0.0000025·x².
// Combustion part (engine on at rpm ≥ 1200): (1 − 0.2778)·f(3000)
//   = 0.7222·(65 + 67.5 − 22.5) = 0.7222·110 = 79.442 N·m.
// Electric part: min(350, 33 000·60/(2π·rpm)) = min(350, 1 980 000/(2π·rpm)).
const PRIUS: [(f64, f64); 7] = [
    // 0 rpm: engine off, electric = 350 (the quotient is +∞).
    (0.0, 350.0),
    // 1000 rpm: engine off, 1 980 000/6283.185 = 315.126787 N·m.
    (1000.0, 315.126_787_321_952_8),
    // 1200 rpm: 79.442 + 1 980 000/7539.822 = 79.442 + 262.605656 = 342.047656 N·m.
    (1200.0, 342.047_656_101_627_35),
    // 3000 rpm: 79.442 + 105.042262 = 184.484262 N·m.
    (3000.0, 184.484_262_440_650_92),
    // 6000 rpm: 79.442 + 52.521131 = 131.963131 N·m.
    (6000.0, 131.963_131_220_325_47),
    // 6500 rpm = engineMaxRPM: zero (would be 79.442 + 48.481 = 127.923).
    (6500.0, 0.0),
    // Above the limit too.
    (7000.0, 0.0),
];

// Combustion (BmwX5): f(x) = 34.11 + 0.136·x − 0.00001461·x², evaluated at max(x, 1000).
const BMW: [(f64, f64); 7] = [
    // 0 and 500 rpm use f(1000) = 34.11 + 136 − 14.61 = 155.5 N·m.
    (0.0, 155.5),
    (500.0, 155.5),
    (1000.0, 155.5),
    // f(3000) = 34.11 + 408 − 131.49 = 310.62 N·m.
    (3000.0, 310.62),
    // f(6000) = 34.11 + 816 − 525.96 = 324.15 N·m.
    (6000.0, 324.15),
    // f(6499) = 34.11 + 883.864 − 0.00001461·42 237 001 (= 617.082585) = 300.891415 N·m
    // (just below the limit).
    (6499.0, 300.891_415_39),
    // 6500 = engineMaxRPM: zero (f would give 300.8375).
    (6500.0, 0.0),
];

// Electric (TeslaModel3): min(639, 147 000·60/(2π·rpm)); base speed
// 8 820 000/(2π·639) = 2196.79 rpm.
const TESLA: [(f64, f64); 6] = [
    (0.0, 639.0),
    (1000.0, 639.0),
    // 8 820 000/(2π·3000) = 467.915533 N·m.
    (3000.0, 467.915_532_690_172_3),
    // 8 820 000/(2π·10 000) = 140.374660 N·m.
    (10_000.0, 140.374_659_807_051_7),
    // 8 820 000/(2π·24 000) = 58.489442 N·m.
    (24_000.0, 58.489_441_586_271_54),
    // 25 000 = engineMaxRPM: zero.
    (25_000.0, 0.0),
];

// Parallel hybrid: (150 + 0.1·rpm if rpm ≥ 1000) + min(250, 50 000·60/(2π·rpm));
// base speed 3 000 000/(2π·250) = 1909.86 rpm.
const PARALLEL: [(f64, f64); 6] = [
    // Engine off: electric only.
    (0.0, 250.0),
    (999.0, 250.0),
    // Engine on: 150 + 100 + 250 = 500 N·m.
    (1000.0, 500.0),
    // 150 + 200 + 3 000 000/(2π·2000) = 350 + 238.732415 = 588.732415 N·m.
    (2000.0, 588.732_414_637_843),
    // 150 + 400 + 119.366207 = 669.366207 N·m.
    (4000.0, 669.366_207_318_921_5),
    // 4500 = engineMaxRPM: zero.
    (4500.0, 0.0),
];

#[test]
fn prius_power_split_hybrid() {
    check(&prius::<f64>(), &PRIUS, 1e-12);
    check(&prius::<f32>(), &PRIUS, 1e-6);
}

#[test]
fn bmw_x5_combustion() {
    check(&bmw_x5::<f64>(), &BMW, 1e-12);
    check(&bmw_x5::<f32>(), &BMW, 1e-5);
}

#[test]
fn tesla_electric() {
    check(&tesla::<f64>(), &TESLA, 1e-12);
    check(&tesla::<f32>(), &TESLA, 1e-6);
}

#[test]
fn parallel_hybrid() {
    check(&parallel::<f64>(), &PARALLEL, 1e-12);
    check(&parallel::<f32>(), &PARALLEL, 1e-6);
}

#[test]
fn electric_torque_is_finite_and_maximal_at_standstill() {
    for e in [tesla::<f64>(), parallel(), prius()] {
        let t0 = e.torque(0.0);
        assert!(t0.is_finite());
        assert!(e.torque(1e-300) == t0 && e.torque(-0.0) == t0);
    }
}

#[test]
fn saturation_speed_per_gear() {
    // ω = 6500·2π/60/|ratio| rad/s for the BmwX5 table [−12.5 12.5 8 5.35 4.3 4].
    let bmw = Powertrain::new(
        bmw_x5::<f64>(),
        Gearbox::new(&[-12.5, 12.5, 8.0, 5.35, 4.3, 4.0]).unwrap(),
    );
    let expected = [
        (Gear::REVERSE, 54.454_272_662_223_08),
        (Gear::FIRST, 54.454_272_662_223_08),
        (Gear::forward(2).unwrap(), 85.084_801_034_723_57),
        (Gear::forward(3).unwrap(), 127.229_609_023_885_71),
        (Gear::forward(4).unwrap(), 158.297_304_250_648_5),
        (Gear::forward(5).unwrap(), 170.169_602_069_447_14),
    ];
    for (gear, w) in expected {
        let got = bmw.saturation_wheel_speed(gear).unwrap();
        assert!((got - w).abs() < 1e-9, "{gear}: {got} vs {w}");
        // Just below it the engine still pulls; at it the rpm estimate saturates and the
        // output is cut.
        let below = bmw.rpm(&PerWheel::splat(0.999 * w), gear);
        assert!(below < 6500.0);
        assert!(bmw.output_torque(below, 1.0, gear, 0.0).abs() > 100.0);
        let at = bmw.rpm(&PerWheel::splat(1.001 * w), gear);
        assert_eq!(at, 6500.0);
        assert_eq!(bmw.output_torque(at, 1.0, gear, 0.0), 0.0);
    }
    assert_eq!(bmw.saturation_wheel_speed(Gear::NEUTRAL), None);

    // Truck (15 ratios, engineMaxRPM 2250): first gear 2250·2π/60/16 = 14.726216 rad/s,
    // top gear (ratio 1) 235.619449 rad/s.
    let truck = Powertrain::new(
        Engine::new(EngineParams {
            min_rpm: 700.0,
            max_rpm: 2250.0,
            function_coefficients: [-600.0, 5.45, -0.0023],
            ..EngineParams::default()
        })
        .unwrap(),
        Gearbox::new(&[
            -14.77, 16.0, 13.0, 11.0, 9.0, 7.0, 6.0, 4.5, 3.7, 3.0, 2.4, 1.9, 1.5, 1.2, 1.0,
        ])
        .unwrap(),
    );
    let first = truck.saturation_wheel_speed(Gear::FIRST).unwrap();
    assert!((first - 14.726_215_563_702_157).abs() < 1e-9);
    let top = truck
        .saturation_wheel_speed(truck.gearbox().highest_gear())
        .unwrap();
    assert!((top - 235.619_449_019_234_5).abs() < 1e-9);
}

#[test]
fn reverse_gives_negative_wheel_torque() {
    let tables: [&[f64]; 4] = [
        &[-12.0, 10.0, 6.5, 4.5, 3.5, 2.75],
        &[-6.0, 6.0],
        &[-2.94, 4.58, 2.96, 1.91, 1.45, 1.00, 0.75],
        &[-6.3, 9.0],
    ];
    for engine in [bmw_x5::<f64>(), tesla(), parallel(), prius()] {
        for table in tables {
            let pt = Powertrain::new(engine, Gearbox::new(table).unwrap());
            for rpm in [0.0, 500.0, 1500.0, 3000.0] {
                let rpm: f64 = rpm.min(pt.engine().max_rpm() - 1.0);
                for throttle in [0.1, 0.5, 1.0] {
                    let rev = pt.output_torque(rpm, throttle, Gear::REVERSE, 0.0);
                    let fwd = pt.output_torque(rpm, throttle, Gear::FIRST, 0.0);
                    assert!(rev < 0.0 && fwd > 0.0, "{table:?} {rpm} {throttle}");
                    // Same engine torque, scaled by the reverse ratio.
                    let t = pt.engine().torque(rpm) * throttle;
                    assert!((rev - t * table[0]).abs() < 1e-9 * t.abs().max(1.0));
                }
            }
        }
    }
}

#[test]
fn prius_wheel_torques_in_a_right_turn() {
    // Front-wheel drive, 1200 rpm, full throttle, ratio 6: 342.047656·6 = 2052.285937 N·m,
    // split 0.45 / 0.55 between FR and FL.
    let pt = Powertrain::new(prius::<f64>(), Gearbox::new(&[-6.0, 6.0]).unwrap());
    let out = pt.output_torque(1200.0, 1.0, Gear::FIRST, 0.0);
    assert!((out - 2_052.285_936_609_764).abs() < 1e-9);
    let t = split_torque(
        out,
        DriveType::Traction,
        &DifferentialRatios::new(0.45, 0.5, 0.5),
    );
    assert!((t.as_array()[0] - 923.528_671_474_393_8).abs() < 1e-9);
    assert!((t.as_array()[1] - 1_128.757_265_135_370_2).abs() < 1e-9);
}
