//! Cars on rapier joints: the Webots `AckermannVehicle` rebuilt from rigid bodies.
//!
//! # Layout
//!
//! * **chassis**: one dynamic body with the model's mass, centre of mass and inertia tensor and
//!   a collision box ([`ChassisSpec`]). Its rapier frame sits at its centre of mass; the car
//!   frame (origin at the rear-axle centre at wheel-centre height, x forward, y left, z up) is
//!   derived from it;
//! * **front wheels** (Webots `Hinge2Joint`): chassis → *knuckle* joint with the suspension on
//!   LinZ and the steering on AngZ, then knuckle → wheel spin joint on AngY. rapier cannot free
//!   two angular axes of one joint in sequence, hence the knuckle, a small body (a quarter of
//!   the wheel mass, taken from the chassis so the car's mass and centre of mass are kept);
//! * **rear wheels** (Webots `HingeJoint`): one chassis → wheel joint, suspension on LinZ and
//!   spin on AngY;
//! * **wheels**: solid cylinders (radius `tireRadius`, length `thickness`, the wheel mass) whose
//!   axis is rapier's local y, the spin axis. They touch only static geometry.
//!
//! All joints form one rapier **multibody** (reduced coordinates) rooted at the chassis. Impulse
//! joints were tried first: cheaper, but their iterative solution between a 2-tonne chassis,
//! 8 kg knuckles and 30 kg wheels left a steering offset of up to 0.07 rad and a creep of
//! 0.1 m/s at rest, and made the heavier cars wander. Multibody joints are exact, give the
//! joint coordinates directly (continuous wheel angles, steering angles, suspension travel)
//! and carry per-DoF implicit springs, damping and dry friction.
//!
//! # Actuators
//!
//! * **suspension** (LinZ): an implicit joint spring `k` with its rest position at the unloaded
//!   wheel height plus implicit DoF damping `c` (Webots: the ODE suspension's `erp`/`cfm` from
//!   `k` and `c`); no stops, as in Webots;
//! * **steering** (AngZ): the Webots position controller ([`PositionServo`]: P = 10, at most
//!   10 rad/s) sets a rigid velocity motor limited to `maxSteeringTorque`; the joint angle is
//!   −steering (positive steering turns right, a rotation about −z);
//! * **wheel spin** (AngY): implicit DoF damping `wheelsDampingConstant` (exactly Webots' joint
//!   damping) and, per step, from the [`WheelDrive`] command:
//!   * `Velocity`: the ramped command of a [`VelocityRamp`] on a rigid velocity motor of
//!     10⁸ N·m (Webots `maxTorque`); brakes and damping are overpowered, as in Webots;
//!   * `Torque(τ)`: `τ` applied with `add_torque` to the wheel and its opposite to the carrier
//!     (knuckle or chassis), the motor switched off;
//!   * `Free`: motor off, no torque;
//!   * the **brake** (any mode) is the DoF's dry friction of magnitude `brake_torque`: a
//!     Coulomb torque opposing the rotation that also holds a stopped wheel. rapier's one motor
//!     per axis is thus never shared: drive on the motor, brake on the DoF friction, damping on
//!     the DoF damping.
//!
//! The wipers are kinematic: their angle follows the Webots position controller (P = 10) at the
//! commanded velocity within the wiper range; no body is simulated.

mod build;
mod spec;

use ackermann::{PerWheel, Wheel, WheelAngles};
use rapier3d::prelude::{JointAxis, PhysicsWorld, RigidBody, Vector};

use vehicle_model::{Commands, Sensors, WheelDrive};

pub use spec::{ChassisSpec, SpringDamper, SteeringSpec, VehicleSpec, WheelSpec};

use crate::error::{BodyOwner, BodyPart, ParamError, SimError};
use crate::geom;
use crate::motor::{self, PositionServo, VelocityRamp, WHEEL_MOTOR_MAX_TORQUE};
use build::Parts;

/// Handle of a car in a [`World`](crate::World).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, PartialOrd, Ord)]
pub struct VehicleId(pub(crate) usize);

impl VehicleId {
    /// The car's index in its world (0 for the first car added).
    pub const fn index(self) -> usize {
        self.0
    }
}

/// Where a car starts.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct VehiclePlacement {
    /// World x of the car origin (m).
    pub x: f64,
    /// World y of the car origin (m).
    pub y: f64,
    /// Heading (rad, counter-clockwise about +z from +x).
    pub yaw: f64,
    /// Height of the car origin (m); `None` puts the rear wheels on the ground (z = 0) with
    /// unloaded springs: the body then settles by the static deflection of the springs in about
    /// half a second.
    pub z: Option<f64>,
}

