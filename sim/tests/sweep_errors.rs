//! Sweeps that fail: the errors of sweep files, each naming file, line and key, and of
//! merges of shards (missing, duplicated, foreign or too many).

#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

#[path = "support/sweep.rs"]
mod support;

use std::path::PathBuf;

use sim::sweep::{self, MergeError, RESULTS_CSV, Shard, Sweep};
use support::{SHORT, parse, read, scratch, write};

#[test]
fn sweep_file_errors_name_file_line_and_key() {
    let err = |text: &str| parse(text).err().map(|e| e.to_string());
    // An axis over a key that worlds do not have: the world file's error, at the axis.
    assert_eq!(
        err("scenario = \"brake\"\n[axes]\n\"vehicle.brakeCoeficient\" = [900]\n").as_deref(),
        Some("s.toml:3:1: unknown key 'vehicle.brakeCoeficient'; did you mean 'brakeCoefficient'?")
    );
    // A value of a type the key does not take, at the value.
    assert_eq!(
        err("scenario = \"brake\"\n[axes]\n\"ground.friction\" = [0.5, \"wet\"]\n").as_deref(),
        Some("s.toml:3:27: 'ground.friction' takes a number, found a string")
    );
    assert_eq!(
        err("[axes]\n\"vehicle.model\" = [\"BmwX5\", \"BMWX6\"]\n").as_deref(),
        Some("s.toml:2:29: unknown vehicle model 'BMWX6'; did you mean 'BmwX5'?")
    );
    // A generated number for a key that takes a string.
    assert_eq!(
        err("[axes]\n\"vehicle.model\" = { from = 1, to = 2, steps = 2 }\n").as_deref(),
        Some("s.toml:2:1: 'vehicle.model' takes a string, found an integer")
    );
    // [set] values are checked at their key.
    assert_eq!(
        err("[set]\n\"ground.friction\" = -2\n").as_deref(),
        Some("s.toml:2:1: invalid 'ground.friction': -2: must be finite and >= 0")
    );
    assert_eq!(
        err("[set]\nvehicle.wheelbase = -2\n").as_deref(),
        Some(
            "s.toml:2:9: invalid 'vehicle.wheelbase': a world file would replace the value: \
             invalid 'wheelbase' value -2 (must be > 0), used 4 instead."
        )
    );
    // The list names every shipped world, whatever `sim/worlds` holds.
    let worlds: Vec<&str> = sim::world_file::shipped::worlds().map(|w| w.name).collect();
    assert_eq!(
        err("world = \"BmwX6\"\n"),
        Some(format!(
            "'BmwX6' is neither a world file, a shipped world nor a vehicle model; did you mean \
             'BmwX5' or 'bmw-x5'? (worlds: {}; models: Car, BmwX5, CitroenCZero, ToyotaPrius, \
             LincolnMKZ, RangeRoverSportSVR, TeslaModel3, MercedesBenzSprinter, GreenPowerEVStar, \
             Bus, Truck, Tractor)",
            worlds.join(", ")
        ))
    );
    assert_eq!(
        err("scenario = \"square\"\n").as_deref(),
        Some(
            "s.toml:1:1: invalid 'scenario': scenario 'square' needs a world with one \
             DifferentialWheels robot, but the world holds BmwX5"
        )
    );
    assert_eq!(
        err("combine = \"zip\"\n[axes]\n\"ground.friction\" = [1, 2]\n\"vehicle.mass\" = [1]\n")
            .as_deref(),
        Some(
            "s.toml:1:1: invalid 'combine': zip needs axes of one length: 'ground.friction' \
             has 2 values, 'vehicle.mass' has 1"
        )
    );
    // A path that leads through a value that is no table.
    assert_eq!(
        err("[axes]\n\"vehicle.model.x\" = [1]\n").as_deref(),
        Some("s.toml:2:1: cannot set 'vehicle.model.x': 'vehicle.model' is a string, not a table")
    );
    // Missing files: the sweep's, the base world's (relative to the sweep file).
    let e = Sweep::load("/nonexistent/s.toml").unwrap_err().to_string();
    assert!(
        e.starts_with("/nonexistent/s.toml: cannot read the sweep file: "),
        "{e}"
    );
    let dir = scratch("errors");
    std::fs::write(dir.join("s.toml"), "world = \"w.toml\"\n").unwrap();
    let e = Sweep::load(dir.join("s.toml")).unwrap_err();
    let world = e.file_error().unwrap();
    assert_eq!(world.file, dir.join("w.toml").display().to_string());
    std::fs::write(
        dir.join("w.toml"),
        "[vehicle]\nmodel = \"ToyotaPrius\"\nmass = 1500\n",
    )
    .unwrap();
    let s = Sweep::load(dir.join("s.toml")).unwrap();
    assert_eq!(s.base().car().unwrap().params.body.mass, 1500.0);
    std::fs::remove_dir_all(&dir).unwrap();
    assert_eq!(
        parse(SHORT).unwrap().run_case(12).unwrap_err().to_string(),
        "no case 12: the sweep has 12 cases, numbered from 0"
    );
}

