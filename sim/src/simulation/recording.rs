//! The recording of a run driven through [`Simulation`]: every vehicle's samples in a
//! [`TelemetryLog`], the enabled devices' samples in a [`DeviceLog`], the replay's keyframes,
//! and the gaps between cars; then the run's report and data files, for any front-end.

use std::path::{Path, PathBuf};
use std::sync::atomic::{AtomicU64, Ordering};
use std::time::Instant;

use crate::config::Outline;
use crate::diff_wheels::RobotId;
use crate::replay::Recorder;
use crate::report::{self, OutputError};
use crate::scenario::{DepartureMeter, Metric, MotionMeter, RunReport, ScenarioResult};
use crate::telemetry::{
    CsvWriter, DeviceLog, DeviceReadings, DeviceRow, LogMark, Retention, Sample, Telemetry,
    TelemetryLog, VehicleKind,
};
use crate::vehicle::VehicleId;

use super::Simulation;
use super::snapshot::SnapshotError;

/// What a log follows.
#[derive(Debug, Clone, Copy)]
enum Target {
    Car(VehicleId),
    Robot(RobotId),
}

/// One vehicle's log.
struct VehicleLog {
    name: String,
    target: Target,
    log: TelemetryLog,
}

/// The recording of a run: see [`Simulation::record`].
pub(super) struct Recording {
    run: String,
    /// What the vehicles' logs keep; a bounded recording keeps no device rows and no replay
    /// frames after the first (both grow with the run).
    retention: Retention,
    vehicles: Vec<VehicleLog>,
    /// The devices' samples, cars and devices by index in the simulation's order.
    devices: DeviceLog,
    replay: Recorder,
    /// Smallest gap between two cars so far (m).
    min_gap: f64,
    /// When two cars first touched (s).
    first_touch: Option<f64>,
    started: Instant,
    /// Tells this recording from a later one of the same simulation (a snapshot's
    /// [`RecordingMark`] belongs to one recording).
    serial: u64,
}

/// Numbers the recordings of this process.
static NEXT_RECORDING: AtomicU64 = AtomicU64::new(0);

/// How far a recording had got: the lengths of its logs, its replay and its gap meters, for
/// [`Recording::rewind`].
#[derive(Debug, Clone)]
pub(super) struct RecordingMark {
    serial: u64,
    samples: Vec<LogMark>,
    device_rows: usize,
    replay: Recorder,
    min_gap: f64,
    first_touch: Option<f64>,
}

impl Simulation {
    /// The device readings recorded so far, handed over with the names of the cars and their
    /// devices (empty when not recording); the recording goes on with an empty device log.
    /// The `programme` scenario gives them to its result for `devices.csv`.
    pub(crate) fn take_device_readings(&mut self) -> DeviceReadings {
        let log = self
            .recording
            .as_mut()
            .map(Recording::take_devices)
            .unwrap_or_default();
        self.device_readings(log)
    }

    /// `log`, whose rows were pushed by [`Simulation::log_sampled_devices`], with the names of
    /// the cars and their devices: what `devices.csv` is written from.
    pub(crate) fn device_readings(&self, log: DeviceLog) -> DeviceReadings {
        let cars = self
            .cars
            .iter()
            .map(|c| {
                let devices = c.devices.all().iter().map(|d| d.name().to_string());
                (c.name.clone(), devices.collect())
            })
            .collect();
        DeviceReadings::new(log, cars)
    }

    /// Pushes into `log` the values of every device that sampled in the last step (none at
    /// the start: a device's first sample comes one period after enabling), cars and devices
    /// by index in this simulation's order. A recorded run ([`Simulation::record`]) and the
    /// built-in car scenarios log through it.
    pub(crate) fn log_sampled_devices(&self, log: &mut DeviceLog) {
        let now_ms = self.world().time_ms();
        let time = self.world().time();
        for (car, c) in (0..).zip(&self.cars) {
            for (device, d) in (0..).zip(c.devices.all()) {
                if d.sampled_at(now_ms) {
                    d.for_each_recorded(|quantity, value| {
                        log.push(DeviceRow {
                            time,
                            car,
                            device,
                            quantity,
                            value,
                        });
                    });
                }
            }
        }
    }
}

