//! What a run leaves behind: the summary table, the metrics as JSON, and the output directory
//! (telemetry CSV, JSON, the 3D replay and, with the `app` feature, the SVG plots). Every
//! function takes any [`RunReport`]: a built-in scenario's, a programme's, or one put together
//! from a run driven through the public API ([`Simulation::report`](crate::Simulation::report)).
//!
//! The data files ([`write_data`]: `telemetry.csv`, `metrics.json`, `replay.glb`) are the
//! engine's and every front-end writes them (the C API and Python under `VEHICLE_OUT`); the
//! plots need plotters and are the application's (`write_outputs`, `vehicle-sim plot`).

#[cfg(feature = "app")]
mod figures;
mod json;
mod page;
#[cfg(feature = "app")]
mod plot;

use std::fs::File;
use std::io::{BufWriter, Write as _};
use std::path::{Path, PathBuf};

use std::fmt::Write as _;

pub use crate::config::{Outline, OutlineKind};
#[cfg(feature = "app")]
pub use figures::figures;
pub use json::to_json;
pub use page::{MAX_PAGE_ROWS, PAGE_COLUMNS, REPORT_HTML};
#[cfg(feature = "app")]
pub(crate) use plot::COLOURS;
#[cfg(all(test, feature = "app"))]
pub(crate) use plot::svg_text;
#[cfg(feature = "app")]
pub use plot::{Figure, Panel, PlotError, Series, SeriesKind, XAxis};

use crate::scenario::{RunReport, Value};
use crate::telemetry::write_csv;

/// The telemetry file.
pub const TELEMETRY_CSV: &str = "telemetry.csv";
/// The metrics file.
pub const METRICS_JSON: &str = "metrics.json";
/// The devices' readings of a run driven through a `Simulation` (one row per recorded value:
/// time, car, device, quantity, value; see `sim::devices::RecordedQuantity`).
pub const DEVICES_CSV: &str = "devices.csv";
/// The file name of the run's animated 3D scene ([`crate::replay`]).
pub const REPLAY_GLB: &str = "replay.glb";

/// Every file a run may write into its output directory. A run removes those of this list
/// that it does not write itself, so that the directory never mixes two runs' outputs; other
/// files are left alone.
pub const KNOWN_OUTPUTS: [&str; 12] = [
    TELEMETRY_CSV,
    DEVICES_CSV,
    METRICS_JSON,
    REPLAY_GLB,
    REPORT_HTML,
    "speed.svg",
    "rpm_gear.svg",
    "steering.svg",
    "lane_change.svg",
    "friction_use.svg",
    "trajectory.svg",
    "lateral.svg",
];

/// Significant digits of the metrics in JSON: the physics runs in f32 (about seven
/// significant digits), so a seventh digit is noise.
pub const METRIC_DIGITS: usize = 6;
/// Significant digits of the wall-clock time and real-time factor in JSON: they vary by more
/// than 1 % from one run to the next.
pub const TIMING_DIGITS: usize = 3;

/// `x` rounded to `digits` significant digits (the shortest decimal that reads back as that),
/// unchanged if not finite.
///
/// ```
/// assert_eq!(sim::report::significant(88.50999999999999, 6), 88.51);
/// assert_eq!(sim::report::significant(-0.000_012_345_67, 3), -0.0000123);
/// ```
pub fn significant(x: f64, digits: usize) -> f64 {
    if !x.is_finite() || x == 0.0 {
        return x + 0.0;
    }
    format!("{:.*e}", digits.saturating_sub(1), x)
        .parse()
        .unwrap_or(x)
}

/// A value for the summary table: three significant decimals at most, `yes`/`no`, or
/// `not reached` (the event did not happen; the run's error says why).
pub fn format_value(v: Value) -> String {
    match v {
        Value::Number(x) if x.is_finite() => {
            let decimals = if x == x.trunc() && x.abs() < 1e6 {
                0
            } else if x.abs() >= 100.0 {
                1
            } else if x.abs() >= 10.0 {
                2
            } else {
                3
            };
            let s = format!("{x:.decimals$}");
            // A value that rounds to zero reads 0, not -0.
            if s.starts_with('-') && s.bytes().all(|b| matches!(b, b'-' | b'0' | b'.')) {
                s.trim_start_matches('-').to_string()
            } else {
                s
            }
        }
        Value::Number(x) => format!("{x}"),
        Value::Bool(true) => "yes".to_string(),
        Value::Bool(false) => "no".to_string(),
        Value::Missing => "not reached".to_string(),
    }
}

