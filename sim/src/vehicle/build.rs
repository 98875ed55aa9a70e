//! Rigid bodies and multibody joints of a car (see the [`vehicle`](super) module docs).

use ackermann::{PerWheel, Wheel};
use rapier3d::prelude::{
    CoefficientCombineRule, ColliderBuilder, GenericJoint, GenericJointBuilder, JointAxesMask,
    JointAxis, MassProperties, Mat3, Multibody, MultibodyJointHandle, PhysicsWorld, Pose,
    RigidBodyBuilder, RigidBodyHandle, Vector,
};

use super::spec::{KNUCKLE_MASS_FRACTION, SpringDamper, VehicleSpec};
use crate::geom::{self, G_CAR_BODY, G_CAR_WHEEL};
use crate::motor;

/// Index of LinZ in rapier's 6-DoF spatial layout (lin x, y, z, ang x, y, z).
pub(crate) const LIN_Z: usize = 2;
/// Index of AngZ in rapier's 6-DoF spatial layout.
pub(crate) const ANG_Z: usize = 5;

/// The rapier handles of one car. All joints belong to one multibody rooted at the chassis.
#[derive(Debug, Clone)]
pub(crate) struct Parts {
    pub chassis: RigidBodyHandle,
    /// Where the chassis body's frame sits in the car frame: the chassis centre of mass (m).
    pub chassis_offset: [f64; 3],
    /// Steering knuckles of the front wheels, `[FR, FL]`.
    pub knuckles: [RigidBodyHandle; 2],
    pub wheels: PerWheel<RigidBodyHandle>,
    /// chassis → knuckle joints, `[FR, FL]`: free LinZ (suspension, DoF 0) and AngZ (steering,
    /// DoF 1).
    pub steer_joints: [MultibodyJointHandle; 2],
    /// Spin joints: knuckle → wheel at the front (free AngY, DoF 0); chassis → wheel at the rear
    /// (free LinZ = suspension, DoF 0, and AngY, DoF 1).
    pub spin_joints: PerWheel<MultibodyJointHandle>,
}

impl Parts {
    /// The body that carries wheel `w`'s spin joint: its knuckle (front) or the chassis (rear).
    pub fn carrier(&self, w: Wheel) -> RigidBodyHandle {
        match front_index(w) {
            Some(i) => self.knuckles[i],
            None => self.chassis,
        }
    }

    /// All bodies in creation order.
    pub fn bodies(&self) -> impl Iterator<Item = RigidBodyHandle> + '_ {
        [self.chassis, self.knuckles[0], self.knuckles[1]]
            .into_iter()
            .chain(self.wheels.iter().copied())
    }

    /// The local index of the spin DoF of wheel `w` in its joint.
    pub fn spin_dof(w: Wheel) -> usize {
        if w.is_front() { 0 } else { 1 }
    }
}

/// The index of a front wheel in the `[FR, FL]` arrays.
pub(crate) fn front_index(w: Wheel) -> Option<usize> {
    match w {
        Wheel::FrontRight => Some(0),
        Wheel::FrontLeft => Some(1),
        Wheel::RearRight | Wheel::RearLeft => None,
    }
}

/// The knuckle mass (kg) of front wheel `w`.
pub(crate) fn knuckle_mass(spec: &VehicleSpec, w: Wheel) -> f64 {
    KNUCKLE_MASS_FRACTION * spec.wheels[w].mass
}

/// Chassis mass properties with the knuckles' mass removed, so that chassis + knuckles have the
/// model's mass and centre of mass (the small change of inertia is neglected), and the centre
/// of mass of the chassis alone (m, car frame).
///
/// The chassis body's frame is put at that centre of mass: rapier's multibody root is then a
/// free body about its centre of mass, which stays stable for cars whose centre of mass is far
/// from the rear axle (the Truck's is 4.5 m ahead of it).
fn chassis_mass_properties(spec: &VehicleSpec) -> (MassProperties, [f64; 3]) {
    let c = &spec.chassis;
    let mut mass = c.mass;
    let mut moment = c.center_of_mass.map(|x| x * c.mass);
    for w in [Wheel::FrontRight, Wheel::FrontLeft] {
        let mk = knuckle_mass(spec, w);
        mass -= mk;
        for (m, p) in moment.iter_mut().zip(spec.wheels[w].position) {
            *m -= mk * p;
        }
    }
    let com = moment.map(|m| m / mass);
    let [xx, yy, zz, xy, xz, yz] = c.inertia.map(|v| v as f32);
    let inertia = Mat3::from_cols(
        Vector::new(xx, xy, xz),
        Vector::new(xy, yy, yz),
        Vector::new(xz, yz, zz),
    );
    (
        MassProperties::with_inertia_matrix(Vector::ZERO, mass as f32, inertia),
        com,
    )
}

