//! Dynamic rigid boxes of a world (`[[body]]` in a world file): free bodies under gravity that
//! cars' chassis, robots and other boxes push around.

use proto_geom::nalgebra::{Point2, Point3, UnitQuaternion, Vector3};
use proto_geom::plausible;
use rapier3d::prelude::{
    CoefficientCombineRule, ColliderBuilder, PhysicsWorld, RigidBodyBuilder, RigidBodyHandle,
};

use crate::attitude::RollPitchYaw;
use crate::error::ParamError;
use crate::geom::{self, G_DYNAMIC};
use crate::geom::{DEFAULT_FRICTION, ground_rectangle};

/// A dynamic box: a cuboid of uniform density free under gravity.
///
/// ```
/// use sim::nalgebra::{Point3, Vector3};
/// use sim::{BodySpec, World, WorldConfig};
/// let cube = BodySpec {
///     center: Point3::new(0.0, 0.0, 0.5),
///     size: Vector3::repeat(1.0),
///     yaw: 0.0,
///     mass: 200.0,
///     friction: None,
///     radar_cross_section: 0.0,
/// };
/// let mut world = World::new(WorldConfig { bodies: vec![cube], ..WorldConfig::default() })?;
/// world.step()?;
/// assert!((world.bodies()[0].position.z - 0.5).abs() < 2e-3); // resting on the ground
/// # Ok::<(), sim::SimError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct BodySpec {
    /// Centre at the start (m, world frame).
    pub center: Point3<f64>,
    /// Full lengths along the box's own x, y, z (m, each in [`plausible::LENGTH`]: below a
    /// millimetre rapier's contact margins dominate the shape).
    pub size: Vector3<f64>,
    /// Heading at the start (rad, counter-clockwise about +z).
    pub yaw: f64,
    /// Mass (kg, in [`plausible::MASS`]), spread uniformly over the box.
    pub mass: f64,
    /// Coulomb friction of its faces (dimensionless, 0 to 100: [`plausible::FRICTION`]),
    /// multiplied by the other surface's (the ground's,
    /// a chassis' 1, another box's); `None` = [`DEFAULT_FRICTION`] (1), so that on the ground
    /// the box slides with the ground's friction.
    pub friction: Option<f64>,
    /// Webots' `radarCrossSection` of the box (m², ≥ 0; 0, the default, hides it from radars).
    pub radar_cross_section: f64,
}

impl BodySpec {
    /// Checks every field: a finite centre and heading, sizes and mass within their ranges and
    /// a friction from 0 to 100, a radar cross-section ≥ 0. Fields are named `body.center`,
    /// `body.size`, `body.yaw`, `body.mass`, `body.friction` and `body.radarCrossSection`.
    pub fn validate(&self) -> Result<(), ParamError> {
        for &c in self.center.iter() {
            ParamError::within("body.center", c, plausible::POSITION)?;
        }
        for &s in self.size.iter() {
            ParamError::within("body.size", s, plausible::LENGTH)?;
        }
        ParamError::finite("body.yaw", self.yaw)?;
        ParamError::within("body.mass", self.mass, plausible::MASS)?;
        if let Some(f) = self.friction {
            ParamError::friction("body.friction", f)?;
        }
        ParamError::non_negative("body.radarCrossSection", self.radar_cross_section)?;
        Ok(())
    }

    /// Its faces' friction coefficient (dimensionless): its own, else [`DEFAULT_FRICTION`].
    pub(crate) fn friction_or_default(&self) -> f64 {
        self.friction.unwrap_or(DEFAULT_FRICTION)
    }

    /// The corners of its footprint on the ground at the start (m, world x and y),
    /// counter-clockwise.
    pub fn footprint(&self) -> [Point2<f64>; 4] {
        let half = self.size / 2.0;
        ground_rectangle(self.center.xy(), self.yaw, [-half.x, half.x], half.y)
    }
}

