//! Driving programmes and their metrics: what `vehicle-sim --scenario` runs.
//!
//! A car is driven only through the [`vehicle_model::Driver`] API, exactly as a Webots
//! controller drives it with `wbu_driver_*`: each step the programme sets its commands, the
//! driver turns the sensor readings into actuator commands, and the world advances one
//! `basicTimeStep`. A DifferentialWheels robot is driven through
//! [`DifferentialWheels::set_speed`](crate::DifferentialWheels::set_speed)
//! (`wb_differential_wheels_set_speed`).
//!
//! | scenario | vehicle | what it does | metrics |
//! |---|---|---|---|
//! | `accel-speed` | car | cruise control to 100 km/h from rest | `time_0_100_s` |
//! | `accel-torque` | car | full throttle, automatic gearbox | `time_0_100_s`, `top_gear`, `max_rpm` |
//! | `brake` | car | brake intensity 1 from 100 km/h | `stop_distance_m`, `stop_time_s` |
//! | `circle` | car | steering 0.2 rad at 10 km/h | `turn_radius_m` vs `turn_radius_expected_m` |
//! | `lane-change` | car | ISO 3888-1-like double lane change at 60 km/h | `max_lateral_accel_mps2`, `left_track` |
//! | `test-track` | car | all five above, each on a fresh world | all of the above |
//! | `square` | robot | a square of side 10 × `axleLength`, open loop | final pose, `closure_error_m` |
//! | `spin` | robot | turns on the spot for 10 s | final pose, `turns` |

mod car;
mod car_programmes;
mod fit;
mod lane;
mod robot;

use core::fmt;
use std::time::Instant;

pub use fit::{Circle, fit_circle};
pub use lane::{LaneSection, double_lane_change};

use crate::error::SimError;
use crate::replay::Recording;
use crate::telemetry::Telemetry;
use crate::world_file::{WorldDescription, WorldVehicle};

/// A driving programme.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Scenario {
    /// Cruise control to 100 km/h from rest.
    AccelSpeed,
    /// Full throttle from rest with automatic gear changes.
    AccelTorque,
    /// Full braking from 100 km/h.
    Brake,
    /// Constant steering at low speed.
    Circle,
    /// A double lane change at 60 km/h.
    LaneChange,
    /// Every car scenario in turn.
    TestTrack,
    /// A DifferentialWheels robot drives a square.
    Square,
    /// A DifferentialWheels robot turns on the spot.
    Spin,
}

impl Scenario {
    /// Every scenario.
    pub const ALL: [Scenario; 8] = [
        Scenario::AccelSpeed,
        Scenario::AccelTorque,
        Scenario::Brake,
        Scenario::Circle,
        Scenario::LaneChange,
        Scenario::TestTrack,
        Scenario::Square,
        Scenario::Spin,
    ];

    /// The scenarios `test-track` runs, in order.
    pub const TEST_TRACK: [Scenario; 5] = [
        Scenario::AccelSpeed,
        Scenario::AccelTorque,
        Scenario::Brake,
        Scenario::Circle,
        Scenario::LaneChange,
    ];