/// The human-readable summary: one row per metric, then the timing line.
pub fn summary_table(report: &RunReport) -> String {
    let mut rows: Vec<[String; 4]> = vec![[
        "scenario".into(),
        "metric".into(),
        "value".into(),
        "unit".into(),
    ]];
    for r in &report.results {
        for (i, m) in r.metrics.iter().enumerate() {
            let name = if i == 0 {
                r.name.clone()
            } else {
                String::new()
            };
            let label = match &m.vehicle {
                Some(v) => format!("{v}: {}", m.label),
                None => m.label.to_string(),
            };
            rows.push([name, label, format_value(m.value), m.unit.to_string()]);
        }
        rows.push([
            if r.metrics.is_empty() {
                r.name.clone()
            } else {
                String::new()
            },
            "simulated time".into(),
            format_value(Value::Number(r.sim_seconds)),
            "s".into(),
        ]);
    }
    let widths: Vec<usize> = (0..4)
        .map(|c| {
            rows.iter()
                .map(|r| r.get(c).map_or(0, |s| s.chars().count()))
                .max()
                .unwrap_or(0)
        })
        .collect();
    let mut out = format!(
        "vehicle-sim: {} in {}, scenario {}\n\n",
        report.vehicle, report.world, report.scenario
    );
    for (k, row) in rows.iter().enumerate() {
        let mut line = String::new();
        for (c, (cell, w)) in row.iter().zip(&widths).enumerate() {
            if c == 2 {
                let _ = write!(line, "{cell:>w$}  ");
            } else {
                let _ = write!(line, "{cell:<w$}  ");
            }
        }
        out.push_str(line.trim_end());
        out.push('\n');
        if k == 0 {
            let total: usize = widths.iter().sum::<usize>() + 6;
            out.push_str(&"-".repeat(total));
            out.push('\n');
        }
    }
    let _ = writeln!(
        out,
        "\nsimulated {:.1} s in {:.2} s of wall time ({} x real time)",
        report.sim_seconds,
        report.wall_seconds,
        format_value(Value::Number(report.realtime_factor()))
    );
    out
}

/// Why the outputs could not be written.
#[derive(Debug, thiserror::Error)]
#[non_exhaustive]
pub enum OutputError {
    /// A file or the directory could not be written (or a stale output removed).
    #[error("{}: {source}", path.display())]
    Io {
        /// The path concerned.
        path: PathBuf,
        /// What the system reported.
        source: std::io::Error,
    },
    /// The telemetry could not be written.
    #[error("{}: {source}", path.display())]
    Csv {
        /// The CSV file.
        path: PathBuf,
        /// What the CSV writer reported.
        source: csv::Error,
    },
    /// A plot could not be drawn.
    #[cfg(feature = "app")]
    #[error(transparent)]
    Plot(#[from] PlotError),
}

/// The files every run writes ([`write_data`]), in order: the data and the page that shows
/// them (`report.html`, [`REPORT_HTML`]).
pub const DATA_OUTPUTS: [&str; 4] = [TELEMETRY_CSV, METRICS_JSON, REPLAY_GLB, REPORT_HTML];

/// The names of the files [`write_outputs`] writes for `report`: `telemetry.csv`,
/// `devices.csv` (when a result has device readings), `metrics.json`, the plots of
/// [`figures`], `replay.glb` and `report.html`, in that order.
#[cfg(feature = "app")]
pub fn output_names(report: &RunReport) -> Vec<&'static str> {
    let devices = report.results.iter().any(|r| !r.devices.is_empty());
    [TELEMETRY_CSV]
        .into_iter()
        .chain(devices.then_some(DEVICES_CSV))
        .chain([METRICS_JSON])
        .chain(figures(report).into_iter().map(|(name, _)| name))
        .chain([REPLAY_GLB, REPORT_HTML])
        .collect()
}

/// Writes `telemetry.csv`, `devices.csv` (when a result has device readings),
/// `metrics.json`, the plots of [`figures`], `replay.glb` and `report.html` into
/// `dir` (created if needed), removes the [`KNOWN_OUTPUTS`] of an earlier run that this one
/// does not write, and returns the paths written.
///
/// # Errors
/// The first error, with the path it concerns.
#[cfg(feature = "app")]
pub fn write_outputs(
    report: &RunReport,
    world_warnings: &[String],
    dir: &Path,
) -> Result<Vec<PathBuf>, OutputError> {
    let plots = figures(report)
        .into_iter()
        .map(|(name, f)| f.to_svg().map(|svg| (name, svg)))
        .collect::<Result<Vec<_>, _>>()?;
    write_report(report, world_warnings, dir, &output_names(report), &plots)
}

