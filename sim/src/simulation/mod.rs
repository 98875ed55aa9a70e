//! A world plus one Webots driver library per car, stepped like a Webots controller calling
//! `wbu_driver_step()`: the one way every front-end (the `vehicle-sim` scenarios, the C API,
//! Python, Rust programs) builds and runs a simulation.
//!
//! It owns what a run is beyond its physics: the cars' drivers and names, the robots' names,
//! the world's `duration` and whether the run is over, the Webots rules that act between two
//! steps (a steering setter moves the steering motors at once; `wbu_car_init` holds the driven
//! wheels), physics-only steps (`wb_robot_step` without the driver), and, when asked, the
//! recording of every vehicle that gives a run's telemetry, metrics and replay.

mod battery;
mod devices;
mod energy;
mod lanes;
mod recording;
mod snapshot;
mod stepping;

use std::path::{Path, PathBuf};

use vehicle_model::{ControlMode, Driver, Gear, ParamReport};

use std::sync::Arc;

use crate::appearance::Appearances;
use crate::battery_sensor::BatterySensor;
use crate::car_builder::CarBuilder;
use crate::devices::CarDevices;
use crate::devices::GpsFrame;
use crate::devices::camera::roads::Patch;
use crate::diff_wheels::{DifferentialWheelsParams, RobotId, RobotMode, RobotPlacement};
use crate::error::{ParamError, SimError};
use crate::keyboard::Keyboard;
use crate::lane_following::LaneFollower;
use crate::report::OutputError;
use crate::scenario::RunReport;
use crate::telemetry::{Retention, TelemetryLog};
use crate::vehicle::{VehicleId, VehicleState};
use crate::world::World;
use crate::world_file::{RobotDescription, WorldDescription};
use energy::EnergyMeter;
pub use energy::EnergyReport;
use recording::Recording;
pub use snapshot::{Snapshot, SnapshotError};

/// Longest simulated time a run may last (s): one day. Every built-in scenario ends within
/// 10 minutes, and a day of simulated time is 8.64 million steps at the default 10 ms (hours
/// of wall time for one car): a longer `duration` or programme step is a typo (`1e9` for
/// `1e3`) or a run that never ends. The limit is on simulated time, not on memory: a run's
/// telemetry is recorded in bounded memory ([`TelemetryLog`]) whatever its length. It is the
/// bound of a world file's `duration` and programme times `at`, of `vehicle-sim --duration`
/// and of [`Simulation::set_duration`].
pub const MAX_DURATION: f64 = 86_400.0;

/// What a duration must be, completing "must be …".
pub(crate) const DURATION_RULE: &str = "finite, > 0 and at most 86400 s (a day)";

/// True for a duration `d` (s) that a run may have: > 0 and at most [`MAX_DURATION`].
pub(crate) fn is_duration(d: f64) -> bool {
    d > 0.0 && d <= MAX_DURATION
}

/// One car's driver, name, sensor devices and whether it has had its first step.
#[derive(Clone)]
struct Controlled {
    id: VehicleId,
    driver: Driver<f64>,
    name: String,
    sampled: bool,
    devices: CarDevices,
    keyboard: Keyboard,
    /// Its built-in lane-following driver, while it follows a lane.
    follower: Option<LaneFollower>,
    /// Its energy accounting, if asked for ([`CarBuilder::energy`]).
    energy: Option<EnergyMeter>,
    /// Its controller's battery sensor.
    battery_sensor: BatterySensor,
}

/// A robot's handle and name.
#[derive(Clone)]
struct Named {
    id: RobotId,
    name: String,
}

/// What a data logger records of a driven car at one instant.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct CarTelemetry {
    /// Simulated time (s).
    pub time: f64,
    /// The physical state measured on the bodies (pose, velocities, wheels, steering).
    pub state: VehicleState,
    /// Chassis speed (m/s, signed, positive forward), from the rigid body: not the driver's
    /// wheel-based estimate.
    pub speed: f64,
    /// The driver library's own speed estimate from the driven wheels (km/h; 0 until the wheel
    /// speeds are measurable, where Webots returns NaN for two steps). Webots:
    /// `wbu_driver_get_current_speed`.
    pub estimated_speed_kmh: f64,
    /// Engine speed (rpm) in torque mode, `None` in the other modes (Webots warns there).
    pub rpm: Option<f64>,
    /// Engaged gear in torque mode, `None` in the other modes.
    pub gear: Option<Gear>,
    /// The control mode.
    pub control_mode: ControlMode,
    /// Throttle (0 to 1).
    pub throttle: f64,
    /// Brake intensity (0 to 1).
    pub brake: f64,
}

