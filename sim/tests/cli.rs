//! The `vehicle-sim` binary's runs: their JSON output and the files they write
//! (`cli_usage.rs` has its help and usage errors). Scenarios are kept short with a world
//! `duration` or `--duration`.

// Helpers outside #[test] functions unwrap too: a failure is a test failure.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::Path;
use std::process::{Command, Output};

mod cli_common;

use cli_common::{scratch, text, vehicle_sim};

/// The JSON of a run that exited 0, or 3 when a scenario could not run to its end (a short
/// `--duration`), which its JSON then says.
fn json_of(out: &Output) -> serde_json::Value {
    let code = out.status.code();
    assert!(
        matches!(code, Some(0 | 3)),
        "{code:?}, stderr: {}",
        text(&out.stderr)
    );
    let j: serde_json::Value = serde_json::from_slice(&out.stdout)
        .unwrap_or_else(|e| panic!("{e}: {}", text(&out.stdout)));
    let unfinished = j["scenarios"]
        .as_object()
        .is_some_and(|s| s.values().any(|r| r.get("unfinished").is_some()));
    assert_eq!(unfinished, code == Some(3), "{j}");
    j
}

fn assert_files(dir: &Path, names: &[&str]) {
    for n in names {
        let p = dir.join(n);
        let len = std::fs::metadata(&p).map(|m| m.len()).unwrap_or(0);
        assert!(len > 0, "{} missing or empty", p.display());
    }
}

