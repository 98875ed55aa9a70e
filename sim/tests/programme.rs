//! Driving programmes (`[[vehicle.programme]]`), several cars and a robot beside cars: the
//! `programme` scenario against the same calls through the Rust API, collisions, and the
//! errors of a programme.

// Helpers outside #[test] functions unwrap too: a failure is a test failure.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use sim::placement::car_placement;
use sim::scenario::{self, RunReport, Scenario, Value};
use sim::telemetry::{Sample, VehicleKind};
use sim::world_file::{WorldFileErrorKind, parse_str};
use sim::{Simulation, World};

fn run(text: &str) -> RunReport {
    let w = parse_str("w.toml", text).unwrap();
    assert_eq!(Scenario::default_for(&w), Scenario::Programme);
    scenario::run(&w, Scenario::Programme, &mut |_| {}).unwrap()
}

fn number(r: &RunReport, vehicle: Option<&str>, key: &str) -> f64 {
    let x = &r.results[0];
    let v = match vehicle {
        Some(v) => x.metric_of(v, key),
        None => x.metric(key),
    };
    match v {
        Some(Value::Number(n)) => n,
        other => panic!("{vehicle:?} {key}: {other:?}"),
    }
}

const BRAKE_AND_STEER: &str = r#"
duration = 6.0
[vehicle]
model = "BmwX5"
[[vehicle.programme]]
at = 0.0
cruising_speed = 40
[[vehicle.programme]]
at = 3.0
throttle = 0
brake_intensity = 1
steering_angle = 0.1
"#;

#[test]
fn a_programme_drives_as_the_same_driver_calls() {
    let r = run(BRAKE_AND_STEER);
    let t = &r.results[0].telemetry;
    assert_eq!(t.len(), 1);
    assert_eq!(
        (t[0].vehicle.as_str(), t[0].kind),
        ("BmwX5", VehicleKind::Car)
    );

    // The same world driven by hand through the public API.
    let w = parse_str("w.toml", BRAKE_AND_STEER).unwrap();
    let car = &w.cars[0];
    let mut sim = Simulation::new(World::new(w.config.clone()).unwrap());
    let (id, _) = sim
        .add_car(
            sim::CarBuilder::new(car.params.clone())
                .tyre(car.tyre.clone())
                .mounting(car.mounting)
                .placement(car_placement(&car.params)),
        )
        .unwrap();
    let mut samples = vec![Sample::of_car(&sim, id).unwrap()];
    for step in 0..600 {
        let d = sim.driver_mut(id).unwrap();
        if step == 0 {
            d.set_cruising_speed(40.0);
        }
        if step == 300 {
            d.set_throttle(0.0);
            d.set_brake_intensity(1.0);
            d.set_steering_angle(0.1);
        }
        sim.step().unwrap();
        samples.push(Sample::of_car(&sim, id).unwrap());
    }
    // Bit for bit: the programme is nothing but those calls at those steps.
    assert_eq!(t[0].samples.len(), samples.len());
    assert_eq!(t[0].samples, samples);
    // It did brake and steer: it stopped turned to the right (yaw decreases).
    let last = samples.last().unwrap();
    assert!(last.speed_kmh.abs() < 0.5, "{last:?}");
    assert!(last.yaw < -0.01, "{last:?}");
    // The metrics follow from that telemetry.
    let distance = number(&r, Some("BmwX5"), "distance_m");
    assert!((number(&r, Some("BmwX5"), "final_x_m") - last.x).abs() < 1e-12);
    assert!(distance > last.x && distance < last.x + 1.0, "{distance}");
    // Braking from about 40 km/h decelerates by several m/s².
    assert!(number(&r, Some("BmwX5"), "max_decel_mps2") > 4.0);
    assert_eq!(r.results[0].metric("touched"), None);
}

/// Two cars `gap` m apart along x (the second facing back towards the first) and `lateral`
/// m apart across, each cruising at 30 km/h, on the mountings given.
fn head_on(mountings: [&str; 2], lateral: f64) -> RunReport {
    run(&format!(
        r#"
duration = 4.0
[[vehicle]]
model = "BmwX5"
name = "north"
mounting = "{}"
[[vehicle.programme]]
at = 0
cruising_speed = 30
[[vehicle]]
model = "BmwX5"
name = "south"
mounting = "{}"
translation = [30, {lateral}, 0]
rotation = [0, 0, 1, 3.14159265]
[[vehicle.programme]]
at = 0
cruising_speed = 30
"#,
        mountings[0], mountings[1]
    ))
}

