//! The rapier boundary: conversions between the public API's f64 nalgebra geometry and
//! rapier's f32 glam types, angle helpers, and what everything in a world shares: the
//! collision groups, the default friction and the footprint of a rectangle on the ground.
//!
//! The public API is f64 nalgebra (`Point3`, `Vector3`, `UnitQuaternion`), as `proto-geom`'s;
//! rapier runs in f32 glam inside, and its types never leave the crate. Every conversion goes
//! through this module, component by component, so that each value is rounded to f32 exactly
//! once. Positions keep about 0.1 mm resolution up to 1 km from the origin, which is enough
//! for the scenarios this crate serves.

use core::f64::consts::{PI, TAU};

use proto_geom::nalgebra::{Point2, Point3, Quaternion, UnitQuaternion, Vector3};
use rapier3d::prelude::{Group, InteractionGroups, InteractionTestMode, Pose, Rotation, Vector};

use crate::attitude::RollPitchYaw;

/// Webots default Coulomb friction of a `ContactProperties` node.
pub const DEFAULT_FRICTION: f64 = 1.0;

/// The corners of a rectangle on the ground (m, world x and y), counter-clockwise: from `x0`
/// to `x1` along the heading `yaw` (rad) and `±half_width` across it, in a frame at `origin`.
/// The footprint of the boxes and ramps, for the plots and the replay's ground.
pub(crate) fn ground_rectangle(
    origin: Point2<f64>,
    yaw: f64,
    [x0, x1]: [f64; 2],
    half_width: f64,
) -> [Point2<f64>; 4] {
    let (s, c) = yaw.sin_cos();
    [
        [x0, -half_width],
        [x1, -half_width],
        [x1, half_width],
        [x0, half_width],
    ]
    .map(|[x, y]| Point2::new(origin.x + c * x - s * y, origin.y + s * x + c * y))
}

/// A vector (m, m/s, m/s², …) as a rapier vector.
pub(crate) fn vector(v: &Vector3<f64>) -> Vector {
    Vector::new(v.x as f32, v.y as f32, v.z as f32)
}

/// A position (m) as a rapier vector (rapier holds positions as vectors).
pub(crate) fn point(p: &Point3<f64>) -> Vector {
    vector(&p.coords)
}

/// A rapier vector as a vector.
pub(crate) fn to_vector(v: Vector) -> Vector3<f64> {
    Vector3::new(f64::from(v.x), f64::from(v.y), f64::from(v.z))
}

/// A rapier vector that holds a position (m) as a point.
pub(crate) fn to_point(v: Vector) -> Point3<f64> {
    Point3::from(to_vector(v))
}

/// A rapier rotation as a unit quaternion (exact: every f32 is an f64).
pub(crate) fn to_rotation(q: Rotation) -> UnitQuaternion<f64> {
    let [w, x, y, z] = [q.w, q.x, q.y, q.z].map(f64::from);
    UnitQuaternion::new_unchecked(Quaternion::new(w, x, y, z))
}

/// A pose from a position (m) and a heading (rad, about +z). The heading is turned into a
/// rotation in f32, as rapier builds its own.
pub(crate) fn pose_xyz_yaw(at: &Point3<f64>, yaw: f64) -> Pose {
    Pose::from_parts(point(at), Rotation::from_rotation_z(yaw as f32))
}

/// Roll, pitch and yaw (rad) of a rotation (see [`RollPitchYaw`]).
pub(crate) fn roll_pitch_yaw(q: Rotation) -> RollPitchYaw {
    let (w, x, y, z) = (
        f64::from(q.w),
        f64::from(q.x),
        f64::from(q.y),
        f64::from(q.z),
    );
    let roll = (2.0 * (w * x + y * z)).atan2(1.0 - 2.0 * (x * x + y * y));
    let pitch = (2.0 * (w * y - z * x)).clamp(-1.0, 1.0).asin();
    let yaw = (2.0 * (w * z + x * y)).atan2(1.0 - 2.0 * (y * y + z * z));
    RollPitchYaw { roll, pitch, yaw }
}

/// The angle (rad, in (−π, π]) of a rotation known to be about the local y axis.
pub(crate) fn angle_about_y(q: Rotation) -> f64 {
    wrap(2.0 * f64::from(q.y).atan2(f64::from(q.w)))
}

/// `a` wrapped into (−π, π].
pub(crate) fn wrap(a: f64) -> f64 {
    let r = (a + PI).rem_euclid(TAU) - PI;
    if r == -PI { PI } else { r }
}

/// The rotation (rad) between two wrapped angle readings, choosing among the readings'
/// 2π-ambiguous differences the one closest to `predicted` (e.g. angular velocity × dt).
///
/// This counts whole turns correctly as long as the prediction is within π of the truth, so a
/// wheel at 134 rad/s (1.34 rad per 10 ms step) or faster is tracked without aliasing, where a
/// plain wrap into (−π, π] (Webots' encoder update) would alias above π per step.
pub(crate) fn unwrap_delta(previous: f64, current: f64, predicted: f64) -> f64 {
    let d = wrap(current - previous);
    if predicted.is_finite() {
        d + TAU * ((predicted - d) / TAU).round()
    } else {
        d
    }
}

