//! A small no_std plant model standing in for the car's physics: what the wheel encoders and
//! steering sensors of the real car would report, given the driver's actuator commands.
//!
//! # Model
//!
//! A planar car on the slip-based tyre of `vehicle_model::tyre`, solved the way the `sim`
//! crate solves its cars, so that a controller sees the same road on the Cortex-M4 as in the
//! simulator:
//!
//! * **Body:** a rigid body in the road plane (3 DOF: forward and lateral velocity of the
//!   centre of mass, yaw rate), with the mass of body plus wheels and a yaw inertia from the
//!   body's inertia (`CarParams::body_inertia`) and the wheels (uniform cylinders, as Webots
//!   computes them) moved to the common centre of mass. Aerodynamic drag `½·ρ·CdA·u·|u|`
//!   acts along the heading.
//! * **Wheels:** four spin rates. A velocity-controlled wheel (speed mode) follows the Webots
//!   ramp ([`VelocityRamp`]) with unlimited torque: its spin is imposed. A wheel in torque mode
//!   or rolling freely gets its drive torque and `wheelsDampingConstant` ([`WheelSpin`]), then
//!   the tyre force and a dry-friction brake of at most the brake torque plus the tyre's
//!   rolling resistance, which holds a stopped wheel ([`coulomb_torque`]).
//! * **Tyres:** each tyre's force per unit load is linearised over the step at the
//!   start-of-step contact velocities ([`MagicFormula::linearise`]; a free wheel at the spin it
//!   starts the step with), then solved implicitly, at the end-of-step slip velocities,
//!   together with the body and the free wheels' spins and brakes: block Gauss–Seidel sweeps
//!   over the wheels, each wheel's tyre force and brake solved exactly given the others, warm
//!   started from the last step's forces; each force is kept within the tyre's friction
//!   ellipse. The step is solved in the axes the body has at its end, so that each tyre meets
//!   its end-of-step slip in its own axes. After the step each tyre's transient slip relaxes
//!   with the end-of-step velocities ([`MagicFormula::relax`]). A braked wheel's spin and
//!   transient slip advance in sub-steps of at most 1 ms within the step, the body held
//!   ([`MagicFormula::linearise_spun`], [`MagicFormula::relax_spinning`]), as in the sim
//!   crate, so that its dive toward lock does not shrink with the step.
//! * **Loads:** the static loads of the sim crate (the body's weight shared between the axles
//!   by its centre of mass, plus each wheel's weight), plus a quasi-static load transfer from
//!   the last step's acceleration: `m·a_x·h/L` from the front to the rear axle, and
//!   `m·a_y·h/t` across each axle, shared between the axles in proportion to their roll
//!   stiffness (spring constant × track²), as the sim crate's springs share it in a steady
//!   turn. `h` is the centre of mass's height over the road. No pitch, roll or heave
//!   dynamics, no wheel hop, a flat road.
//! * **Steering:** each steering motor is the Webots position servo, a P controller
//!   `ω = 10·(target − angle)` capped at 10 rad/s, with the target clamped to
//!   `[minSteeringAngle, maxSteeringAngle]`, whose rate is reached within `maxSteeringTorque`
//!   against the wheel's inertia about its steering axis ([`SteeringMotor`]).
//! * **Pose:** the rear-axle centre along the exact arc of the step's mean body velocities.
//!
//! The motor rules are `vehicle_model::actuator`'s and the tyre is `vehicle_model::tyre`'s,
//! the ones the `sim` crate applies too. Everything is `f32`, allocation-free and panic-free.
//! Non-finite commands are ignored and counted ([`Plant::faults`]); a non-finite state is not
//! masked, so that [`Plant::is_finite`] exposes it.

// One concept per module: the constants a plant is built with (`build`), the Webots motors and
// each wheel's set-up for a step (`motors`), the implicit solve of the step (`solve`) and the
// pose's advance along the step's arc (`pose`); this file holds the state and the step that
// ties them together.
mod build;
mod motors;
mod pose;
mod solve;
#[cfg(test)]
mod tests;

