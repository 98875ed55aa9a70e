//! Sweeps that stop early and go on (issue #37): a stopped run leaves `sweep.json`,
//! `timings.csv` and `results.csv` agreeing on the rows written, `--resume` finishes it with
//! the same bytes as an uninterrupted run, an edited row is caught by its checksum, and a
//! failed merge leaves the output directory as it was.

// Helpers outside #[test] functions unwrap too: a failure is a test failure.
#![allow(clippy::unwrap_used, clippy::expect_used, clippy::panic)]

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicBool, Ordering};

use sim::sweep::{
    self, MANIFEST_JSON, Manifest, MergeError, OutputError, RESULTS_CSV, STAGING_PREFIX, Shard,
    Sweep, TIMINGS_CSV, WriteOptions,
};

/// A fresh scratch directory for one test.
fn scratch(name: &str) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("sim-resume-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).unwrap();
    dir
}

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap()
}

/// The threads of the tests' runs.
const THREADS: usize = 2;

/// Ten short braking cases.
fn sweep() -> Sweep {
    braking(10, 1.4)
}

/// `cases` short braking cases, on frictions from 0.5 to `to`.
fn braking(cases: usize, to: f64) -> Sweep {
    let text = format!(
        "world = \"BmwX5\"\nscenario = \"brake\"\n[set]\nduration = 0.3\n[axes]\n\
         \"ground.friction\" = {{ from = 0.5, to = {to}, steps = {cases} }}\n"
    );
    Sweep::parse("s.toml", &text, Path::new(".")).unwrap()
}

fn write(sweep: &Sweep, shard: Shard, dir: &Path, options: WriteOptions<'_>) -> sweep::RunSummary {
    sweep::write_sweep(sweep, shard, Some(THREADS), dir, options, &mut |_, _| {}).unwrap()
}

/// The data lines of a CSV file (its header left out).
fn data_lines(path: &Path) -> usize {
    read(path).lines().count() - 1
}

