//! The test rig of the car scenarios: a [`Simulation`] with one car and its driver library,
//! stepped as a Webots controller steps (`while (wbu_driver_step() != -1) { … }`), recording
//! every step.

use vehicle_model::Driver;

use crate::placement::car_placement;
use crate::replay::Recorder;
use crate::simulation::Simulation;
use crate::telemetry::{Sample, Telemetry};
use crate::vehicle::{VehicleId, VehicleSpec, VehicleState};
use crate::world::World;
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
    state: VehicleState,
    spec: VehicleSpec,
    samples: Vec<Sample>,
    notes: Vec<String>,
    guides: Vec<Vec<[f64; 2]>>,
    recorder: Recorder,
    next_progress: f64,
    /// The world's time limit for this scenario (s).
    pub(crate) limit: f64,
    /// The simulated time the scenario is expected to take, for the progress display (s).
    pub(crate) expected: f64,
}

impl CarRig {
    /// Builds the world of `desc` with the car of `car` on its tyres at its
    /// `translation`/`rotation`.
    pub(crate) fn new(
        desc: &WorldDescription,
        car: &CarDescription,
        limit: f64,
        expected: f64,
    ) -> Result<Self, ScenarioError> {
        let mut sim = Simulation::new(World::new(desc.config.clone())?);
        let mut notes = Vec::new();
        let [ax, ay, _, angle] = car.params.rotation;
        if angle != 0.0 && (ax != 0.0 || ay != 0.0) {
            notes.push(format!(
                "the car's rotation {:?} tilts it: only its heading is used, it starts level",
                car.params.rotation
            ));
        }
        // The world file validated the params already: the report is empty.
        let (id, _) = sim.add_car_with(
            car.params.clone(),
            &car.tyre,
            car.mounting,
            car_placement(&car.params),
        )?;
        let vehicle = sim.world().vehicle(id)?;
        let (state, spec) = (*vehicle.state(), *vehicle.spec());
        let recorder = Recorder::for_simulation(&sim);
        Ok(CarRig {
            sim,
            id,
            state,
            spec,
            samples: Vec::new(),
            notes,
            guides: Vec::new(),
            recorder,
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

    /// The step length (s).
    pub(crate) fn time_step(&self) -> f64 {
        self.sim.world().dt()
    }

    /// The ground's Coulomb friction and the magnitude of gravity (m/s²).
    pub(crate) fn ground(&self) -> (f64, f64) {
        let c = self.sim.world().config();
        (c.ground_friction, -c.gravity[2])
    }

    /// The car's heading (rad).
    pub(crate) fn yaw(&self) -> f64 {
        self.state.roll_pitch_yaw[2]
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
    /// the world advances one `basicTimeStep` with them, and the new state is recorded.
    pub(crate) fn step(&mut self, progress: &mut dyn FnMut(f64, f64)) -> Result<(), ScenarioError> {
        self.sim.step()?;
        self.recorder.sample(self.sim.world());
        let t = self.sim.telemetry(self.id)?;
        self.state = t.state;
        let d = self.sim.driver(self.id)?;
        let s = &t.state;
        self.samples.push(Sample {
            time: t.time,
            x: s.position[0],
            y: s.position[1],
            yaw: s.roll_pitch_yaw[2],
            speed_kmh: t.speed * KMH,
            driver_speed_kmh: Some(t.estimated_speed_kmh).filter(|v| v.is_finite()),
            rpm: t.rpm,
            gear: t.gear.map(|g| g.number()),
            steering_command: Some(d.commanded_steering_angle()),
            steering: Some(d.steering_angle()),
            throttle: Some(t.throttle),
            brake: Some(t.brake),
            lateral_accel: Some(s.lateral_acceleration),
            longitudinal_accel: Some(s.longitudinal_acceleration),
            tyres: Some(s.tyres),
        });
        if t.time >= self.next_progress {
            progress(t.time, self.expected);
            self.next_progress = t.time + PROGRESS_PERIOD;
        }
        Ok(())
    }

    /// Adds a line of the course (m, world frame) to draw under the trajectory.
    pub(crate) fn guide(&mut self, line: Vec<[f64; 2]>) {
        self.guides.push(line);
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
            scenario,
            metrics,
            sim_seconds: self.sim.world().time(),
            telemetry: Telemetry {
                scenario: scenario.name().to_string(),
                samples: self.samples,
            },
            notes: self.notes,
            guides: self.guides,
            replay: self.recorder.finish(self.sim.world()),
        }
    }
}
