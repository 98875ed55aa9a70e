//! A supervisor moving a car: a new pose, a new velocity, its motion stopped (Webots'
//! `wb_supervisor_field_set_sf_vec3f` on `translation`/`rotation`,
//! `wb_supervisor_node_set_velocity`, `wb_supervisor_node_reset_physics`).
//!
//! The car moves as one rigid piece: what is relative to the chassis is kept, what would make
//! the move show up as a jolt is set to match the new motion.
//!
//! * **Suspension.** A cast car's spring compression is not state: each step measures it
//!   from the chassis' height over the ground under each wheel, so a car put down at the
//!   height it stood at on flat ground finds its springs at the same (static) deflection. A
//!   car on joints keeps its suspension and steering joint coordinates (the deflections it
//!   had), with their rates set to zero: no spring motion starts from the move.
//! * **Wheel spin.** Each wheel spins at the rate of free rolling for the new velocity, the
//!   speed of its centre along its heading (the car's turned by its steering angle) over its
//!   radius, so that the tyres start without longitudinal slip; the transient slips restart at
//!   zero and the solve's warm start is dropped (it was for the old motion).

use ackermann::Wheel;
use proto_geom::nalgebra::{Point3, UnitQuaternion, Vector3};
use proto_geom::plausible::{self, Plausible};
use rapier3d::prelude::{PhysicsWorld, Pose, Rotation, Vector};
use vehicle_model::TransientSlip;

use super::contact::Impulses;
use super::{Parts, Vehicle, joints};
use crate::error::ParamError;
use crate::geom;

/// The speeds a supervisor may give a body (m/s): up to 200 m/s (720 km/h), above any car's.
const SPEED: Plausible = Plausible {
    min: -200.0,
    max: 200.0,
    unit: "m/s",
};

/// The angular speeds a supervisor may give a body (rad/s): up to 20 rad/s, a fast spin-out.
const ANGULAR_SPEED: Plausible = Plausible {
    min: -20.0,
    max: 20.0,
    unit: "rad/s",
};

/// `position` (m) if every coordinate is within the plausible range of positions.
pub(crate) fn checked_position(position: &Point3<f64>) -> Result<Vector, ParamError> {
    for (name, v) in ["translation.x", "translation.y", "translation.z"]
        .into_iter()
        .zip(position.iter())
    {
        ParamError::within(name, *v, plausible::POSITION)?;
    }
    Ok(geom::point(position))
}

/// `rotation` as rapier's, if it is finite.
pub(crate) fn checked_rotation(rotation: &UnitQuaternion<f64>) -> Result<Rotation, ParamError> {
    let q = rotation.quaternion();
    for (name, v) in ["rotation.x", "rotation.y", "rotation.z", "rotation.w"]
        .into_iter()
        .zip([q.i, q.j, q.k, q.w])
    {
        ParamError::finite(name, v)?;
    }
    Ok(Rotation::from_xyzw(q.i as f32, q.j as f32, q.k as f32, q.w as f32).normalize())
}

/// `linear` (m/s) and `angular` (rad/s) if finite and within the supervisor's bounds.
pub(crate) fn checked_velocity(
    linear: &Vector3<f64>,
    angular: &Vector3<f64>,
) -> Result<(Vector, Vector), ParamError> {
    for (name, v) in ["velocity.x", "velocity.y", "velocity.z"]
        .into_iter()
        .zip(linear.iter())
    {
        ParamError::within(name, *v, SPEED)?;
    }
    for (name, v) in [
        "angular_velocity.x",
        "angular_velocity.y",
        "angular_velocity.z",
    ]
    .into_iter()
    .zip(angular.iter())
    {
        ParamError::within(name, *v, ANGULAR_SPEED)?;
    }
    Ok((geom::vector(linear), geom::vector(angular)))
}

impl Vehicle {
    /// Puts the car's origin (the rear-axle centre, m, world) at `position` with orientation
    /// `rotation`, keeping its velocity in its own frame (see the module docs).
    pub(crate) fn teleport(
        &mut self,
        world: &mut PhysicsWorld,
        position: &Point3<f64>,
        rotation: &UnitQuaternion<f64>,
    ) -> Result<(), ParamError> {
        let origin = Pose::from_parts(checked_position(position)?, checked_rotation(rotation)?);
        let Some((old_pose, linvel, angvel)) = self.chassis_motion(world) else {
            return Ok(());
        };
        // The velocity turns with the car: a car moving forward keeps moving forward.
        let turn = origin.rotation * old_pose.rotation.inverse();
        match &self.parts {
            Parts::Cast(p) => {
                if let Some(b) = world.bodies.get_mut(p.chassis) {
                    b.set_position(origin, true);
                    b.set_linvel(turn * linvel, true);
                    b.set_angvel(turn * angvel, true);
                }
            }
            Parts::Joints(p) => {
                let body = origin * Pose::from_translation(p.chassis_offset);
                if let Some(b) = world.bodies.get_mut(p.chassis) {
                    b.set_position(body, true);
                }
                let bodies = &mut world.bodies;
                if let Some((mb, _)) = world.multibody_joints.get_mut(p.joints[Wheel::FrontRight]) {
                    // The links follow their root now (the step would move them only after
                    // its collision detection, which must see the car where it is).
                    mb.forward_kinematics(bodies, true);
                    mb.update_rigid_bodies(bodies, false);
                    let mut v = mb.generalized_velocity_mut();
                    if v.len() >= 6 {
                        let (l, a) = (turn * linvel, turn * angvel);
                        for (i, x) in [l.x, l.y, l.z, a.x, a.y, a.z].into_iter().enumerate() {
                            v[i] = x;
                        }
                    }
                }
            }
        }
        self.state.position = *position;
        self.state.orientation = geom::to_rotation(origin.rotation);
        self.state.roll_pitch_yaw = geom::roll_pitch_yaw(origin.rotation);
        self.road_hits = super::cast::RoadHits::default();
        self.previous_com_velocity = None;
        Ok(())
    }