#[test]
fn a_stopped_run_is_consistent_and_resume_finishes_it_byte_for_byte() {
    let dir = scratch("stop");
    // More cases than the workers may run ahead of the rows written (their window):
    // however fast they are next to the thread writing the rows, the stop comes before
    // every case has started.
    let cases = 4 + sweep::WINDOW_PER_THREAD * THREADS + 1;
    let sweep = braking(cases, 0.5 + 0.01 * (cases - 1) as f64);
    write(
        &sweep,
        Shard::WHOLE,
        &dir.join("whole"),
        WriteOptions::default(),
    );
    let whole = read(&dir.join("whole").join(RESULTS_CSV));

    // Stopped from the progress callback once 4 rows are written, as a signal handler would.
    let stop = AtomicBool::new(false);
    let out = dir.join("stopped");
    let options = WriteOptions {
        resume: false,
        stop: Some(&stop),
    };
    let summary = sweep::write_sweep(
        &sweep,
        Shard::WHOLE,
        Some(THREADS),
        &out,
        options,
        &mut |n, _| {
            if n == 4 {
                stop.store(true, Ordering::SeqCst);
            }
        },
    )
    .unwrap();
    assert!(!summary.complete);
    // The cases started when the flag was seen finish: 4 rows or more, at most the window
    // beyond them, never all.
    assert!(
        (4..cases).contains(&summary.rows),
        "{} of {cases}",
        summary.rows
    );
    let m = Manifest::read(&out).unwrap();
    assert!(!m.complete);
    assert_eq!(m.rows, summary.rows);
    assert_eq!(data_lines(&out.join(RESULTS_CSV)), summary.rows);
    assert_eq!(data_lines(&out.join(TIMINGS_CSV)), summary.rows);
    assert!(whole.starts_with(&read(&out.join(RESULTS_CSV))));
    // No plots for a run that did not finish.
    assert!(!out.join(sweep::PLOTS_DIR).exists());

    let resume = WriteOptions {
        resume: true,
        stop: None,
    };
    let summary2 = write(&sweep, Shard::WHOLE, &out, resume);
    assert!(summary2.complete);
    assert_eq!((summary2.resumed, summary2.rows), (summary.rows, cases));
    assert_eq!(read(&out.join(RESULTS_CSV)), whole);
    assert_eq!(data_lines(&out.join(TIMINGS_CSV)), cases);
    assert!(Manifest::read(&out).unwrap().complete);
    // Resuming a complete run runs nothing and changes nothing.
    let again = write(&sweep, Shard::WHOLE, &out, resume);
    assert_eq!((again.resumed, again.rows), (cases, cases));
    assert_eq!(read(&out.join(RESULTS_CSV)), whole);
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn resume_cuts_a_torn_row_and_refuses_damage_and_other_runs() {
    let dir = scratch("torn");
    let sweep = sweep();
    let shard = Shard::new(1, 2).unwrap();
    let full_dir = dir.join("full");
    write(&sweep, shard, &full_dir, WriteOptions::default());
    let full = read(&full_dir.join(RESULTS_CSV));
    let timings = read(&full_dir.join(TIMINGS_CSV));
    let resume = WriteOptions {
        resume: true,
        stop: None,
    };

    // As a run killed mid-write leaves it: 2 whole rows and half a third in results.csv, the
    // third timing written, and the manifest of the run's start (0 rows, not complete).
    let out = dir.join("killed");
    std::fs::create_dir_all(&out).unwrap();
    let lines: Vec<&str> = full.split_inclusive('\n').collect();
    let torn = format!(
        "{}{}{}{}",
        lines[0],
        lines[1],
        lines[2],
        &lines[3][..lines[3].len() / 2]
    );
    std::fs::write(out.join(RESULTS_CSV), torn).unwrap();
    let t: Vec<&str> = timings.split_inclusive('\n').collect();
    std::fs::write(out.join(TIMINGS_CSV), t[..4].concat()).unwrap();
    let manifest = read(&full_dir.join(MANIFEST_JSON))
        .replace("\"complete\": true", "\"complete\": false")
        .replace("\"rows\": 5", "\"rows\": 0");
    std::fs::write(out.join(MANIFEST_JSON), &manifest).unwrap();
    let s = write(&sweep, shard, &out, resume);
    assert_eq!((s.resumed, s.rows, s.complete), (2, 5, true));
    assert_eq!(read(&out.join(RESULTS_CSV)), full);
    assert_eq!(data_lines(&out.join(TIMINGS_CSV)), 5);

    // A value edited by hand in a row before the end: refused, nothing cut.
    let edited = full.replacen(",0.6,", ",0.65,", 1);
    assert_ne!(edited, full);
    std::fs::write(out.join(RESULTS_CSV), &edited).unwrap();
    std::fs::write(out.join(MANIFEST_JSON), &manifest).unwrap();
    let e = sweep::write_sweep(&sweep, shard, Some(1), &out, resume, &mut |_, _| {}).unwrap_err();
    assert!(matches!(e, OutputError::Resume { .. }), "{e}");
    assert!(
        e.to_string()
            .contains("results.csv line 2: case 1's checksum does not match"),
        "{e}"
    );
    assert_eq!(read(&out.join(RESULTS_CSV)), edited);

    // Another shard's directory, another sweep's: refused by name.
    let e = sweep::write_sweep(
        &sweep,
        Shard::new(0, 2).unwrap(),
        Some(1),
        &full_dir,
        resume,
        &mut |_, _| {},
    )
    .unwrap_err()
    .to_string();
    assert!(
        e.contains("it holds shard 1/2 where shard 0/2 was asked for"),
        "{e}"
    );
    let other = Sweep::parse(
        "s.toml",
        "world = \"BmwX5\"\nscenario = \"brake\"\n[axes]\n\"ground.friction\" = [0.7]\n",
        Path::new("."),
    )
    .unwrap();
    let e = sweep::write_sweep(&other, shard, Some(1), &full_dir, resume, &mut |_, _| {})
        .unwrap_err()
        .to_string();
    assert!(e.contains("it holds a run of another sweep"), "{e}");
    // A directory with nothing in it starts afresh.
    let fresh = write(&sweep, shard, &dir.join("fresh"), resume);
    assert_eq!((fresh.resumed, fresh.rows), (0, 5));
    std::fs::remove_dir_all(&dir).unwrap();
}

#[test]
fn an_edited_row_stops_a_merge_and_a_failed_merge_leaves_the_output_as_it_was() {
    let dir = scratch("merge");
    let sweep = sweep();
    let shards: Vec<PathBuf> = (0..2)
        .map(|i| {
            let d = dir.join(format!("s{i}"));
            write(
                &sweep,
                Shard::new(i, 2).unwrap(),
                &d,
                WriteOptions::default(),
            );
            d
        })
        .collect();
    let out = dir.join("out");
    sweep::merge(&shards, &out).unwrap();
    let before: Vec<String> = [RESULTS_CSV, TIMINGS_CSV, MANIFEST_JSON]
        .iter()
        .map(|f| read(&out.join(f)))
        .collect();

    // Case 2's friction edited in shard 0 (its second row, line 3).
    let results = shards[0].join(RESULTS_CSV);
    let good = read(&results);
    let edited = good.replacen("\n2,0.7,", "\n2,0.75,", 1);
    assert_ne!(edited, good);
    std::fs::write(&results, &edited).unwrap();
    let e = sweep::merge(&shards, &out).unwrap_err();
    assert!(
        matches!(
            e,
            MergeError::Checksum {
                line: 3,
                case: 2,
                ..
            }
        ),
        "{e}"
    );
    // The earlier merge is untouched and no staging directory is left.
    let after: Vec<String> = [RESULTS_CSV, TIMINGS_CSV, MANIFEST_JSON]
        .iter()
        .map(|f| read(&out.join(f)))
        .collect();
    assert_eq!(after, before);
    let left: Vec<String> = std::fs::read_dir(&out)
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with(STAGING_PREFIX))
        .collect();
    assert!(left.is_empty(), "{left:?}");
    assert!(
        out.join(sweep::PLOTS_DIR)
            .join("ground.friction.svg")
            .exists()
    );
    std::fs::remove_dir_all(&dir).unwrap();
}
