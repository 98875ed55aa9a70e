//! The joints car's rapier multibody: its handles, its motion as rapier holds it, and how the
//! tyre solve's impulses reach it.
//!
//! # Reading the motion
//!
//! A multibody's state is its generalized velocity. rapier copies it onto the link bodies'
//! own velocities (`RigidBody::linvel`, `angvel`) when a step starts and between substeps, not
//! after the last one: after `step()` those read the velocities the step started from, one
//! step behind. The chassis' motion is therefore read from the multibody's root DoFs (its
//! free joint: the world velocity of its centre of mass, then its angular velocity). Read from
//! the chassis body, the tyre solve started each step from the chassis motion of the step
//! before: on Webots' rigid contact that made the car shake sideways at ±9.9 m/s² at
//! 60 km/h, and the telemetry lagged a step.
//!
//! # Handing over the impulses
//!
//! rapier integrates a multibody in one substep per step, with its velocity-product
//! (Coriolis and gyroscopic) terms semi-implicit. An impulse handed over as a force over the
//! step meets those terms at the velocity the step starts from; handed over as a change of the
//! generalized velocity before the step (through rapier's own joint-space mass, the implicit
//! springs and dampers included), at the velocity after it. Either is first-order in the
//! step, in opposite directions: a BmwX5 at the grip limit (the suite's steering ramp at
//! 20 m/s) peaks at v·r = 9.52/9.71/10.25 m/s² over 0.5 s at 5/10/20 ms steps with forces and
//! 9.36/9.29/9.13 m/s² with velocity changes, against 9.43/9.40/9.43 m/s² with four rapier
//! substeps (each substep adds about 240,000 instructions to the 350,000 of a step). Half of
//! each impulse goes each way: the first-order terms cancel, and the car peaks at
//! 9.40/9.40/9.51 m/s² at one substep.

use ackermann::{PerWheel, Wheel};
use rapier3d::na;
use rapier3d::prelude::{
    ColliderHandle, Mat3, MultibodyJointHandle, PhysicsWorld, RigidBodyHandle, Vector,
};

use super::Motion;

/// The rapier handles of one car on joints and the whole car's mass properties.
#[derive(Debug, Clone)]
pub(crate) struct Parts {
    pub chassis: RigidBodyHandle,
    /// The chassis body's frame in the car frame: its own centre of mass (m).
    pub chassis_offset: Vector,
    pub wheels: PerWheel<RigidBodyHandle>,
    pub colliders: PerWheel<ColliderHandle>,
    /// chassis → wheel joints: the suspension (LinZ, DoF 0) and, at the front, the steering
    /// (AngZ, DoF 1).
    pub joints: PerWheel<MultibodyJointHandle>,
    /// The whole car's centre of mass in the car frame (m).
    pub com: Vector,
    /// 1/total mass (1/kg).
    pub inv_mass: f32,
    /// Inverse inertia tensor of the whole car about its centre of mass, car frame
    /// (1/(kg·m²)).
    pub inv_inertia: Mat3,
}

/// Share of each impulse handed to rapier as a change of the generalized velocity before the
/// step; the rest acts as a force over the step (see the module documentation).
const VELOCITY_SHARE: f32 = 0.5;

/// Most DoFs of a car's multibody [`hand_over`] solves for on the stack (a joints car has 12).
const MAX_DOFS: usize = 16;

/// The chassis' motion from the multibody's root DoFs (its free joint: the world velocity of
/// the chassis' centre of mass, then its angular velocity); `None` if the chassis or the
/// multibody is missing.
pub(super) fn chassis_motion(world: &PhysicsWorld, parts: &Parts) -> Option<Motion> {
    let centre = world.bodies.get(parts.chassis)?.center_of_mass();
    let (mb, _) = world
        .multibody_joints
        .get(parts.joints[Wheel::FrontRight])?;
    let v = mb.generalized_velocity();
    (v.len() >= 6).then(|| Motion {
        linvel: Vector::new(v[0], v[1], v[2]),
        angvel: Vector::new(v[3], v[4], v[5]),
        centre,
    })
}

/// What one wheel hands to rapier after the solve.
#[derive(Debug, Clone, Copy, Default)]
pub(crate) struct WheelImpulse {
    /// The tyre's impulse on the wheel over the step (N·s, world) and where it acts (m,
    /// world); `None` in the air.
    pub tyre: Option<(Vector, Vector)>,
    /// The angular impulse that spun the wheel up or down, reacted on the wheel (N·m·s, world).
    pub spin: Vector,
    /// The ground's dynamic body, if any: it takes the tyre impulse's reaction.
    pub ground: Option<RigidBodyHandle>,
}