impl Recording {
    /// Starts recording `sim` now, keeping what `retention` says: a first sample of every
    /// vehicle.
    pub(super) fn start(sim: &Simulation, run: &str, retention: Retention) -> Recording {
        let vehicles = sim
            .cars
            .iter()
            .map(|c| (c.name.clone(), Target::Car(c.id)))
            .chain(
                sim.robots
                    .iter()
                    .map(|r| (r.name.clone(), Target::Robot(r.id))),
            )
            .map(|(name, target)| VehicleLog {
                name,
                target,
                log: TelemetryLog::with_retention(retention),
            })
            .collect();
        let mut recording = Recording {
            run: run.to_string(),
            retention,
            vehicles,
            devices: DeviceLog::new(),
            replay: Recorder::for_simulation(sim),
            min_gap: f64::INFINITY,
            first_touch: None,
            started: Instant::now(),
            serial: NEXT_RECORDING.fetch_add(1, Ordering::Relaxed),
        };
        recording.log_samples(sim);
        recording
    }

    /// How far this recording has got.
    pub(super) fn mark(&self) -> RecordingMark {
        RecordingMark {
            serial: self.serial,
            samples: self.vehicles.iter().map(|v| v.log.mark()).collect(),
            device_rows: self.devices.len(),
            replay: self.replay.clone(),
            min_gap: self.min_gap,
            first_touch: self.first_touch,
        }
    }

    /// Takes this recording back to `mark`: the samples, device rows and replay frames
    /// recorded since are dropped.
    ///
    /// # Errors
    /// [`SnapshotError::OtherRecording`] if `mark` is not of this recording or the device
    /// rows were handed over since; [`SnapshotError::Io`] if a log's temporary file cannot
    /// be shortened.
    pub(super) fn rewind(&mut self, mark: &RecordingMark) -> Result<(), SnapshotError> {
        if mark.serial != self.serial || self.devices.len() < mark.device_rows {
            return Err(SnapshotError::OtherRecording);
        }
        for (v, log_mark) in self.vehicles.iter_mut().zip(&mark.samples) {
            v.log
                .rewind(log_mark)
                .map_err(|e| SnapshotError::Io(e.to_string()))?;
        }
        self.devices
            .truncate(mark.device_rows)
            .map_err(|e| SnapshotError::Io(e.to_string()))?;
        self.replay = mark.replay.clone();
        self.min_gap = mark.min_gap;
        self.first_touch = mark.first_touch;
        Ok(())
    }

    /// Records the state after a step.
    pub(super) fn sample(&mut self, sim: &Simulation) {
        self.log_samples(sim);
        if self.retention == Retention::All {
            sim.log_sampled_devices(&mut self.devices);
            self.replay.sample_simulation(sim);
        }
        let world = sim.world();
        for (i, a) in sim.cars.iter().enumerate() {
            for b in sim.cars.iter().skip(i + 1) {
                if let Ok(gap) = world.vehicle_gap(a.id, b.id) {
                    self.min_gap = self.min_gap.min(gap);
                }
                if self.first_touch.is_none()
                    && world.vehicles_in_contact(a.id, b.id).unwrap_or(false)
                {
                    self.first_touch = Some(world.time());
                }
            }
        }
    }

    fn log_samples(&mut self, sim: &Simulation) {
        for v in &mut self.vehicles {
            // The handles are the simulation's own: a sample always exists.
            let sample = match v.target {
                Target::Car(id) => Sample::of_car(sim, id),
                Target::Robot(id) => Sample::of_robot(sim.world(), id),
            };
            if let Ok(s) = sample {
                v.log.push(&s);
            }
        }
    }

    /// The devices' samples so far, handed over: the log starts anew.
    pub(super) fn take_devices(&mut self) -> DeviceLog {
        std::mem::take(&mut self.devices)
    }

    /// The log of the vehicle named `name`.
    pub(super) fn log(&self, name: &str) -> Option<&TelemetryLog> {
        self.vehicles
            .iter()
            .find(|v| v.name == name)
            .map(|v| &v.log)
    }