/// Writes the data files of `report` into `dir` (created if needed): `telemetry.csv`,
/// `metrics.json`, `replay.glb` and the page `report.html` ([`DATA_OUTPUTS`]); removes the [`KNOWN_OUTPUTS`] of an
/// earlier run (its plots included) so that the directory never mixes two runs; returns the
/// paths written. This is what a controller run writes under `VEHICLE_OUT`; `vehicle-sim plot
/// DIR` draws the plots from them.
///
/// # Errors
/// The first error, with the path it concerns.
pub fn write_data(
    report: &RunReport,
    world_warnings: &[String],
    dir: &Path,
) -> Result<Vec<PathBuf>, OutputError> {
    write_report(report, world_warnings, dir, &DATA_OUTPUTS, &[])
}

/// [`write_files`] with the telemetry of `report` itself, and `devices.csv` after
/// `telemetry.csv` when a result has device readings (a `programme` run's).
fn write_report(
    report: &RunReport,
    world_warnings: &[String],
    dir: &Path,
    names: &[&str],
    plots: &[(&str, String)],
) -> Result<Vec<PathBuf>, OutputError> {
    let telemetry = |out: &mut dyn std::io::Write| {
        write_csv(out, report.results.iter().flat_map(|r| &r.telemetry))
    };
    let Some(devices) = report
        .results
        .iter()
        .map(|r| &r.devices)
        .find(|d| !d.is_empty())
    else {
        return write_files(report, world_warnings, dir, names, plots, &telemetry);
    };
    let mut names = names.to_vec();
    if !names.contains(&DEVICES_CSV) {
        names.insert(1, DEVICES_CSV);
    }
    let mut written = write_files(report, world_warnings, dir, &names, plots, &telemetry)?;
    let path = dir.join(DEVICES_CSV);
    let file = File::create(&path).map_err(io_error(&path))?;
    devices
        .write_csv(BufWriter::new(file))
        .map_err(|source| OutputError::Csv {
            path: path.clone(),
            source,
        })?;
    written.insert(1, path);
    Ok(written)
}

/// The I/O error of `path`.
fn io_error(path: &Path) -> impl FnOnce(std::io::Error) -> OutputError {
    let path = path.to_path_buf();
    move |source| OutputError::Io { path, source }
}

/// Writes `bytes` into `dir/name`; returns the path.
fn write_file(dir: &Path, name: &str, bytes: &[u8]) -> Result<PathBuf, OutputError> {
    let path = dir.join(name);
    let mut file = File::create(&path).map_err(io_error(&path))?;
    file.write_all(bytes).map_err(io_error(&path))?;
    Ok(path)
}

/// Writes a run's telemetry as CSV into the writer it is given.
pub(crate) type TelemetryWriter<'a> =
    dyn Fn(&mut dyn std::io::Write) -> Result<(), csv::Error> + 'a;

