//! The control-loop benchmark: one [`Driver::step`] of a car in motion, without physics.
//!
//! The sensor frame is fixed up front (a Range Rover Sport SVR, 4x4, at 30 km/h with each
//! wheel slipping a little differently) and advanced by constant increments each step (the
//! time by dt, each encoder by ω·dt), so the wheel-speed estimate, the limited-slip
//! integrators and the torque split all see live, distinct values. The steering command changes every step
//! (a slalom through a 16-entry table), so the Ackermann angles and the differential ratios
//! are recomputed each step, as for a driver who steers continuously.

use core::fmt;

use vehicle_model::{
    Commands, Driver, KMH_PER_MS, Model, ParamWarning, PerWheel, Real, Sensors, Wheel,
};

/// Which control mode the loop runs in.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub enum LoopMode {
    /// Torque mode (Webots `wbu_driver_set_throttle`): first gear, throttle 0.5, limited-slip
    /// differential on, 4x4.
    Torque,
    /// Speed mode (Webots `wbu_driver_set_cruising_speed`): cruising at 30 km/h.
    Speed,
}

/// Cruising speed of the frame and of speed mode (km/h).
pub const SPEED_KMH: f64 = 30.0;
/// The world's `basicTimeStep` (ms).
pub const BASIC_TIME_STEP_MS: u32 = 10;
/// Per-wheel slip of the frame (dimensionless), FR, FL, RR, RL: ω = v/r · (1 + slip).
const SLIP: [f64; 4] = [-0.02, 0.03, -0.01, 0.02];
/// Steering commands cycled through, one per step (rad): a slalom of ±0.2 rad.
const STEERING: [f64; 16] = [
    0.0, 0.05, 0.1, 0.15, 0.2, 0.15, 0.1, 0.05, 0.0, -0.05, -0.1, -0.15, -0.2, -0.15, -0.1, -0.05,
];
/// Every this many steps the frame returns to its start (time 0, encoders 0), so that f32
/// readings keep their resolution however long criterion runs: after 4096 steps an encoder
/// reads about 940 rad, where an f32 still resolves 6·10⁻⁵ rad. The driver then sees one step
/// of negative wheel speed (and its clock going back), 1 step in 4096.
const WRAP_STEPS: u32 = 4096;

/// The shipped car model the loop drives: 4x4, so that all three limited-slip integrators and
/// the four-wheel torque split run.
pub const MODEL: Model = Model::RangeRoverSportSVR;

/// The model's parameters did not validate (a regression in `vehicle-model`'s presets).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct InvalidModel {
    /// Number of validation warnings.
    pub total: usize,
    /// The first of them.
    pub first: Option<ParamWarning>,
}

impl fmt::Display for InvalidModel {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{MODEL:?} parameters gave {} warnings", self.total)?;
        if let Some(w) = &self.first {
            write!(f, ", first: {w}")?;
        }
        Ok(())
    }
}

impl std::error::Error for InvalidModel {}

/// A driver and its advancing sensor frame.
pub struct ControlLoop<T: Real> {
    driver: Driver<T>,
    sensors: Sensors<T>,
    /// Encoder increment per step (rad).
    increments: PerWheel<T>,
    dt: T,
    step: u32,
}

impl<T: Real> ControlLoop<T> {
    /// A [`MODEL`] driver in `mode`, at time 0 with the encoders at 0.
    ///
    /// # Errors
    /// [`InvalidModel`] if the shipped model's parameters do not validate.
    pub fn new(mode: LoopMode) -> Result<Self, InvalidModel> {
        let (mut driver, report) = Driver::<T>::new(MODEL.params(), BASIC_TIME_STEP_MS);
        if !report.is_empty() {
            return Err(InvalidModel {
                total: report.total(),
                first: report.iter().next().copied(),
            });
        }
        let f = T::from_f64;
        match mode {
            LoopMode::Torque => {
                driver.enable_limited_slip_differential(true);
                driver.set_gear(1);
                driver.set_throttle(f(0.5));
            }
            LoopMode::Speed => {
                driver.set_cruising_speed(f(SPEED_KMH));
            }
        }
        let dt = f(f64::from(BASIC_TIME_STEP_MS) / 1000.0);
        let v = SPEED_KMH / KMH_PER_MS;
        let geometry = *driver.geometry();
        let increments = PerWheel::from_fn(|w| {
            let r = if w.is_front() {
                geometry.radius_front()
            } else {
                geometry.radius_rear()
            };
            f(v * (1.0 + SLIP[w.index()])) / r * dt
        });
        let mut sensors = Sensors::unsampled(T::ZERO);
        sensors.wheel_angles = PerWheel::splat(T::ZERO);
        Ok(ControlLoop {
            driver,
            sensors,
            increments,
            dt,
            step: 0,
        })
    }

