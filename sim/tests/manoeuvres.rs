//! The standard manoeuvres on the simulated car: the ISO 4138 understeer gradient against the
//! single-track model's, and the step steer and sine with dwell measuring what they should.

// Helpers outside #[test] functions unwrap too: a failure is a test failure.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use sim::VehicleSpec;
use sim::scenario::{self, RunReport, Scenario, Value};
use sim::world_file::parse_str;
use vehicle_model::{TyreModel, Wheel};

fn run(text: &str, scenario: Scenario) -> RunReport {
    let w = parse_str("w.toml", text).unwrap_or_else(|e| panic!("{e}"));
    scenario::run(&w, scenario, &mut |_| {}).unwrap()
}

fn value(r: &RunReport, key: &str) -> Value {
    r.results[0]
        .metric(key)
        .unwrap_or_else(|| panic!("{key} missing"))
}

fn number(r: &RunReport, key: &str) -> f64 {
    match value(r, key) {
        Value::Number(v) => v,
        other => panic!("{key}: {other:?}"),
    }
}

/// A BmwX5 whose tyres stay linear through the test (peak friction 5: at 4 m/s² the tyres use
/// under a tenth of their grip, where the Magic Formula is its slope to 0.5 %).
const LINEAR: &str = "[vehicle]\nmodel = \"BmwX5\"\n[vehicle.tyre.lateral]\npeak_friction = 5\n\
[vehicle.tyre.longitudinal]\npeak_friction = 5\n";

#[test]
fn constant_radius_gives_the_single_track_understeer_gradient() {
    let r = run(LINEAR, Scenario::ConstantRadius);
    let measured = number(&r, "understeer_gradient_rad_per_mps2");
    // The single-track model with the car's own cornering stiffness: K = (m/L)·(b/C_f −
    // a/C_r) = (W_f/C_f − W_r/C_r)/g with W the axle loads, C each axle's two tyres' slope at
    // their static load, from the loads the car rolls on at the first, slowest steady state.
    let w = parse_str("w.toml", LINEAR).unwrap();
    let car = w.car().unwrap();
    let spec = VehicleSpec::from_car_with(&car.params, &car.tyre).unwrap();
    let samples = &r.results[0].telemetry[0].samples;
    let s = samples.iter().find(|s| s.time >= 6.0).unwrap();
    let tyres = s.tyres.unwrap();
    let g = 9.81;
    let axle = |wheels: [Wheel; 2]| {
        let TyreModel::MagicFormula(t) = spec.tyres.of(wheels[0]) else {
            panic!("slip tyre expected")
        };
        let slip = 1e-5;
        let loads = wheels.map(|w| tyres[w].fz);
        let weight: f64 = loads.iter().sum();
        let stiffness: f64 = loads
            .iter()
            .map(|&fz| t.force([0.0, slip], fz, 1.0)[1] / slip)
            .sum();
        weight / stiffness
    };
    let expected = (axle([Wheel::FrontRight, Wheel::FrontLeft])
        - axle([Wheel::RearRight, Wheel::RearLeft]))
        / g;
    // 10 %: the brief's bound; what the single-track model leaves out (the lateral load
    // transfer's loss of axle stiffness, roll, the steering geometry) stays below it at 4 m/s².
    assert!(
        (measured - expected).abs() <= 0.1 * expected.abs(),
        "measured {measured} vs single-track {expected}"
    );
}

#[test]
fn step_steer_settles_on_the_single_track_yaw_gain() {
    // The steady yaw gain of the single-track model, v/(L + K·v²), with the understeer
    // gradient the constant-radius test measures on the same car (checked against the
    // single-track K above).
    let k = number(
        &run(LINEAR, Scenario::ConstantRadius),
        "understeer_gradient_rad_per_mps2",
    );
    let r = run(LINEAR, Scenario::StepSteer);
    let w = parse_str("w.toml", LINEAR).unwrap();
    let wheelbase = w.car().unwrap().params.wheelbase;
    let v = 80.0 / 3.6;
    let expected = v / (wheelbase + k * v * v);
    let gain = number(&r, "steady_yaw_gain_per_s");
    // 3 %: the cruise control holds the speed within a few tenths of a km/h of 80 (its tyres'
    // slip), and the steady lateral acceleration (≈ 4.5 m/s²) is past the constant-radius
    // fit's range (4 m/s²) by a little.
    assert!(
        (gain - expected).abs() <= 0.03 * expected,
        "{gain} vs {expected}"
    );
    // The yaw rate rises after the steering, within the car's yaw time constant (a few
    // tenths of a second) and not before it.
    let t90 = number(&r, "response_time_s");
    assert!(t90 > 0.05 && t90 < 1.0, "{t90}");
    assert!(number(&r, "overshoot_percent") >= 0.0);
}

#[test]
fn sine_with_dwell_on_the_shipped_bmw_x5_spins() {
    // The shipped models are Webots' data, one tyre front and rear and no anti-roll bars: the
    // BmwX5 oversteers at the limit (sim/README.md), and 6.5 times the steer of 0.3 g at
    // 80 km/h spins it. Its yaw rate after the completion of steer stays at (and above) the
    // peak: both ratios over 1, the test failed; the displacement criterion alone is met.
    let r = run("[vehicle]\nmodel = \"BmwX5\"\n", Scenario::SineWithDwell);
    assert!(number(&r, "yaw_ratio_1_0") > 1.0);
    assert!(number(&r, "yaw_ratio_1_75") > 1.0);
    assert!(number(&r, "lateral_displacement_m") >= 1.83);
    assert_eq!(value(&r, "passes_fmvss126"), Value::Bool(false));
}

#[test]
fn split_mu_stops_between_the_two_frictions_and_turns() {
    let r = run("[vehicle]\nmodel = \"BmwX5\"\n", Scenario::SplitMu);
    let v = number(&r, "initial_speed_kmh") / 3.6;
    let d = number(&r, "stop_distance_m");
    let g = 9.81;
    // Longer than a stop at the ground's friction (1) and the tyre's peak (1) on all four
    // wheels, shorter than one at the strip's 0.3 on all four, sliding at 0.75 of the peak.
    assert!(
        d > v * v / (2.0 * g) && d < v * v / (2.0 * 0.3 * 0.75 * g),
        "{d}"
    );
    // Braking harder on the left with the steering held straight yaws the car (without ABS it
    // spins): far more than the run-up's few milliradians.
    assert!(number(&r, "heading_change_rad").abs() > 0.1);
    // The run-up's driver kept the right wheels on the strip (track ≈ 1.6 m).
    assert!(number(&r, "offset_at_braking_m").abs() < 0.7);
}

#[test]
fn iso_3888_enters_at_its_speed_and_judges_the_cones() {
    let r = run("[vehicle]\nmodel = \"BmwX5\"\n", Scenario::Iso3888);
    // The cruise control's 60 km/h less the tyres' slip (a few tenths of a km/h).
    assert!((number(&r, "entry_speed_kmh") - 60.0).abs() < 1.0);
    // Coasting through the track (throttle released at the entry) loses speed.
    assert!(number(&r, "exit_speed_kmh") < number(&r, "entry_speed_kmh"));
    let hits = number(&r, "cones_hit");
    assert_eq!(value(&r, "passed"), Value::Bool(hits == 0.0));
    // The cones drawn: both edges of the three lanes, at most 5 m apart.
    assert_eq!(r.results[0].cones.len(), 2 * (4 + 4 + 4));
}
