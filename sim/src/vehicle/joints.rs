//! The car on rapier joints (`mounting = "joints"`): the Webots `Car` PROTO's bodies and joints
//! as one rapier multibody, with the tyre forces of the same solve as the cast car.
//!
//! # Bodies and joints
//!
//! * **chassis**: the model's body (mass, centre of mass, inertia tensor) less the two
//!   knuckles, and the collision box; its rapier frame sits at its own centre of mass, the root
//!   of the multibody (a free root far from its centre of mass, like the Truck's rear axle 4.5 m
//!   behind it, makes rapier's reduced-coordinate solve drift);
//! * **front wheels** (Webots `Hinge2Joint`): chassis → *knuckle* on a joint whose free axes are
//!   the suspension (LinZ, the chassis' vertical) and the steering (AngZ), then knuckle → wheel
//!   on a spin hinge (AngY). A rapier joint cannot free two angular axes one after the other,
//!   hence the knuckle: a small body (a quarter of the wheel's mass, taken from the chassis so
//!   the car keeps its mass and centre of mass);
//! * **rear wheels** (Webots `HingeJoint`): chassis → wheel, suspension (LinZ) and spin (AngY);
//! * **wheels**: solid cylinders of `tireRadius` × `thickness` with the wheel's mass, whose axis
//!   is rapier's local y, the spin axis. They collide with the ground, ramps, steps, boxes and
//!   other cars (not with their own car: the multibody's self-contacts are off), and their
//!   rapier friction is 0: the tyre forces are this crate's.
//!
//! All joints form one rapier **multibody** (reduced coordinates): exact joints at a 2-tonne
//! chassis on 8 kg knuckles, where impulse joints leave a steering offset and a creep at rest.
//!
//! # Who solves what
//!
//! rapier: the joints, the **suspension** (an implicit joint spring `k` at the unloaded length
//! and implicit DoF damping `c`, no stops, as Webots' ODE suspension), the **steering motors**
//! (rigid velocity motors of `maxSteeringTorque` at the Webots position controller's velocity),
//! the **wheel–ground normal contacts** and every collision.
//!
//! This crate: the **tyre forces**, brakes and wheel spins, by the cast car's solve
//! (`contact`): each wheel's ground contact of the last rapier step gives the contact normal,
//! the load (its normal impulse) and the ground's friction; the solve runs on the whole car as
//! one rigid body (the joints hold the wheels to the chassis in the ground plane) with the
//! loads given, and its results go to rapier as the tyre force at each contact point on the
//! wheel (its reaction on the ground, if the ground is a dynamic body) and as each spin
//! joint's rigid velocity motor at the solved spin: the motor's torque, which rapier applies
//! between wheel and carrier, is the drive, brake and damping torque the solve found.

use ackermann::{PerWheel, Wheel};
use proto_geom::nalgebra::Point3;
use rapier3d::prelude::{
    CoefficientCombineRule, ColliderBuilder, ColliderHandle, GenericJoint, GenericJointBuilder,
    JointAxesMask, JointAxis, MassProperties, Mat3, Multibody, MultibodyJointHandle, PhysicsWorld,
    Pose, RigidBody, RigidBodyBuilder, RigidBodyHandle, RigidBodyType, Vector,
};

use super::cast::{body_inertia, mass_properties};
use super::contact::{self, Body, Contact, Support, WheelRow};
use super::spec::{SpringDamper, VehicleSpec};
use super::wheels::Footing;
use super::{Frame, MIN_GROUND_COSINE, Vehicle};
use crate::geom::{self, G_CAR_BODY, G_CAR_WHEEL};
use crate::motor::{self, WHEEL_MOTOR_MAX_TORQUE};

/// A knuckle's mass as a fraction of its wheel's (dimensionless): light enough not to change
/// the car, heavy enough for the multibody's mass matrix to stay well conditioned.
const KNUCKLE_MASS_FRACTION: f64 = 0.25;

