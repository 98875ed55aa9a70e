//! The driver library's commands and getters (Webots `wbu_driver_*`).

use ackermann::{DriveType, PerWheel, Real, Wheel};
use powertrain::{AutoShift, AutoShiftParams, Gear, GearWarning, PowertrainError};

use super::Driver;
use crate::KMH_PER_MS;
use crate::brake_balance::{BrakeBalance, BrakeBalanceError};
use crate::mode::{ControlMode, IndicatorState, WiperMode};
use crate::warning::Warning;

/// Steering amplitude (rad) by which the wheel must come back from its extreme to cancel the
/// indicator (Webots: `INDICATOR_AUTO_DISABLING_THRESHOLD`).
pub const INDICATOR_AUTO_DISABLING_THRESHOLD: f64 = 0.1;

impl<T: Real> Driver<T> {
    /// Steers the front wheels to the Ackermann angles of the central angle `angle` (rad,
    /// positive = right). Webots: `wbu_driver_set_steering_angle`.
    ///
    /// Stores `angle`, sets the steering targets to
    /// [`Geometry::wheel_angles`](ackermann::Geometry::wheel_angles) (the steering motors clamp
    /// them to `[minSteeringAngle, maxSteeringAngle]`), the steering wheel to `10·angle`, in
    /// speed mode recomputes the wheel speed targets, then runs the indicator auto-cancel: an
    /// indicator switches off once the steering has come back 0.1 rad from the extreme reached
    /// in its direction since it was set.
    ///
    /// Returns (and ignores the call for) a NaN or infinite angle: `Warning:
    /// wbu_driver_set_steering_angle() called with an invalid 'steering_angle' argument (NaN)`.
    pub fn set_steering_angle(&mut self, angle: T) -> Option<Warning> {
        if !angle.is_finite() {
            return Some(self.warn(Warning::InvalidArgument {
                function: "wbu_driver_set_steering_angle",
                argument: "steering_angle",
                value: angle.to_f64(),
            }));
        }
        // Controllers re-send the same angle every step: the angles, ratios and speed targets
        // it gave are still in place unless the wheels were steered directly since. The bits
        // are compared so that −0 (which steers the wheels to −0) counts as a change from 0.
        let unchanged = !self.wheel_angles_direct
            && angle.to_f64().to_bits() == self.steering_angle.to_f64().to_bits();
        if !unchanged {
            self.steering_angle = angle;
            (self.wheel_angles, self.ratios) = self.car.geometry.ackermann_steering(angle);
            self.wheel_angles_direct = false;
            if self.mode == ControlMode::Speed {
                self.update_speed_targets();
            }
        }
        if self.indicator_auto_disabling {
            self.auto_cancel_indicator(angle);
        }
        None
    }

    fn auto_cancel_indicator(&mut self, angle: T) {
        let threshold = T::from_f64(INDICATOR_AUTO_DISABLING_THRESHOLD);
        match self.indicator {
            IndicatorState::Right => {
                if angle > self.indicator_angle {
                    self.indicator_angle = angle;
                } else if angle - self.indicator_angle <= -threshold {
                    self.indicator = IndicatorState::Off;
                }
            }
            IndicatorState::Left => {
                if angle < self.indicator_angle {
                    self.indicator_angle = angle;
                } else if self.indicator_angle - angle <= -threshold {
                    self.indicator = IndicatorState::Off;
                }
            }
            IndicatorState::Off => {}
        }
    }

    /// The steering angle (rad): the mean of the two **measured** front-wheel angles of the
    /// last step, `(right + left)/2`, 0 before they are measured. Webots:
    /// `wbu_driver_get_steering_angle` (which returns NaN before the first sample).
    pub fn steering_angle(&self) -> T {
        super::saturate(self.measured_steering.mean())
    }

    /// The central steering angle last commanded with [`Driver::set_steering_angle`] (rad).
    /// Not in Webots.
    pub fn commanded_steering_angle(&self) -> T {
        self.steering_angle
    }

