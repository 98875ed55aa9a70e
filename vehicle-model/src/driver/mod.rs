//! The driver/car control loop: Webots' `libdriver` and `libcar` as one state machine.

mod car;
mod controls;
mod measure;
mod step;

use core::cell::Cell;

use ackermann::{DifferentialRatios, DriveType, Geometry, PerWheel, Real, Wheel, WheelAngles};
use powertrain::{AutoShift, Brake, Engine, EngineType, Gear, Gearbox, LimitedSlip, Powertrain};

use crate::brake_balance::{BrakeBalance, axle_brake_factor};
use crate::driveline::Driveline;
use crate::io::{Cockpit, Commands, WheelDrive};
use crate::lights::{DEFAULT_INDICATOR_PERIOD, Lights};
use crate::mode::{ControlMode, IndicatorState};
use crate::params::{CarParams, ParamReport, ParamWarning, WheelMotor};
use crate::sound::{SoundCommand, Sounds};
use crate::warning::Warning;
use crate::wipers::Wipers;

pub use controls::INDICATOR_AUTO_DISABLING_THRESHOLD;
use measure::WheelSpeedEstimator;

/// Webots' default `basicTimeStep` (ms), used when 0 is given.
pub const DEFAULT_BASIC_TIME_STEP_MS: u32 = 32;

/// The read-only car data the libraries work from (Webots' `car` struct after `wbu_car_init`).
#[derive(Debug, Clone, PartialEq)]
struct Car<T: Real> {
    geometry: Geometry<T>,
    drive: DriveType,
    powertrain: Powertrain<T>,
    brake: Brake<T>,
    /// The front axle's share of the brake torque (dimensionless, in [0, 1]).
    brake_front_share: T,
    /// Speed-mode motor limits per wheel (all four, driven or not).
    motors: PerWheel<WheelMotor<T>>,
    engine_sound: bool,
    sound_rpm_reference: T,
    /// The engine's rotating inertia (kg·m², ≥ 0; [`CarParams::engine_inertia`]).
    engine_inertia: T,
}

impl<T: Real> Car<T> {
    /// Builds from validated params. Each part falls back to the plain `Car` default in the
    /// (unreachable after validation) case that it is still rejected.
    fn new(p: &CarParams<T>) -> Self {
        let geometry = p.geometry().unwrap_or_default();
        let engine = p.engine().unwrap_or_else(|_| Engine::default());
        let gearbox = p.gearbox().unwrap_or_else(|_| Gearbox::default());
        Car {
            geometry,
            drive: p.drive_type,
            powertrain: Powertrain::new(engine, gearbox),
            brake: p.brake().unwrap_or_default(),
            brake_front_share: T::HALF,
            motors: PerWheel::from_fn(|w| p.wheel_motor(w)),
            engine_sound: !p.engine_sound.is_none(),
            sound_rpm_reference: p.engine_sound_rpm_reference,
            engine_inertia: p.engine_inertia(),
        }
    }
}

/// The driver and car libraries of Webots (`wbu_driver_*`, `wbu_car_*`) as a value: the
/// driver's commands (steering, cruise control or throttle, brake, gear, lights, wipers) go in
/// through setters, and each [`Driver::step`] turns them plus the sensor readings into actuator
/// [`Commands`], in the order of Webots' `wbu_driver_step`.
///
/// Generic over [`Real`] (`f32` on firmware, `f64` for Webots parity). Allocates nothing and
/// never panics; setters refuse or clamp bad input and return the [`Warning`] Webots would
/// print. Every function documents its Webots name; see the crate docs for the full table.
#[derive(Debug, Clone)]
pub struct Driver<T: Real> {
    params: CarParams<T>,
    car: Car<T>,
    dt_ms: u32,

    mode: ControlMode,
    /// Commanded central steering angle δ (rad).
    steering_angle: T,
    /// Stored right/left wheel angles (rad) used by the front differential ratio.
    wheel_angles: WheelAngles<T>,
    /// True once `wheel_angles` were set directly (car library) since the last Ackermann
    /// evaluation of `steering_angle`.
    wheel_angles_direct: bool,
    /// Geometric differential ratios of `steering_angle` and `wheel_angles` (dimensionless),
    /// recomputed only when either changes: torque mode applies them every step.
    ratios: DifferentialRatios<T>,
    /// Cruise-control target (km/h).
    cruising_speed: T,
    /// Speed-mode velocity targets of the driven wheels (rad/s), as last computed.
    speed_targets: PerWheel<T>,
    throttle: T,
    brake: T,
    gear: Gear,
    indicator: IndicatorState,
    /// Steering angle reached since the indicator was set (rad), for the auto-cancel.
    indicator_angle: T,
    hazard_flashers: bool,
    dipped_beams: bool,
    lights: Lights,
    rpm: T,
    wipers: Option<Wipers<T>>,

    indicator_period: T,
    indicator_auto_disabling: bool,
    limited_slip: LimitedSlip<T>,
    auto_shift: Option<AutoShift<T>>,
    brake_balance: BrakeBalance<T>,