/// Where a dynamic box is after a step.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BodyPose {
    /// Centre (m, world frame).
    pub position: Point3<f64>,
    /// Orientation (world frame); `rotation.axis_angle()` gives Webots' `rotation` field (unit
    /// axis and angle in [0, π] rad, `None` for no rotation).
    pub rotation: UnitQuaternion<f64>,
    /// Roll, pitch and yaw (rad, z-y-x convention, as [`VehicleState`](crate::VehicleState)).
    pub roll_pitch_yaw: RollPitchYaw,
    /// Velocity of the centre (m/s, world frame).
    pub velocity: Vector3<f64>,
}

/// Inserts the boxes of `specs` (validated) into `world`, in order; they never sleep, like
/// every body of a world, so that stepping stays deterministic.
pub(crate) fn build(world: &mut PhysicsWorld, specs: &[BodySpec]) -> Vec<RigidBodyHandle> {
    specs
        .iter()
        .map(|b| {
            let handle = world.insert_body(
                RigidBodyBuilder::dynamic()
                    .pose(geom::pose_xyz_yaw(&b.center, b.yaw))
                    .can_sleep(false),
            );
            let half = geom::vector(&(b.size / 2.0));
            let collider = ColliderBuilder::cuboid(half.x, half.y, half.z)
                .mass(b.mass as f32)
                .friction(b.friction_or_default() as f32)
                .friction_combine_rule(CoefficientCombineRule::Multiply)
                .collision_groups(geom::groups(G_DYNAMIC));
            world.insert_collider(collider, Some(handle));
            handle
        })
        .collect()
}

/// The pose of the box `handle`, `None` if it is gone or no longer finite.
pub(crate) fn pose(world: &PhysicsWorld, handle: RigidBodyHandle) -> Option<BodyPose> {
    let b = geom::finite_body(world, handle)?;
    let q = *b.rotation();
    Some(BodyPose {
        position: geom::to_point(b.translation()),
        rotation: geom::to_rotation(q),
        roll_pitch_yaw: geom::roll_pitch_yaw(q),
        velocity: geom::to_vector(b.linvel()),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cube() -> BodySpec {
        BodySpec {
            center: Point3::new(0.0, 0.0, 0.5),
            size: Vector3::repeat(1.0),
            yaw: 0.0,
            mass: 200.0,
            friction: None,
            radar_cross_section: 0.0,
        }
    }

    #[test]
    fn rejects_bad_fields() {
        assert!(cube().validate().is_ok());
        let e = BodySpec {
            size: Vector3::new(1.0, 2e3, 1.0),
            ..cube()
        }
        .validate()
        .unwrap_err();
        assert_eq!((e.field, e.value), ("body.size", 2e3));
        let e = BodySpec {
            mass: f64::NAN,
            ..cube()
        }
        .validate()
        .unwrap_err();
        assert_eq!(e.field, "body.mass");
        let e = BodySpec {
            center: Point3::new(0.0, f64::INFINITY, 0.0),
            ..cube()
        }
        .validate()
        .unwrap_err();
        assert_eq!(e.field, "body.center");
        let e = BodySpec {
            friction: Some(-0.1),
            ..cube()
        }
        .validate()
        .unwrap_err();
        assert_eq!((e.field, e.value), ("body.friction", -0.1));
    }

    #[test]
    fn axis_angle_of_a_turned_box() {
        let mut world = PhysicsWorld::new();
        let handles = build(
            &mut world,
            &[BodySpec {
                yaw: -0.3,
                ..cube()
            }],
        );
        let p = pose(&world, handles[0]).unwrap();
        // −0.3 rad about +z is 0.3 rad about −z, as Webots writes a rotation.
        let (axis, a) = p.rotation.axis_angle().unwrap();
        assert!(
            axis.x.abs() < 1e-6 && axis.y.abs() < 1e-6 && (axis.z + 1.0).abs() < 1e-6,
            "{p:?}"
        );
        assert!((a - 0.3).abs() < 1e-6);
        assert!((p.roll_pitch_yaw.yaw + 0.3).abs() < 1e-6);
    }
}