#[test]
fn two_cars_on_a_collision_course_touch() {
    for mountings in [["cast", "cast"], ["joints", "cast"], ["joints", "joints"]] {
        let r = head_on(mountings, 0.0);
        let x = &r.results[0];
        assert_eq!(
            x.metric("touched"),
            Some(Value::Bool(true)),
            "{mountings:?}"
        );
        // Touching is a gap of zero up to rapier's contact margin (a few mm).
        let gap = number(&r, None, "min_gap_m");
        assert!(gap < 0.01, "{mountings:?}: {gap}");
        // 30 m apart, rear axles to rear axles, each about 1 m behind its nose and 4 m from
        // it: some 20 m to close at up to 2 × 8.3 m/s after a 2 s ramp: between 1.5 and 4 s.
        let t = number(&r, None, "first_touch_s");
        assert!((1.5..4.0).contains(&t), "{mountings:?}: {t}");
        let names: Vec<&str> = x.telemetry.iter().map(|t| t.vehicle.as_str()).collect();
        assert_eq!(names, ["north", "south"]);
    }
    // Side by side in lanes 6 m apart, they pass without touching: the smallest gap is the
    // lane spacing less one car width (about 2 m).
    let r = head_on(["cast", "cast"], 6.0);
    assert_eq!(r.results[0].metric("touched"), Some(Value::Bool(false)));
    assert!(r.results[0].metric("first_touch_s") == Some(Value::Missing));
    let gap = number(&r, None, "min_gap_m");
    assert!((3.0..5.0).contains(&gap), "{gap}");
}

#[test]
fn a_robot_and_a_car_share_a_world() {
    let r = run(r#"
duration = 4.0
[vehicle]
model = "ToyotaPrius"
[[vehicle.programme]]
at = 0
cruising_speed = 20
[differential_wheels]
wheelRadius = 0.05
slipNoise = 0
translation = [0, 5, 0]
[[differential_wheels.programme]]
at = 0
speed = [5, 5]
[[differential_wheels.programme]]
at = 2
speed = [0, 0]
"#);
    let x = &r.results[0];
    let kinds: Vec<(&str, VehicleKind)> = x
        .telemetry
        .iter()
        .map(|t| (t.vehicle.as_str(), t.kind))
        .collect();
    assert_eq!(
        kinds,
        [
            ("ToyotaPrius", VehicleKind::Car),
            ("DifferentialWheels", VehicleKind::Robot)
        ]
    );
    // The robot: 5 rad/s × 0.05 m = 0.25 m/s for 2 s, ramping up and down at
    // maxAcceleration 10 rad/s² (0.5 s each way, which cancel): 0.5 m along +x.
    let d = number(&r, Some("DifferentialWheels"), "distance_m");
    assert!((d - 0.5).abs() < 0.01, "{d}");
    assert!((number(&r, Some("DifferentialWheels"), "final_y_m") - 5.0).abs() < 1e-9);
    // The car drove on.
    assert!(number(&r, Some("ToyotaPrius"), "distance_m") > 5.0);
    // One car: no gap metrics. The CSV names both.
    assert_eq!(x.metric("min_gap_m"), None);
    let csv = sim::telemetry::to_csv(&x.telemetry);
    assert!(csv.lines().any(|l| l.starts_with("programme,ToyotaPrius,")));
    assert!(
        csv.lines()
            .any(|l| l.starts_with("programme,DifferentialWheels,"))
    );
}

// The plots are the application's (`app` feature).
#[cfg(feature = "app")]
#[test]
fn several_cars_are_named_and_drawn() {
    let w = parse_str(
        "w.toml",
        "[[vehicle]]\nmodel = \"BmwX5\"\n[[vehicle]]\nmodel = \"BmwX5\"\ntranslation = [0, 10, 0]\n\
         [[vehicle]]\nmodel = \"Bus\"\ntranslation = [0, 20, 0]\n[[box]]\ntranslation = [50, 0, 1]\n\
         size = [2, 2, 2]\n",
    )
    .unwrap();
    assert_eq!(w.vehicle_names(), ["BmwX5-1", "BmwX5-2", "Bus"]);
    // Several vehicles without programmes: `programme` runs them (they stand still).
    assert_eq!(Scenario::default_for(&w), Scenario::Programme);
    assert!(Scenario::Brake.check(&w).is_err());
    let mut w = w;
    w.duration = Some(0.1);
    let r = scenario::run(&w, Scenario::Programme, &mut |_| {}).unwrap();
    let figures = sim::report::figures(&r);
    let (_, trajectory) = figures
        .iter()
        .find(|(n, _)| *n == "trajectory.svg")
        .unwrap();
    let names: Vec<&str> = trajectory.panels[0]
        .series
        .iter()
        .map(|s| s.name.as_str())
        .collect();
    assert_eq!(names, ["boxes", "BmwX5-1", "BmwX5-2", "Bus"]);
}

fn error(text: &str) -> sim::world_file::WorldFileError {
    parse_str("w.toml", text).unwrap_err()
}

#[test]
fn programme_errors_name_file_line_and_key() {
    let head = "[vehicle]\nmodel = \"BmwX5\"\n[[vehicle.programme]]\nat = 1\n";
    let e = error(&format!("{head}throtle = 1\n"));
    assert_eq!(
        e.to_string(),
        "w.toml:5:1: unknown key 'vehicle.programme[1].throtle'; did you mean 'throttle'?"
    );
    let e = error(&format!("{head}throttle = 2\n"));
    assert_eq!(
        e.to_string(),
        "w.toml:5:1: invalid 'vehicle.programme[1].throttle': 2: must be from 0 to 1"
    );
    let e = error(&format!("{head}gear = 7\n"));
    assert!(
        e.to_string()
            .starts_with("w.toml:5:1: invalid 'vehicle.programme[1].gear': 7"),
        "{e}"
    );
    let e = error(&format!("{head}indicator = \"up\"\n"));
    assert!(
        matches!(e.kind, WorldFileErrorKind::UnknownName { .. }),
        "{e:?}"
    );
    assert_eq!(e.suggestions(), ["off", "right", "left"]);
    let e = error(&format!("{head}steering_angle = \"left\"\n"));
    assert_eq!(
        e.to_string(),
        "w.toml:5:1: 'vehicle.programme[1].steering_angle' takes a number, found a string"
    );
    // A step without time, and one without a command.
    let e = error("[vehicle]\n[[vehicle.programme]]\nthrottle = 1\n");
    assert!(
        e.to_string()
            .contains("missing key 'vehicle.programme[1].at'"),
        "{e}"
    );
    let e = error("[vehicle]\n[[vehicle.programme]]\nat = 2\n");
    assert!(e.to_string().contains("has no command"), "{e}");
    let e = error("[vehicle]\n[[vehicle.programme]]\nat = -1\nthrottle = 1\n");
    assert_eq!(e.key.as_deref(), Some("vehicle.programme[1].at"));
    // In the second of several cars.
    let e = error(
        "[[vehicle]]\nname = \"a\"\n[[vehicle]]\nname = \"b\"\n[[vehicle.programme]]\nat = 0\n\
         brake_intensity = 1.5\n",
    );
    assert_eq!(
        (e.location.map(|l| l.line), e.key.as_deref()),
        (Some(7), Some("vehicle[2].programme[1].brake_intensity"))
    );
    // The robot's wheel speeds stay within maxSpeed / speedUnit (10 here).
    let e = error(
        "[differential_wheels]\n[[differential_wheels.programme]]\nat = 0\nspeed = [11, 0]\n",
    );
    assert_eq!(
        (e.location.map(|l| l.line), e.key.as_deref()),
        (Some(4), Some("differential_wheels.programme[1].speed"))
    );
}

#[test]
fn the_shipped_worlds_load_and_the_overtaking_world_overtakes() {
    for entry in std::fs::read_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/worlds")).unwrap() {
        let path = entry.unwrap().path();
        // The worlds, not the OpenDRIVE files they read.
        if path.extension().is_none_or(|e| e != "toml") {
            continue;
        }
        let w = sim::world_file::load_file(&path);
        assert!(w.is_ok(), "{}: {}", path.display(), w.unwrap_err());
    }
    let w = sim::world_file::load(concat!(env!("CARGO_MANIFEST_DIR"), "/worlds/two-cars.toml"))
        .unwrap();
    assert_eq!(w.vehicle_names(), ["prius", "bmw", "DifferentialWheels"]);
    let r = scenario::run(&w, Scenario::default_for(&w), &mut |_| {}).unwrap();
    // The BmwX5 passes the Prius on the left without touching it, by more than a metre, and
    // ends ahead of it.
    assert_eq!(r.results[0].metric("touched"), Some(Value::Bool(false)));
    assert!(number(&r, None, "min_gap_m") > 1.0);
    assert!(number(&r, Some("bmw"), "final_x_m") > number(&r, Some("prius"), "final_x_m"));
}

