//! One FMU instance in safe Rust: its world, the co-simulation state machine (the same for
//! FMI 2.0 and 3.0 as this FMU uses them: no event mode, no intermediate updates), the inputs
//! and parameters as last set, the journal of the run, and the messages for the tool's logger.
//! The C entry points ([`crate::fmi2`], [`crate::fmi3`]) only marshal to and from it.

use std::path::{Path, PathBuf};

use sim::traffic::TrafficNote;
use vehicle_model::IndicatorState;

use crate::devices::{self, DeviceOutput};
use crate::journal::{INPUTS, Journal};
use crate::variables::{
    self, BRAKE_INTENSITY, CONTROL_MODE, CRUISING_SPEED, Causality, GEAR, INDICATOR, Kind,
    STEERING_ANGLE, THROTTLE,
};
use crate::world::{self, Built};

mod state;
pub use state::State;

/// The file of the world in the FMU's `resources` directory.
pub const WORLD_FILE: &str = "world.toml";

/// The log categories the model description declares, in the order of [`Severity`].
pub const LOG_CATEGORIES: [&str; 2] = ["logStatusWarning", "logStatusError"];

/// How bad a message is: an `fmi2Warning` or an `fmi2Error`.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Severity {
    /// The call did what it could (a value clamped as the driver library does).
    Warning,
    /// The call was refused.
    Error,
}

/// A refused call: its message, already logged.
pub type Refused = String;

/// The FMI version an instance was created through, for the function names in its messages.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Version {
    /// FMI 2.0 (`fmi2*`).
    Fmi2,
    /// FMI 3.0 (`fmi3*`).
    Fmi3,
}

impl Version {
    /// The C name of `function` (e.g. `DoStep`) in this version.
    pub fn name(self, function: &str) -> String {
        match self {
            Version::Fmi2 => format!("fmi2{function}"),
            Version::Fmi3 => format!("fmi3{function}"),
        }
    }
}

/// Where an instance is in the co-simulation state machine (FMI 2.0.3 §4.2.4; FMI 3.0's
/// without event mode, §4.2.1).
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum Phase {
    /// After `fmi2Instantiate` or `fmi2Reset`: parameters and inputs may be set.
    Instantiated,
    /// Between `fmi2EnterInitializationMode` and `fmi2ExitInitializationMode`.
    Initialising,
    /// Stepping.
    Stepping,
    /// After `fmi2Terminate`, or after a step failed: only reading, reset and freeing.
    Terminated,
}

impl Phase {
    const ALL: [Phase; 4] = [
        Phase::Instantiated,
        Phase::Initialising,
        Phase::Stepping,
        Phase::Terminated,
    ];
}

/// One instance.
pub struct Instance {
    /// The instance name the tool gave, for its logger.
    pub name: String,
    /// The FMI version it was created through.
    version: Version,
    /// The world file's path in the resources.
    world_path: PathBuf,
    /// Its text.
    world_text: String,
    /// The world as built with the parameters set.
    world: Built,
    /// The outputs of the car's devices (value references from 2000).
    device_outputs: Vec<DeviceOutput>,
    phase: Phase,
    /// Inputs by value reference (integers stored as f64 exactly).
    inputs: [f64; INPUTS],
    /// The inputs the driver last received, `None` before the first step.
    applied: Option<[f64; INPUTS]>,
    /// The run since the world was built.
    journal: Journal,
    /// Parameters set by the tool, by value reference.
    parameters: Vec<(u32, f64)>,
    /// Messages for the logger, taken by [`Instance::take_messages`].
    messages: Vec<(Severity, String)>,
    /// The driven car's telemetry since the last step, measured at the first output read:
    /// a tool reads a dozen outputs per step, and each would measure the car again.
    telemetry: Option<sim::CarTelemetry>,
}

