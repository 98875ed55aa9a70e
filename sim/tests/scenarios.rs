//! The scenarios on the default car and on DifferentialWheels robots: metrics that follow from
//! the geometry and kinematics, and the consistency of the measurements with each other.

// Helpers outside #[test] functions unwrap too: a failure is a test failure.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use sim::scenario::{self, RunReport, Scenario, ScenarioError, Value};
use sim::world_file::{self, parse_str};

fn run(world: &world_file::WorldDescription, scenario: Scenario) -> RunReport {
    scenario::run(world, scenario, &mut |_| {}).unwrap()
}

fn number(r: &RunReport, s: Scenario, key: &str) -> f64 {
    match r.result(s.name()).and_then(|x| x.metric(key)) {
        Some(Value::Number(v)) => v,
        other => panic!("{s} {key}: {other:?}"),
    }
}

#[test]
fn world_duration_caps_a_scenario() {
    let w = parse_str("w.toml", "duration = 0.5\n[vehicle]\nmodel = \"BmwX5\"\n").unwrap();
    let r = run(&w, Scenario::AccelSpeed);
    assert_eq!(r.sim_seconds, 0.5);
    assert_eq!(r.results[0].metric("time_0_100_s"), Some(Value::Missing));
    let json = sim::report::to_json(&r, &[], &[]);
    assert!(json.contains("\"time_0_100_s\":null"), "{json}");
}

#[test]
fn scenarios_refuse_the_other_vehicle() {
    let robot = parse_str("r.toml", "[differential_wheels]\n").unwrap();
    assert_eq!(
        scenario::run(&robot, Scenario::Circle, &mut |_| {}).unwrap_err(),
        ScenarioError::WrongVehicle {
            scenario: Scenario::Circle,
            vehicle: "DifferentialWheels".into()
        }
    );
    let car = world_file::default_world();
    assert!(scenario::run(&car, Scenario::Square, &mut |_| {}).is_err());
    assert_eq!(Scenario::default_for(&robot), Scenario::Square);
    assert_eq!(Scenario::default_for(&car), Scenario::TestTrack);
}

#[test]
fn noiseless_robot_closes_its_square() {
    // Side 10 × 0.1 m at 5 rad/s × 0.05 m = 0.25 m/s; turns of π/2 in place.
    let w = parse_str(
        "r.toml",
        "basicTimeStep = 8\n[differential_wheels]\nslipNoise = 0\naxleLength = 0.1\nwheelRadius = 0.05\n",
    )
    .unwrap();
    let mut fractions = Vec::new();
    let r = scenario::run(&w, Scenario::Square, &mut |p| fractions.push(p.fraction)).unwrap();
    assert_eq!(number(&r, Scenario::Square, "side_m"), 1.0);
    // Each move lasts a whole number of 8 ms steps, so the square closes to within a few
    // steps of travel (0.25 m/s × 8 ms = 2 mm per step).
    let closure = number(&r, Scenario::Square, "closure_error_m");
    assert!(closure < 0.02, "{closure}");
    let heading = number(&r, Scenario::Square, "final_heading_rad");
    assert!(heading.abs() < 0.05, "{heading}");
    assert!((number(&r, Scenario::Square, "distance_m") - 4.0).abs() < 0.05);
    // Progress is reported, increasing, within [0, 1].
    assert!(!fractions.is_empty());
    assert!(fractions.windows(2).all(|w| w[0] <= w[1]));
    assert!(fractions.iter().all(|f| (0.0..=1.0).contains(f)));
}

#[test]
fn physics_e_puck_closes_its_square() {
    // The shipped e-puck world with rigid bodies: 0.52 m sides at 3.14 rad/s × 0.0205 m =
    // 6.4 cm/s, quarter turns on the spot. Open loop, so the only errors are the step
    // quantisation (which kinematics mode closes to 7 mm) and the wheels' slip where a command
    // steps the wheel speed (Webots' physics mode has no acceleration ramp): the converged
    // solver puts that at about 7 mm and 0.02 rad. 2 cm and 0.05 rad leave about 3× margin
    // and still catch the spin-resisting cylinder contact and the unconverged motor that made
    // this robot end 0.30 m away, turned −0.79 rad.
    let text = include_str!("../worlds/e-puck.toml").replace("physics = false", "physics = true");
    let w = parse_str("e-puck.toml", &text).unwrap();
    assert!(matches!(
        w.robot().unwrap().mode,
        sim::RobotMode::Physics(_)
    ));
    let r = run(&w, Scenario::Square);
    let closure = number(&r, Scenario::Square, "closure_error_m");
    assert!(closure < 0.02, "{closure}");
    let heading = number(&r, Scenario::Square, "final_heading_rad");
    assert!(heading.abs() < 0.05, "{heading}");
    // It did drive the square: four sides of 10 axle lengths.
    let path = number(&r, Scenario::Square, "distance_m");
    assert!((path - 4.0 * 0.52).abs() < 0.05, "{path}");
}

#[test]
fn noisy_robot_drifts_reproducibly() {
    // The same seed gives the same noise, so the same final pose; another seed another pose.
    let world = |seed: u64| {
        parse_str(
            "r.toml",
            &format!("[differential_wheels]\nslipNoise = 0.2\nwheelRadius = 0.05\nseed = {seed}\n"),
        )
        .unwrap()
    };
    let pose = |seed| {
        let r = run(&world(seed), Scenario::Spin);
        (
            number(&r, Scenario::Spin, "final_x_m"),
            number(&r, Scenario::Spin, "final_heading_rad"),
        )
    };
    assert_eq!(pose(7), pose(7));
    assert_ne!(pose(7), pose(8));
}