/// Hands the solved impulses of a step of `dt` seconds to rapier: [`VELOCITY_SHARE`] of them
/// as a change of the multibody's generalized velocity, the rest as forces and torques on the
/// wheels over the step, and each tyre impulse's reaction to a dynamic ground as an impulse.
/// `ready` says whether the multibody's joint-space mass has the size of its DoFs (rapier
/// builds it at the first step); before that, everything is a force.
pub(crate) fn hand_over(
    world: &mut PhysicsWorld,
    parts: &Parts,
    impulses: &PerWheel<WheelImpulse>,
    dt: f32,
    ready: bool,
) {
    let share = if ready && velocity_change(world, parts, impulses) {
        VELOCITY_SHARE
    } else {
        0.0
    };
    let rest = (1.0 - share) / dt;
    for w in Wheel::ALL {
        let i = impulses[w];
        if let Some(b) = world.bodies.get_mut(parts.wheels[w]) {
            // rapier keeps user forces and torques (separately) until reset.
            b.reset_forces(true);
            b.reset_torques(true);
            if let Some((impulse, point)) = i.tyre {
                b.add_force_at_point(impulse * rest, point, true);
            }
            b.add_torque(i.spin * rest, true);
        }
        if let (Some((impulse, point)), Some(ground)) = (i.tyre, i.ground)
            && let Some(b) = world.bodies.get_mut(ground)
        {
            b.apply_impulse_at_point(-impulse, point, true);
        }
    }
}

/// True if the multibody's joint-space mass matches its DoFs (it is built at rapier's first
/// step): [`hand_over`] may then solve with it. Allocates, so the caller asks once.
pub(crate) fn joint_space_mass_ready(world: &PhysicsWorld, parts: &Parts) -> bool {
    let Some((mb, _)) = world.multibody_joints.get(parts.joints[Wheel::FrontRight]) else {
        return false;
    };
    let n = mb.ndofs();
    let l = mb.inv_augmented_mass().l();
    l.nrows() == n && l.ncols() == n
}

/// Adds [`VELOCITY_SHARE`] of the impulses to the multibody's generalized velocity: the
/// generalized impulse `Σ Jᵀ·(p, (x − c) × p + L)` of the wheel links (each link's Jacobian `J`
/// at its centre of mass `c`), through the joint-space mass. False, with nothing changed, if a
/// Jacobian does not have the multibody's size or the solve fails.
fn velocity_change(
    world: &mut PhysicsWorld,
    parts: &Parts,
    impulses: &PerWheel<WheelImpulse>,
) -> bool {
    let joints = &world.multibody_joints;
    let Some((mb, _)) = joints.get(parts.joints[Wheel::FrontRight]) else {
        return false;
    };
    // On the stack: a joints car has 12 DoFs (the chassis' 6, four suspensions, two steerings).
    let mut buffer = [0.0_f32; MAX_DOFS];
    let n = mb.ndofs();
    if n > MAX_DOFS {
        return false;
    }
    let mut g = na::DVectorViewMut::from_slice(&mut buffer[..n], n);
    for w in Wheel::ALL {
        let (Some((_, link)), Some(wheel)) = (
            joints.get(parts.joints[w]),
            world.bodies.get(parts.wheels[w]),
        ) else {
            return false;
        };
        let i = impulses[w];
        let (p, l) = match i.tyre {
            Some((impulse, point)) => (
                impulse,
                i.spin + (point - wheel.center_of_mass()).cross(impulse),
            ),
            None => (Vector::ZERO, i.spin),
        };
        let j = mb.body_jacobian(link);
        if j.ncols() != g.len() {
            return false;
        }
        let wrench = na::Vector6::new(p.x, p.y, p.z, l.x, l.y, l.z);
        g.gemv_tr(VELOCITY_SHARE, j, &wrench, 1.0);
    }
    let Some((mb, _)) = world
        .multibody_joints
        .get_mut(parts.joints[Wheel::FrontRight])
    else {
        return false;
    };
    if !mb.inv_augmented_mass().solve_mut(&mut g) || g.iter().any(|x| !x.is_finite()) {
        return false;
    }
    let mut v = mb.generalized_velocity_mut();
    v += &g;
    true
}