/// A [`World`] whose cars are each driven by a `vehicle_model::Driver<f64>`.
///
/// [`Simulation::step`] does what `wbu_driver_step()` does in a Webots controller: each driver
/// steps with the sensor readings at the current time `t` (the state after the previous
/// physics step; unsampled, i.e. NaN, at a car's first step), its commands are applied, then
/// the world advances by one `basicTimeStep`.
///
/// ```
/// use sim::{CarBuilder, Simulation, World, WorldConfig};
/// use vehicle_model::Model;
/// let mut sim = Simulation::new(World::new(WorldConfig::default())?);
/// let (id, report) = sim.add_car(CarBuilder::of_model(Model::BmwX5))?;
/// assert!(report.is_empty());
/// sim.driver_mut(id)?.set_cruising_speed(20.0); // km/h, as in Webots
/// for _ in 0..100 {
///     sim.step()?;
/// }
/// assert!(sim.telemetry(id)?.speed > 0.5); // m/s after 1 s
/// # Ok::<(), sim::SimError>(())
/// ```
pub struct Simulation {
    world: World,
    cars: Vec<Controlled>,
    robots: Vec<Named>,
    /// Simulated time after which the run is over (s).
    duration: Option<f64>,
    recording: Option<Recording>,
    /// The replay shows the radars' targets ([`crate::replay::overlay`]).
    replay_overlay: bool,
    /// How the world's things look to the cameras.
    appearances: Appearances,
    /// The frame the GPS devices report in.
    gps: GpsFrame,
    /// The roads as the cameras see them, built at the first render (the roads never move).
    road_patches: Option<Arc<[Patch]>>,
    /// Tells this simulation's snapshots from others'.
    serial: u64,
    /// The world as loaded, for [`Simulation::simulation_reset`].
    loaded: Option<Box<Snapshot>>,
}

impl Simulation {
    /// A simulation of `world` with no driven car yet, and no `duration`. Cars and robots
    /// already in `world` have no driver and no name; add them through the simulation
    /// ([`Simulation::add_car`], [`Simulation::add_robot`]) instead.
    pub fn new(world: World) -> Self {
        Simulation {
            world,
            cars: Vec::new(),
            robots: Vec::new(),
            duration: None,
            recording: None,
            replay_overlay: false,
            appearances: Appearances::default(),
            gps: GpsFrame::default(),
            road_patches: None,
            serial: snapshot::next_serial(),
            loaded: None,
        }
    }

    /// The world of `description` with every car (as described: parameters, tyre, mounting,
    /// brake balance, placement, name) and the robot, and its `duration`. Nothing the
    /// description says is left out; what the front-ends add (recording, outputs) is theirs to
    /// ask for.
    ///
    /// Also returns the cars' parameter reports: the loader validated them already, so they
    /// are empty unless the description was changed since.
    ///
    /// ```
    /// use sim::{Simulation, world_file};
    /// let text = "duration = 2.0\n[vehicle]\nmodel = \"BmwX5\"\nmounting = \"joints\"\n";
    /// let description = world_file::parse_str("w.toml", text)?;
    /// let (mut sim, reports) = Simulation::from_description(&description)?;
    /// assert!(reports.iter().all(|r| r.is_empty()));
    /// let id = sim.car_ids().next().unwrap();
    /// assert_eq!(sim.world().vehicle(id)?.spec().mounting, sim::Mounting::Joints);
    /// while !sim.is_over() {
    ///     sim.step()?;
    /// }
    /// assert_eq!(sim.world().time_ms(), 2000);
    /// # Ok::<(), Box<dyn std::error::Error>>(())
    /// ```
    ///
    /// # Errors
    /// The [`SimError`] of a world or car that cannot be built, or of a `duration` that
    /// [`Simulation::set_duration`] refuses.
    pub fn from_description(
        description: &WorldDescription,
    ) -> Result<(Simulation, Vec<ParamReport>), SimError> {
        let mut sim = Simulation::new(World::new(description.config.clone())?);
        sim.set_duration(description.duration)?;
        let mut reports = Vec::with_capacity(description.cars.len());
        for car in &description.cars {
            let (_, report) = sim.add_car(CarBuilder::from(car))?;
            reports.push(report);
        }
        if let Some(robot) = &description.robot {
            sim.add_robot(robot)?;
        }
        for (object, appearance) in description.appearances.iter() {
            sim.set_appearance(*object, appearance.clone())?;
        }
        sim.set_replay_overlay(description.replay_overlay);
        sim.set_gps_frame(description.gps)?;
        sim.loaded = Some(Box::new(sim.snapshot()));
        Ok((sim, reports))
    }

