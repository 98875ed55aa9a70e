//! The scalar type every no_std crate of the workspace is generic over.
//!
//! Firmware runs in `f32` (the Cortex-M4F FPU is single precision); the C API and Webots parity
//! work use `f64`. All transcendental functions go through [`libm`], never the platform's maths
//! library, so the host and the target compute bit-identical results for the same inputs; the
//! polynomial kernels for hot paths ([`Real::atan_unit`] and its variants, [`Real::atan_nonneg`],
//! [`Real::sin_quadrant`]) are pure arithmetic in a fixed order, bit-identical too.

mod poly;

use core::fmt::{Debug, Display};
use core::ops::{Add, AddAssign, Div, DivAssign, Mul, MulAssign, Neg, Rem, Sub, SubAssign};

/// A floating-point scalar: implemented for `f32` and `f64` only.
///
/// Constants are provided as associated constants; other literals are written with
/// [`Real::from_f64`], which the compiler folds to a constant.
pub trait Real:
    Copy
    + Default
    + Debug
    + Display
    + PartialEq
    + PartialOrd
    + Add<Output = Self>
    + Sub<Output = Self>
    + Mul<Output = Self>
    + Div<Output = Self>
    + Rem<Output = Self>
    + Neg<Output = Self>
    + AddAssign
    + SubAssign
    + MulAssign
    + DivAssign
    + Send
    + Sync
    + 'static
{
    /// 0.
    const ZERO: Self;
    /// 1.
    const ONE: Self;
    /// 2.
    const TWO: Self;
    /// 0.5.
    const HALF: Self;
    /// π.
    const PI: Self;
    /// π/2.
    const FRAC_PI_2: Self;
    /// 2π.
    const TAU: Self;
    /// Positive infinity.
    const INFINITY: Self;
    /// Machine epsilon.
    const EPSILON: Self;
    /// Largest finite value.
    const MAX: Self;

    /// Converts an `f64` (rounding to nearest for `f32`).
    fn from_f64(v: f64) -> Self;
    /// Converts to `f64` (exact for both types).
    fn to_f64(self) -> f64;
    /// Converts an `i32` (rounding to nearest for large values in `f32`).
    fn from_i32(v: i32) -> Self;

    /// Sine (rad).
    fn sin(self) -> Self;
    /// Cosine (rad).
    fn cos(self) -> Self;
    /// Tangent (rad).
    fn tan(self) -> Self;
    /// Arc tangent, in (−π/2, π/2) rad.
    fn atan(self) -> Self;
    /// Four-quadrant arc tangent of `self / x`, in (−π, π] rad.
    fn atan2(self, x: Self) -> Self;
    /// Arc sine, in [−π/2, π/2] rad (NaN outside [−1, 1]).
    fn asin(self) -> Self;
    /// Square root (NaN for negative input).
    fn sqrt(self) -> Self;
    /// `sqrt(self² + other²)` without undue overflow.
    fn hypot(self, other: Self) -> Self;
    /// Largest integer value not greater than `self`.
    fn floor(self) -> Self;
    /// Nearest integer value, halfway cases away from zero.
    fn round(self) -> Self;
    /// Integer part, rounding toward zero.
    fn trunc(self) -> Self;
    /// `self` raised to the power `n`.
    fn powi(self, n: i32) -> Self;
    /// `e^self`.
    fn exp(self) -> Self;
    /// `atan(self)` (rad) for `self` in [0, 1], by a polynomial without libm's argument
    /// reduction: within 1 ulp of [`Real::atan`] on [0, 1] (the tests of `real/poly.rs`), and
    /// bit-identical on every target. Meaningless outside [0, 1].
    fn atan_unit(self) -> Self;
    /// [`Real::atan_unit`] given `square`, `self²` formed by the caller (which may have it
    /// before `self`, so that the polynomial, in the square, need not wait for `self`). Within
    /// 1 ulp of [`Real::atan`] for `square = self·self`; a square off by a few ulp moves the
    /// result by less than `0.22·self` times its relative error.
    fn atan_unit_sq(self, square: Self) -> Self;
    /// `offset + scale·atan(self)` for `self` in [0, 1] given `square = self²`, as
    /// [`Real::atan_unit_sq`] with the affine map folded into the polynomial's last product
    /// and sum (one product and one sum follow the polynomial, not four operations). Its
    /// rounding differs from the map applied to [`Real::atan_unit_sq`]'s result.
    fn atan_unit_affine(self, square: Self, offset: Self, scale: Self) -> Self;
    /// `atan(self)` (rad) for `self ≥ 0`: [`Real::atan_unit`] up to 1; above, `π/2 − 1/x`
    /// plus `1/x` times a rational in `x²`, so the reciprocal and the rational's two
    /// polynomials start together, and only the rational's quotient follows them. Within 2 ulp
    /// of [`Real::atan`] (the tests of `real/poly.rs`), bit-identical on every target.
    /// Meaningless below 0.
    fn atan_nonneg(self) -> Self;
    /// `scale·atan(self)` (rad) for `self ≥ 0`, given `inv_scale = 1/scale`: as
    /// [`Real::atan_nonneg`] with the product by `scale` folded into the last operations (up
    /// to 1 into [`Real::atan_unit_affine`]'s; above, into the leading terms and the rational's
    /// denominator), so no product follows the kernel. Within 4 ulp of `scale` times
    /// [`Real::atan`] for `scale` in [1, 2] and `inv_scale` up to 2 ulp off `1/scale` (the tests
    /// of `real/poly.rs`). Meaningless below 0.
    fn atan_nonneg_scaled(self, scale: Self, inv_scale: Self) -> Self;
    /// `sin(self)` for `self` in [0, π/2], by a polynomial: within 2 ulp of [`Real::sin`] there,
    /// bit-identical on every target. Meaningless outside [0, π/2].
    fn sin_quadrant(self) -> Self;

    /// True for NaN.
    fn is_nan(self) -> bool;
    /// True unless NaN or ±∞.
    fn is_finite(self) -> bool;

    /// Absolute value.
    #[inline]
    fn abs(self) -> Self {
        if self < Self::ZERO { -self } else { self }
    }
    /// The smaller of the two; if one is NaN, the other.
    #[inline]
    fn min(self, other: Self) -> Self {
        if self.is_nan() || other < self {
            other
        } else {
            self
        }
    }
    /// The larger of the two; if one is NaN, the other.
    #[inline]
    fn max(self, other: Self) -> Self {
        if self.is_nan() || other > self {
            other
        } else {
            self
        }
    }
    /// `self` limited to `[lo, hi]`; NaN stays NaN. Requires `lo <= hi`.
    #[inline]
    fn clamp(self, lo: Self, hi: Self) -> Self {
        if self < lo {
            lo
        } else if self > hi {
            hi
        } else {
            self
        }
    }
    /// −1, 0 or +1 (0 for ±0 and NaN), unlike `f64::signum`.
    #[inline]
    fn sign(self) -> Self {
        if self > Self::ZERO {
            Self::ONE
        } else if self < Self::ZERO {
            -Self::ONE
        } else {
            Self::ZERO
        }
    }
    /// `self` if finite, `fallback` otherwise: the guard that keeps NaN and ∞ out of state.
    #[inline]
    fn finite_or(self, fallback: Self) -> Self {
        if self.is_finite() { self } else { fallback }
    }
}

