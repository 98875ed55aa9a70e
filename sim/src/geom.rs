//! Conversions between the f64 public API and rapier's f32 glam types, angle helpers and the
//! collision groups shared by everything in a world.
//!
//! The public API is f64 (as Webots); rapier runs in f32 inside. Positions keep about 0.1 mm
//! resolution up to 1 km from the origin, which is enough for the scenarios this crate serves.

use core::f64::consts::{PI, TAU};

use rapier3d::prelude::{Group, InteractionGroups, InteractionTestMode, Pose, Rotation, Vector};

/// An f64 triple as a rapier vector.
pub(crate) fn vec3(v: [f64; 3]) -> Vector {
    Vector::new(v[0] as f32, v[1] as f32, v[2] as f32)
}

/// A rapier vector as an f64 triple.
pub(crate) fn arr3(v: Vector) -> [f64; 3] {
    [f64::from(v.x), f64::from(v.y), f64::from(v.z)]
}

/// A pose from a translation (m) and a heading (rad, about +z).
pub(crate) fn pose_xyz_yaw(t: [f64; 3], yaw: f64) -> Pose {
    Pose::from_parts(vec3(t), Rotation::from_rotation_z(yaw as f32))
}

/// Roll, pitch and yaw (rad) of a rotation, in the z-y-x (yaw, then pitch, then roll)
/// convention of vehicle dynamics (ISO 8855).
pub(crate) fn roll_pitch_yaw(q: Rotation) -> [f64; 3] {
    let (w, x, y, z) = (
        f64::from(q.w),
        f64::from(q.x),
        f64::from(q.y),
        f64::from(q.z),
    );
    let roll = (2.0 * (w * x + y * z)).atan2(1.0 - 2.0 * (x * x + y * y));
    let pitch = (2.0 * (w * y - z * x)).clamp(-1.0, 1.0).asin();
    let yaw = (2.0 * (w * z + x * y)).atan2(1.0 - 2.0 * (y * y + z * z));
    [roll, pitch, yaw]
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
    let filter = if g == G_STATIC {
        Group::ALL
    } else if g == G_DYNAMIC {
        G_STATIC | G_CAR_BODY | G_ROBOT_BODY | G_ROBOT_WHEEL | G_DYNAMIC | G_CAR_WHEEL
    } else if g == G_CAR_BODY || g == G_ROBOT_BODY || g == G_CAR_WHEEL {
        G_STATIC | G_CAR_BODY | G_ROBOT_BODY | G_DYNAMIC | G_CAR_WHEEL
    } else {
        G_STATIC | G_DYNAMIC
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
        let [r, p, y] = roll_pitch_yaw(q);
        assert!(r.abs() < 1e-6 && p.abs() < 1e-6 && (y - 0.7).abs() < 1e-6);
        assert!((angle_about_y(Rotation::from_rotation_y(-2.0)) + 2.0).abs() < 1e-6);
    }
}