/// Index of LinZ in rapier's 6-DoF spatial layout (lin x, y, z, ang x, y, z).
const LIN_Z: usize = 2;
/// Index of AngZ in rapier's 6-DoF spatial layout.
const ANG_Z: usize = 5;

/// The rapier handles of one car on joints and the whole car's mass properties.
#[derive(Debug, Clone)]
pub(crate) struct Parts {
    pub chassis: RigidBodyHandle,
    /// The chassis body's frame in the car frame: its own centre of mass (m).
    pub chassis_offset: Vector,
    /// Steering knuckles of the front wheels, `[FR, FL]`.
    pub knuckles: [RigidBodyHandle; 2],
    pub wheels: PerWheel<RigidBodyHandle>,
    pub colliders: PerWheel<ColliderHandle>,
    /// chassis → knuckle joints `[FR, FL]`: suspension (LinZ, DoF 0), steering (AngZ, DoF 1).
    pub steer_joints: [MultibodyJointHandle; 2],
    /// Spin joints: knuckle → wheel at the front (AngY, DoF 0); chassis → wheel at the rear
    /// (suspension LinZ, DoF 0, and spin AngY, DoF 1).
    pub spin_joints: PerWheel<MultibodyJointHandle>,
    /// The whole car's centre of mass in the car frame (m).
    pub com: Vector,
    /// 1/total mass (1/kg).
    pub inv_mass: f32,
    /// Inverse inertia tensor of the whole car about its centre of mass, car frame
    /// (1/(kg·m²)).
    pub inv_inertia: Mat3,
}

impl Parts {
    /// The local index of the spin DoF of wheel `w` in its joint.
    fn spin_dof(w: Wheel) -> usize {
        if w.is_front() { 0 } else { 1 }
    }

    /// The joint that carries wheel `w`'s suspension and its DoF.
    fn suspension_joint(&self, w: Wheel) -> (MultibodyJointHandle, usize) {
        match front_index(w) {
            Some(i) => (self.steer_joints[i], 0),
            None => (self.spin_joints[w], 0),
        }
    }

    /// Every body of the car with the part it is, chassis first.
    pub fn bodies(&self) -> impl Iterator<Item = (RigidBodyHandle, crate::error::BodyPart)> + '_ {
        use crate::error::BodyPart;
        [
            (self.chassis, BodyPart::Chassis),
            (self.knuckles[0], BodyPart::Knuckle(Wheel::FrontRight)),
            (self.knuckles[1], BodyPart::Knuckle(Wheel::FrontLeft)),
        ]
        .into_iter()
        .chain(Wheel::ALL.map(|w| (self.wheels[w], BodyPart::Wheel(w))))
    }
}

/// The index of a front wheel in the `[FR, FL]` arrays.
fn front_index(w: Wheel) -> Option<usize> {
    match w {
        Wheel::FrontRight => Some(0),
        Wheel::FrontLeft => Some(1),
        Wheel::RearRight | Wheel::RearLeft => None,
    }
}

/// The knuckle mass (kg) of front wheel `w`.
fn knuckle_mass(spec: &VehicleSpec, w: Wheel) -> f64 {
    KNUCKLE_MASS_FRACTION * spec.wheels[w].mass
}

/// The chassis body's mass properties about its own centre of mass (the model's body less the
/// knuckles, whose small share of the inertia is neglected) and that centre of mass in the
/// car frame (m).
fn chassis_mass_properties(spec: &VehicleSpec) -> (MassProperties, Point3<f64>) {
    let c = &spec.chassis;
    let mut mass = c.mass;
    let mut moment = c.center_of_mass.coords.map(|x| x * c.mass);
    for w in [Wheel::FrontRight, Wheel::FrontLeft] {
        let mk = knuckle_mass(spec, w);
        mass -= mk;
        for (m, p) in moment.iter_mut().zip(spec.wheels[w].position.iter()) {
            *m -= mk * p;
        }
    }
    let com = Point3::from(moment.map(|m| m / mass));
    let inertia = body_inertia(c);
    (
        MassProperties::with_inertia_matrix(Vector::ZERO, mass as f32, inertia),
        com,
    )
}