/// Collision group of the ground and the static obstacles.
pub(crate) const G_STATIC: Group = Group::GROUP_1;
/// Collision group of the road surfaces: static like [`G_STATIC`] (everything that meets the
/// ground meets them), apart so that a cast car's wheels find them by a ray and the triangle's
/// plane instead of a shape cast against each triangle (see `vehicle::cast`).
pub(crate) const G_ROAD: Group = Group::GROUP_7;
/// Collision group of car chassis.
pub(crate) const G_CAR_BODY: Group = Group::GROUP_2;
/// Collision group of the wheels of cars on joints.
pub(crate) const G_CAR_WHEEL: Group = Group::GROUP_3;
/// Collision group of the dynamic boxes (`[[body]]`).
pub(crate) const G_DYNAMIC: Group = Group::GROUP_6;
/// Collision group of DifferentialWheels bodies (with their casters).
pub(crate) const G_ROBOT_BODY: Group = Group::GROUP_4;
/// Collision group of DifferentialWheels wheels.
pub(crate) const G_ROBOT_WHEEL: Group = Group::GROUP_5;

/// The interaction groups of a collider in group `g`.
///
/// Robot wheels touch only static geometry and dynamic boxes, so a wheel never collides with
/// its own body; car chassis, robot bodies, dynamic boxes and the wheels of cars on joints
/// collide with each other (a car on joints never meets its own wheels: its multibody's
/// self-contacts are off). The wheels of cast cars are shape casts that see static geometry
/// only, not colliders.
pub(crate) fn groups(g: Group) -> InteractionGroups {
    let statics = G_STATIC | G_ROAD;
    let filter = if g == G_STATIC || g == G_ROAD {
        Group::ALL
    } else if g == G_DYNAMIC {
        statics | G_CAR_BODY | G_ROBOT_BODY | G_ROBOT_WHEEL | G_DYNAMIC | G_CAR_WHEEL
    } else if g == G_CAR_BODY || g == G_ROBOT_BODY || g == G_CAR_WHEEL {
        statics | G_CAR_BODY | G_ROBOT_BODY | G_DYNAMIC | G_CAR_WHEEL
    } else {
        statics | G_DYNAMIC
    };
    InteractionGroups::new(g, filter, InteractionTestMode::And)
}

/// The body `handle` of `world`, if it exists and its pose and velocities are finite: what a
/// step reads back, so that a diverged body is reported rather than measured.
pub(crate) fn finite_body(
    world: &rapier3d::prelude::PhysicsWorld,
    handle: rapier3d::prelude::RigidBodyHandle,
) -> Option<&rapier3d::prelude::RigidBody> {
    world
        .bodies
        .get(handle)
        .filter(|b| b.position().is_finite() && b.linvel().is_finite() && b.angvel().is_finite())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wrap_range() {
        assert_eq!(wrap(PI), PI);
        assert_eq!(wrap(-PI), PI);
        assert!((wrap(3.0 * PI / 2.0) + PI / 2.0).abs() < 1e-12);
    }

    #[test]
    fn unwrap_follows_prediction() {
        // True rotation 4 rad: readings 0 → wrap(4) = 4 − 2π.
        let d = unwrap_delta(0.0, wrap(4.0), 3.9);
        assert!((d - 4.0).abs() < 1e-12);
        // Backward 1 rad.
        assert!((unwrap_delta(0.5, -0.5, -1.1) + 1.0).abs() < 1e-12);
        // No prediction: plain wrap.
        assert!((unwrap_delta(0.0, wrap(4.0), f64::NAN) - (4.0 - TAU)).abs() < 1e-12);
    }

    #[test]
    fn euler_of_yaw() {
        let q = Rotation::from_rotation_z(0.7);
        let RollPitchYaw { roll, pitch, yaw } = roll_pitch_yaw(q);
        assert!(roll.abs() < 1e-6 && pitch.abs() < 1e-6 && (yaw - 0.7).abs() < 1e-6);
        // z-y-x: yaw about the world's z, then pitch and roll about the body's own axes; the
        // angles read back build the same rotation.
        let q = Rotation::from_rotation_z(0.3)
            * Rotation::from_rotation_y(-0.1)
            * Rotation::from_rotation_x(0.2);
        let a = roll_pitch_yaw(q);
        assert!(
            (a.roll - 0.2).abs() < 1e-6 && (a.pitch + 0.1).abs() < 1e-6,
            "{a:?}"
        );
        assert!((a.yaw - 0.3).abs() < 1e-6, "{a:?}");
        assert!(a.rotation().angle_to(&to_rotation(q)) < 1e-6);
        assert!((angle_about_y(Rotation::from_rotation_y(-2.0)) + 2.0).abs() < 1e-6);
    }
}
