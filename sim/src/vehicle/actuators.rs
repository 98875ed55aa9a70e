//! The Webots motors of a car for one step: the steering (the position controller, reached
//! within the motors' torque), each wheel's spin before the tyres act (the velocity ramp, or the
//! drive torque, damping and brake) and the kinematic wipers.

use ackermann::{Wheel, WheelAngles};
use vehicle_model::WheelDrive;

use super::Vehicle;
use super::contact::Spin;
use crate::motor::{self, PositionServo, VelocityRamp};

impl Vehicle {
    /// The steering angles commanded (rad, positive = right): 0 before the first command.
    fn steering_target(&self) -> WheelAngles<f64> {
        self.commands
            .as_ref()
            .map_or(WheelAngles::new(0.0, 0.0), |c| c.steering)
    }

    /// Moves the steering for the coming step of `dt` seconds: the Webots position controller's
    /// velocity command, reached within `maxSteeringTorque` against the wheel's inertia about
    /// the steering axis.
    pub(super) fn steer(&mut self, dt: f64) {
        use vehicle_model::actuator::{SteeringMotor, SteeringState};
        let target = self.steering_target();
        let motor = |w: Wheel| SteeringMotor {
            servo: self.steering_servo,
            max_torque: self.spec.steering.max_torque,
            inertia: self.spec.wheels[w].transverse_inertia(),
        };
        let [right_rate, left_rate] = self.steering_rates;
        let right = motor(Wheel::FrontRight).step(
            SteeringState {
                angle: self.state.steering.right,
                rate: right_rate,
            },
            target.right,
            dt,
        );
        let left = motor(Wheel::FrontLeft).step(
            SteeringState {
                angle: self.state.steering.left,
                rate: left_rate,
            },
            target.left,
            dt,
        );
        self.steering_rates = [right.rate, left.rate];
        self.state.steering = WheelAngles::new(right.angle, left.angle);
    }

    /// The position controller's steering velocities toward the command, `[right, left]`
    /// (rad/s, positive = right): what the steering motors of a car on joints turn at, within
    /// their torque.
    pub(super) fn steering_rates(&self) -> [f64; 2] {
        let target = self.steering_target();
        let measured = self.state.steering;
        [
            self.steering_servo.velocity(target.right, measured.right),
            self.steering_servo.velocity(target.left, measured.left),
        ]
    }

    /// Sets up wheel `w`'s spin for the step: the imposed rate of a velocity command, or a free
    /// spin after the drive torque and the damping, with its brake.
    pub(super) fn spin(&mut self, w: Wheel, dt: f64) -> (Spin, f64) {
        let (drive, brake) = match &self.commands {
            Some(c) => (c.drive[w], c.brake_torque[w]),
            None => (WheelDrive::Free, 0.0),
        };
        let omega = self.state.wheel_speeds[w];
        if let WheelDrive::Velocity {
            target,
            acceleration,
            max_velocity,
        } = drive
        {
            // The ramp starts from the axle's mean wheel speed: both motors of an axle take
            // over from the same command, so a settling or slipping wheel's speed at the
            // switch does not become a lasting left–right difference of the drive.
            let axle_mean = 0.5 * (omega + self.state.wheel_speeds[w.mirror()]);
            let ramp = self.ramps[w].get_or_insert(VelocityRamp::starting_at(axle_mean));
            return (
                Spin::Imposed,
                ramp.step(target, acceleration, max_velocity, dt),
            );
        }
        self.ramps[w] = None;
        let inertia = self.spin_inertia(w);
        let wheel = vehicle_model::actuator::WheelSpin {
            inertia,
            damping: self.viscous_wheel_drag(),
        };
        let omega = wheel.step(omega, drive.torque().unwrap_or(0.0), dt);
        let brake = if brake.is_finite() {
            brake.max(0.0)
        } else {
            0.0
        };
        let spin = Spin::Free {
            inv_inertia: (1.0 / inertia) as f32,
            brake_impulse: (brake * dt) as f32,
        };
        (spin, omega)
    }

    /// The inertia (kg·m²) wheel `w`'s spin is solved with: its own, plus, under a torque
    /// command, its equal share of the engine's inertia reflected through the engaged gear
    /// ([`Commands::driveline`](vehicle_model::Commands::driveline)). Not in Webots, whose
    /// wheels carry no engine (COMPATIBILITY.md): without it a driven wheel beyond its grip
    /// spins up at thousands of rad/s² and the driver's wheel-acceleration limiter chatters
    /// (ARCHITECTURE.md, "Launch chatter"). A velocity-controlled or free wheel keeps its own.
    pub(super) fn spin_inertia(&self, w: Wheel) -> f64 {
        self.spec.wheels[w].spin_inertia() + self.reflected_inertia(w)
    }

    /// Wheel `w`'s share of the engaged engine's reflected inertia (kg·m², ≥ 0; see
    /// [`spin_inertia`](Self::spin_inertia)): 0 unless it is under a torque command.
    pub(crate) fn reflected_inertia(&self, w: Wheel) -> f64 {
        self.driveline_share(w).0
    }

    /// The inertia (kg·m²) whose angular momentum changes, about wheel `w`'s axis, with its
    /// spin: its own, plus, under a torque command, its share of the engine's momentum per
    /// unit wheel speed `J_e·|ξ|` ([`Driveline::engine_momentum`]): the engine turns `|ξ|`
    /// times as fast as the wheel, and the gears' housings take the rest of the reflected
    /// `J_e·ξ²` from the chassis. The engine's axis is taken as the wheel's (a transverse
    /// engine turning with its wheels; a longitudinal one would react in roll).
    ///
    /// [`Driveline::engine_momentum`]: vehicle_model::Driveline::engine_momentum
    pub(super) fn spin_momentum_inertia(&self, w: Wheel) -> f64 {
        let (_, momentum) = self.driveline_share(w);
        self.spec.wheels[w].spin_inertia() + momentum
    }

    /// Wheel `w`'s share of the engaged engine, `(J_e·ξ², J_e·|ξ|)`
    /// ([`Commands::driveline_share`](vehicle_model::Commands::driveline_share): equal among
    /// the torque-driven wheels; it also resists their turning apart, which an open
    /// differential does not). A share in proportion to each wheel's torque was measured too
    /// and is worse: on the 4x4 Truck it feeds the limited slip's torque shifts between the
    /// axles back into their inertia, and the engine speed swung by up to 33 rpm
    /// (ARCHITECTURE.md, "Launch chatter"). `(0, 0)` before the first command.
    fn driveline_share(&self, w: Wheel) -> (f64, f64) {
        self.commands
            .as_ref()
            .map_or((0.0, 0.0), |c| c.driveline_share(w))
    }

    /// Moves the kinematic wipers toward their command for a step of `dt` seconds.
    pub(super) fn step_wipers(&mut self, dt: f64) {
        if let (Some(angle), Some([lo, hi])) = (self.state.wiper, self.spec.wiper_range)
            && let Some(cmd) = self.commands.as_ref().and_then(|c| c.cockpit.wipers)
        {
            let servo = PositionServo {
                gain: motor::POSITION_P_GAIN,
                max_velocity: if cmd.velocity.is_finite() {
                    cmd.velocity.abs()
                } else {
                    0.0
                },
                min_position: lo,
                max_position: hi,
            };
            let next = angle + servo.velocity(cmd.target, angle) * dt;
            self.state.wiper = Some(next.clamp(lo, hi));
        }
    }
}
