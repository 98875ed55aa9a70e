//! `report.html`: one self-contained page of a run that opens offline in a browser. It holds
//! the metrics table, the run's SVG plots inline, and an interactive 3D viewer of the run's
//! `replay.glb` (embedded as base64) with its telemetry (embedded as JSON, thinned to at most
//! [`MAX_PAGE_ROWS`] rows per scenario and vehicle so that the page stays a few MB whatever the
//! run's length).
//!
//! The viewer is our own script (`page/viewer.js`, readable) on three.js with its GLTFLoader
//! and OrbitControls addons, vendored as one minified bundle (`sim/vendor/three`, pinned by
//! its `package.json`, rebuilt and checked by its `vendor.sh`); both are compiled in with
//! `include_str!`, so a machine with only Rust writes the page.

use std::fs::File;
use std::io::{BufReader, Write as _};
use std::path::{Path, PathBuf};

use base64::Engine as _;

use super::{OutputError, TELEMETRY_CSV, format_value, io_error};
use crate::replay::{self, CarNode};
use crate::scenario::{RunReport, Value};

/// The file name of the page.
pub const REPORT_HTML: &str = "report.html";

/// Most telemetry rows the page holds per scenario and vehicle: a longer series keeps every
/// k-th row (and its last), k the smallest whole number that fits. 2,000 rows of the
/// [`PAGE_COLUMNS`] are about 150 kB of JSON, so the test track's five scenarios stay under
/// 1 MB; the telemetry CSV keeps every row.
pub const MAX_PAGE_ROWS: usize = 2_000;

/// The telemetry columns the viewer shows (names of `telemetry.csv`'s header).
pub const PAGE_COLUMNS: [&str; 12] = [
    "time_s",
    "x_m",
    "y_m",
    "yaw_rad",
    "speed_kmh",
    "rpm",
    "gear",
    "steering_rad",
    "throttle",
    "brake",
    "lateral_accel_mps2",
    "longitudinal_accel_mps2",
];

const TEMPLATE: &str = include_str!("page/report.html");
const VIEWER_JS: &str = include_str!("page/viewer.js");
const THREE_JS: &str = include_str!("../../vendor/three/three-viewer.min.js");
const THREE_LICENCE: &str = include_str!("../../vendor/three/LICENSE.three");

/// One vehicle's rows of one scenario, thinned.
#[derive(serde::Serialize)]
struct Series {
    scenario: String,
    car: String,
    rows: Vec<Vec<Option<f64>>>,
}

/// A car of the replay as the viewer finds it.
#[derive(serde::Serialize)]
struct PageCar {
    /// The car's name (its glTF root node's name, which a loader may change: messages only).
    node: String,
    /// The glTF node index of its root, which the viewer follows.
    root: usize,
    /// The glTF node index of its body, whose visible mesh the camera aims at.
    body: usize,
    /// Its body colour (linear RGB, 0–1), the material's base colour.
    colour: [f32; 3],
}

/// Everything the viewer reads, as one JSON document.
#[derive(serde::Serialize)]
struct PageData<'a> {
    world: &'a str,
    vehicle: &'a str,
    scenario: &'a str,
    parts: Vec<&'a str>,
    cars: Vec<PageCar>,
    columns: [&'static str; 12],
    max_rows: usize,
    series: Vec<Series>,
}

/// Writes `report.html` into `dir` for `report`, whose `telemetry.csv` is already in `dir`,
/// with the `plots` (file name and SVG), the replay `glb` and its cars' nodes (`car_nodes`,
/// in the order of the first part's cars); returns its path.
///
/// # Errors
/// The first I/O or CSV error, with the path it concerns.
pub(crate) fn write_page(
    report: &RunReport,
    dir: &Path,
    plots: &[(&str, String)],
    glb: &[u8],
    car_nodes: &[CarNode],
) -> Result<PathBuf, OutputError> {
    let series = thinned_telemetry(&dir.join(TELEMETRY_CSV))?;
    let cars = report
        .results
        .first()
        .map_or(&[][..], |r| &r.replay.cars[..]);
    let data = PageData {
        world: &report.world,
        vehicle: &report.vehicle,
        scenario: &report.scenario,
        parts: report.results.iter().map(|r| r.name.as_str()).collect(),
        cars: cars
            .iter()
            .zip(car_nodes)
            .enumerate()
            .map(|(i, (car, nodes))| PageCar {
                node: car.name.clone(),
                root: nodes.root,
                body: nodes.body,
                colour: replay::car_colour(i),
            })
            .collect(),
        columns: PAGE_COLUMNS,
        max_rows: MAX_PAGE_ROWS,
        series,
    };
    // Serialising strings, numbers and options into memory cannot fail. `</` is escaped so
    // that no string can close the script element holding the JSON.
    let json = serde_json::to_string(&data)
        .unwrap_or_default()
        .replace("</", "<\\/");
    let glb = base64::engine::general_purpose::STANDARD.encode(glb);
    let html = fill(
        TEMPLATE,
        &[
            ("title", &escape(&title(report))),
            ("metrics", &metrics_table(report)),
            ("plots", &plot_figures(plots)),
            ("three_licence", THREE_LICENCE),
            ("three", THREE_JS),
            ("viewer", VIEWER_JS),
            ("data", &json),
            ("glb", &glb),
        ],
    );
    let path = dir.join(REPORT_HTML);
    let mut file = File::create(&path).map_err(io_error(&path))?;
    file.write_all(html.as_bytes()).map_err(io_error(&path))?;
    Ok(path)
}