    /// Builds the car of `car` and gives it a driver running at the world's `basicTimeStep`;
    /// returns its handle and the report of its parameters' validation (an invalid field takes
    /// its Webots default, as `Driver::new` does).
    ///
    /// # Errors
    /// [`SimError::Param`] naming a tyre coefficient or body field the car cannot be built
    /// with; [`SimError::BrakeBalance`]; [`SimError::DuplicateName`] for a name already taken;
    /// [`SimError::Recording`] once a recording has started.
    pub fn add_car(&mut self, car: CarBuilder) -> Result<(VehicleId, ParamReport), SimError> {
        let built = car.build(self.world.config().basic_time_step_ms)?;
        let name = self.unique_name(built.name, built.default_name)?;
        self.refuse_while_recording(&name)?;
        let id = self.world.add_vehicle(built.spec, built.placement)?;
        self.world
            .vehicle_mut(id)?
            .set_radar_cross_section(built.radar_cross_section)?;
        let mut devices = built.devices;
        devices.start_at(self.world.time_ms());
        let energy = built.energy.map(|(params, soc)| {
            let engine = built.driver.params().engine;
            EnergyMeter::new(params, engine, soc, built.powers_controller)
        });
        self.cars.push(Controlled {
            id,
            driver: built.driver,
            name,
            sampled: false,
            devices,
            keyboard: built.keyboard,
            follower: None,
            energy,
            battery_sensor: BatterySensor::default(),
        });
        Ok((id, built.report))
    }

    /// Adds the DifferentialWheels robot of `robot` (its parameters, mode, placement, name and
    /// `radarCrossSection`).
    ///
    /// # Errors
    /// [`SimError::Param`] for an invalid field; [`SimError::DuplicateName`];
    /// [`SimError::Recording`] once a recording has started.
    pub fn add_robot(&mut self, robot: &RobotDescription) -> Result<RobotId, SimError> {
        // Checked before the robot is added, so that a refused one leaves nothing behind.
        let rcs = ParamError::non_negative("radarCrossSection", robot.radar_cross_section)?;
        let id =
            self.add_differential_wheels(robot.params, robot.mode, robot.placement, &robot.name)?;
        self.world.robot_mut(id)?.set_radar_cross_section(rcs)?;
        Ok(id)
    }

    /// Adds a DifferentialWheels robot named `name` (see [`World::add_differential_wheels`]).
    ///
    /// # Errors
    /// As [`Simulation::add_robot`].
    pub fn add_differential_wheels(
        &mut self,
        params: DifferentialWheelsParams,
        mode: RobotMode,
        placement: RobotPlacement,
        name: &str,
    ) -> Result<RobotId, SimError> {
        let name = self.unique_name(Some(name.to_string()), "DifferentialWheels")?;
        self.refuse_while_recording(&name)?;
        let id = self
            .world
            .add_differential_wheels(params, mode, placement)?;
        self.robots.push(Named { id, name });
        Ok(id)
    }

    /// `name`, refused if taken; without a name, `default` or, if that is taken, `default-2`,
    /// `default-3`…
    fn unique_name(&self, name: Option<String>, default: &str) -> Result<String, SimError> {
        let taken = |n: &str| {
            self.cars.iter().any(|c| c.name == n) || self.robots.iter().any(|r| r.name == n)
        };
        match name {
            Some(n) if n.is_empty() => self.unique_name(None, default),
            Some(n) if taken(&n) => Err(SimError::DuplicateName(n)),
            Some(n) => Ok(n),
            None => Ok((1..)
                .map(|k| {
                    if k == 1 {
                        default.to_string()
                    } else {
                        format!("{default}-{k}")
                    }
                })
                .find(|n| !taken(n))
                .unwrap_or_default()),
        }
    }

    /// A recording follows the vehicles it started with; a vehicle added later would be
    /// missing from it.
    fn refuse_while_recording(&self, name: &str) -> Result<(), SimError> {
        match &self.recording {
            Some(_) => Err(SimError::Recording(name.to_string())),
            None => Ok(()),
        }
    }

