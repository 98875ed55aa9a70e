//! The Magic Formula curve shape, in a variable whose slope at zero is 1 for every shape.
//!
//! Pacejka's pure-slip formula is `y(x) = D·sin(C·atan(B·x − E·(B·x − atan(B·x))))`. Written in
//! `t = B·C·x` (the force the initial slope would give, over the peak `D`), its shape depends
//! on `C` and `E` only and its slope at zero is 1 whatever they are: `g(t) ≈ t`. That is what
//! lets [`super::MagicFormula`] blend the longitudinal and lateral shapes for a combined slip
//! without changing the tyre's stiffness in any direction. The peak is where
//! `C·atan((1 − E)·u + E·atan(u)) = π/2`, `u = t/C`, i.e. at the root `u_p` of
//! `(1 − E)·u + E·atan(u) = tan(π / (2·C))`, found once per parameter set.

use ackermann::Real;

/// The shape of one Magic Formula curve (`C`, `E`) and where its peak lies.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct Shape<T> {
    /// Shape factor `C` (1 < C < 2).
    pub c: T,
    /// Curvature factor `E` (< 1).
    pub e: T,
    /// `u_p = B·x_peak` (dimensionless, > 0): the peak in Pacejka's variable `B·x`; in `t` it is
    /// at `C·u_p`.
    pub u_peak: T,
}

