//! A small no_std plant model standing in for the car's physics: what the wheel encoders and
//! steering sensors of the real car would report, given the driver's actuator commands.
//!
//! # Model
//!
//! * **Longitudinal:** a point mass at the rear-axle centre moving at speed `v` (m/s), with
//!   the wheels rolling without slip (a rolling constraint). For the central steering angle δ
//!   each wheel's contact point moves at `k_w·v`, where `k_w` is its turning radius over the
//!   rear axle's ([`ackermann::Geometry::turning`]); it spins at `ω_w = k_w·v/r_w`. The wheel
//!   inertias `I_w` therefore add `Σ I_w·(k_w/r_w)²` to the mass, and a wheel torque `τ_w`
//!   pushes with `τ_w·k_w/r_w` (virtual power).
//! * **Forces:** drive torques (torque mode), aerodynamic drag `½·ρ·CdA·v·|v|`, and two
//!   dry frictions, the brakes (`Σ brake_w·k_w/r_w`) and the rolling resistance
//!   (`Crr·m·g`). A dry friction opposes the motion, stops the car exactly within a step
//!   when it can, and then holds it (no sign chatter, no creeping).
//! * **Velocity-controlled wheels** (speed mode): like Webots' wheel motors, each driven
//!   wheel's motor moves its velocity command toward the target by at most
//!   `acceleration·dt` per step (starting from the wheel's speed), clamps it to
//!   `±max_velocity` ([`VelocityRamp`]), and has unlimited torque: the car follows the mean of
//!   what the driven wheels impose.
//! * **Steering:** each steering motor is the Webots position servo, a P controller
//!   `ω = 10·(target − angle)` capped at 10 rad/s, with the target clamped to
//!   `[minSteeringAngle, maxSteeringAngle]`, whose rate is reached within `maxSteeringTorque`
//!   against the wheel's inertia about its steering axis ([`SteeringMotor`]).
//! * **Yaw and pose:** the kinematic bicycle model at the rear-axle centre,
//!   `ψ̇ = −v·tan δ / L` (positive δ turns right), integrated along exact arcs by
//!   [`ackermann::Odometry::integrate`].
//!
//! The motor rules are `vehicle_model::actuator`'s, the ones the `sim` crate applies too.
//! Everything is `f32`, allocation-free and panic-free. Non-finite commands are ignored and
//! counted ([`Plant::faults`]); a non-finite state is not masked, so that [`Plant::is_finite`]
//! exposes it.

use ackermann::{
    Geometry, Odometry, PerWheel, Pose, Real, SpeedSource, Turning, Velocity, Wheel, WheelAngles,
};
use vehicle_model::actuator::{PositionServo, SteeringMotor, SteeringState, VelocityRamp};
use vehicle_model::{CarParams, Commands, Sensors, WheelDrive};

/// Standard gravity (m/s²).
const GRAVITY: f32 = 9.81;
/// Air density at sea level, 15 °C (kg/m³).
const AIR_DENSITY: f32 = 1.225;
/// A wheel whose contact point moves slower than this fraction of the rear-axle speed (the
/// inner rear wheel of a very tight turn) cannot say how fast the car goes.
const MIN_SPEED_RATIO: f32 = 0.1;

/// The physical constants of the plant that the car's parameters do not give.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Environment {
    /// Drag coefficient × frontal area (m²).
    pub drag_area: f32,
    /// Rolling-resistance coefficient (dimensionless).
    pub rolling_resistance: f32,
}

impl Environment {
    /// A large SUV on dry asphalt: CdA 0.95 m² (Cd 0.33 × 2.9 m²), Crr 0.012.
    pub const SUV_ON_ASPHALT: Environment = Environment {
        drag_area: 0.95,
        rolling_resistance: 0.012,
    };
}

/// The simulated car: its state and the constants it moves by.
#[derive(Debug, Clone)]
pub struct Plant {
    geometry: Geometry<f32>,
    /// The front-right and front-left steering motors.
    steering_motors: [SteeringMotor<f32>; 2],
    /// Body plus wheels (kg).
    mass: f32,
    /// Axial inertia of each wheel (kg·m²).
    wheel_inertia: PerWheel<f32>,
    /// Tyre radius of each wheel (m).
    tyre_radius: PerWheel<f32>,
    environment: Environment,