/// A joint whose frame on the first body sits at `anchor` (m, first body's frame), axes
/// aligned with the car, with the axes of `locked` locked and no contacts between the bodies.
fn joint(locked: JointAxesMask, anchor: Vector) -> GenericJoint {
    GenericJointBuilder::new(locked)
        .local_frame1(Pose::from_translation(anchor))
        .contacts_enabled(false)
        .build()
}

/// Sets the implicit spring (at rest at the unloaded length) and damping of the suspension
/// DoF `dof` of link `link`.
fn set_suspension(mb: &mut Multibody, link: usize, dof: usize, s: SpringDamper) {
    let Some(l) = mb.link_mut(link) else {
        return;
    };
    l.joint.set_spring(LIN_Z, s.stiffness as f32, 0.0);
    let index = l.assembly_id() + dof;
    if let Some(d) = mb.damping_mut().get_mut(index) {
        *d = s.damping as f32;
    }
}

/// The joint description of `handle`, to set its motors.
fn joint_mut(world: &mut PhysicsWorld, handle: MultibodyJointHandle) -> Option<&mut GenericJoint> {
    let (mb, link) = world.multibody_joints.get_mut(handle)?;
    mb.link_mut(link).map(|l| &mut l.joint.data)
}

/// Joint coordinates (rapier spatial layout: m and rad) and the velocity of DoF `dof` (m/s or
/// rad/s) of the joint of `handle`.
fn joint_state(
    world: &PhysicsWorld,
    handle: MultibodyJointHandle,
    dof: usize,
) -> Option<([f32; 6], f32)> {
    let (mb, link) = world.multibody_joints.get(handle)?;
    let l = mb.link(link)?;
    let c = l.joint().coords();
    let v = mb.joint_velocity(l).get(dof).copied()?;
    Some(([c[0], c[1], c[2], c[3], c[4], c[5]], v))
}

