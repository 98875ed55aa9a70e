//! What a Webots supervisor does to a world's things: reads and sets a car's or a dynamic
//! body's pose and velocity, and stops its motion (`wb_supervisor_field_get/set_sf_vec3f` on
//! `translation`, `..._sf_rotation` on `rotation`, `wb_supervisor_node_get/set_velocity`,
//! `wb_supervisor_node_reset_physics`). How a car is moved is [`crate::vehicle`]'s
//! `teleport` module.

use proto_geom::nalgebra::{Point3, UnitQuaternion, Vector3};
use rapier3d::prelude::{Pose, RigidBodyHandle};

use super::World;
use crate::error::{ParamError, SimError};
use crate::geom;
use crate::vehicle::{VehicleId, teleport};

/// Where a car or body is and how it moves: world frame, x east (forward at yaw 0), y north
/// (left), z up.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Placement {
    /// Position (m): a car's origin (the rear-axle centre at wheel-centre height), a body's
    /// centre. Webots: `translation`.
    pub position: Point3<f64>,
    /// Orientation. Webots: `rotation` (`rotation.axis_angle()` gives its axis and angle).
    pub rotation: UnitQuaternion<f64>,
    /// Velocity of that position (m/s). Webots: `wb_supervisor_node_get_velocity`'s first three.
    pub velocity: Vector3<f64>,
    /// Angular velocity (rad/s). Webots: `wb_supervisor_node_get_velocity`'s last three.
    pub angular_velocity: Vector3<f64>,
}

impl Placement {
    /// The orientation as Webots' `rotation` field: unit axis and angle (rad, in [0, π]);
    /// `[0, 0, 1, 0]` for no rotation.
    pub fn axis_angle(&self) -> [f64; 4] {
        match self.rotation.axis_angle() {
            Some((axis, angle)) => [axis.x, axis.y, axis.z, angle],
            None => [0.0, 0.0, 1.0, 0.0],
        }
    }
}

/// The rotation of Webots' `rotation` field `[x, y, z, angle]` (axis, any length but zero, and
/// angle in rad).
///
/// # Errors
/// [`ParamError`] naming `rotation.angle` or the axis component that is not finite, or
/// `rotation` for a zero axis.
pub fn rotation_from_axis_angle(rotation: [f64; 4]) -> Result<UnitQuaternion<f64>, ParamError> {
    let [x, y, z, angle] = rotation;
    for (name, v) in ["rotation.x", "rotation.y", "rotation.z", "rotation.angle"]
        .into_iter()
        .zip(rotation)
    {
        ParamError::finite(name, v)?;
    }
    let axis = Vector3::new(x, y, z);
    let norm = axis.norm();
    ParamError::check("rotation axis length", norm, "> 0", |n| n > 0.0)?;
    Ok(UnitQuaternion::from_axis_angle(
        &proto_geom::nalgebra::Unit::new_normalize(axis),
        angle,
    ))
}

impl World {
    /// Car `id`'s pose and velocity after the last step (or as a supervisor set them since).
    pub fn vehicle_placement(&self, id: VehicleId) -> Result<Placement, SimError> {
        let s = self.vehicle(id)?.state();
        Ok(Placement {
            position: s.position,
            rotation: s.orientation,
            velocity: s.velocity,
            angular_velocity: s.angular_velocity,
        })
    }

    /// Puts car `id`'s origin (m) at `position` with orientation `rotation`; its velocity turns
    /// with it (a car driving forward drives forward in its new heading); its suspension and
    /// steering keep their deflections and angles (the `teleport` module says why the springs
    /// are then at their static deflection on flat ground).
    ///
    /// # Errors
    /// [`SimError::UnknownVehicle`]; [`SimError::Param`] for a position beyond 10 km or a
    /// non-finite rotation (nothing is moved).
    pub fn set_vehicle_pose(
        &mut self,
        id: VehicleId,
        position: &Point3<f64>,
        rotation: &UnitQuaternion<f64>,
    ) -> Result<(), SimError> {
        let vehicle = self
            .vehicles
            .get_mut(id.0)
            .ok_or(SimError::UnknownVehicle(id.0))?;
        Ok(vehicle.teleport(&mut self.physics, position, rotation)?)
    }

