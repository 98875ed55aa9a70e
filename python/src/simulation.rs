//! `_native.Simulation`: the core of the Pythonic `webots_vehicle.Simulation`.
//!
//! A world described by a world file (or a model name, or world-file text built from keyword
//! arguments by the Python side), its car driven by `vehicle_model::Driver` as
//! `sim::Simulation` drives it, more cars added from `[vehicle]` tables, one telemetry sample
//! per car and step (the columns of `vehicle-sim`'s CSV), and the `vehicle-sim` scenarios run
//! on a fresh copy of the world.

use pyo3::exceptions::{PyIndexError, PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::PyBytes;

use sim::scenario::{self, Scenario};
use sim::telemetry::{CSV_HEADER, Retention, SAMPLE_COLUMNS, TelemetryLog};
use sim::world_file::{self, WorldDescription, WorldFileError};
use sim::{CarBuilder, SimError, VehicleId};
use vehicle_model::Warning;

use crate::snapshot::Snapshot;
use crate::telemetry;
use crate::{SimulationError, WorldError};

/// One driven car.
struct Car {
    id: VehicleId,
    model: &'static str,
}

/// The name of a `webots_vehicle.Simulation` run in its outputs (the `scenario` column).
const RUN: &str = "simulation";

/// A simulation of one world: see the module docs. It belongs to the thread that created it
/// (`unsendable`: the driver library keeps per-car state in cells, which are not `Sync`);
/// another thread gets a RuntimeError.
#[pyclass(module = "webots_vehicle._native", unsendable)]
pub(crate) struct Simulation {
    description: WorldDescription,
    simulation: sim::Simulation,
    cars: Vec<Car>,
    warnings: Vec<String>,
    /// How much of each car's run the recording keeps (`Simulation(record=...)`).
    retention: Retention,
}

/// `WorldError` with the error's message and its `file`, `line`, `column` and `key`
/// attributes (`None` where unknown).
fn world_error(py: Python<'_>, e: &WorldFileError) -> PyErr {
    let err = WorldError::new_err(e.to_string());
    let value = err.value(py);
    let (line, column) = e.location.map(|l| (l.line, l.column)).unzip();
    // Setting attributes on a fresh exception instance cannot fail in practice; if it did, the
    // message still says everything.
    let _ = value.setattr("file", &e.file);
    let _ = value.setattr("line", line);
    let _ = value.setattr("column", column);
    let _ = value.setattr("key", e.key.as_deref());
    err
}

/// A refused placement (a value out of range: ValueError) or a missing car or body.
fn placement_error(e: &SimError) -> PyErr {
    match e {
        SimError::Param(p) => PyValueError::new_err(p.to_string()),
        other => sim_error(other),
    }
}

/// A physics failure as a Python `RuntimeError`.
pub(crate) fn sim_error(e: &SimError) -> PyErr {
    SimulationError::new_err(format!("the simulation failed: {e}"))
}

/// The driver's warning as a Python string (the Python side issues it as a warning).
fn warning_text(w: Option<Warning>) -> Option<String> {
    w.map(|w| w.to_string().trim_end().to_string())
}

impl Simulation {
    /// Builds the world of `description` with its cars (car 0 first) and robot.
    fn build(description: WorldDescription) -> PyResult<Simulation> {
        let (simulation, reports) =
            sim::Simulation::from_description(&description).map_err(|e| sim_error(&e))?;
        let source = description.source.clone();
        let mut warnings: Vec<String> = description
            .warnings
            .iter()
            .map(ToString::to_string)
            .collect();
        warnings.extend(reports.iter().flatten().map(|w| format!("{source}: {w}")));
        let cars = description
            .cars
            .iter()
            .zip(simulation.car_ids())
            .map(|(c, id)| Car {
                id,
                model: c.model.webots_name(),
            })
            .collect();
        Ok(Simulation {
            description,
            simulation,
            cars,
            warnings,
            retention: Retention::All,
        })
    }

    /// The engine's simulation.
    pub(crate) fn engine(&self) -> &sim::Simulation {
        &self.simulation
    }

    /// The engine's simulation, to step it outside `step` (`_native.GymEnv`: no telemetry
    /// is recorded then).
    pub(crate) fn engine_mut(&mut self) -> &mut sim::Simulation {
        &mut self.simulation
    }

    fn car(&self, car: usize) -> PyResult<&Car> {
        self.cars
            .get(car)
            .ok_or_else(|| PyIndexError::new_err(format!("no car {car} in this simulation")))
    }

    fn driver_mut(&mut self, car: usize) -> PyResult<&mut vehicle_model::Driver<f64>> {
        let id = self.car(car)?.id;
        self.simulation.driver_mut(id).map_err(|e| sim_error(&e))
    }

    fn driver(&self, car: usize) -> PyResult<&vehicle_model::Driver<f64>> {
        let id = self.car(car)?.id;
        self.simulation.driver(id).map_err(|e| sim_error(&e))
    }

    /// `index` as a body index, if `kind` is "body".
    fn body_index(&self, kind: &str, index: usize) -> PyResult<usize> {
        if kind != "body" {
            return Err(PyValueError::new_err(format!(
                "kind must be 'car' or 'body', not {kind:?}"
            )));
        }
        if index >= self.simulation.world().body_count() {
            return Err(PyIndexError::new_err(format!(
                "no body {index} in this simulation"
            )));
        }
        Ok(index)
    }

    /// Car `car`'s log, empty before the first step.
    fn log(&self, car: usize) -> PyResult<Option<&TelemetryLog>> {
        let id = self.car(car)?.id;
        Ok(self.simulation.car_log(id))
    }
}

#[pymethods]
impl Simulation {
    /// The world `spec`: a world-file path or a shipped model name ("" is the default world).
    #[staticmethod]
    fn load(py: Python<'_>, spec: &str) -> PyResult<Simulation> {
        let description = world_file::load(spec).map_err(|e| world_error(py, &e))?;
        Simulation::build(description)
    }

    /// The world of world-file `text`; `name` names it in messages.
    #[staticmethod]
    fn parse(py: Python<'_>, name: &str, text: &str) -> PyResult<Simulation> {
        let description = world_file::parse_str(name, text).map_err(|e| world_error(py, &e))?;
        Simulation::build(description)
    }

    /// The telemetry columns, in order (those of `vehicle-sim`'s CSV after `scenario`).
    #[staticmethod]
    fn columns() -> Vec<&'static str> {
        CSV_HEADER.split(',').skip(2).collect()
    }

    /// Where the world came from.
    #[getter]
    fn source(&self) -> &str {
        &self.description.source
    }

    /// What drives in the world file: its car model, `DifferentialWheels`, or `N vehicles (names)`.
    #[getter]
    fn vehicle(&self) -> String {
        self.description.vehicles_label()
    }

    /// The world's and the cars' warnings so far (fields replaced by their defaults).
    #[getter]
    fn warnings(&self) -> Vec<String> {
        self.warnings.clone()
    }

    /// Simulated time (s).
    #[getter]
    fn time(&self) -> f64 {
        self.simulation.world().time()
    }

    /// The world's basicTimeStep (ms).
    #[getter]
    fn basic_time_step(&self) -> u32 {
        self.simulation.world().config().basic_time_step_ms
    }

    /// The world's duration (s), if any.
    #[getter]
    fn duration(&self) -> Option<f64> {
        self.description.duration
    }

    /// How much of the run the recording keeps: True (every step), False (none but the
    /// last sample) or N (the last N samples). Set before the first step.
    fn set_record(&mut self, record: &Bound<'_, PyAny>) -> PyResult<()> {
        if self.simulation.is_recording() {
            return Err(SimulationError::new_err(
                "record= is set before the first step (recording has started)",
            ));
        }
        self.retention = telemetry::retention(record)?;
        Ok(())
    }

    /// The number of cars.
    #[getter]
    fn car_count(&self) -> usize {
        self.cars.len()
    }

    /// True once the world's duration has elapsed (or the physics failed).
    #[getter]
    fn is_over(&self) -> bool {
        self.simulation.is_over()
    }

    /// Adds the car of the `[vehicle]` table of world-file `text` (named `name` in messages);
    /// returns its index and the warnings of its fields.
    fn add_car(
        &mut self,
        py: Python<'_>,
        name: &str,
        text: &str,
    ) -> PyResult<(usize, Vec<String>)> {
        let description = world_file::parse_str(name, text).map_err(|e| world_error(py, &e))?;
        let Some(car) = description.car() else {
            return Err(PyValueError::new_err(
                "add_car needs a car, not a DifferentialWheels robot",
            ));
        };
        let mut warnings: Vec<String> = description
            .warnings
            .iter()
            .map(ToString::to_string)
            .collect();
        let (id, report) = self
            .simulation
            .add_car(CarBuilder::from(car))
            .map_err(|e| sim_error(&e))?;
        self.cars.push(Car {
            id,
            model: car.model.webots_name(),
        });
        warnings.extend(report.iter().map(|w| format!("{name}: {w}")));
        self.warnings.extend(warnings.iter().cloned());
        Ok((self.cars.len() - 1, warnings))
    }

    /// The Webots model name of car `car`.
    fn model(&self, car: usize) -> PyResult<&'static str> {
        Ok(self.car(car)?.model)
    }

    /// Wheelbase, front track, rear track, front and rear tyre radius of car `car` (m).
    fn geometry(&self, car: usize) -> PyResult<(f64, f64, f64, f64, f64)> {
        let d = self.driver(car)?;
        Ok((
            d.wheelbase(),
            d.track_front(),
            d.track_rear(),
            d.front_wheel_radius(),
            d.rear_wheel_radius(),
        ))
    }

    /// Advances up to `steps` basic time steps (each: every driver steps, then the physics),
    /// recording every car from the first step on (its state then, and one sample per step);
    /// stops at the world's duration. Returns False once the simulation is over. A physics
    /// failure raises RuntimeError (and ends the simulation).
    ///
    /// With `drivers` false the drivers do not run: the physics advances with the commands in
    /// force (a Webots controller's `wb_robot_step` without `wbu_driver_step`); the steering a
    /// setter commanded since still acts, as in Webots.
    #[pyo3(signature = (steps, drivers = true))]
    fn step(&mut self, steps: u64, drivers: bool) -> PyResult<bool> {
        if steps > 0 && !self.simulation.is_recording() {
            self.simulation.record_with(RUN, self.retention);
        }
        for _ in 0..steps {
            if self.simulation.is_over() {
                break;
            }
            let stepped = if drivers {
                self.simulation.step()
            } else {
                self.simulation.step_physics()
            };
            stepped.map_err(|e| sim_error(&e))?;
        }
        Ok(!self.simulation.is_over())
    }

    /// The whole state of the simulation now (physics, drivers, devices and their noise, time,
    /// recording length), for `restore`.
    fn snapshot(&self) -> Snapshot {
        Snapshot {
            state: self.simulation.snapshot(),
            cars: self.cars.len(),
            warnings: self.warnings.len(),
        }
    }

    /// Puts the simulation back in the state of `snapshot` (taken of this simulation; it can
    /// be restored again): the run continues bit for bit as it did from there, the cars added
    /// and the samples recorded since are gone.
    fn restore(&mut self, snapshot: &Snapshot) -> PyResult<()> {
        self.simulation
            .restore(&snapshot.state)
            .map_err(|e| SimulationError::new_err(format!("cannot restore: {e}")))?;
        self.cars.truncate(snapshot.cars);
        self.warnings.truncate(snapshot.warnings);
        Ok(())
    }

    /// Where car or body `index` is (`kind` "car" or "body"): translation (m), rotation
    /// (Webots axis-angle: unit axis, rad), velocity (m/s) and angular velocity (rad/s), world.
    #[allow(clippy::type_complexity)]
    fn placement(
        &self,
        kind: &str,
        index: usize,
    ) -> PyResult<([f64; 3], [f64; 4], [f64; 3], [f64; 3])> {
        let world = self.simulation.world();
        let p = match kind {
            "car" => world.vehicle_placement(self.car(index)?.id),
            _ => world.body_placement(self.body_index(kind, index)?),
        }
        .map_err(|e| placement_error(&e))?;
        Ok((
            p.position.coords.into(),
            p.axis_angle(),
            p.velocity.into(),
            p.angular_velocity.into(),
        ))
    }

    /// Puts car or body `index` at `translation` (m) with Webots `rotation` (axis, rad).
    fn set_pose(
        &mut self,
        kind: &str,
        index: usize,
        translation: [f64; 3],
        rotation: [f64; 4],
    ) -> PyResult<()> {
        let q = sim::rotation_from_axis_angle(rotation)
            .map_err(|e| PyValueError::new_err(e.to_string()))?;
        let at = sim::nalgebra::Point3::from(translation);
        let done = match kind {
            "car" => {
                let id = self.car(index)?.id;
                self.simulation.world_mut().set_vehicle_pose(id, &at, &q)
            }
            _ => {
                let i = self.body_index(kind, index)?;
                self.simulation.world_mut().set_body_pose(i, &at, &q)
            }
        };
        done.map_err(|e| placement_error(&e))
    }

    /// Gives car or body `index` the velocity `linear` (m/s) and `angular` (rad/s), world.
    fn set_velocity(
        &mut self,
        kind: &str,
        index: usize,
        linear: [f64; 3],
        angular: [f64; 3],
    ) -> PyResult<()> {
        let (l, a) = (
            sim::nalgebra::Vector3::from(linear),
            sim::nalgebra::Vector3::from(angular),
        );
        let done = match kind {
            "car" => {
                let id = self.car(index)?.id;
                self.simulation.world_mut().set_vehicle_velocity(id, &l, &a)
            }
            _ => {
                let i = self.body_index(kind, index)?;
                self.simulation.world_mut().set_body_velocity(i, &l, &a)
            }
        };
        done.map_err(|e| placement_error(&e))
    }

    /// The number of dynamic bodies (`[[body]]`).
    #[getter]
    fn body_count(&self) -> usize {
        self.simulation.world().body_count()
    }

    /// Back to the world as loaded (time 0, cars added since dropped, recording restarted at
    /// the next step).
    fn simulation_reset(&mut self) -> PyResult<()> {
        self.simulation
            .simulation_reset()
            .map_err(|e| SimulationError::new_err(format!("cannot reset: {e}")))?;
        self.cars.truncate(self.description.cars.len());
        Ok(())
    }

    /// Writes the run recorded so far into `dir` (`telemetry.csv`, `metrics.json`,
    /// `replay.glb`); returns the paths written (none before the first step).
    fn save(&self, dir: std::path::PathBuf) -> PyResult<Vec<std::path::PathBuf>> {
        self.simulation
            .save(&self.description.source, &self.warnings, &dir)
            .map_err(|e| PyOSError::new_err(e.to_string()))
    }

    /// Cruise control to `speed` km/h (SPEED mode); returns the driver's warning, if any.
    fn set_cruising_speed(&mut self, car: usize, speed: f64) -> PyResult<Option<String>> {
        Ok(warning_text(
            self.driver_mut(car)?.set_cruising_speed(speed),
        ))
    }

    /// Steering angle (rad, positive right); returns the driver's warning, if any.
    fn set_steering_angle(&mut self, car: usize, angle: f64) -> PyResult<Option<String>> {
        Ok(warning_text(
            self.driver_mut(car)?.set_steering_angle(angle),
        ))
    }

    /// Throttle (0 to 1, TORQUE mode); returns the driver's warning, if any.
    fn set_throttle(&mut self, car: usize, throttle: f64) -> PyResult<Option<String>> {
        Ok(warning_text(self.driver_mut(car)?.set_throttle(throttle)))
    }

    /// Brake intensity (0 to 1); returns the driver's warning, if any.
    fn set_brake_intensity(&mut self, car: usize, intensity: f64) -> PyResult<Option<String>> {
        Ok(warning_text(
            self.driver_mut(car)?.set_brake_intensity(intensity),
        ))
    }

    /// Gear (-1 reverse, 0 neutral, 1.. forward); returns the driver's warning, if any.
    fn set_gear(&mut self, car: usize, gear: i32) -> PyResult<Option<String>> {
        Ok(warning_text(self.driver_mut(car)?.set_gear(gear)))
    }

    /// The number of samples car `car` holds (all it recorded, or the last N of them).
    fn sample_count(&self, car: usize) -> PyResult<usize> {
        Ok(self.log(car)?.map_or(0, TelemetryLog::len))
    }

    /// The number of samples car `car` has recorded (the t = 0 sample and one per step),
    /// whether held or not.
    fn recorded_count(&self, car: usize) -> PyResult<usize> {
        Ok(self.log(car)?.map_or(0, TelemetryLog::recorded))
    }

    /// The last sample of car `car` (NaN where a quantity does not exist), None before the
    /// first step.
    fn last_sample(&self, car: usize) -> PyResult<Option<Vec<f64>>> {
        Ok(self
            .log(car)?
            .and_then(TelemetryLog::last)
            .map(|r| r.to_vec()))
    }

    /// The samples car `car` holds, row-major (rows × columns, f64): the recorded memory
    /// itself, read-only, while it is all in memory (a `TelemetryRows` buffer), else a
    /// `bytearray` read back from the log's temporary file (see the `telemetry` module);
    /// None before the first step.
    fn telemetry<'py>(&self, py: Python<'py>, car: usize) -> PyResult<Option<Bound<'py, PyAny>>> {
        self.log(car)?
            .map(|log| telemetry::rows(py, log))
            .transpose()
    }

    /// Runs the `vehicle-sim` scenario `name` on a fresh copy of this simulation's world file
    /// (not on the cars added or the time stepped here). Returns the JSON object of
    /// `vehicle-sim --json` and each single scenario's name and telemetry table.
    #[allow(clippy::type_complexity)]
    fn run<'py>(
        &self,
        py: Python<'py>,
        name: &str,
    ) -> PyResult<(String, Vec<(String, Bound<'py, PyBytes>)>)> {
        let scenario = Scenario::from_name(name).ok_or_else(|| {
            let names: Vec<&str> = Scenario::ALL.iter().map(|s| s.name()).collect();
            PyValueError::new_err(format!(
                "unknown scenario '{name}' (one of: {})",
                names.join(", ")
            ))
        })?;
        let description = &self.description;
        let report = py
            .detach(|| scenario::run(description, scenario, &mut |_| {}))
            .map_err(|e| SimulationError::new_err(e.to_string()))?;
        let world_warnings: Vec<String> = description
            .warnings
            .iter()
            .map(ToString::to_string)
            .collect();
        let files = sim::report::DATA_OUTPUTS;
        let json = sim::report::to_json(&report, &world_warnings, &files);
        let tables = report
            .results
            .iter()
            .flat_map(|r| {
                r.telemetry
                    .iter()
                    .map(|t| (r.name.clone(), telemetry::table(py, &t.samples)))
            })
            .collect();
        Ok((json, tables))
    }
}

/// Adds the class to the module.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Simulation>()?;
    m.add("TELEMETRY_COLUMNS", SAMPLE_COLUMNS)?;
    Ok(())
}