    /// Gives the car's origin the velocity `linear` (m/s, world) and the car the angular
    /// velocity `angular` (rad/s, world); its wheels spin at free rolling for it and its
    /// suspension and steering stop moving (see the module docs).
    pub(crate) fn set_motion(
        &mut self,
        world: &mut PhysicsWorld,
        linear: &Vector3<f64>,
        angular: &Vector3<f64>,
    ) -> Result<(), ParamError> {
        let (v_origin, omega) = checked_velocity(linear, angular)?;
        let Some((pose, _, _)) = self.chassis_motion(world) else {
            return Ok(());
        };
        match &self.parts {
            Parts::Cast(p) => {
                if let Some(b) = world.bodies.get_mut(p.chassis) {
                    let com = b.center_of_mass();
                    b.set_linvel(v_origin + omega.cross(com - pose.translation), true);
                    b.set_angvel(omega, true);
                }
            }
            Parts::Joints(p) => {
                let Some(com) = world.bodies.get(p.chassis).map(|b| b.center_of_mass()) else {
                    return Ok(());
                };
                let v_com = v_origin + omega.cross(com - pose.translation);
                if let Some(b) = world.bodies.get_mut(p.chassis) {
                    b.set_linvel(v_com, true);
                    b.set_angvel(omega, true);
                }
                if let Some((mb, _)) = world.multibody_joints.get_mut(p.joints[Wheel::FrontRight]) {
                    let mut v = mb.generalized_velocity_mut();
                    v.fill(0.0);
                    if v.len() >= 6 {
                        for (i, x) in [v_com.x, v_com.y, v_com.z, omega.x, omega.y, omega.z]
                            .into_iter()
                            .enumerate()
                        {
                            v[i] = x;
                        }
                    }
                }
            }
        }
        let s = &mut self.state;
        for w in Wheel::ALL {
            let spec = self.spec.wheels[w];
            let steer = match w {
                Wheel::FrontRight => s.steering.right,
                Wheel::FrontLeft => s.steering.left,
                Wheel::RearRight | Wheel::RearLeft => 0.0,
            };
            // Positive steering turns right: about −z of the car.
            let heading = pose.rotation * Rotation::from_rotation_z(-steer as f32) * Vector::X;
            let centre = pose.transform_point(geom::point(&spec.position));
            let v_wheel = v_origin + omega.cross(centre - pose.translation);
            s.wheel_speeds[w] = f64::from(v_wheel.dot(heading)) / spec.radius;
        }
        s.velocity = *linear;
        s.angular_velocity = *angular;
        s.yaw_rate = angular.z;
        s.forward_speed = f64::from(v_origin.dot(pose.rotation * Vector::X));
        s.longitudinal_acceleration = 0.0;
        s.lateral_acceleration = 0.0;
        self.slips = ackermann::PerWheel::splat(TransientSlip::default());
        self.impulses = ackermann::PerWheel::splat(Impulses::default());
        self.steering_rates = [0.0; 2];
        self.previous_com_velocity = None;
        Ok(())
    }

    /// The car frame's pose, and the chassis body's linear (of its centre of mass, m/s) and
    /// angular (rad/s) velocity, world; `None` if the chassis is gone.
    fn chassis_motion(&self, world: &PhysicsWorld) -> Option<(Pose, Vector, Vector)> {
        match &self.parts {
            Parts::Cast(p) => {
                let b = world.bodies.get(p.chassis)?;
                Some((*b.position(), b.linvel(), b.angvel()))
            }
            Parts::Joints(p) => {
                let b = world.bodies.get(p.chassis)?;
                let (mb, _) = world.multibody_joints.get(p.joints[Wheel::FrontRight])?;
                let v = mb.generalized_velocity();
                let (l, a) = if v.len() >= 6 {
                    (Vector::new(v[0], v[1], v[2]), Vector::new(v[3], v[4], v[5]))
                } else {
                    (b.linvel(), b.angvel())
                };
                Some((joints::car_pose(b, p), l, a))
            }
        }
    }
}