    /// Switches to speed (cruise-control) mode with target `speed` (km/h, negative = reverse).
    /// Webots: `wbu_driver_set_cruising_speed`.
    ///
    /// Each driven wheel gets a velocity target from
    /// [`Geometry::wheel_speed_targets`](ackermann::Geometry::wheel_speed_targets) for the
    /// current steering (geometric differential, no limited slip), ramped by the motor at
    /// `(1000/36)/time0To100/r` rad/s² and clamped to `maxVelocity/r` rad/s.
    ///
    /// Returns (and ignores the call for) a NaN or infinite speed, which Webots would pass to
    /// its motors: `Warning: wbu_driver_set_cruising_speed() called with an invalid 'speed'
    /// argument (NaN)`.
    pub fn set_cruising_speed(&mut self, speed: T) -> Option<Warning> {
        if !speed.is_finite() {
            return Some(self.warn(Warning::InvalidArgument {
                function: "wbu_driver_set_cruising_speed",
                argument: "speed",
                value: speed.to_f64(),
            }));
        }
        self.cruising_speed = speed;
        self.mode = ControlMode::Speed;
        self.update_speed_targets();
        None
    }

    /// Recomputes the speed-mode wheel targets from the cruising speed and the stored ratios.
    fn update_speed_targets(&mut self) {
        let speed = self.cruising_speed / T::from_f64(KMH_PER_MS);
        self.speed_targets = self
            .car
            .geometry
            .wheel_speed_targets(speed, self.car.drive, self.ratios)
            .map(|t| t.unwrap_or(T::ZERO));
    }

    /// The last cruising speed set (km/h), 0 initially. Webots:
    /// `wbu_driver_get_target_cruising_speed`.
    pub fn target_cruising_speed(&self) -> T {
        self.cruising_speed
    }

    /// The estimated vehicle speed (km/h) from the driven wheels' speeds of the last step
    /// (one step behind): `3.6·r·(ω_R + ω_L)/2` for the driven axle, the mean of both axles
    /// for 4x4. 0 until the wheel speeds are measurable (Webots: NaN for two steps).
    /// Webots: `wbu_driver_get_current_speed`.
    pub fn current_speed(&self) -> T {
        self.speed_kmh(&self.wheel_speeds.speeds())
    }

    /// [`Driver::current_speed`] from the wheel speeds `s` (rad/s).
    pub(super) fn speed_kmh(&self, s: &PerWheel<T>) -> T {
        let g = &self.car.geometry;
        let front = s[Wheel::FrontRight] + s[Wheel::FrontLeft];
        let rear = s[Wheel::RearRight] + s[Wheel::RearLeft];
        let quarter = T::HALF * T::HALF;
        let v = match self.car.drive {
            DriveType::Traction => T::HALF * front * g.radius_front(),
            DriveType::Propulsion => T::HALF * rear * g.radius_rear(),
            DriveType::FourByFour => {
                quarter * front * g.radius_front() + quarter * rear * g.radius_rear()
            }
        };
        super::saturate(v * T::from_f64(KMH_PER_MS))
    }

    /// Switches to torque mode with throttle `throttle` (dimensionless, [0, 1]). Webots:
    /// `wbu_driver_set_throttle`.
    ///
    /// Out-of-range values are clamped and the call still applies, with Webots' warning
    /// (`Warning: 'throttle' should be bigger or equal to 0, used 0 instead.` or `... smaller
    /// or equal to 1, used 1 instead.`). A NaN is refused (Webots stores it and its motors
    /// later reject the NaN torque): `Warning: wbu_driver_set_throttle() called with an
    /// invalid 'throttle' argument (NaN)`.
    pub fn set_throttle(&mut self, throttle: T) -> Option<Warning> {
        let (value, warning) =
            match self.unit_interval(throttle, "wbu_driver_set_throttle", "throttle") {
                Ok(v) => v,
                Err(w) => return Some(w),
            };
        self.throttle = value;
        self.mode = ControlMode::Torque;
        warning
    }

    /// The stored throttle (dimensionless, [0, 1]). Webots: `wbu_driver_get_throttle`.
    pub fn throttle(&self) -> T {
        self.throttle
    }

    /// Sets the brake intensity (dimensionless, [0, 1]) of all four wheels: a friction torque
    /// of `intensity·brakeCoefficient` N·m per wheel from the next step. Lights the brake
    /// lights iff `intensity > 0`. Does not change the control mode. Webots:
    /// `wbu_driver_set_brake_intensity` (and the deprecated `wbu_driver_set_brake`).
    ///
    /// Clamping and warnings as [`Driver::set_throttle`], naming `'intensity'`; a NaN is
    /// refused (Webots stores it).
    pub fn set_brake_intensity(&mut self, intensity: T) -> Option<Warning> {
        let (value, warning) =
            match self.unit_interval(intensity, "wbu_driver_set_brake_intensity", "intensity") {
                Ok(v) => v,
                Err(w) => return Some(w),
            };
        self.brake = value;
        self.lights.brake = value > T::ZERO;
        warning
    }

