//! `metrics.json`: a run's metrics, timings, files and warnings, numbers rounded to the
//! digits they mean.

use serde::ser::{Serialize, SerializeMap, Serializer};

use super::{METRIC_DIGITS, TIMING_DIGITS, significant};
use crate::scenario::{Metric, RunReport, ScenarioResult, Value};

/// A metric value in JSON: a number rounded to [`METRIC_DIGITS`], a boolean, or `null` for a
/// missing or non-finite one.
struct JsonValue(Value);

impl Serialize for JsonValue {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        match self.0 {
            Value::Number(x) if x.is_finite() => s.serialize_f64(significant(x, METRIC_DIGITS)),
            Value::Bool(b) => s.serialize_bool(b),
            Value::Number(_) | Value::Missing => s.serialize_none(),
        }
    }
}

/// Metrics as a JSON object, in display order.
struct JsonMetrics<'a>(Vec<&'a Metric>);

impl Serialize for JsonMetrics<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut map = s.serialize_map(Some(self.0.len()))?;
        for m in &self.0 {
            map.serialize_entry(m.key, &JsonValue(m.value))?;
        }
        map.end()
    }
}

/// A scenario's object: its run-wide metrics, `vehicles` (each vehicle's metrics) when it has
/// per-vehicle ones, `sim_seconds`, and `unfinished` (why) when it could not run to its end.
struct JsonResult<'a>(&'a ScenarioResult);

impl Serialize for JsonResult<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let r = self.0;
        let mut map = s.serialize_map(None)?;
        for m in r.metrics.iter().filter(|m| m.vehicle.is_none()) {
            map.serialize_entry(m.key, &JsonValue(m.value))?;
        }
        let mut vehicles: Vec<&str> = Vec::new();
        for v in r.metrics.iter().filter_map(|m| m.vehicle.as_deref()) {
            if !vehicles.contains(&v) {
                vehicles.push(v);
            }
        }
        if !vehicles.is_empty() {
            map.serialize_entry("vehicles", &JsonVehicles(r, vehicles))?;
        }
        map.serialize_entry("sim_seconds", &significant(r.sim_seconds, METRIC_DIGITS))?;
        if let Some(why) = &r.unfinished {
            map.serialize_entry("unfinished", why)?;
        }
        map.end()
    }
}

/// The per-vehicle metrics of a result, by vehicle name.
struct JsonVehicles<'a>(&'a ScenarioResult, Vec<&'a str>);

impl Serialize for JsonVehicles<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut map = s.serialize_map(Some(self.1.len()))?;
        for v in &self.1 {
            let metrics = self
                .0
                .metrics
                .iter()
                .filter(|m| m.vehicle.as_deref() == Some(*v))
                .collect();
            map.serialize_entry(v, &JsonMetrics(metrics))?;
        }
        map.end()
    }
}

/// The results by name, in run order.
struct JsonResults<'a>(&'a [ScenarioResult]);

impl Serialize for JsonResults<'_> {
    fn serialize<S: Serializer>(&self, s: S) -> Result<S::Ok, S::Error> {
        let mut map = s.serialize_map(Some(self.0.len()))?;
        for r in self.0 {
            map.serialize_entry(&r.name, &JsonResult(r))?;
        }
        map.end()
    }
}

/// The whole metrics document.
#[derive(serde::Serialize)]
struct JsonReport<'a> {
    world: &'a str,
    vehicle: &'a str,
    scenario: &'a str,
    sim_seconds: f64,
    wall_seconds: f64,
    realtime_factor: Option<f64>,
    scenarios: JsonResults<'a>,
    files: &'a [&'a str],
    warnings: Vec<&'a str>,
}

/// The metrics as one JSON object:
///
/// ```json
/// {"world": "<default world>", "vehicle": "BmwX5", "scenario": "brake",
///  "sim_seconds": 12.3, "wall_seconds": 0.8, "realtime_factor": 15.4,
///  "scenarios": {"brake": {"stop_distance_m": 42.1, …, "sim_seconds": 12.3}},
///  "files": ["telemetry.csv", …], "warnings": []}
/// ```
///
/// Metrics have [`METRIC_DIGITS`] significant digits, the timings [`TIMING_DIGITS`]. A metric
/// that was not reached is `null`; per-vehicle metrics (a programme's) are in the scenario's
/// `vehicles` object by vehicle name; `files` lists the files the run wrote (`files`);
/// `warnings` holds the world file's warnings (`world_warnings`) and the scenarios' notes.
pub fn to_json(report: &RunReport, world_warnings: &[String], files: &[&str]) -> String {
    let realtime = report.realtime_factor();
    let doc = JsonReport {
        world: &report.world,
        vehicle: &report.vehicle,
        scenario: &report.scenario,
        sim_seconds: significant(report.sim_seconds, METRIC_DIGITS),
        wall_seconds: significant(report.wall_seconds, TIMING_DIGITS),
        realtime_factor: realtime
            .is_finite()
            .then(|| significant(realtime, TIMING_DIGITS)),
        scenarios: JsonResults(&report.results),
        files,
        warnings: world_warnings
            .iter()
            .map(String::as_str)
            .chain(
                report
                    .results
                    .iter()
                    .flat_map(|r| r.notes.iter().map(String::as_str)),
            )
            .collect(),
    };
    // Serialising strings, numbers and booleans into memory cannot fail.
    serde_json::to_string(&doc).unwrap_or_default()
}