    time: T,
    wheel_speeds: WheelSpeedEstimator<T>,
    measured_steering: WheelAngles<T>,
    engine_sound: SoundCommand<T>,
    commands: Commands<T>,
    warnings: Cell<u32>,
}

impl<T: Real> Driver<T> {
    /// Validates `params` and starts the libraries in Webots' initial state (Webots:
    /// `wbu_driver_init`, which calls `wbu_car_init`): speed 0, throttle 0, brake 0, neutral,
    /// steering 0, indicator off, wipers down, lights off, indicator period 0.34 s,
    /// limited-slip differential and indicator auto-disabling on, control mode undefined (the
    /// driven wheels held at zero speed). `basic_time_step_ms` is the world's `basicTimeStep`
    /// (ms); 0 is replaced by 32 ms with a warning.
    ///
    /// Returns the driver and the validation report (empty for valid params).
    pub fn new(params: CarParams<T>, basic_time_step_ms: u32) -> (Self, ParamReport) {
        let (params, mut report) = params.validated();
        let dt_ms = if basic_time_step_ms == 0 {
            report.push(ParamWarning::TimeStep {
                value: 0,
                used: DEFAULT_BASIC_TIME_STEP_MS,
            });
            DEFAULT_BASIC_TIME_STEP_MS
        } else {
            basic_time_step_ms
        };
        let car = Car::new(&params);
        let limited_slip = LimitedSlip::for_geometry(&car.geometry);
        let wipers = params.wipers.map(Wipers::new);
        let mut driver = Driver {
            car,
            dt_ms,
            mode: ControlMode::Undefined,
            steering_angle: T::ZERO,
            wheel_angles: WheelAngles::STRAIGHT,
            wheel_angles_direct: false,
            ratios: DifferentialRatios::EVEN,
            cruising_speed: T::ZERO,
            speed_targets: PerWheel::splat(T::ZERO),
            throttle: T::ZERO,
            brake: T::ZERO,
            gear: Gear::NEUTRAL,
            indicator: IndicatorState::Off,
            indicator_angle: T::ZERO,
            hazard_flashers: false,
            dipped_beams: false,
            lights: Lights::OFF,
            rpm: T::ZERO,
            wipers,
            indicator_period: T::from_f64(DEFAULT_INDICATOR_PERIOD),
            indicator_auto_disabling: true,
            limited_slip,
            auto_shift: None,
            brake_balance: BrakeBalance::Equal,
            time: T::ZERO,
            wheel_speeds: WheelSpeedEstimator::new(),
            measured_steering: WheelAngles::STRAIGHT,
            engine_sound: SoundCommand::STOPPED,
            commands: Commands {
                steering: WheelAngles::STRAIGHT,
                drive: PerWheel::splat(WheelDrive::Free),
                brake_torque: PerWheel::splat(T::ZERO),
                driveline: Driveline::DISENGAGED,
                lights: Lights::OFF,
                cockpit: Cockpit {
                    steering_wheel: T::ZERO,
                    indicator_lever: IndicatorState::Off,
                    rpm_needle: T::ZERO,
                    speed_needle: T::ZERO,
                    wipers: wipers.map(|w| w.command()),
                },
                sound: Sounds::SILENT,
            },
            warnings: Cell::new(0),
            params,
        };
        driver.commands =
            driver.assemble_commands(&PerWheel::splat(T::ZERO), driver.current_speed());
        (driver, report)
    }

    /// The validated parameters the driver runs with.
    #[inline]
    pub fn params(&self) -> &CarParams<T> {
        &self.params
    }

    /// The steering geometry (wheelbase, tracks, tyre radii).
    #[inline]
    pub fn geometry(&self) -> &Geometry<T> {
        &self.car.geometry
    }

    /// The engine and gearbox.
    #[inline]
    pub fn powertrain(&self) -> &Powertrain<T> {
        &self.car.powertrain
    }

    /// The step length (ms; Webots: `basicTimeStep` truncated to an integer).
    #[inline]
    pub fn basic_time_step_ms(&self) -> u32 {
        self.dt_ms
    }

    /// The commands of the last [`Driver::step`] (before the first step: the initial commands,
    /// with the driven wheels held at zero speed).
    #[inline]
    pub fn commands(&self) -> &Commands<T> {
        &self.commands
    }

    /// Number of [`Warning`]s returned since construction (saturating), for firmware that only
    /// counts them.
    #[inline]
    pub fn warning_count(&self) -> u32 {
        self.warnings.get()
    }

    /// Counts `w` and returns it.
    fn warn(&self, w: Warning) -> Warning {
        self.warnings.set(self.warnings.get().saturating_add(1));
        w
    }