impl Instance {
    /// Loads `resources/world.toml` from the directory `resources` and builds its world.
    ///
    /// # Errors
    /// Why the world cannot be loaded, built or driven, as a sentence.
    pub fn new(name: &str, resources: &Path, version: Version) -> Result<Instance, Refused> {
        let world_path = resources.join(WORLD_FILE);
        let world_text = std::fs::read_to_string(&world_path)
            .map_err(|e| format!("cannot read the world {}: {e}", world_path.display()))?;
        let built = world::build(world::parse(&world_path, &world_text)?)?;
        let device_outputs = device_outputs(&built)?;
        Ok(Instance {
            name: name.to_string(),
            version,
            world_path,
            world_text,
            world: built,
            device_outputs,
            phase: Phase::Instantiated,
            inputs: core::array::from_fn(|r| variables::input_start(r as u32)),
            applied: None,
            journal: Journal::default(),
            parameters: Vec::new(),
            messages: Vec::new(),
            telemetry: None,
        })
    }

    /// Where it is in the state machine.
    pub fn phase(&self) -> Phase {
        self.phase
    }

    /// The messages since the last call, oldest first.
    pub fn take_messages(&mut self) -> Vec<(Severity, String)> {
        std::mem::take(&mut self.messages)
    }

    /// Records an error and returns it.
    fn refuse(&mut self, message: String) -> Refused {
        self.messages.push((Severity::Error, message.clone()));
        message
    }

    /// `EnterInitializationMode`.
    ///
    /// # Errors
    /// Outside [`Phase::Instantiated`].
    pub fn enter_initialisation(&mut self) -> Result<(), Refused> {
        self.expect(
            &[Phase::Instantiated],
            &self.version.name("EnterInitializationMode"),
        )?;
        self.phase = Phase::Initialising;
        Ok(())
    }

    /// `ExitInitializationMode`: rebuilds the world with the parameters set.
    ///
    /// # Errors
    /// Outside [`Phase::Initialising`], or a parameter the world refuses (named with its
    /// value and rule).
    pub fn exit_initialisation(&mut self) -> Result<(), Refused> {
        self.expect(
            &[Phase::Initialising],
            &self.version.name("ExitInitializationMode"),
        )?;
        if !self.parameters.is_empty() {
            self.telemetry = None;
            match self.rebuild(&self.parameters) {
                Ok(built) => self.world = built,
                Err(e) => return Err(self.refuse(e)),
            }
        }
        self.phase = Phase::Stepping;
        Ok(())
    }

    /// `Terminate`.
    ///
    /// # Errors
    /// Outside [`Phase::Stepping`].
    pub fn terminate(&mut self) -> Result<(), Refused> {
        self.expect(&[Phase::Stepping], &self.version.name("Terminate"))?;
        self.phase = Phase::Terminated;
        Ok(())
    }

    /// `Reset`: the instance as instantiation left it.
    ///
    /// # Errors
    /// The world can no longer be built (it could at instantiation: only if its file changed).
    pub fn reset(&mut self) -> Result<(), Refused> {
        match Instance::new(
            &self.name,
            self.world_path.parent().unwrap_or(Path::new(".")),
            self.version,
        ) {
            Ok(fresh) => {
                *self = fresh;
                Ok(())
            }
            Err(e) => Err(self.refuse(e)),
        }
    }

    /// Refuses `function` outside `phases`.
    fn expect(&mut self, phases: &[Phase], function: &str) -> Result<(), Refused> {
        if phases.contains(&self.phase) {
            Ok(())
        } else {
            Err(self.refuse(format!(
                "{function} is not allowed in the {:?} state",
                self.phase
            )))
        }
    }

