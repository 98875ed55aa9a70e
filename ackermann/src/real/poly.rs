//! Polynomial arc tangent and sine on reduced ranges, and a rational arc tangent above 1, for the
//! hot paths that cannot afford libm's argument reduction (the tyre curve).
//!
//! Pure `+` and `×` (and the rational's divisions, correctly rounded everywhere) in a fixed
//! order (Rust never contracts them into fused operations), so every target computes the same
//! bits, like the rest of [`super::Real`]. The coefficients were fitted for this crate: the
//! polynomials near-minimax, by least squares on Chebyshev points in 50-digit arithmetic, each
//! coefficient rounded to the type before the later ones were refitted to that rounding; the
//! rationals by linearised least squares (the denominator of the previous pass as weight,
//! reweighted toward minimax), rounded once. The tests below bound the whole evaluation,
//! rounding included, against libm.

mod tables;

use super::Real;
use tables::{
    ATAN_F32, ATAN_HI_F64, ATAN_LO_F64, ATAN_REV_P_F32, ATAN_REV_P_F64, ATAN_REV_Q_F32,
    ATAN_REV_Q_F64, SIN_F32, SIN_F64,
};

// `c[0] + c[1]·x + … + c[N−1]·x^(N−1)` by Estrin's scheme: neighbouring coefficients paired
// with `x`, the pairs paired with `x²`, and so on. That is ⌈log₂ N⌉ dependent multiply–adds
// instead of Horner's `N − 1`, and the out-of-order core evaluates each level's terms at once.
// Written out per length: a loop over the levels is not unrolled by the compiler, and its
// stores and loads serialise the levels.

#[inline(always)]
fn pair<T: Real>(c: &[T], x: T) -> T {
    c[0] + c[1] * x
}

#[inline(always)]
fn estrin3<T: Real>(x: T, c: &[T; 3]) -> T {
    pair(&c[0..2], x) + c[2] * (x * x)
}

#[inline(always)]
fn estrin6<T: Real>(x: T, c: &[T; 6]) -> T {
    let x2 = x * x;
    (pair(&c[0..2], x) + pair(&c[2..4], x) * x2) + pair(&c[4..6], x) * (x2 * x2)
}

#[inline(always)]
fn estrin9<T: Real>(x: T, c: &[T; 9]) -> T {
    let x2 = x * x;
    let x4 = x2 * x2;
    let q0 = pair(&c[0..2], x) + pair(&c[2..4], x) * x2;
    let q1 = pair(&c[4..6], x) + pair(&c[6..8], x) * x2;
    (q0 + q1 * x4) + c[8] * (x4 * x4)
}

/// `R = Σ (c[2i] + c[2i+1]·z)·s^(2i)` by Estrin's scheme with pairs in `z` and powers of `s`
/// (the bases of [`tables::ATAN_LO_F64`]), as the last level's halves: `R = low + high·s⁸`,
/// returned as `(low, high, s⁸)` so that the caller folds its own product into that level.
#[inline(always)]
fn estrin16_halves<T: Real>(z: T, s: T, c: &[T; 16]) -> (T, T, T) {
    let s2 = s * s;
    let s4 = s2 * s2;
    let q = |i: usize| pair(&c[i..i + 2], z) + pair(&c[i + 2..i + 4], z) * s2;
    (q(0) + q(4) * s4, q(8) + q(12) * s4, s4 * s4)
}

/// `s·(c[0] + c[1]·x + … + c[3]·x³)` by Estrin's scheme, `s` folded into its first level:
/// `s·low + high·(s·x²)`, no longer than the polynomial alone when `s` is known with `x`.
#[inline(always)]
fn estrin4_times<T: Real>(x: T, c: &[T; 4], s: T) -> T {
    s * pair(&c[0..2], x) + pair(&c[2..4], x) * (s * (x * x))
}

/// `s·(c[0] + c[1]·x + … + c[6]·x⁶)` by Estrin's scheme, `s` folded into its first level:
/// `(s·low + c₂₃·(s·x²)) + high·(s·x⁴)`, no longer than the polynomial alone when `s` is known
/// with `x`.
#[inline(always)]
fn estrin7_times<T: Real>(x: T, c: &[T; 7], s: T) -> T {
    let x2 = x * x;
    let sx2 = s * x2;
    let low = s * pair(&c[0..2], x) + pair(&c[2..4], x) * sx2;
    let high = pair(&c[4..6], x) + c[6] * x2;
    low + high * (sx2 * x2)
}

