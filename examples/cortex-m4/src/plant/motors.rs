//! The Webots motors of the plant (steering servos, wheel velocity motors, drive torques and
//! brakes) and each wheel's set-up for the solve of a step: its spin, its load and its tyre's
//! linearised force law (sub-stepped over the step for a braked wheel, as in the sim crate).

use ackermann::{PerWheel, Real, Wheel, WheelAngles};
use vehicle_model::actuator::{SteeringState, VelocityRamp};
use vehicle_model::{Commands, ContactVelocity, FreeSpin, SpinStep, WheelDrive};

use super::Plant;
use super::solve::{Body, Row, Spin, point_velocity, to_wheel};

impl Plant {
    /// The Webots steering motors: a P controller capped in speed, targets clamped to the
    /// steering limits, the rate reached within the motor's torque.
    pub(super) fn steer(&mut self, target: WheelAngles<f32>, dt: f32) {
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
    pub(super) fn row(&mut self, w: Wheel, commands: &Commands<f32>, dt: f32) -> Row {
        let corner = self.corners[w];
        let (mut spin, spin_rate) = self.spin(w, commands, dt);
        let load = self.load(w, self.acceleration);
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
        let tyre = &corner.tyre;
        let slip = &self.slips[w];
        self.spin_steps[w] = None;
        if let Spin::Free { inertia, capacity } = &mut spin {
            // A braked wheel's spin and slip advance in sub-steps, as in the sim crate (its
            // `vehicle::wheels` says why only a braked one).
            let braked = *capacity > 0.0;
            *capacity += tyre.rolling_resistance_torque(load, corner.radius) * dt;
            let wheel = FreeSpin {
                inertia: *inertia,
                radius: corner.radius,
                spin: omega,
                drive: spin_rate - omega,
                brake: *capacity,
                chassis: 0.0,
            };
            if braked {
                self.spin_steps[w] = tyre.begin_spinning(slip, &contact, &wheel, load, road, dt);
            }
        }
        // Taken whole for now: `divide_axles` divides it if its axle needs.
        let (law, prediction) = match &self.spin_steps[w] {
            Some(step) => tyre.linearise_spun(step, false),
            None => (tyre.linearise(slip, &contact, load, road, dt), None),
        };
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
            prediction,
            impulse: self.forces[w].map(|f| f * dt),
        }
    }

    /// Begins the braked wheels' sub-stepped tyres again with what the first solve of the step
    /// found (`start` the body before it, `end` after it), as the sim crate does: the
    /// chassis' change of forward speed at each contact, and the mean of the step's start and
    /// end loads (the end's from the body's acceleration over the step). `rows` are the rows
    /// as they were before that solve. Returns whether any wheel was begun again (then the
    /// step is solved again); none is while every braked wheel is steady.
    pub(super) fn respin_braked(
        &mut self,
        rows: &mut PerWheel<Row>,
        start: &Body,
        end: &Body,
        dt: f32,
    ) -> bool {
        if !SpinStep::to_divide(&self.spin_steps).iter().any(|&d| d) {
            return false;
        }
        let acceleration = [0, 1].map(|i| (end.velocity[i] - start.velocity[i]) / dt);
        for w in Wheel::ALL {
            let Some(step) = self.spin_steps[w] else {
                continue;
            };
            let row = &mut rows[w];
            let change = row.contact(end)[0] - row.contact(start)[0];
            let load = 0.5 * (row.load + self.load(w, acceleration));
            self.spin_steps[w] = self.corners[w].tyre.respin(&step, change, load);
            // A step that cannot be begun again keeps the first one's law (taken whole).
            if self.spin_steps[w].is_some() {
                row.load = load;
                row.normal = load * dt;
            } else {
                row.prediction = None;
            }
        }
        self.set_spun_laws(rows, true);
        true
    }

    /// Wheel `w`'s load (N) with the body at `acceleration` (forward and leftward, m/s²): its
    /// static load plus the quasi-static transfer. A wheel cannot pull the road: it lifts off
    /// instead.
    // Called from each wheel's set-up and from its second solve: one copy.
    #[inline(never)]
    fn load(&self, w: Wheel, [ax, ay]: [f32; 2]) -> f32 {
        let corner = &self.corners[w];
        let [forward_transfer, lateral_transfer] = corner.transfer;
        (corner.static_load + forward_transfer * ax + lateral_transfer * ay).max(0.0)
    }

    /// Divides the step of the sub-stepped tyres of every axle on which one is not steady
    /// over the step taken whole: both wheels of an axle take the same path, so that a
    /// mirror-image pair gets mirror-image forces.
    pub(super) fn divide_axles(&self, rows: &mut PerWheel<Row>) {
        self.set_spun_laws(rows, false);
    }

    /// Sets the law and the prediction of the sub-stepped tyres in `rows`, divided as
    /// [`SpinStep::to_divide`] says: of those it divides, or, with `every`, of all of them.
    // Called before each solve of a step: one copy.
    #[inline(never)]
    fn set_spun_laws(&self, rows: &mut PerWheel<Row>, every: bool) {
        let divide = SpinStep::to_divide(&self.spin_steps);
        for w in Wheel::ALL {
            let Some(step) = self.spin_steps[w] else {
                continue;
            };
            if every || divide[w] {
                (rows[w].law, rows[w].prediction) =
                    self.corners[w].tyre.linearise_spun(&step, divide[w]);
            }
        }
    }

    /// How wheel `w` spins over a step of `dt` (s) before the tyre acts, and its spin rate
    /// (rad/s): imposed by its velocity motor, or free after its drive torque and damping.
    pub(super) fn spin(&mut self, w: Wheel, commands: &Commands<f32>, dt: f32) -> (Spin, f32) {
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
        // Under a torque command the wheel carries its equal share of the engaged engine's
        // inertia (`Commands::driveline`), as the sim crate's wheels do: without it a driven
        // wheel beyond its grip spins up at thousands of rad/s² and the driver's
        // wheel-acceleration limiter chatters (ARCHITECTURE.md, "Launch chatter").
        let mut wheel = self.corners[w].spin;
        wheel.inertia += commands.driveline_share(w).0;
        let spin = Spin::Free {
            inertia: wheel.inertia,
            capacity: brake * dt,
        };
        (spin, wheel.step(omega, torque, dt))
    }
}