    /// One control-loop step: the next steering command, [`Driver::step`] on the frame, then
    /// the frame advances (the steering sensors read back the commanded angles).
    pub fn step(&mut self) -> &Commands<T> {
        let i = (self.step % STEERING.len() as u32) as usize;
        let delta = STEERING.get(i).copied().unwrap_or(0.0);
        self.driver.set_steering_angle(T::from_f64(delta));
        let commands = self.driver.step(&self.sensors);

        self.sensors.steering = commands.steering;
        self.step += 1;
        if self.step.is_multiple_of(WRAP_STEPS) {
            self.sensors.time = T::ZERO;
            self.sensors.wheel_angles = PerWheel::splat(T::ZERO);
        } else {
            self.sensors.time += self.dt;
            for (a, d) in self
                .sensors
                .wheel_angles
                .iter_mut()
                .zip(self.increments.iter())
            {
                *a += *d;
            }
        }
        self.driver.commands()
    }

    /// The driver under test.
    pub fn driver(&self) -> &Driver<T> {
        &self.driver
    }

    /// The frame the next step will read.
    pub fn sensors(&self) -> &Sensors<T> {
        &self.sensors
    }

    /// Encoder increment of `wheel` per step (rad).
    pub fn increment(&self, wheel: Wheel) -> T {
        self.increments[wheel]
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use vehicle_model::{ControlMode, WheelDrive};

    #[test]
    fn torque_loop_drives_all_four_wheels_with_limited_slip() {
        let mut l = ControlLoop::<f64>::new(LoopMode::Torque).unwrap();
        assert_eq!(l.driver().control_mode(), ControlMode::Torque);
        for _ in 0..100 {
            l.step();
        }
        let c = *l.step();
        // 4x4 torque mode: every wheel gets a torque command, and the torques differ because
        // the wheels slip differently and the steering moves.
        let torques: Vec<f64> = c.drive.iter().map(|d| d.torque().unwrap()).collect();
        assert!(torques.iter().all(|t| t.is_finite()));
        assert!(torques.iter().any(|&t| t != torques[0]));
        // The estimated speed is the frame's: 30 km/h times the mean slip factor
        // (1 + (−0.02 + 0.03 − 0.01 + 0.02)/4) = 1.005 → 30.15 km/h.
        assert!((l.driver().current_speed() - 30.15).abs() < 1e-6);
        // The limited-slip integrators have moved (the wheels never turn alike).
        let lsd = l.driver().limited_slip();
        assert!(lsd.front() != 0.0 && lsd.rear() != 0.0);
    }

    #[test]
    fn speed_loop_commands_velocities_and_steers() {
        let mut l = ControlLoop::<f32>::new(LoopMode::Speed).unwrap();
        assert_eq!(l.driver().control_mode(), ControlMode::Speed);
        // Step k commands STEERING[k % 16]; after 5 steps the last command is 0.2 rad.
        for _ in 0..5 {
            l.step();
        }
        assert!((l.driver().commanded_steering_angle() - 0.2).abs() < 1e-6);
        let c = *l.step();
        assert!(matches!(
            c.drive[Wheel::RearLeft],
            WheelDrive::Velocity { .. }
        ));
        assert!(c.steering.right != c.steering.left);
    }

    #[test]
    fn the_frame_wraps_back_to_its_start() {
        let mut l = ControlLoop::<f32>::new(LoopMode::Torque).unwrap();
        let d = l.increment(Wheel::FrontRight);
        // FR: 30 km/h · 0.98 / r per second, r = the model's front radius.
        let r = l.driver().front_wheel_radius();
        assert!((d - (30.0 / KMH_PER_MS as f32) * 0.98 / r * 0.01).abs() < 1e-7);
        for _ in 0..WRAP_STEPS - 1 {
            l.step();
        }
        let s = *l.sensors();
        let a = s.wheel_angles[Wheel::FrontRight];
        // f32 sums of 4095 increments: rounding of up to 3·10⁻⁵ rad each near 900 rad.
        assert!((a - 4095.0 * d).abs() < 0.13, "{a} vs {}", 4095.0 * d);
        assert!((s.time - 40.95).abs() < 1e-2);
        l.step();
        assert_eq!(l.sensors().wheel_angles, PerWheel::splat(0.0));
        assert_eq!(l.sensors().time, 0.0);
        // Two steps after the wrap the speed estimate is back to the frame's 30.15 km/h.
        let mut l = ControlLoop::<f64>::new(LoopMode::Torque).unwrap();
        for _ in 0..WRAP_STEPS + 3 {
            l.step();
        }
        assert!((l.driver().current_speed() - 30.15).abs() < 1e-6);
    }
}