/// Creates the bodies and joints of `spec` with the car origin at `origin` (springs unloaded).
/// `None` if rapier refuses a joint (it never does for this tree).
pub(crate) fn build(world: &mut PhysicsWorld, spec: &VehicleSpec, origin: Pose) -> Option<Parts> {
    let multiply = CoefficientCombineRule::Multiply;
    let (mass_properties_chassis, offset) = chassis_mass_properties(spec);
    let offset = geom::point(&offset);
    let chassis = world.insert_body(
        RigidBodyBuilder::dynamic()
            .pose(origin * Pose::from_translation(offset))
            .additional_mass_properties(mass_properties_chassis)
            .can_sleep(false),
    );
    let half = geom::vector(&spec.chassis.box_half_extents);
    world.insert_collider(
        ColliderBuilder::cuboid(half.x, half.y, half.z)
            .translation(geom::point(&spec.chassis.box_center) - offset)
            .density(0.0)
            .friction(1.0)
            .friction_combine_rule(multiply)
            .collision_groups(geom::groups(G_CAR_BODY)),
        Some(chassis),
    );

    let at = |p: &Point3<f64>| origin * Pose::from_translation(geom::point(p));
    let mut knuckles = [chassis; 2];
    let mut steer_joints = [None; 2];
    for w in [Wheel::FrontRight, Wheel::FrontLeft] {
        let s = &spec.wheels[w];
        // The knuckle gets the wheel's transverse inertia: a light, low-inertia body between
        // the chassis and a wheel only slows the solver down.
        let ik = s.transverse_inertia() as f32;
        let knuckle = world.insert_body(
            RigidBodyBuilder::dynamic()
                .pose(at(&s.position))
                .additional_mass_properties(MassProperties::new(
                    Vector::ZERO,
                    knuckle_mass(spec, w) as f32,
                    Vector::splat(ik),
                ))
                .can_sleep(false),
        );
        let mut j = joint(
            JointAxesMask::LIN_X
                | JointAxesMask::LIN_Y
                | JointAxesMask::ANG_X
                | JointAxesMask::ANG_Y,
            geom::point(&s.position) - offset,
        );
        // No joint limits: rapier's multibody emits every limit row every step, active or
        // not; the servo keeps the steering within its range and Webots' suspension has no
        // stops.
        motor::set_rigid_velocity_motor(&mut j, JointAxis::AngZ, 0.0, spec.steering.max_torque);
        let i = usize::from(w == Wheel::FrontLeft);
        steer_joints[i] = Some(world.insert_multibody_joint(chassis, knuckle, j)?);
        knuckles[i] = knuckle;
    }

    let mut wheels = PerWheel::splat(chassis);
    let mut colliders = PerWheel::splat(ColliderHandle::invalid());
    let mut spin_joints = [None; 4];
    for (n, w) in Wheel::ALL.into_iter().enumerate() {
        let s = &spec.wheels[w];
        let wheel = world.insert_body(
            RigidBodyBuilder::dynamic()
                .pose(at(&s.position))
                .can_sleep(false)
                .allow_fast_rotation(true),
        );
        // rapier's cylinder axis is its local y: the spin axis.
        colliders[w] = world.insert_collider(
            ColliderBuilder::cylinder((s.width / 2.0) as f32, s.radius as f32)
                .mass(s.mass as f32)
                .friction(0.0)
                .friction_combine_rule(multiply)
                .collision_groups(geom::groups(G_CAR_WHEEL)),
            Some(wheel),
        );
        let spin_locked = JointAxesMask::LIN_X
            | JointAxesMask::LIN_Y
            | JointAxesMask::ANG_X
            | JointAxesMask::ANG_Z;
        let j = match front_index(w) {
            Some(_) => joint(spin_locked | JointAxesMask::LIN_Z, Vector::ZERO),
            None => joint(spin_locked, geom::point(&s.position) - offset),
        };
        let carrier = front_index(w).map_or(chassis, |i| knuckles[i]);
        spin_joints[n] = Some(world.insert_multibody_joint(carrier, wheel, j)?);
        wheels[w] = wheel;
    }
    let [fr, fl] = steer_joints;
    let [s0, s1, s2, s3] = spin_joints;
    let whole = mass_properties(spec);
    let parts = Parts {
        chassis,
        chassis_offset: offset,
        knuckles,
        wheels,
        colliders,
        steer_joints: [fr?, fl?],
        spin_joints: PerWheel([s0?, s1?, s2?, s3?]),
        com: whole.local_com,
        inv_mass: whole.inv_mass,
        inv_inertia: whole.reconstruct_inverse_inertia_matrix(),
    };

    if let Some((mb, _)) = world.multibody_joints.get_mut(parts.steer_joints[0]) {
        // rapier gives every free angular DoF a default damping of 0.1; Webots has none but
        // `wheelsDampingConstant` on the spins, which the tyre solve applies.
        mb.damping_mut().fill(0.0);
        mb.set_self_contacts_enabled(false);
    }
    for w in Wheel::ALL {
        let (handle, dof) = parts.suspension_joint(w);
        let suspension = if w.is_front() {
            spec.front_suspension
        } else {
            spec.rear_suspension
        };
        if let Some((mb, link)) = world.multibody_joints.get_mut(handle) {
            set_suspension(mb, link, dof, suspension);
        }
    }
    Some(parts)
}

/// The car frame's pose in the world, from the chassis body.
pub(crate) fn car_pose(chassis: &RigidBody, parts: &Parts) -> Pose {
    *chassis.position() * Pose::from_translation(-parts.chassis_offset)
}

/// Sets the steering motors to the position controller's velocities `rates` (rad/s, positive
/// = right, `[FR, FL]`), within `max_torque` (N·m).
fn steer(world: &mut PhysicsWorld, parts: &Parts, rates: [f64; 2], max_torque: f64) {
    for (handle, rate) in parts.steer_joints.into_iter().zip(rates) {
        if let Some(j) = joint_mut(world, handle) {
            // The joint angle is −steering: positive steering turns right, about −z.
            motor::set_rigid_velocity_motor(j, JointAxis::AngZ, -rate, max_torque);
        }
    }
}