// Transcendental maths goes through `Real` (libm), so that the host tests compute what the
// firmware does rather than std's versions.
use ackermann::{PerWheel, Pose, Real, WheelAngles};
use solve::{Body, point_velocity, solve_step};
use vehicle_model::actuator::{SteeringMotor, VelocityRamp};
use vehicle_model::{Commands, ContactVelocity, Sensors, SpinStep, TransientSlip};

use build::Corner;
pub use build::Environment;

/// Air density at sea level, 15 °C (kg/m³).
const AIR_DENSITY: f32 = 1.225;
/// Block Gauss–Seidel sweeps over the four wheels per step. The wheels couple only through
/// the body, which is heavy next to a tyre's compliance over a step, so with the warm start
/// few are needed: with 2, the turns and stops of the tests agree with 30 sweeps to five
/// significant digits at 1, 10 and 32 ms.
const SWEEPS: usize = 4;

/// The simulated car: its state and the constants it moves by.
#[derive(Debug, Clone)]
pub struct Plant {
    /// The front-right and front-left steering motors.
    steering_motors: [SteeringMotor<f32>; 2],
    corners: PerWheel<Corner>,
    /// Body plus wheels (kg).
    mass: f32,
    /// Yaw inertia about the centre of mass (kg·m²).
    yaw_inertia: f32,
    /// Centre of mass − rear-axle centre, x forward and y left (m).
    centre_of_mass: [f32; 2],
    environment: Environment,

    /// Elapsed time (ms), an integer so that it never drifts.
    time_ms: u32,
    /// Velocity of the centre of mass in body axes, forward and leftward (m/s), and the yaw
    /// rate (rad/s, counter-clockwise).
    velocity: [f32; 3],
    /// Acceleration of the centre of mass over the last step, in body axes, forward and
    /// leftward (m/s²).
    acceleration: [f32; 2],
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
    /// Each tyre's transient slip.
    slips: PerWheel<TransientSlip<f32>>,
    /// Each braked wheel's sub-stepped tyre step of the step being solved (`None` for the
    /// others).
    spin_steps: PerWheel<Option<SpinStep<f32>>>,
    /// Each tyre's force over the last step along its heading and its axis (N): the warm
    /// start of the next solve.
    forces: PerWheel<[f32; 2]>,
    /// The true pose of the rear-axle centre (m, m, rad counter-clockwise).
    pose: Pose<f32>,
    /// Path length of the rear-axle centre (m).
    distance: f32,
    /// Non-finite commands ignored, and pose updates refused.
    faults: u32,
}

impl Plant {
    /// What the sensors read now: the time, the four encoders and the two steering angles.
    /// The car's wiper sensor is not modelled.
    pub fn sensors(&self) -> Sensors<f32> {
        Sensors {
            time: self.time(),
            wheel_angles: self.wheel_angle,
            steering: self.steering,
            wiper: None,
        }
    }

