//! Minimal 3-D vector, rotation and rigid-transform types.
//!
//! Kept here instead of pulling a linear-algebra crate into the no_std layer: the crate needs
//! only points, unit quaternions and their composition. Every type converts to and from plain
//! arrays so callers can hand them to nalgebra, glam or rapier.

use core::ops::{Add, AddAssign, Mul, Neg, Sub};

use ackermann::Real;

/// A 3-D vector or point (components in m for positions, dimensionless for directions).
///
/// In the vehicle frame: x forward, y left, z up, origin at the rear-axle centre at wheel-centre
/// height.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Vec3<T> {
    /// x component.
    pub x: T,
    /// y component.
    pub y: T,
    /// z component.
    pub z: T,
}

impl<T: Real> Vec3<T> {
    /// The zero vector.
    pub const ZERO: Self = Vec3 {
        x: T::ZERO,
        y: T::ZERO,
        z: T::ZERO,
    };
    /// Unit vector +x (forward in the vehicle frame; the axle in a wheel's own frame).
    pub const X: Self = Vec3 {
        x: T::ONE,
        y: T::ZERO,
        z: T::ZERO,
    };
    /// Unit vector +y (left in the vehicle frame).
    pub const Y: Self = Vec3 {
        x: T::ZERO,
        y: T::ONE,
        z: T::ZERO,
    };
    /// Unit vector +z (up).
    pub const Z: Self = Vec3 {
        x: T::ZERO,
        y: T::ZERO,
        z: T::ONE,
    };

    /// Builds from the three components.
    #[inline]
    pub const fn new(x: T, y: T, z: T) -> Self {
        Vec3 { x, y, z }
    }

    /// Builds from `[x, y, z]`.
    #[inline]
    pub const fn from_array(a: [T; 3]) -> Self {
        Vec3 {
            x: a[0],
            y: a[1],
            z: a[2],
        }
    }

    /// The components as `[x, y, z]`.
    #[inline]
    pub const fn to_array(self) -> [T; 3] {
        [self.x, self.y, self.z]
    }

    /// Dot product.
    #[inline]
    pub fn dot(self, o: Self) -> T {
        self.x * o.x + self.y * o.y + self.z * o.z
    }

    /// Cross product `self × o` (right-handed).
    #[inline]
    pub fn cross(self, o: Self) -> Self {
        Vec3 {
            x: self.y * o.z - self.z * o.y,
            y: self.z * o.x - self.x * o.z,
            z: self.x * o.y - self.y * o.x,
        }
    }

    /// Euclidean length.
    #[inline]
    pub fn length(self) -> T {
        self.dot(self).sqrt()
    }

    /// The unit vector in the same direction, or `None` for a zero or non-finite vector.
    #[inline]
    pub fn normalized(self) -> Option<Self> {
        let l = self.length();
        if l.is_finite() && l > T::ZERO {
            Some(self * (T::ONE / l))
        } else {
            None
        }
    }

    /// True if every component is finite.
    #[inline]
    pub fn is_finite(self) -> bool {
        self.x.is_finite() && self.y.is_finite() && self.z.is_finite()
    }

    /// Converts the components to `f32` (rounding to nearest); an `f64` component beyond the
    /// `f32` range saturates at ±`f32::MAX` instead of becoming ±∞.
    #[inline]
    pub fn to_f32(self) -> [f32; 3] {
        let limit = f64::from(f32::MAX);
        [self.x, self.y, self.z].map(|c| c.to_f64().clamp(-limit, limit) as f32)
    }
}

impl<T: Real> Add for Vec3<T> {
    type Output = Self;
    #[inline]
    fn add(self, o: Self) -> Self {
        Vec3::new(self.x + o.x, self.y + o.y, self.z + o.z)
    }
}

impl<T: Real> AddAssign for Vec3<T> {
    #[inline]
    fn add_assign(&mut self, o: Self) {
        *self = *self + o;
    }
}

impl<T: Real> Sub for Vec3<T> {
    type Output = Self;
    #[inline]
    fn sub(self, o: Self) -> Self {
        Vec3::new(self.x - o.x, self.y - o.y, self.z - o.z)
    }
}

impl<T: Real> Neg for Vec3<T> {
    type Output = Self;
    #[inline]
    fn neg(self) -> Self {
        Vec3::new(-self.x, -self.y, -self.z)
    }
}

impl<T: Real> Mul<T> for Vec3<T> {
    type Output = Self;
    #[inline]
    fn mul(self, k: T) -> Self {
        Vec3::new(self.x * k, self.y * k, self.z * k)
    }
}