#[test]
fn a_refused_lane_command_is_noted_with_its_car_and_time() {
    // Two cars on a one-lane road; the second asks at 0.2 s for lane -2, which only a
    // second road far away has (so the world file accepts it): the note names that car and
    // the time, and the first car's commands give none.
    let r = run(r#"
duration = 0.5
[[road]]
id = "r"
numberOfLanes = 1
numberOfForwardLanes = 1
laneWidths = [3.5]
[[road.segment]]
type = "straight"
length = 200
[[road]]
id = "far"
start = [0, 500]
numberOfLanes = 2
numberOfForwardLanes = 2
laneWidths = [3.5, 3.5]
[[road.segment]]
type = "straight"
length = 50
[[vehicle]]
model = "BmwX5"
name = "first"
translation = [20, -1.75, 0]
[[vehicle.programme]]
at = 0.0
cruising_speed = 10
follow_lane = true
[[vehicle]]
model = "BmwX5"
name = "second"
translation = [60, -1.75, 0]
[[vehicle.programme]]
at = 0.2
follow_lane = true
lane = -2
"#);
    let notes = &r.results[0].notes;
    let lane: Vec<&String> = notes.iter().filter(|n| n.contains("follow_lane")).collect();
    assert_eq!(lane.len(), 1, "{notes:?}");
    assert!(lane[0].starts_with("second at 0.2"), "{notes:?}");
    assert!(!notes.iter().any(|n| n.starts_with("first")), "{notes:?}");
}