/// A wheel's ground contact of the last rapier step.
#[derive(Debug, Clone, Copy)]
struct GroundContact {
    /// The ground's normal (unit, out of the ground).
    pub normal: Vector,
    /// The normal impulse rapier applied over the last step (N·s, ≥ 0).
    pub impulse: f32,
    /// The ground's friction coefficient.
    pub friction: f32,
    /// The ground's body, if it is dynamic (it takes the tyre force's reaction).
    pub body: Option<RigidBodyHandle>,
}

/// Wheel `w`'s ground: of the surfaces its tyre touched in the last step and that are not too
/// steep to stand on (against the chassis' `up`), the one that carried the largest load.
fn ground_contact(
    world: &PhysicsWorld,
    parts: &Parts,
    w: Wheel,
    up: Vector,
) -> Option<GroundContact> {
    let me = parts.colliders[w];
    let mut best: Option<GroundContact> = None;
    for pair in world.contact_pairs_with(me) {
        // rapier's manifold normal points from collider 1 into collider 2.
        let (other, sign) = if pair.collider1 == me {
            (pair.collider2, -1.0)
        } else {
            (pair.collider1, 1.0)
        };
        for m in pair.solver_manifolds() {
            if m.points.is_empty() {
                continue;
            }
            let normal = m.data.normal * sign;
            if normal.dot(up) < MIN_GROUND_COSINE {
                continue;
            }
            let impulse: f32 = m.points.iter().map(|p| p.data.impulse.max(0.0)).sum();
            if best.is_some_and(|b| b.impulse >= impulse) {
                continue;
            }
            let collider = world.colliders.get(other);
            let body = collider.and_then(|c| c.parent()).filter(|&h| {
                world
                    .bodies
                    .get(h)
                    .is_some_and(|b| b.body_type() == RigidBodyType::Dynamic)
            });
            best = Some(GroundContact {
                normal,
                impulse,
                friction: collider.map_or(0.0, |c| c.friction()),
                body,
            });
        }
    }
    best
}

/// The wheel centre (m, world) and its spin axis (unit, world) of wheel `w`.
fn wheel_frame(world: &PhysicsWorld, parts: &Parts, w: Wheel) -> Option<(Vector, Vector)> {
    let b = world.bodies.get(parts.wheels[w])?;
    Some((b.translation(), *b.rotation() * Vector::Y))
}

/// Applies the solved step of wheel `w`: the spin joint's rigid velocity motor at `omega`
/// (rad/s), and the tyre's impulse over the step `tyre.impulse` (N·s, world) at `tyre.point`
/// on the wheel, as a force over the step of `dt` seconds (a multibody link moves only through
/// its joints' coordinates), with its reaction on the ground's body if that is dynamic, as an
/// impulse. The wheel's forces of the last step are cleared first.
fn drive(
    world: &mut PhysicsWorld,
    parts: &Parts,
    w: Wheel,
    omega: f64,
    tyre: Option<TyreImpulse>,
    dt: f32,
) {
    if let Some(j) = joint_mut(world, parts.spin_joints[w]) {
        motor::set_rigid_velocity_motor(j, JointAxis::AngY, omega, WHEEL_MOTOR_MAX_TORQUE);
    }
    if let Some(b) = world.bodies.get_mut(parts.wheels[w]) {
        // rapier keeps user forces and torques (separately) until reset.
        b.reset_forces(true);
        b.reset_torques(true);
        if let Some(t) = tyre {
            b.add_force_at_point(t.impulse / dt, t.point, true);
        }
    }
    if let Some(t) = tyre
        && let Some(ground) = t.ground
        && let Some(b) = world.bodies.get_mut(ground)
    {
        b.apply_impulse_at_point(-t.impulse, t.point, true);
    }
}

/// A tyre's impulse over one step, where it acts, and the ground's body that takes its
/// reaction.
#[derive(Debug, Clone, Copy)]
struct TyreImpulse {
    /// Impulse on the wheel (N·s, world).
    pub impulse: Vector,
    /// Contact point (m, world).
    pub point: Vector,
    /// The ground's dynamic body, if any.
    pub ground: Option<RigidBodyHandle>,
}

