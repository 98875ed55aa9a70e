//! Physics mode of the DifferentialWheels robot: a body on two motorised hinge wheels.

use core::f32::consts::FRAC_PI_2;

use proto_geom::nalgebra::Point3;
use rapier3d::prelude::{
    CoefficientCombineRule, ColliderBuilder, GenericJointBuilder, ImpulseJointHandle,
    JointAxesMask, JointAxis, MassProperties, PhysicsWorld, Pose, RigidBodyBuilder,
    RigidBodyHandle, Rotation, Vector,
};

use super::RobotPose;
use super::params::{DifferentialWheelsParams, RobotBody, RobotPlacement};
use crate::error::BodyPart;
use crate::geom::{self, G_ROBOT_BODY, G_ROBOT_WHEEL};
use crate::motor;

/// The rapier handles of a physics-mode robot and the last wheel-angle readings.
#[derive(Debug, Clone)]
pub(crate) struct PhysicsParts {
    body: RigidBodyHandle,
    /// `[left, right]`.
    wheels: [RigidBodyHandle; 2],
    /// `[left, right]`.
    joints: [ImpulseJointHandle; 2],
    /// Last relative wheel angles, wrapped into (−π, π] (rad).
    wrapped: [f64; 2],
    /// Last body yaw, wrapped into (−π, π] (rad).
    wrapped_yaw: f64,
}

/// What the physics step did to the robot.
impl PhysicsParts {
    /// The robot's rapier bodies: its body, then its wheels `[left, right]`.
    pub(crate) fn bodies(&self) -> [RigidBodyHandle; 3] {
        [self.body, self.wheels[0], self.wheels[1]]
    }

    /// Which part of the robot the rapier body `handle` is, if any.
    pub(crate) fn part_of(&self, handle: RigidBodyHandle) -> Option<BodyPart> {
        [
            (self.body, BodyPart::RobotBody),
            (self.wheels[0], BodyPart::LeftWheel),
            (self.wheels[1], BodyPart::RightWheel),
        ]
        .into_iter()
        .find(|(h, _)| *h == handle)
        .map(|(_, part)| part)
    }
}

/// What a physics-mode step measured.
pub(crate) struct Measurement {
    /// Wheel rotation during the step (rad), `[left, right]`.
    pub deltas: [f64; 2],
    /// Wheel speeds relative to the body (rad/s), `[left, right]`.
    pub speeds: [f64; 2],
    /// The robot pose after the step.
    pub pose: RobotPose,
}

/// Spin axis of both wheels in the body frame: the axle, +y (left).
const AXLE: Vector = Vector::Y;