    /// The command-line name, e.g. `"accel-speed"`.
    pub const fn name(self) -> &'static str {
        match self {
            Scenario::AccelSpeed => "accel-speed",
            Scenario::AccelTorque => "accel-torque",
            Scenario::Brake => "brake",
            Scenario::Circle => "circle",
            Scenario::LaneChange => "lane-change",
            Scenario::TestTrack => "test-track",
            Scenario::Square => "square",
            Scenario::Spin => "spin",
        }
    }

    /// The scenario named `name`, or `None`.
    pub fn from_name(name: &str) -> Option<Scenario> {
        Scenario::ALL.into_iter().find(|s| s.name() == name)
    }

    /// One line on what it does.
    pub const fn description(self) -> &'static str {
        match self {
            Scenario::AccelSpeed => "cruise control to 100 km/h from rest",
            Scenario::AccelTorque => "full throttle from rest, automatic gearbox",
            Scenario::Brake => "brake intensity 1 from 100 km/h to a stop",
            Scenario::Circle => "steering 0.2 rad at 10 km/h: turn radius vs L/tan(delta)",
            Scenario::LaneChange => "ISO 3888-1-like double lane change (3.5 m) at 60 km/h",
            Scenario::TestTrack => "all five car scenarios in turn",
            Scenario::Square => "DifferentialWheels: drive a square, open loop",
            Scenario::Spin => "DifferentialWheels: turn on the spot for 10 s",
        }
    }

    /// True for the scenarios of a car, false for those of a DifferentialWheels robot.
    pub const fn is_for_car(self) -> bool {
        !matches!(self, Scenario::Square | Scenario::Spin)
    }

    /// What `vehicle-sim` runs on `world` without `--scenario`: `test-track` for a car,
    /// `square` for a robot.
    pub fn default_for(world: &WorldDescription) -> Scenario {
        match world.vehicle {
            WorldVehicle::Car(_) => Scenario::TestTrack,
            WorldVehicle::DifferentialWheels(_) => Scenario::Square,
        }
    }

    /// The single scenarios this one runs (itself, or the five of `test-track`).
    pub fn parts(self) -> Vec<Scenario> {
        if self == Scenario::TestTrack {
            Scenario::TEST_TRACK.to_vec()
        } else {
            vec![self]
        }
    }

    /// The simulated time the scenario may take at most (s); it usually ends earlier.
    pub(crate) const fn time_limit(self) -> f64 {
        match self {
            Scenario::AccelSpeed | Scenario::AccelTorque => 60.0,
            Scenario::Brake => 90.0,
            Scenario::Circle => 90.0,
            Scenario::LaneChange => 60.0,
            Scenario::TestTrack => 360.0,
            Scenario::Square => 600.0,
            Scenario::Spin => 10.0,
        }
    }
}

impl fmt::Display for Scenario {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.name())
    }
}

/// A metric's value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Value {
    /// A number in the metric's unit.
    Number(f64),
    /// A yes/no outcome.
    Bool(bool),
    /// Not measured: the event did not happen within the time limit.
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
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Metric {
    /// Key in the JSON output, unit suffixed (e.g. `time_0_100_s`).
    pub key: &'static str,
    /// What it is, for the summary table.
    pub label: &'static str,
    /// Unit for the summary table (`""` for none).
    pub unit: &'static str,
    /// The value.
    pub value: Value,
}

impl Metric {
    pub(crate) const fn number(
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
        }
    }

    pub(crate) fn maybe(
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
        }
    }

    pub(crate) const fn flag(key: &'static str, label: &'static str, v: bool) -> Self {
        Metric {
            key,
            label,
            unit: "",
            value: Value::Bool(v),
        }
    }
}

/// The outcome of one single scenario.
#[derive(Debug, Clone, PartialEq)]
pub struct ScenarioResult {
    /// Which.
    pub scenario: Scenario,
    /// The measured results, in display order.
    pub metrics: Vec<Metric>,
    /// Simulated time (s).
    pub sim_seconds: f64,
    /// Every step's sample.
    pub telemetry: Telemetry,
    /// Messages the run produced (e.g. a driver warning), for stderr.
    pub notes: Vec<String>,
    /// Lines of the course drawn under the trajectory (m, world frame), e.g. the cone lines of
    /// the lane change.
    pub guides: Vec<Vec<[f64; 2]>>,
    /// The run sampled for its 3D replay.
    pub replay: Recording,
}

impl ScenarioResult {
    /// The metric `key`, if the scenario reports it.
    pub fn metric(&self, key: &str) -> Option<Value> {
        self.metrics.iter().find(|m| m.key == key).map(|m| m.value)
    }
}

/// The outcome of a `vehicle-sim` run.
#[derive(Debug, Clone, PartialEq)]
pub struct RunReport {
    /// Where the world came from.
    pub world: String,
    /// What drove: the car model, or `DifferentialWheels`.
    pub vehicle: String,
    /// The scenario asked for.
    pub scenario: Scenario,
    /// One result per single scenario run.
    pub results: Vec<ScenarioResult>,
    /// Total simulated time (s).
    pub sim_seconds: f64,
    /// Wall-clock time of the simulation (s).
    pub wall_seconds: f64,
}

