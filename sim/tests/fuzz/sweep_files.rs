//! The sweep fuzz harness (issue #37): any sweep-file text through the sweep loader, and any
//! damage to a shard's output files through `sweep-merge` and `sweep --resume`.
//!
//! Shared by the property tests of this directory and the coverage-guided target
//! `fuzz/fuzz_targets/sweep_files.rs` (which includes this file by path). Invariants:
//!
//! * a sweep file loads or gives an error naming the file; a loaded sweep's first, middle and
//!   last cases have their values, and its columns start with `case` and end with `checksum`;
//! * a merge with a damaged shard either succeeds with every case's row, each carrying its
//!   checksum, or fails and leaves the output directory as an earlier merge left it, with no
//!   staging directory;
//! * a resume of a damaged shard either fails with the resume error or finishes with a
//!   `results.csv` byte for byte the undamaged run's: damage is never kept, and a torn tail is
//!   redone.

use std::path::{Path, PathBuf};
use std::sync::OnceLock;

use sim::sweep::{
    self, MANIFEST_JSON, OutputError, RESULTS_CSV, STAGING_PREFIX, Shard, Sweep, TIMINGS_CSV,
    WriteOptions,
};

/// The name sweep texts are given in messages.
pub const FILE: &str = "fuzz-sweep.toml";

/// Loads `text` as a sweep file and checks the first invariant.
///
/// # Errors
/// The broken invariant.
pub fn check_text(text: &str) -> Result<(), String> {
    let sweep = match Sweep::parse(FILE, text, Path::new(".")) {
        Ok(s) => s,
        Err(e) => {
            let message = e.to_string();
            // Every error but a missing case is about the file (or the base world it names).
            return if message.contains(FILE) || e.file_error().is_some() {
                Ok(())
            } else {
                Err(format!("an error that names no file: {message}"))
            };
        }
    };
    let names = sweep.columns().names();
    if names.first() != Some(&sweep::CASE_COLUMN) || names.last() != Some(&sweep::CHECKSUM_COLUMN) {
        return Err(format!("columns {names:?}"));
    }
    let n = sweep.len();
    for index in [0, n / 2, n.saturating_sub(1)] {
        if n > 0 {
            sweep
                .values(index)
                .map_err(|e| format!("case {index} of {n}: {e}"))?;
        }
    }
    if sweep.values(n).is_ok() {
        return Err(format!("case {n} of {n} has values"));
    }
    Ok(())
}

/// The sweep whose outputs are damaged: six short braking cases, in two shards.
const SWEEP: &str = "world = \"BmwX5\"\nscenario = \"brake\"\n[set]\nduration = 0.05\n\
                     [axes]\n\"ground.friction\" = [0.5, 0.6, 0.7, 0.8, 0.9, 1.0]\n";

/// Where the undamaged outputs are kept: a directory per test process.
fn pristine() -> &'static (Sweep, PathBuf) {
    static DIRS: OnceLock<(Sweep, PathBuf)> = OnceLock::new();
    DIRS.get_or_init(|| {
        let sweep = Sweep::parse("s.toml", SWEEP, Path::new(".")).expect("the sweep loads");
        let dir = std::env::temp_dir().join(format!("sim-fuzz-sweep-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        for i in 0..2 {
            let shard = Shard::new(i, 2).expect("shard i of 2");
            let out = dir.join(format!("s{i}"));
            sweep::write_sweep(
                &sweep,
                shard,
                Some(1),
                &out,
                WriteOptions::default(),
                &mut |_, _| {},
            )
            .expect("the undamaged shard runs");
        }
        sweep::merge(&[dir.join("s0"), dir.join("s1")], &dir.join("merged"))
            .expect("the undamaged shards merge");
        (sweep, dir)
    })
}

/// Damage to one file of shard 1: cut it at `cut` bytes (when given), then set the byte at
/// `at` (modulo the length) to `byte`.
#[derive(Debug, Clone, Copy)]
pub struct Damage {
    /// `timings.csv` rather than `results.csv`.
    pub timings: bool,
    /// The length to cut the file to (modulo its length + 1), if any.
    pub cut: Option<usize>,
    /// The byte to overwrite (modulo the length), if any, and its new value.
    pub byte: Option<(usize, u8)>,
}