/// The physical state of a car after a step: what a test bench would measure on the body.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct VehicleState {
    /// Position of the car origin (rear-axle centre at wheel-centre height), m, world frame.
    pub position: [f64; 3],
    /// Roll, pitch and yaw of the chassis (rad, z-y-x convention; yaw in (−π, π]).
    pub roll_pitch_yaw: [f64; 3],
    /// Velocity of the car origin (m/s, world frame), from the chassis rigid body.
    pub velocity: [f64; 3],
    /// Signed speed along the chassis x axis (m/s, positive forward).
    pub forward_speed: f64,
    /// Yaw rate (rad/s, counter-clockwise about world +z).
    pub yaw_rate: f64,
    /// Acceleration of the centre of mass along the chassis x axis over the last step (m/s²).
    pub longitudinal_acceleration: f64,
    /// Acceleration of the centre of mass along the chassis y axis (left) over the last step
    /// (m/s²): positive in a left turn.
    pub lateral_acceleration: f64,
    /// Wheel spin speeds relative to their carrier (rad/s, positive = rolling forward).
    pub wheel_speeds: PerWheel<f64>,
    /// Continuous wheel rotation angles (rad, positive = rolling forward): the Webots wheel
    /// position sensors.
    ///
    /// Each step adds `wheel_speeds · dt`, the rotation at the solved end-of-step spin rate.
    /// rapier's own joint coordinate is integrated from the velocity of its biased solver
    /// pass, which leaves out the tyre friction (solved in the relaxation pass, as rapier does
    /// by default): under a drive torque it runs ahead by up to `τ·dt²/I` per step (0.1 rad
    /// for a BmwX5 front wheel in first gear) and would feed the driver library a jittering,
    /// too-high wheel speed.
    pub wheel_angles: PerWheel<f64>,
    /// Measured front steering angles (rad, positive = right): the Webots steering sensors.
    pub steering: WheelAngles<f64>,
    /// Suspension compression of each wheel from its unloaded position (m, positive = wheel
    /// pushed up toward the body).
    pub suspension: PerWheel<f64>,
    /// Wiper angle (rad), `None` for a car without wipers.
    pub wiper: Option<f64>,
}