/// `x²` at most `limit`, for the reversed rational: `P̃/Q̃ ≈ 1/(3·x²)` adds less than
/// `2⁻⁶⁴/x` to the arc tangent above the limit, far below the last bit of `π/2`, and the
/// limit keeps `Q̃` finite (and `∞` out of it).
#[inline(always)]
fn square_at_most<T: Real>(x: T, limit: T) -> T {
    let z = x * x;
    if z < limit { z } else { limit }
}

/// `scale·atan(x)` for `x > 1`, `f64`, given `inv_scale = 1/scale` (to a few ulp: it scales
/// only the rational term, below a third of the result), as
/// `scale·(π/2 − 1/x) + P̃/((x/scale)·Q̃)` (`x²` at most 2⁶⁴): [`ATAN_REV_P_F64`]'s
/// `(1/x)·P̃/Q̃` with the product by `scale` moved into the denominator. The reciprocal `1/x`
/// is formed alongside the two polynomials and `x/scale` is folded into `Q̃`'s first level, so
/// only the quotient and one sum follow the polynomials (the previous form divided, then
/// multiplied by `1/x`, then added, then multiplied by `scale`).
#[inline(always)]
fn atan_above_one_f64(x: f64, scale: f64, inv_scale: f64) -> f64 {
    let inv = 1.0 / x;
    let z = square_at_most(x, 4_294_967_296.0 * 4_294_967_296.0);
    let ratio = estrin6(z, &ATAN_REV_P_F64) / estrin7_times(z, &ATAN_REV_Q_F64, x * inv_scale);
    scale * (core::f64::consts::FRAC_PI_2 - inv) + ratio
}

/// As [`atan_above_one_f64`], `f32` (`x²` at most 2²⁴).
#[inline(always)]
fn atan_above_one_f32(x: f32, scale: f32, inv_scale: f32) -> f32 {
    let inv = 1.0 / x;
    let z = square_at_most(x, 16_777_216.0);
    let ratio = estrin3(z, &ATAN_REV_P_F32) / estrin4_times(z, &ATAN_REV_Q_F32, x * inv_scale);
    scale * (core::f32::consts::FRAC_PI_2 - inv) + ratio
}

/// `atan(x)` for `x ≥ 0`, `f64`: [`atan_unit_f64`] up to 1, [`atan_above_one_f64`] above.
#[inline(always)]
pub(super) fn atan_nonneg_f64(x: f64) -> f64 {
    if x > 1.0 {
        atan_above_one_f64(x, 1.0, 1.0)
    } else {
        atan_unit_f64(x)
    }
}

/// `atan(x)` for `x ≥ 0`, `f32`: as [`atan_nonneg_f64`].
#[inline(always)]
pub(super) fn atan_nonneg_f32(x: f32) -> f32 {
    if x > 1.0 {
        atan_above_one_f32(x, 1.0, 1.0)
    } else {
        atan_unit_f32(x)
    }
}

/// `scale·atan(x)` for `x ≥ 0`, `f64`, given `inv_scale = 1/scale`: [`atan_unit_affine_f64`]
/// (offset 0) up to 1, [`atan_above_one_f64`] above.
#[inline(always)]
pub(super) fn atan_nonneg_scaled_f64(x: f64, scale: f64, inv_scale: f64) -> f64 {
    if x > 1.0 {
        atan_above_one_f64(x, scale, inv_scale)
    } else {
        atan_unit_affine_f64(x, x * x, 0.0, scale)
    }
}

/// As [`atan_nonneg_scaled_f64`], `f32`.
#[inline(always)]
pub(super) fn atan_nonneg_scaled_f32(x: f32, scale: f32, inv_scale: f32) -> f32 {
    if x > 1.0 {
        atan_above_one_f32(x, scale, inv_scale)
    } else {
        atan_unit_affine_f32(x, x * x, 0.0, scale)
    }
}