    /// `SetReal`/`SetInteger` (FMI 2) or `SetFloat64`/`SetInt32` (FMI 3) of one variable.
    ///
    /// # Errors
    /// An unknown reference, an output, a parameter after initialisation, a non-finite value.
    pub fn set(&mut self, reference: u32, kind: Kind, value: f64) -> Result<(), Refused> {
        if let Some(o) = self.device_output(reference, kind) {
            let name = o.name.clone();
            return Err(self.refuse(format!("{name} is an output")));
        }
        let Some(v) = variables::find(reference, kind) else {
            return Err(self.refuse(format!(
                "no {kind:?} variable has value reference {reference}"
            )));
        };
        if !value.is_finite() {
            return Err(self.refuse(format!("{} = {value}: must be finite", v.name)));
        }
        match v.causality {
            Causality::Output | Causality::Independent => Err(self.refuse(format!(
                "{} is an {}: the tool reads it",
                v.name,
                if v.causality == Causality::Output {
                    "output"
                } else {
                    "independent variable"
                }
            ))),
            Causality::Parameter => {
                if self.phase != Phase::Instantiated && self.phase != Phase::Initialising {
                    return Err(self.refuse(format!(
                        "{} is a parameter: it is set before {}",
                        v.name,
                        self.version.name("ExitInitializationMode")
                    )));
                }
                self.parameters.retain(|(r, _)| *r != reference);
                self.parameters.push((reference, value));
                Ok(())
            }
            Causality::Input => {
                if self.phase == Phase::Terminated {
                    return Err(self.refuse(format!(
                        "{} is set after {}",
                        v.name,
                        self.version.name("Terminate")
                    )));
                }
                self.inputs[reference as usize] = value;
                Ok(())
            }
        }
    }

    /// `GetReal`/`GetInteger` (FMI 2) or `GetFloat64`/`GetInt32` (FMI 3) of one variable.
    ///
    /// # Errors
    /// An unknown reference.
    pub fn get(&mut self, reference: u32, kind: Kind) -> Result<f64, Refused> {
        if let Some(o) = self.device_output(reference, kind) {
            return match self.world.simulation.devices(self.world.car) {
                Ok(all) => Ok(devices::value(all, o)),
                Err(e) => Err(self.refuse(e.to_string())),
            };
        }
        let Some(v) = variables::find(reference, kind) else {
            return Err(self.refuse(format!(
                "no {kind:?} variable has value reference {reference}"
            )));
        };
        let value = match v.causality {
            Causality::Independent => Some(self.time()),
            Causality::Input => Some(self.inputs[reference as usize]),
            Causality::Parameter => self
                .parameters
                .iter()
                .find(|(r, _)| *r == reference)
                .map(|(_, value)| *value)
                .or_else(|| {
                    variables::parameter_of(&self.world.description, self.world.driven, reference)
                }),
            Causality::Output => {
                if self.telemetry.is_none() {
                    match self.world.simulation.telemetry(self.world.car) {
                        Ok(t) => self.telemetry = Some(t),
                        Err(e) => return Err(self.refuse(e.to_string())),
                    }
                }
                self.telemetry
                    .as_ref()
                    .and_then(|t| variables::output_of(t, reference))
            }
        };
        value.ok_or_else(|| self.refuse(format!("{} has no value", v.name)))
    }

    /// The device output of value reference `reference`, if it is one (they are all Real).
    fn device_output(&self, reference: u32, kind: Kind) -> Option<&DeviceOutput> {
        if kind != Kind::Real {
            return None;
        }
        self.device_outputs
            .iter()
            .find(|o| o.reference == reference)
    }

    /// The simulated time (s).
    pub fn time(&self) -> f64 {
        self.world.simulation.world().time()
    }

    /// `DoStep` from `at` (s) over `step` (s): a whole number of `basicTimeStep`s, the
    /// inputs handed to the driver first.
    ///
    /// # Errors
    /// Outside [`Phase::Stepping`], a communication point that is not the FMU's time, a step
    /// that is not a positive multiple of `basicTimeStep`, or a physics failure (the instance
    /// is then terminated).
    pub fn do_step(&mut self, at: f64, step: f64) -> Result<(), Refused> {
        self.expect(&[Phase::Stepping], &self.version.name("DoStep"))?;
        let dt = self.world.simulation.world().dt();
        let now = self.time();
        // The tool adds its steps in floating point; 1 µs is far below any basicTimeStep.
        if !at.is_finite() || (at - now).abs() > 1e-6 {
            return Err(self.refuse(format!(
                "{} from t = {at} s, but the FMU is at t = {now} s",
                self.version.name("DoStep")
            )));
        }
        let steps = (step / dt).round();
        if !step.is_finite() || steps < 1.0 || (steps * dt - step).abs() > 1e-9 * steps.max(1.0) {
            return Err(self.refuse(format!(
                "communication step {step} s: must be a positive multiple of the world's \
                 basicTimeStep, {dt} s"
            )));
        }
        self.apply_inputs();
        let ran = self.run(steps as u64);
        // The journal holds what ran, a failed step included, so a state saved after a
        // failure replays to the same failure.
        if let Some(inputs) = self.applied {
            self.journal.push(inputs, steps as u64);
        }
        ran.map_err(|e| {
            self.phase = Phase::Terminated;
            self.refuse(e)
        })
    }

