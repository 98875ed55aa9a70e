//! Dynamic rigid boxes of a world (`[[body]]` in a world file): free bodies under gravity that
//! cars' chassis, robots and other boxes push around.

use proto_geom::plausible;
use rapier3d::prelude::{
    CoefficientCombineRule, ColliderBuilder, PhysicsWorld, RigidBodyBuilder, RigidBodyHandle,
};

use crate::config::DEFAULT_FRICTION;
use crate::error::ParamError;
use crate::geom::{self, G_DYNAMIC};

/// A dynamic box: a cuboid of uniform density free under gravity.
///
/// ```
/// use sim::{BodySpec, World, WorldConfig};
/// let cube = BodySpec { center: [0.0, 0.0, 0.5], size: [1.0; 3], yaw: 0.0, mass: 200.0, friction: None };
/// let mut world = World::new(WorldConfig { bodies: vec![cube], ..WorldConfig::default() })?;
/// world.step()?;
/// assert!((world.bodies()[0].position[2] - 0.5).abs() < 2e-3); // resting on the ground
/// # Ok::<(), sim::SimError>(())
/// ```
#[derive(Debug, Clone, PartialEq)]
pub struct BodySpec {
    /// Centre at the start (m, world frame).
    pub center: [f64; 3],
    /// Full lengths along the box's own x, y, z (m, each in [`plausible::LENGTH`]: below a millimetre rapier's contact
    /// margins dominate the shape).
    pub size: [f64; 3],
    /// Heading at the start (rad, counter-clockwise about +z).
    pub yaw: f64,
    /// Mass (kg, in [`plausible::MASS`]), spread uniformly over the box.
    pub mass: f64,
    /// Coulomb friction of its faces (≥ 0), multiplied by the other surface's (the ground's,
    /// a chassis' 1, another box's); `None` = [`DEFAULT_FRICTION`] (1), so that on the ground
    /// the box slides with the ground's friction.
    pub friction: Option<f64>,
}

impl BodySpec {
    /// Checks every field: a finite centre and heading, sizes and mass within their ranges and
    /// a finite friction ≥ 0. Fields are named `body.center`, `body.size`, `body.yaw`,
    /// `body.mass` and `body.friction`.
    pub fn validate(&self) -> Result<(), ParamError> {
        for c in self.center {
            ParamError::within("body.center", c, plausible::POSITION)?;
        }
        for s in self.size {
            ParamError::within("body.size", s, plausible::LENGTH)?;
        }
        ParamError::finite("body.yaw", self.yaw)?;
        ParamError::within("body.mass", self.mass, plausible::MASS)?;
        if let Some(f) = self.friction {
            ParamError::non_negative("body.friction", f)?;
        }
        Ok(())
    }
}

/// Where a dynamic box is after a step.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct BodyPose {
    /// Centre (m, world frame).
    pub position: [f64; 3],
    /// Orientation as Webots' `rotation` field: unit axis x, y, z and angle (rad, in [0, π]);
    /// `[0, 0, 1, 0]` for no rotation.
    pub rotation: [f64; 4],
    /// Roll, pitch and yaw (rad, z-y-x convention, as [`VehicleState`](crate::VehicleState)).
    pub roll_pitch_yaw: [f64; 3],
    /// Velocity of the centre (m/s, world frame).
    pub velocity: [f64; 3],
}

/// Inserts the boxes of `specs` (validated) into `world`, in order; they never sleep, like
/// every body of a world, so that stepping stays deterministic.
pub(crate) fn build(world: &mut PhysicsWorld, specs: &[BodySpec]) -> Vec<RigidBodyHandle> {
    specs
        .iter()
        .map(|b| {
            let handle = world.insert_body(
                RigidBodyBuilder::dynamic()
                    .pose(geom::pose_xyz_yaw(b.center, b.yaw))
                    .can_sleep(false),
            );
            let [hx, hy, hz] = b.size.map(|s| (s / 2.0) as f32);
            let collider = ColliderBuilder::cuboid(hx, hy, hz)
                .mass(b.mass as f32)
                .friction(b.friction.unwrap_or(DEFAULT_FRICTION) as f32)
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
    let (w, x, y, z) = (
        f64::from(q.w),
        f64::from(q.x),
        f64::from(q.y),
        f64::from(q.z),
    );
    // q and −q are the same rotation: take w ≥ 0 for an angle in [0, π].
    let s = if w < 0.0 { -1.0 } else { 1.0 };
    let sin_half = (x * x + y * y + z * z).sqrt();
    let angle = 2.0 * sin_half.atan2(w * s);
    let rotation = if sin_half > 1e-12 {
        [s * x / sin_half, s * y / sin_half, s * z / sin_half, angle]
    } else {
        [0.0, 0.0, 1.0, 0.0]
    };
    Some(BodyPose {
        position: geom::arr3(b.translation()),
        rotation,
        roll_pitch_yaw: geom::roll_pitch_yaw(q),
        velocity: geom::arr3(b.linvel()),
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    fn cube() -> BodySpec {
        BodySpec {
            center: [0.0, 0.0, 0.5],
            size: [1.0; 3],
            yaw: 0.0,
            mass: 200.0,
            friction: None,
        }
    }

    #[test]
    fn rejects_bad_fields() {
        assert!(cube().validate().is_ok());
        let e = BodySpec {
            size: [1.0, 2e3, 1.0],
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
            center: [0.0, f64::INFINITY, 0.0],
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
        // −0.3 rad about +z is 0.3 rad about −z.
        let [x, y, z, a] = p.rotation;
        assert!(
            x.abs() < 1e-6 && y.abs() < 1e-6 && (z + 1.0).abs() < 1e-6,
            "{p:?}"
        );
        assert!((a - 0.3).abs() < 1e-6);
        assert!((p.roll_pitch_yaw[2] + 0.3).abs() < 1e-6);
    }
}
