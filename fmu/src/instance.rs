//! One FMU instance in safe Rust: its world, the FMI 2.0 co-simulation state machine, the
//! inputs and parameters as last set, and the messages for the tool's logger. The C entry
//! points ([`crate::fmi2`]) only marshal to and from it.

use std::path::{Path, PathBuf};

use sim::world_file::{self, KeyPath, WorldDescription};
use sim::{Simulation, VehicleId};
use vehicle_model::IndicatorState;

use crate::variables::{
    self, BRAKE_INTENSITY, CONTROL_MODE, CRUISING_SPEED, Causality, GEAR, INDICATOR, Kind,
    STEERING_ANGLE, THROTTLE,
};

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

/// Where an instance is in FMI 2.0's co-simulation state machine (FMI 2.0.3, §4.2.4).
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

/// A saved instance state (`fmi2FMUstate`): the world's snapshot and the driver inputs and
/// phase around it.
#[derive(Clone)]
pub struct State {
    snapshot: sim::Snapshot,
    phase: Phase,
    inputs: [f64; 7],
    applied: Option<[f64; 7]>,
}

/// One instance.
pub struct Instance {
    /// The instance name the tool gave, for its logger.
    pub name: String,
    /// The world file's path in the resources.
    world_path: PathBuf,
    /// Its text.
    world_text: String,
    /// Its description with the parameters as set.
    description: WorldDescription,
    simulation: Simulation,
    car: VehicleId,
    phase: Phase,
    /// Inputs by value reference (integers stored as f64 exactly).
    inputs: [f64; 7],
    /// The inputs the driver last received, `None` before the first step.
    applied: Option<[f64; 7]>,
    /// Parameters set by the tool, by value reference.
    parameters: Vec<(u32, f64)>,
    /// Messages for the logger, taken by [`Instance::take_messages`].
    messages: Vec<(Severity, String)>,
}

