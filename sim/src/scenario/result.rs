//! What a run measured: metrics and their values, each scenario's result with its
//! telemetry, and the whole run's report.

use crate::config::Outline;
use crate::replay::{Part, Recording};
use crate::telemetry::{DeviceReadings, Telemetry};

/// A metric's value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Value {
    /// A number in the metric's unit.
    Number(f64),
    /// A yes/no outcome.
    Bool(bool),
    /// Not measured: the event did not happen within the time limit (the result's
    /// [`ScenarioResult::unfinished`] says why).
    Missing,
}

impl Value {
    /// The number, if any.
    pub fn as_f64(self) -> Option<f64> {
        match self {
            Value::Number(v) => Some(v),
            _ => None,
        }
    }
}

/// A measured result of a scenario.
#[derive(Debug, Clone, PartialEq)]
pub struct Metric {
    /// Key in the JSON output, unit suffixed (e.g. `time_0_100_s`).
    pub key: &'static str,
    /// What it is, for the summary table.
    pub label: &'static str,
    /// Unit for the summary table (`""` for none).
    pub unit: &'static str,
    /// The value.
    pub value: Value,
    /// The vehicle it is about, by name, when a run drives several (`None`: the run's one
    /// vehicle, or the run as a whole).
    pub vehicle: Option<String>,
}

impl Metric {
    /// A number in `unit` under `key` (unit-suffixed, e.g. `distance_m`) with a table `label`.
    pub const fn number(
        key: &'static str,
        label: &'static str,
        unit: &'static str,
        v: f64,
    ) -> Self {
        Metric {
            key,
            label,
            unit,
            value: Value::Number(v),
            vehicle: None,
        }
    }

    /// A number, or [`Value::Missing`] for `None` or a non-finite value.
    pub fn maybe(
        key: &'static str,
        label: &'static str,
        unit: &'static str,
        v: Option<f64>,
    ) -> Self {
        Metric {
            key,
            label,
            unit,
            value: v
                .filter(|v| v.is_finite())
                .map_or(Value::Missing, Value::Number),
            vehicle: None,
        }
    }

    /// A yes/no outcome.
    pub const fn flag(key: &'static str, label: &'static str, v: bool) -> Self {
        Metric {
            key,
            label,
            unit: "",
            value: Value::Bool(v),
            vehicle: None,
        }
    }

    /// A yes/no outcome, or [`Value::Missing`] for `None` (the run ended before it was
    /// decided).
    pub fn maybe_flag(key: &'static str, label: &'static str, v: Option<bool>) -> Self {
        Metric {
            key,
            label,
            unit: "",
            value: v.map_or(Value::Missing, Value::Bool),
            vehicle: None,
        }
    }

    /// The same metric about the vehicle named `vehicle`.
    pub fn of(mut self, vehicle: &str) -> Self {
        self.vehicle = Some(vehicle.to_string());
        self
    }
}

/// The outcome of one single scenario, or of any run driven through the public API.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct ScenarioResult {
    /// Its name (a [`Scenario::name`](super::Scenario::name) or any other, e.g. `"my-route"`).
    pub name: String,
    /// The measured results, in display order.
    pub metrics: Vec<Metric>,
    /// Simulated time (s).
    pub sim_seconds: f64,
    /// Every vehicle's samples (from time 0, then one per step).
    pub telemetry: Vec<Telemetry>,
    /// Messages the run produced (e.g. a driver warning), for stderr.
    pub notes: Vec<String>,
    /// Lines of the course drawn under the trajectory (m, world frame), e.g. the lane edges of
    /// the lane change.
    pub guides: Vec<Vec<[f64; 2]>>,
    /// Cones of the course (m, world frame), drawn as markers.
    pub cones: Vec<[f64; 2]>,
    /// The run sampled for its 3D replay.
    pub replay: Recording,
    /// The readings of the devices the run sampled, for `devices.csv`: those the world
    /// enables with `samplingPeriod`, in the `programme` scenario and the car scenarios alike
    /// (empty when none is enabled, and for the robot scenarios, whose robot has no devices).
    pub devices: DeviceReadings,
    /// Why the scenario could not run to its end, when it could not (e.g. a `--duration` that
    /// ended before braking started): the metrics of what never happened are
    /// [`Value::Missing`] or absent, and `vehicle-sim` exits with
    /// [`EXIT_UNFINISHED`](crate::cli::EXIT_UNFINISHED).
    pub unfinished: Option<String>,
}

impl ScenarioResult {
    /// A result named `name` with `telemetry`, lasting the last sample's time; no metrics,
    /// notes, guides or cones yet.
    pub fn new(name: &str, telemetry: Vec<Telemetry>) -> Self {
        let sim_seconds = telemetry
            .iter()
            .filter_map(|t| t.samples.last().map(|s| s.time))
            .fold(0.0, f64::max);
        ScenarioResult {
            name: name.to_string(),
            sim_seconds,
            telemetry,
            ..ScenarioResult::default()
        }
    }

    /// The first metric `key`, if the scenario reports it.
    pub fn metric(&self, key: &str) -> Option<Value> {
        self.metrics.iter().find(|m| m.key == key).map(|m| m.value)
    }

    /// The metric `key` of the vehicle named `vehicle`.
    pub fn metric_of(&self, vehicle: &str, key: &str) -> Option<Value> {
        self.metrics
            .iter()
            .find(|m| m.key == key && m.vehicle.as_deref() == Some(vehicle))
            .map(|m| m.value)
    }
}

/// The outcome of a `vehicle-sim` run, or of any run put together through the public API.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct RunReport {
    /// Where the world came from.
    pub world: String,
    /// What drove: the car model, `DifferentialWheels`, or the vehicles by name.
    pub vehicle: String,
    /// The scenario asked for, by name.
    pub scenario: String,
    /// One result per single scenario run.
    pub results: Vec<ScenarioResult>,
    /// Total simulated time (s).
    pub sim_seconds: f64,
    /// Wall-clock time of the simulation (s).
    pub wall_seconds: f64,
    /// The world's boxes, ramps and dynamic boxes (at their start), seen from above.
    pub obstacles: Vec<Outline>,
}

impl RunReport {
    /// The replay's parts: one per scenario run, named after it, with its course's guides
    /// ([`replay::to_glb`](crate::replay::to_glb) writes them).
    pub fn replay_parts(&self) -> Vec<Part<'_>> {
        self.results
            .iter()
            .map(|r| Part {
                name: &r.name,
                recording: &r.replay,
                guides: &r.guides,
            })
            .collect()
    }

    /// Simulated seconds per wall-clock second (∞ for an instantaneous run).
    pub fn realtime_factor(&self) -> f64 {
        if self.wall_seconds > 0.0 {
            self.sim_seconds / self.wall_seconds
        } else {
            f64::INFINITY
        }
    }

    /// The result named `name`, if it ran.
    pub fn result(&self, name: &str) -> Option<&ScenarioResult> {
        self.results.iter().find(|r| r.name == name)
    }
}
