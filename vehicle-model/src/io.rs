//! What a host exchanges with the [`Driver`](crate::Driver) each step: sensor readings in,
//! actuator commands out.

use ackermann::{PerWheel, Real, Wheel, WheelAngles};

use crate::driveline::Driveline;
use crate::lights::Lights;
use crate::mode::IndicatorState;
use crate::sound::Sounds;
use crate::wipers::WiperCommand;

/// The command of one wheel's drive motor (Webots: the `RotationalMotor` of a driven wheel).
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum WheelDrive<T: Real> {
    /// No motor force: the wheel rolls freely (non-driven wheels).
    Free,
    /// Velocity control (Webots: `wb_motor_set_velocity` with position +∞): the motor moves its
    /// velocity command towards `target` by at most `acceleration·dt` per step, clamps it to
    /// ±`max_velocity`, and may use unlimited torque (Webots' 10⁸ N·m) to follow it.
    Velocity {
        /// Target angular speed (rad/s, positive = rolling forward), not clamped.
        target: T,
        /// Ramp limit of the velocity command (rad/s², > 0); Webots motor field `acceleration`.
        acceleration: T,
        /// The motor clamps `target` to ±this (rad/s, > 0); Webots motor field `maxVelocity`.
        max_velocity: T,
    },
    /// Torque control (Webots: `wb_motor_set_torque`): apply this torque (N·m on the wheel,
    /// positive = driving forward).
    Torque(T),
}

impl<T: Real> WheelDrive<T> {
    /// The torque of a [`WheelDrive::Torque`] command, else `None`.
    pub fn torque(&self) -> Option<T> {
        match *self {
            WheelDrive::Torque(t) => Some(t),
            WheelDrive::Free | WheelDrive::Velocity { .. } => None,
        }
    }

    /// The target of a [`WheelDrive::Velocity`] command (rad/s), else `None`.
    pub fn velocity_target(&self) -> Option<T> {
        match *self {
            WheelDrive::Velocity { target, .. } => Some(target),
            WheelDrive::Free | WheelDrive::Torque(_) => None,
        }
    }
}

/// Sensor readings at the start of a step.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Sensors<T: Real> {
    /// Simulation time at the start of the step (s; Webots: `wb_robot_get_time`). A NaN or
    /// infinite time is ignored (the previous one is kept).
    pub time: T,
    /// The four wheel encoders (rad, continuous, positive = rolling forward; Webots position
    /// sensors `right_front_sensor` …). NaN = no sample yet.
    pub wheel_angles: PerWheel<T>,
    /// The measured front-wheel steering angles (rad; Webots sensors `right_steer_sensor`,
    /// `left_steer_sensor`). NaN = no sample yet.
    pub steering: WheelAngles<T>,
    /// The wiper position sensor (rad; Webots `wiper_sensor`), `None` if the car has none.
    pub wiper: Option<T>,
}

impl<T: Real> Sensors<T> {
    /// Readings at `time` (s) before any sensor has sampled: every angle NaN, no wiper sensor.
    pub fn unsampled(time: T) -> Self {
        let nan = T::from_f64(f64::NAN);
        Sensors {
            time,
            wheel_angles: PerWheel::splat(nan),
            steering: WheelAngles::new(nan, nan),
            wiper: None,
        }
    }
}

/// The cosmetic actuators of the cockpit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Cockpit<T: Real> {
    /// Steering-wheel position (rad): 10 × the commanded steering angle (Webots motor
    /// `steering_wheel_motor`, normally without limits).
    pub steering_wheel: T,
    /// Indicator lever (Webots motor `indicator_lever_motor`): its maximum position for
    /// [`IndicatorState::Right`], its minimum position for [`IndicatorState::Left`], 0 for
    /// [`IndicatorState::Off`].
    pub indicator_lever: IndicatorState,
    /// Rev-counter needle as a fraction of its full scale (dimensionless, [0, 1]):
    /// `min(rpm/11000, 1)`. Webots motor `rpm_needle_motor`: position = fraction × its
    /// `maxPosition` (4.42 rad on the BmwX5).
    pub rpm_needle: T,
    /// Speedometer needle as a fraction of its full scale (dimensionless, [0, 1]):
    /// `min(|v|/220 km/h, 1)`. Webots motor `speed_needle_motor`: position = fraction × its
    /// `maxPosition`.
    pub speed_needle: T,
    /// Both wiper motors (Webots `right_wiper_motor`, `left_wiper_motor`), `None` for a car
    /// without wipers.
    pub wipers: Option<WiperCommand<T>>,
}

