//! A fake plant for the scenario tests: no physics engine, just enough kinematics to close the
//! loop (velocity motors ramp to their clamped targets, torques accelerate a wheel inertia,
//! steering motors reach their clamped targets within one step).

#![allow(dead_code)] // each test binary uses a different subset

pub mod golden;

use vehicle_model::{Commands, Driver, PerWheel, Real, Sensors, WheelAngles, WheelDrive};

/// The plant state and its clock.
pub struct Plant<T: Real> {
    pub dt: T,
    pub time: T,
    pub angles: PerWheel<T>,
    pub speeds: PerWheel<T>,
    pub steering: WheelAngles<T>,
    pub steering_limits: (T, T),
    /// Wheel inertia for torque commands (kg·m²).
    pub inertia: T,
    pub wiper: Option<T>,
}

impl<T: Real> Plant<T> {
    pub fn new(driver: &Driver<T>) -> Self {
        let p = driver.params();
        Plant {
            dt: T::from_f64(f64::from(driver.basic_time_step_ms()) / 1000.0),
            time: T::ZERO,
            angles: PerWheel::splat(T::ZERO),
            speeds: PerWheel::splat(T::ZERO),
            steering: WheelAngles::STRAIGHT,
            steering_limits: (p.min_steering_angle, p.max_steering_angle),
            inertia: T::from_f64(100.0),
            wiper: p.wipers.map(|w| w.min),
        }
    }

    pub fn sensors(&self) -> Sensors<T> {
        Sensors {
            time: self.time,
            wheel_angles: self.angles,
            steering: self.steering,
            wiper: self.wiper,
        }
    }

    /// Applies `c` for one step and advances the clock.
    pub fn apply(&mut self, c: &Commands<T>) {
        let dt = self.dt;
        for (i, drive) in c.drive.iter().enumerate() {
            let w = &mut self.speeds.0[i];
            match *drive {
                WheelDrive::Velocity {
                    target,
                    acceleration,
                    max_velocity,
                } => {
                    let target = target.clamp(-max_velocity, max_velocity);
                    let step = acceleration * dt;
                    *w += (target - *w).clamp(-step, step);
                }
                WheelDrive::Torque(t) => *w += t / self.inertia * dt,
                WheelDrive::Free => {}
            }
            self.angles.0[i] += *w * dt;
        }
        let (lo, hi) = self.steering_limits;
        self.steering = WheelAngles::new(
            c.steering.right.clamp(lo, hi),
            c.steering.left.clamp(lo, hi),
        );
        if let (Some(w), Some(cmd)) = (&mut self.wiper, c.cockpit.wipers) {
            let step = cmd.velocity * dt;
            *w += (cmd.target - *w).clamp(-step, step);
        }
        self.time += dt;
    }

    /// One closed-loop step.
    pub fn run(&mut self, driver: &mut Driver<T>) {
        let c = *driver.step(&self.sensors());
        self.apply(&c);
    }

    /// Sets constant wheel speeds (rad/s) that the plant keeps, ignoring the commands.
    pub fn roll(&mut self, driver: &mut Driver<T>, speeds: PerWheel<T>, steps: usize) {
        for _ in 0..steps {
            driver.step(&self.sensors());
            for i in 0..4 {
                self.angles.0[i] += speeds.0[i] * self.dt;
            }
            self.time += self.dt;
        }
    }
}

/// True if every number of `c` is finite and every brake torque non-negative.
pub fn all_finite<T: Real>(c: &Commands<T>) -> bool {
    c.is_finite() && c.brake_torque.iter().all(|t| *t >= T::ZERO)
}
