//! What a run leaves behind: the summary table, the metrics as JSON, and the output directory
//! (telemetry CSV, SVG plots, JSON).

mod svg;

use std::fmt::Write as _;
use std::path::{Path, PathBuf};

pub use svg::{Figure, Panel, Series};

use vehicle_model::Wheel;

use crate::scenario::{RunReport, Scenario, Value};
use crate::telemetry::{Sample, write_csv};

/// A value for the summary table: three significant decimals at most, `yes`/`no`, or `n/a`.
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
        Value::Missing => "n/a".to_string(),
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
                r.scenario.name().to_string()
            } else {
                String::new()
            };
            rows.push([
                name,
                m.label.to_string(),
                format_value(m.value),
                m.unit.to_string(),
            ]);
        }
        rows.push([
            if r.metrics.is_empty() {
                r.scenario.name().to_string()
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

/// `s` as a JSON string literal.
fn json_string(s: &str) -> String {
    let mut out = String::with_capacity(s.len() + 2);
    out.push('"');
    for c in s.chars() {
        match c {
            '"' => out.push_str("\\\""),
            '\\' => out.push_str("\\\\"),
            '\n' => out.push_str("\\n"),
            '\r' => out.push_str("\\r"),
            '\t' => out.push_str("\\t"),
            c if u32::from(c) < 0x20 => {
                let _ = write!(out, "\\u{:04x}", u32::from(c));
            }
            c => out.push(c),
        }
    }
    out.push('"');
    out
}

/// A JSON number, or `null` for NaN and ±∞ (which JSON cannot represent).
fn json_number(x: f64) -> String {
    if x.is_finite() {
        format!("{x}")
    } else {
        "null".to_string()
    }
}

fn json_value(v: Value) -> String {
    match v {
        Value::Number(x) => json_number(x),
        Value::Bool(b) => b.to_string(),
        Value::Missing => "null".to_string(),
    }
}

/// The metrics as one JSON object:
///
/// ```json
/// {"world": "<default world>", "vehicle": "BmwX5", "scenario": "brake",
///  "sim_seconds": 12.3, "wall_seconds": 0.8, "realtime_factor": 15.4,
///  "scenarios": {"brake": {"stop_distance_m": 42.1, …, "sim_seconds": 12.3}},
///  "warnings": []}
/// ```
///
/// A metric that was not reached is `null`; `warnings` holds the world file's warnings
/// (`world_warnings`) and the scenarios' notes.
pub fn to_json(report: &RunReport, world_warnings: &[String]) -> String {
    let mut out = String::from("{");
    let _ = write!(
        out,
        "\"world\":{},\"vehicle\":{},\"scenario\":{},\"sim_seconds\":{},\"wall_seconds\":{},\
         \"realtime_factor\":{},\"scenarios\":{{",
        json_string(&report.world),
        json_string(&report.vehicle),
        json_string(report.scenario.name()),
        json_number(report.sim_seconds),
        json_number(report.wall_seconds),
        json_number(report.realtime_factor()),
    );
    for (i, r) in report.results.iter().enumerate() {
        if i > 0 {
            out.push(',');
        }
        let _ = write!(out, "{}:{{", json_string(r.scenario.name()));
        for m in &r.metrics {
            let _ = write!(out, "{}:{},", json_string(m.key), json_value(m.value));
        }
        let _ = write!(out, "\"sim_seconds\":{}}}", json_number(r.sim_seconds));
    }
    out.push_str("},\"warnings\":[");
    let notes = report.results.iter().flat_map(|r| r.notes.iter());
    for (i, w) in world_warnings.iter().chain(notes).enumerate() {
        if i > 0 {
            out.push(',');
        }
        out.push_str(&json_string(w));
    }
    out.push_str("]}");
    out
}

/// One series per scenario of `f(sample)` against time, skipping scenarios where `f` gives
/// nothing.
fn series(report: &RunReport, f: impl Fn(&Sample) -> Option<f64>) -> Vec<Series> {
    report
        .results
        .iter()
        .filter_map(|r| {
            let points: Vec<[f64; 2]> = r
                .telemetry
                .samples
                .iter()
                .filter_map(|s| f(s).map(|v| [s.time, v]))
                .collect();
            (!points.is_empty()).then(|| Series {
                name: r.scenario.name().to_string(),
                points,
            })
        })
        .collect()
}

/// The plots of a run, by file name: speed, rpm and gear, steering, the lane change and its
/// tyres' friction use, and the trajectory; a plot without data (e.g. rpm for a robot) is left
/// out.
pub fn figures(report: &RunReport) -> Vec<(&'static str, Figure)> {
    let title = |what: &str| format!("{what}: {}, {}", report.vehicle, report.scenario);
    let time = "time (s)".to_string();
    let mut out = Vec::new();
    out.push((
        "speed.svg",
        Figure {
            title: title("Speed"),
            x_label: time.clone(),
            panels: vec![Panel {
                y_label: "speed (km/h)".into(),
                series: series(report, |s| Some(s.speed_kmh)),
                steps: false,
                guides: Vec::new(),
            }],
            equal_aspect: false,
        },
    ));
    // Scenarios whose engine never turned (braking in neutral) would only add a flat line.
    let rpm: Vec<Series> = series(report, |s| s.rpm)
        .into_iter()
        .filter(|s| s.points.iter().any(|p| p[1] != 0.0))
        .collect();
    let engine_runs: Vec<&str> = rpm.iter().map(|s| s.name.as_str()).collect();
    let gears: Vec<Series> = series(report, |s| s.gear.map(f64::from))
        .into_iter()
        .filter(|s| engine_runs.contains(&s.name.as_str()))
        .collect();
    if !rpm.is_empty() {
        out.push((
            "rpm_gear.svg",
            Figure {
                title: title("Engine speed and gear"),
                x_label: time.clone(),
                panels: vec![
                    Panel {
                        y_label: "engine speed (rpm)".into(),
                        series: rpm,
                        steps: false,
                        guides: Vec::new(),
                    },
                    Panel {
                        y_label: "gear".into(),
                        series: gears,
                        steps: true,
                        guides: Vec::new(),
                    },
                ],
                equal_aspect: false,
            },
        ));
    }
    let turning = |s: &Sample| s.steering_command.is_some_and(|d| d != 0.0);
    let steered: Vec<_> = report
        .results
        .iter()
        .filter(|r| r.telemetry.samples.iter().any(turning))
        .collect();
    if !steered.is_empty() {
        let mut lines = Vec::new();
        for r in steered {
            for (what, f) in [
                (
                    "commanded",
                    (|s: &Sample| s.steering_command) as fn(&Sample) -> Option<f64>,
                ),
                ("measured", |s: &Sample| s.steering),
            ] {
                lines.push(Series {
                    name: format!("{} ({what})", r.scenario.name()),
                    points: r
                        .telemetry
                        .samples
                        .iter()
                        .filter_map(|s| f(s).map(|v| [s.time, v]))
                        .collect(),
                });
            }
        }
        out.push((
            "steering.svg",
            Figure {
                title: title("Steering angle (positive = right)"),
                x_label: time,
                panels: vec![Panel {
                    y_label: "steering angle (rad)".into(),
                    series: lines,
                    steps: false,
                    guides: Vec::new(),
                }],
                equal_aspect: false,
            },
        ));
    }
    if let Some(r) = report.result(Scenario::LaneChange) {
        out.push((
            "lane_change.svg",
            Figure {
                title: title("Double lane change, lateral scale exaggerated"),
                x_label: "x (m)".into(),
                panels: vec![Panel {
                    y_label: "y (m)".into(),
                    series: vec![Series {
                        name: "rear-axle centre".into(),
                        points: r.telemetry.samples.iter().map(|s| [s.x, s.y]).collect(),
                    }],
                    steps: false,
                    guides: r.guides.clone(),
                }],
                equal_aspect: false,
            },
        ));
    }
    if let Some(figure) = report.result(Scenario::LaneChange).and_then(|r| {
        friction_use(
            &r.telemetry.samples,
            title("Tyre friction use, double lane change"),
        )
    }) {
        out.push(("friction_use.svg", figure));
    }
    out.push((
        "trajectory.svg",
        Figure {
            title: title("Trajectory seen from above"),
            x_label: "x (m)".into(),
            panels: vec![Panel {
                y_label: "y (m)".into(),
                series: report
                    .results
                    .iter()
                    .map(|r| Series {
                        name: r.scenario.name().to_string(),
                        points: r.telemetry.samples.iter().map(|s| [s.x, s.y]).collect(),
                    })
                    .collect(),
                steps: false,
                guides: report
                    .results
                    .iter()
                    .flat_map(|r| r.guides.iter().cloned())
                    .collect(),
            }],
            equal_aspect: true,
        },
    ));
    out
}

/// The friction use (0–1) of each tyre against time, one line per wheel, with the grip limit
/// (1) as a guide; `None` for samples without tyres (a robot).
fn friction_use(samples: &[Sample], title: String) -> Option<Figure> {
    let names = ["front right", "front left", "rear right", "rear left"];
    let series: Vec<Series> = Wheel::ALL
        .into_iter()
        .zip(names)
        .map(|(w, name)| Series {
            name: name.to_string(),
            points: samples
                .iter()
                .filter_map(|s| s.tyres.map(|t| [s.time, t[w].friction_use]))
                .collect(),
        })
        .filter(|s| !s.points.is_empty())
        .collect();
    let span = series
        .first()
        .and_then(|s| Some([s.points.first()?[0], s.points.last()?[0]]))?;
    Some(Figure {
        title,
        x_label: "time (s)".into(),
        panels: vec![Panel {
            y_label: "friction use (0 to 1)".into(),
            series,
            steps: false,
            guides: vec![vec![[span[0], 1.0], [span[1], 1.0]]],
        }],
        equal_aspect: false,
    })
}

/// Writes `telemetry.csv`, `metrics.json`, the plots of [`figures`] and the 3D replay
/// `replay.glb` ([`crate::replay`]) into `dir` (created if needed) and returns the paths
/// written.
///
/// # Errors
/// The first I/O error, with the path it concerns.
pub fn write_outputs(
    report: &RunReport,
    world_warnings: &[String],
    dir: &Path,
) -> Result<Vec<PathBuf>, std::io::Error> {
    let annotate = |path: &Path, e: std::io::Error| {
        std::io::Error::new(e.kind(), format!("{}: {e}", path.display()))
    };
    std::fs::create_dir_all(dir).map_err(|e| annotate(dir, e))?;
    let mut written = Vec::new();
    let mut write = |name: &str, bytes: Vec<u8>| -> Result<(), std::io::Error> {
        let path = dir.join(name);
        std::fs::write(&path, bytes).map_err(|e| annotate(&path, e))?;
        written.push(path);
        Ok(())
    };
    write(
        "telemetry.csv",
        write_csv(report.results.iter().map(|r| &r.telemetry)).into(),
    )?;
    write(
        "metrics.json",
        (to_json(report, world_warnings) + "\n").into(),
    )?;
    for (name, figure) in figures(report) {
        write(name, figure.to_svg().into())?;
    }
    write("replay.glb", crate::replay::to_glb(report)?)?;
    Ok(written)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::TyreTelemetry;
    use crate::scenario::{Metric, ScenarioResult};
    use crate::telemetry::Telemetry;
    use vehicle_model::PerWheel;

    fn report() -> RunReport {
        RunReport {
            world: "w \"1\".toml".into(),
            vehicle: "BmwX5".into(),
            scenario: Scenario::Brake,
            results: vec![ScenarioResult {
                scenario: Scenario::Brake,
                metrics: vec![
                    Metric::number("stop_distance_m", "stopping distance", "m", 42.123_456),
                    Metric::maybe("stop_time_s", "stopping time", "s", None),
                    Metric::flag("at_rest", "at rest", true),
                ],
                sim_seconds: 12.5,
                telemetry: Telemetry {
                    scenario: "brake".into(),
                    samples: vec![Sample::default()],
                },
                notes: vec!["a note".into()],
                guides: Vec::new(),
                replay: Default::default(),
            }],
            sim_seconds: 12.5,
            wall_seconds: 0.5,
        }
    }

    #[test]
    fn json_has_every_metric_and_escapes_strings() {
        let j = to_json(&report(), &["warn\n".into()]);
        assert_eq!(
            j,
            "{\"world\":\"w \\\"1\\\".toml\",\"vehicle\":\"BmwX5\",\"scenario\":\"brake\",\
             \"sim_seconds\":12.5,\"wall_seconds\":0.5,\"realtime_factor\":25,\"scenarios\":\
             {\"brake\":{\"stop_distance_m\":42.123456,\"stop_time_s\":null,\"at_rest\":true,\
             \"sim_seconds\":12.5}},\"warnings\":[\"warn\\n\",\"a note\"]}"
        );
    }

    #[test]
    fn friction_use_has_one_labelled_line_per_tyre() {
        let tyres = PerWheel::from_fn(|w| TyreTelemetry {
            friction_use: if w.is_front() { 0.5 } else { 0.25 },
            ..TyreTelemetry::default()
        });
        let samples: Vec<Sample> = (0..3)
            .map(|i| Sample {
                time: 0.01 * f64::from(i),
                tyres: Some(tyres),
                ..Sample::default()
            })
            .collect();
        let f = friction_use(&samples, "t".into()).unwrap();
        let panel = &f.panels[0];
        let names: Vec<&str> = panel.series.iter().map(|s| s.name.as_str()).collect();
        assert_eq!(
            names,
            ["front right", "front left", "rear right", "rear left"]
        );
        assert_eq!(
            panel.series[0].points,
            [[0.0, 0.5], [0.01, 0.5], [0.02, 0.5]]
        );
        assert_eq!(panel.series[3].points[2], [0.02, 0.25]);
        assert_eq!(panel.guides, [vec![[0.0, 1.0], [0.02, 1.0]]]);
        // A robot has no tyres.
        assert_eq!(friction_use(&[Sample::default()], "t".into()), None);
    }

    #[test]
    fn summary_rows() {
        let t = summary_table(&report());
        assert!(t.contains("brake     stopping distance  42.12  m"), "{t}");
        assert!(t.contains("stopping time"));
        assert!(t.contains("n/a"));
        assert!(t.contains("(25 x real time)"));
        assert_eq!(format_value(Value::Number(7.123_456)), "7.123");
        assert_eq!(format_value(Value::Number(3.0)), "3");
        assert_eq!(format_value(Value::Bool(false)), "no");
        assert_eq!(format_value(Value::Number(-0.000_04)), "0.000");
    }
}