/// `template` with each `{{name}}` replaced by its value in `values`, in one pass, so that a
/// value (a world's name, a plot) holding such a mark is never filled in itself.
fn fill(template: &str, values: &[(&str, &str)]) -> String {
    let mut out =
        String::with_capacity(template.len() + values.iter().map(|(_, v)| v.len()).sum::<usize>());
    let mut rest = template;
    while let Some(start) = rest.find("{{") {
        let (before, mark) = rest.split_at(start);
        out.push_str(before);
        let value = mark.find("}}").and_then(|end| {
            let name = &mark[2..end];
            values
                .iter()
                .find(|(n, _)| *n == name)
                .map(|(_, v)| (*v, end + 2))
        });
        match value {
            Some((v, len)) => {
                out.push_str(v);
                rest = &mark[len..];
            }
            None => {
                out.push_str("{{");
                rest = &mark[2..];
            }
        }
    }
    out.push_str(rest);
    out
}

/// The page's title: what ran where.
fn title(report: &RunReport) -> String {
    format!(
        "vehicle-sim: {} in {}, scenario {}",
        report.vehicle, report.world, report.scenario
    )
}

/// `s` with the five characters HTML gives a meaning escaped.
fn escape(s: &str) -> String {
    let mut out = String::with_capacity(s.len());
    for c in s.chars() {
        match c {
            '&' => out.push_str("&amp;"),
            '<' => out.push_str("&lt;"),
            '>' => out.push_str("&gt;"),
            '"' => out.push_str("&quot;"),
            '\'' => out.push_str("&#39;"),
            c => out.push(c),
        }
    }
    out
}

/// The metrics as an HTML table body: one row per metric, then each scenario's simulated time.
fn metrics_table(report: &RunReport) -> String {
    let mut rows = String::new();
    let mut row = |scenario: &str, label: &str, value: Value, unit: &str| {
        rows.push_str(&format!(
            "<tr><td>{}</td><td>{}</td><td class=\"num\">{}</td><td>{}</td></tr>\n",
            escape(scenario),
            escape(label),
            escape(&format_value(value)),
            escape(unit)
        ));
    };
    for r in &report.results {
        for m in &r.metrics {
            let label = match &m.vehicle {
                Some(v) => format!("{v}: {}", m.label),
                None => m.label.to_string(),
            };
            row(&r.name, &label, m.value, m.unit);
        }
        row(&r.name, "simulated time", Value::Number(r.sim_seconds), "s");
    }
    rows
}

/// Each plot as a figure with its file name as caption, the SVG inline.
fn plot_figures(plots: &[(&str, String)]) -> String {
    plots
        .iter()
        .map(|(name, svg)| {
            // An XML declaration is not allowed inside HTML.
            let svg = match svg.find("<svg") {
                Some(start) => &svg[start..],
                None => svg.as_str(),
            };
            format!(
                "<figure>{svg}<figcaption>{}</figcaption></figure>\n",
                escape(name)
            )
        })
        .collect()
}

