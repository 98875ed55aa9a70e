//! `test-track`, the five car scenarios, on a BmwX5: what each must show, whichever the tyre
//! and the mounting.

use sim::scenario::{self, RunReport, Scenario};
use sim::world_file::{self, parse_str};

/// The scenario run of `world` with its car on the suite's mounting.
fn run(world: &world_file::WorldDescription, scenario: Scenario) -> RunReport {
    let mut world = world.clone();
    for car in &mut world.cars {
        car.mounting = crate::MOUNTING;
    }
    scenario::run(&world, scenario, &mut |_| {}).unwrap()
}

fn number(r: &RunReport, s: Scenario, key: &str) -> f64 {
    match r.result(s.name()).and_then(|x| x.metric(key)) {
        Some(scenario::Value::Number(v)) => v,
        other => panic!("{s} {key}: {other:?}"),
    }
}

fn flag(r: &RunReport, s: Scenario, key: &str) -> bool {
    match r.result(s.name()).and_then(|x| x.metric(key)) {
        Some(scenario::Value::Bool(b)) => b,
        other => panic!("{s} {key}: {other:?}"),
    }
}

#[test]
fn test_track_on_the_default_car() {
    test_track(&world_file::default_world());
}

#[test]
fn test_track_on_webots_contact() {
    let world = parse_str(
        "webots.toml",
        "[vehicle]\nmodel = \"BmwX5\"\ntyre = \"webots\"\n[ground]\nfriction = 1.0\n",
    )
    .unwrap();
    test_track(&world);
}

/// The five car scenarios on a BmwX5 and what each must show, whichever the tyre.
fn test_track(world: &world_file::WorldDescription) {
    let r = run(world, Scenario::TestTrack);
    let names: Vec<&str> = r.results.iter().map(|x| x.name.as_str()).collect();
    assert_eq!(names, Scenario::TEST_TRACK.map(Scenario::name));
    let total: f64 = r.results.iter().map(|x| x.sim_seconds).sum();
    assert!((r.sim_seconds - total).abs() < 1e-9);
    for x in &r.results {
        // The state at time 0, then one sample per 10 ms step.
        let steps = (x.sim_seconds / 0.01).round() as usize;
        assert_eq!(x.telemetry[0].samples.len(), 1 + steps, "{}", x.name);
        assert_eq!(x.telemetry[0].samples[0].time, 0.0);
    }

    // Circle: the rear-axle centre of a car without tyre slip turns about the point on the
    // rear axle line at L/tan δ = 2.995/tan 0.2 = 14.7748 m.
    let expected = number(&r, Scenario::Circle, "turn_radius_expected_m");
    assert!((expected - 2.995 / 0.2f64.tan()).abs() < 1e-12);
    let radius = number(&r, Scenario::Circle, "turn_radius_m");
    assert!(
        (radius - expected).abs() < 0.03 * expected,
        "{radius} vs {expected}"
    );
    assert!(number(&r, Scenario::Circle, "circle_fit_rms_m") < 0.05);

    // Brake: a positive distance, the car at rest, and distance and time consistent with a
    // roughly constant deceleration from v0 (d = v0·t/2).
    let d = number(&r, Scenario::Brake, "stop_distance_m");
    let t = number(&r, Scenario::Brake, "stop_time_s");
    let v0 = number(&r, Scenario::Brake, "initial_speed_kmh") / 3.6;
    assert!(v0 > 25.0, "braking started at {v0} m/s");
    assert!(d > 0.0 && t > 0.0);
    assert!(
        (d - v0 * t / 2.0).abs() < 0.15 * d,
        "d {d} m, v0·t/2 {} m",
        v0 * t / 2.0
    );
    assert!(flag(&r, Scenario::Brake, "at_rest"));
    // The brake-torque bound: 4 × 1800 N·m / 0.374 m over 2120 kg = 9.081 m/s² (below μg).
    let expected = number(&r, Scenario::Brake, "stop_distance_expected_m");
    assert!((expected - v0 * v0 / (2.0 * 4.0 * 1800.0 / 0.374 / 2120.0)).abs() < 1e-6 * expected);

    // Full throttle with the automatic gearbox: it shifts up before 100 km/h.
    assert!(number(&r, Scenario::AccelTorque, "top_gear") >= 2.0);
    assert!(number(&r, Scenario::AccelTorque, "max_rpm") <= 6500.0);

    // Lane change at 60 km/h: the driver model keeps the car between the cones.
    assert!(!flag(&r, Scenario::LaneChange, "left_track"));
    assert_eq!(
        number(&r, Scenario::LaneChange, "max_lane_excursion_m"),
        0.0
    );
    let a = number(&r, Scenario::LaneChange, "max_lateral_accel_mps2");
    assert!((1.0..9.81).contains(&a), "{a}");

    // The plots: one file per kind, each series a scenario (the application's `app` feature).
    #[cfg(feature = "app")]
    {
        let figures = sim::report::figures(&r);
        let files: Vec<&str> = figures.iter().map(|(n, _)| *n).collect();
        assert_eq!(
            files,
            [
                "speed.svg",
                "rpm_gear.svg",
                "steering.svg",
                "lane_change.svg",
                "friction_use.svg",
                "trajectory.svg",
                // The straight runs (accel, brake, lane change) are far longer than the circle
                // is wide: their lateral motion gets its own plot.
                "lateral.svg"
            ]
        );
    }
}