impl<T> From<[T; 3]> for Vec3<T> {
    #[inline]
    fn from(a: [T; 3]) -> Self {
        let [x, y, z] = a;
        Vec3 { x, y, z }
    }
}

impl<T> From<Vec3<T>> for [T; 3] {
    #[inline]
    fn from(v: Vec3<T>) -> Self {
        [v.x, v.y, v.z]
    }
}

/// A rotation, stored as a unit quaternion `w + xi + yj + zk`.
///
/// Webots writes rotations as axis–angle (`rotation 0 0 1 1.5708`); [`Rotation::from_axis_angle`]
/// and [`Rotation::axis_angle`] convert both ways.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Rotation<T> {
    w: T,
    x: T,
    y: T,
    z: T,
}

impl<T: Real> Default for Rotation<T> {
    fn default() -> Self {
        Self::IDENTITY
    }
}

impl<T: Real> Rotation<T> {
    /// No rotation.
    pub const IDENTITY: Self = Rotation {
        w: T::ONE,
        x: T::ZERO,
        y: T::ZERO,
        z: T::ZERO,
    };

    /// Rotation of `angle` (rad, right-handed) about `axis` (any length).
    ///
    /// A zero or non-finite axis, or a non-finite angle, gives the identity: a rotation about
    /// nothing is no rotation, and nothing non-finite enters the result.
    pub fn from_axis_angle(axis: Vec3<T>, angle: T) -> Self {
        match axis.normalized() {
            Some(a) if angle.is_finite() => {
                let half = angle * T::HALF;
                let s = half.sin();
                Rotation {
                    w: half.cos(),
                    x: a.x * s,
                    y: a.y * s,
                    z: a.z * s,
                }
            }
            _ => Self::IDENTITY,
        }
    }

    /// Rotation of `angle` (rad) about +z (a positive angle turns +x towards +y, i.e. left).
    #[inline]
    pub fn about_z(angle: T) -> Self {
        Self::from_axis_angle(Vec3::Z, angle)
    }

    /// The quaternion as `[x, y, z, w]` (the glTF and glam order).
    #[inline]
    pub const fn to_xyzw(self) -> [T; 4] {
        [self.x, self.y, self.z, self.w]
    }

    /// Builds from a quaternion `[x, y, z, w]`, normalising it; a zero or non-finite quaternion
    /// gives the identity.
    pub fn from_xyzw(q: [T; 4]) -> Self {
        let [x, y, z, w] = q;
        let n = (x * x + y * y + z * z + w * w).sqrt();
        if n.is_finite() && n > T::ZERO {
            let k = T::ONE / n;
            Rotation {
                w: w * k,
                x: x * k,
                y: y * k,
                z: z * k,
            }
        } else {
            Self::IDENTITY
        }
    }

    /// The rotation as a unit axis and an angle in [0, π] rad (axis +x for the identity).
    pub fn axis_angle(self) -> (Vec3<T>, T) {
        // Pick the hemisphere with w ≥ 0 so the angle is at most π.
        let (w, v) = if self.w < T::ZERO {
            (-self.w, Vec3::new(-self.x, -self.y, -self.z))
        } else {
            (self.w, Vec3::new(self.x, self.y, self.z))
        };
        let s = v.length();
        match v.normalized() {
            Some(axis) => (axis, T::TWO * s.atan2(w)),
            None => (Vec3::X, T::ZERO),
        }
    }

    /// Applies the rotation to a vector.
    pub fn rotate(self, v: Vec3<T>) -> Vec3<T> {
        // v' = v + 2w (q × v) + 2 q × (q × v), q the vector part.
        let q = Vec3::new(self.x, self.y, self.z);
        let t = q.cross(v) * T::TWO;
        v + t * self.w + q.cross(t)
    }

    /// The inverse rotation.
    #[inline]
    pub fn inverse(self) -> Self {
        Rotation {
            w: self.w,
            x: -self.x,
            y: -self.y,
            z: -self.z,
        }
    }

    /// The rotation matrix, row-major (`m[row][column]`).
    pub fn to_matrix(self) -> [[T; 3]; 3] {
        let c0 = self.rotate(Vec3::X);
        let c1 = self.rotate(Vec3::Y);
        let c2 = self.rotate(Vec3::Z);
        [[c0.x, c1.x, c2.x], [c0.y, c1.y, c2.y], [c0.z, c1.z, c2.z]]
    }
}