macro_rules! impl_real {
    ($t:ty, $m:ident, sin = $sin:ident, cos = $cos:ident, tan = $tan:ident, atan = $atan:ident,
     atan2 = $atan2:ident, asin = $asin:ident, sqrt = $sqrt:ident, hypot = $hypot:ident,
     floor = $floor:ident, round = $round:ident, trunc = $trunc:ident, pow = $pow:ident,
     exp = $exp:ident, atan_unit = $atan_unit:ident, atan_unit_sq = $atan_unit_sq:ident, atan_unit_affine = $atan_unit_affine:ident, atan_nonneg = $atan_nonneg:ident, atan_nonneg_scaled = $atan_nonneg_scaled:ident, sin_quadrant = $sin_quadrant:ident) => {
        impl Real for $t {
            const ZERO: Self = 0.0;
            const ONE: Self = 1.0;
            const TWO: Self = 2.0;
            const HALF: Self = 0.5;
            const PI: Self = core::$m::consts::PI;
            const FRAC_PI_2: Self = core::$m::consts::FRAC_PI_2;
            const TAU: Self = core::$m::consts::TAU;
            const INFINITY: Self = <$t>::INFINITY;
            const EPSILON: Self = <$t>::EPSILON;
            const MAX: Self = <$t>::MAX;

            #[inline]
            fn from_f64(v: f64) -> Self {
                v as $t
            }
            #[inline]
            fn to_f64(self) -> f64 {
                f64::from(self)
            }
            #[inline]
            fn from_i32(v: i32) -> Self {
                v as $t
            }
            #[inline]
            fn sin(self) -> Self {
                libm::$sin(self)
            }
            #[inline]
            fn cos(self) -> Self {
                libm::$cos(self)
            }
            #[inline]
            fn tan(self) -> Self {
                libm::$tan(self)
            }
            #[inline]
            fn atan(self) -> Self {
                libm::$atan(self)
            }
            #[inline]
            fn atan2(self, x: Self) -> Self {
                libm::$atan2(self, x)
            }
            #[inline]
            fn asin(self) -> Self {
                libm::$asin(self)
            }
            #[inline]
            fn sqrt(self) -> Self {
                libm::$sqrt(self)
            }
            #[inline]
            fn hypot(self, other: Self) -> Self {
                libm::$hypot(self, other)
            }
            #[inline]
            fn floor(self) -> Self {
                libm::$floor(self)
            }
            #[inline]
            fn round(self) -> Self {
                libm::$round(self)
            }
            #[inline]
            fn trunc(self) -> Self {
                libm::$trunc(self)
            }
            #[inline]
            fn powi(self, n: i32) -> Self {
                libm::$pow(self, n as $t)
            }
            #[inline]
            fn exp(self) -> Self {
                libm::$exp(self)
            }
            #[inline]
            fn atan_unit(self) -> Self {
                poly::$atan_unit(self)
            }
            #[inline(always)]
            fn atan_unit_sq(self, square: Self) -> Self {
                poly::$atan_unit_sq(self, square)
            }
            #[inline(always)]
            fn atan_unit_affine(self, square: Self, offset: Self, scale: Self) -> Self {
                poly::$atan_unit_affine(self, square, offset, scale)
            }
            #[inline(always)]
            fn atan_nonneg(self) -> Self {
                poly::$atan_nonneg(self)
            }
            #[inline(always)]
            fn atan_nonneg_scaled(self, scale: Self, inv_scale: Self) -> Self {
                poly::$atan_nonneg_scaled(self, scale, inv_scale)
            }
            #[inline]
            fn sin_quadrant(self) -> Self {
                poly::$sin_quadrant(self)
            }
            #[inline]
            fn is_nan(self) -> bool {
                <$t>::is_nan(self)
            }
            #[inline]
            fn is_finite(self) -> bool {
                <$t>::is_finite(self)
            }
        }
    };
}