    /// Elapsed time (ms), an integer so that it never drifts.
    time_ms: u32,
    /// Forward speed of the rear-axle centre (m/s).
    speed: f32,
    /// Wheel angular speeds (rad/s, positive = rolling forward).
    wheel_speed: PerWheel<f32>,
    /// Encoder angles (rad, continuous).
    wheel_angle: PerWheel<f32>,
    /// Front-wheel steering angles (rad, positive = right).
    steering: WheelAngles<f32>,
    /// Front-wheel steering rates (rad/s, positive = turning right).
    steering_rate: WheelAngles<f32>,
    /// Speed-mode velocity command of each wheel motor, `None` while not in speed mode.
    wheel_motors: PerWheel<Option<VelocityRamp<f32>>>,
    /// The true pose of the rear-axle centre, and the distance it travelled.
    pose: Odometry<f32>,
    /// Non-finite commands ignored, and pose updates refused.
    faults: u32,
}

impl Plant {
    /// A car at rest at the origin, heading along +x, with straight wheels, built from the
    /// driver's validated parameters (pass `driver.params()`).
    ///
    /// Wheel masses and inertias come from the wheels' `Physics` (a uniform cylinder, as
    /// Webots computes it); a wheel without physics counts as massless.
    pub fn new(params: &CarParams<f32>, environment: Environment) -> Self {
        let geometry = params.geometry().unwrap_or_default();
        let wheel_mass = PerWheel::from_fn(|w| params.wheels[w].validate().0.mass_properties());
        let wheels_total: f32 = wheel_mass.iter().flatten().map(|m| m.mass).sum();
        let steering_motor = |w: Wheel| SteeringMotor {
            servo: PositionServo::steering(params.min_steering_angle, params.max_steering_angle),
            max_torque: params.max_steering_torque,
            inertia: wheel_mass[w].map_or(0.0, |m| m.transverse),
        };
        Plant {
            geometry,
            steering_motors: [
                steering_motor(Wheel::FrontRight),
                steering_motor(Wheel::FrontLeft),
            ],
            mass: params.body.mass + wheels_total,
            wheel_inertia: wheel_mass.map(|m| m.map_or(0.0, |m| m.axial)),
            tyre_radius: PerWheel::from_fn(|w| params.axle_radius(w)),
            environment,
            time_ms: 0,
            speed: 0.0,
            wheel_speed: PerWheel::splat(0.0),
            wheel_angle: PerWheel::splat(0.0),
            steering: WheelAngles::STRAIGHT,
            steering_rate: WheelAngles::new(0.0, 0.0),
            wheel_motors: PerWheel::splat(None),
            pose: Odometry::new(geometry, SpeedSource::RearWheels),
            faults: 0,
        }
    }

    /// What the sensors read now: the time, the four encoders and the two steering angles.
    /// The car's wiper sensor is not modelled.
    pub fn sensors(&self) -> Sensors<f32> {
        Sensors {
            time: self.time_ms as f32 / 1000.0,
            wheel_angles: self.wheel_angle,
            steering: self.steering,
            wiper: None,
        }
    }

    /// Applies `commands` for `dt_ms` milliseconds.
    pub fn step(&mut self, commands: &Commands<f32>, dt_ms: u32) {
        let dt = dt_ms as f32 / 1000.0;
        self.steer(commands.steering, dt);

        let delta = self.geometry.central_angle_from_wheel_angles(self.steering);
        let ratio = self.speed_ratios(delta);
        let speed_before = self.speed;
        let wheel_speed_before = self.wheel_speed;

        let imposed = self.imposed_speed(&commands.drive, &ratio, dt);
        self.speed = match imposed {
            Some(v) => v,
            None => self.free_speed(commands, &ratio, dt),
        };
        self.wheel_speed = PerWheel::from_fn(|w| ratio[w] * self.speed / self.tyre_radius[w]);
        for w in Wheel::ALL {
            let mean = (wheel_speed_before[w] + self.wheel_speed[w]) * 0.5;
            self.wheel_angle[w] += mean * dt;
        }

        // Bicycle model at the rear-axle centre over the step's mean speed.
        let v = (speed_before + self.speed) * 0.5;
        let yaw_rate = -v * delta.tan() / self.geometry.wheelbase();
        if self.pose.integrate(Velocity::new(v, yaw_rate), dt).is_err() {
            self.faults = self.faults.saturating_add(1);
        }
        self.time_ms = self.time_ms.saturating_add(dt_ms);
    }

    /// The Webots steering motors: a P controller capped in speed, targets clamped to the
    /// steering limits, the rate reached within the motor's torque.
    fn steer(&mut self, target: WheelAngles<f32>, dt: f32) {
        // The motors hold their angle on a non-finite target; the plant counts it.
        for t in [target.right, target.left] {
            if !t.is_finite() {
                self.faults = self.faults.saturating_add(1);
            }
        }
        let [right, left] = self.steering_motors;
        let right = right.step(
            SteeringState {
                angle: self.steering.right,
                rate: self.steering_rate.right,
            },
            target.right,
            dt,
        );
        let left = left.step(
            SteeringState {
                angle: self.steering.left,
                rate: self.steering_rate.left,
            },
            target.left,
            dt,
        );
        self.steering = WheelAngles::new(right.angle, left.angle);
        self.steering_rate = WheelAngles::new(right.rate, left.rate);
    }

