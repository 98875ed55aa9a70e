//! Cars on rapier: one rigid chassis on four shape-cast wheels, with Webots motor semantics.
//!
//! # Layout
//!
//! * **chassis**: one dynamic rapier body whose frame is the car frame (origin at the rear-axle
//!   centre at wheel-centre height, x forward, y left, z up), with the mass properties of the
//!   whole car (the model's body plus four solid-cylinder wheels at their unloaded positions)
//!   and a collision box ([`ChassisSpec`]) that meets walls, ramps and other cars;
//! * **wheels**: no rapier bodies. Each step the tyre, a cylinder of `tireRadius` × `thickness`
//!   turned by the wheel's steering angle, is swept down the chassis' −z axis from one radius
//!   above the wheel's hard point (its centre at the unloaded spring length) to the hard point;
//!   the first static surface it meets is the wheel's ground contact (point, normal, friction,
//!   and the spring compression). Each wheel keeps its own spin rate and, at the front, a
//!   steering angle.
//!
//! Webots builds the same car from ODE joints (`Hinge2Joint` at the front, `HingeJoint` at the
//! rear) and cylinder contacts. A rapier multibody of chassis, knuckles and cylinders was this
//! crate's first model: exact, but 56 µs per step, and rapier solves a multibody contact's
//! friction one world axis at a time, which made wheels away from the world axes chatter. The
//! wheels here are the same joints written as constraints of a small solver of our own
//! (`contact`), exact at any heading and about ten times cheaper; what changes is listed in
//! `COMPATIBILITY.md` (no wheel hop, one contact per wheel, found along the suspension axis).
//!
//! # Actuators and the step
//!
//! Before each rapier step, [`Vehicle::pre_step`](Vehicle) (in this order):
//!
//! * **steering**: the Webots position controller ([`PositionServo`]: P = 10, at most
//!   10 rad/s) gives a velocity command that a motor of `maxSteeringTorque` reaches at once or,
//!   against the wheel's inertia about the steering axis, within its torque; the angle stays
//!   within `[minSteeringAngle, maxSteeringAngle]`;
//! * **wheel spin**, from the [`WheelDrive`] command:
//!   * `Velocity`: the ramped command of a [`VelocityRamp`] is imposed (Webots `maxTorque`
//!     10⁸ N·m: never saturated); brakes and damping are overpowered, as in Webots;
//!   * `Torque(τ)`: `τ·dt/I` is added to the spin; the chassis takes the opposite torque;
//!   * `Free`: no torque;
//!   * in the last two, `wheelsDampingConstant` slows the spin (implicitly) and the brake is a
//!     Coulomb torque of at most `brake_torque` that also holds a stopped wheel;
//! * **gravity** is added to the chassis velocity, then the **suspension springs and dampers**
//!   (implicit, per axle `k` and `c`, no stops, as in Webots), the **tyre forces** (the car's
//!   [`TyreModel`]: the slip-based tyre linearised over the step, or Webots' friction pyramid
//!   with μ = the ground's friction) and the **brakes** are solved together (`contact`
//!   module), and the resulting chassis velocity goes to rapier, which integrates it and
//!   resolves the chassis' own collisions;
//! * after the solve, each slip-based tyre's transient slip advances with the end-of-step
//!   velocities, and the tyre forces, slips and loads are recorded ([`TyreTelemetry`]).
//!
//! The wipers are kinematic: their angle follows the Webots position controller (P = 10) at the
//! commanded velocity within the wiper range; no body is simulated.

mod cast;
mod contact;
mod joints;
mod spec;
mod state;

use ackermann::{PerWheel, Wheel, WheelAngles};
use proto_geom::plausible;
use rapier3d::prelude::{PhysicsWorld, Pose, RigidBody, RigidBodyHandle, Rotation, Vector};

use vehicle_model::tyre::LOW_SPEED;
use vehicle_model::{
    Commands, ContactVelocity, Linearised, Real, Sensors, TransientSlip, TyreModel, WheelDrive,
};

pub use spec::{
    ChassisSpec, Mounting, SpringDamper, SteeringSpec, TyreChoice, TyreSpec, VehicleSpec, WheelSpec,
};
pub use state::{TyreTelemetry, VehicleId, VehiclePlacement, VehicleState};

