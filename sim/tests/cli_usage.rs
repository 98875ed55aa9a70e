//! The `vehicle-sim` binary's usage: its help, and the usage and world errors with their
//! exit codes and locations (`cli.rs` has its runs and the files they write).

// Helpers outside #[test] functions unwrap too: a failure is a test failure.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

mod cli_common;

use cli_common::{scratch, text, vehicle_sim};

#[test]
fn help_lists_options_scenarios_and_models() {
    let out = vehicle_sim(&["--help"]);
    assert_eq!(out.status.code(), Some(0));
    let help = text(&out.stdout);
    for word in [
        "--world",
        "--scenario",
        "--out",
        "--json",
        "--no-files",
        "--quiet",
        "--duration",
        "--seed",
        "--replay-overlay",
        "--version",
        "test-track",
        "lane-change",
        "square",
        "programme",
        "BmwX5",
        "Exit status",
        "sweep",
        "sweep-merge",
    ] {
        assert!(help.contains(word), "help lacks {word}:\n{help}");
    }
    let out = vehicle_sim(&["--version"]);
    assert_eq!(out.status.code(), Some(0));
    assert_eq!(
        text(&out.stdout).trim(),
        format!("vehicle-sim {}", env!("CARGO_PKG_VERSION"))
    );
}

#[test]
fn unknown_option_is_a_usage_error() {
    let out = vehicle_sim(&["--fastest"]);
    assert_eq!(out.status.code(), Some(2));
    assert!(out.stdout.is_empty());
    let err = text(&out.stderr);
    assert!(err.contains("unexpected argument '--fastest'"), "{err}");
    assert!(err.contains("--help"), "{err}");
    for args in [
        &["--scenario", "drift"][..],
        &["--world"],
        &["--duration", "0"],
        &["--seed", "x"],
    ] {
        let out = vehicle_sim(args);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(out.stdout.is_empty(), "{args:?}");
    }
}

#[test]
fn world_errors_exit_1_with_the_location() {
    let dir = scratch("bad-world");
    let world = dir.join("w.toml");
    std::fs::write(&world, "[vehicle]\nmodel = \"BmwX5\"\nmaxVelocty = 30\n").unwrap();
    let out = vehicle_sim(&[
        "--world",
        world.to_str().unwrap(),
        "--out",
        dir.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(1));
    let err = text(&out.stderr);
    assert!(
        err.contains("error: unknown key 'vehicle.maxVelocty'; did you mean 'maxVelocity'?"),
        "{err}"
    );
    assert!(
        err.contains(&format!("--> {}:3:1", world.display())),
        "{err}"
    );
    // Neither a file nor a model: said so, with the models (before: "cannot read the world
    // file").
    let out = vehicle_sim(&["--world", "Nope"]);
    assert_eq!(out.status.code(), Some(1));
    let err = text(&out.stderr);
    assert!(
        err.contains("'Nope' is neither a world file, a shipped world nor a vehicle model"),
        "{err}"
    );
    assert!(
        err.contains("models: ") && err.contains("ToyotaPrius"),
        "{err}"
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_scenario_the_world_cannot_run_is_a_usage_error() {
    let dir = scratch("wrong-vehicle");
    // A car scenario on a robot world: exit 2 (before: 1), nothing written.
    let robot = dir.join("r.toml");
    std::fs::write(&robot, "[differential_wheels]\n").unwrap();
    let out_dir = dir.join("out");
    let out = vehicle_sim(&[
        "--world",
        robot.to_str().unwrap(),
        "--scenario",
        "brake",
        "--out",
        out_dir.to_str().unwrap(),
    ]);
    assert_eq!(out.status.code(), Some(2));
    let err = text(&out.stderr);
    assert!(err.contains("needs a world with one car"), "{err}");
    assert!(err.contains("--help"), "{err}");
    assert!(!out_dir.exists());
    // And a robot scenario on a car world.
    assert_eq!(vehicle_sim(&["--scenario", "spin"]).status.code(), Some(2));
    std::fs::remove_dir_all(&dir).unwrap();
}