/// `R` of `atan(x) = x − x³·R` for `x` in [0, 1], `f64`, given `z = x²`, as [`estrin16_halves`]
/// of the half of [0, 1] that `z` lies in.
#[inline(always)]
fn atan_r_f64(z: f64) -> (f64, f64, f64) {
    if z < 0.5 {
        estrin16_halves(z, z - 0.25, &ATAN_LO_F64)
    } else {
        estrin16_halves(z, z - 0.75, &ATAN_HI_F64)
    }
}

/// `atan(x)` for `x` in [0, 1], `f64`, given `z = x²`: `x − ((x·z)·low + (x·z·s⁸)·high)`, the
/// product by `x·z` folded into the polynomial's last level (its two products run at once).
#[inline(always)]
pub(super) fn atan_unit_sq_f64(x: f64, z: f64) -> f64 {
    let (low, high, s8) = atan_r_f64(z);
    let xz = x * z;
    x - (xz * low + (xz * s8) * high)
}

/// `atan(x)` for `x` in [0, 1], `f32`, given `z = x²`.
#[inline(always)]
pub(super) fn atan_unit_sq_f32(x: f32, z: f32) -> f32 {
    x - x * z * estrin9(z - 0.5, &ATAN_F32)
}

/// `offset + scale·atan(x)` for `x` in [0, 1], `f64`, given `z = x²`: `(offset + scale·x) −
/// ((scale·x·z)·low + (scale·x·z·s⁸)·high)`, so that the map adds no step after the polynomial.
#[inline(always)]
pub(super) fn atan_unit_affine_f64(x: f64, z: f64, offset: f64, scale: f64) -> f64 {
    let (low, high, s8) = atan_r_f64(z);
    let sx = scale * x;
    let sxz = sx * z;
    (offset + sx) - (sxz * low + (sxz * s8) * high)
}

/// As [`atan_unit_affine_f64`], `f32`.
#[inline(always)]
pub(super) fn atan_unit_affine_f32(x: f32, z: f32, offset: f32, scale: f32) -> f32 {
    let sx = scale * x;
    (offset + sx) - (sx * z) * estrin9(z - 0.5, &ATAN_F32)
}

/// `atan(x)` for `x` in [0, 1], `f64`.
#[inline]
pub(super) fn atan_unit_f64(x: f64) -> f64 {
    atan_unit_sq_f64(x, x * x)
}

/// `atan(x)` for `x` in [0, 1], `f32`.
#[inline]
pub(super) fn atan_unit_f32(x: f32) -> f32 {
    atan_unit_sq_f32(x, x * x)
}

/// `sin(x)` for `x` in [0, π/2], `f64`: `x + x³·Q(x²)` with the product by `x·z` folded into
/// the polynomial's last level, `x + ((x·z)·Q_low + (x·z·z⁴)·Q_high)`, so that it adds no step
/// after it (the small terms are summed first: one rounding of the leading term's size).
#[inline]
pub(super) fn sin_quadrant_f64(x: f64) -> f64 {
    let z = x * x;
    let z2 = z * z;
    let low = pair(&SIN_F64[0..2], z) + pair(&SIN_F64[2..4], z) * z2;
    let high = pair(&SIN_F64[4..6], z) + pair(&SIN_F64[6..8], z) * z2;
    let xz = x * z;
    x + (xz * low + (xz * (z2 * z2)) * high)
}

/// `sin(x)` for `x` in [0, π/2], `f32`: as [`sin_quadrant_f64`],
/// `x + ((x·z)·Q_low + (x·z·z²)·Q_high)`.
#[inline]
pub(super) fn sin_quadrant_f32(x: f32) -> f32 {
    let z = x * x;
    let xz = x * z;
    x + (xz * pair(&SIN_F32[0..2], z) + (xz * (z * z)) * pair(&SIN_F32[2..4], z))
}

#[cfg(test)]
mod tests {
    use super::super::Real;

    /// Distance in units in the last place between two non-negative finite values.
    fn ulps64(a: f64, b: f64) -> u64 {
        a.to_bits().abs_diff(b.to_bits())
    }

    fn ulps32(a: f32, b: f32) -> u32 {
        a.to_bits().abs_diff(b.to_bits())
    }

    // The argument sweeps: every 2⁻²⁰ of the range, plus a stride through the bit patterns
    // that visits every binade down to the subnormals (f32: every 211th value). libm's `atan`
    // and `sin` are themselves within 1 ulp of the truth.

