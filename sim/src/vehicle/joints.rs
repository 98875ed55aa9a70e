//! The car on rapier joints (`mounting = "joints"`): the Webots `Car` PROTO's bodies and
//! joints as one rapier multibody, with the tyre forces, brakes and wheel spins of the same
//! solve as the cast car.
//!
//! # Bodies and joints
//!
//! * **chassis**: the model's body (mass, centre of mass, inertia tensor) and the collision
//!   box; its rapier frame sits at its centre of mass, the root of the multibody (a free root
//!   far from its centre of mass, like the Truck's rear axle 4.5 m behind it, makes rapier's
//!   reduced-coordinate solve drift);
//! * **front wheels** (Webots `Hinge2Joint`): chassis → wheel on a joint whose free axes are
//!   the suspension (LinZ, the chassis' vertical) and the steering (AngZ);
//! * **rear wheels** (Webots `HingeJoint`): chassis → wheel on the suspension (LinZ);
//! * **wheels**: the wheel's mass and inertia, colliding as a cylinder of `tireRadius` ×
//!   `thickness` whose tread is rounded across its whole width (axis: rapier's local y). A
//!   sharp-edged cylinder stands on its edge as soon as the body rolls and carries roll moment
//!   there (a BmwX5 in a steady turn loaded its inner wheels more than its outer ones); the
//!   rounded tread touches flat ground near its centre plane however the wheel leans, as the
//!   tyre solve assumes, and on the road it keeps one contact point (`tread`). They collide
//!   with the ground, ramps, steps, boxes and other cars (not with their own car: the
//!   multibody's self-contacts are off), and their rapier friction is 0: the tyre forces are
//!   this crate's.
//!
//! All joints form one rapier **multibody** (reduced coordinates): exact joints at a 2-tonne
//! chassis on 30 kg wheels, where impulse joints leave a steering offset and a creep at rest.
//!
//! # The wheels' spin is this crate's
//!
//! The wheel bodies do not spin in rapier: the spin is a coordinate of the tyre solve, as on
//! the cast car (its rate, the wheel angle it integrates to, its inertia in the solve). rapier's
//! multibody treats the velocity-product (Coriolis and gyroscopic) terms semi-implicitly, which
//! is a poor fit for a wheel turning half a radian per 10 ms step: with spinning wheel bodies
//! a BmwX5 understeered 25 % more than the single-track model, more the faster it went and the
//! longer the step. (A momentum balance then put 30 N of lateral force and a 57 N·m yaw moment
//! from nowhere on it in a 1 m/s² turn at 20 m/s, but it read the link bodies' velocities,
//! which are a step old (`multibody`), so those two figures are uncertain.) The wheel's spin
//! inertia enters the solve, and the reaction of its change of spin (`I·Δω`) goes to rapier
//! as a torque on the wheel about its axle, which the joint passes to the chassis. The
//! gyroscopic moment of the spinning wheels is left out, as on the cast car (under 2 % of the
//! roll moment of a turn). So a torque-driven wheel's share of the engaged engine's inertia
//! (`Vehicle::spin_inertia`, `spin_momentum_inertia`) reaches a car on joints by the same
//! solve and reaction as a cast one; the wheel bodies keep the wheel's own mass properties,
//! their spin being locked in rapier.
//!
//! # Who solves what
//!
//! rapier: the joints, the **suspension** (an implicit joint spring `k` at the unloaded length
//! and implicit DoF damping `c`, no stops, as Webots' ODE suspension), the **steering motors**
//! (rigid velocity motors of `maxSteeringTorque` at the Webots position controller's velocity),
//! the **wheel–ground normal contacts** and every collision.
//!
//! This crate: the **tyre forces**, brakes and wheel spins, by the cast car's step and solve
//! (`step`, `contact`): each wheel's ground contact of the last rapier step gives the contact
//! normal, the load (its normal impulse) and the collider whose friction the world's ground
//! gives (a dynamic box's own, the ground's for another car); the solve runs on the whole car as
//! one rigid body (the joints hold the wheels to the chassis in the ground plane) with the
//! loads given, and its results go to rapier as the tyre force at each contact point on the
//! wheel (its reaction on the ground, if the ground is a dynamic body) and the spin reaction.

