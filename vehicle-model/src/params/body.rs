//! The car body's mass properties (the `Physics` node of the Car robot).

use ackermann::Real;

/// Mass properties of the car body, without the wheels (Webots: the `physics Physics { … }`
/// node of the `Car`), in the car frame (x forward, y left, z up, origin at the rear-axle centre
/// at wheel-centre height).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BodyPhysics<T: Real> {
    /// Body mass (kg, > 0); Webots `Physics` field `mass`.
    pub mass: T,
    /// Centre of mass (m); Webots `Physics` field `centerOfMass`.
    pub center_of_mass: [T; 3],
    /// Inertia about the centre of mass `[Ixx, Iyy, Izz, Ixy, Ixz, Iyz]` (kg·m²); Webots
    /// `Physics` field `inertiaMatrix`. `None`: not given by the model; use
    /// [`BodyPhysics::inertia_or_derived`].
    pub inertia: Option<[T; 6]>,
}

/// Length of the body box of [`BodyPhysics::box_inertia`] per wheelbase (dimensionless): a
/// passenger car's wheelbase is about 60 % of its length.
pub const BODY_LENGTH_PER_WHEELBASE: f64 = 1.6;

/// Height of the body box of [`BodyPhysics::box_inertia`] per track (dimensionless).
pub const BODY_HEIGHT_PER_TRACK: f64 = 0.75;

impl<T: Real> BodyPhysics<T> {
    /// Inertia (kg·m², `[Ixx, Iyy, Izz, Ixy, Ixz, Iyz]`) of a uniform solid box of this mass,
    /// used for models whose PROTO gives none: length `1.6·wheelbase`
    /// ([`BODY_LENGTH_PER_WHEELBASE`]), width `track` and height `0.75·track`
    /// ([`BODY_HEIGHT_PER_TRACK`]), where `track` is the wider of the two tracks (m). Products
    /// of inertia are 0.
    ///
    /// `I = m/12·(w² + h², l² + h², l² + w²)`.
    pub fn box_inertia(mass: T, wheelbase: T, track: T) -> [T; 6] {
        let l = T::from_f64(BODY_LENGTH_PER_WHEELBASE) * wheelbase;
        let w = track;
        let h = T::from_f64(BODY_HEIGHT_PER_TRACK) * track;
        let k = mass / T::from_f64(12.0);
        [
            k * (w * w + h * h),
            k * (l * l + h * h),
            k * (l * l + w * w),
            T::ZERO,
            T::ZERO,
            T::ZERO,
        ]
    }

    /// The inertia a simulator should use (kg·m²): the given one, or
    /// [`BodyPhysics::box_inertia`] for `wheelbase` and `track` (m).
    pub fn inertia_or_derived(&self, wheelbase: T, track: T) -> [T; 6] {
        self.inertia
            .unwrap_or_else(|| Self::box_inertia(self.mass, wheelbase, track))
    }
}

/// True if `m = [Ixx, Iyy, Izz, Ixy, Ixz, Iyz]` (kg·m²) is a physical inertia tensor: finite,
/// positive definite (Sylvester's criterion) and with diagonal terms satisfying the triangle
/// inequality (`Ixx + Iyy ≥ Izz`, …), which every rigid body's tensor does in any frame.
pub fn is_physical_inertia<T: Real>(m: &[T; 6]) -> bool {
    let [xx, yy, zz, xy, xz, yz] = *m;
    if !m.iter().all(|v| v.is_finite()) {
        return false;
    }
    let minor2 = xx * yy - xy * xy;
    let det = xx * (yy * zz - yz * yz) - xy * (xy * zz - yz * xz) + xz * (xy * yz - yy * xz);
    xx > T::ZERO
        && minor2 > T::ZERO
        && det > T::ZERO
        && xx + yy >= zz
        && yy + zz >= xx
        && zz + xx >= yy
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn box_inertia_formula() {
        // m = 1200 kg, L = 2.5 m, track 1.6 m: l = 4, w = 1.6, h = 1.2;
        // Ixx = 100·(2.56 + 1.44) = 400, Iyy = 100·(16 + 1.44) = 1744, Izz = 100·(16 + 2.56) = 1856.
        let i = BodyPhysics::<f64>::box_inertia(1200.0, 2.5, 1.6);
        assert!((i[0] - 400.0).abs() < 1e-9);
        assert!((i[1] - 1744.0).abs() < 1e-9);
        assert!((i[2] - 1856.0).abs() < 1e-9);
        assert_eq!(&i[3..], &[0.0; 3]);
        assert!(is_physical_inertia(&i));
    }

    #[test]
    fn physical_inertia_checks() {
        assert!(is_physical_inertia(&[
            1125.07, 4473.54, 4346.1, 0.0, 846.89, 0.0_f64
        ]));
        assert!(!is_physical_inertia(&[1.0, 1.0, 3.0, 0.0, 0.0, 0.0_f64])); // triangle
        assert!(!is_physical_inertia(&[1.0, 1.0, 1.0, 2.0, 0.0, 0.0_f64])); // not definite
        assert!(!is_physical_inertia(&[-1.0, 1.0, 1.0, 0.0, 0.0, 0.0_f64]));
        assert!(!is_physical_inertia(&[f32::NAN, 1.0, 1.0, 0.0, 0.0, 0.0]));
    }
}
