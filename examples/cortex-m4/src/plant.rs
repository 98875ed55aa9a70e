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
//!   with the end-of-step velocities ([`MagicFormula::relax`]).
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

// Transcendental maths goes through `Real` (libm), so that the host tests compute what the
// firmware does rather than std's versions.
use ackermann::{PerWheel, Pose, Real, Wheel, WheelAngles};
use solve::{Body, Row, Spin, point_velocity, to_wheel};
use vehicle_model::actuator::{
    PositionServo, SteeringMotor, SteeringState, VelocityRamp, WheelSpin,
};
use vehicle_model::{
    CarParams, Commands, ContactVelocity, MagicFormula, Sensors, TransientSlip, TyreClass,
    TyreError, WheelDrive,
};

/// Standard gravity (m/s²), as the sim crate's static loads use.
const GRAVITY: f32 = 9.81;
/// Air density at sea level, 15 °C (kg/m³).
const AIR_DENSITY: f32 = 1.225;
/// Webots' `Physics {}` density for a wheel whose model gives no mass (kg/m³), as the sim crate
/// gives such a wheel.
const DEFAULT_WHEEL_DENSITY: f32 = vehicle_model::DEFAULT_WHEEL_DENSITY as f32;
/// Block Gauss–Seidel sweeps over the four wheels per step. The wheels couple only through
/// the body, which is heavy next to a tyre's compliance over a step, so with the warm start
/// few are needed: with 2, the turns and stops of the tests agree with 30 sweeps to five
/// significant digits at 1, 10 and 32 ms.
const SWEEPS: usize = 4;

/// The physical constants of the plant that the car's parameters do not give.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Environment {
    /// Drag coefficient × frontal area (m²).
    pub drag_area: f32,
    /// Friction of the road (dimensionless): the ground's `friction` (Webots'
    /// `coulombFriction`), multiplying the tyres' peak friction.
    pub road_friction: f32,
    /// The kind of tyre the car rolls on, with its default coefficients.
    pub tyres: TyreClass,
}

impl Environment {
    /// A large SUV on passenger-car tyres on dry asphalt: CdA 0.95 m² (Cd 0.33 × 2.9 m²),
    /// road friction 1.
    pub const SUV_ON_ASPHALT: Environment = Environment {
        drag_area: 0.95,
        road_friction: 1.0,
        tyres: TyreClass::PassengerCar,
    };
}

/// A wheel's mass and moments of inertia: a uniform cylinder, as Webots computes them.
#[derive(Debug, Clone, Copy)]
struct WheelMass {
    /// Mass (kg).
    mass: f32,
    /// Moment of inertia about the axle (kg·m²).
    axial: f32,
    /// Moment of inertia about a diameter (kg·m²): about the steering axis, and about the
    /// vertical for the car's yaw.
    transverse: f32,
}