use crate::error::{BodyOwner, BodyPart, ParamError, SimError};
use crate::geom;
use crate::motor::{self, PositionServo, VelocityRamp};
use contact::{Body, Contact, Grip, Impulses, Spin, Support, WheelRow};

/// The rapier side of a car, by mounting.
#[derive(Debug, Clone)]
enum Parts {
    Cast(cast::Parts),
    Joints(joints::Parts),
}

/// Smallest cosine between the ground normal under a wheel and the chassis' up axis for the
/// wheel to stand on it (about 84°): a steeper face (a wall beside the tyre) is no ground.
const MIN_GROUND_COSINE: f32 = 0.1;

/// A car in a world: its chassis body, its wheels' state, its latest commands and its measured
/// state.
#[derive(Debug, Clone)]
pub struct Vehicle {
    id: VehicleId,
    spec: VehicleSpec,
    parts: Parts,
    commands: Option<Commands<f64>>,
    ramps: PerWheel<Option<VelocityRamp>>,
    /// Steering rates of the front wheels `[right, left]` (rad/s, positive = right).
    steering_rates: [f64; 2],
    /// The tyre solve's impulses of the last step: the next step's warm start.
    impulses: PerWheel<Impulses>,
    /// Transient slip of each slip-based tyre.
    slips: PerWheel<TransientSlip<f64>>,
    previous_com_velocity: Option<Vector>,
    state: VehicleState,
    steering_servo: PositionServo,
}

impl Vehicle {
    pub(crate) fn new(
        id: VehicleId,
        world: &mut PhysicsWorld,
        spec: VehicleSpec,
        placement: VehiclePlacement,
    ) -> Result<Self, SimError> {
        spec.validate()?;
        ParamError::within("placement.x", placement.x, plausible::POSITION)?;
        ParamError::within("placement.y", placement.y, plausible::POSITION)?;
        ParamError::finite("placement.yaw", placement.yaw)?;
        let z = match placement.z {
            Some(z) => ParamError::within("placement.z", z, plausible::POSITION)?,
            None => {
                let [rr, rl] = [Wheel::RearRight, Wheel::RearLeft]
                    .map(|w| spec.wheels[w].radius - spec.wheels[w].position[2]);
                0.5 * (rr + rl)
            }
        };
        let origin = geom::pose_xyz_yaw([placement.x, placement.y, z], placement.yaw);
        let parts = match spec.mounting {
            Mounting::Cast => Parts::Cast(cast::build(world, &spec, origin)),
            Mounting::Joints => Parts::Joints(
                joints::build(world, &spec, origin)
                    .ok_or(SimError::JointRefused(BodyOwner::Vehicle(id.0)))?,
            ),
        };
        Ok(Vehicle {
            id,
            spec,
            parts,
            commands: None,
            ramps: PerWheel::splat(None),
            steering_rates: [0.0; 2],
            impulses: PerWheel::splat(Impulses::default()),
            slips: PerWheel::splat(TransientSlip::default()),
            previous_com_velocity: None,
            state: VehicleState {
                position: [placement.x, placement.y, z],
                roll_pitch_yaw: [0.0, 0.0, geom::wrap(placement.yaw)],
                wiper: spec.wiper_range.map(|[lo, _]| lo),
                ..VehicleState::default()
            },
            steering_servo: PositionServo::steering(
                spec.steering.min_angle,
                spec.steering.max_angle,
            ),
        })
    }

    /// This car's handle.
    pub fn id(&self) -> VehicleId {
        self.id
    }

    /// The rapier bodies of this car: the chassis, then (on joints) the knuckles and wheels.
    pub(crate) fn bodies(&self) -> Vec<RigidBodyHandle> {
        match &self.parts {
            Parts::Cast(p) => vec![p.chassis],
            Parts::Joints(p) => [p.chassis]
                .into_iter()
                .chain(p.knuckles)
                .chain(p.wheels.iter().copied())
                .collect(),
        }
    }

    /// The description the car was built from.
    pub fn spec(&self) -> &VehicleSpec {
        &self.spec
    }

    /// The state measured after the last step.
    pub fn state(&self) -> &VehicleState {
        &self.state
    }

    /// The sensor readings a controller sees at time `time` (s): the wheel position sensors,
    /// the steering sensors and the wiper sensor of the last step.
    pub fn sensors(&self, time: f64) -> Sensors<f64> {
        Sensors {
            time,
            wheel_angles: self.state.wheel_angles,
            steering: self.state.steering,
            wiper: self.state.wiper,
        }
    }