#[test]
fn json_metrics_of_a_short_car_run() {
    let dir = scratch("json-car");
    let world = dir.join("short.toml");
    // One simulated second: the car cannot reach 100 km/h, so the time is null.
    std::fs::write(&world, "duration = 1.0\n[vehicle]\nmodel = \"BmwX5\"\n").unwrap();
    let out_dir = dir.join("out");
    let out = vehicle_sim(&[
        "--world",
        world.to_str().unwrap(),
        "--scenario",
        "accel-speed",
        "--json",
        "--out",
        out_dir.to_str().unwrap(),
    ]);
    let j = json_of(&out);
    assert_eq!(j["vehicle"], "BmwX5");
    assert_eq!(j["scenario"], "accel-speed");
    for key in ["sim_seconds", "wall_seconds", "realtime_factor"] {
        assert!(j[key].is_number(), "{key}: {j}");
    }
    assert!(
        (j["sim_seconds"].as_f64().unwrap() - 1.0).abs() < 1e-9,
        "{j}"
    );
    let m = &j["scenarios"]["accel-speed"];
    assert!(m["time_0_100_s"].is_null(), "{m}");
    assert_eq!(m["time_0_100_nominal_s"], 7.0);
    assert!(m["max_speed_kmh"].as_f64().unwrap() > 5.0, "{m}");
    assert_files(
        &out_dir,
        &[
            "telemetry.csv",
            "metrics.json",
            "speed.svg",
            "trajectory.svg",
        ],
    );
    // The tyres' friction use is plotted for the lane change only.
    assert!(!out_dir.join("friction_use.svg").exists());
    let csv = std::fs::read_to_string(out_dir.join("telemetry.csv")).unwrap();
    // Header, the state at t = 0 (before: none), then one row per 10 ms step.
    assert_eq!(csv.lines().count(), 1 + 1 + 100);
    let first: Vec<&str> = csv.lines().nth(1).unwrap().split(',').collect();
    assert_eq!(first[..3], ["accel-speed", "BmwX5", "0"]);
    // 16 columns of the car (with its name), 6 per tyre, 5 of energy; no `-0` cell
    // (before: many, in the lateral quantities of a car driving straight).
    for line in csv.lines() {
        assert_eq!(line.split(',').count(), 16 + 4 * 6 + 5, "{line}");
        assert!(line.split(',').all(|c| c != "-0"), "{line}");
    }
    // Every number of metrics.json has at most 6 significant digits (before:
    // 88.50999999999999).
    let json = std::fs::read_to_string(out_dir.join("metrics.json")).unwrap();
    let j: serde_json::Value = serde_json::from_str(&json).unwrap();
    for (key, v) in j["scenarios"]["accel-speed"].as_object().unwrap() {
        if let Some(x) = v.as_f64() {
            let digits = x
                .to_string()
                .trim_start_matches(['-', '0', '.'])
                .chars()
                .filter(char::is_ascii_digit)
                .count();
            assert!(digits <= 6, "{key}: {x}");
        }
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The file names in `dir`, sorted.
fn listing(dir: &Path) -> Vec<String> {
    let mut names: Vec<String> = std::fs::read_dir(dir)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .collect();
    names.sort();
    names
}

#[test]
fn outputs_are_this_runs_and_listed_in_metrics_json() {
    let dir = scratch("outputs");
    let out_dir = dir.join("out");
    let run = |scenario: &str, extra: &[&str]| {
        let mut args = vec![
            "--scenario",
            scenario,
            "--duration",
            "0.5",
            "--json",
            "--out",
            out_dir.to_str().unwrap(),
        ];
        args.extend(extra);
        json_of(&vehicle_sim(&args))
    };
    // A lane change writes its own plots...
    let j = run("lane-change", &[]);
    assert!(
        j["files"]
            .as_array()
            .unwrap()
            .contains(&"lane_change.svg".into())
    );
    // ... which a brake run into the same directory removes (before: left behind).
    std::fs::write(out_dir.join("notes.txt"), "mine").unwrap();
    let j = run("brake", &[]);
    let mut files: Vec<String> = j["files"]
        .as_array()
        .unwrap()
        .iter()
        .map(|f| f.as_str().unwrap().to_string())
        .collect();
    let on_disk = std::fs::read_to_string(out_dir.join("metrics.json")).unwrap();
    assert_eq!(
        serde_json::from_str::<serde_json::Value>(&on_disk).unwrap()["files"],
        j["files"]
    );
    files.push("notes.txt".into());
    files.sort();
    assert_eq!(listing(&out_dir), files);
    assert!(!out_dir.join("lane_change.svg").exists());
    // --json writes the files too; --no-files writes none and lists none.
    let fresh = dir.join("none");
    let out = vehicle_sim(&[
        "--duration",
        "0.2",
        "--scenario",
        "brake",
        "--json",
        "--no-files",
        "--out",
        fresh.to_str().unwrap(),
    ]);
    let j = json_of(&out);
    assert_eq!(j["files"], serde_json::json!([]));
    assert!(!fresh.exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn duration_quiet_and_the_tilt_note_once() {
    let dir = scratch("quiet");
    // The Tractor's rotation pitches it: one note for the run (before: one per scenario, 5).
    let out = vehicle_sim(&[
        "--world",
        "Tractor",
        "--duration",
        "0.1",
        "--out",
        dir.to_str().unwrap(),
    ]);
    // 0.1 s ends the brake test before it brakes and the lane change before its track: exit 3.
    assert_eq!(out.status.code(), Some(3), "{}", text(&out.stderr));
    assert_eq!(
        text(&out.stderr).matches("tilts it").count(),
        1,
        "{}",
        text(&out.stderr)
    );
    // --duration caps each of the five scenarios.
    let table = text(&out.stdout);
    assert!(table.contains("simulated 0.5 s"), "{table}");
    // --quiet: nothing on either stream, the files still written.
    std::fs::remove_dir_all(&dir).unwrap();
    let out = vehicle_sim(&[
        "--world",
        "Tractor",
        "--duration",
        "0.1",
        "--quiet",
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(3));
    // Nothing but the errors: the scenarios that could not run to their end.
    assert!(out.stdout.is_empty());
    assert!(
        text(&out.stderr)
            .lines()
            .all(|l| l.contains("did not run to its end")),
        "{}",
        text(&out.stderr)
    );
    assert!(dir.join("telemetry.csv").exists());
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn seed_overrides_the_robots_noise_seed() {
    let dir = scratch("seed");
    let world = dir.join("noisy.toml");
    std::fs::write(
        &world,
        "[differential_wheels]\nslipNoise = 0.2\nwheelRadius = 0.05\nseed = 1\n",
    )
    .unwrap();
    let heading = |seed: &str| {
        let out = vehicle_sim(&[
            "--world",
            world.to_str().unwrap(),
            "--scenario",
            "spin",
            "--seed",
            seed,
            "--json",
            "--no-files",
        ]);
        json_of(&out)["scenarios"]["spin"]["final_heading_rad"]
            .as_f64()
            .unwrap()
    };
    assert_eq!(heading("7"), heading("7"));
    assert_ne!(heading("7"), heading("8"));
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The names of the nodes of the glTF file `path`.
fn node_names(path: &Path) -> Vec<String> {
    let doc = gltf::Gltf::open(path).expect("a valid replay.glb");
    doc.nodes()
        .filter_map(|n| n.name().map(str::to_string))
        .collect()
}

#[test]
fn replay_overlay_draws_the_radar_targets_without_editing_the_world() {
    // The ACC world has no `replayOverlay` key: the flag alone turns the overlay on.
    let world = concat!(env!("CARGO_MANIFEST_DIR"), "/worlds/acc.toml");
    let markers = |flag: bool| {
        let dir = scratch(if flag { "overlay-on" } else { "overlay-off" });
        let mut args = vec![
            "--world",
            world,
            "--duration",
            "0.5",
            "-q",
            "--out",
            dir.to_str().unwrap(),
        ];
        if flag {
            args.push("--replay-overlay");
        }
        let out = vehicle_sim(&args);
        assert_eq!(out.status.code(), Some(0), "stderr: {}", text(&out.stderr));
        let names = node_names(&dir.join("replay.glb"));
        std::fs::remove_dir_all(&dir).unwrap();
        names.iter().filter(|n| n.contains(" target ")).count()
    };
    assert_eq!(markers(false), 0);
    // One radar in the world: one pool of MAX_TARGET_MARKERS marker nodes.
    assert_eq!(markers(true), sim::replay::overlay::MAX_TARGET_MARKERS);
}

/// The columns of `name` in `header`, for every wheel in the order FR, FL, RR, RL.
fn tyre_columns(header: &str, name: &str) -> Vec<usize> {
    ["fr", "fl", "rr", "rl"]
        .map(|w| {
            header
                .split(',')
                .position(|c| c == format!("{w}_{name}"))
                .unwrap_or_else(|| panic!("no column {w}_{name} in {header}"))
        })
        .to_vec()
}

#[test]
fn lane_change_writes_the_tyres_friction_use() {
    let dir = scratch("lane-change");
    let out = vehicle_sim(&["--scenario", "lane-change", "--out", dir.to_str().unwrap()]);
    assert_eq!(out.status.code(), Some(0), "stderr: {}", text(&out.stderr));
    let stdout = text(&out.stdout);
    assert!(
        stdout.contains("lane_change.svg, friction_use.svg"),
        "{stdout}"
    );
    let svg = std::fs::read_to_string(dir.join("friction_use.svg")).unwrap();
    // One labelled line per tyre, and the grip limit as a dashed guide, in the legend.
    for label in [
        "front right",
        "front left",
        "rear right",
        "rear left",
        "grip limit",
    ] {
        assert_eq!(
            svg.matches(&format!(">\n{label}\n</text>")).count(),
            1,
            "{label}"
        );
    }
    assert!(svg.contains("friction use (0 to 1)"));
    // The cones have a legend entry in both maps (before: none).
    for plot in ["lane_change.svg", "trajectory.svg"] {
        let svg = std::fs::read_to_string(dir.join(plot)).unwrap();
        assert_eq!(svg.matches(">\ncones\n</text>").count(), 1, "{plot}");
    }

    let csv = std::fs::read_to_string(dir.join("telemetry.csv")).unwrap();
    let mut lines = csv.lines();
    let header = lines.next().unwrap();
    let use_columns = tyre_columns(header, "friction_use");
    let load_columns = tyre_columns(header, "fz_n");
    let rows: Vec<Vec<f64>> = lines
        .map(|l| {
            // Empty cells (no rpm in speed mode) read as NaN.
            l.split(',')
                .skip(2)
                .map(|c| {
                    if c.is_empty() {
                        f64::NAN
                    } else {
                        c.parse().unwrap()
                    }
                })
                .collect()
        })
        .collect();
    let cell = |row: &Vec<f64>, column: usize| row[column - 2];
    let mut peak = [0.0_f64; 4];
    for row in rows.iter().filter(|r| r[0] > 1.0) {
        for (i, (&u, &z)) in use_columns.iter().zip(&load_columns).enumerate() {
            let (friction_use, load) = (cell(row, u), cell(row, z));
            assert!(
                (0.0..=1.0).contains(&friction_use),
                "{friction_use} at t = {}",
                row[0]
            );
            // Settled on the ground: every tyre carries part of the car's weight (N).
            assert!(load > 1000.0, "load {load} N at t = {}", row[0]);
            peak[i] = peak[i].max(friction_use);
        }
    }
    // Steering through the lanes at 60 km/h asks every tyre for a good part of its grip.
    assert!(peak.iter().all(|&p| p > 0.2), "{peak:?}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn json_metrics_of_a_robot_run_and_the_table() {
    let dir = scratch("json-robot");
    let world = dir.join("robot.toml");
    std::fs::write(
        &world,
        "basicTimeStep = 16\n[differential_wheels]\nslipNoise = 0\naxleLength = 0.1\nwheelRadius = 0.05\n",
    )
    .unwrap();
    let out_dir = dir.join("out");
    let args = |json: bool| {
        let mut a = vec![
            "--world",
            world.to_str().unwrap(),
            "--scenario",
            "spin",
            "--out",
            out_dir.to_str().unwrap(),
        ];
        if json {
            a.push("--json");
        }
        a.into_iter().map(String::from).collect::<Vec<_>>()
    };
    let out = Command::new(env!("CARGO_BIN_EXE_vehicle-sim"))
        .args(args(true))
        .output()
        .unwrap();
    let j = json_of(&out);
    let m = &j["scenarios"]["spin"];
    for key in [
        "turns",
        "turns_expected",
        "position_drift_m",
        "final_x_m",
        "final_y_m",
        "final_heading_rad",
    ] {
        assert!(m[key].is_number(), "{key}: {m}");
    }
    // No noise: the robot turns on the spot as the kinematics predict.
    let (turns, expected) = (
        m["turns"].as_f64().unwrap(),
        m["turns_expected"].as_f64().unwrap(),
    );
    assert!(
        (turns - expected).abs() < 0.01 * expected,
        "{turns} vs {expected}"
    );
    assert!(m["position_drift_m"].as_f64().unwrap() < 1e-6);
    // Without --json: the summary table.
    let out = Command::new(env!("CARGO_BIN_EXE_vehicle-sim"))
        .args(args(false))
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(0));
    let table = text(&out.stdout);
    assert!(table.contains("DifferentialWheels"), "{table}");
    assert!(table.contains("turns made"), "{table}");
    assert!(table.contains("x real time"), "{table}");
    // The robot's speed is plotted in m/s (before: km/h).
    let svg = std::fs::read_to_string(out_dir.join("speed.svg")).unwrap();
    assert!(svg.contains("robot speed (m/s)"), "{svg}");
    assert!(!svg.contains("km/h"));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_built_in_scenario_writes_the_readings_of_the_worlds_devices() {
    let dir = scratch("devices-brake");
    let world = dir.join("gps.toml");
    // One simulated second of `brake` (which starts at 100 km/h) with a GPS sampled every
    // 100 ms: ten samples, at 0.1, 0.2 … 1.0 s, each of the same quantities.
    std::fs::write(
        &world,
        "duration = 1.0\n[vehicle]\nmodel = \"BmwX5\"\n\
         [[vehicle.device]]\ntype = \"GPS\"\nsamplingPeriod = 100\n",
    )
    .unwrap();
    let out_dir = dir.join("out");
    let out = vehicle_sim(&[
        "--world",
        world.to_str().unwrap(),
        "--scenario",
        "brake",
        "--json",
        "--out",
        out_dir.to_str().unwrap(),
    ]);
    let j = json_of(&out);
    assert_eq!(j["scenario"], "brake");
    let csv = std::fs::read_to_string(out_dir.join("devices.csv")).unwrap();
    let mut lines = csv.lines();
    assert_eq!(lines.next(), Some("time,car,device,quantity,value"));
    let rows: Vec<Vec<&str>> = lines.map(|l| l.split(',').collect()).collect();
    assert_eq!(rows.len() % 10, 0, "{csv}");
    let per_sample = rows.len() / 10;
    for (k, sample) in rows.chunks(per_sample).enumerate() {
        for r in sample {
            // Whole 10 ms steps summed in f64: 0.1 (k + 1) to well under a step.
            let t: f64 = r[0].parse().unwrap();
            assert!((t - 0.1 * (k + 1) as f64).abs() < 1e-9, "{r:?}");
        }
        let quantities: Vec<&str> = sample.iter().map(|r| r[3]).collect();
        let first: Vec<&str> = rows[..per_sample].iter().map(|r| r[3]).collect();
        assert_eq!(quantities, first);
    }
    // The GPS's position among them.
    assert!(rows[..per_sample].iter().any(|r| r[3] == "x"), "{csv}");
    assert!(
        rows.iter().all(|r| r[1] == "BmwX5" && r[2] == "gps"),
        "{csv}"
    );
    let metrics = std::fs::read_to_string(out_dir.join("metrics.json")).unwrap();
    assert!(metrics.contains("\"devices.csv\""), "{metrics}");
    std::fs::remove_dir_all(&dir).unwrap();
}