impl<T: Real> Cockpit<T> {
    /// Webots' lever position (rad) for a lever motor with limits `[min, max]` (rad).
    pub fn indicator_lever_position(&self, min: T, max: T) -> T {
        match self.indicator_lever {
            IndicatorState::Off => T::ZERO,
            IndicatorState::Right => max,
            IndicatorState::Left => min,
        }
    }
}

/// Every actuator command of one step. All numbers are finite.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Commands<T: Real> {
    /// Position targets of the right and left steering motors (rad, positive = right; Webots
    /// motors `right_steer`, `left_steer`). The motors clamp them to
    /// `[minSteeringAngle, maxSteeringAngle]`.
    pub steering: WheelAngles<T>,
    /// Drive command of each wheel motor; [`WheelDrive::Free`] for non-driven wheels.
    pub drive: PerWheel<WheelDrive<T>>,
    /// Brake friction torque of each wheel (N·m, ≥ 0): the magnitude of a dry-friction torque
    /// opposing the wheel's rotation, which also holds a stopped wheel (Webots: `Brake` devices
    /// `right_front_brake` …, emulated by a damping of `brake·brakeCoefficient/|ω|`).
    pub brake_torque: PerWheel<T>,
    /// The engine's inertia and the ratio it turns the driven wheels through this step
    /// ([`Driveline::DISENGAGED`] in neutral and outside torque mode). Not in Webots, whose
    /// wheels carry no engine: a host that solves the wheels' spin adds
    /// [`Driveline::reflected_inertia`], shared equally, to the spin inertia of the wheels
    /// under [`WheelDrive::Torque`], so that a wheel beyond its grip spins up as one dragging
    /// its engine does; one that ignores it runs Webots' wheels.
    pub driveline: Driveline<T>,
    /// Every light.
    pub lights: Lights,
    /// Steering wheel, lever, needles, wipers.
    pub cockpit: Cockpit<T>,
    /// Engine and blinker sounds of the `engine_speaker`.
    pub sound: Sounds<T>,
}

impl<T: Real> Commands<T> {
    /// Wheel `w`'s equal share of the engaged engine, `(J_e·ξ², J_e·|ξ|)` over the number of
    /// wheels under [`WheelDrive::Torque`] (kg·m² each): what a host adds to the wheel's spin
    /// inertia ([`Driveline::reflected_inertia`]) and the engine's angular momentum per unit
    /// of the wheel's speed its change of spin takes from the chassis
    /// ([`Driveline::engine_momentum`]). `(0, 0)` for a wheel not under a torque command.
    /// An equal share is the simple form of an open differential coupling the engine to the
    /// mean of its wheels: exact while they turn alike.
    pub fn driveline_share(&self, w: Wheel) -> (T, T) {
        if self.drive[w].torque().is_none() {
            return (T::ZERO, T::ZERO);
        }
        // At least 1: wheel `w` itself is one.
        let driven = self.drive.iter().filter(|d| d.torque().is_some()).count();
        let driven = T::from_f64(driven as f64);
        (
            self.driveline.reflected_inertia() / driven,
            self.driveline.engine_momentum() / driven,
        )
    }

    /// True if every number is finite: steering targets, drive commands, brake torques,
    /// driveline, cockpit positions, wiper command and engine-sound volume and pitch. Always
    /// true for the commands of a [`Driver`](crate::Driver); a host or firmware can assert it
    /// cheaply.
    pub fn is_finite(&self) -> bool {
        let drive_finite = |d: &WheelDrive<T>| match *d {
            WheelDrive::Free => true,
            WheelDrive::Torque(t) => t.is_finite(),
            WheelDrive::Velocity {
                target,
                acceleration,
                max_velocity,
            } => target.is_finite() && acceleration.is_finite() && max_velocity.is_finite(),
        };
        let k = &self.cockpit;
        self.steering.right.is_finite()
            && self.steering.left.is_finite()
            && self.drive.iter().all(drive_finite)
            && self.brake_torque.iter().all(|t| t.is_finite())
            && self.driveline.is_finite()
            && k.steering_wheel.is_finite()
            && k.rpm_needle.is_finite()
            && k.speed_needle.is_finite()
            && k.wipers
                .is_none_or(|w| w.target.is_finite() && w.velocity.is_finite())
            && self.sound.engine.volume.is_finite()
            && self.sound.engine.pitch.is_finite()
    }
}