    /// Each wheel's contact-point speed over the rear-axle centre's (dimensionless).
    fn speed_ratios(&self, delta: f32) -> PerWheel<f32> {
        match self.geometry.turning(delta) {
            Turning::Straight => PerWheel::splat(1.0),
            Turning::Circle(r) => r.wheels.map(|radius| radius / r.rear_axle),
        }
    }

    /// Speed mode: the speed (m/s) the velocity-controlled wheels impose, after ramping their
    /// motors; `None` when no wheel is velocity-controlled.
    fn imposed_speed(
        &mut self,
        drive: &PerWheel<WheelDrive<f32>>,
        ratio: &PerWheel<f32>,
        dt: f32,
    ) -> Option<f32> {
        let mut sum = 0.0;
        let mut count = 0_u8;
        for w in Wheel::ALL {
            let WheelDrive::Velocity {
                target,
                acceleration,
                max_velocity,
            } = drive[w]
            else {
                self.wheel_motors[w] = None;
                continue;
            };
            if !(target.is_finite() && acceleration.is_finite() && max_velocity.is_finite()) {
                self.faults = self.faults.saturating_add(1);
                continue;
            }
            // The motor's command starts from the wheel's speed when speed mode begins.
            let command = self.wheel_motors[w]
                .get_or_insert(VelocityRamp::starting_at(self.wheel_speed[w]))
                .step(target, acceleration, max_velocity, dt);
            if ratio[w] > MIN_SPEED_RATIO {
                sum += command * self.tyre_radius[w] / ratio[w];
                count += 1;
            }
        }
        (count > 0).then(|| sum / f32::from(count))
    }

    /// Torque mode (or free rolling): the speed (m/s) after one step of drive torques, drag,
    /// brakes and rolling resistance acting on the rolling car.
    fn free_speed(&mut self, commands: &Commands<f32>, ratio: &PerWheel<f32>, dt: f32) -> f32 {
        let mut inertial_mass = self.mass;
        let mut drive_force = 0.0;
        let mut brake_capacity = 0.0;
        for w in Wheel::ALL {
            let lever = ratio[w] / self.tyre_radius[w]; // rad/m: wheel spin per metre travelled
            inertial_mass += self.wheel_inertia[w] * lever * lever;
            if let Some(torque) = commands.drive[w].torque() {
                if torque.is_finite() {
                    drive_force += torque * lever;
                } else {
                    self.faults = self.faults.saturating_add(1);
                }
            }
            let brake = commands.brake_torque[w];
            if brake.is_finite() {
                brake_capacity += brake.max(0.0) * lever.abs();
            } else {
                self.faults = self.faults.saturating_add(1);
            }
        }
        let v = self.speed;
        let drag = 0.5 * AIR_DENSITY * self.environment.drag_area * v * v.abs();
        let rolling = self.environment.rolling_resistance * self.mass * GRAVITY;
        let free_force = drive_force - drag;
        // The dry frictions: whatever stops the car within the step, up to their capacity.
        let force_to_stop = -(inertial_mass * v / dt + free_force);
        let capacity = brake_capacity + rolling;
        let friction = Real::clamp(force_to_stop, -capacity, capacity);
        v + dt * (free_force + friction) / inertial_mass
    }

    /// Elapsed time (s).
    pub fn time(&self) -> f32 {
        self.time_ms as f32 / 1000.0
    }

    /// Forward speed of the rear-axle centre (m/s).
    pub fn speed(&self) -> f32 {
        self.speed
    }

    /// The true pose of the rear-axle centre (m, m, rad counter-clockwise).
    pub fn pose(&self) -> Pose<f32> {
        self.pose.pose()
    }

    /// Path length of the rear-axle centre (m).
    pub fn distance(&self) -> f32 {
        self.pose.distance()
    }

    /// Number of non-finite command values ignored and pose updates refused so far (0 for a
    /// healthy controller).
    pub fn faults(&self) -> u32 {
        self.faults
    }

    /// True if every state variable is finite.
    pub fn is_finite(&self) -> bool {
        self.speed.is_finite()
            && self.wheel_speed.iter().all(|x| x.is_finite())
            && self.wheel_angle.iter().all(|x| x.is_finite())
            && self.steering.right.is_finite()
            && self.steering.left.is_finite()
            && self.steering_rate.right.is_finite()
            && self.steering_rate.left.is_finite()
            && self.pose.pose().is_finite()
    }
}
