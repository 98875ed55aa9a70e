//! The arithmetic every Webots sensor applies to what it measures: Gaussian noise drawn from
//! the car's seeded generator, and `resolution`'s discretisation with its C truncation.

use crate::rng::SplitMix64;

/// A standard normal draw N(0, 1) (Box–Muller, the cosine branch: two uniform draws per value,
/// so the k-th value of a stream depends on nothing but the seed and k).
///
/// Webots draws from its own generator (`WbRandom::nextGaussian`); its stream cannot be
/// reproduced, only its distribution.
pub(crate) fn gaussian(rng: &mut SplitMix64) -> f64 {
    // 1 − U is in (0, 1]: its logarithm is finite.
    let radius = (-2.0 * (1.0 - rng.uniform()).ln()).sqrt();
    radius * (core::f64::consts::TAU * rng.uniform()).cos()
}

/// Webots' `discretize(value, resolution)`: `(int)(value / resolution + 0.5) · resolution`
/// when `resolution` is not −1 (the "no resolution" value), else `value`. C's `(int)` truncates
/// toward zero, so a negative value rounds one step up where it should round down
/// (−1.767 at 0.2 gives −1.6, not −1.8): Webots' behaviour, kept. NaN (a disabled axis, no
/// sample yet) stays NaN, where C's conversion would be undefined.
pub(crate) fn discretize(value: f64, resolution: f64) -> f64 {
    if resolution == -1.0 || value.is_nan() {
        value
    } else {
        (value / resolution + 0.5).trunc() * resolution
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn discretize_truncates_like_c() {
        // (int)(8.835 + 0.5) = 9 → 1.8; (int)(−8.835 + 0.5) = (int)(−8.335) = −8 → −1.6.
        // Tolerance 1e-12: one rounding of the product in f64.
        assert!((discretize(1.767, 0.2) - 1.8).abs() < 1e-12);
        assert!((discretize(-1.767, 0.2) - -1.6).abs() < 1e-12);
        // Exactly halfway: 0.25 / 0.5 + 0.5 = 1 → 0.5; −0.25 / 0.5 + 0.5 = 0 → 0.
        assert_eq!(discretize(0.25, 0.5), 0.5);
        assert_eq!(discretize(-0.25, 0.5), 0.0);
        assert_eq!(discretize(-1.767, -1.0), -1.767);
        assert!(discretize(f64::NAN, 0.2).is_nan());
    }

    #[test]
    fn gaussian_has_unit_variance() {
        let mut rng = SplitMix64::new(3);
        let n = 200_000;
        let (mut sum, mut sum_sq) = (0.0, 0.0);
        for _ in 0..n {
            let x = gaussian(&mut rng);
            assert!(x.is_finite());
            sum += x;
            sum_sq += x * x;
        }
        let mean = sum / f64::from(n);
        let variance = sum_sq / f64::from(n) - mean * mean;
        // Standard errors: mean 1/√n ≈ 0.0022, variance √(2/n) ≈ 0.0032; five of each.
        assert!(mean.abs() < 0.011, "{mean}");
        assert!((variance - 1.0).abs() < 0.016, "{variance}");
    }
}