    #[test]
    fn atan_unit_f64_within_1_ulp_of_libm() {
        let mut worst = (0, 0.0);
        let dense = (0..=1u64 << 20).map(|i| i as f64 / (1u64 << 20) as f64);
        let binades = (0..1_000_000u64).map(|i| f64::from_bits(i * (1.0f64.to_bits() / 1_000_000)));
        for x in dense.chain(binades) {
            let d = ulps64(x.atan_unit(), libm::atan(x));
            if d > worst.0 {
                worst = (d, x);
            }
        }
        assert!(worst.0 <= 1, "{worst:?}");
    }

    #[test]
    fn atan_unit_f32_within_1_ulp_of_libm() {
        let mut worst = (0, 0.0);
        for bits in (0..=1.0f32.to_bits()).step_by(211) {
            let x = f32::from_bits(bits);
            let d = ulps32(x.atan_unit(), libm::atanf(x));
            if d > worst.0 {
                worst = (d, x);
            }
        }
        assert!(worst.0 <= 1, "{worst:?}");
    }

    /// `offset + scale·atan(x)` against the same map of libm's `atan` (rounded once more): with
    /// offset 0 and scale 1 it is `atan_unit` to the bit; otherwise the sum `offset + scale·x`
    /// and the product `scale·x` add a rounding each (and the f64 reference its own), so the
    /// error is bounded in units of `ε·(|offset| + |scale|·x)`: three half-ulp roundings and the
    /// polynomial's part of an ulp make 1.5; measured 0.98 in f64, 0.87 in f32.
    #[test]
    fn atan_unit_affine_is_the_affine_map() {
        let maps = [
            (0.0, 1.0),
            (0.0, -0.5),
            (2.5, -10.0),
            (16.5, 0.7),
            (-3.0, 0.97),
        ];
        let (mut worst, mut worst32): (f64, f64) = (0.0, 0.0);
        for i in 0..=1u32 << 16 {
            let x = f64::from(i) / f64::from(1u32 << 16);
            for (offset, scale) in maps {
                let a = x.atan_unit_affine(x * x, offset, scale);
                if (offset, scale) == (0.0, 1.0) {
                    assert_eq!(a, x.atan_unit(), "{x}");
                }
                let unit = f64::EPSILON * (f64::abs(offset) + f64::abs(scale) * x);
                let reference = offset + scale * libm::atan(x);
                worst = worst.max((a - reference).abs() / unit.max(f64::MIN_POSITIVE));
                let (x32, o32, s32) = (x as f32, offset as f32, scale as f32);
                let a32 = x32.atan_unit_affine(x32 * x32, o32, s32);
                let unit32 = f64::from(f32::EPSILON) * f64::from(o32.abs() + s32.abs() * x32);
                let reference32 = f64::from(o32) + f64::from(s32) * libm::atan(f64::from(x32));
                worst32 = worst32.max((f64::from(a32) - reference32).abs() / unit32.max(1e-300));
            }
        }
        assert!(worst <= 1.5 && worst32 <= 1.5, "{worst} {worst32}");
    }

    // Above 1: every 2⁻²⁰ of 1/x on (0, 1) (x from 1 to 2²⁰), plus a stride through the bit
    // patterns from 1 to 2⁶⁴ and beyond the limit of x² (f32: every 211th value up to 2²⁴).
    // Up to 1 the kernel is `atan_unit`, tested above.

    #[test]
    fn atan_nonneg_f64_within_2_ulp_of_libm() {
        let mut worst = (0, 0.0);
        let dense = (1..1u64 << 20).map(|i| (1u64 << 20) as f64 / i as f64);
        let (lo, hi) = (1.0f64.to_bits(), 1e40f64.to_bits());
        let binades = (0..=1_000_000u64).map(|i| f64::from_bits(lo + i * ((hi - lo) / 1_000_000)));
        for x in dense.chain(binades).chain([1.0, f64::MAX, f64::INFINITY]) {
            let d = ulps64(x.atan_nonneg(), libm::atan(x));
            if d > worst.0 {
                worst = (d, x);
            }
        }
        assert!(worst.0 <= 2, "{worst:?}");
    }

