//! Driving programmes: timed lists of driver commands (`[[vehicle.programme]]` in a world
//! file), named after the Webots driver setters without their `wbu_driver_set_` prefix, and
//! the DifferentialWheels robot's timed wheel speeds (`[[differential_wheels.programme]]`).
//!
//! A programme is applied before each driver step: every step whose `at` (s) has been reached
//! issues its commands, in file order, exactly as a controller calling the setters at that
//! time would.
//!
//! ```
//! use sim::programme::{DriverCommand, Programme, Step};
//! use sim::{Simulation, VehiclePlacement, World, WorldConfig};
//! use vehicle_model::Model;
//!
//! let programme = Programme::new(vec![
//!     Step { at: 0.0, commands: vec![DriverCommand::CruisingSpeed(30.0)] },
//!     Step { at: 0.5, commands: vec![DriverCommand::SteeringAngle(0.1)] },
//! ]);
//! let mut sim = Simulation::new(World::new(WorldConfig::default())?);
//! let (car, _) = sim.add_car(sim::CarBuilder::new(Model::BmwX5.params()).placement(VehiclePlacement::default()))?;
//! let mut cursor = programme.cursor();
//! for _ in 0..100 {
//!     let t = sim.world().time();
//!     for (_, warning) in cursor.apply_due(t, sim.driver_mut(car)?) {
//!         eprintln!("{warning}");
//!     }
//!     sim.step()?;
//! }
//! assert_eq!(sim.driver(car)?.steering_angle().signum(), 1.0); // steering to the right
//! # Ok::<(), sim::SimError>(())
//! ```

use vehicle_model::{Driver, IndicatorState, Warning, WiperMode};

/// One driver command: a Webots `wbu_driver_set_*` call.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum DriverCommand {
    /// `cruising_speed` (km/h): speed mode at this target.
    CruisingSpeed(f64),
    /// `steering_angle` (rad, positive = right).
    SteeringAngle(f64),
    /// `throttle` (0 to 1): torque mode.
    Throttle(f64),
    /// `brake_intensity` (0 to 1).
    BrakeIntensity(f64),
    /// `gear` (−1 reverse, 0 neutral, 1… forward).
    Gear(i32),
    /// `indicator`.
    Indicator(IndicatorState),
    /// `hazard_flashers`.
    HazardFlashers(bool),
    /// `dipped_beams`.
    DippedBeams(bool),
    /// `antifog_lights`.
    AntifogLights(bool),
    /// `wiper_mode`.
    WiperMode(WiperMode),
}

impl DriverCommand {
    /// Every command's world-file key, in the order of the enum.
    pub const KEYS: [&'static str; 10] = [
        "cruising_speed",
        "steering_angle",
        "throttle",
        "brake_intensity",
        "gear",
        "indicator",
        "hazard_flashers",
        "dipped_beams",
        "antifog_lights",
        "wiper_mode",
    ];

    /// The world-file key, e.g. `"cruising_speed"`.
    pub const fn key(&self) -> &'static str {
        match self {
            DriverCommand::CruisingSpeed(_) => "cruising_speed",
            DriverCommand::SteeringAngle(_) => "steering_angle",
            DriverCommand::Throttle(_) => "throttle",
            DriverCommand::BrakeIntensity(_) => "brake_intensity",
            DriverCommand::Gear(_) => "gear",
            DriverCommand::Indicator(_) => "indicator",
            DriverCommand::HazardFlashers(_) => "hazard_flashers",
            DriverCommand::DippedBeams(_) => "dipped_beams",
            DriverCommand::AntifogLights(_) => "antifog_lights",
            DriverCommand::WiperMode(_) => "wiper_mode",
        }
    }

    /// Calls the matching setter of `driver`; its warning, if any (a clamped or refused
    /// value, as Webots prints it).
    pub fn apply(&self, driver: &mut Driver<f64>) -> Option<Warning> {
        match *self {
            DriverCommand::CruisingSpeed(v) => driver.set_cruising_speed(v),
            DriverCommand::SteeringAngle(v) => driver.set_steering_angle(v),
            DriverCommand::Throttle(v) => driver.set_throttle(v),
            DriverCommand::BrakeIntensity(v) => driver.set_brake_intensity(v),
            DriverCommand::Gear(g) => driver.set_gear(g),
            DriverCommand::Indicator(s) => {
                driver.set_indicator(s);
                None
            }
            DriverCommand::HazardFlashers(on) => {
                driver.set_hazard_flashers(on);
                None
            }
            DriverCommand::DippedBeams(on) => {
                driver.set_dipped_beams(on);
                None
            }
            DriverCommand::AntifogLights(on) => {
                driver.set_antifog_lights(on);
                None
            }
            DriverCommand::WiperMode(m) => {
                driver.set_wiper_mode(m);
                None
            }
        }
    }
}

