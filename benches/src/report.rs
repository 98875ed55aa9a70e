//! Reading criterion's results back, to print ratios between benchmarks at the end of a run.
//!
//! Criterion writes `<criterion dir>/<group>/<function>/<parameter>/new/estimates.json` after
//! each benchmark (only when run by `cargo bench`, not in test mode). The median of that file
//! is the number the README tables use.

use std::fs;
use std::path::{Path, PathBuf};
use std::time::{Duration, SystemTime};

use criterion::Criterion;

/// The settings of every criterion bench of this crate: short (0.5 s warm-up, 2 s of
/// measurement, 30 samples), so the whole `cargo bench -p benches` finishes in minutes on 2 cores.
pub fn criterion_config() -> Criterion {
    Criterion::default()
        .warm_up_time(Duration::from_millis(500))
        .measurement_time(Duration::from_secs(2))
        .sample_size(30)
}

/// True when the bench binary was started by `cargo bench` (which passes `--bench`), false in
/// `cargo test --benches`, where criterion runs each benchmark once and writes no results.
pub fn is_bench_run() -> bool {
    std::env::args().any(|a| a == "--bench")
}

/// The directory criterion writes to: `$CRITERION_HOME`, else `$CARGO_TARGET_DIR/criterion`,
/// else `target/criterion` found from this executable's path (`target/<profile>/deps/<exe>`).
pub fn criterion_dir() -> PathBuf {
    if let Some(home) = std::env::var_os("CRITERION_HOME") {
        return PathBuf::from(home);
    }
    if let Some(target) = std::env::var_os("CARGO_TARGET_DIR") {
        return PathBuf::from(target).join("criterion");
    }
    std::env::current_exe()
        .ok()
        .and_then(|exe| exe.ancestors().nth(3).map(Path::to_path_buf))
        .unwrap_or_else(|| PathBuf::from("target"))
        .join("criterion")
}

/// The median time (ns) of benchmark `id` (`"group/function/parameter"`, as criterion prints
/// it) in `dir`, if its `new/estimates.json` exists, parses, and was written at or after
/// `since` (so a benchmark filtered out of this run does not report a stale number).
pub fn median_ns(dir: &Path, id: &str, since: SystemTime) -> Option<f64> {
    let path = dir.join(id).join("new").join("estimates.json");
    let modified = fs::metadata(&path).and_then(|m| m.modified()).ok()?;
    if modified < since {
        return None;
    }
    let text = fs::read_to_string(&path).ok()?;
    let json: serde_json::Value = serde_json::from_str(&text).ok()?;
    json.get("median")?.get("point_estimate")?.as_f64()
}

/// The medians (ns) that this run of a bench binary wrote, by benchmark id.
#[derive(Debug, Clone)]
pub struct Medians {
    dir: PathBuf,
    since: SystemTime,
}

impl Medians {
    /// The results written in `dir` at or after `since`.
    pub fn new(dir: PathBuf, since: SystemTime) -> Self {
        Medians { dir, since }
    }

    /// The median time (ns) of benchmark `id` ([`median_ns`]), `None` if this run did not
    /// measure it.
    pub fn get(&self, id: &str) -> Option<f64> {
        median_ns(&self.dir, id, self.since)
    }

    /// Where the results are read from.
    pub fn dir(&self) -> &Path {
        &self.dir
    }
}

/// The `main` of a criterion bench binary that prints a summary: runs `benches` (the function
/// of a `criterion_group!`) and criterion's final summary, then, under `cargo bench` (not in
/// `cargo test --benches`, which writes no results), `summary` with the medians of this run.
pub fn main_with_summary(benches: fn(), summary: fn(&Medians)) {
    let since = SystemTime::now();
    benches();
    Criterion::default().configure_from_args().final_summary();
    if is_bench_run() {
        summary(&Medians::new(criterion_dir(), since));
    }
}

/// A duration (ns) in the unit that reads best: ns, µs or ms, three significant figures.
pub fn format_ns(ns: f64) -> String {
    if ns < 1e3 {
        format!("{ns:.1} ns")
    } else if ns < 1e6 {
        format!("{:.2} µs", ns / 1e3)
    } else {
        format!("{:.2} ms", ns / 1e6)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn reads_the_median_of_a_criterion_estimates_file() {
        let dir = std::env::temp_dir().join(format!("benches-report-{}", std::process::id()));
        let new = dir.join("g/f/8/new");
        fs::create_dir_all(&new).unwrap();
        let since = SystemTime::now() - Duration::from_secs(5);
        fs::write(
            new.join("estimates.json"),
            r#"{"mean":{"point_estimate":12.5},"median":{"point_estimate":11.25}}"#,
        )
        .unwrap();
        assert_eq!(median_ns(&dir, "g/f/8", since), Some(11.25));
        assert_eq!(median_ns(&dir, "g/f/9", since), None);
        // A file older than the run start is stale.
        let later = SystemTime::now() + Duration::from_secs(60);
        assert_eq!(median_ns(&dir, "g/f/8", later), None);
        fs::remove_dir_all(&dir).unwrap();
    }

    #[test]
    fn formats_durations() {
        assert_eq!(format_ns(85.04), "85.0 ns");
        assert_eq!(format_ns(12_345.0), "12.35 µs");
        assert_eq!(format_ns(2_500_000.0), "2.50 ms");
    }
}
