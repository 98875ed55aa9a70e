//! The programme's `cycle` command: a car handed to the built-in drive-cycle driver from a
//! `[[vehicle.programme]]` step drives exactly as the drive-cycle scenario does, every car of
//! a world may follow its own trace (a shipped cycle or a user's file), the pedals stay at
//! the trace's end, and a bad step or file is an error with its file, line and key.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::PathBuf;

use sim::scenario::{self, RunReport, Scenario, ScenarioResult, Value};
use sim::world_file::{WorldFileError, parse_str};

/// A BmwX5 with its air, road-load losses and energy accounting at 20 ms (the drive-cycle
/// tests' world, `sim/tests/drive_cycles.rs`), then `rest`.
fn world(rest: &str) -> String {
    format!(
        "basicTimeStep = 20\n[vehicle]\nmodel = \"BmwX5\"\naero = true\n\
         losses = \"road-load\"\nenergy = true\n{rest}"
    )
}

fn run(text: &str, scenario: Scenario) -> RunReport {
    let w = parse_str("w.toml", text).unwrap_or_else(|e| panic!("{e}"));
    scenario::run(&w, scenario, &mut |_| {}).unwrap()
}

/// The metric `key` of vehicle `vehicle` (`None`: the run's own).
fn number(r: &ScenarioResult, vehicle: Option<&str>, key: &str) -> f64 {
    match r
        .metrics
        .iter()
        .find(|m| m.key == key && m.vehicle.as_deref() == vehicle)
        .map(|m| m.value)
    {
        Some(Value::Number(v)) => v,
        other => panic!("{vehicle:?} {key}: {other:?}"),
    }
}

/// The cycle's metrics of a combustion car.
const CYCLE_KEYS: [&str; 8] = [
    "distance_km",
    "trace_distance_km",
    "time_outside_band_s",
    "longest_excursion_s",
    "max_speed_error_kmh",
    "fuel_l_per_100km",
    "wheel_wh",
    "wheel_wh_per_km",
];

#[test]
fn a_programmed_hwfet_gives_the_scenarios_numbers() {
    let scenario = run(&world(""), Scenario::Hwfet);
    let programme = run(
        &world("[[vehicle.programme]]\nat = 0\ncycle = \"hwfet\"\n"),
        Scenario::Programme,
    );
    let (s, p) = (&scenario.results[0], &programme.results[0]);
    // The same driver on the same car from the same state: the same numbers, to the bit
    // (the programme runs 10 s past the trace's end, which its metrics leave out).
    for key in CYCLE_KEYS {
        assert_eq!(number(s, None, key), number(p, Some("BmwX5"), key), "{key}");
    }
    // And the scenario's figure holds: inside the EPA band (`sim/tests/drive_cycles.rs`).
    assert!(number(p, Some("BmwX5"), "longest_excursion_s") < 2.0);
    // The trace's 765 s and the programme's tail of 10 s.
    assert!((p.sim_seconds - 775.0).abs() < 1e-6, "{}", p.sim_seconds);
    assert!(
        p.notes.iter().all(|n| !n.contains("ended")),
        "{:?}",
        p.notes
    );
}