impl<T: Real> Shape<T> {
    /// The shape of `C` and `E`, `None` unless `1 < C < 2` and `E < 1` (the ranges in which the
    /// curve has one peak and falls to `sin(C·π/2) > 0` after it).
    pub fn new(c: T, e: T) -> Option<Self> {
        if !(c > T::ONE && c < T::TWO && e < T::ONE && e.is_finite()) {
            return None;
        }
        let target = (T::FRAC_PI_2 / c).tan();
        // h(u) = (1 − E)·u + E·atan(u) rises from 0 without bound (h' ≥ min(1, 1 − E) > 0):
        // bracket the root by doubling, then bisect to the last bit.
        let h = |u: T| (T::ONE - e) * u + e * u.atan();
        let mut hi = T::ONE;
        let mut doublings = 0;
        while h(hi) < target {
            hi *= T::TWO;
            doublings += 1;
            if doublings > 200 {
                return None;
            }
        }
        let mut lo = T::ZERO;
        for _ in 0..200 {
            let mid = T::HALF * (lo + hi);
            if mid <= lo || mid >= hi {
                break;
            }
            if h(mid) < target {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        let u_peak = T::HALF * (lo + hi);
        (u_peak > T::ZERO && u_peak.is_finite()).then_some(Shape { c, e, u_peak })
    }

    /// The curve `g(t)` at `t ≥ 0` (slope 1 at zero, peak 1 at `t = C·u_p`), in [−1, 1]: the
    /// force over its peak.
    #[cfg(test)]
    pub fn at(&self, t: T) -> T {
        let u = t / self.c;
        let inv_u = T::ONE / u;
        self.at_u(u, inv_u, u * u, inv_u * inv_u, T::ONE / self.c)
    }

    /// The curve at `u = t/C ≥ 0`, given `1/u` too (∞ at `u = 0`): `sin(C·atan(φ))`,
    /// `φ = (1 − E)·u + E·atan(u)`. The caller forms both `u` and `1/u` by products of values
    /// it has anyway ([`super::MagicFormula`]'s combined slip), so the first arc tangent needs no
    /// division to reduce its argument, and the second is [`Real::atan_nonneg_scaled`], whose
    /// reciprocal starts with its polynomials and whose product by `C` is folded into its last
    /// steps. The arc tangents and the sine are polynomial kernels after exact reductions: within
    /// 1.5e-15 of the peak of the same formula through libm's `atan` and `sin` in `f64`, 6e-7 in
    /// `f32` (the test `polynomial_curve_is_libm_curve`).
    ///
    /// The squares `u²` and `1/u²` are given too (to a few ulp): the caller forms them
    /// without the square root that `u` waits for, and the first arc tangent's polynomial, in
    /// the square, starts before `u` is known. So is `inv_c`, `1/C` to a few ulp, which scales
    /// only the rational term of the second arc tangent (below a third of it).
    #[inline(always)]
    pub fn at_u(&self, u: T, inv_u: T, u_sq: T, inv_u_sq: T, inv_c: T) -> T {
        // φ = (1 − E)·u + E·atan(u); above 1, atan(u) = π/2 − atan(1/u). The map from the
        // polynomial's arc tangent to φ is affine, folded into its last level.
        let base = (T::ONE - self.e) * u;
        let phi = if u > T::ONE {
            inv_u.atan_unit_affine(inv_u_sq, base + self.e * T::FRAC_PI_2, -self.e)
        } else {
            u.atan_unit_affine(u_sq, base, self.e)
        };
        sin_0_pi(phi.atan_nonneg_scaled(self.c, inv_c))
    }

    /// Where the curve peaks, `t = C·u_p`.
    pub fn t_peak(&self) -> T {
        self.c * self.u_peak
    }

    /// The shape between `self` (weight `1 − w`) and `other` (weight `w`), for a slip direction
    /// between the two axes.
    #[inline]
    pub fn blend(&self, other: &Self, w: T) -> Self {
        let mix = |a: T, b: T| a + (b - a) * w;
        Shape {
            c: mix(self.c, other.c),
            e: mix(self.e, other.e),
            u_peak: mix(self.u_peak, other.u_peak),
        }
    }
}

/// `sin(x)` for `x` in [0, π): the curve's angle `C·atan(φ)` with `C < 2`, `φ ≥ 0`. Folded into
/// [0, π/2] as `sin(π − x)`; `π − x` is `(π_hi − x) + π_lo`, whose first difference is exact
/// (Sterbenz: `x ≥ π_hi/2`), so the fold adds one rounding and not the error of `π_hi`.
#[inline(always)]
fn sin_0_pi<T: Real>(x: T) -> T {
    // π − π_hi: `T::PI` differs from π by its own rounding. Taken as (π_f64 − π_T) plus the low
    // part of π_f64, exact in f64 and rounded once to `T` (both are constants the compiler folds).
    let pi_lo = T::from_f64((core::f64::consts::PI - T::PI.to_f64()) + 1.224_646_799_147_353_2e-16);
    let y = if x > T::FRAC_PI_2 {
        (T::PI - x) + pi_lo
    } else {
        x
    };
    y.sin_quadrant()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// One shape of each kind `Shape::new` accepts: typical longitudinal and lateral, E near
    /// 1, strongly negative E, E = 0 (closed-form peak).
    const SHAPES: [(f64, f64); 5] = [
        (1.65, 0.7),
        (1.3, -0.5),
        (1.9, 0.97),
        (1.1, -3.0),
        (1.5, 0.0),
    ];

    /// Pacejka's form, for comparison.
    fn pacejka(x: f64, b: f64, c: f64, d: f64, e: f64) -> f64 {
        d * (c * (b * x - e * (b * x - (b * x).atan())).atan()).sin()
    }

    #[test]
    fn peak_is_at_c_times_u_peak() {
        for (c, e) in SHAPES {
            let s = Shape::<f64>::new(c, e).unwrap();
            let p = s.t_peak();
            assert!((s.at(p) - 1.0).abs() < 1e-12, "C {c} E {e}");
            assert!(s.at(0.98 * p) < 1.0 && s.at(1.02 * p) < 1.0);
            // With E = 0 the root is closed-form: u_p = tan(π/(2C)).
            if e == 0.0 {
                assert!((s.u_peak - (core::f64::consts::FRAC_PI_2 / c).tan()).abs() < 1e-12);
            }
        }
    }

    #[test]
    fn matches_pacejka_and_has_unit_slope() {
        // The dry-tarmac "single set" B = 10, C = 1.9, D = 1, E = 0.97: y(x) = g(B·C·x).
        let (b, c, e) = (10.0, 1.9, 0.97);
        let s = Shape::<f64>::new(c, e).unwrap();
        for x in [0.01, 0.05, 0.1, 0.18, 0.5, 1.0] {
            let g = s.at(b * c * x);
            assert!((g - pacejka(x, b, c, 1.0, e)).abs() < 1e-12, "x {x}");
        }
        // The slope at zero is 1 for every shape.
        assert_eq!(s.at(0.0), 0.0);
        for (c, e) in [(1.65, 0.7), (1.3, -0.5), (1.1, -3.0)] {
            let s = Shape::<f64>::new(c, e).unwrap();
            let tiny = 1e-6;
            assert!((s.at(tiny) / tiny - 1.0).abs() < 1e-9, "C {c} E {e}");
        }
    }

    /// The curve through the polynomial kernels against the same formula through libm (in f64),
    /// absolute (the force over its peak): every kind of accepted shape, `t` from 1e-8 to 1e6
    /// (600 points per decade).
    #[test]
    fn polynomial_curve_is_libm_curve() {
        let reference = |s: &Shape<f64>, t: f64| {
            let u = t / s.c;
            (s.c * ((1.0 - s.e) * u + s.e * u.atan()).atan()).sin()
        };
        let (mut worst, mut worst32): (f64, f64) = (0.0, 0.0);
        // And a shape at the edge of the accepted range.
        for (c, e) in SHAPES.into_iter().chain([(1.99, -10.0)]) {
            let s = Shape::<f64>::new(c, e).unwrap();
            let s32 = Shape::<f32>::new(c as f32, e as f32).unwrap();
            let r32 = Shape::<f64>::new(f64::from(s32.c), f64::from(s32.e)).unwrap();
            for i in 0..=8400 {
                let t = 10f64.powf(-8.0 + f64::from(i) / 600.0);
                let g = reference(&s, t);
                worst = worst.max((s.at(t) - g).abs());
                let t32 = t as f32;
                let g32 = reference(&r32, f64::from(t32));
                worst32 = worst32.max((f64::from(s32.at(t32)) - g32).abs());
            }
        }
        // f64: the two arc tangents (≤ 1 ulp each), the sine (≤ 2 ulp) and the reference's own
        // libm roundings, measured 1.0e-15 of the peak; f32: the whole evaluation in f32
        // arithmetic against an f64 reference, measured 4.8e-7 (about 8 f32 ulp of 1).
        assert!(worst < 1.5e-15 && worst32 < 6e-7, "{worst:e} {worst32:e}");
    }

    #[test]
    fn folded_sine_is_the_sine() {
        for i in 0..=1000 {
            let x = f64::from(i) * core::f64::consts::PI / 1000.0 * 0.9999;
            assert!((sin_0_pi(x) - x.sin()).abs() < 4e-16, "{x}");
            let x32 = x as f32;
            assert!((sin_0_pi(x32) - x32.sin()).abs() < 2e-7, "{x32}");
        }
    }

    #[test]
    fn sliding_value_and_rejected_shapes() {
        // Far past the peak the curve tends to sin(C·π/2).
        let s = Shape::<f32>::new(1.5, 0.0).unwrap();
        assert!((s.at(1e7) - core::f32::consts::FRAC_1_SQRT_2).abs() < 1e-5);
        assert!(Shape::<f64>::new(1.0, 0.0).is_none());
        assert!(Shape::<f64>::new(2.0, 0.0).is_none());
        assert!(Shape::<f64>::new(1.5, 1.0).is_none());
        assert!(Shape::<f64>::new(f64::NAN, 0.0).is_none());
        assert!(Shape::<f64>::new(1.5, f64::NEG_INFINITY).is_none());
    }
}