/// The commands issued at one instant.
#[derive(Debug, Clone, PartialEq)]
pub struct Step<C> {
    /// Simulated time at which the commands are issued (s, finite, ≥ 0).
    pub at: f64,
    /// The commands, issued in this order.
    pub commands: Vec<C>,
}

/// A DifferentialWheels command: `wb_differential_wheels_set_speed(left, right)`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelSpeeds {
    /// Left wheel (speed units: `speedUnit` rad/s each).
    pub left: f64,
    /// Right wheel (speed units).
    pub right: f64,
}

/// A timed list of commands, sorted by time (a stable sort: steps at the same time keep their
/// order).
#[derive(Debug, Clone, PartialEq)]
pub struct Programme<C = DriverCommand> {
    steps: Vec<Step<C>>,
}

impl<C> Default for Programme<C> {
    fn default() -> Self {
        Programme { steps: Vec::new() }
    }
}

/// Time within which a step counts as due (s): far below any step length, so that a step at
/// `at = 0.3` is due at the step starting at 0.3 s although 30 × 0.01 is 0.30000000000000004.
pub(crate) const DUE_TOLERANCE: f64 = 1e-9;

impl<C> Programme<C> {
    /// The programme of `steps`, sorted by `at`.
    pub fn new(mut steps: Vec<Step<C>>) -> Self {
        steps.sort_by(|a, b| a.at.total_cmp(&b.at));
        Programme { steps }
    }

    /// The steps, in time order.
    pub fn steps(&self) -> &[Step<C>] {
        &self.steps
    }

    /// True when there is no step.
    pub fn is_empty(&self) -> bool {
        self.steps.is_empty()
    }

    /// The time of the last step (s), 0 without steps.
    pub fn last_time(&self) -> f64 {
        self.steps.last().map_or(0.0, |s| s.at)
    }

    /// A cursor at the start of the programme.
    pub fn cursor(&self) -> Cursor<'_, C> {
        Cursor {
            steps: &self.steps,
            next: 0,
        }
    }

    /// A cursor at step `next` (a [`Cursor::position`]), for a runner that keeps the
    /// programme and its position apart.
    pub fn cursor_at(&self, next: usize) -> Cursor<'_, C> {
        Cursor {
            steps: &self.steps,
            next: next.min(self.steps.len()),
        }
    }
}

/// Where a run is in a [`Programme`].
#[derive(Debug, Clone)]
pub struct Cursor<'p, C> {
    steps: &'p [Step<C>],
    next: usize,
}

impl<'p, C> Cursor<'p, C> {
    /// The index of the next step to fall due.
    pub fn position(&self) -> usize {
        self.next
    }

    /// The commands that have come due at time `t` (s) since the last call, in order.
    pub fn due(&mut self, t: f64) -> impl Iterator<Item = (f64, &'p C)> + use<'p, C> {
        let start = self.next;
        while self
            .steps
            .get(self.next)
            .is_some_and(|s| s.at <= t + DUE_TOLERANCE)
        {
            self.next += 1;
        }
        let steps: &'p [Step<C>] = self.steps.get(start..self.next).unwrap_or(&[]);
        steps
            .iter()
            .flat_map(|s| s.commands.iter().map(move |c| (s.at, c)))
    }
}

impl Cursor<'_, DriverCommand> {
    /// Issues the commands due at time `t` (s) to `driver`; the warnings, with the command
    /// that caused each.
    pub fn apply_due(&mut self, t: f64, driver: &mut Driver<f64>) -> Vec<(DriverCommand, Warning)> {
        self.due(t)
            .filter_map(|(_, c)| c.apply(driver).map(|w| (*c, w)))
            .collect()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn steps_come_due_once_in_time_order() {
        let p = Programme::new(vec![
            Step {
                at: 1.0,
                commands: vec!['b', 'c'],
            },
            Step {
                at: 0.0,
                commands: vec!['a'],
            },
            Step {
                at: 0.3,
                commands: vec!['x'],
            },
        ]);
        assert_eq!(p.last_time(), 1.0);
        let mut c = p.cursor();
        let due = |c: &mut Cursor<'_, char>, t| c.due(t).map(|(_, x)| *x).collect::<String>();
        assert_eq!(due(&mut c, 0.0), "a");
        assert_eq!(due(&mut c, 0.0), "");
        // 30 steps of 10 ms reach 0.3 s up to rounding.
        assert_eq!(due(&mut c, (0..30).map(|_| 0.01).sum()), "x");
        assert_eq!(due(&mut c, 5.0), "bc");
        assert_eq!(due(&mut c, 6.0), "");
    }
}
