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
//!   the first static surface it meets is the wheel's ground contact (point, normal and the
//!   spring compression). Each wheel keeps its own spin rate and, at the front, a steering
//!   angle.
//!
//! Webots builds the same car from ODE joints (`Hinge2Joint` at the front, `HingeJoint` at the
//! rear) and cylinder contacts. The wheels here are those joints written as constraints of a
//! small solver of our own (`contact`), exact at any heading and about a sixth of the cost of
//! the same car in rapier; what changes is listed in `COMPATIBILITY.md` (no wheel hop, one
//! contact per wheel, found along the suspension axis). That car in rapier is the other
//! mounting (`joints`): a multibody of the chassis and four wheel bodies on suspension and
//! steering joints, with the same solve for the tyres, brakes and spins.
//!
//! # Actuators and the step
//!
//! Before each rapier step, [`Vehicle::pre_step`](Vehicle) (in this order):
//!
//! * **steering**: the Webots position controller ([`PositionServo`]: P = 10, at most
//!   10 rad/s) gives a velocity command that a motor of `maxSteeringTorque` reaches at once or,
//!   against the wheel's inertia about the steering axis, within its torque; the angle stays
//!   within `[minSteeringAngle, maxSteeringAngle]`;
//! * **wheel spin**, from the [`WheelDrive`](vehicle_model::WheelDrive) command:
//!   * `Velocity`: the ramped command of a [`VelocityRamp`] is imposed (Webots `maxTorque`
//!     10⁸ N·m: never saturated); brakes and damping are overpowered, as in Webots;
//!   * `Torque(τ)`: `τ·dt/I` is added to the spin; the chassis takes the opposite torque;
//!   * `Free`: no torque;
//!   * in the last two, `wheelsDampingConstant` slows the spin (implicitly) and the brake is a
//!     Coulomb torque of at most `brake_torque` that also holds a stopped wheel;
//! * **gravity** is added to the chassis velocity, then the **suspension springs and dampers**
//!   (implicit, per axle `k` and `c`, no stops, as in Webots), the **tyre forces** (the car's
//!   [`TyreModel`](vehicle_model::TyreModel): the slip-based tyre linearised over the step,
//!   or Webots' friction pyramid with μ = the ground's friction) and the **brakes** are
//!   solved together (`contact` module), and the resulting chassis velocity goes to rapier,
//!   which integrates it and resolves the chassis' own collisions;
//! * after the solve, each slip-based tyre's transient slip advances with the end-of-step
//!   velocities, and the tyre forces, slips and loads are recorded ([`TyreTelemetry`]).
//!
//! The wipers are kinematic: their angle follows the Webots position controller (P = 10) at the
//! commanded velocity within the wiper range; no body is simulated.
//!
//! # One step, two mountings
//!
//! The step above is written once (`step`) for both mountings. What differs is a `Mount`,
//! implemented by each mounting's rapier parts: how the steering moves (this crate's motor
//! model, or rapier's motors at the position controller's velocity), how the chassis' motion
//! is read (the chassis body's, or the multibody's generalized velocity), where a wheel
//! touches the ground (the shape cast, or rapier's last contacts, whose loads are then given
//! to the solve), and how the solved step reaches rapier (the chassis' velocity, or impulses
//! on the multibody). The ground's friction under a wheel (dimensionless, f64) is not read
//! back from rapier's colliders: both mountings ask the world's `Ground` for the surface they
//! touch at the contact point, the configured friction of the ground or of that obstacle
//! (that of a dynamic box under a joints car's wheel; the ground's for anything else, another
//! car or a robot).

// One concept per module: what a car is built from (`spec`) and what it measures (`state`);
// the Webots motors of a step (`actuators`); each wheel's row before and after the solve
// (`wheels`); the solve itself (`contact`); the step that ties the others together, once for
// both mountings (`step`); and, per mounting, the rapier bodies, the contact query and the
// rest of what `step`'s `Mount` asks (`cast`, `joints` with `multibody`). This file holds the
// car and its life in a world: construction, commands, the step's dispatch and the read-back.
mod actuators;
mod aero;
mod cast;
mod contact;
mod inertia;
mod joints;
mod multibody;
mod road_load;
mod spec;
mod state;
mod step;
pub(crate) mod teleport;
mod tread;
mod wheels;

