//! The chassis as the contact solve sees it: its velocities and inverse mass properties, and
//! how an impulse at a point changes them.

use rapier3d::prelude::{Mat3, Rotation, Vector};

/// The chassis as the solve sees it: its velocities (changed in place) and inverse mass
/// properties in the world frame.
#[derive(Debug, Clone, Copy)]
pub(crate) struct Body {
    /// Velocity of the centre of mass (m/s).
    pub linvel: Vector,
    /// Angular velocity (rad/s).
    pub angvel: Vector,
    /// 1/mass (1/kg).
    pub inv_mass: f32,
    /// Inverse inertia tensor about the centre of mass in world axes (1/(kg·m²)).
    pub inv_inertia: Mat3,
}

impl Body {
    /// The chassis at velocities `linvel` (m/s, of the centre of mass) and `angvel` (rad/s),
    /// with inverse mass `inv_mass` (1/kg) and the inverse inertia tensor `inv_inertia` of the
    /// body frame (1/(kg·m²)), turned into world axes by the body's rotation `rotation`.
    pub fn new(
        linvel: Vector,
        angvel: Vector,
        inv_mass: f32,
        inv_inertia: Mat3,
        rotation: Rotation,
    ) -> Body {
        let r = Mat3::from_quat(rotation);
        Body {
            linvel,
            angvel,
            inv_mass,
            inv_inertia: r * inv_inertia * r.transpose(),
        }
    }

    /// Velocity (m/s) of the chassis point at `arm` (m) from the centre of mass.
    #[inline]
    pub fn velocity_at(&self, arm: Vector) -> Vector {
        self.linvel + self.angvel.cross(arm)
    }

    /// Applies `impulse` (N·s) at `arm` (m) from the centre of mass.
    #[inline]
    pub(super) fn apply(&mut self, arm: Vector, impulse: Vector) {
        self.linvel += impulse * self.inv_mass;
        self.angvel += self.inv_inertia * arm.cross(impulse);
    }

    /// `d1ᵀ·M⁻¹·d2` for a unit impulse along `d2` at `arm2` seen along `d1` at `arm1`: the
    /// inverse effective mass (1/kg) coupling two rows.
    #[inline]
    pub(super) fn coupling(&self, arm1: Vector, d1: Vector, arm2: Vector, d2: Vector) -> f32 {
        d1.dot(d2) * self.inv_mass + arm1.cross(d1).dot(self.inv_inertia * arm2.cross(d2))
    }
}