impl_real!(
    f32,
    f32,
    sin = sinf,
    cos = cosf,
    tan = tanf,
    atan = atanf,
    atan2 = atan2f,
    asin = asinf,
    sqrt = sqrtf,
    hypot = hypotf,
    floor = floorf,
    round = roundf,
    trunc = truncf,
    pow = powf,
    exp = expf,
    atan_unit = atan_unit_f32,
    atan_unit_sq = atan_unit_sq_f32,
    atan_unit_affine = atan_unit_affine_f32,
    atan_nonneg = atan_nonneg_f32,
    atan_nonneg_scaled = atan_nonneg_scaled_f32,
    sin_quadrant = sin_quadrant_f32
);
impl_real!(
    f64,
    f64,
    sin = sin,
    cos = cos,
    tan = tan,
    atan = atan,
    atan2 = atan2,
    asin = asin,
    sqrt = sqrt,
    hypot = hypot,
    floor = floor,
    round = round,
    trunc = trunc,
    pow = pow,
    exp = exp,
    atan_unit = atan_unit_f64,
    atan_unit_sq = atan_unit_sq_f64,
    atan_unit_affine = atan_unit_affine_f64,
    atan_nonneg = atan_nonneg_f64,
    atan_nonneg_scaled = atan_nonneg_scaled_f64,
    sin_quadrant = sin_quadrant_f64
);

#[cfg(test)]
mod tests {
    use super::Real;

    #[test]
    fn min_max_ignore_nan() {
        assert_eq!(Real::min(f64::NAN, 2.0), 2.0);
        assert_eq!(Real::min(2.0_f64, f64::NAN), 2.0);
        assert_eq!(Real::max(f32::NAN, -3.0), -3.0);
        assert_eq!(Real::max(1.0_f32, 4.0), 4.0);
    }

    #[test]
    fn sign_and_finite_or() {
        assert_eq!(Real::sign(-0.0_f64), 0.0);
        assert_eq!(Real::sign(-2.5_f32), -1.0);
        assert_eq!(Real::sign(f64::NAN), 0.0);
        assert_eq!(f64::INFINITY.finite_or(7.0), 7.0);
        assert_eq!(3.0_f32.finite_or(7.0), 3.0);
    }

    #[test]
    fn libm_backed_functions() {
        assert!((Real::tan(0.5_f64) - 0.546_302_489_843_790_5).abs() < 1e-15);
        assert!((Real::atan2(1.0_f32, -1.0) - 2.356_194_5).abs() < 1e-6);
        assert_eq!(Real::powi(3.0_f64, 3), 27.0);
        assert_eq!(<f32 as Real>::from_i32(-4), -4.0);
    }
}