    /// Gives car `id`'s origin the velocity `linear` (m/s, world) and the car the angular
    /// velocity `angular` (rad/s, world); its wheels spin at free rolling for it and its
    /// suspension and steering stop moving.
    ///
    /// # Errors
    /// [`SimError::UnknownVehicle`]; [`SimError::Param`] for a speed beyond 200 m/s or an
    /// angular speed beyond 20 rad/s on an axis (nothing is changed).
    pub fn set_vehicle_velocity(
        &mut self,
        id: VehicleId,
        linear: &Vector3<f64>,
        angular: &Vector3<f64>,
    ) -> Result<(), SimError> {
        let vehicle = self
            .vehicles
            .get_mut(id.0)
            .ok_or(SimError::UnknownVehicle(id.0))?;
        Ok(vehicle.set_motion(&mut self.physics, linear, angular)?)
    }

    /// Stops car `id`: no velocity, no wheel spin, no suspension motion. Webots:
    /// `wb_supervisor_node_reset_physics`.
    ///
    /// # Errors
    /// [`SimError::UnknownVehicle`].
    pub fn reset_vehicle_physics(&mut self, id: VehicleId) -> Result<(), SimError> {
        self.set_vehicle_velocity(id, &Vector3::zeros(), &Vector3::zeros())
    }

    /// The number of dynamic bodies (`[[body]]`), indexed from 0 in the world file's order.
    pub fn body_count(&self) -> usize {
        self.bodies.len()
    }

    fn body_handle(&self, index: usize) -> Result<RigidBodyHandle, SimError> {
        self.bodies
            .get(index)
            .copied()
            .ok_or(SimError::UnknownBody(index))
    }

    /// Dynamic body `index`'s pose and velocity (of its centre).
    ///
    /// # Errors
    /// [`SimError::UnknownBody`].
    pub fn body_placement(&self, index: usize) -> Result<Placement, SimError> {
        let h = self.body_handle(index)?;
        let b = self
            .physics
            .bodies
            .get(h)
            .ok_or(SimError::UnknownBody(index))?;
        Ok(Placement {
            position: geom::to_point(b.translation()),
            rotation: geom::to_rotation(*b.rotation()),
            velocity: geom::to_vector(b.linvel()),
            angular_velocity: geom::to_vector(b.angvel()),
        })
    }

    /// Puts dynamic body `index`'s centre (m) at `position` with orientation `rotation`,
    /// keeping its velocity.
    ///
    /// # Errors
    /// [`SimError::UnknownBody`]; [`SimError::Param`] as for [`World::set_vehicle_pose`].
    pub fn set_body_pose(
        &mut self,
        index: usize,
        position: &Point3<f64>,
        rotation: &UnitQuaternion<f64>,
    ) -> Result<(), SimError> {
        let h = self.body_handle(index)?;
        let pose = Pose::from_parts(
            teleport::checked_position(position)?,
            teleport::checked_rotation(rotation)?,
        );
        if let Some(b) = self.physics.bodies.get_mut(h) {
            b.set_position(pose, true);
        }
        Ok(())
    }

    /// Gives dynamic body `index`'s centre the velocity `linear` (m/s) and the body the angular
    /// velocity `angular` (rad/s), world axes.
    ///
    /// # Errors
    /// [`SimError::UnknownBody`]; [`SimError::Param`] as for [`World::set_vehicle_velocity`].
    pub fn set_body_velocity(
        &mut self,
        index: usize,
        linear: &Vector3<f64>,
        angular: &Vector3<f64>,
    ) -> Result<(), SimError> {
        let h = self.body_handle(index)?;
        let (l, a) = teleport::checked_velocity(linear, angular)?;
        if let Some(b) = self.physics.bodies.get_mut(h) {
            // A box's frame is its centre of mass (a uniform cuboid).
            b.set_linvel(l, true);
            b.set_angvel(a, true);
        }
        Ok(())
    }
}
