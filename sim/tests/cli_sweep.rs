//! The `vehicle-sim sweep` and `sweep-merge` subcommands: outputs, shards and their merge,
//! and the Slurm example run as a job array would run it.

// Helpers outside #[test] functions unwrap too: a failure is a test failure.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

mod cli_common;

use cli_common::{scratch, text, vehicle_sim};

/// `vehicle-sim sweep …` with extra environment variables.
fn sweep_cmd(args: &[&str], env: &[(&str, &str)]) -> Output {
    let mut c = Command::new(env!("CARGO_BIN_EXE_vehicle-sim"));
    c.args(args);
    for var in [
        "SLURM_ARRAY_TASK_ID",
        "SLURM_ARRAY_TASK_COUNT",
        "SLURM_ARRAY_TASK_MIN",
        "JOB_COMPLETION_INDEX",
    ] {
        c.env_remove(var);
    }
    c.envs(env.iter().copied())
        .output()
        .expect("vehicle-sim runs")
}

#[test]
fn sweep_and_sweep_merge_subcommands() {
    let dir = scratch("sweep");
    let sweep = dir.join("s.toml");
    std::fs::write(
        &sweep,
        "world = \"BmwX5\"\nscenario = \"brake\"\n[set]\nduration = 0.5\n[axes]\n\
         \"ground.friction\" = [0.7, 0.8, 0.9, -1]\n",
    )
    .unwrap();
    let s = sweep.to_str().unwrap();
    let path = |name: &str| dir.join(name).to_str().unwrap().to_string();
    let whole = path("whole");
    let out = sweep_cmd(&["sweep", s, "--out", &whole, "--threads", "2"], &[]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let stdout = text(&out.stdout);
    assert!(
        stdout.contains("4 cases of brake on <default world>, 2 threads"),
        "{stdout}"
    );
    assert!(
        stdout.contains("1 failed (see their error column)"),
        "{stdout}"
    );
    assert!(
        stdout.contains("results.csv, timings.csv, sweep.json, plots/ground.friction.svg"),
        "{stdout}"
    );
    // Not a terminal: no progress bar.
    assert!(out.stderr.is_empty(), "{}", text(&out.stderr));
    let results = std::fs::read_to_string(dir.join("whole/results.csv")).unwrap();
    assert_eq!(results.lines().count(), 5);
    // The error cell, then the row's checksum.
    let last = results.lines().last().unwrap();
    assert!(
        last.contains(",invalid 'ground.friction': -1: must be finite and >= 0,"),
        "{last}"
    );
    // Two shards: one by its index, one from a Slurm array task's environment (tasks 1-2).
    let a = path("a");
    let out = sweep_cmd(&["sweep", s, "--out", &a, "--shard", "0/2", "-q"], &[]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(out.stdout.is_empty());
    let b = path("b");
    let slurm = [
        ("SLURM_ARRAY_TASK_ID", "2"),
        ("SLURM_ARRAY_TASK_COUNT", "2"),
        ("SLURM_ARRAY_TASK_MIN", "1"),
    ];
    let out = sweep_cmd(&["sweep", s, "--out", &b, "--shard", "auto", "-q"], &slurm);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    let merged = path("merged");
    let out = sweep_cmd(&["sweep-merge", &b, &a, "--out", &merged], &[]);
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert!(text(&out.stdout).starts_with("vehicle-sim: merged 2 shards: 4 cases, 1 failed\n"));
    assert_eq!(
        std::fs::read_to_string(dir.join("merged/results.csv")).unwrap(),
        results
    );
    // A Kubernetes pod: its index, the count from --shards.
    let k = path("k");
    let out = sweep_cmd(
        &[
            "sweep", s, "--out", &k, "--shard", "auto", "--shards", "2", "-q",
        ],
        &[("JOB_COMPLETION_INDEX", "1")],
    );
    assert_eq!(out.status.code(), Some(0), "{}", text(&out.stderr));
    assert_eq!(
        std::fs::read_to_string(dir.join("k/results.csv")).unwrap(),
        std::fs::read_to_string(dir.join("b/results.csv")).unwrap()
    );
    // Usage errors exit 2, load and merge errors 1, each saying why.
    let out = sweep_cmd(
        &["sweep", s, "--shard", "auto"],
        &[("JOB_COMPLETION_INDEX", "1")],
    );
    assert_eq!(out.status.code(), Some(2));
    assert!(
        text(&out.stderr).contains("give --shards N (the Job's completions)"),
        "{}",
        text(&out.stderr)
    );
    let out = sweep_cmd(&["sweep", s, "--shard", "auto"], &[]);
    assert_eq!(out.status.code(), Some(2));
    assert!(text(&out.stderr).contains("neither SLURM_ARRAY_TASK_ID"));
    let out = sweep_cmd(&["sweep", s, "--shard", "1/2", "--shards", "3"], &[]);
    assert_eq!(out.status.code(), Some(2));
    let out = sweep_cmd(&["sweep", &path("missing.toml")], &[]);
    assert_eq!(out.status.code(), Some(1));
    assert!(text(&out.stderr).contains("cannot read the sweep file"));
    let out = sweep_cmd(&["sweep-merge", &a, "--out", &path("m2")], &[]);
    assert_eq!(out.status.code(), Some(1));
    assert_eq!(
        text(&out.stderr),
        "vehicle-sim: error: shard 1/2 is missing: merge the outputs of all 2 shards\n"
    );
    // The default run is untouched by the subcommands; `sweep --help` documents the outputs.
    let out = vehicle_sim(&["sweep", "--help"]);
    assert_eq!(out.status.code(), Some(0));
    let help = text(&out.stdout);
    for word in [
        "--shard",
        "--shards",
        "--threads",
        "results.csv",
        "timings.csv",
        "sweep-merge",
    ] {
        assert!(help.contains(word), "sweep --help lacks {word}:\n{help}");
    }
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn a_signal_stops_a_sweep_with_consistent_files_and_resume_finishes_it() {
    let dir = scratch("sigint");
    let sweep = dir.join("s.toml");
    std::fs::write(
        &sweep,
        "world = \"BmwX5\"\nscenario = \"brake\"\n[set]\nduration = 2\n[axes]\n\
         \"ground.friction\" = { from = 0.5, to = 1.2, steps = 200 }\n",
    )
    .unwrap();
    let s = sweep.to_str().unwrap();
    let out = dir.join("out");
    let o = out.to_str().unwrap();
    let child = Command::new(env!("CARGO_BIN_EXE_vehicle-sim"))
        .args(["sweep", s, "--out", o, "--threads", "1", "-q"])
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    // SIGINT once the first rows are written (the handler is installed before the first case).
    let results = out.join("results.csv");
    let start = std::time::Instant::now();
    while std::fs::read_to_string(&results).map_or(0, |t| t.lines().count()) < 3 {
        assert!(start.elapsed().as_secs() < 120, "no rows after 120 s");
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
    let kill = Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .unwrap();
    assert!(kill.success());
    let output = child.wait_with_output().unwrap();
    let stderr = text(&output.stderr);
    // 200 cases of several ms each on one thread: the signal comes before the end.
    assert_eq!(output.status.code(), Some(130), "{stderr}");
    assert!(stderr.contains("vehicle-sim: stopped: "), "{stderr}");
    assert!(stderr.contains("--resume` runs the others"), "{stderr}");
    let rows = std::fs::read_to_string(&results).unwrap().lines().count() - 1;
    let timings = std::fs::read_to_string(out.join("timings.csv")).unwrap();
    assert_eq!(timings.lines().count() - 1, rows);
    let manifest = std::fs::read_to_string(out.join("sweep.json")).unwrap();
    assert!(
        manifest.contains(&format!("\"rows\": {rows},")),
        "{manifest}"
    );
    assert!(manifest.contains("\"complete\": false"), "{manifest}");
    assert!(rows < 200, "{rows}");

    let resumed = sweep_cmd(&["sweep", s, "--out", o, "--resume"], &[]);
    assert_eq!(resumed.status.code(), Some(0), "{}", text(&resumed.stderr));
    assert!(
        text(&resumed.stdout).contains(&format!("{} cases in ", 200 - rows))
            && text(&resumed.stdout)
                .contains(&format!("after the {rows} kept from the earlier run")),
        "{}",
        text(&resumed.stdout)
    );
    let whole = dir.join("whole");
    let w = sweep_cmd(&["sweep", s, "--out", whole.to_str().unwrap(), "-q"], &[]);
    assert_eq!(w.status.code(), Some(0));
    assert_eq!(
        std::fs::read_to_string(&results).unwrap(),
        std::fs::read_to_string(whole.join("results.csv")).unwrap()
    );
    std::fs::remove_dir_all(&dir).unwrap();
}

/// The repository's root.
fn repo() -> PathBuf {
    Path::new(env!("CARGO_MANIFEST_DIR"))
        .parent()
        .unwrap()
        .to_path_buf()
}

#[test]
fn the_slurm_example_runs_as_a_job_array_would() {
    // examples/sweeps/slurm.sh as Slurm runs it for --array=0-7 (with `vehicle-sim` on the
    // PATH and the variables Slurm sets), then slurm-merge.sh; a short sweep of 5 cases, so
    // that 3 of the 8 shards have no case at all.
    let dir = scratch("slurm");
    let sweep = dir.join("s.toml");
    std::fs::write(
        &sweep,
        "world = \"ToyotaPrius\"\nscenario = \"accel-speed\"\n[set]\nduration = 0.3\n[axes]\n\
         \"vehicle.time0To100\" = { from = 8, to = 12, steps = 5 }\n",
    )
    .unwrap();
    let bin = Path::new(env!("CARGO_BIN_EXE_vehicle-sim"))
        .parent()
        .unwrap();
    let path = format!(
        "{}:{}",
        bin.display(),
        std::env::var("PATH").unwrap_or_default()
    );
    let out = dir.join("out");
    let run = |script: &str, task: Option<usize>| {
        let mut c = Command::new("bash");
        c.arg(repo().join("examples/sweeps").join(script))
            .current_dir(&dir)
            .env("PATH", &path)
            .env("SWEEP", &sweep)
            .env("OUT", &out)
            .env("SLURM_CPUS_PER_TASK", "1")
            .env_remove("JOB_COMPLETION_INDEX");
        if let Some(t) = task {
            c.env("SLURM_ARRAY_TASK_ID", t.to_string())
                .env("SLURM_ARRAY_TASK_MIN", "0")
                .env("SLURM_ARRAY_TASK_COUNT", "8");
        }
        let o = c.output().unwrap();
        assert_eq!(
            o.status.code(),
            Some(0),
            "{script} {task:?}: {}",
            text(&o.stderr)
        );
        o
    };
    for task in 0..8 {
        run("slurm.sh", Some(task));
    }
    let merged = run("slurm-merge.sh", None);
    assert!(text(&merged.stdout).contains("merged 8 shards: 5 cases, 0 failed"));
    let whole = dir.join("whole");
    let o = vehicle_sim(&[
        "sweep",
        sweep.to_str().unwrap(),
        "--out",
        whole.to_str().unwrap(),
        "-q",
    ]);
    assert_eq!(o.status.code(), Some(0));
    assert_eq!(
        std::fs::read_to_string(out.join("merged/results.csv")).unwrap(),
        std::fs::read_to_string(whole.join("results.csv")).unwrap()
    );
    // An empty shard: the header alone.
    let empty = std::fs::read_to_string(out.join("shard-7/results.csv")).unwrap();
    assert_eq!(empty.lines().count(), 1);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn thread_and_shard_counts_past_their_bounds_are_usage_errors() {
    // Issue #37: --threads 10000 spent 12 s before failing, --shard 0/1000000000 was taken
    // and its merge allocated 4 GB. Both are refused at once, before the sweep file is read.
    let usage = |args: &[&str], message: &str| {
        let out = sweep_cmd(args, &[]);
        assert_eq!(out.status.code(), Some(2), "{args:?}");
        assert!(text(&out.stderr).contains(message), "{}", text(&out.stderr));
    };
    usage(
        &["sweep", "none.toml", "--threads", "10000"],
        "'10000' is not a number of threads from 1 to 1024",
    );
    usage(
        &["sweep", "none.toml", "--threads", "0"],
        "'0' is not a number of threads from 1 to 1024",
    );
    usage(
        &["sweep", "none.toml", "--shard", "0/1000000000"],
        "1000000000 shards: a sweep is split into at most 100000 shards",
    );
    usage(
        &["sweep", "none.toml", "--shard", "1/18446744073709551615"],
        "18446744073709551615 shards: a sweep is split into at most 100000 shards",
    );
    // 1024 threads and 100000 shards are accepted: the missing file is then the error.
    let out = sweep_cmd(
        &[
            "sweep",
            "none.toml",
            "--threads",
            "1024",
            "--shard",
            "0/100000",
        ],
        &[],
    );
    assert_eq!(out.status.code(), Some(1));
    assert!(text(&out.stderr).contains("cannot read the sweep file"));
}