    /// Webots' [0, 1] clamp with its warnings; `Err` for NaN (call refused).
    fn unit_interval(
        &self,
        x: T,
        function: &'static str,
        argument: &'static str,
    ) -> Result<(T, Option<Warning>), Warning> {
        if x.is_nan() {
            Err(self.warn(Warning::InvalidArgument {
                function,
                argument,
                value: x.to_f64(),
            }))
        } else if x < T::ZERO {
            Ok((
                T::ZERO,
                Some(self.warn(Warning::ClampedToZero { argument })),
            ))
        } else if x > T::ONE {
            Ok((T::ONE, Some(self.warn(Warning::ClampedToOne { argument }))))
        } else {
            Ok((x, None))
        }
    }

    /// The stored brake intensity (dimensionless, [0, 1]). Webots:
    /// `wbu_driver_get_brake_intensity` (and the deprecated `wbu_driver_get_brake`).
    pub fn brake_intensity(&self) -> T {
        self.brake
    }

    /// Sets the indicator lever; the indicator then blinks with the blink clock and the blinker
    /// sound plays. Remembers the current steering angle for the auto-cancel. Webots:
    /// `wbu_driver_set_indicator` (see [`IndicatorState::try_from_webots_value`] for raw
    /// integers).
    pub fn set_indicator(&mut self, state: IndicatorState) {
        self.indicator = state;
        self.indicator_angle = self.steering_angle;
    }

    /// The indicator state (possibly auto-cancelled). Webots: `wbu_driver_get_indicator`.
    pub fn indicator(&self) -> IndicatorState {
        self.indicator
    }

    /// Switches the hazard flashers (both indicators blinking, never auto-cancelled). Webots:
    /// `wbu_driver_set_hazard_flashers` (old name `wbu_driver_set_indicator_warning`).
    pub fn set_hazard_flashers(&mut self, on: bool) {
        self.hazard_flashers = on;
    }

    /// The hazard flasher switch. Webots: `wbu_driver_get_hazard_flashers`.
    pub fn hazard_flashers(&self) -> bool {
        self.hazard_flashers
    }

    /// Switches the dipped beams: the front and rear lights together. Webots:
    /// `wbu_driver_set_dipped_beams`.
    pub fn set_dipped_beams(&mut self, on: bool) {
        self.dipped_beams = on;
        self.lights.front = on;
        self.lights.rear = on;
    }

    /// The stored dipped-beam switch. Webots: `wbu_driver_get_dipped_beams`.
    pub fn dipped_beams(&self) -> bool {
        self.dipped_beams
    }

    /// Switches the antifog lights. Webots: `wbu_driver_set_antifog_lights`.
    pub fn set_antifog_lights(&mut self, on: bool) {
        self.lights.antifog = on;
    }

    /// The antifog light state. Webots: `wbu_driver_get_antifog_lights` (reads the LED).
    pub fn antifog_lights(&self) -> bool {
        self.lights.antifog
    }

    /// The engine speed estimated at the last step (rpm, in [0, `engineMaxRPM`]): the mean of
    /// the four wheel speeds times the gear ratio, 0 in neutral and before the wheel speeds are
    /// measurable. Webots: `wbu_driver_get_rpm`.
    ///
    /// # Errors
    /// In speed mode, [`Warning::NoEngineModel`] (`Warning: no engine model when cruise control
    /// is enable, call to 'wbu_driver_get_rpm()' is therefore not allowed.`); Webots then
    /// returns 0.
    pub fn rpm(&self) -> Result<T, Warning> {
        if self.mode == ControlMode::Speed {
            Err(self.warn(Warning::NoEngineModel))
        } else {
            Ok(self.rpm)
        }
    }

    /// The engaged gear. Webots: `wbu_driver_get_gear` (use [`Gear::number`] for its `int`).
    ///
    /// # Errors
    /// In speed mode, [`Warning::NoGearModel`]; Webots then returns 0.
    pub fn gear(&self) -> Result<Gear, Warning> {
        if self.mode == ControlMode::Speed {
            Err(self.warn(Warning::NoGearModel))
        } else {
            Ok(self.gear)
        }
    }