/// The page's columns of the telemetry CSV at `path`, at most [`MAX_PAGE_ROWS`] rows per run of
/// consecutive rows of one scenario and vehicle. The file is read twice, as a stream (the
/// first pass counts the rows), so a run of any length costs no more memory than the page.
fn thinned_telemetry(path: &Path) -> Result<Vec<Series>, OutputError> {
    let csv_error = |source| OutputError::Csv {
        path: path.to_path_buf(),
        source,
    };
    let open = || -> Result<csv::Reader<BufReader<File>>, OutputError> {
        let file = File::open(path).map_err(io_error(path))?;
        Ok(csv::Reader::from_reader(BufReader::new(file)))
    };
    // Pass 1: the length of each run of rows.
    let mut lengths: Vec<usize> = Vec::new();
    let mut key: Option<(String, String)> = None;
    let mut reader = open()?;
    for record in reader.records() {
        let record = record.map_err(csv_error)?;
        let k = (
            record.get(0).unwrap_or("").to_string(),
            record.get(1).unwrap_or("").to_string(),
        );
        if key.as_ref() == Some(&k) {
            if let Some(n) = lengths.last_mut() {
                *n += 1;
            }
        } else {
            lengths.push(1);
            key = Some(k);
        }
    }
    // Pass 2: every k-th row of each run, and its last.
    let mut reader = open()?;
    let header = reader.headers().map_err(csv_error)?.clone();
    let columns: Vec<Option<usize>> = PAGE_COLUMNS
        .iter()
        .map(|c| header.iter().position(|h| h == *c))
        .collect();
    let mut out: Vec<Series> = Vec::new();
    let mut index = 0;
    for record in reader.records() {
        let record = record.map_err(csv_error)?;
        let (scenario, car) = (record.get(0).unwrap_or(""), record.get(1).unwrap_or(""));
        let same = out
            .last()
            .is_some_and(|s| s.scenario == scenario && s.car == car && index > 0);
        if !same {
            out.push(Series {
                scenario: scenario.to_string(),
                car: car.to_string(),
                rows: Vec::new(),
            });
            index = 0;
        }
        let length = lengths.get(out.len() - 1).copied().unwrap_or(1);
        let stride = length.div_ceil(MAX_PAGE_ROWS).max(1);
        if index % stride == 0 || index + 1 == length {
            let row = columns
                .iter()
                .map(|c| {
                    c.and_then(|c| record.get(c))
                        .and_then(|v| v.parse::<f64>().ok())
                        .filter(|v| v.is_finite())
                })
                .collect();
            if let Some(s) = out.last_mut() {
                s.rows.push(row);
            }
        }
        index += 1;
        if index == length {
            // The next row starts a new run even if it has the same names.
            index = 0;
        }
    }
    Ok(out)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fills_each_mark_once() {
        let page = fill("<{{a}}|{{b}}|{{c}}", &[("a", "{{b}}"), ("b", "x")]);
        assert_eq!(page, "<{{b}}|x|{{c}}");
    }

    #[test]
    fn escapes_markup() {
        assert_eq!(escape("a<b & \"c\"'"), "a&lt;b &amp; &quot;c&quot;&#39;");
    }

    #[test]
    fn the_bundle_cannot_end_its_script_element() {
        // The bundle and our viewer are inlined in <script> elements.
        assert!(!THREE_JS.contains("</script"));
        assert!(!VIEWER_JS.contains("</script"));
        assert!(!THREE_LICENCE.contains("*/"));
    }

    #[test]
    fn long_series_are_thinned_to_the_cap_with_their_last_row() {
        let dir = std::env::temp_dir().join(format!("sim-page-thin-{}", std::process::id()));
        std::fs::create_dir_all(&dir).unwrap();
        let path = dir.join(TELEMETRY_CSV);
        // 5,001 rows of one car, then 3 of another: strides 3 (5001 / 2000 rounded up) and 1.
        let mut csv = String::from("scenario,car,time_s,x_m\n");
        for i in 0..5001 {
            csv.push_str(&format!("a,one,{i},1\n"));
        }
        for i in 0..3 {
            csv.push_str(&format!("a,two,{i},2\n"));
        }
        std::fs::write(&path, csv).unwrap();
        let series = thinned_telemetry(&path).unwrap();
        assert_eq!(series.len(), 2);
        // Rows 0, 3, ..., 4998 (1,667 of them) and the last, 5000.
        assert_eq!(series[0].rows.len(), 1668);
        assert!(series[0].rows.len() <= MAX_PAGE_ROWS);
        assert_eq!(series[0].rows.last().unwrap()[0], Some(5000.0));
        assert_eq!(series[0].rows[1][0], Some(3.0));
        // A column the file lacks is null.
        assert_eq!(series[0].rows[0][4], None);
        assert_eq!(series[1].rows.len(), 3);
        std::fs::remove_dir_all(&dir).unwrap();
    }
}