    /// The commands in force (the last ones set), `None` before the first.
    pub fn commands(&self) -> Option<&Commands<f64>> {
        self.commands.as_ref()
    }

    /// Sets the actuator commands, applied from the next step and kept until replaced (Webots
    /// motor targets persist the same way). Before any command the steering holds 0 and the
    /// wheels roll freely.
    pub fn set_commands(&mut self, commands: &Commands<f64>) {
        self.commands = Some(*commands);
    }

    /// The steering angles commanded (rad, positive = right): 0 before the first command.
    fn steering_target(&self) -> WheelAngles<f64> {
        self.commands
            .as_ref()
            .map_or(WheelAngles::new(0.0, 0.0), |c| c.steering)
    }

    /// Moves the steering for the coming step of `dt` seconds: the Webots position controller's
    /// velocity command, reached within `maxSteeringTorque` against the wheel's inertia about
    /// the steering axis.
    fn steer(&mut self, dt: f64) {
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

    /// Sets up wheel `w`'s spin for the step: the imposed rate of a velocity command, or a free
    /// spin after the drive torque and the damping, with its brake.
    fn spin(&mut self, w: Wheel, dt: f64) -> (Spin, f64) {
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
        let inertia = self.spec.wheels[w].spin_inertia();
        let wheel = vehicle_model::actuator::WheelSpin {
            inertia,
            damping: self.spec.wheels_damping,
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

    /// Applies the commands for the coming step of `dt` seconds: steering, wheel spins, then
    /// the tyre and brake solve (with the suspension, for a cast car), whose results rapier
    /// integrates.
    pub(crate) fn pre_step(&mut self, world: &mut PhysicsWorld, dt: f64) {
        self.step_wipers(dt);
        match self.parts.clone() {
            Parts::Cast(p) => self.pre_step_cast(world, &p, dt),
            Parts::Joints(p) => self.pre_step_joints(world, &p, dt),
        }
    }

    /// The cast car's step: the steering is this crate's; the suspension, tyres, brakes and
    /// spins are solved together on the chassis, whose velocity goes to rapier.
    fn pre_step_cast(&mut self, world: &mut PhysicsWorld, parts: &cast::Parts, dt: f64) {
        self.steer(dt);
        let Some(chassis) = world.bodies.get(parts.chassis) else {
            return;
        };
        let frame = Frame::of(chassis);
        let mut body = Body::new(
            chassis.linvel() + world.gravity * dt as f32,
            chassis.angvel(),
            parts.inv_mass,
            parts.inv_inertia,
            frame.pose.rotation,
        );
        let mut rows = [WheelRow::idle(); 4];
        let mut imposed = [0.0; 4];
        let mut axes = [Vector::ZERO; 4];
        let mut roads = [0.0; 4];
        for (i, w) in Wheel::ALL.into_iter().enumerate() {
            let (steer, axis) = self.wheel_axis(w, &frame);
            axes[i] = axis;
            imposed[i] = self.start_row(w, &mut rows[i], dt);
            if let Some((contact, road)) =
                cast::find_contact(world, &self.spec, w, &frame, steer, axis)
            {
                roads[i] = road;
                // The load the tyre's coefficients are taken at: the last step's, or the
                // spring's at the current compression for a wheel that just landed.
                let previous = f64::from(self.impulses[w].normal) / dt;
                let load = match contact.support {
                    Support::Spring(s) if previous <= 0.0 => f64::from(s.stiffness * s.compression),
                    _ => previous,
                };
                let footing = Footing {
                    road: f64::from(road),
                    load,
                };
                self.set_grip(w, &mut rows[i], contact, &body, footing, dt);
                rows[i].contact = Some(contact);
            }
        }
        contact::solve(&mut body, &mut rows, dt as f32);
        for (i, w) in Wheel::ALL.into_iter().enumerate() {
            let omega = rows[i].solved_spin(imposed[i]);
            self.react_to_spin(&mut body, w, axes[i], omega);
            self.finish_wheel(w, &rows[i], &body, f64::from(roads[i]), omega, dt);
        }
        if let Some(chassis) = world.bodies.get_mut(parts.chassis) {
            chassis.set_linvel(body.linvel, true);
            chassis.set_angvel(body.angvel, true);
        }
    }

    /// The step of a car on joints: rapier's steering motors get the position controller's
    /// velocities; the tyres, brakes and spins are solved on the whole car with the loads of
    /// rapier's last contacts, and go to rapier as tyre forces and spin motors.
    fn pre_step_joints(&mut self, world: &mut PhysicsWorld, parts: &joints::Parts, dt: f64) {
        let target = self.steering_target();
        let measured = self.state.steering;
        let rates = [
            self.steering_servo.velocity(target.right, measured.right),
            self.steering_servo.velocity(target.left, measured.left),
        ];
        joints::steer(world, parts, rates, self.spec.steering.max_torque);
        let Some(chassis) = world.bodies.get(parts.chassis) else {
            return;
        };
        let pose = joints::car_pose(chassis, parts);
        let frame = Frame {
            pose,
            com: pose.transform_point(parts.com),
            up: pose.rotation * Vector::Z,
        };
        let mut body = Body::new(
            chassis.velocity_at_point(frame.com) + world.gravity * dt as f32,
            chassis.angvel(),
            parts.inv_mass,
            parts.inv_inertia,
            pose.rotation,
        );
        let mut rows = [WheelRow::idle(); 4];
        let mut imposed = [0.0; 4];
        let mut roads = [0.0; 4];
        let mut grounds = [None; 4];
        for (i, w) in Wheel::ALL.into_iter().enumerate() {
            imposed[i] = self.start_row(w, &mut rows[i], dt);
            let (Some(g), Some((centre, axis))) = (
                joints::ground_contact(world, parts, w, frame.up),
                joints::wheel_frame(world, parts, w),
            ) else {
                continue;
            };
            let radius = self.spec.wheels[w].radius as f32;
            let support = Support::Given { normal: g.normal };
            let Some(contact) =
                Contact::on_ground(support, g.normal, axis, centre, radius, frame.com)
            else {
                continue;
            };
            rows[i].impulses.normal = g.impulse;
            roads[i] = g.friction;
            grounds[i] = g.body;
            let footing = Footing {
                road: f64::from(g.friction),
                load: f64::from(g.impulse) / dt,
            };
            self.set_grip(w, &mut rows[i], contact, &body, footing, dt);
            rows[i].contact = Some(contact);
        }
        for row in &mut rows {
            row.cold_start_rigid_forward();
        }
        contact::solve(&mut body, &mut rows, dt as f32);
        for (i, w) in Wheel::ALL.into_iter().enumerate() {
            let omega = rows[i].solved_spin(imposed[i]);
            let tyre = rows[i].contact.map(|c| joints::TyreImpulse {
                impulse: c.forward * rows[i].impulses.forward
                    + c.lateral * rows[i].impulses.lateral,
                point: frame.com + c.contact_arm,
                ground: grounds[i],
            });
            joints::drive(world, parts, w, omega, tyre, dt as f32);
            self.finish_wheel(w, &rows[i], &body, f64::from(roads[i]), omega, dt);
        }
    }

    /// Sets up wheel `w`'s row for the step (spin, warm start), in the air until a contact is
    /// found; returns the spin rate a velocity command imposes (rad/s).
    fn start_row(&mut self, w: Wheel, row: &mut WheelRow, dt: f64) -> f64 {
        let (spin, omega) = self.spin(w, dt);
        row.spin = spin;
        row.omega = omega as f32;
        row.impulses = self.impulses[w];
        omega
    }

    /// The rotation of wheel `w` by its steering angle, and its spin axis in world axes (the
    /// chassis' y turned by the steering).
    fn wheel_axis(&self, w: Wheel, frame: &Frame) -> (Rotation, Vector) {
        let delta = match w {
            Wheel::FrontRight => self.state.steering.right,
            Wheel::FrontLeft => self.state.steering.left,
            Wheel::RearRight | Wheel::RearLeft => 0.0,
        };
        // Positive steering turns right: the wheel (its axis, car y) turned by −δ about z.
        let steer = Rotation::from_rotation_z(-delta as f32);
        (steer, frame.pose.rotation * (steer * Vector::Y))
    }

    /// The tyre law of wheel `w` (on the ground at `contact`, on `footing`) for the step: the
    /// slip-based tyre linearised at the velocities before the solve, with its rolling
    /// resistance added to the wheel's brake, or Webots' contact.
    fn set_grip(
        &self,
        w: Wheel,
        row: &mut WheelRow,
        contact: Contact,
        body: &Body,
        footing: Footing,
        dt: f64,
    ) {
        let Footing { road, load } = footing;
        row.grip = match self.spec.tyres.of(w) {
            TyreModel::Webots(c) => Grip::Coulomb {
                compliance: c.force_dependent_slip.map(|fds| (fds / dt) as f32),
                friction: road as f32,
            },
            TyreModel::MagicFormula(tyre) => {
                // Linearised at the spin the wheel starts the step with: the drive torque's
                // spin-up is part of the solve (a free spin is a row coordinate), and a
                // point near the step's solution keeps the linearisation accurate when a
                // large torque would spin the wheel far into sliding before the tyre acts.
                let omega = match row.spin {
                    Spin::Imposed => row.omega,
                    Spin::Free { .. } => self.state.wheel_speeds[w] as f32,
                };
                let v = contact_velocity(&contact, body, omega);
                let lin = tyre.linearise(&self.slips[w], &v, load, road, dt);
                if let Spin::Free { brake_impulse, .. } = &mut row.spin {
                    let rolling = tyre.rolling_resistance_torque(load, f64::from(contact.radius));
                    *brake_impulse += (rolling * dt) as f32;
                }
                let f32s = |v: [f64; 2]| v.map(|x| x as f32);
                Grip::Slip(Linearised {
                    force: f32s(lin.force),
                    damping: f32s(lin.damping),
                    slip_velocity: f32s(lin.slip_velocity),
                    friction: f32s(lin.friction),
                })
            }
        };
    }

    /// The reaction of wheel `w`'s angular acceleration on the chassis. The solve puts the
    /// tyre force at the contact point, which carries the reaction of the torque that the tyre
    /// balances; this adds the part that spun the wheel up or down (I·Δω), so a motor, brake
    /// or damper turning a wheel in the air, or a speed ramp, also turns the chassis the other
    /// way.
    fn react_to_spin(&self, body: &mut Body, w: Wheel, axis: Vector, omega: f64) {
        let spin_change = self.spec.wheels[w].spin_inertia() * (omega - self.state.wheel_speeds[w]);
        body.angvel -= body.inv_inertia * (axis * spin_change as f32);
    }

    /// Records wheel `w`'s end of step (spin `omega`, rad/s) and advances its tyre's transient
    /// slip.
    fn finish_wheel(
        &mut self,
        w: Wheel,
        row: &WheelRow,
        body: &Body,
        road: f64,
        omega: f64,
        dt: f64,
    ) {
        self.impulses[w] = row.impulses;
        self.state.wheel_speeds[w] = omega;
        let Some(contact) = row.contact else {
            self.state.suspension[w] = 0.0;
            self.state.tyres[w] = TyreTelemetry::default();
            // An unloaded tyre springs back.
            self.slips[w] = TransientSlip::default();
            return;
        };
        if let Support::Spring(s) = contact.support {
            self.state.suspension[w] = f64::from(s.compression);
        }
        let i = row.impulses;
        let [fx, fy, fz] = [i.forward, i.lateral, i.normal].map(|p| f64::from(p) / dt);
        let v = contact_velocity(&contact, body, omega as f32);
        if let TyreModel::MagicFormula(tyre) = self.spec.tyres.of(w) {
            tyre.relax(&mut self.slips[w], &v, fz, road, dt);
        }
        let reference = v.forward.abs().max(LOW_SPEED);
        let friction_use = match row.grip {
            Grip::Slip(law) if fz > 0.0 => {
                let [ax, ay] = law.friction.map(|mu| f64::from(mu) * fz);
                (fx / ax).hypot(fy / ay)
            }
            Grip::Coulomb { friction, .. } if fz > 0.0 => {
                fx.abs().max(fy.abs()) / (f64::from(friction) * fz)
            }
            _ => 0.0,
        };
        self.state.tyres[w] = TyreTelemetry {
            slip_ratio: -v.slip[0] / reference,
            slip_angle: (-v.slip[1]).atan2(reference),
            fx,
            fy,
            fz,
            friction_use: Real::finite_or(friction_use.min(1.0), 0.0),
        };
    }

    /// Moves the kinematic wipers toward their command for a step of `dt` seconds.
    fn step_wipers(&mut self, dt: f64) {
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

    /// True for a car on rapier joints ([`Mounting::Joints`]).
    pub(crate) fn on_joints(&self) -> bool {
        matches!(self.parts, Parts::Joints(_))
    }

    /// Which part of this car the rapier body `handle` is, if any.
    pub(crate) fn part_of(&self, handle: RigidBodyHandle) -> Option<BodyPart> {
        match &self.parts {
            Parts::Cast(p) => (p.chassis == handle).then_some(BodyPart::Chassis),
            Parts::Joints(p) => p.bodies().find(|(h, _)| *h == handle).map(|(_, part)| part),
        }
    }

    /// Reads the state back after the physics step of `dt` seconds ending at `time_ms`.
    pub(crate) fn post_step(
        &mut self,
        world: &PhysicsWorld,
        dt: f64,
        time_ms: u64,
    ) -> Result<(), SimError> {
        let fail = SimError::diverged(BodyOwner::Vehicle(self.id.0), time_ms);
        let mut s = self.state;
        let (chassis, pose, com) = match &self.parts {
            Parts::Cast(p) => {
                let chassis = geom::finite_body(world, p.chassis).ok_or(fail(BodyPart::Chassis))?;
                (chassis, *chassis.position(), chassis.center_of_mass())
            }
            Parts::Joints(p) => {
                for (h, part) in p.bodies() {
                    geom::finite_body(world, h).ok_or(fail(part))?;
                }
                let chassis = geom::finite_body(world, p.chassis).ok_or(fail(BodyPart::Chassis))?;
                let r = joints::read(world, p).ok_or(fail(BodyPart::Chassis))?;
                s.steering = WheelAngles::new(r.steering[0], r.steering[1]);
                s.suspension = r.suspension;
                s.wheel_speeds = r.spins;
                let pose = joints::car_pose(chassis, p);
                (chassis, pose, pose.transform_point(p.com))
            }
        };
        for w in Wheel::ALL {
            s.wheel_angles[w] += s.wheel_speeds[w] * dt;
            if !(s.wheel_angles[w].is_finite() && s.wheel_speeds[w].is_finite()) {
                return Err(fail(BodyPart::Wheel(w)));
            }
        }
        let q = pose.rotation;
        let origin = pose.translation;
        s.position = geom::arr3(origin);
        s.roll_pitch_yaw = geom::roll_pitch_yaw(q);
        let v = chassis.velocity_at_point(origin);
        s.velocity = geom::arr3(v);
        s.forward_speed = f64::from(v.dot(q * Vector::X));
        s.yaw_rate = f64::from(chassis.angvel().z);
        // The whole car's centre of mass: the chassis body's, unless the wheels are bodies.
        let v_com = chassis.velocity_at_point(com);
        if let Some(prev) = self.previous_com_velocity {
            let a = (v_com - prev) / dt as f32;
            s.longitudinal_acceleration = f64::from(a.dot(q * Vector::X));
            s.lateral_acceleration = f64::from(a.dot(q * Vector::Y));
        }
        self.previous_com_velocity = Some(v_com);
        self.state = s;
        Ok(())
    }
}

/// The ground under a tyre for one step.
#[derive(Debug, Clone, Copy)]
struct Footing {
    /// The ground's friction coefficient (dimensionless).
    road: f64,
    /// The tyre's load (N).
    load: f64,
}

/// The chassis' pose for one step.
struct Frame {
    /// The chassis frame (the car frame) in the world.
    pose: Pose,
    /// The centre of mass in the world (m).
    com: Vector,
    /// The chassis' up axis (unit).
    up: Vector,
}

impl Frame {
    fn of(chassis: &RigidBody) -> Frame {
        let pose = *chassis.position();
        Frame {
            pose,
            com: chassis.center_of_mass(),
            up: pose.rotation * Vector::Z,
        }
    }
}

/// The velocities of `contact` (m/s) on `body` for a wheel spinning at `omega` (rad/s).
fn contact_velocity(contact: &Contact, body: &Body, omega: f32) -> ContactVelocity<f64> {
    let v = body.velocity_at(contact.contact_arm);
    ContactVelocity {
        forward: f64::from(contact.forward.dot(v)),
        slip: contact.slip_velocity(body, omega).map(f64::from),
    }
}