/// The constants of one wheel.
#[derive(Debug, Clone, Copy)]
struct Corner {
    /// Contact point − centre of mass, in body axes (m).
    arm: [f32; 2],
    /// Tyre radius (m).
    radius: f32,
    /// Spin inertia (kg·m²) and `wheelsDampingConstant` (N·m·s/rad).
    spin: WheelSpin<f32>,
    /// Load on the wheel at rest (N).
    static_load: f32,
    /// Change of load per m/s² of forward and of leftward acceleration (kg).
    transfer: [f32; 2],
    /// The tyre, fitted to the wheel's radius and static load.
    tyre: MagicFormula<f32>,
}

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
    /// A car at rest at the origin, heading along +x, with straight wheels, built from the
    /// driver's validated parameters (pass `driver.params()`).
    ///
    /// Wheel masses and inertias come from the wheels' `Physics` (a uniform cylinder, as
    /// Webots computes it); a wheel without mass gets Webots' `Physics {}` (1000 kg/m³ over
    /// its cylinder), as in the sim crate. The tyres are `environment.tyres` fitted to each
    /// axle's radius and static wheel load.
    ///
    /// # Errors
    /// The tyre coefficient that the fitted tyre refuses (not for a validated car).
    // Called once: out of line, its temporaries (four validated wheels, two tyre fits) do not
    // stay in the caller's stack frame for the whole run (1.3 KiB of the firmware's stack).
    #[inline(never)]
    pub fn new(params: &CarParams<f32>, environment: Environment) -> Result<Self, TyreError> {
        let wheelbase = params.wheelbase;
        let half_track = |w: Wheel| {
            let track = if w.is_front() {
                params.track_front
            } else {
                params.track_rear
            };
            if w.is_right() {
                -0.5 * track
            } else {
                0.5 * track
            }
        };
        let centre = |w: Wheel| [if w.is_front() { wheelbase } else { 0.0 }, half_track(w)];
        let wheel_mass = PerWheel::from_fn(|w| {
            let (valid, _) = params.wheels[w].validate();
            match valid.mass_properties().filter(|m| m.axial > 0.0) {
                Some(m) => WheelMass {
                    mass: m.mass,
                    axial: m.axial,
                    transverse: m.transverse,
                },
                None => {
                    let p = valid.params();
                    let r2 = p.tire_radius * p.tire_radius;
                    let mass = DEFAULT_WHEEL_DENSITY * core::f32::consts::PI * r2 * p.thickness;
                    WheelMass {
                        mass,
                        axial: 0.5 * mass * r2,
                        transverse: mass * (3.0 * r2 + p.thickness * p.thickness) / 12.0,
                    }
                }
            }
        });
        let body = &params.body;
        let [body_x, body_y, body_z] = body.center_of_mass;
        let mass = body.mass + wheel_mass.iter().map(|m| m.mass).sum::<f32>();
        let [com_x, com_y] = Wheel::ALL
            .iter()
            .fold([body.mass * body_x, body.mass * body_y], |[mx, my], &w| {
                let [x, y] = centre(w);
                [mx + wheel_mass[w].mass * x, my + wheel_mass[w].mass * y]
            })
            .map(|moment| moment / mass);
        let squared_distance = |[x, y]: [f32; 2]| {
            let [dx, dy] = [x - com_x, y - com_y];
            dx * dx + dy * dy
        };
        // The body's own inertia and the wheels' (each spinning about a diameter to turn),
        // moved to the common centre of mass.
        let yaw_inertia = params.body_inertia()[2]
            + body.mass * squared_distance([body_x, body_y])
            + Wheel::ALL
                .iter()
                .map(|&w| {
                    let m = wheel_mass[w];
                    m.transverse + m.mass * squared_distance(centre(w))
                })
                .sum::<f32>();

        // The sim crate's static loads, so that the tyres are fitted to the same loads.
        let front_share = (body_x / wheelbase).clamp(0.0, 1.0);
        let static_load = |w: Wheel| {
            let share = if w.is_front() {
                front_share
            } else {
                1.0 - front_share
            };
            GRAVITY * (0.5 * share * body.mass + wheel_mass[w].mass)
        };
        let fit = |w: Wheel| {
            let load = static_load(w).max(1.0);
            environment
                .tyres
                .params(params.axle_radius(w), load)
                .validate()
        };
        let (front_tyre, rear_tyre) = (fit(Wheel::FrontRight)?, fit(Wheel::RearRight)?);
        // Centre of mass over the road, which is one rear tyre radius below the car frame (the
        // wheel centres are at the frame's height: only the body lifts the centre of mass).
        let height = body.mass * body_z / mass + params.radius_rear();
        let roll_stiffness = [
            params.suspension_front_spring_constant * params.track_front * params.track_front,
            params.suspension_rear_spring_constant * params.track_rear * params.track_rear,
        ];
        let corners = PerWheel::from_fn(|w| {
            let (axle_roll, track) = if w.is_front() {
                (roll_stiffness[0], params.track_front)
            } else {
                (roll_stiffness[1], params.track_rear)
            };
            let pitch = 0.5 * mass * height / wheelbase;
            let roll = axle_roll / (roll_stiffness[0] + roll_stiffness[1]) * mass * height / track;
            let [x, y] = centre(w);
            Corner {
                arm: [x - com_x, y - com_y],
                radius: params.axle_radius(w),
                spin: WheelSpin {
                    inertia: wheel_mass[w].axial,
                    damping: params.wheels_damping_constant,
                },
                static_load: static_load(w),
                transfer: [
                    if w.is_front() { -pitch } else { pitch },
                    if w.is_right() { roll } else { -roll },
                ],
                tyre: if w.is_front() { front_tyre } else { rear_tyre },
            }
        });

        let steering_motor = |w: Wheel| SteeringMotor {
            servo: PositionServo::steering(params.min_steering_angle, params.max_steering_angle),
            max_torque: params.max_steering_torque,
            inertia: wheel_mass[w].transverse,
        };
        Ok(Plant {
            steering_motors: [
                steering_motor(Wheel::FrontRight),
                steering_motor(Wheel::FrontLeft),
            ],
            corners,
            mass,
            yaw_inertia,
            centre_of_mass: [com_x, com_y],
            environment,
            time_ms: 0,
            velocity: [0.0; 3],
            acceleration: [0.0; 2],
            wheel_speed: PerWheel::splat(0.0),
            wheel_angle: PerWheel::splat(0.0),
            steering: WheelAngles::STRAIGHT,
            steering_rate: WheelAngles::new(0.0, 0.0),
            wheel_motors: PerWheel::splat(None),
            slips: PerWheel::splat(TransientSlip::default()),
            forces: PerWheel::splat([0.0; 2]),
            pose: Pose::ORIGIN,
            distance: 0.0,
            faults: 0,
        })
    }
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
        for row in rows.iter_mut() {
            row.warm_start(&mut body);
        }
        for _ in 0..SWEEPS {
            for row in rows.iter_mut() {
                row.solve(&mut body);
            }
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
            corner
                .tyre
                .relax(&mut self.slips[w], &contact, row.load, road, dt);
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

    /// The Webots steering motors: a P controller capped in speed, targets clamped to the
    /// steering limits, the rate reached within the motor's torque.
    fn steer(&mut self, target: WheelAngles<f32>, dt: f32) {
        // The motors hold their angle on a non-finite target; the plant counts it.
        for t in [target.right, target.left] {
            if !t.is_finite() {
                self.fault();
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

    /// Wheel `w` set up for the solve of a step of `dt` (s): its spin before the tyre acts,
    /// its load, and its tyre's force law linearised at the start-of-step velocities.
    fn row(&mut self, w: Wheel, commands: &Commands<f32>, dt: f32) -> Row {
        let corner = self.corners[w];
        let (mut spin, spin_rate) = self.spin(w, commands, dt);
        let [ax, ay] = self.acceleration;
        let [forward_transfer, lateral_transfer] = corner.transfer;
        // A wheel cannot pull the road: it lifts off instead.
        let load = (corner.static_load + forward_transfer * ax + lateral_transfer * ay).max(0.0);
        let steer = match w {
            Wheel::FrontRight => self.steering.right,
            Wheel::FrontLeft => self.steering.left,
            Wheel::RearRight | Wheel::RearLeft => 0.0,
        };
        // Positive steering turns the wheel's heading clockwise.
        let heading = [Real::cos(steer), -Real::sin(steer)];
        // A free wheel's law is taken at the spin it starts the step with: its drive torque's
        // spin-up is part of the solve, as in the sim crate.
        let omega = match spin {
            Spin::Imposed => spin_rate,
            Spin::Free { .. } => self.wheel_speed[w],
        };
        let [forward, lateral] = to_wheel(heading, point_velocity(self.velocity, corner.arm));
        let contact = ContactVelocity {
            forward,
            slip: [forward - omega * corner.radius, lateral],
        };
        let road = self.environment.road_friction;
        let law = corner
            .tyre
            .linearise(&self.slips[w], &contact, load, road, dt);
        if let Spin::Free { capacity, .. } = &mut spin {
            *capacity += corner.tyre.rolling_resistance_torque(load, corner.radius) * dt;
        }
        Row {
            heading,
            arm: corner.arm,
            radius: corner.radius,
            spin,
            omega: spin_rate,
            brake: 0.0,
            load,
            normal: load * dt,
            law,
            impulse: self.forces[w].map(|f| f * dt),
        }
    }

    /// How wheel `w` spins over a step of `dt` (s) before the tyre acts, and its spin rate
    /// (rad/s): imposed by its velocity motor, or free after its drive torque and damping.
    fn spin(&mut self, w: Wheel, commands: &Commands<f32>, dt: f32) -> (Spin, f32) {
        let omega = self.wheel_speed[w];
        let brake = commands.brake_torque[w];
        let brake = if brake.is_finite() {
            brake.max(0.0)
        } else {
            self.fault();
            0.0
        };
        let drive = commands.drive[w];
        if let WheelDrive::Velocity {
            target,
            acceleration,
            max_velocity,
        } = drive
        {
            if target.is_finite() && acceleration.is_finite() && max_velocity.is_finite() {
                // The motor's command starts from the wheel's speed when speed mode begins.
                let ramp = self.wheel_motors[w].get_or_insert(VelocityRamp::starting_at(omega));
                return (
                    Spin::Imposed,
                    ramp.step(target, acceleration, max_velocity, dt),
                );
            }
            self.fault();
            // A running motor keeps its command; a wheel whose motor never ran rolls freely.
            if let Some(ramp) = self.wheel_motors[w] {
                return (Spin::Imposed, ramp.command());
            }
        } else {
            self.wheel_motors[w] = None;
        }
        let torque = match drive.torque() {
            Some(t) if !t.is_finite() => {
                self.fault();
                0.0
            }
            t => t.unwrap_or(0.0),
        };
        let wheel = self.corners[w].spin;
        let spin = Spin::Free {
            inertia: wheel.inertia,
            capacity: brake * dt,
        };
        (spin, wheel.step(omega, torque, dt))
    }

    /// Velocity of the rear-axle centre in body axes (m/s) for the centre-of-mass velocity and
    /// yaw rate `velocity`.
    fn rear_axle_velocity(&self, velocity: [f32; 3]) -> [f32; 2] {
        let [x, y] = self.centre_of_mass;
        point_velocity(velocity, [-x, -y])
    }

    /// Moves the rear-axle centre along the arc of constant body velocity `velocity` (m/s)
    /// that turns by `turn` (rad) in `dt` (s).
    fn advance_pose(&mut self, velocity: [f32; 2], turn: f32, dt: f32) {
        let half = 0.5 * turn;
        // The chord of the arc: the travelled vector times sin(h)/h, turned by half the turn.
        let sinc = if half == 0.0 {
            1.0
        } else {
            Real::sin(half) / half
        };
        let [dx, dy] = velocity.map(|v| v * dt * sinc);
        let heading = self.pose.yaw + half;
        let (sin, cos) = (Real::sin(heading), Real::cos(heading));
        let next = Pose::new(
            self.pose.x + dx * cos - dy * sin,
            self.pose.y + dx * sin + dy * cos,
            wrap_angle(self.pose.yaw + turn),
        );
        let distance = self.distance + Real::hypot(velocity[0], velocity[1]) * dt;
        if next.is_finite() && distance.is_finite() {
            self.pose = next;
            self.distance = distance;
        } else {
            self.fault();
        }
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

/// `angle` (rad) in (−π, π].
fn wrap_angle(angle: f32) -> f32 {
    use core::f32::consts::{PI, TAU};
    // `%` is the exact fmod; the corrections are exact too.
    let r = angle % TAU;
    if r > PI {
        r - TAU
    } else if r <= -PI {
        r + TAU
    } else {
        r
    }
}

mod solve;
#[cfg(test)]
mod tests;