    /// The drive command of each wheel for the current mode (torque-mode torques come from
    /// `torques`).
    fn drive_commands(&self, torques: &PerWheel<T>) -> PerWheel<WheelDrive<T>> {
        PerWheel::from_fn(|w| {
            if !self.car.drive.drives(w) {
                return WheelDrive::Free;
            }
            match self.mode {
                ControlMode::Torque => WheelDrive::Torque(torques[w]),
                ControlMode::Speed | ControlMode::Undefined => {
                    let motor = self.car.motors[w];
                    WheelDrive::Velocity {
                        target: self.speed_targets[w],
                        acceleration: motor.acceleration,
                        max_velocity: motor.max_velocity,
                    }
                }
            }
        })
    }

    /// The commands implied by the current state, the torque-mode wheel torques `torques`
    /// (N·m) and the estimated vehicle speed `speed_kmh` ([`Driver::current_speed`], km/h).
    fn assemble_commands(&self, torques: &PerWheel<T>, speed_kmh: T) -> Commands<T> {
        let brake_torque = if self.brake > T::ZERO {
            let torque = self.car.brake.torque(self.brake);
            PerWheel::from_fn(|w| torque * axle_brake_factor(self.car.brake_front_share, w))
        } else {
            PerWheel::splat(T::ZERO)
        };
        let speed = speed_kmh.abs();
        Commands {
            steering: self.wheel_angles,
            drive: self.drive_commands(torques),
            brake_torque,
            driveline: self.driveline(),
            lights: self.lights,
            cockpit: Cockpit {
                steering_wheel: saturate(T::from_f64(STEERING_WHEEL_RATIO) * self.steering_angle),
                indicator_lever: self.indicator,
                rpm_needle: (self.rpm / T::from_f64(RPM_NEEDLE_FULL_SCALE)).min(T::ONE),
                speed_needle: (speed / T::from_f64(SPEED_NEEDLE_FULL_SCALE)).min(T::ONE),
                wipers: self.wipers.map(|w| w.command()),
            },
            sound: Sounds {
                engine: self.engine_sound,
                blinker: self.blinker_playing(),
            },
        }
    }

    /// The engine engaged through the current gear in torque mode; disengaged in neutral, in
    /// speed mode, whose wheel motors follow a speed with no engine behind them, and while a
    /// combustion engine with the throttle released would turn below `engineMinRPM`: it
    /// idles there behind a slipping clutch or torque converter, so the wheels (a stop on
    /// the brakes, a coast to rest) do not drag its inertia below idle. Webots' engine speed
    /// never goes below `engineMinRPM` either. With the throttle open the engine stays on
    /// the wheels below idle too: decoupled there, wheels spinning past their grip at a
    /// launch set Webots' wheel-acceleration limiter chattering again (ARCHITECTURE.md,
    /// "Launch chatter").
    fn driveline(&self) -> Driveline<T> {
        if self.mode != ControlMode::Torque || self.gear.is_neutral() {
            return Driveline::DISENGAGED;
        }
        let engine = self.car.powertrain.engine();
        if engine.engine_type() == EngineType::Combustion
            && self.throttle <= T::ZERO
            && self.rpm < engine.min_rpm()
        {
            return Driveline::DISENGAGED;
        }
        Driveline {
            engine_inertia: self.car.engine_inertia,
            ratio: self.car.powertrain.gearbox().ratio(self.gear),
        }
    }

    /// Webots plays the blinker loop while an indicator or the hazard flashers are on.
    fn blinker_playing(&self) -> bool {
        self.hazard_flashers || self.indicator != IndicatorState::Off
    }
}

/// Milliseconds per second: the step length is in ms (Webots' `basicTimeStep`), rates are per s.
const MS_PER_S: f64 = 1000.0;
/// Steering-wheel angle per wheel steering angle (dimensionless): Webots turns the
/// `steering_wheel` motor to 10·δ.
const STEERING_WHEEL_RATIO: f64 = 10.0;
/// Engine speed at which the rpm needle reaches its full deflection (rpm, spec §3).
const RPM_NEEDLE_FULL_SCALE: f64 = 11_000.0;
/// Speed at which the speed needle reaches its full deflection (km/h, spec §2.6).
const SPEED_NEEDLE_FULL_SCALE: f64 = 220.0;

/// `x` forced into the finite range (NaN → 0, ±∞ → ±`T::MAX`), for outputs that scale a
/// stored finite input and could overflow.
fn saturate<T: Real>(x: T) -> T {
    if x.is_nan() {
        T::ZERO
    } else {
        x.clamp(-T::MAX, T::MAX)
    }
}

/// The wheel with raw Webots index `index` (Webots: `WbuCarWheelIndex`, for the C API).
///
/// # Errors
/// [`Warning::WheelIndex`] (`Warning: maximum wheel index is 4.`) outside 0..=3; Webots checks
/// only `index >= 4` and reads out of bounds for negative indices, which are refused here too.
pub fn wheel_from_webots_index(index: i64) -> Result<Wheel, Warning> {
    usize::try_from(index)
        .ok()
        .and_then(Wheel::from_index)
        .ok_or(Warning::WheelIndex { index })
}