/// A car in a world: its bodies, its latest commands and its measured state.
#[derive(Debug, Clone)]
pub struct Vehicle {
    id: VehicleId,
    spec: VehicleSpec,
    parts: Parts,
    commands: Option<Commands<f64>>,
    ramps: PerWheel<Option<VelocityRamp>>,
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
        ParamError::finite("placement.x", placement.x)?;
        ParamError::finite("placement.y", placement.y)?;
        ParamError::finite("placement.yaw", placement.yaw)?;
        let z = match placement.z {
            Some(z) => ParamError::finite("placement.z", z)?,
            None => {
                let [rr, rl] = [Wheel::RearRight, Wheel::RearLeft]
                    .map(|w| spec.wheels[w].radius - spec.wheels[w].position[2]);
                0.5 * (rr + rl)
            }
        };
        let origin = geom::pose_xyz_yaw([placement.x, placement.y, z], placement.yaw);
        let parts = build::build(world, &spec, origin).ok_or(SimError::NonFinite {
            owner: BodyOwner::Vehicle(id.0),
            part: BodyPart::Chassis,
            time_ms: 0,
        })?;
        Ok(Vehicle {
            id,
            spec,
            parts,
            commands: None,
            ramps: PerWheel::splat(None),
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

    /// The largest wheel rotation (rad) of the last step: the world sub-steps rapier when it is
    /// large.
    pub(crate) fn max_wheel_rotation(&self, dt: f64) -> f64 {
        self.state
            .wheel_speeds
            .iter()
            .fold(0.0_f64, |m, w| m.max(w.abs()))
            * dt
    }

    /// Applies the commands to the joints for the coming step of `dt` seconds.
    pub(crate) fn pre_step(&mut self, world: &mut PhysicsWorld, dt: f64) {
        let commands = self.commands;
        let steering = commands
            .as_ref()
            .map_or(WheelAngles::new(0.0, 0.0), |c| c.steering);
        let measured = self.state.steering;
        for (handle, target, angle) in [
            (self.parts.steer_joints[0], steering.right, measured.right),
            (self.parts.steer_joints[1], steering.left, measured.left),
        ] {
            let v = self.steering_servo.velocity(target, angle);
            if let Some(j) = build::joint_mut(world, handle) {
                motor::set_rigid_velocity_motor(
                    j,
                    JointAxis::AngZ,
                    -v,
                    self.spec.steering.max_torque,
                );
            }
        }

        for h in self.parts.bodies() {
            if let Some(b) = world.bodies.get_mut(h) {
                b.reset_torques(false);
            }
        }
        for w in Wheel::ALL {
            let (drive, brake) = match &commands {
                Some(c) => (c.drive[w], c.brake_torque[w]),
                None => (WheelDrive::Free, 0.0),
            };
            let brake = if brake.is_finite() {
                brake.max(0.0)
            } else {
                0.0
            };
            let handle = self.parts.spin_joints[w];
            build::set_dof_friction(world, handle, Parts::spin_dof(w), brake);
            match drive {
                WheelDrive::Velocity {
                    target,
                    acceleration,
                    max_velocity,
                } => {
                    let omega = self.state.wheel_speeds[w];
                    let ramp = self.ramps[w].get_or_insert(VelocityRamp::starting_at(omega));
                    let command = ramp.step(target, acceleration, max_velocity, dt);
                    if let Some(j) = build::joint_mut(world, handle) {
                        motor::set_rigid_velocity_motor(
                            j,
                            JointAxis::AngY,
                            command,
                            WHEEL_MOTOR_MAX_TORQUE,
                        );
                    }
                }
                WheelDrive::Torque(_) | WheelDrive::Free => {
                    self.ramps[w] = None;
                    if let Some(j) = build::joint_mut(world, handle) {
                        motor::set_motor_off(j, JointAxis::AngY);
                    }
                    if let WheelDrive::Torque(t) = drive
                        && t.is_finite()
                        && t != 0.0
                    {
                        let t = t.clamp(-WHEEL_MOTOR_MAX_TORQUE, WHEEL_MOTOR_MAX_TORQUE);
                        self.apply_spin_torque(world, w, t);
                    }
                }
            }
        }

        if let (Some(angle), Some([lo, hi])) = (self.state.wiper, self.spec.wiper_range)
            && let Some(cmd) = commands.as_ref().and_then(|c| c.cockpit.wipers)
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

    /// Applies `torque` (N·m) about wheel `w`'s spin axis to the wheel and its reaction to the
    /// carrier, as a Webots torque-controlled motor does.
    fn apply_spin_torque(&self, world: &mut PhysicsWorld, w: Wheel, torque: f64) {
        let carrier = self.parts.carrier(w);
        let Some(axis) = world.bodies.get(carrier).map(|b| *b.rotation() * Vector::Y) else {
            return;
        };
        let t = axis * torque as f32;
        if let Some(b) = world.bodies.get_mut(self.parts.wheels[w]) {
            b.add_torque(t, true);
        }
        if let Some(b) = world.bodies.get_mut(carrier) {
            b.add_torque(-t, true);
        }
    }

    /// Reads the state back after the physics step of `dt` seconds ending at `time_ms`.
    pub(crate) fn post_step(
        &mut self,
        world: &PhysicsWorld,
        dt: f64,
        time_ms: u64,
    ) -> Result<(), SimError> {
        let fail = |part| SimError::NonFinite {
            owner: BodyOwner::Vehicle(self.id.0),
            part,
            time_ms,
        };
        for (h, part) in [
            (self.parts.chassis, BodyPart::Chassis),
            (self.parts.knuckles[0], BodyPart::Knuckle(Wheel::FrontRight)),
            (self.parts.knuckles[1], BodyPart::Knuckle(Wheel::FrontLeft)),
        ]
        .into_iter()
        .chain(Wheel::ALL.map(|w| (self.parts.wheels[w], BodyPart::Wheel(w))))
        {
            if !world.bodies.get(h).is_some_and(finite) {
                return Err(fail(part));
            }
        }
        let chassis = world
            .bodies
            .get(self.parts.chassis)
            .ok_or(fail(BodyPart::Chassis))?;
        let mut s = self.state;
        for (i, handle) in self.parts.steer_joints.into_iter().enumerate() {
            let w = if i == 0 {
                Wheel::FrontRight
            } else {
                Wheel::FrontLeft
            };
            let (c, _) = build::joint_state(world, handle).ok_or(fail(BodyPart::Knuckle(w)))?;
            s.suspension[w] = f64::from(c[build::LIN_Z]);
            let steer = -f64::from(c[build::ANG_Z]);
            if i == 0 {
                s.steering.right = steer;
            } else {
                s.steering.left = steer;
            }
        }
        for w in Wheel::ALL {
            let (c, v) = build::joint_state(world, self.parts.spin_joints[w])
                .ok_or(fail(BodyPart::Wheel(w)))?;
            s.wheel_speeds[w] = f64::from(v[Parts::spin_dof(w)]);
            // Not rapier's joint coordinate: see `VehicleState::wheel_angles`.
            s.wheel_angles[w] += s.wheel_speeds[w] * dt;
            if !w.is_front() {
                s.suspension[w] = f64::from(c[build::LIN_Z]);
            }
        }
        let q = *chassis.rotation();
        let origin = chassis
            .position()
            .transform_point(-geom::vec3(self.parts.chassis_offset));
        s.position = geom::arr3(origin);
        s.roll_pitch_yaw = geom::roll_pitch_yaw(q);
        let v = chassis.velocity_at_point(origin);
        s.velocity = geom::arr3(v);
        s.forward_speed = f64::from(v.dot(q * Vector::X));
        s.yaw_rate = f64::from(chassis.angvel().z);
        let v_com = chassis.linvel();
        if let Some(prev) = self.previous_com_velocity {
            let a = (v_com - prev) / dt as f32;
            s.longitudinal_acceleration = f64::from(a.dot(q * Vector::X));
            s.lateral_acceleration = f64::from(a.dot(q * Vector::Y));
        }
        self.previous_com_velocity = Some(v_com);
        if !(s
            .wheel_angles
            .iter()
            .chain(s.wheel_speeds.iter())
            .all(|x| x.is_finite()))
        {
            return Err(fail(BodyPart::Chassis));
        }
        self.state = s;
        Ok(())
    }
}

/// True if the body's pose and velocities are finite.
fn finite(b: &RigidBody) -> bool {
    b.position().is_finite() && b.linvel().is_finite() && b.angvel().is_finite()
}