    /// Engages gear `gear` (−1 reverse, 0 neutral, 1 … `gear_number() − 1` forward), in any
    /// mode; only torque mode uses it. Webots: `wbu_driver_set_gear`.
    ///
    /// Below −1: reverse with `Warning: Minimum gear value is -1`. At or above
    /// [`Driver::gear_number`]: the highest forward gear with `Warning: this car has only N
    /// gears.` (Webots clamps only above N and reads past its ratio table for N.)
    pub fn set_gear(&mut self, gear: i32) -> Option<Warning> {
        let selection = self.car.powertrain.gearbox().select(gear);
        self.gear = selection.gear;
        selection.warning.map(|w| {
            self.warn(match w {
                GearWarning::AboveHighest { gear_count, .. } => Warning::TooManyGears {
                    gear_number: gear_count,
                },
                GearWarning::BelowReverse { .. } => Warning::MinimumGear,
            })
        })
    }

    /// Number of `gearRatio` entries, reverse included. Webots: `wbu_driver_get_gear_number`.
    pub fn gear_number(&self) -> usize {
        self.car.powertrain.gearbox().gear_count()
    }

    /// The control mode. Webots: `wbu_driver_get_control_mode`.
    pub fn control_mode(&self) -> ControlMode {
        self.mode
    }

    /// Sets the wiper mode; ignored by a car without wipers (as Webots does silently). Webots:
    /// `wbu_driver_set_wiper_mode` (deprecated alias `wbu_driver_set_wipers_mode`).
    pub fn set_wiper_mode(&mut self, mode: WiperMode) {
        if let Some(w) = &mut self.wipers {
            w.set_mode(mode);
        }
    }

    /// The wiper mode ([`WiperMode::Down`] for a car without wipers). Webots:
    /// `wbu_driver_get_wiper_mode` (deprecated alias `wbu_driver_get_wipers_mode`).
    pub fn wiper_mode(&self) -> WiperMode {
        self.wipers.map_or(WiperMode::Down, |w| w.mode())
    }

    /// Turns the automatic gearbox on (`Some`) or off (`None`); off by default. Not in Webots.
    ///
    /// While on, each torque-mode step may shift between forward gears (see
    /// [`AutoShift`]): the driver still selects reverse, neutral or a starting
    /// gear with [`Driver::set_gear`].
    ///
    /// # Errors
    /// [`PowertrainError`] if `params` do not suit the engine; the gearbox state is unchanged.
    pub fn set_automatic_gearbox(
        &mut self,
        params: Option<AutoShiftParams<T>>,
    ) -> Result<(), PowertrainError> {
        self.auto_shift = match params {
            Some(p) => Some(AutoShift::new(p, self.car.powertrain.engine())?),
            None => None,
        };
        Ok(())
    }

    /// The automatic gearbox tuning, `None` while it is off. Not in Webots.
    pub fn automatic_gearbox(&self) -> Option<&AutoShiftParams<T>> {
        self.auto_shift.as_ref().map(AutoShift::params)
    }

    /// Shares the brake torque between the axles as `balance` says, from the next
    /// [`Driver::step`] (or brake change) on; [`BrakeBalance::Equal`], Webots' brakes, by
    /// default. The total at intensity `i` stays `4·i·brakeCoefficient` (N·m). Not in Webots.
    ///
    /// # Errors
    /// [`BrakeBalanceError`] for a [`BrakeBalance::FrontShare`] outside [0, 1] or NaN; the
    /// balance is unchanged.
    pub fn set_brake_balance(&mut self, balance: BrakeBalance<T>) -> Result<(), BrakeBalanceError> {
        self.car.brake_front_share = balance.front_share(&self.params)?;
        self.brake_balance = balance;
        Ok(())
    }

    /// How the brake torque is shared between the axles. Not in Webots.
    pub fn brake_balance(&self) -> BrakeBalance<T> {
        self.brake_balance
    }

    /// The front axle's share of the brake torque (dimensionless, in [0, 1]): 0.5 with
    /// [`BrakeBalance::Equal`]. Each front wheel brakes with `2·share·i·brakeCoefficient` and
    /// each rear one with `2·(1 − share)·i·brakeCoefficient` (N·m) at intensity `i`. Not in
    /// Webots.
    pub fn brake_front_share(&self) -> T {
        self.car.brake_front_share
    }
}