#[test]
fn a_merge_of_one_shard_of_many_names_a_few_missing_and_refuses_too_many() {
    // Issue #37: one shard of 10⁹ was accepted and its merge allocated a record per missing
    // shard (4 GB). The most shards now: MAX_SHARDS, and the merge names eight.
    let dir = scratch("merge-many");
    let sweep = parse(SHORT).unwrap();
    let last = dir.join("last");
    write(&sweep, Shard::new(3, sweep::MAX_SHARDS).unwrap(), 1, &last);
    let e = sweep::merge(std::slice::from_ref(&last), &dir.join("out")).unwrap_err();
    let MergeError::MissingShards {
        ref missing,
        absent,
        count,
    } = e
    else {
        panic!("{e:?}");
    };
    assert_eq!((absent, count), (sweep::MAX_SHARDS - 1, sweep::MAX_SHARDS));
    let first: Vec<usize> = missing.iter().map(|s| s.index()).collect();
    assert_eq!(first, [0, 1, 2, 4, 5, 6, 7, 8]);
    assert_eq!(
        e.to_string(),
        "shards 0/100000, 1/100000, 2/100000, 4/100000, 5/100000, 6/100000, 7/100000, \
         8/100000 and 99991 more are missing: merge the outputs of all 100000 shards"
    );
    // A manifest whose count was corrupted past the bound is no shard.
    let manifest = last.join(sweep::MANIFEST_JSON);
    let m = read(&manifest);
    std::fs::write(
        &manifest,
        m.replace(
            "\"shard_count\": 100000",
            "\"shard_count\": 18446744073709551615",
        ),
    )
    .unwrap();
    let e = sweep::merge(std::slice::from_ref(&last), &dir.join("out")).unwrap_err();
    assert_eq!(
        e.to_string(),
        format!(
            "{}: shard 3/18446744073709551615 is not a shard (0 <= I < N <= 100000)",
            manifest.display()
        )
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn merges_refuse_missing_duplicated_and_foreign_shards() {
    let dir = scratch("merge-errors");
    let text = "world = \"BmwX5\"\nscenario = \"brake\"\n[set]\nduration = 0.2\n[axes]\n\
                \"ground.friction\" = [0.5, 0.6, 0.7, 0.8, 0.9]\n";
    let sweep = parse(text).unwrap();
    let shard = |i: usize| {
        let d = dir.join(format!("s{i}"));
        write(&sweep, Shard::new(i, 2).unwrap(), 1, &d);
        d
    };
    let (s0, s1) = (shard(0), shard(1));
    let err = |dirs: &[PathBuf]| sweep::merge(dirs, &dir.join("out")).unwrap_err();
    assert!(matches!(
        err(std::slice::from_ref(&s0)),
        MergeError::MissingShards { ref missing, absent: 1, count: 2 } if missing == &[Shard::new(1, 2).unwrap()]
    ));
    assert!(matches!(
        err(&[s0.clone(), s0.clone()]),
        MergeError::DuplicateShard { .. }
    ));
    // Another sweep's shard: another fingerprint.
    let other = parse(&text.replace("0.9]", "0.95]")).unwrap();
    let foreign = dir.join("foreign");
    write(&other, Shard::new(1, 2).unwrap(), 1, &foreign);
    let e = err(&[s0.clone(), foreign.clone()]).to_string();
    assert!(
        e.contains("is not a shard of the sweep of") && e.contains("fingerprint"),
        "{e}"
    );
    // A case lost from a shard's file (a row deleted by hand): named with its shard.
    let results = s1.join(RESULTS_CSV);
    let full = read(&results);
    let cut: String = full
        .lines()
        .filter(|l| !l.starts_with("3,"))
        .map(|l| format!("{l}\n"))
        .collect();
    std::fs::write(&results, cut).unwrap();
    let e = err(&[s0.clone(), s1.clone()]).to_string();
    assert_eq!(
        e,
        format!(
            "case 3 is missing: {}/results.csv ends before it",
            s1.display()
        )
    );
    // A duplicated case.
    std::fs::write(&results, full.clone() + full.lines().last().unwrap() + "\n").unwrap();
    let e = err(&[s0.clone(), s1.clone()]).to_string();
    assert!(
        e.contains("has a row after its shard's last case (case 3)"),
        "{e}"
    );
    // A shard whose run stopped: its manifest says so.
    std::fs::write(&results, &full).unwrap();
    let manifest = s1.join(sweep::MANIFEST_JSON);
    let m = read(&manifest);
    std::fs::write(
        &manifest,
        m.replace("\"complete\": true", "\"complete\": false"),
    )
    .unwrap();
    let e = err(&[s0.clone(), s1.clone()]).to_string();
    assert_eq!(
        e,
        format!(
            "shard 1/2 in {} did not finish: it has 2 of its 2 rows (run it again)",
            s1.display()
        )
    );
    std::fs::write(&manifest, m).unwrap();
    assert!(matches!(
        sweep::merge(&[s0.clone(), s1.clone()], &s0).unwrap_err(),
        MergeError::OutputIsInput(_)
    ));
    sweep::merge(&[s0, s1], &dir.join("out")).unwrap();
    std::fs::remove_dir_all(&dir).unwrap();
}

#[cfg(unix)]
#[test]
fn an_endless_sweep_file_is_read_no_further_than_the_bound() {
    let e = Sweep::load("/dev/zero").unwrap_err();
    assert_eq!(
        e.to_string(),
        "/dev/zero: cannot read the sweep file: it is longer than 16 MiB, the most a world or \
         sweep file may hold"
    );
}