/// A file in the test's temporary directory holding `text`.
fn trace_file(name: &str, text: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("sim-programme-cycle-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join(name);
    std::fs::write(&path, text).unwrap();
    path
}

#[test]
fn every_car_of_a_world_follows_its_own_trace_and_then_holds_its_pedals() {
    // A user's trace in km/h: 5 s at rest, 0 to 36 km/h in 10 s (1 m/s²), 10 s at 36 km/h,
    // back to rest in 10 s, 5 s at rest.
    let mut table = String::from("# time (s), speed (km/h)\n");
    for t in 0..=40 {
        let v = match t {
            0..=5 => 0.0,
            6..=15 => 3.6 * f64::from(t - 5),
            16..=25 => 36.0,
            26..=35 => 36.0 - 3.6 * f64::from(t - 25),
            _ => 0.0,
        };
        table.push_str(&format!("{t} {v}\n"));
    }
    let path = trace_file("ramp.txt", &table);
    let text = format!(
        "basicTimeStep = 20\nduration = 60\n\
         [[vehicle]]\nmodel = \"TeslaModel3\"\nname = \"tesla\"\nlosses = \"road-load\"\n\
         energy = true\n\
         [[vehicle.programme]]\nat = 2\ncycle_file = \"{}\"\ncycle_unit = \"km/h\"\n\
         [[vehicle]]\nmodel = \"BmwX5\"\nname = \"bmw\"\nlosses = \"road-load\"\n\
         translation = [0, 10, 0.5]\n\
         [[vehicle.programme]]\nat = 0\ncycle_file = \"{}\"\ncycle_unit = \"km/h\"\n\
         [[vehicle.programme]]\nat = 45\nbrake_intensity = 1\n",
        path.display(),
        path.display()
    );
    let r = run(&text, Scenario::Programme);
    let p = &r.results[0];
    // The trace's distance: 50 m up, 100 m at 10 m/s, 50 m down.
    for car in ["tesla", "bmw"] {
        assert!((number(p, Some(car), "trace_distance_km") - 0.2).abs() < 1e-12);
        // Inside the EPA band all the way (the driver's own test: `cycle_driver.rs`).
        assert_eq!(number(p, Some(car), "time_outside_band_s"), 0.0, "{car}");
        // 0.5 %: the distance driven is the trace's (as `sim/tests/drive_cycles.rs`).
        let d = number(p, Some(car), "distance_km");
        assert!((d - 0.2).abs() < 0.001, "{car}: {d} km");
    }
    // The BmwX5 had no energy accounting: the cycle turned it on, and said so.
    assert!(
        p.notes
            .iter()
            .any(|n| n.starts_with("bmw: energy accounting turned on")),
        "{:?}",
        p.notes
    );
    // After the trace's end (40 s for the BmwX5, 42 s for the TeslaModel3) the holding brake
    // stays, and the later `brake_intensity = 1` is the programme's own.
    let bmw = p.telemetry.iter().find(|t| t.vehicle == "bmw").unwrap();
    let at = |t: f64| {
        bmw.samples
            .iter()
            .find(|s| (s.time - t).abs() < 1e-6)
            .unwrap()
    };
    assert_eq!(at(44.0).brake, at(41.0).brake);
    assert!(at(44.0).brake.unwrap() > 0.0 && at(44.0).throttle == Some(0.0));
    assert_eq!(at(50.0).brake, Some(1.0));
}

fn err(text: &str) -> WorldFileError {
    parse_str("w.toml", text).expect_err("the world should be rejected")
}

#[test]
fn bad_cycle_steps_name_their_line_and_key() {
    let step = |body: &str| world(&format!("[[vehicle.programme]]\nat = 0\n{body}\n"));
    // The programme step is lines 7 to 9; its command on line 9.
    let e = err(&step("cycle = \"hwfte\""));
    assert_eq!(e.key.as_deref(), Some("vehicle.programme[1].cycle"));
    assert_eq!(e.location.unwrap().line, 9);
    assert_eq!(e.suggestions(), ["hwfet"]);
    let e = err(&step("cycle_file = \"x.txt\""));
    assert!(e.to_string().contains("cycle_unit = \"km/h\""), "{e}");
    let e = err(&step("cycle = \"udds\"\ncycle_unit = \"mph\""));
    assert_eq!(e.key.as_deref(), Some("vehicle.programme[1].cycle_unit"));
    let e = err(&step("cycle_unit = \"mph\""));
    assert!(e.to_string().contains("without a cycle_file"), "{e}");
    let e = err(&step("cycle = \"udds\"\ncycle_file = \"x.txt\""));
    assert!(e.to_string().contains("not both"), "{e}");
    let e = err(&step("cycle_file = \"x.txt\"\ncycle_unit = \"kmh\""));
    assert_eq!(e.suggestions()[0], "km/h");
    // A second cycle, and a pedal command while the HWFET (765 s) drives.
    let two = world(
        "[[vehicle.programme]]\nat = 0\ncycle = \"hwfet\"\n\
         [[vehicle.programme]]\nat = 800\ncycle = \"udds\"\n",
    );
    let e = err(&two);
    assert_eq!(e.key.as_deref(), Some("vehicle.programme[2].cycle"));
    assert_eq!(e.location.unwrap().line, 12);
    let pedal = world(
        "[[vehicle.programme]]\nat = 0\ncycle = \"hwfet\"\n\
         [[vehicle.programme]]\nat = 100\nsteering_angle = 0.01\nthrottle = 1\n",
    );
    let e = err(&pedal);
    assert_eq!(e.key.as_deref(), Some("vehicle.programme[2].throttle"));
    assert_eq!(e.location.unwrap().line, 13);
    assert!(e.to_string().contains("give it after 765 s"), "{e}");
    // At the trace's end the pedals are the programme's again.
    let after = world(
        "[[vehicle.programme]]\nat = 0\ncycle = \"hwfet\"\n\
         [[vehicle.programme]]\nat = 765\nthrottle = 1\n",
    );
    assert!(parse_str("w.toml", &after).is_ok());
}

#[test]
fn a_bad_trace_file_is_located_in_the_world_and_in_the_file() {
    let step = |path: &PathBuf, unit: &str| {
        world(&format!(
            "[[vehicle.programme]]\nat = 0\ncycle_file = \"{}\"\ncycle_unit = \"{unit}\"\n",
            path.display()
        ))
    };
    // A missing second: the file's line 4, at the world's `cycle_file`.
    let gap = trace_file("gap.txt", "# t v\n0 0\n1 2\n3 4\n");
    let e = err(&step(&gap, "m/s"));
    assert_eq!(e.key.as_deref(), Some("vehicle.programme[1].cycle_file"));
    assert_eq!(e.location.unwrap().line, 9);
    let shown = gap.display().to_string();
    assert!(
        e.to_string().contains(&format!(
            "{shown}: line 4 of the speed table: time 3 s, expected 2 s"
        )),
        "{e}"
    );
    // A negative speed, a word.
    let negative = trace_file("negative.txt", "0 0\n1 -1\n");
    assert!(err(&step(&negative, "m/s")).to_string().contains("line 2"));
    let word = trace_file("word.txt", "0 0\n1 fast\n");
    assert!(
        err(&step(&word, "mph"))
            .to_string()
            .contains("speed 'fast'")
    );
    // A trace in km/h given as m/s: 120 m/s is no road speed.
    let kmh = trace_file("kmh.txt", "0 0\n1 60\n2 120\n");
    let e = err(&step(&kmh, "m/s"));
    assert!(e.to_string().contains("is cycle_unit right?"), "{e}");
    assert!(parse_str("w.toml", &step(&kmh, "km/h")).is_ok());
    // No such file.
    let e = err(&step(&PathBuf::from("/nonexistent/trace.txt"), "mph"));
    assert!(e.to_string().contains("/nonexistent/trace.txt"), "{e}");
}
