//! One driver step (Webots `wbu_driver_step`, spec §2), in Webots' order.

use ackermann::{PerWheel, Real};
use powertrain::{Gear, split_torque};

use super::Driver;
use crate::io::{Commands, Sensors};
use crate::lights::blink_on;
use crate::mode::{ControlMode, IndicatorState};
use crate::sound::{EngineSoundInput, SoundCommand, engine_sound};

impl<T: Real> Driver<T> {
    /// Runs one step with the readings `sensors` taken at the start of the step and returns
    /// the commands to apply until the next one. Webots: `wbu_driver_step` (the host then
    /// advances its simulation by [`Driver::basic_time_step_ms`]).
    ///
    /// Order (spec §2): indicators from the blink clock; wipers; backwards light; wheel speeds
    /// (finite differences, one step behind); engine speed; in torque mode the limited-slip
    /// update and the wheel torques (engine model × throttle × gear ratio, acceleration limiter,
    /// geometric differential with limited slip); brake torques; engine sound.
    ///
    /// Non-finite readings count as "no sample": the time and steering angles keep their last
    /// values, a wheel without a sample has no speed. All returned numbers are finite.
    pub fn step(&mut self, sensors: &Sensors<T>) -> &Commands<T> {
        if sensors.time.is_finite() {
            self.time = sensors.time;
        }
        let time = self.time;

        // 1. Indicators, rewritten every step (the blink clock only read while one is on).
        let on = || blink_on(time, self.indicator_period);
        let (right, left) = if self.hazard_flashers {
            let on = on();
            (on, on)
        } else {
            match self.indicator {
                IndicatorState::Right => (on(), false),
                IndicatorState::Left => (false, on()),
                IndicatorState::Off => (false, false),
            }
        };
        self.lights.set_right_indicators(right);
        self.lights.set_left_indicators(left);

        // 2. Wipers.
        if let Some(w) = &mut self.wipers {
            w.step(time, sensors.wiper);
        }

        // 3. Backwards light.
        self.lights.backwards = (self.mode == ControlMode::Torque && self.gear == Gear::REVERSE)
            || (self.mode == ControlMode::Speed && self.cruising_speed < T::ZERO);

        // 4. Wheel speeds, and the steering read-back.
        let dt_ms = T::from_f64(f64::from(self.dt_ms));
        self.wheel_speeds.update(&sensors.wheel_angles, dt_ms);
        if sensors.steering.right.is_finite() {
            self.measured_steering.right = sensors.steering.right;
        }
        if sensors.steering.left.is_finite() {
            self.measured_steering.left = sensors.steering.left;
        }
        let speeds = self.wheel_speeds.speeds();

        // 5. Engine speed, every step in every mode (plus the optional automatic gearbox).
        let powertrain = &self.car.powertrain;
        self.rpm = powertrain.rpm(&speeds, self.gear);
        if self.mode == ControlMode::Torque
            && let Some(auto) = &mut self.auto_shift
        {
            let dt = dt_ms / T::from_f64(super::MS_PER_S);
            if let Some(gear) = auto.update(dt, self.rpm, self.gear, powertrain.gearbox()) {
                self.gear = gear;
                self.rpm = powertrain.rpm(&speeds, gear);
            }
        }

        // 6. Torque mode: limited slip, then the wheel torques.
        let torques = if self.mode == ControlMode::Torque {
            self.limited_slip.update(self.car.drive, &speeds);
            let out = powertrain.output_torque(
                self.rpm,
                self.throttle,
                self.gear,
                self.wheel_speeds.max_acceleration(),
            );
            split_torque(out, self.car.drive, &self.limited_slip.apply(&self.ratios))
        } else {
            PerWheel::splat(T::ZERO)
        };

        // 7. (Webots sets the brakes' damping here; the brake torque is part of the commands
        // assembled below.)

        // 8. Engine sound.
        let speed_kmh = self.speed_kmh(&speeds);
        self.engine_sound = if self.car.engine_sound {
            let input = EngineSoundInput {
                mode: self.mode,
                rpm: self.rpm,
                throttle: self.throttle,
                wheel_speeds: self.wheel_speeds.all_measured().then_some(&speeds),
                cruising_speed: self.cruising_speed,
                current_speed: speed_kmh,
            };
            engine_sound(powertrain, self.car.sound_rpm_reference, &input)
                .unwrap_or(self.engine_sound)
        } else {
            SoundCommand::STOPPED
        };

        self.commands = self.assemble_commands(&torques, speed_kmh);
        &self.commands
    }
}
