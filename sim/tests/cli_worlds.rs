//! `vehicle-sim`: shipped worlds by name, `vehicle-sim worlds`, every world-file error at once
//! with its line and a caret, and scenarios that could not run to their end.

// Helpers outside #[test] functions unwrap too: a failure is a test failure.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::process::{Command, Output};

mod cli_common;

use cli_common::{scratch, text, vehicle_sim};

/// Runs `vehicle-sim` with `args` in the directory `dir`, where no world file lies.
fn vehicle_sim_in(dir: &std::path::Path, args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_vehicle-sim"))
        .args(args)
        .current_dir(dir)
        .output()
        .expect("vehicle-sim runs")
}

#[test]
fn shipped_worlds_run_by_name_from_anywhere() {
    let dir = scratch("worlds-by-name");
    // Before: "neither a world file nor a vehicle model; did you mean 'Car'?".
    for args in [
        &["--world", "two-cars", "--duration", "0.2", "--no-files"][..],
        &[
            "--world",
            "two-cars.toml",
            "--duration",
            "0.2",
            "--no-files",
        ],
        // Its OpenDRIVE road comes from the embedded set too.
        &["--world", "hilly-road", "--duration", "0.2", "--no-files"],
    ] {
        let out = vehicle_sim_in(&dir, args);
        assert_eq!(
            out.status.code(),
            Some(0),
            "{args:?}: {}",
            text(&out.stderr)
        );
    }
    // A misspelt world name gets the world as a suggestion.
    let out = vehicle_sim_in(&dir, &["--world", "two-car"]);
    assert_eq!(out.status.code(), Some(1));
    let err = text(&out.stderr);
    assert!(err.contains("did you mean 'two-cars'"), "{err}");
    assert!(err.contains("worlds: acc,"), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn worlds_lists_every_shipped_world_with_its_first_comment() {
    let out = vehicle_sim(&["worlds"]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let listing = text(&out.stdout);
    let shipped = std::fs::read_dir(concat!(env!("CARGO_MANIFEST_DIR"), "/worlds")).unwrap();
    let mut names = 0;
    for entry in shipped {
        let path = entry.unwrap().path();
        if path.extension().is_none_or(|e| e != "toml") {
            continue;
        }
        names += 1;
        let name = path.file_stem().unwrap().to_str().unwrap();
        let first = std::fs::read_to_string(&path)
            .unwrap()
            .lines()
            .find_map(|l| l.trim().strip_prefix('#').map(|c| c.trim().to_string()))
            .unwrap();
        let line = listing
            .lines()
            .find(|l| l.split_whitespace().next() == Some(name))
            .unwrap_or_else(|| panic!("{name} missing:\n{listing}"));
        assert!(line.ends_with(&first), "{line}");
    }
    assert!(names >= 10, "{listing}");
    let help = text(&vehicle_sim(&["--help"]).stdout);
    assert!(help.contains("vehicle-sim worlds"), "{help}");
    assert!(help.contains("https://"), "{help}");
}

#[test]
fn three_typos_are_three_errors_in_file_order_with_their_lines() {
    let dir = scratch("three-typos");
    let world = dir.join("w.toml");
    // The reader meets [ground]'s typo before [vehicle]'s: the report is in file order.
    let lines = [
        "basicTimeStep = 10",
        "[vehicle]",
        "model = \"BmwX5\"",
        "maxVelocty = 30",
        "time0to10 = 7",
        "[ground]",
        "fricton = 1.0",
    ];
    std::fs::write(&world, lines.join("\n") + "\n").unwrap();
    let out = vehicle_sim(&["--world", world.to_str().unwrap(), "--no-files"]);
    assert_eq!(out.status.code(), Some(1));
    let err = text(&out.stderr);
    let err_lines: Vec<&str> = err.lines().collect();
    let mut last = 0;
    for (line, key) in [(4, "maxVelocty"), (5, "time0to10"), (7, "fricton")] {
        let source = lines[line - 1];
        // The location, then the line's text after its number, then a caret line under the
        // key.
        let at = err_lines
            .iter()
            .position(|l| l.ends_with(&format!("w.toml:{line}:1")))
            .unwrap_or_else(|| panic!("no location of line {line}:\n{err}"));
        assert!(at > last || last == 0, "out of order:\n{err}");
        last = at;
        let text_line = err_lines[at + 2];
        assert!(text_line.ends_with(source), "{text_line}\n{err}");
        let caret = err_lines[at + 3];
        let column = text_line.len() - source.len();
        assert_eq!(
            &caret[column..column + key.len()],
            "^".repeat(key.len()),
            "{err}"
        );
        assert!(err_lines[at - 1].contains("unknown key '"), "{err}");
    }
    assert!(err.contains("3 errors in this file"), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_brake_test_that_never_braked_says_so_and_fails() {
    // Before: "stopping distance n/a", a stopping distance "from brake torque" and a heading
    // change of 0 as if measured, exit 0.
    let out = vehicle_sim(&["--scenario", "brake", "--duration", "5", "--no-files"]);
    assert_eq!(out.status.code(), Some(3), "{}", text(&out.stderr));
    let err = text(&out.stderr);
    assert!(
        err.contains("scenario brake did not run to its end: braking never started"),
        "{err}"
    );
    // Nothing reads as measured: every brake metric is "not reached".
    let table = text(&out.stdout);
    for label in [
        "speed when braking starts",
        "stopping distance",
        "stopping time",
        "stopping distance from brake torque",
        "heading change while braking",
        "at rest 1 s after stopping",
    ] {
        let row = table
            .lines()
            .find(|l| l.contains(label))
            .unwrap_or_else(|| panic!("no {label}:\n{table}"));
        assert!(row.contains("not reached"), "{row}");
    }
    let out = vehicle_sim(&[
        "--scenario",
        "brake",
        "--duration",
        "5",
        "--no-files",
        "--json",
    ]);
    assert_eq!(out.status.code(), Some(3));
    let json: serde_json::Value = serde_json::from_slice(&out.stdout).unwrap();
    let why = json["scenarios"]["brake"]["unfinished"].as_str().unwrap();
    assert!(why.starts_with("braking never started"), "{why}");
}

#[test]
fn a_sweep_file_reports_every_error_with_its_line() {
    let dir = scratch("sweep-typos");
    let sweep = dir.join("s.toml");
    let lines = [
        "world = \"BmwX5\"",
        "scenario = \"brake\"",
        "[set]",
        "duraton = 1",
        "[axes]",
        "\"ground.fricton\" = [0.5, 1.0]",
    ];
    std::fs::write(&sweep, lines.join("\n") + "\n").unwrap();
    let out = vehicle_sim(&[
        "sweep",
        sweep.to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(1));
    let err = text(&out.stderr);
    let at = |line: usize| {
        err.find(&format!("s.toml:{line}:"))
            .unwrap_or_else(|| panic!("no error at line {line}:\n{err}"))
    };
    assert!(at(4) < at(6), "{err}");
    for line in [4, 6] {
        assert!(
            err.contains(&format!("{line} | {}", lines[line - 1])),
            "{err}"
        );
    }
    assert!(err.contains("2 errors in this file"), "{err}");
    std::fs::remove_dir_all(&dir).unwrap();
}
