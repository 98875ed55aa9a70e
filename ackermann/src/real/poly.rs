//! Polynomial arc tangent and sine on reduced ranges, and a rational arc tangent above 1, for the
//! hot paths that cannot afford libm's argument reduction (the tyre curve).
//!
//! Pure `+` and `×` (and the rational's two divisions, correctly rounded everywhere) in a fixed
//! order (Rust never contracts them into fused operations), so every target computes the same
//! bits, like the rest of [`super::Real`]. The coefficients were fitted for this crate: the
//! polynomials near-minimax, by least squares on Chebyshev points in 50-digit arithmetic, each
//! coefficient rounded to the type before the later ones were refitted to that rounding; the
//! rationals by linearised least squares (the denominator of the previous pass as weight,
//! reweighted toward minimax), rounded once. The tests below bound the whole evaluation,
//! rounding included, against libm.

use super::Real;

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
fn estrin4<T: Real>(x: T, c: &[T; 4]) -> T {
    pair(&c[0..2], x) + pair(&c[2..4], x) * (x * x)
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
fn estrin7<T: Real>(x: T, c: &[T; 7]) -> T {
    let x2 = x * x;
    (pair(&c[0..2], x) + pair(&c[2..4], x) * x2) + (pair(&c[4..6], x) + c[6] * x2) * (x2 * x2)
}

#[inline(always)]
fn estrin8<T: Real>(x: T, c: &[T; 8]) -> T {
    let x2 = x * x;
    let q0 = pair(&c[0..2], x) + pair(&c[2..4], x) * x2;
    let q1 = pair(&c[4..6], x) + pair(&c[6..8], x) * x2;
    q0 + q1 * (x2 * x2)
}

#[inline(always)]
fn estrin9<T: Real>(x: T, c: &[T; 9]) -> T {
    let x2 = x * x;
    let x4 = x2 * x2;
    let q0 = pair(&c[0..2], x) + pair(&c[2..4], x) * x2;
    let q1 = pair(&c[4..6], x) + pair(&c[6..8], x) * x2;
    (q0 + q1 * x4) + c[8] * (x4 * x4)
}

#[inline(always)]
fn estrin20<T: Real>(x: T, c: &[T; 20]) -> T {
    let x2 = x * x;
    let x4 = x2 * x2;
    let x8 = x4 * x4;
    let q = |i: usize| pair(&c[i..i + 2], x) + pair(&c[i + 2..i + 4], x) * x2;
    let o0 = q(0) + q(4) * x4;
    let o1 = q(8) + q(12) * x4;
    (o0 + o1 * x8) + q(16) * (x8 * x8)
}

/// `R` of `atan(x) = x − x³·R(x² − 1/2)` for x in [0, 1]: the shifted variable keeps the
/// coefficients falling (by about 1/3 each) where those in `x²` would not, and the exact leading
/// `x` leaves the rounding errors of the sum to a term below 0.22·x. Fit error 6.7e-18 relative
/// to `atan(x)`.
#[rustfmt::skip]
pub(super) const ATAN_F64: [f64; 20] = [
    0.2591604972657936,
    -0.11081482513071446,
    0.05481484060456599,
    -0.029135862645127054,
    0.0161729749019224,
    -0.009243096232686805,
    0.005394792649914513,
    -0.003199174863931624,
    0.0019209409341014254,
    -0.001165071644582028,
    0.000712503994164679,
    -0.000438690456082388,
    0.00027158494463293324,
    -0.0001695268346509617,
    0.0001070354014043747,
    -6.537057941268814e-05,
    3.7078662008226313e-05,
    -2.7490789420936267e-05,
    2.638718366720627e-05,
    -1.296649760750847e-05,
];

/// As [`ATAN_F64`], in `f32`: fit error 4.9e-9 relative.
#[rustfmt::skip]
pub(super) const ATAN_F32: [f32; 9] = [
    0.2591605,
    -0.110814795,
    0.05481584,
    -0.029138928,
    0.01614977,
    -0.00917262,
    0.005552901,
    -0.003732138,
    0.0017483131,
];

/// `Q` of `sin(x) = x + x³·Q(x²)` for x in [0, π/2]: fit error 3.0e-19 relative to `sin(x)`.
#[rustfmt::skip]
pub(super) const SIN_F64: [f64; 8] = [
    -0.16666666666666666,
    0.008333333333333207,
    -0.00019841269841212495,
    2.7557319211575365e-06,
    -2.5052106905220692e-08,
    1.605894105362705e-10,
    -7.643020951963178e-13,
    2.7214383155491413e-15,
];

/// As [`SIN_F64`], in `f32`: fit error 6.5e-9 relative.
#[rustfmt::skip]
pub(super) const SIN_F32: [f32; 4] = [
    -0.1666666,
    0.008333068,
    -0.00019809656,
    2.6057342e-6,
];

/// The rational `x³·P(x²)/Q(x²)` of `atan(x) = x − x³·P(x²)/Q(x²)` on [0, 1] (`P` of degree 5,
/// `Q` of degree 6, `Q(0) = 1`), stored reversed for `x > 1`: with `w = 1/x²`,
/// `atan(1/x) = (1/x)·(1 − w·P(w)/Q(w))` and `w·P(w)/Q(w) = P̃(x²)/Q̃(x²)`, where `P̃` and `Q̃`
/// are `P` and `Q` with their coefficients in reverse order. So the argument's reciprocal
/// `1/x` is needed only for the leading term and is formed alongside the two polynomials,
/// not before them. Every coefficient is positive (no cancellation for `x² ≥ 1`). Fit error
/// 6.9e-18 relative to `atan` (1.6e-17 with the coefficients rounded to `f64`).
#[rustfmt::skip]
pub(super) const ATAN_REV_P_F64: [f64; 6] = [
    0.0007522652075534019,
    0.02377872547082582,
    0.1912787511419628,
    0.5861668863123194,
    0.7470658875115803,
    0.33333333333333165,
];

/// `Q̃` of [`ATAN_REV_P_F64`].
#[rustfmt::skip]
pub(super) const ATAN_REV_Q_F64: [f64; 7] = [
    0.0008337726015245978,
    0.03320648198069285,
    0.35129272446523047,
    1.5103021421369414,
    3.0346478279025164,
    2.8411976625342503,
    1.0,
];

/// As [`ATAN_REV_P_F64`], in `f32` (`P` of degree 2, `Q` of degree 3): fit error 1.1e-9
/// relative (5.5e-9 with the coefficients rounded to `f32`).
#[rustfmt::skip]
pub(super) const ATAN_REV_P_F32: [f32; 3] = [
    0.041967686,
    0.288545,
    0.33333325,
];

/// `Q̃` of [`ATAN_REV_P_F32`].
#[rustfmt::skip]
pub(super) const ATAN_REV_Q_F32: [f32; 4] = [
    0.050986346,
    0.5767694,
    1.4656285,
    1.0,
];

/// `x²` at most `limit`, for the reversed rational: `P̃/Q̃ ≈ 1/(3·x²)` adds less than
/// `2⁻⁶⁴/x` to the arc tangent above the limit, far below the last bit of `π/2`, and the
/// limit keeps `Q̃` finite (and `∞` out of it).
#[inline(always)]
fn square_at_most<T: Real>(x: T, limit: T) -> T {
    let z = x * x;
    if z < limit { z } else { limit }
}

/// `atan(x)` for `x ≥ 0`, `f64`: [`atan_unit_f64`] up to 1; above, `π/2 − 1/x + (1/x)·P̃/Q̃`
/// (`x²` at most 2⁶⁴).
#[inline(always)]
pub(super) fn atan_nonneg_f64(x: f64) -> f64 {
    if x > 1.0 {
        let inv = 1.0 / x;
        let z = square_at_most(x, 4_294_967_296.0 * 4_294_967_296.0);
        let ratio = estrin6(z, &ATAN_REV_P_F64) / estrin7(z, &ATAN_REV_Q_F64);
        (core::f64::consts::FRAC_PI_2 - inv) + inv * ratio
    } else {
        atan_unit_f64(x)
    }
}

/// `atan(x)` for `x ≥ 0`, `f32`: as [`atan_nonneg_f64`] (`x²` at most 2²⁴).
#[inline(always)]
pub(super) fn atan_nonneg_f32(x: f32) -> f32 {
    if x > 1.0 {
        let inv = 1.0 / x;
        let z = square_at_most(x, 16_777_216.0);
        let ratio = estrin3(z, &ATAN_REV_P_F32) / estrin4(z, &ATAN_REV_Q_F32);
        (core::f32::consts::FRAC_PI_2 - inv) + inv * ratio
    } else {
        atan_unit_f32(x)
    }
}

/// `atan(x)` for `x` in [0, 1], `f64`, given `z = x²`.
#[inline(always)]
pub(super) fn atan_unit_sq_f64(x: f64, z: f64) -> f64 {
    x - x * z * estrin20(z - 0.5, &ATAN_F64)
}

/// `atan(x)` for `x` in [0, 1], `f32`, given `z = x²`.
#[inline(always)]
pub(super) fn atan_unit_sq_f32(x: f32, z: f32) -> f32 {
    x - x * z * estrin9(z - 0.5, &ATAN_F32)
}

/// `offset + scale·atan(x)` for `x` in [0, 1], `f64`, given `z = x²`: `(offset + scale·x) −
/// (scale·x·z)·R`, so that only one product and one sum follow the polynomial.
#[inline(always)]
pub(super) fn atan_unit_affine_f64(x: f64, z: f64, offset: f64, scale: f64) -> f64 {
    let sx = scale * x;
    (offset + sx) - (sx * z) * estrin20(z - 0.5, &ATAN_F64)
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

/// `sin(x)` for `x` in [0, π/2], `f64`.
#[inline]
pub(super) fn sin_quadrant_f64(x: f64) -> f64 {
    let z = x * x;
    x + x * z * estrin8(z, &SIN_F64)
}

/// `sin(x)` for `x` in [0, π/2], `f32`.
#[inline]
pub(super) fn sin_quadrant_f32(x: f32) -> f32 {
    let z = x * x;
    x + x * z * estrin4(z, &SIN_F32)
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
    /// polynomial's part of an ulp make 1.5; measured 1.0 in f64, 0.87 in f32.
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
