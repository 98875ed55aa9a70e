//! The wheel's bounding cylinder and the mass properties Webots derives from it.

use ackermann::Real;
use nalgebra::{UnitQuaternion, UnitVector3};

use super::params::WheelPhysics;
use super::validate::ValidWheel;
use crate::glue::{rotation, x_axis, y_axis};
use crate::mesh::CylinderMesh;

/// The collision shape of a wheel: a solid cylinder centred on the wheel centre whose axis is
/// the wheel's local x axis (the axle).
///
/// Webots: `boundingObject Transform { rotation 0 1 0 1.570796 children [ Cylinder { height
/// thickness radius tireRadius subdivision subdivision } ] }` — a z-axis `Cylinder` turned
/// onto x.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BoundingCylinder<T> {
    /// Radius (m), the wheel's `tireRadius`.
    pub radius: T,
    /// Length along the axle (m), the wheel's `thickness`.
    pub height: T,
    /// Segments around the axle (rendering only; physics engines use the exact cylinder).
    pub subdivision: u32,
}

impl<T: Real> BoundingCylinder<T> {
    /// The cylinder axis in the wheel frame (unit direction): +x.
    #[inline]
    pub fn axis(&self) -> UnitVector3<T> {
        x_axis()
    }

    /// The rotation Webots applies to its z-axis `Cylinder` (π/2 rad about +y, exact here where
    /// Webots writes 1.570796).
    #[inline]
    pub fn webots_rotation(&self) -> UnitQuaternion<T> {
        rotation(&y_axis(), T::FRAC_PI_2)
    }

    /// Volume `π·r²·h` (m³), saturated at `T::MAX` for dimensions whose volume `T` cannot
    /// represent (never ∞).
    #[inline]
    pub fn volume(&self) -> T {
        self.unsaturated_volume().min(T::MAX)
    }

    /// `π·r²·h` (m³), ∞ on overflow: the mass must see the overflow rather than a saturated
    /// volume that a density below 1 would turn back into a plausible-looking number.
    #[inline]
    fn unsaturated_volume(&self) -> T {
        T::PI * self.radius * self.radius * self.height
    }

    /// A triangle mesh of the cylinder (side and both caps), axis +x.
    #[inline]
    pub fn mesh(&self) -> CylinderMesh<T> {
        CylinderMesh::new(self.radius, self.height, self.subdivision)
    }
}

/// Mass and principal moments of inertia of a wheel, treated like Webots as a uniform solid
/// cylinder (its bounding object).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MassProperties<T> {
    /// Mass (kg).
    pub mass: T,
    /// Moment of inertia about the axle, `m·r²/2` (kg·m²).
    pub axial: T,
    /// Moment of inertia about any diameter through the centre, `m·(3r² + h²)/12` (kg·m²).
    pub transverse: T,
}

impl<T: Real> ValidWheel<T> {
    /// The collision cylinder, or `None` when `boundingObject` is `FALSE` (Webots then gives
    /// the wheel no bounding object, contact material or physics).
    pub fn bounding_cylinder(&self) -> Option<BoundingCylinder<T>> {
        let p = self.params();
        p.bounding_object.then(|| BoundingCylinder {
            radius: p.tire_radius,
            height: p.thickness,
            subdivision: self.subdivision(),
        })
    }

    /// The wheel's mass (kg): the `physics` mass, or density × bounding-cylinder volume
    /// (`Physics {}`: 1000 kg/m³ × π·0.4²·0.3 m³ ≈ 150.8 kg for the default wheel). `None`
    /// with `physics NULL` or `boundingObject FALSE`, and when density × volume overflows `T`
    /// (absurd dimensions, e.g. a 10²⁰ m tyre in `f32`): never ∞.
    pub fn mass(&self) -> Option<T> {
        let cylinder = self.bounding_cylinder()?;
        let mass = match self.params().physics {
            WheelPhysics::None => return None,
            WheelPhysics::Mass(m) => m,
            WheelPhysics::Density(d) => d * cylinder.unsaturated_volume(),
        };
        mass.is_finite().then_some(mass)
    }

    /// Mass (kg) and moments of inertia (kg·m²) of the uniform bounding cylinder, as Webots
    /// computes them when the `Physics` node has no `inertiaMatrix`. `None` when
    /// [`ValidWheel::mass`] is `None` or a moment of inertia is not representable in `T`
    /// (absurd dimensions): never NaN or ∞.
    pub fn mass_properties(&self) -> Option<MassProperties<T>> {
        let c = self.bounding_cylinder()?;
        let m = self.mass()?;
        let r2 = c.radius * c.radius;
        let props = MassProperties {
            mass: m,
            axial: m * r2 * T::HALF,
            transverse: m * (T::from_f64(3.0) * r2 + c.height * c.height) / T::from_f64(12.0),
        };
        (props.axial.is_finite() && props.transverse.is_finite()).then_some(props)
    }
}