    /// Applies `commands` for `dt_ms` milliseconds. A step of 0 ms changes nothing.
    pub fn step(&mut self, commands: &Commands<f32>, dt_ms: u32) {
        if dt_ms == 0 {
            return;
        }
        let dt = dt_ms as f32 / 1000.0;
        self.steer(commands.steering, dt);

        let start = self.velocity;
        let spin_before = self.wheel_speed;
        // The step is solved in the axes the body has at its end, having turned at its
        // start-of-step yaw rate, so that each tyre meets its end-of-step slip in its own
        // end-of-step axes (in the start-of-step axes its lateral slip would be off by
        // u·r·dt, 0.05 m/s at 30 km/h in a 15 m turn and 10 ms steps).
        let [u0, v0, r] = start;
        let (sin, cos) = (Real::sin(r * dt), Real::cos(r * dt));
        let [u, v] = [cos * u0 + sin * v0, cos * v0 - sin * u0];
        // Drag is implicit in the forward speed: linear in it about the start of the step.
        let drag = 0.5 * AIR_DENSITY * self.environment.drag_area * u.abs();
        let forward_mass = self.mass + dt * drag;
        let mut body = Body {
            velocity: [self.mass * u / forward_mass, v, r],
            inverse: [1.0 / forward_mass, 1.0 / self.mass, 1.0 / self.yaw_inertia],
        };
        let mut rows = PerWheel::from_fn(|w| self.row(w, commands, dt));
        let (start_body, mut again) = (body, rows);
        self.divide_axles(&mut rows);
        solve_step(&mut body, &mut rows);
        if self.respin_braked(&mut again, &start_body, &body, dt) {
            (body, rows) = (start_body, again);
            solve_step(&mut body, &mut rows);
        }

        self.velocity = body.velocity;
        for (w, row) in rows.iter_wheels() {
            let omega = row.omega;
            let corner = &self.corners[w];
            let [forward, lateral] = row.contact(&body);
            let contact = ContactVelocity {
                forward,
                slip: [forward - omega * corner.radius, lateral],
            };
            let road = self.environment.road_friction;
            let slip = &mut self.slips[w];
            match &row.prediction {
                Some(p) => corner
                    .tyre
                    .relax_spinning(slip, p, &contact, row.load, road, dt),
                None => corner.tyre.relax(slip, &contact, row.load, road, dt),
            }
            self.forces[w] = row.impulse.map(|p| p / dt);
            self.wheel_angle[w] += 0.5 * (spin_before[w] + omega) * dt;
            self.wheel_speed[w] = omega;
        }
        let [u1, v1, r1] = self.velocity;
        self.acceleration = [(u1 - u) / dt, (v1 - v) / dt];

        let [start_x, start_y] = self.rear_axle_velocity(start);
        let [end_x, end_y] = self.rear_axle_velocity(self.velocity);
        let mean = [0.5 * (start_x + end_x), 0.5 * (start_y + end_y)];
        self.advance_pose(mean, 0.5 * (r + r1) * dt, dt);
        self.time_ms = self.time_ms.saturating_add(dt_ms);
    }

    /// Velocity of the rear-axle centre in body axes (m/s) for the centre-of-mass velocity and
    /// yaw rate `velocity`.
    fn rear_axle_velocity(&self, velocity: [f32; 3]) -> [f32; 2] {
        let [x, y] = self.centre_of_mass;
        point_velocity(velocity, [-x, -y])
    }

    /// Counts an ignored command value or a refused pose update.
    fn fault(&mut self) {
        self.faults = self.faults.saturating_add(1);
    }

    /// Elapsed time (s).
    pub fn time(&self) -> f32 {
        self.time_ms as f32 / 1000.0
    }

    /// Forward speed of the rear-axle centre (m/s).
    pub fn speed(&self) -> f32 {
        self.rear_axle_velocity(self.velocity)[0]
    }

    /// Yaw rate of the car (rad/s, counter-clockwise).
    pub fn yaw_rate(&self) -> f32 {
        self.velocity[2]
    }

    /// Acceleration of the centre of mass over the last step, in the car's axes: forward and
    /// leftward (m/s²).
    pub fn acceleration(&self) -> [f32; 2] {
        self.acceleration
    }

    /// The true pose of the rear-axle centre (m, m, rad counter-clockwise).
    pub fn pose(&self) -> Pose<f32> {
        self.pose
    }

    /// Path length of the rear-axle centre (m).
    pub fn distance(&self) -> f32 {
        self.distance
    }

    /// Number of non-finite command values ignored and pose updates refused so far (0 for a
    /// healthy controller).
    pub fn faults(&self) -> u32 {
        self.faults
    }

    /// True if every state variable is finite.
    pub fn is_finite(&self) -> bool {
        let finite = |x: &f32| x.is_finite();
        self.velocity.iter().all(finite)
            && self.acceleration.iter().all(finite)
            && self.wheel_speed.iter().all(finite)
            && self.wheel_angle.iter().all(finite)
            && self
                .slips
                .iter()
                .all(|s| s.ratio.is_finite() && s.angle_tan.is_finite())
            && self.forces.iter().flatten().all(finite)
            && [self.steering, self.steering_rate]
                .iter()
                .all(|a| a.right.is_finite() && a.left.is_finite())
            && self.pose.is_finite()
            && self.distance.is_finite()
    }
}