use ackermann::{PerWheel, Wheel};
use rapier3d::prelude::{
    CoefficientCombineRule, ColliderBuilder, ColliderHandle, GenericJoint, GenericJointBuilder,
    JointAxesMask, JointAxis, MassProperties, Multibody, MultibodyJointHandle, PhysicsWorld, Pose,
    RigidBody, RigidBodyBuilder, RigidBodyHandle, Vector,
};

use super::contact::{Body, Contact, Support};
use super::inertia::{Inertia, body_inertia, mass_properties};
use super::multibody::{self, Parts, WheelImpulse};
use super::spec::{SpringDamper, VehicleSpec, WheelSpec};
use super::step::{Found, Mount, Solved, Touch};
use super::tread::WHEEL_HOOKS;
use super::{Frame, Vehicle};
use crate::geom::{self, G_CAR_BODY, G_CAR_WHEEL};
use crate::motor;

/// Half height (m) of the flat core of a wheel's rounded tread: rapier's round cylinder needs
/// one; the rest of the half width is the rounded border.
///
/// As thin as can be (10 µm): rapier puts the ground's normal force at one end of the core,
/// while the tyre's force acts on its mid-plane ([`Tread::contact_point`]), so the core's half
/// width is a lever on which a wheel carries roll moment in its tread, not its spring, and
/// on which its braking force turns the car. With a 1 mm core, the C-Zero (centre of mass
/// 2 mm off the centre line) took half its static roll moment in the treads and, braking on
/// four locked wheels, yawed under 4 N·m instead of the 1 N·m its tyres' load sensitivity
/// gives (0.0125 rad over the stop; the cast car and now this: 0.003).
const ROUND_TREAD_CORE: f64 = 1e-5;

/// A wheel's tread as its rapier collider has it.
#[derive(Debug, Clone, Copy)]
struct Tread {
    /// Outer radius (m).
    radius: f32,
    /// Radius of the rounded border across the tread (m): the half width less the core's.
    border: f32,
}

impl Tread {
    fn of(s: &WheelSpec) -> Tread {
        Tread {
            radius: s.radius as f32,
            border: (s.width / 2.0 - ROUND_TREAD_CORE) as f32,
        }
    }

    /// Where the tread of a wheel centred at `centre` (m, world) on the spin `axis` touches
    /// ground of unit `normal`: one border radius along `−normal` from the border's centre
    /// line nearest the ground (on the tread's mid-plane, across the 20 µm core, for both
    /// wheels of an axle alike). As the wheel leans, this moves across the tread by
    /// `(radius − border)·sin(lean)`, and there the ground's normal force acts in rapier: the
    /// tyre force goes there too, so that the solve's roll and pitch moments are rapier's
    /// (under the wheel centre, a BmwX5 turning at 8.6 m/s² had about 100 N·m of roll the
    /// solve did not see). Right under the centre if the wheel lies flat.
    fn contact_point(&self, centre: Vector, axis: Vector, normal: Vector) -> Vector {
        let down = (normal.dot(axis) * axis - normal).normalize_or_zero();
        if down == Vector::ZERO {
            return centre - normal * self.radius;
        }
        centre + down * (self.radius - self.border) - normal * self.border
    }
}

/// Smallest cosine between a contact's normal and the chassis' up axis for the contact to be
/// a wheel's ground, the surface its tyre grips on (45°): the road or a ramp, or the edge of a
/// step up to `1 − cos 45°` = 29 % of the tyre's radius high (a BmwX5 climbs a 10 cm step on
/// its tyres' grip). A higher edge (a box's, a kerb's) meets the tyre's shoulder: it pushes
/// the wheel and takes no tyre force, and the ground under the wheel keeps the load and grip.
const TREAD_GROUND_COSINE: f32 = core::f32::consts::FRAC_1_SQRT_2;

/// Index of LinZ in rapier's 6-DoF spatial layout (lin x, y, z, ang x, y, z).
const LIN_Z: usize = 2;
/// Index of AngZ in rapier's 6-DoF spatial layout.
const ANG_Z: usize = 5;

impl Parts {
    /// The steering joints, `[FR, FL]`.
    fn steer_joints(&self) -> [MultibodyJointHandle; 2] {
        [
            self.joints[Wheel::FrontRight],
            self.joints[Wheel::FrontLeft],
        ]
    }