    #[test]
    fn atan_nonneg_f32_within_2_ulp_of_libm() {
        let mut worst = (0, 0.0);
        let top = 16_777_216.0f32.to_bits();
        let bits = (1.0f32.to_bits()..=top).step_by(211);
        for x in bits
            .map(f32::from_bits)
            .chain([1e30, f32::MAX, f32::INFINITY])
        {
            let d = ulps32(x.atan_nonneg(), libm::atanf(x));
            if d > worst.0 {
                worst = (d, x);
            }
        }
        assert!(worst.0 <= 2, "{worst:?}");
    }

    /// `scale·atan(x)` for the shape factors of the tyre curve, against the product of libm's
    /// arc tangent and the scale (in f64 the reference rounds once more; in f32 the product is
    /// formed in f64 from libm's f64 `atan` and rounded once). Above 1 the kernel adds the
    /// product by `scale` (half an ulp) and, near 1, where the rational term is a quarter of the
    /// result, that term's error: 3 ulp in both types with `inv_scale = 1/scale` rounded; with
    /// `inv_scale` 2 ulp off, as the tyre passes it (a few ulp from `1/C`), measured 4 in f64,
    /// 3 in f32.
    #[test]
    fn atan_nonneg_scaled_within_4_ulp_of_scaled_libm() {
        let (mut worst, mut worst32) = ((0, 0.0, 0.0), (0, 0.0, 0.0));
        // [0, 2) every 2⁻¹⁶, 1/x every 2⁻¹⁶ above 1, and a stride through the bit patterns from
        // 1 to 1e40.
        let (lo, hi) = (1.0f64.to_bits(), 1e40f64.to_bits());
        let xs = || {
            let dense = (0..1u64 << 17).map(|i| i as f64 / (1u64 << 16) as f64);
            let inverse = (1..1u64 << 16).map(|i| (1u64 << 16) as f64 / i as f64);
            let binades =
                (0..=100_000u64).map(move |i| f64::from_bits(lo + i * ((hi - lo) / 100_000)));
            dense.chain(inverse).chain(binades)
        };
        for scale in [1.0f64, 1.1, 1.3, 1.5, 1.65, 1.9, 1.99] {
            let inv = f64::from_bits((1.0 / scale).to_bits() + 2);
            let (s32, x_inv32) = (
                scale as f32,
                f32::from_bits((1.0 / scale as f32).to_bits() + 2),
            );
            for x in xs() {
                let d = ulps64(x.atan_nonneg_scaled(scale, inv), scale * libm::atan(x));
                if d > worst.0 {
                    worst = (d, x, scale);
                }
                let x32 = x as f32;
                let reference = (f64::from(s32) * libm::atan(f64::from(x32))) as f32;
                let d32 = ulps32(x32.atan_nonneg_scaled(s32, x_inv32), reference);
                if d32 > worst32.0 {
                    worst32 = (d32, f64::from(x32), scale);
                }
            }
        }
        assert!(worst.0 <= 4 && worst32.0 <= 4, "{worst:?} {worst32:?}");
    }

    #[test]
    fn sin_quadrant_f64_within_2_ulp_of_libm() {
        let mut worst = (0, 0.0);
        let half_pi = core::f64::consts::FRAC_PI_2;
        let dense = (0..=1u64 << 20).map(|i| i as f64 / (1u64 << 20) as f64 * half_pi);
        let binades =
            (0..1_000_000u64).map(|i| f64::from_bits(i * (half_pi.to_bits() / 1_000_000)));
        for x in dense.chain(binades) {
            let d = ulps64(x.sin_quadrant(), libm::sin(x));
            if d > worst.0 {
                worst = (d, x);
            }
        }
        assert!(worst.0 <= 2, "{worst:?}");
    }

    #[test]
    fn sin_quadrant_f32_within_2_ulp_of_libm() {
        let mut worst = (0, 0.0);
        for bits in (0..=core::f32::consts::FRAC_PI_2.to_bits()).step_by(211) {
            let x = f32::from_bits(bits);
            let d = ulps32(x.sin_quadrant(), libm::sinf(x));
            if d > worst.0 {
                worst = (d, x);
            }
        }
        assert!(worst.0 <= 2, "{worst:?}");
    }
}
