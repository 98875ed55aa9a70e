//! nalgebra values built from [`ackermann::Real`] scalars.
//!
//! The crate's generic code is bounded by `ackermann::Real` only, as are its users
//! (`vehicle-model`, the firmware). nalgebra's rotation constructors, products and norms want
//! `T: RealField` instead, and adding that bound next to `Real` would make every `x.sin()`
//! ambiguous between the two traits. So the few values the layout needs are built here from
//! their closed forms with `Real` arithmetic; every consumer gets plain nalgebra types, and with
//! a concrete `f32` or `f64` all of nalgebra's operations apply.

use ackermann::Real;
use nalgebra::{Isometry3, Quaternion, Translation3, Unit, UnitQuaternion, UnitVector3, Vector3};

/// The unit vector +x (forward in the vehicle frame; the axle in a wheel's own frame).
#[inline]
pub(crate) fn x_axis<T: Real>() -> UnitVector3<T> {
    Unit::new_unchecked(Vector3::new(T::ONE, T::ZERO, T::ZERO))
}

/// The unit vector +y (left in the vehicle frame).
#[inline]
pub(crate) fn y_axis<T: Real>() -> UnitVector3<T> {
    Unit::new_unchecked(Vector3::new(T::ZERO, T::ONE, T::ZERO))
}

/// The unit vector +z (up).
#[inline]
pub(crate) fn z_axis<T: Real>() -> UnitVector3<T> {
    Unit::new_unchecked(Vector3::new(T::ZERO, T::ZERO, T::ONE))
}

/// The opposite unit vector.
#[inline]
pub(crate) fn flip<T: Real>(v: UnitVector3<T>) -> UnitVector3<T> {
    Unit::new_unchecked(-v.into_inner())
}

/// The rotation of `angle` (rad, right-handed) about the unit `axis`:
/// `w = cos(angle/2)`, `(x, y, z) = axis·sin(angle/2)`, as
/// [`UnitQuaternion::from_axis_angle`] computes it.
#[inline]
pub(crate) fn rotation<T: Real>(axis: &UnitVector3<T>, angle: T) -> UnitQuaternion<T> {
    let half = angle * T::HALF;
    let (s, c) = (half.sin(), half.cos());
    Unit::new_unchecked(Quaternion::new(c, axis.x * s, axis.y * s, axis.z * s))
}

/// The rigid transform that rotates by `rotation`, then translates by `translation` (m).
#[inline]
pub(crate) fn isometry<T: Real>(
    translation: Vector3<T>,
    rotation: UnitQuaternion<T>,
) -> Isometry3<T> {
    Isometry3 {
        rotation,
        translation: Translation3::from(translation),
    }
}

/// No rotation.
#[inline]
pub(crate) fn no_rotation<T: Real>() -> UnitQuaternion<T> {
    Unit::new_unchecked(Quaternion::new(T::ONE, T::ZERO, T::ZERO, T::ZERO))
}

/// The identity transform.
#[inline]
pub(crate) fn identity<T: Real>() -> Isometry3<T> {
    isometry(Vector3::new(T::ZERO, T::ZERO, T::ZERO), no_rotation())
}

/// The dot product `a·b`.
#[inline]
pub(crate) fn dot<T: Real>(a: &Vector3<T>, b: &Vector3<T>) -> T {
    a.x * b.x + a.y * b.y + a.z * b.z
}

/// The Euclidean length `|v|` (m for an offset).
#[inline]
pub(crate) fn norm<T: Real>(v: &Vector3<T>) -> T {
    dot(v, v).sqrt()
}

/// `v / |v|`, or `None` for a zero or non-finite vector.
#[inline]
pub(crate) fn normalize<T: Real>(v: Vector3<T>) -> Option<Vector3<T>> {
    let l = norm(&v);
    (l.is_finite() && l > T::ZERO).then(|| v * (T::ONE / l))
}

/// A vector's components in `f64`.
#[cfg(feature = "alloc")]
#[inline]
pub(crate) fn vector_f64<T: Real>(v: &Vector3<T>) -> Vector3<f64> {
    v.map(Real::to_f64)
}

/// A point's coordinates in `f64` (m).
#[cfg(feature = "alloc")]
#[inline]
pub(crate) fn point_f64<T: Real>(p: &nalgebra::Point3<T>) -> nalgebra::Point3<f64> {
    p.map(Real::to_f64)
}

/// A transform in `f64` (translation in m).
#[cfg(feature = "alloc")]
pub(crate) fn isometry_f64<T: Real>(t: &Isometry3<T>) -> Isometry3<f64> {
    let q = t.rotation.into_inner().coords.map(Real::to_f64);
    Isometry3 {
        // Re-normalised: an `f32` unit quaternion is unit only to `f32` precision.
        rotation: UnitQuaternion::from_quaternion(Quaternion::from(q)),
        translation: Translation3::from(vector_f64(&t.translation.vector)),
    }
}

/// Components converted to `f32` (rounding to nearest); an `f64` component beyond the `f32`
/// range saturates at ±`f32::MAX` instead of becoming ±∞.
#[cfg(feature = "alloc")]
pub(crate) fn to_f32(v: [f64; 3]) -> [f32; 3] {
    let limit = f64::from(f32::MAX);
    v.map(|c| c.clamp(-limit, limit) as f32)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn closed_forms_match_nalgebra() {
        let axis = Unit::new_normalize(Vector3::new(1.0, 1.0, 0.0_f64));
        let ours = rotation(&axis, 0.7);
        let theirs = UnitQuaternion::from_axis_angle(&axis, 0.7);
        assert!((ours.coords - theirs.coords).norm() < 1e-15);
        let q = rotation(&z_axis(), core::f64::consts::FRAC_PI_2);
        assert!((q * Vector3::x() - Vector3::y()).norm() < 1e-15);
        assert_eq!(identity::<f64>(), Isometry3::identity());
        assert_eq!(no_rotation::<f32>(), rotation(&z_axis(), 0.0));
        let v = Vector3::new(3.0, -4.0, 12.0);
        assert_eq!((dot(&v, &v), norm(&v)), (169.0, 13.0));
        assert_eq!(normalize(v), Some(v / 13.0));
        assert_eq!(normalize(Vector3::new(0.0, 0.0, 0.0)), None);
        assert_eq!(normalize(Vector3::new(f64::NAN, 0.0, 0.0)), None);
        assert_eq!(*flip(x_axis::<f32>()), Vector3::new(-1.0, 0.0, 0.0));
        assert_eq!(*y_axis::<f32>(), Vector3::y());
    }

    #[cfg(feature = "alloc")]
    #[test]
    fn conversions_round_and_saturate() {
        assert_eq!(to_f32([0.1, -2.5, 0.0]), [0.1_f32, -2.5, 0.0]);
        assert_eq!(
            to_f32([1e200, -1e39, 3.0e38]),
            [f32::MAX, -f32::MAX, 3.0e38]
        );
        let t = isometry(Vector3::new(1.5_f32, -2.0, 0.25), rotation(&z_axis(), 1.2));
        let d = isometry_f64(&t);
        assert_eq!(d.translation.vector, Vector3::new(1.5, -2.0, 0.25));
        assert!((d.rotation.angle() - 1.2).abs() < 1e-6);
        assert!((d.rotation.norm() - 1.0).abs() < 1e-15);
    }
}
