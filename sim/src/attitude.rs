//! A body's attitude as the three angles of vehicle dynamics.

use proto_geom::nalgebra::UnitQuaternion;

/// Roll, pitch and yaw (rad) in the z-y-x convention of vehicle dynamics (ISO 8855): the body
/// is turned by `yaw` about the world's z, then by `pitch` about its own y, then by `roll`
/// about its own x.
///
/// A named triple rather than a rotation because these are the angles a test bench reads and
/// plots; [`RollPitchYaw::rotation`] gives the rotation.
///
/// ```
/// use sim::RollPitchYaw;
/// let a = RollPitchYaw { roll: 0.0, pitch: 0.0, yaw: 0.5 };
/// let q = a.rotation();
/// assert!((q.angle() - 0.5).abs() < 1e-12);
/// ```
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct RollPitchYaw {
    /// Rotation about the body's x axis (rad, positive = left side up).
    pub roll: f64,
    /// Rotation about the body's y axis (rad, positive = nose down), in [−π/2, π/2].
    pub pitch: f64,
    /// Heading (rad, counter-clockwise about world +z from +x), in (−π, π].
    pub yaw: f64,
}

impl RollPitchYaw {
    /// The rotation these angles describe (yaw, then pitch, then roll).
    pub fn rotation(&self) -> UnitQuaternion<f64> {
        UnitQuaternion::from_euler_angles(self.roll, self.pitch, self.yaw)
    }
}