/// `p − o` for car-frame points (m).
fn sub(p: [f64; 3], o: [f64; 3]) -> [f64; 3] {
    [p[0] - o[0], p[1] - o[1], p[2] - o[2]]
}

/// A joint whose frame on the first body sits at `anchor` (m, body frame of body 1), axes
/// aligned with the car, with the axes of `locked` locked and no contacts between the bodies.
fn joint(locked: JointAxesMask, anchor: [f64; 3]) -> GenericJoint {
    GenericJointBuilder::new(locked)
        .local_frame1(Pose::from_translation(geom::vec3(anchor)))
        .contacts_enabled(false)
        .build()
}

/// Sets a joint's implicit spring and the multibody's implicit DoF damping of the suspension.
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

/// Sets the implicit viscous damping (N·m·s/rad) of DoF `dof` of the joint of `handle`.
pub(crate) fn set_dof_damping(
    world: &mut PhysicsWorld,
    handle: MultibodyJointHandle,
    dof: usize,
    d: f64,
) {
    if let Some((mb, link)) = world.multibody_joints.get_mut(handle) {
        let index = mb.link(link).map(|l| l.assembly_id() + dof);
        if let Some(x) = index.and_then(|i| mb.damping_mut().get_mut(i)) {
            *x = d as f32;
        }
    }
}

/// Sets the dry friction (N·m) of DoF `dof` of the joint of `handle`: a brake.
pub(crate) fn set_dof_friction(
    world: &mut PhysicsWorld,
    handle: MultibodyJointHandle,
    dof: usize,
    f: f64,
) {
    if let Some((mb, link)) = world.multibody_joints.get_mut(handle) {
        let index = mb.link(link).map(|l| l.assembly_id() + dof);
        if let Some(x) = index.and_then(|i| mb.frictions_mut().get_mut(i)) {
            *x = f as f32;
        }
    }
}

/// The joint description of `handle`, to set its motors.
pub(crate) fn joint_mut(
    world: &mut PhysicsWorld,
    handle: MultibodyJointHandle,
) -> Option<&mut GenericJoint> {
    let (mb, link) = world.multibody_joints.get_mut(handle)?;
    mb.link_mut(link).map(|l| &mut l.joint.data)
}

/// Joint coordinates (rapier spatial layout: m and rad, unwrapped) and the DoF velocities
/// (m/s or rad/s, in DoF order) of the joint of `handle`.
pub(crate) fn joint_state(
    world: &PhysicsWorld,
    handle: MultibodyJointHandle,
) -> Option<([f32; 6], [f32; 2])> {
    let (mb, link) = world.multibody_joints.get(handle)?;
    let l = mb.link(link)?;
    let c = l.joint().coords();
    let v = mb.joint_velocity(l);
    let mut vel = [0.0; 2];
    for (o, x) in vel.iter_mut().zip(v.iter()) {
        *o = *x;
    }
    Some(([c[0], c[1], c[2], c[3], c[4], c[5]], vel))
}