/// Creates `dir`, removes the known outputs not in `names`, and writes the telemetry (by
/// `telemetry`), the metrics of `report` (listing `names`), the `plots` (file name and SVG),
/// its replay and the page of all of them (`report.html`); returns their paths in that order.
pub(crate) fn write_files(
    report: &RunReport,
    world_warnings: &[String],
    dir: &Path,
    names: &[&str],
    plots: &[(&str, String)],
    telemetry: &TelemetryWriter<'_>,
) -> Result<Vec<PathBuf>, OutputError> {
    std::fs::create_dir_all(dir).map_err(io_error(dir))?;
    for stale in KNOWN_OUTPUTS.iter().filter(|n| !names.contains(n)) {
        let path = dir.join(stale);
        match std::fs::remove_file(&path) {
            Err(e) if e.kind() != std::io::ErrorKind::NotFound => return Err(io_error(&path)(e)),
            _ => {}
        }
    }
    let path = dir.join(TELEMETRY_CSV);
    let file = File::create(&path).map_err(io_error(&path))?;
    telemetry(&mut BufWriter::new(file)).map_err(|source| OutputError::Csv {
        path: path.clone(),
        source,
    })?;
    let metrics = to_json(report, world_warnings, names) + "\n";
    let mut written = vec![path, write_file(dir, METRICS_JSON, metrics.as_bytes())?];
    for (name, svg) in plots {
        written.push(write_file(dir, name, svg.as_bytes())?);
    }
    let (glb, car_nodes) = crate::replay::to_glb_and_cars(&report.replay_parts())
        .map_err(io_error(&dir.join(REPLAY_GLB)))?;
    written.push(write_file(dir, REPLAY_GLB, &glb)?);
    written.push(page::write_page(report, dir, plots, &glb, &car_nodes)?);
    Ok(written)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::{Metric, ScenarioResult};
    use crate::telemetry::{Sample, Telemetry};

    fn report() -> RunReport {
        RunReport {
            world: "w \"1\".toml".into(),
            vehicle: "BmwX5".into(),
            scenario: "brake".into(),
            results: vec![ScenarioResult {
                name: "brake".into(),
                metrics: vec![
                    Metric::number("stop_distance_m", "stopping distance", "m", 42.123_456_7),
                    Metric::maybe("stop_time_s", "stopping time", "s", None),
                    Metric::flag("at_rest", "at rest", true),
                    Metric::number("initial_speed_kmh", "speed", "km/h", 88.50999999999999),
                ],
                sim_seconds: 12.5,
                telemetry: vec![Telemetry {
                    scenario: "brake".into(),
                    samples: vec![Sample::default()],
                    ..Telemetry::default()
                }],
                notes: vec!["a note".into()],
                ..ScenarioResult::default()
            }],
            sim_seconds: 12.5,
            wall_seconds: 0.512_345,
            obstacles: Vec::new(),
        }
    }

    #[test]
    fn json_rounds_to_meaningful_digits_and_escapes_strings() {
        let j = to_json(&report(), &["warn\n".into()], &["telemetry.csv"]);
        // 42.1234567 has 6 significant digits kept, 88.50999999999999 reads 88.51; the wall
        // time 3, and the real-time factor 12.5 / 0.512345 = 24.397… reads 24.4.
        assert_eq!(
            j,
            "{\"world\":\"w \\\"1\\\".toml\",\"vehicle\":\"BmwX5\",\"scenario\":\"brake\",\
             \"sim_seconds\":12.5,\"wall_seconds\":0.512,\"realtime_factor\":24.4,\"scenarios\":\
             {\"brake\":{\"stop_distance_m\":42.1235,\"stop_time_s\":null,\"at_rest\":true,\
             \"initial_speed_kmh\":88.51,\"sim_seconds\":12.5}},\"files\":[\"telemetry.csv\"],\
             \"warnings\":[\"warn\\n\",\"a note\"]}"
        );
    }

    #[test]
    fn json_groups_per_vehicle_metrics() {
        let mut r = report();
        r.results[0].metrics = vec![
            Metric::number("distance_m", "distance", "m", 10.0).of("a"),
            Metric::number("distance_m", "distance", "m", 20.0).of("b"),
            Metric::flag("touched", "touched", false),
        ];
        let j: serde_json::Value = serde_json::from_str(&to_json(&r, &[], &[])).unwrap();
        let brake = &j["scenarios"]["brake"];
        assert_eq!(brake["vehicles"]["a"]["distance_m"], 10.0);
        assert_eq!(brake["vehicles"]["b"]["distance_m"], 20.0);
        assert_eq!(brake["touched"], false);
        let t = summary_table(&r);
        assert!(t.contains("b: distance"), "{t}");
    }

    #[test]
    fn significant_digits() {
        assert_eq!(significant(88.50999999999999, 6), 88.51);
        assert_eq!(significant(1234567.0, 3), 1230000.0);
        assert_eq!(significant(-0.0, 3).to_string(), "0");
        assert!(significant(f64::NAN, 3).is_nan());
    }

    #[test]
    fn summary_rows() {
        let t = summary_table(&report());
        assert!(
            t.contains("brake     stopping distance        42.12  m"),
            "{t}"
        );
        assert!(t.contains("stopping time"));
        assert!(t.contains("not reached"));
        assert!(t.contains("(24.40 x real time)"), "{t}");
        assert_eq!(format_value(Value::Number(7.123_456)), "7.123");
        assert_eq!(format_value(Value::Number(3.0)), "3");
        assert_eq!(format_value(Value::Bool(false)), "no");
        assert_eq!(format_value(Value::Number(-0.000_04)), "0.000");
    }

    #[test]
    #[cfg(feature = "app")]
    fn a_run_replaces_the_known_outputs_of_an_earlier_one() {
        let dir = std::env::temp_dir().join(format!("sim-report-stale-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).unwrap();
        // An earlier lane-change run left its plot; the user keeps notes beside it.
        std::fs::write(dir.join("lane_change.svg"), "old").unwrap();
        std::fs::write(dir.join("notes.txt"), "mine").unwrap();
        let written = write_outputs(&report(), &[], &dir).unwrap();
        let mut on_disk: Vec<String> = std::fs::read_dir(&dir)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        on_disk.sort();
        assert_eq!(
            on_disk,
            [
                "metrics.json",
                "notes.txt",
                "replay.glb",
                "report.html",
                "speed.svg",
                "telemetry.csv",
                "trajectory.svg"
            ]
        );
        let names: Vec<_> = written.iter().map(|p| p.file_name().unwrap()).collect();
        assert_eq!(names, output_names(&report()));
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