impl RunReport {
    /// Simulated seconds per wall-clock second (∞ for an instantaneous run).
    pub fn realtime_factor(&self) -> f64 {
        if self.wall_seconds > 0.0 {
            self.sim_seconds / self.wall_seconds
        } else {
            f64::INFINITY
        }
    }

    /// The result of `scenario`, if it ran.
    pub fn result(&self, scenario: Scenario) -> Option<&ScenarioResult> {
        self.results.iter().find(|r| r.scenario == scenario)
    }
}

/// Why a scenario could not run.
#[derive(Debug, Clone, PartialEq)]
#[non_exhaustive]
pub enum ScenarioError {
    /// The scenario is for the other kind of vehicle.
    WrongVehicle {
        /// The scenario asked for.
        scenario: Scenario,
        /// What the world holds.
        vehicle: &'static str,
    },
    /// The simulator refused the world or diverged.
    Sim(SimError),
}

impl fmt::Display for ScenarioError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match self {
            ScenarioError::WrongVehicle { scenario, vehicle } => {
                let wanted = if scenario.is_for_car() {
                    "a car"
                } else {
                    "a DifferentialWheels robot"
                };
                write!(
                    f,
                    "scenario '{scenario}' needs {wanted}, but the world holds a {vehicle}"
                )
            }
            ScenarioError::Sim(e) => write!(f, "simulation failed: {e}"),
        }
    }
}

impl std::error::Error for ScenarioError {
    fn source(&self) -> Option<&(dyn std::error::Error + 'static)> {
        match self {
            ScenarioError::Sim(e) => Some(e),
            ScenarioError::WrongVehicle { .. } => None,
        }
    }
}

impl From<SimError> for ScenarioError {
    fn from(e: SimError) -> Self {
        ScenarioError::Sim(e)
    }
}

/// Where a run is, for a progress display.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Progress {
    /// The single scenario running.
    pub scenario: Scenario,
    /// Its position among the run's scenarios (0-based) and their number.
    pub index: usize,
    /// Number of single scenarios in the run.
    pub count: usize,
    /// Simulated time in this scenario (s).
    pub time: f64,
    /// Estimated fraction of the whole run done, in [0, 1].
    pub fraction: f64,
}

/// The simulated time (s) a single scenario may take on `world`: its own limit, cut to the
/// world's `duration` if that is shorter.
pub(crate) fn limit(scenario: Scenario, world: &WorldDescription) -> f64 {
    world
        .duration
        .map_or(scenario.time_limit(), |d| d.min(scenario.time_limit()))
}

/// Runs `scenario` on `world`, calling `progress` every few simulated seconds.
///
/// # Errors
/// [`ScenarioError::WrongVehicle`] for a car scenario in a robot world (or the reverse), and
/// [`ScenarioError::Sim`] if the world cannot be built or the simulation diverges.
pub fn run(
    world: &WorldDescription,
    scenario: Scenario,
    progress: &mut dyn FnMut(Progress),
) -> Result<RunReport, ScenarioError> {
    if scenario.is_for_car() != matches!(world.vehicle, WorldVehicle::Car(_)) {
        return Err(ScenarioError::WrongVehicle {
            scenario,
            vehicle: world.vehicle_name(),
        });
    }
    let start = Instant::now();
    let parts = scenario.parts();
    let count = parts.len();
    let mut results = Vec::with_capacity(count);
    for (index, part) in parts.into_iter().enumerate() {
        let mut report = |time: f64, expected: f64| {
            let within = if expected > 0.0 {
                (time / expected).min(1.0)
            } else {
                1.0
            };
            progress(Progress {
                scenario: part,
                index,
                count,
                time,
                fraction: (index as f64 + within) / count as f64,
            });
        };
        let result = match &world.vehicle {
            WorldVehicle::Car(car) => car_programmes::run(world, car, part, &mut report)?,
            WorldVehicle::DifferentialWheels(robot) => robot::run(world, robot, part, &mut report)?,
        };
        results.push(result);
    }
    let sim_seconds = results.iter().map(|r| r.sim_seconds).sum();
    Ok(RunReport {
        world: world.source.clone(),
        vehicle: world.vehicle_name().to_string(),
        scenario,
        results,
        sim_seconds,
        wall_seconds: start.elapsed().as_secs_f64(),
    })
}