/// Creates the bodies and joints of `spec` with the car origin at `origin` (springs unloaded).
/// `None` if rapier refuses a joint (it never does for this tree).
pub(crate) fn build(world: &mut PhysicsWorld, spec: &VehicleSpec, origin: Pose) -> Option<Parts> {
    let multiply = CoefficientCombineRule::Multiply;
    let (mass_properties, offset) = chassis_mass_properties(spec);
    let chassis = world.insert_body(
        RigidBodyBuilder::dynamic()
            .pose(origin * Pose::from_translation(geom::vec3(offset)))
            .additional_mass_properties(mass_properties)
            .can_sleep(false),
    );
    let [hx, hy, hz] = spec.chassis.box_half_extents.map(|v| v as f32);
    world.insert_collider(
        ColliderBuilder::cuboid(hx, hy, hz)
            .translation(geom::vec3(sub(spec.chassis.box_center, offset)))
            .density(0.0)
            .friction(1.0)
            .friction_combine_rule(multiply)
            .collision_groups(geom::groups(G_CAR_BODY)),
        Some(chassis),
    );

    let at = |p: [f64; 3]| origin * Pose::from_translation(geom::vec3(p));
    let mut knuckles = [chassis; 2];
    let mut steer_joints = Vec::with_capacity(2);
    for w in [Wheel::FrontRight, Wheel::FrontLeft] {
        let s = &spec.wheels[w];
        let mk = knuckle_mass(spec, w) as f32;
        // The knuckle gets the wheel's transverse inertia: a light, low-inertia body between
        // the chassis and a wheel only slows the solver down.
        let ik = (s.mass * (3.0 * s.radius * s.radius + s.width * s.width) / 12.0) as f32;
        let knuckle = world.insert_body(
            RigidBodyBuilder::dynamic()
                .pose(at(s.position))
                .additional_mass_properties(MassProperties::new(
                    Vector::ZERO,
                    mk,
                    Vector::splat(ik),
                ))
                .can_sleep(false),
        );
        let mut j = joint(
            JointAxesMask::LIN_X
                | JointAxesMask::LIN_Y
                | JointAxesMask::ANG_X
                | JointAxesMask::ANG_Y,
            sub(s.position, offset),
        );
        // No joint limits: rapier's multibody emits every limit row every step, active or not
        // (an LU solve each); the servo already keeps the steering within its range and Webots'
        // suspension has no stops.
        motor::set_rigid_velocity_motor(&mut j, JointAxis::AngZ, 0.0, spec.steering.max_torque);
        steer_joints.push(world.insert_multibody_joint(chassis, knuckle, j)?);
        knuckles[usize::from(w == Wheel::FrontLeft)] = knuckle;
    }

    let mut wheels = PerWheel::splat(chassis);
    let mut spin_joints = Vec::with_capacity(4);
    for w in Wheel::ALL {
        let s = &spec.wheels[w];
        let wheel = world.insert_body(
            RigidBodyBuilder::dynamic()
                .pose(at(s.position))
                .can_sleep(false)
                .allow_fast_rotation(true),
        );
        // rapier's cylinder axis is its local y: the spin axis.
        world.insert_collider(
            ColliderBuilder::cylinder((s.width / 2.0) as f32, s.radius as f32)
                .mass(s.mass as f32)
                .friction(1.0)
                .friction_combine_rule(multiply)
                .collision_groups(geom::groups(G_CAR_WHEEL)),
            Some(wheel),
        );
        let spin_locked = JointAxesMask::LIN_X
            | JointAxesMask::LIN_Y
            | JointAxesMask::ANG_X
            | JointAxesMask::ANG_Z;
        let handle = match front_index(w) {
            Some(i) => world.insert_multibody_joint(
                knuckles[i],
                wheel,
                joint(spin_locked | JointAxesMask::LIN_Z, [0.0; 3]),
            )?,
            None => {
                let j = joint(spin_locked, sub(s.position, offset));
                world.insert_multibody_joint(chassis, wheel, j)?
            }
        };
        wheels[w] = wheel;
        spin_joints.push(handle);
    }
    let steer_joints: [MultibodyJointHandle; 2] = steer_joints.try_into().ok()?;
    let spin_joints: [MultibodyJointHandle; 4] = spin_joints.try_into().ok()?;
    let parts = Parts {
        chassis,
        chassis_offset: offset,
        knuckles,
        wheels,
        steer_joints,
        spin_joints: PerWheel(spin_joints),
    };

    // rapier gives every free angular DoF a default damping of 0.1; Webots has none but
    // `wheelsDampingConstant` on the spin axes.
    if let Some((mb, _)) = world.multibody_joints.get_mut(parts.steer_joints[0]) {
        mb.damping_mut().fill(0.0);
    }
    for handle in parts.steer_joints {
        if let Some((mb, link)) = world.multibody_joints.get_mut(handle) {
            set_suspension(mb, link, 0, spec.front_suspension);
        }
    }
    for w in [Wheel::RearRight, Wheel::RearLeft] {
        if let Some((mb, link)) = world.multibody_joints.get_mut(parts.spin_joints[w]) {
            set_suspension(mb, link, 0, spec.rear_suspension);
        }
    }
    for w in Wheel::ALL {
        set_dof_damping(
            world,
            parts.spin_joints[w],
            Parts::spin_dof(w),
            spec.wheels_damping,
        );
    }
    Some(parts)
}