    /// Runs `steps` basic steps, the other cars' programmes issuing their commands before
    /// each (their warnings to the logger).
    fn run(&mut self, steps: u64) -> Result<(), Refused> {
        self.telemetry = None;
        for _ in 0..steps {
            for note in self.world.traffic.issue_due(&mut self.world.simulation) {
                let text = match note {
                    TrafficNote::Driver { warning, .. } => format!("another car: {warning}"),
                    TrafficNote::FollowLane { error, .. } => {
                        format!("another car: follow_lane: {error}")
                    }
                };
                self.messages.push((Severity::Warning, text));
            }
            self.world
                .simulation
                .step()
                .map_err(|e| format!("the simulation failed: {e}"))?;
        }
        Ok(())
    }

    /// The world of this instance's file with `parameters` at their keys, built.
    fn rebuild(&self, parameters: &[(u32, f64)]) -> Result<Built, Refused> {
        world::build(world::with_parameters(
            &self.world_path,
            &self.world_text,
            parameters,
            self.world.driven,
        )?)
    }

    /// Hands the inputs that changed since the last step to the driver (all of them before
    /// the first), as a controller calls the driver library's setters; its warnings (a value
    /// clamped) go to the logger.
    fn apply_inputs(&mut self) {
        let inputs = self.inputs;
        let first = self.applied.is_none();
        let previous = self.applied.unwrap_or([f64::NAN; INPUTS]);
        let changed =
            |r: u32| first || previous[r as usize].to_bits() != inputs[r as usize].to_bits();
        let Ok(driver) = self.world.simulation.driver_mut(self.world.car) else {
            return;
        };
        let mut warnings = Vec::new();
        let torque = inputs[CONTROL_MODE as usize] != 0.0;
        if changed(CONTROL_MODE) || changed(THROTTLE) || changed(CRUISING_SPEED) {
            if torque {
                warnings.extend(driver.set_throttle(inputs[THROTTLE as usize]));
            } else {
                // m/s in, km/h to the driver library, as the Webots function takes.
                warnings.extend(driver.set_cruising_speed(inputs[CRUISING_SPEED as usize] * 3.6));
            }
        }
        if torque && (changed(GEAR) || changed(CONTROL_MODE)) {
            warnings.extend(driver.set_gear(inputs[GEAR as usize] as i32));
        }
        if changed(STEERING_ANGLE) {
            warnings.extend(driver.set_steering_angle(inputs[STEERING_ANGLE as usize]));
        }
        if changed(BRAKE_INTENSITY) {
            warnings.extend(driver.set_brake_intensity(inputs[BRAKE_INTENSITY as usize]));
        }
        if changed(INDICATOR) {
            let state = match inputs[INDICATOR as usize] as i32 {
                1 => IndicatorState::Right,
                2 => IndicatorState::Left,
                _ => IndicatorState::Off,
            };
            driver.set_indicator(state);
        }
        self.applied = Some(inputs);
        self.messages.extend(
            warnings
                .into_iter()
                .map(|w| (Severity::Warning, w.to_string())),
        );
    }
}

/// The outputs of the devices of the driven car.
pub(crate) fn device_outputs(world: &Built) -> Result<Vec<DeviceOutput>, Refused> {
    world
        .simulation
        .devices(world.car)
        .map(devices::outputs)
        .map_err(|e| e.to_string())
}