impl Instance {
    /// Loads `resources/world.toml` from the directory `resources` and builds its world.
    ///
    /// # Errors
    /// Why the world cannot be loaded, built or driven, as a sentence.
    pub fn new(name: &str, resources: &Path) -> Result<Instance, Refused> {
        let world_path = resources.join(WORLD_FILE);
        let world_text = std::fs::read_to_string(&world_path)
            .map_err(|e| format!("cannot read the world {}: {e}", world_path.display()))?;
        let description = parse(&world_path, &world_text, &[])?;
        let (simulation, car) = build(&description)?;
        Ok(Instance {
            name: name.to_string(),
            world_path,
            world_text,
            description,
            simulation,
            car,
            phase: Phase::Instantiated,
            inputs: core::array::from_fn(|r| variables::input_start(r as u32)),
            applied: None,
            parameters: Vec::new(),
            messages: Vec::new(),
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

    /// `fmi2EnterInitializationMode`.
    ///
    /// # Errors
    /// Outside [`Phase::Instantiated`].
    pub fn enter_initialisation(&mut self) -> Result<(), Refused> {
        self.expect(&[Phase::Instantiated], "fmi2EnterInitializationMode")?;
        self.phase = Phase::Initialising;
        Ok(())
    }

    /// `fmi2ExitInitializationMode`: rebuilds the world with the parameters set.
    ///
    /// # Errors
    /// Outside [`Phase::Initialising`], or a parameter the world refuses (named with its
    /// value and rule).
    pub fn exit_initialisation(&mut self) -> Result<(), Refused> {
        self.expect(&[Phase::Initialising], "fmi2ExitInitializationMode")?;
        if !self.parameters.is_empty() {
            let mut numbers = Vec::with_capacity(self.parameters.len());
            for &(reference, value) in &self.parameters {
                let name = variables::find(reference, Kind::Real).map_or("", |v| v.name);
                let key = KeyPath::parse(name).map_err(|e| e.to_string());
                match key {
                    Ok(key) => numbers.push((key, value)),
                    Err(e) => return Err(self.refuse(e)),
                }
            }
            let built = parse(&self.world_path, &self.world_text, &numbers)
                .and_then(|d| build(&d).map(|(s, c)| (d, s, c)));
            match built {
                Ok((description, simulation, car)) => {
                    self.description = description;
                    self.simulation = simulation;
                    self.car = car;
                }
                Err(e) => return Err(self.refuse(e)),
            }
        }
        self.phase = Phase::Stepping;
        Ok(())
    }

    /// `fmi2Terminate`.
    ///
    /// # Errors
    /// Outside [`Phase::Stepping`].
    pub fn terminate(&mut self) -> Result<(), Refused> {
        self.expect(&[Phase::Stepping], "fmi2Terminate")?;
        self.phase = Phase::Terminated;
        Ok(())
    }

    /// `fmi2Reset`: the instance as `fmi2Instantiate` left it.
    ///
    /// # Errors
    /// The world can no longer be built (it could at instantiation: only if its file changed).
    pub fn reset(&mut self) -> Result<(), Refused> {
        match Instance::new(
            &self.name,
            self.world_path.parent().unwrap_or(Path::new(".")),
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

    /// `fmi2SetReal` / `fmi2SetInteger` of one variable.
    ///
    /// # Errors
    /// An unknown reference, an output, a parameter after initialisation, a non-finite value.
    pub fn set(&mut self, reference: u32, kind: Kind, value: f64) -> Result<(), Refused> {
        let Some(v) = variables::find(reference, kind) else {
            return Err(self.refuse(format!(
                "no {kind:?} variable has value reference {reference}"
            )));
        };
        if !value.is_finite() {
            return Err(self.refuse(format!("{} = {value}: must be finite", v.name)));
        }
        match v.causality {
            Causality::Output => Err(self.refuse(format!("{} is an output", v.name))),
            Causality::Parameter => {
                if self.phase != Phase::Instantiated && self.phase != Phase::Initialising {
                    return Err(self.refuse(format!(
                        "{} is a parameter: it is set before fmi2ExitInitializationMode",
                        v.name
                    )));
                }
                self.parameters.retain(|(r, _)| *r != reference);
                self.parameters.push((reference, value));
                Ok(())
            }
            Causality::Input => {
                if self.phase == Phase::Terminated {
                    return Err(self.refuse(format!("{} is set after fmi2Terminate", v.name)));
                }
                self.inputs[reference as usize] = value;
                Ok(())
            }
        }
    }

    /// `fmi2GetReal` / `fmi2GetInteger` of one variable.
    ///
    /// # Errors
    /// An unknown reference.
    pub fn get(&mut self, reference: u32, kind: Kind) -> Result<f64, Refused> {
        let Some(v) = variables::find(reference, kind) else {
            return Err(self.refuse(format!(
                "no {kind:?} variable has value reference {reference}"
            )));
        };
        let value = match v.causality {
            Causality::Input => Some(self.inputs[reference as usize]),
            Causality::Parameter => self
                .parameters
                .iter()
                .find(|(r, _)| *r == reference)
                .map(|(_, value)| *value)
                .or_else(|| variables::parameter_of(&self.description, reference)),
            Causality::Output => match self.simulation.telemetry(self.car) {
                Ok(t) => variables::output_of(&t, reference),
                Err(e) => return Err(self.refuse(e.to_string())),
            },
        };
        value.ok_or_else(|| self.refuse(format!("{} has no value", v.name)))
    }

    /// `fmi2GetFMUstate`: everything a later [`Instance::set_state`] needs to continue
    /// exactly as this instance would from here.
    pub fn state(&self) -> State {
        State {
            snapshot: self.simulation.snapshot(),
            phase: self.phase,
            inputs: self.inputs,
            applied: self.applied,
        }
    }

    /// `fmi2SetFMUstate`: back to `state`, which this instance saved since its last
    /// initialisation (or reset).
    ///
    /// # Errors
    /// A state of another instance or of before a reset (the world refuses it; nothing changes).
    pub fn set_state(&mut self, state: &State) -> Result<(), Refused> {
        if let Err(e) = self.simulation.restore(&state.snapshot) {
            return Err(self.refuse(format!("fmi2SetFMUstate: {e}")));
        }
        self.phase = state.phase;
        self.inputs = state.inputs;
        self.applied = state.applied;
        Ok(())
    }

    /// The simulated time (s).
    pub fn time(&self) -> f64 {
        self.simulation.world().time()
    }

    /// `fmi2DoStep` from `at` (s) over `step` (s): a whole number of `basicTimeStep`s, the
    /// inputs handed to the driver first.
    ///
    /// # Errors
    /// Outside [`Phase::Stepping`], a communication point that is not the FMU's time, a step
    /// that is not a positive multiple of `basicTimeStep`, or a physics failure (the instance
    /// is then terminated).
    pub fn do_step(&mut self, at: f64, step: f64) -> Result<(), Refused> {
        self.expect(&[Phase::Stepping], "fmi2DoStep")?;
        let dt = self.simulation.world().dt();
        let now = self.time();
        // The tool adds its steps in floating point; 1 µs is far below any basicTimeStep.
        if !at.is_finite() || (at - now).abs() > 1e-6 {
            return Err(self.refuse(format!(
                "fmi2DoStep from t = {at} s, but the FMU is at t = {now} s"
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
        for _ in 0..steps as u64 {
            if let Err(e) = self.simulation.step() {
                self.phase = Phase::Terminated;
                return Err(self.refuse(format!("the simulation failed: {e}")));
            }
        }
        Ok(())
    }

    /// Hands the inputs that changed since the last step to the driver (all of them before
    /// the first), as a controller calls the driver library's setters; its warnings (a value
    /// clamped) go to the logger.
    fn apply_inputs(&mut self) {
        let inputs = self.inputs;
        let first = self.applied.is_none();
        let previous = self.applied.unwrap_or([f64::NAN; 7]);
        let changed =
            |r: u32| first || previous[r as usize].to_bits() != inputs[r as usize].to_bits();
        let Ok(driver) = self.simulation.driver_mut(self.car) else {
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

/// The world of `text` at `path` with `numbers` set at their keys.
fn parse(path: &Path, text: &str, numbers: &[(KeyPath, f64)]) -> Result<WorldDescription, Refused> {
    world_file::parse_with_numbers(&path.display().to_string(), text, numbers)
        .map_err(|e| e.to_string())
}

/// Refuses a world the FMU cannot drive: anything but exactly one car (`name` names the world
/// in the message). The packager checks it too, so an FMU is never built for such a world.
pub(crate) fn check_one_car(description: &WorldDescription, name: &str) -> Result<(), Refused> {
    if description.cars.len() == 1 && description.robot.is_none() {
        return Ok(());
    }
    Err(format!(
        "the world {name} has {} cars{}: the FMU drives a world with exactly one car",
        description.cars.len(),
        if description.robot.is_some() {
            " and a robot"
        } else {
            ""
        }
    ))
}

/// The simulation of `description` and the car the FMU drives: its only car.
fn build(description: &WorldDescription) -> Result<(Simulation, VehicleId), Refused> {
    check_one_car(description, &description.source)?;
    let (simulation, _) = Simulation::from_description(description).map_err(|e| e.to_string())?;
    let car = simulation
        .car_ids()
        .next()
        .ok_or_else(|| "the world has no car".to_string())?;
    Ok((simulation, car))
}