impl<T: Real> Mul for Rotation<T> {
    type Output = Self;
    /// `a * b` applies `b` first, then `a`.
    fn mul(self, o: Self) -> Self {
        let (a, b) = (self, o);
        Rotation {
            w: a.w * b.w - a.x * b.x - a.y * b.y - a.z * b.z,
            x: a.w * b.x + a.x * b.w + a.y * b.z - a.z * b.y,
            y: a.w * b.y - a.x * b.z + a.y * b.w + a.z * b.x,
            z: a.w * b.z + a.x * b.y - a.y * b.x + a.z * b.w,
        }
    }
}

/// A rigid transform: rotate, then translate (Webots `Transform`/`Pose` with `translation` in m
/// and `rotation`).
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub struct Isometry<T: Real> {
    /// Translation (m), applied after the rotation.
    pub translation: Vec3<T>,
    /// Rotation, applied first.
    pub rotation: Rotation<T>,
}

impl<T: Real> Isometry<T> {
    /// The identity transform.
    pub const IDENTITY: Self = Isometry {
        translation: Vec3::ZERO,
        rotation: Rotation::IDENTITY,
    };

    /// Builds from a translation (m) and a rotation.
    #[inline]
    pub const fn new(translation: Vec3<T>, rotation: Rotation<T>) -> Self {
        Isometry {
            translation,
            rotation,
        }
    }

    /// A pure translation (m).
    #[inline]
    pub const fn from_translation(translation: Vec3<T>) -> Self {
        Isometry {
            translation,
            rotation: Rotation::IDENTITY,
        }
    }

    /// Maps a point (m) from the local frame to the parent frame.
    #[inline]
    pub fn transform_point(&self, p: Vec3<T>) -> Vec3<T> {
        self.rotation.rotate(p) + self.translation
    }

    /// Maps a direction from the local frame to the parent frame (no translation).
    #[inline]
    pub fn transform_vector(&self, v: Vec3<T>) -> Vec3<T> {
        self.rotation.rotate(v)
    }

    /// The inverse transform.
    pub fn inverse(&self) -> Self {
        let r = self.rotation.inverse();
        Isometry {
            translation: -r.rotate(self.translation),
            rotation: r,
        }
    }
}

impl<T: Real> Mul for Isometry<T> {
    type Output = Self;
    /// `a * b` maps from `b`'s local frame through `b` then `a` (b is nested inside a).
    fn mul(self, o: Self) -> Self {
        Isometry {
            translation: self.transform_point(o.translation),
            rotation: self.rotation * o.rotation,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn close(a: Vec3<f64>, b: Vec3<f64>) -> bool {
        (a - b).length() < 1e-12
    }

    #[test]
    fn to_f32_rounds_and_saturates() {
        assert_eq!(Vec3::new(0.1_f64, -2.5, 0.0).to_f32(), [0.1_f32, -2.5, 0.0]);
        assert_eq!(
            Vec3::new(1e200_f64, -1e39, 3.0e38).to_f32(),
            [f32::MAX, -f32::MAX, 3.0e38]
        );
    }

    #[test]
    fn quarter_turn_about_z_maps_x_to_y() {
        let r = Rotation::about_z(core::f64::consts::FRAC_PI_2);
        assert!(close(r.rotate(Vec3::X), Vec3::Y));
        assert!(close(r.rotate(Vec3::Y), -Vec3::X));
        let (axis, angle) = r.axis_angle();
        assert!(close(axis, Vec3::Z));
        assert!((angle - core::f64::consts::FRAC_PI_2).abs() < 1e-12);
    }

    #[test]
    fn composition_and_inverse() {
        let a = Isometry::new(
            Vec3::new(1.0, 2.0, 3.0),
            Rotation::from_axis_angle(Vec3::new(1.0, 1.0, 0.0), 0.7),
        );
        let b = Isometry::new(Vec3::new(-0.5, 0.25, 2.0), Rotation::about_z(-1.2));
        let p = Vec3::new(0.3, -0.9, 1.7);
        assert!(close(
            (a * b).transform_point(p),
            a.transform_point(b.transform_point(p))
        ));
        assert!(close(a.inverse().transform_point(a.transform_point(p)), p));
    }

    #[test]
    fn degenerate_axis_is_identity() {
        let r = Rotation::<f32>::from_axis_angle(Vec3::ZERO, 1.0);
        assert_eq!(r, Rotation::IDENTITY);
        let r = Rotation::<f64>::from_axis_angle(Vec3::X, f64::NAN);
        assert_eq!(r, Rotation::IDENTITY);
    }

    #[test]
    fn matrix_columns_are_rotated_axes() {
        let r = Rotation::about_z(core::f64::consts::FRAC_PI_2);
        let m = r.to_matrix();
        // Column 0 = R·x = +y.
        assert!((m[1][0] - 1.0).abs() < 1e-12 && m[0][0].abs() < 1e-12);
    }
}