/// The joint readings of one step: steering angles `[FR, FL]` (rad, positive = right),
/// suspension compressions (m, > 0 = wheel pushed up) and spin rates (rad/s).
pub(crate) struct Readings {
    pub steering: [f64; 2],
    pub suspension: PerWheel<f64>,
    pub spins: PerWheel<f64>,
}

/// Reads the joints of `parts`; `None` if a joint is missing.
pub(crate) fn read(world: &PhysicsWorld, parts: &Parts) -> Option<Readings> {
    let mut r = Readings {
        steering: [0.0; 2],
        suspension: PerWheel::splat(0.0),
        spins: PerWheel::splat(0.0),
    };
    for (i, handle) in parts.steer_joints.into_iter().enumerate() {
        let (c, _) = joint_state(world, handle, 0)?;
        r.steering[i] = -f64::from(c[ANG_Z]);
    }
    for w in Wheel::ALL {
        let (handle, _) = parts.suspension_joint(w);
        let (c, _) = joint_state(world, handle, 0)?;
        r.suspension[w] = f64::from(c[LIN_Z]);
        let (_, v) = joint_state(world, parts.spin_joints[w], Parts::spin_dof(w))?;
        r.spins[w] = f64::from(v);
    }
    Some(r)
}

impl Vehicle {
    /// The step of `dt` seconds of a car on joints: rapier's steering motors get the position
    /// controller's velocities; the tyres, brakes and spins are solved on the whole car with
    /// the loads of rapier's last contacts, and go to rapier as tyre forces and spin motors.
    pub(super) fn pre_step_joints(&mut self, world: &mut PhysicsWorld, parts: &Parts, dt: f64) {
        let rates = self.steering_rates();
        steer(world, parts, rates, self.spec.steering.max_torque);
        let Some(chassis) = world.bodies.get(parts.chassis) else {
            return;
        };
        let pose = car_pose(chassis, parts);
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
            let radius = self.spec.wheels[w].radius as f32;
            let Some((contact, g)) = wheel_contact(world, parts, w, &frame, radius) else {
                continue;
            };
            // rapier carried the load: the row's normal impulse is given.
            rows[i].impulses.normal = g.impulse;
            roads[i] = g.friction;
            grounds[i] = g.body;
            let footing = Footing {
                road: f64::from(g.friction),
                load: f64::from(g.impulse) / dt,
            };
            self.set_up_contact(w, &mut rows[i], contact, &body, footing, dt);
        }
        for row in &mut rows {
            row.cold_start_rigid_forward();
        }
        contact::solve(&mut body, &mut rows, dt as f32);
        for (i, w) in Wheel::ALL.into_iter().enumerate() {
            let omega = rows[i].solved_spin(imposed[i]);
            let tyre = rows[i].contact.map(|c| TyreImpulse {
                impulse: c.forward * rows[i].impulses.forward
                    + c.lateral * rows[i].impulses.lateral,
                point: frame.com + c.contact_arm,
                ground: grounds[i],
            });
            drive(world, parts, w, omega, tyre, dt as f32);
            self.finish_wheel(w, &rows[i], &body, f64::from(roads[i]), omega, dt);
        }
    }
}

/// Wheel `w`'s contact for the solve (its tyre of `radius`, m, on the ground rapier found under
/// it in the last step, with arms from the centre of mass of `frame`) and that ground; `None`
/// in the air.
fn wheel_contact(
    world: &PhysicsWorld,
    parts: &Parts,
    w: Wheel,
    frame: &Frame,
    radius: f32,
) -> Option<(Contact, GroundContact)> {
    let g = ground_contact(world, parts, w, frame.up)?;
    let (centre, axis) = wheel_frame(world, parts, w)?;
    let contact = Contact::on_ground(Support::Given, g.normal, axis, centre, radius, frame.com)?;
    Some((contact, g))
}