fn copy_dir(from: &Path, to: &Path) -> Result<(), String> {
    std::fs::create_dir_all(to).map_err(|e| e.to_string())?;
    for entry in std::fs::read_dir(from).map_err(|e| e.to_string())? {
        let entry = entry.map_err(|e| e.to_string())?;
        if entry.path().is_file() {
            std::fs::copy(entry.path(), to.join(entry.file_name())).map_err(|e| e.to_string())?;
        }
    }
    Ok(())
}

fn read(path: &Path) -> String {
    std::fs::read_to_string(path).unwrap_or_default()
}

/// Applies `damage` to a copy of shard 1 and checks the merge and resume invariants.
///
/// # Errors
/// The broken invariant.
pub fn check_damage(damage: Damage) -> Result<(), String> {
    static CASES: std::sync::atomic::AtomicU64 = std::sync::atomic::AtomicU64::new(0);
    let case = CASES.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
    let (sweep, dir) = pristine();
    let scratch = dir.join(format!("case-{case}"));
    let _ = std::fs::remove_dir_all(&scratch);
    let damaged = scratch.join("s1");
    copy_dir(&dir.join("s1"), &damaged)?;
    let out = scratch.join("out");
    copy_dir(&dir.join("merged"), &out)?;
    let file = damaged.join(if damage.timings {
        TIMINGS_CSV
    } else {
        RESULTS_CSV
    });
    let mut bytes = std::fs::read(&file).map_err(|e| e.to_string())?;
    if let Some(cut) = damage.cut {
        bytes.truncate(cut % (bytes.len() + 1));
    }
    if let Some((at, value)) = damage.byte
        && !bytes.is_empty()
    {
        let n = bytes.len();
        bytes[at % n] = value;
    }
    std::fs::write(&file, &bytes).map_err(|e| e.to_string())?;

    // The merge: every row with its checksum, or the output as it was.
    let before = [RESULTS_CSV, TIMINGS_CSV, MANIFEST_JSON].map(|f| read(&out.join(f)));
    match sweep::merge(&[dir.join("s0"), damaged.clone()], &out) {
        Ok(m) => {
            let text = read(&out.join(RESULTS_CSV));
            let mut reader = csv::Reader::from_reader(text.as_bytes());
            let rows: Vec<csv::StringRecord> = reader.records().filter_map(Result::ok).collect();
            if m.rows != 6 || rows.len() != 6 || !rows.iter().all(sweep::checksum_matches) {
                return Err(format!("a merge of damaged files succeeded with:\n{text}"));
            }
        }
        Err(_) => {
            let after = [RESULTS_CSV, TIMINGS_CSV, MANIFEST_JSON].map(|f| read(&out.join(f)));
            if after != before {
                return Err("a failed merge changed the output directory".to_string());
            }
        }
    }
    let staging = std::fs::read_dir(&out)
        .map_err(|e| e.to_string())?
        .filter_map(Result::ok)
        .any(|e| e.file_name().to_string_lossy().starts_with(STAGING_PREFIX));
    if staging {
        return Err("a staging directory was left".to_string());
    }

    // The resume: the undamaged bytes, or the resume error.
    let resume = WriteOptions {
        resume: true,
        stop: None,
    };
    let shard = Shard::new(1, 2).ok_or("shard 1 of 2")?;
    let result = sweep::write_sweep(sweep, shard, Some(1), &damaged, resume, &mut |_, _| {});
    match result {
        Ok(_) => {
            let got = read(&damaged.join(RESULTS_CSV));
            if got != read(&dir.join("s1").join(RESULTS_CSV)) {
                return Err(format!("a resume kept damage:\n{got}"));
            }
        }
        Err(OutputError::Resume { .. }) => {}
        Err(e) => return Err(format!("a resume failed otherwise: {e}")),
    }
    let _ = std::fs::remove_dir_all(&scratch);
    Ok(())
}
