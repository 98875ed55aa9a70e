//! The test rig of the car scenarios: a [`Simulation`] with one car and its driver library,
//! stepped as a Webots controller steps (`while (wbu_driver_step() != -1) { … }`), recording
//! every step.

use vehicle_model::Driver;

use crate::error::SimError;
use crate::replay::Recorder;
use crate::simulation::Simulation;
use crate::telemetry::{DeviceLog, Sample, Telemetry, VehicleKind};
use crate::vehicle::{VehicleId, VehicleSpec, VehicleState};
use crate::world_file::{CarDescription, WorldDescription};

use super::{Metric, Scenario, ScenarioError, ScenarioResult};

/// km/h per m/s.
pub(crate) use vehicle_model::KMH_PER_MS as KMH;

/// Simulated time between two progress reports (s).
const PROGRESS_PERIOD: f64 = 0.5;

/// A world with one car driven by a [`Driver`].
pub(crate) struct CarRig {
    sim: Simulation,
    id: VehicleId,
    name: String,
    state: VehicleState,
    spec: VehicleSpec,
    samples: Vec<Sample>,
    notes: Vec<String>,
    guides: Vec<Vec<[f64; 2]>>,
    cones: Vec<[f64; 2]>,
    recorder: Recorder,
    /// The values the car's enabled devices sampled, for `devices.csv`.
    devices: DeviceLog,
    next_progress: f64,
    /// The world's time limit for this scenario (s).
    pub(crate) limit: f64,
    /// The simulated time the scenario is expected to take, for the progress display (s).
    pub(crate) expected: f64,
}

impl CarRig {
    /// Builds the world of `desc` (whose car is `car`), as described.
    pub(crate) fn new(
        desc: &WorldDescription,
        car: &CarDescription,
        limit: f64,
        expected: f64,
    ) -> Result<Self, ScenarioError> {
        // The world as every front-end builds it; the scenarios drive worlds of one car
        // (`Scenario::check`), so `car` is its only one.
        let (sim, _) = Simulation::from_description(desc)?;
        let id = sim
            .car_ids()
            .find(|&id| sim.car_name(id).is_ok_and(|n| n == car.name))
            .ok_or(SimError::UnknownVehicle(0))?;
        let vehicle = sim.world().vehicle(id)?;
        let (state, spec) = (*vehicle.state(), *vehicle.spec());
        let samples = vec![Sample::of_car(&sim, id)?];
        let recorder = Recorder::for_simulation(&sim);
        Ok(CarRig {
            sim,
            id,
            name: car.name.clone(),
            state,
            spec,
            samples,
            notes: Vec::new(),
            guides: Vec::new(),
            cones: Vec::new(),
            recorder,
            devices: DeviceLog::new(),
            next_progress: 0.0,
            limit,
            expected,
        })
    }

    /// The driver library, as a controller sees it.
    pub(crate) fn driver(&self) -> Result<&Driver<f64>, ScenarioError> {
        Ok(self.sim.driver(self.id)?)
    }

    /// The driver library, to command the car (`wbu_driver_set_*`).
    pub(crate) fn driver_mut(&mut self) -> Result<&mut Driver<f64>, ScenarioError> {
        Ok(self.sim.driver_mut(self.id)?)
    }

    /// Simulated time (s).
    pub(crate) fn time(&self) -> f64 {
        self.sim.world().time()
    }

    /// The car's measured state after the last step.
    pub(crate) fn state(&self) -> &VehicleState {
        &self.state
    }

    /// What the car was built from.
    pub(crate) fn spec(&self) -> &VehicleSpec {
        &self.spec
    }

    /// The simulation and the car in it, for a driver written for any car of a simulation
    /// (the drive-cycle follower).
    pub(crate) fn simulation_mut(&mut self) -> (&mut Simulation, VehicleId) {
        (&mut self.sim, self.id)
    }

    /// The simulation and the car in it.
    pub(crate) fn simulation(&self) -> (&Simulation, VehicleId) {
        (&self.sim, self.id)
    }

    /// The step length (s).
    pub(crate) fn time_step(&self) -> f64 {
        self.sim.world().dt()
    }

    /// The ground's Coulomb friction and the magnitude of gravity (m/s²).
    pub(crate) fn ground(&self) -> (f64, f64) {
        let c = self.sim.world().config();
        (c.ground_friction, -c.gravity.z)
    }

    /// The car's heading (rad).
    pub(crate) fn yaw(&self) -> f64 {
        self.state.roll_pitch_yaw.yaw
    }

    /// The car's speed along its heading (m/s).
    pub(crate) fn speed(&self) -> f64 {
        self.state.forward_speed
    }

    /// True while the scenario may go on.
    pub(crate) fn running(&self) -> bool {
        self.time() < self.limit - 1e-9
    }

    /// One `wbu_driver_step`: the driver turns the readings of the last step into commands,
    /// the world advances one `basicTimeStep` with them, and the new state is recorded (after
    /// the state at time 0, recorded when the rig was built).
    pub(crate) fn step(&mut self, progress: &mut dyn FnMut(f64, f64)) -> Result<(), ScenarioError> {
        self.sim.step()?;
        self.recorder.sample(self.sim.world());
        self.sim.log_sampled_devices(&mut self.devices);
        let sample = Sample::of_car(&self.sim, self.id)?;
        self.state = *self.sim.world().vehicle(self.id)?.state();
        let t = sample.time;
        self.samples.push(sample);
        if t >= self.next_progress {
            progress(t, self.expected);
            self.next_progress = t + PROGRESS_PERIOD;
        }
        Ok(())
    }

    /// Adds a line of the course (m, world frame) to draw under the trajectory.
    pub(crate) fn guide(&mut self, line: Vec<[f64; 2]>) {
        self.guides.push(line);
    }

    /// Adds a cone of the course (m, world frame).
    pub(crate) fn cone(&mut self, at: [f64; 2]) {
        self.cones.push(at);
    }

    /// Adds a message for the user.
    pub(crate) fn note(&mut self, message: String) {
        self.notes.push(message);
    }

    /// The samples recorded so far.
    pub(crate) fn samples(&self) -> &[Sample] {
        &self.samples
    }

    /// The scenario's result.
    pub(crate) fn finish(self, scenario: Scenario, metrics: Vec<Metric>) -> ScenarioResult {
        ScenarioResult {
            name: scenario.name().to_string(),
            metrics,
            sim_seconds: self.sim.world().time(),
            telemetry: vec![Telemetry {
                scenario: scenario.name().to_string(),
                vehicle: self.name,
                kind: VehicleKind::Car,
                samples: self.samples,
            }],
            notes: self.notes,
            guides: self.guides,
            cones: self.cones,
            replay: self.recorder.finish(self.sim.world()),
            devices: self.sim.device_readings(self.devices),
            unfinished: None,
        }
    }
}