    fn car(&self, id: VehicleId) -> Result<&Controlled, SimError> {
        self.cars
            .iter()
            .find(|c| c.id == id)
            .ok_or(SimError::UnknownVehicle(id.index()))
    }

    /// The driven cars, in the order they were added.
    pub fn car_ids(&self) -> impl Iterator<Item = VehicleId> + '_ {
        self.cars.iter().map(|c| c.id)
    }

    /// The robots added through the simulation, in order.
    pub fn robot_ids(&self) -> impl Iterator<Item = RobotId> + '_ {
        self.robots.iter().map(|r| r.id)
    }

    /// The name of car `id`.
    pub fn car_name(&self, id: VehicleId) -> Result<&str, SimError> {
        self.car(id).map(|c| c.name.as_str())
    }

    /// The name of robot `id`.
    pub fn robot_name(&self, id: RobotId) -> Result<&str, SimError> {
        self.robots
            .iter()
            .find(|r| r.id == id)
            .map(|r| r.name.as_str())
            .ok_or(SimError::UnknownRobot(id.index()))
    }

    /// The driver of car `id`.
    pub fn driver(&self, id: VehicleId) -> Result<&Driver<f64>, SimError> {
        self.car(id).map(|c| &c.driver)
    }

    /// The driver of car `id`, to set throttle, steering, gear… (Webots: `wbu_driver_set_*`,
    /// `wbu_car_set_*`). As in Webots, where the steering setters move the steering motors at
    /// once, the steering they command acts from the next step, also a physics-only one
    /// ([`Simulation::step_physics`]).
    pub fn driver_mut(&mut self, id: VehicleId) -> Result<&mut Driver<f64>, SimError> {
        self.cars
            .iter_mut()
            .find(|c| c.id == id)
            .map(|c| &mut c.driver)
            .ok_or(SimError::UnknownVehicle(id.index()))
    }

    /// What Webots' `wbu_car_init` does to car `id`: the driver's present commands act on the
    /// car at once, so that its driven wheels are held at 0 rad/s (velocity mode) until a
    /// control mode is chosen, even through physics-only steps.
    pub fn start_car_library(&mut self, id: VehicleId) -> Result<(), SimError> {
        let commands = *self.driver(id)?.commands();
        self.world.vehicle_mut(id)?.set_commands(&commands);
        Ok(())
    }

    /// The world.
    pub fn world(&self) -> &World {
        &self.world
    }

    /// The world, e.g. to command DifferentialWheels robots or cars without a driver.
    pub fn world_mut(&mut self) -> &mut World {
        &mut self.world
    }

    /// The simulated time after which the run is over (s), if any (a world file's `duration`).
    pub fn duration(&self) -> Option<f64> {
        self.duration
    }

    /// Sets the simulated time after which the run is over (s, > 0 and at most
    /// [`MAX_DURATION`]), or none.
    ///
    /// # Errors
    /// [`ParamError`] naming `duration` and the value.
    pub fn set_duration(&mut self, duration: Option<f64>) -> Result<(), ParamError> {
        if let Some(d) = duration {
            ParamError::check("duration", d, DURATION_RULE, is_duration)?;
        }
        self.duration = duration;
        Ok(())
    }

    /// True once the `duration` has elapsed or the physics has failed: a Webots controller's
    /// step returns -1 from then on. The duration is compared in ms with a margin far below
    /// one step, so that a duration that is a whole number of steps ends exactly on that step.
    pub fn is_over(&self) -> bool {
        let elapsed_ms = self.world.time_ms() as f64;
        self.world.failure().is_some()
            || self
                .duration
                .is_some_and(|d| elapsed_ms >= d * 1000.0 - 1e-6)
    }

    /// Why the physics failed, if it did (the world steps no more).
    pub fn failure(&self) -> Option<&SimError> {
        self.world.failure()
    }

    /// What car `id`'s powertrain did since it was added, and its battery's charge; `None`
    /// for a car without energy accounting ([`CarBuilder::energy`]).
    ///
    /// # Errors
    /// [`SimError::UnknownVehicle`] for an unknown car.
    pub fn energy(&self, id: VehicleId) -> Result<Option<EnergyReport>, SimError> {
        Ok(self.car(id)?.energy.as_ref().map(|m| *m.report()))
    }

    /// The telemetry of car `id` after the last step.
    pub fn telemetry(&self, id: VehicleId) -> Result<CarTelemetry, SimError> {
        let driver = &self.car(id)?.driver;
        let state = *self.world.vehicle(id)?.state();
        let torque = driver.control_mode() == ControlMode::Torque;
        Ok(CarTelemetry {
            time: self.world.time(),
            state,
            speed: state.forward_speed,
            estimated_speed_kmh: driver.current_speed(),
            rpm: if torque { driver.rpm().ok() } else { None },
            gear: if torque { driver.gear().ok() } else { None },
            control_mode: driver.control_mode(),
            throttle: driver.throttle(),
            brake: driver.brake_intensity(),
        })
    }

    /// Starts recording the run named `run` (the `scenario` column of its telemetry): every
    /// car and robot now gets a sample now and after every step, in bounded memory
    /// ([`TelemetryLog`]), and the replay a keyframe at most 60 times per simulated second.
    /// [`Simulation::report`] and [`Simulation::save`] give what was recorded. Recording
    /// again starts afresh.
    pub fn record(&mut self, run: &str) {
        self.record_with(run, Retention::All);
    }

    /// [`Simulation::record`] keeping what `retention` says of the vehicles' samples: all,
    /// the last `n` or only the last (whose [`TelemetryLog::last`] is always there). A
    /// bounded recording (not [`Retention::All`]) keeps its memory whatever the run's length:
    /// it records no device rows (`devices.csv` stays empty) and the replay only its first
    /// frame; its metrics are those of the samples it holds.
    ///
    /// ```
    /// use sim::telemetry::Retention;
    /// use sim::{CarBuilder, Simulation, World, WorldConfig};
    /// use std::num::NonZeroUsize;
    /// use vehicle_model::Model;
    /// let mut sim = Simulation::new(World::new(WorldConfig::default())?);
    /// let (id, _) = sim.add_car(CarBuilder::of_model(Model::BmwX5))?;
    /// sim.record_with("run", Retention::Last(NonZeroUsize::new(10).unwrap()));
    /// for _ in 0..100 {
    ///     sim.step()?;
    /// }
    /// let log = sim.car_log(id).unwrap();
    /// // The t = 0 sample and one per step were recorded, the last 10 are held.
    /// assert_eq!((log.recorded(), log.len()), (101, 10));
    /// assert_eq!(log.last().unwrap()[0], 1.0); // time_s of the last sample
    /// # Ok::<(), sim::SimError>(())
    /// ```
    pub fn record_with(&mut self, run: &str, retention: Retention) {
        self.recording = Some(Recording::start(self, run, retention));
    }

    /// True while recording.
    pub fn is_recording(&self) -> bool {
        self.recording.is_some()
    }

    /// The telemetry log of car `id`, if recording.
    pub fn car_log(&self, id: VehicleId) -> Option<&TelemetryLog> {
        let name = self.car(id).ok()?.name.as_str();
        self.recording.as_ref()?.log(name)
    }

    /// The run recorded so far as a report ([`Simulation::record`]): its telemetry (read back
    /// from the logs), each vehicle's motion metrics (and, for several cars, the smallest gap
    /// and first touch), its replay, and its notes; `None` if not recording.
    ///
    /// # Errors
    /// The error of reading a log's temporary file back.
    pub fn report(&self, world: &str) -> Option<std::io::Result<RunReport>> {
        self.recording.as_ref().map(|r| r.report(self, world, true))
    }

    /// Writes the run recorded so far into `dir` ([`report::write_data`](
    /// crate::report::write_data): `telemetry.csv`, `metrics.json` with `world_warnings`,
    /// `replay.glb`), streaming the telemetry from the logs, `devices.csv` (every value the
    /// enabled devices sampled: time, car, device, quantity, value), and the last image of every
    /// camera that took one and every display as `<car>-<device>.png` (characters other
    /// than letters, digits, `-` and `_` written `_`); `world` names the world in
    /// `metrics.json`. Returns the paths written; nothing if not recording.
    ///
    /// # Errors
    /// The first file that could not be written, with its path.
    pub fn save(
        &self,
        world: &str,
        world_warnings: &[String],
        dir: &Path,
    ) -> Result<Vec<PathBuf>, OutputError> {
        let Some(r) = &self.recording else {
            return Ok(Vec::new());
        };
        let mut written = r.save(self, world, world_warnings, dir)?;
        written.extend(self.save_images(dir)?);
        Ok(written)
    }
}