    /// Every body of the car with the part it is, chassis first.
    pub fn bodies(&self) -> impl Iterator<Item = (RigidBodyHandle, crate::error::BodyPart)> + '_ {
        use crate::error::BodyPart;
        [(self.chassis, BodyPart::Chassis)]
            .into_iter()
            .chain(Wheel::ALL.map(|w| (self.wheels[w], BodyPart::Wheel(w))))
    }
}

/// The chassis body's mass properties about its own centre of mass.
fn chassis_mass_properties(spec: &VehicleSpec) -> MassProperties {
    let body = body_inertia(&spec.chassis);
    Inertia {
        com: Default::default(),
        ..body
    }
    .mass_properties()
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

/// Joint coordinates (rapier spatial layout: m and rad) of the joint of `handle`.
fn joint_coords(world: &PhysicsWorld, handle: MultibodyJointHandle) -> Option<[f32; 6]> {
    let (mb, link) = world.multibody_joints.get(handle)?;
    let c = mb.link(link)?.joint().coords();
    Some([c[0], c[1], c[2], c[3], c[4], c[5]])
}

/// Creates the bodies and joints of `spec` with the car origin at `origin` (springs unloaded).
/// `None` if rapier refuses a joint (it never does for this tree).
pub(crate) fn build(world: &mut PhysicsWorld, spec: &VehicleSpec, origin: Pose) -> Option<Parts> {
    let multiply = CoefficientCombineRule::Multiply;
    let offset = geom::point(&spec.chassis.center_of_mass);
    let chassis = world.insert_body(
        RigidBodyBuilder::dynamic()
            .pose(origin * Pose::from_translation(offset))
            .additional_mass_properties(chassis_mass_properties(spec))
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

    let mut wheels = PerWheel::splat(chassis);
    let mut colliders = PerWheel::splat(ColliderHandle::invalid());
    let mut joints = [None; 4];
    for (n, w) in Wheel::ALL.into_iter().enumerate() {
        let s = &spec.wheels[w];
        let wheel = world.insert_body(
            RigidBodyBuilder::dynamic()
                .pose(origin * Pose::from_translation(geom::point(&s.position)))
                .can_sleep(false),
        );
        // rapier's (round) cylinder axis is its local y, the axle. The mass properties are the
        // solid cylinder's (`WheelSpec`), not the rounded shape's. The core's radius
        // `radius − border` is ≥ 0 (parry asserts it): `VehicleSpec::check_mounting` refuses a
        // joints wheel whose `tireRadius` is under half its width, and f32 rounding keeps the
        // order of the two.
        let tread = Tread::of(s);
        let transverse = s.transverse_inertia() as f32;
        colliders[w] = world.insert_collider(
            ColliderBuilder::round_cylinder(
                ROUND_TREAD_CORE as f32,
                tread.radius - tread.border,
                tread.border,
            )
            .mass_properties(MassProperties::new(
                Vector::ZERO,
                s.mass as f32,
                Vector::new(transverse, s.spin_inertia() as f32, transverse),
            ))
            .friction(0.0)
            .friction_combine_rule(multiply)
            .collision_groups(geom::groups(G_CAR_WHEEL))
            .active_hooks(WHEEL_HOOKS),
            Some(wheel),
        );
        // Every wheel slides on its suspension (LinZ); a front wheel also steers (AngZ). The
        // spin (AngY) is locked: it is the solve's coordinate.
        let steering = if w.is_front() {
            JointAxesMask::empty()
        } else {
            JointAxesMask::ANG_Z
        };
        let locked = JointAxesMask::LIN_X
            | JointAxesMask::LIN_Y
            | JointAxesMask::ANG_X
            | JointAxesMask::ANG_Y
            | steering;
        let mut j = joint(locked, geom::point(&s.position) - offset);
        if w.is_front() {
            // No joint limits: rapier's multibody emits every limit row every step, active or
            // not; the servo keeps the steering within its range.
            motor::set_rigid_velocity_motor(&mut j, JointAxis::AngZ, 0.0, spec.steering.max_torque);
        }
        joints[n] = Some(world.insert_multibody_joint(chassis, wheel, j)?);
        wheels[w] = wheel;
    }
    let [j0, j1, j2, j3] = joints;
    let whole = mass_properties(spec);
    let parts = Parts {
        chassis,
        chassis_offset: offset,
        wheels,
        colliders,
        joints: PerWheel([j0?, j1?, j2?, j3?]),
        com: whole.local_com,
        inv_mass: whole.inv_mass,
        inv_inertia: whole.reconstruct_inverse_inertia_matrix(),
    };

    if let Some((mb, _)) = world
        .multibody_joints
        .get_mut(parts.joints[Wheel::FrontRight])
    {
        // rapier gives every free angular DoF a default damping of 0.1; Webots has none.
        mb.damping_mut().fill(0.0);
        mb.set_self_contacts_enabled(false);
    }
    for w in Wheel::ALL {
        let suspension = if w.is_front() {
            spec.front_suspension
        } else {
            spec.rear_suspension
        };
        if let Some((mb, link)) = world.multibody_joints.get_mut(parts.joints[w]) {
            set_suspension(mb, link, 0, suspension);
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
    for (handle, rate) in parts.steer_joints().into_iter().zip(rates) {
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
    normal: Vector,
    /// The normal impulse rapier applied over the last step (N·s, ≥ 0).
    impulse: f32,
    /// The ground's collider: its friction is the world's `Ground`'s for it.
    collider: ColliderHandle,
    /// The ground's body, if it is dynamic (it takes the tyre force's reaction).
    body: Option<RigidBodyHandle>,
}

/// Wheel `w`'s ground: of the surfaces its tyre touched in the last step within 45° of the
/// chassis' `up` ([`TREAD_GROUND_COSINE`]), the one that carried the largest load.
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
            if m.data.solver_contacts.is_empty() {
                continue;
            }
            let normal = m.data.normal * sign;
            if normal.dot(up) < TREAD_GROUND_COSINE {
                continue;
            }
            // The points the solver used: a wheel's ground contact keeps one (`tread`), and a
            // point it dropped keeps the impulse of a step it was used in.
            let impulse: f32 = m
                .data
                .solver_contacts
                .iter()
                .filter_map(|c| m.points.get(c.contact_indices()[0] as usize))
                .map(|p| p.data.impulse.max(0.0))
                .sum();
            if best.is_some_and(|b| b.impulse >= impulse) {
                continue;
            }
            let body = world
                .colliders
                .get(other)
                .and_then(|c| c.parent())
                .filter(|&h| world.bodies.get(h).is_some_and(|b| b.is_dynamic()));
            best = Some(GroundContact {
                normal,
                impulse,
                collider: other,
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

/// The joint readings of one step: steering angles `[FR, FL]` (rad, positive = right) and
/// suspension compressions (m, > 0 = wheel pushed up).
pub(crate) struct Readings {
    pub steering: [f64; 2],
    pub suspension: PerWheel<f64>,
}

/// Reads the joints of `parts`; `None` if a joint is missing.
pub(crate) fn read(world: &PhysicsWorld, parts: &Parts) -> Option<Readings> {
    let mut r = Readings {
        steering: [0.0; 2],
        suspension: PerWheel::splat(0.0),
    };
    for w in Wheel::ALL {
        let c = joint_coords(world, parts.joints[w])?;
        r.suspension[w] = f64::from(c[LIN_Z]);
        match w {
            Wheel::FrontRight => r.steering[0] = -f64::from(c[ANG_Z]),
            Wheel::FrontLeft => r.steering[1] = -f64::from(c[ANG_Z]),
            Wheel::RearRight | Wheel::RearLeft => {}
        }
    }
    Some(r)
}

/// The step of a car on joints: rapier's steering motors get the position controller's
/// velocities; the tyres, brakes and spins are solved on the whole car with the loads of
/// rapier's last contacts, and go to rapier as tyre forces and the spins' reactions.
impl Mount for Parts {
    const CARRIES_LOAD: bool = false;
    const WARM_RIGID_FORWARD: bool = false;

    fn steer(&self, car: &mut Vehicle, world: &mut PhysicsWorld, _dt: f64) {
        let rates = car.steering_rates();
        steer(world, self, rates, car.spec.steering.max_torque);
    }

    fn chassis(&self, world: &PhysicsWorld, dt: f64) -> Option<(Frame, Body)> {
        let chassis = world.bodies.get(self.chassis)?;
        let pose = car_pose(chassis, self);
        let frame = Frame {
            pose,
            com: pose.transform_point(self.com),
            up: pose.rotation * Vector::Z,
        };
        let motion = multibody::chassis_motion(world, self)?;
        let body = Body::new(
            motion.velocity_at(frame.com) + world.gravity * dt as f32,
            motion.angvel,
            self.inv_mass,
            self.inv_inertia,
            pose.rotation,
        );
        Some((frame, body))
    }

    fn find(&self, car: &Vehicle, world: &PhysicsWorld, w: Wheel, frame: &Frame) -> Option<Found> {
        let (centre, axis) = wheel_frame(world, self, w)?;
        let tread = Tread::of(&car.spec.wheels[w]);
        let touch = wheel_contact(world, self, w, frame, centre, axis, tread);
        Some(Found { axis, touch })
    }

    fn hand_back(&self, car: &mut Vehicle, world: &mut PhysicsWorld, solved: &Solved, dt: f64) {
        let mut handed = PerWheel::splat(WheelImpulse::default());
        for (i, w) in Wheel::ALL.into_iter().enumerate() {
            let row = &solved.rows[i];
            handed[w] = WheelImpulse {
                tyre: row.contact.map(|c| {
                    (
                        c.forward * row.impulses.forward + c.lateral * row.impulses.lateral,
                        solved.frame.com + c.contact_arm,
                    )
                }),
                spin: solved.axes[i] * -solved.spin_changes[i] as f32,
                ground: solved.ground_bodies[i],
            };
        }
        if !car.joint_space_mass_ready {
            car.joint_space_mass_ready = multibody::joint_space_mass_ready(world, self);
        }
        multibody::hand_over(world, self, &handed, dt as f32, car.joint_space_mass_ready);
    }
}

/// Wheel `w`'s contact for the solve (its `tread` centred at `centre` on the spin `axis`, on
/// the ground rapier found under it in the last step, with arms from the centre of mass of
/// `frame`); `None` in the air.
fn wheel_contact(
    world: &PhysicsWorld,
    parts: &Parts,
    w: Wheel,
    frame: &Frame,
    centre: Vector,
    axis: Vector,
    tread: Tread,
) -> Option<Touch> {
    let g = ground_contact(world, parts, w, frame.up)?;
    let point = tread.contact_point(centre, axis, g.normal);
    let contact = Contact::at_point(
        Support::Given,
        g.normal,
        axis,
        point,
        tread.radius,
        frame.com,
    )?;
    Some(Touch {
        contact,
        collider: g.collider,
        given_impulse: Some(g.impulse),
        ground_body: g.body,
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    const TREAD: Tread = Tread {
        radius: 0.374,
        border: 0.124,
    };

    #[test]
    fn an_upright_tread_touches_right_under_its_centre() {
        let centre = Vector::new(1.0, 2.0, 0.5);
        let p = TREAD.contact_point(centre, Vector::Y, Vector::Z);
        assert!(
            (p - Vector::new(1.0, 2.0, 0.5 - 0.374)).length() < 1e-6,
            "{p:?}"
        );
    }

    #[test]
    fn a_leaning_tread_touches_under_its_border_circle_and_mirrors() {
        // Leaning by φ = 0.05 rad about x: the border's centre line nearest the ground is
        // (r − b)·(0, sin φ, −cos φ) from the centre, the contact b below it: y = 0.25·sin φ =
        // 0.012495 m, z = −0.25·cos φ − 0.124 = −0.373688 m.
        let phi: f32 = 0.05;
        let lean = Vector::new(0.0, phi.cos(), phi.sin());
        let p = TREAD.contact_point(Vector::ZERO, lean, Vector::Z);
        assert!(
            (p - Vector::new(0.0, 0.012_495, -0.373_688)).length() < 1e-6,
            "{p:?}"
        );
        // The mirrored wheel (the other side of the axle, its axis mirrored in y and pointing
        // the same way) touches at the mirrored point.
        let mirrored = Vector::new(0.0, phi.cos(), -phi.sin());
        let q = TREAD.contact_point(Vector::ZERO, mirrored, Vector::Z);
        assert_eq!(q, Vector::new(p.x, -p.y, p.z));
        // A wheel lying flat has no lowest circle: right under its centre.
        let flat = TREAD.contact_point(Vector::ZERO, Vector::Z, Vector::Z);
        assert_eq!(flat, Vector::new(0.0, 0.0, -0.374));
    }
}
