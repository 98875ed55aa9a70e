//! The Fresnel integrals C(x) = ∫₀ˣ cos(πt²/2) dt and S(x) = ∫₀ˣ sin(πt²/2) dt, to double
//! precision: the exact positions along a clothoid (OpenDRIVE's `spiral`).
//!
//! Power series below |x| = 1.5 (every term positive in magnitude order, no cancellation
//! there), and above it the continued fraction of the complementary error function evaluated
//! by the modified Lentz method, which converges in a few dozen terms for every larger x (the
//! method of Numerical Recipes' `frenel`, rewritten here).

use core::f64::consts::FRAC_PI_2;

/// Relative accuracy sought (a few units of f64's epsilon).
const EPS: f64 = 4.0 * f64::EPSILON;
/// Below this |x| the series is used, above it the continued fraction.
const SERIES_LIMIT: f64 = 1.5;
/// Most terms of either expansion (both converge in far fewer).
const MAX_TERMS: usize = 200;

/// `(C(x), S(x))`, both odd in x; C, S → ½ as x → ∞.
pub(crate) fn fresnel(x: f64) -> (f64, f64) {
    let ax = x.abs();
    let (c, s) = if ax < SERIES_LIMIT {
        series(ax)
    } else {
        continued_fraction(ax)
    };
    if x < 0.0 { (-c, -s) } else { (c, s) }
}

/// C = Σ (−1)ⁿ (π/2)²ⁿ x⁴ⁿ⁺¹ / ((2n)! (4n+1)), S = Σ (−1)ⁿ (π/2)²ⁿ⁺¹ x⁴ⁿ⁺³ / ((2n+1)! (4n+3)):
/// one sequence of terms (π/2·x²)ᵏ/k!·x, alternating between C (even k) and S (odd k).
fn series(x: f64) -> (f64, f64) {
    let fact = FRAC_PI_2 * x * x;
    let (mut c, mut s) = (x, 0.0);
    let mut term = x;
    for k in 1..MAX_TERMS {
        term *= fact / k as f64;
        // Term k has the sign (−1)^⌊k/2⌋: S's k = 2n+1 and C's k = 2n both (−1)ⁿ.
        let sign = if (k / 2) % 2 == 0 { 1.0 } else { -1.0 };
        let add = sign * term / (2 * k + 1) as f64;
        if k % 2 == 1 {
            s += add;
        } else {
            c += add;
        }
        if term < EPS * c.abs().max(s.abs()) {
            break;
        }
    }
    (c, s)
}

/// A complex number as (re, im): the little arithmetic the continued fraction needs.
#[derive(Clone, Copy)]
struct Cx(f64, f64);

impl Cx {
    fn mul(self, o: Cx) -> Cx {
        Cx(self.0 * o.0 - self.1 * o.1, self.0 * o.1 + self.1 * o.0)
    }
    fn inv(self) -> Cx {
        let d = self.0 * self.0 + self.1 * self.1;
        Cx(self.0 / d, -self.1 / d)
    }
    fn add(self, o: Cx) -> Cx {
        Cx(self.0 + o.0, self.1 + o.1)
    }
    fn scale(self, k: f64) -> Cx {
        Cx(self.0 * k, self.1 * k)
    }
}

/// C + iS = (1+i)/2 · (1 − e^{iπx²/2}·h·(1−i)x) with h the continued fraction
/// 1/(b₀ + a₁/(b₁ + a₂/(b₂ + …))), b_k = 1 + 4k − iπx², a_k = −(2k−1)(2k) (from erfc).
fn continued_fraction(x: f64) -> (f64, f64) {
    let pix2 = core::f64::consts::PI * x * x;
    let tiny = 1e-300;
    let mut b = Cx(1.0, -pix2);
    let mut cc = Cx(1.0 / tiny, 0.0);
    let mut d = b.inv();
    let mut h = d;
    let mut n = -1.0;
    for _ in 1..MAX_TERMS {
        n += 2.0;
        let a = -n * (n + 1.0);
        b = b.add(Cx(4.0, 0.0));
        d = d.scale(a).add(b).inv();
        cc = b.add(cc.inv().scale(a));
        let del = cc.mul(d);
        h = h.mul(del);
        if (del.0 - 1.0).abs() + del.1.abs() < EPS {
            break;
        }
    }
    let h = h.mul(Cx(x, -x));
    let (sn, cs) = (0.5 * pix2).sin_cos();
    let one_minus = Cx(1.0, 0.0).add(Cx(cs, sn).mul(h).scale(-1.0));
    let r = Cx(0.5, 0.5).mul(one_minus);
    (r.0, r.1)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// C and S by composite Gauss–Legendre quadrature (5 points on each of `n` panels):
    /// an independent check, exact to ~1e-14 for the smooth integrands with n = 400.
    fn quadrature(x: f64, n: usize) -> (f64, f64) {
        let nodes = [
            (0.0, 128.0 / 225.0),
            (-0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
            (0.538_469_310_105_683_1, 0.478_628_670_499_366_5),
            (-0.906_179_845_938_664, 0.236_926_885_056_189_1),
            (0.906_179_845_938_664, 0.236_926_885_056_189_1),
        ];
        let h = x / n as f64;
        let (mut c, mut s) = (0.0, 0.0);
        for i in 0..n {
            let mid = (i as f64 + 0.5) * h;
            for (xi, w) in nodes {
                let t = mid + xi * h / 2.0;
                let phase = FRAC_PI_2 * t * t;
                c += w * h / 2.0 * phase.cos();
                s += w * h / 2.0 * phase.sin();
            }
        }
        (c, s)
    }

    #[test]
    fn tabulated_values() {
        // Abramowitz & Stegun table 7.7 (and any CAS) to 16 digits.
        let (c, s) = fresnel(1.0);
        assert!((c - 0.779_893_400_376_822_8).abs() < 1e-15, "{c}");
        assert!((s - 0.438_259_147_390_354_8).abs() < 1e-15, "{s}");
        let (c, s) = fresnel(2.0);
        assert!((c - 0.488_253_406_075_340_8).abs() < 1e-15, "{c}");
        assert!((s - 0.343_415_678_363_698_2).abs() < 1e-15, "{s}");
    }

    #[test]
    fn agrees_with_quadrature_on_both_branches_and_is_odd() {
        for x in [0.01, 0.3, 1.0, 1.49, 1.51, 2.5, 4.0, 7.3] {
            let (c, s) = fresnel(x);
            let (qc, qs) = quadrature(x, 400);
            // The quadrature's own error grows with the oscillations (x² / panel): 1e-12.
            assert!((c - qc).abs() < 1e-12 && (s - qs).abs() < 1e-12, "{x}");
            assert_eq!(fresnel(-x), (-c, -s));
        }
        assert_eq!(fresnel(0.0), (0.0, 0.0));
        // The limits at infinity: ½ within the 1/(πx) tail.
        let (c, s) = fresnel(1e4);
        assert!((c - 0.5).abs() < 1e-4 && (s - 0.5).abs() < 1e-4);
    }
}