pub(crate) use tread::WheelRoadHooks;

use ackermann::{PerWheel, Wheel, WheelAngles};
use proto_geom::nalgebra::{Point3, UnitQuaternion, Vector3};
use proto_geom::plausible;
use rapier3d::prelude::{PhysicsWorld, Pose, RigidBody, RigidBodyHandle, Vector};
use vehicle_model::{Commands, Sensors, SpinPrediction, SpinStep, TransientSlip};

pub use spec::{
    ChassisSpec, Mounting, SpringDamper, SteeringSpec, TyreChoice, TyreSpec, VehicleSpec, WheelSpec,
};
pub use state::{TyreTelemetry, VehicleId, VehiclePlacement, VehicleState};

use crate::attitude::RollPitchYaw;
use crate::error::{BodyOwner, BodyPart, ParamError, SimError};
use crate::geom;
use crate::ground::Ground;
use crate::motor::{PositionServo, VelocityRamp};
use contact::Impulses;

/// The rapier side of a car, by mounting.
#[derive(Debug, Clone)]
enum Parts {
    Cast(cast::Parts),
    Joints(multibody::Parts),
}

/// The height (m) of the origin of a car of `spec` whose rear wheels stand on z = 0 with
/// unloaded springs.
pub(crate) fn rest_height(spec: &VehicleSpec) -> f64 {
    let [rr, rl] = [Wheel::RearRight, Wheel::RearLeft]
        .map(|w| spec.wheels[w].radius - spec.wheels[w].position.z);
    0.5 * (rr + rl)
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
    /// What the step's sub-stepped tyre of each free wheel on the ground predicted for the end
    /// of the step (set up before the solve, used after it).
    predictions: PerWheel<Option<SpinPrediction<f64>>>,
    /// The sub-stepped tyre's step of each free wheel on the ground, begun before the solve
    /// and finished per axle ([`Vehicle::divide_axles`]).
    spin_steps: PerWheel<Option<SpinStep<f64>>>,
    previous_com_velocity: Option<Vector>,
    /// A car on joints: rapier has built its multibody's joint-space mass (at its first step),
    /// so impulses may go to it as velocity changes (`multibody`).
    joint_space_mass_ready: bool,
    state: VehicleState,
    steering_servo: PositionServo,
    /// Webots' `radarCrossSection` of the car's solid (m², ≥ 0; 0: radars do not see it).
    radar_cross_section: f64,
    /// The lane triangle each wheel's road ray hit last (a cast car's cache, see
    /// [`cast::RoadHits`]).
    road_hits: cast::RoadHits,
    /// The air's drag on the body over the last step (N), for telemetry
    /// ([`Vehicle::drag_force`]).
    drag_force: Option<f64>,
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
            None => rest_height(&spec),
        };
        let start = Point3::new(placement.x, placement.y, z);
        let origin = geom::pose_xyz_yaw(&start, placement.yaw);
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
            predictions: PerWheel::splat(None),
            spin_steps: PerWheel::splat(None),
            previous_com_velocity: None,
            joint_space_mass_ready: false,
            state: VehicleState {
                position: start,
                roll_pitch_yaw: RollPitchYaw {
                    yaw: geom::wrap(placement.yaw),
                    ..RollPitchYaw::default()
                },
                orientation: UnitQuaternion::from_axis_angle(&Vector3::z_axis(), placement.yaw),
                wiper: spec.wiper_range.map(|[lo, _]| lo),
                ..VehicleState::default()
            },
            steering_servo: PositionServo::steering(
                spec.steering.min_angle,
                spec.steering.max_angle,
            ),
            radar_cross_section: 0.0,
            road_hits: cast::RoadHits::default(),
            drag_force: None,
        })
    }

    /// Its `radarCrossSection` (m²): 0 (the default, as in Webots) hides it from radars.
    pub fn radar_cross_section(&self) -> f64 {
        self.radar_cross_section
    }

    /// Sets its `radarCrossSection` (m², finite and ≥ 0).
    ///
    /// # Errors
    /// [`ParamError`] naming `radarCrossSection` and the value.
    pub fn set_radar_cross_section(&mut self, rcs: f64) -> Result<(), ParamError> {
        self.radar_cross_section = ParamError::non_negative("radarCrossSection", rcs)?;
        Ok(())
    }

    /// This car's handle.
    pub fn id(&self) -> VehicleId {
        self.id
    }

    /// The rapier bodies of this car: the chassis, then (on joints) the wheels.
    pub(crate) fn bodies(&self) -> Vec<RigidBodyHandle> {
        match &self.parts {
            Parts::Cast(p) => vec![p.chassis],
            Parts::Joints(p) => [p.chassis]
                .into_iter()
                .chain(p.wheels.iter().copied())
                .collect(),
        }
    }

    /// The description the car was built from.
    pub fn spec(&self) -> &VehicleSpec {
        &self.spec
    }

    /// The specification, to break it behind the validation's back (the step's panic guard's
    /// test).
    #[cfg(test)]
    pub(crate) fn spec_mut(&mut self) -> &mut VehicleSpec {
        &mut self.spec
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

    /// Applies the commands for the coming step of `dt` seconds: steering, wheel spins, then
    /// the tyre and brake solve (with the suspension, for a cast car) on the friction that
    /// `ground` gives each wheel, whose results rapier integrates, and the air's force in
    /// `wind` (m/s, world frame) if the car has [`VehicleSpec::aero`].
    pub(crate) fn pre_step(
        &mut self,
        world: &mut PhysicsWorld,
        ground: &Ground,
        wind: Vector,
        dt: f64,
    ) {
        self.step_wipers(dt);
        match self.parts.clone() {
            Parts::Cast(p) => self.step_on(&p, world, ground, dt),
            Parts::Joints(p) => self.step_on(&p, world, ground, dt),
        }
        self.apply_aero(world, wind);
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
        let (motion, pose, com) = match &self.parts {
            Parts::Cast(p) => {
                let chassis = geom::finite_body(world, p.chassis).ok_or(fail(BodyPart::Chassis))?;
                (
                    Motion::of_body(chassis),
                    *chassis.position(),
                    chassis.center_of_mass(),
                )
            }
            Parts::Joints(p) => {
                for (h, part) in p.bodies() {
                    geom::finite_body(world, h).ok_or(fail(part))?;
                }
                let chassis = geom::finite_body(world, p.chassis).ok_or(fail(BodyPart::Chassis))?;
                let r = joints::read(world, p).ok_or(fail(BodyPart::Chassis))?;
                s.steering = WheelAngles::new(r.steering[0], r.steering[1]);
                s.suspension = r.suspension;
                let pose = joints::car_pose(chassis, p);
                // A multibody link's own velocities are those its last step started from.
                let motion = multibody::chassis_motion(world, p).ok_or(fail(BodyPart::Chassis))?;
                (motion, pose, pose.transform_point(p.com))
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
        s.position = geom::to_point(origin);
        s.roll_pitch_yaw = geom::roll_pitch_yaw(q);
        s.orientation = geom::to_rotation(q);
        if !(motion.linvel.is_finite() && motion.angvel.is_finite()) {
            return Err(fail(BodyPart::Chassis));
        }
        let v = motion.velocity_at(origin);
        s.velocity = geom::to_vector(v);
        s.forward_speed = f64::from(v.dot(q * Vector::X));
        s.yaw_rate = f64::from(motion.angvel.z);
        s.angular_velocity = geom::to_vector(motion.angvel);
        // The whole car's centre of mass: the chassis body's, unless the wheels are bodies.
        let v_com = motion.velocity_at(com);
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

/// The chassis' motion: the velocity (m/s) of its centre of mass `centre` (m, world) and its
/// angular velocity (rad/s), world axes.
#[derive(Debug, Clone, Copy)]
struct Motion {
    linvel: Vector,
    angvel: Vector,
    centre: Vector,
}

impl Motion {
    /// A rigid body's own velocities (those of a multibody link are a step old: see
    /// `multibody::chassis_motion`).
    fn of_body(b: &RigidBody) -> Motion {
        Motion {
            linvel: b.linvel(),
            angvel: b.angvel(),
            centre: b.center_of_mass(),
        }
    }

    /// Velocity (m/s) of the body's point at `p` (m, world).
    fn velocity_at(&self, p: Vector) -> Vector {
        self.linvel + self.angvel.cross(p - self.centre)
    }
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