    /// The run so far as a report on the world named `world`; its telemetry read back from the
    /// logs if `with_telemetry`.
    pub(super) fn report(
        &self,
        sim: &Simulation,
        world: &str,
        with_telemetry: bool,
    ) -> std::io::Result<RunReport> {
        let mut metrics = Vec::new();
        let mut telemetry = Vec::new();
        let mut notes = Vec::new();
        for v in &self.vehicles {
            let mut meter = MotionMeter::new();
            let roads = &sim.world().config().roads;
            let mut departures = match v.target {
                Target::Car(id) if !roads.is_empty() => {
                    sim.driver(id).ok().map(|d| DepartureMeter::new(d.params()))
                }
                _ => None,
            };
            v.log.for_each(|row| {
                let sample = Sample::from_row(row);
                meter.push(&sample);
                if let Some(d) = &mut departures {
                    d.push(roads, sample.time, sample.x, sample.y, sample.yaw);
                }
            })?;
            metrics.extend(meter.metrics().into_iter().map(|m| m.of(&v.name)));
            if let Some(d) = &departures {
                metrics.extend(d.metrics().into_iter().map(|m| m.of(&v.name)));
                notes.extend(d.notes(&v.name));
            }
            if let Some(e) = v.log.spill_error() {
                notes.push(format!(
                    "{}: the telemetry stayed in memory, its temporary file failed: {e}",
                    v.name
                ));
            }
            if with_telemetry {
                telemetry.push(Telemetry {
                    scenario: self.run.clone(),
                    vehicle: v.name.clone(),
                    kind: match v.target {
                        Target::Car(_) => VehicleKind::Car,
                        Target::Robot(_) => VehicleKind::Robot,
                    },
                    samples: v.log.samples()?,
                });
            }
        }
        if let Some(e) = self.devices.spill_error() {
            notes.push(format!(
                "the device readings stayed in memory, their temporary file failed: {e}"
            ));
        }
        if sim.cars.len() > 1 {
            metrics.extend([
                Metric::maybe(
                    "min_gap_m",
                    "smallest gap between two cars",
                    "m",
                    Some(self.min_gap),
                ),
                Metric::flag("touched", "two cars touched", self.first_touch.is_some()),
                Metric::maybe("first_touch_s", "first touch", "s", self.first_touch),
            ]);
        }
        if let Some(e) = sim.failure() {
            notes.push(format!("the simulation stopped: {e}"));
        }
        let sim_seconds = sim.world().time();
        let names: Vec<&str> = self.vehicles.iter().map(|v| v.name.as_str()).collect();
        Ok(RunReport {
            world: world.to_string(),
            vehicle: match names.as_slice() {
                [one] => (*one).to_string(),
                _ => format!("{} vehicles ({})", names.len(), names.join(", ")),
            },
            scenario: self.run.clone(),
            results: vec![ScenarioResult {
                name: self.run.clone(),
                metrics,
                sim_seconds,
                telemetry,
                notes,
                replay: self.replay.clone().finish_simulation(sim),
                ..ScenarioResult::default()
            }],
            sim_seconds,
            wall_seconds: self.started.elapsed().as_secs_f64(),
            obstacles: Outline::of_world(sim.world().config()),
        })
    }

    /// Writes the run's data files into `dir`, the telemetry and the devices' readings
    /// streamed from the logs.
    pub(super) fn save(
        &self,
        sim: &Simulation,
        world: &str,
        world_warnings: &[String],
        dir: &Path,
    ) -> Result<Vec<PathBuf>, OutputError> {
        let io = |e: std::io::Error| OutputError::Io {
            path: dir.to_path_buf(),
            source: e,
        };
        let run = self.report(sim, world, false).map_err(io)?;
        let telemetry = |out: &mut dyn std::io::Write| -> Result<(), csv::Error> {
            let mut w = CsvWriter::new(out)?;
            for v in &self.vehicles {
                let mut result = Ok(());
                v.log
                    .for_each(|row| {
                        if result.is_ok() {
                            let values = row.iter().map(|&x| (!x.is_nan()).then_some(x));
                            result = w.write(&self.run, &v.name, values);
                        }
                    })
                    .map_err(csv::Error::from)?;
                result?;
            }
            w.finish()
        };
        let [csv, json, glb, html] = report::DATA_OUTPUTS;
        let mut written = report::write_files(
            &run,
            world_warnings,
            dir,
            &[csv, report::DEVICES_CSV, json, glb, html],
            &[],
            &telemetry,
        )?;
        let path = dir.join(report::DEVICES_CSV);
        let file = std::fs::File::create(&path).map_err(|source| OutputError::Io {
            path: path.clone(),
            source,
        })?;
        // The indices are the simulation's own (cars are not added while recording).
        let names = |car: u32, device: u32| {
            let c = sim.cars.get(car as usize);
            let d = c.and_then(|c| c.devices.all().get(device as usize));
            (
                c.map_or("", |c| c.name.as_str()),
                d.map_or("", |d| d.name()),
            )
        };
        self.devices
            .write_csv(std::io::BufWriter::new(file), names)
            .map_err(|source| OutputError::Csv {
                path: path.clone(),
                source,
            })?;
        written.insert(1, path);
        Ok(written)
    }
}