/// Builds the body, casters, wheels and hinges (see [`RobotBody`]) with the robot origin at
/// `placement`.
pub(crate) fn build(
    world: &mut PhysicsWorld,
    p: &DifferentialWheelsParams,
    b: &RobotBody,
    placement: &RobotPlacement,
) -> PhysicsParts {
    let r = p.wheel_radius as f32;
    let half_axle = (p.axle_length / 2.0) as f32;
    let start = Point3::new(placement.x, placement.y, placement.z);
    let origin = geom::pose_xyz_yaw(&start, placement.heading);
    let multiply = CoefficientCombineRule::Multiply;

    let body = world.insert_body(RigidBodyBuilder::dynamic().pose(origin).can_sleep(false));
    // The body cylinder's axis is rapier's local y: turn it upright.
    let shell = ColliderBuilder::cylinder(r / 2.0, half_axle)
        .position(Pose::from_parts(
            Vector::new(0.0, 0.0, r),
            Rotation::from_rotation_x(FRAC_PI_2),
        ))
        .mass(b.body_mass as f32)
        .friction(1.0)
        .friction_combine_rule(multiply)
        .collision_groups(geom::groups(G_ROBOT_BODY));
    world.insert_collider(shell, Some(body));
    for x in [0.8 * half_axle, -0.8 * half_axle] {
        let caster = ColliderBuilder::ball(r / 4.0)
            .translation(Vector::new(x, 0.0, r / 4.0))
            .density(0.0)
            .friction(0.0)
            .friction_combine_rule(multiply)
            .collision_groups(geom::groups(G_ROBOT_BODY));
        world.insert_collider(caster, Some(body));
    }

    let mut wheels = [body; 2];
    let mut joints = [ImpulseJointHandle::invalid(); 2];
    for (i, side) in [1.0_f32, -1.0].into_iter().enumerate() {
        let anchor = Vector::new(0.0, side * half_axle, r);
        let wheel = world.insert_body(
            RigidBodyBuilder::dynamic()
                .pose(origin * Pose::from_translation(anchor))
                .can_sleep(false)
                .allow_fast_rotation(true),
        );
        // The tyre touches the ground at one point under the axle: a ball of the wheel radius,
        // with the mass properties of the cylindrical wheel. A cylinder lying on the ground
        // touches it along its width, which rapier reduces to two points at the rims; turning
        // on the spot then scrubs them sideways, and rapier's default (simplified) friction
        // adds a twist friction that resists any rotation of the wheel about the vertical. On
        // the e-puck (1 cm wide wheels 5.2 cm apart) that resistance cost each quarter turn of
        // the square 0.09 to 0.25 rad. The kinematic model, and Webots' own formula, assume a
        // contact under the wheel's mid-plane.
        let half_width = (b.wheel_width / 2.0) as f32;
        let volume = core::f32::consts::PI * r * r * 2.0 * half_width;
        let tyre = ColliderBuilder::ball(r)
            .mass_properties(MassProperties::from_cylinder(
                b.wheel_mass as f32 / volume,
                half_width,
                r,
            ))
            .friction(1.0)
            .friction_combine_rule(multiply)
            .collision_groups(geom::groups(G_ROBOT_WHEEL));
        world.insert_collider(tyre, Some(wheel));
        let hinge = GenericJointBuilder::new(
            JointAxesMask::LIN_AXES | JointAxesMask::ANG_X | JointAxesMask::ANG_Z,
        )
        .local_frame1(Pose::from_translation(anchor))
        .contacts_enabled(false)
        .build();
        joints[i] = world.insert_impulse_joint(body, wheel, hinge);
        wheels[i] = wheel;
    }
    PhysicsParts {
        body,
        wheels,
        joints,
        wrapped: [0.0; 2],
        wrapped_yaw: geom::wrap(placement.heading),
    }
}

/// Commands both hinge motors: velocity `targets` (rad/s, `[left, right]`) with at most
/// `max_force` (N·m) each, like an ODE hinge motor with `dParamVel`/`dParamFMax`.
pub(crate) fn command(
    world: &mut PhysicsWorld,
    parts: &PhysicsParts,
    targets: [f64; 2],
    max_force: f64,
) {
    for (j, t) in parts.joints.iter().zip(targets) {
        if let Some(joint) = world.impulse_joints.get_mut(*j, true) {
            motor::set_rigid_velocity_motor(&mut joint.data, JointAxis::AngY, t, max_force);
        }
    }
}

/// Reads the wheel rotations and the pose after a physics step of `dt` seconds; `heading` is
/// the continuous heading before the step (rad). Fails with the first non-finite body.
pub(crate) fn measure(
    world: &PhysicsWorld,
    parts: &mut PhysicsParts,
    heading: f64,
    dt: f64,
) -> Result<Measurement, BodyPart> {
    let body = geom::finite_body(world, parts.body).ok_or(BodyPart::RobotBody)?;
    let q_body = *body.rotation();
    let axle = q_body * AXLE;
    let mut deltas = [0.0; 2];
    let mut speeds = [0.0; 2];
    for i in 0..2 {
        let part = if i == 0 {
            BodyPart::LeftWheel
        } else {
            BodyPart::RightWheel
        };
        let wheel = geom::finite_body(world, parts.wheels[i]).ok_or(part)?;
        let omega = f64::from((wheel.angvel() - body.angvel()).dot(axle));
        let wrapped = geom::angle_about_y(q_body.inverse() * *wheel.rotation());
        deltas[i] = geom::unwrap_delta(parts.wrapped[i], wrapped, omega * dt);
        speeds[i] = omega;
        parts.wrapped[i] = wrapped;
    }
    let yaw = geom::roll_pitch_yaw(q_body).yaw;
    let yaw_rate = f64::from(body.angvel().z);
    let heading = heading + geom::unwrap_delta(parts.wrapped_yaw, yaw, yaw_rate * dt);
    parts.wrapped_yaw = yaw;
    Ok(Measurement {
        deltas,
        speeds,
        pose: RobotPose {
            position: geom::to_point(body.translation()),
            heading,
        },
    })
}
