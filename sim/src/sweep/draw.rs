//! Seeded random draws of the axes.
//!
//! Draw `k` of an axis is a function of the axis's `seed`, its key and `k` alone: the axis's
//! stream is SplitMix64 ([`crate::rng`]) started from the seed mixed with an FNV-1a hash of
//! the key, and draw `k` takes numbers `2k` and `2k + 1` of that stream, reached by jumping
//! ahead, never by drawing the ones before. So a case has the same values whichever shard,
//! thread or Python worker makes it, in whatever order, and two axes with the same seed draw
//! different numbers. The logarithm and cosine of the normal draws are `libm`'s, so the
//! numbers are the same on every platform too.

use core::f64::consts::TAU;

use crate::rng::SplitMix64;

/// FNV-1a, 64 bits: a fixed hash of bytes, the same on every platform and version (unlike
/// the standard library's hashers).
pub(crate) fn fnv1a(bytes: &[u8]) -> u64 {
    const OFFSET: u64 = 0xCBF2_9CE4_8422_2325;
    const PRIME: u64 = 0x0000_0100_0000_01B3;
    bytes
        .iter()
        .fold(OFFSET, |h, &b| (h ^ u64::from(b)).wrapping_mul(PRIME))
}

/// The generator positioned at draw `index` of the axis `key` seeded with `seed`.
fn generator(seed: u64, key: &str, index: u64) -> SplitMix64 {
    // One SplitMix64 output mixes the seed and the key's hash into the stream's start, so
    // that seeds 1 and 2 (or keys differing by a letter) start unrelated streams.
    let start = SplitMix64::new(seed ^ fnv1a(key.as_bytes())).next_u64();
    let mut g = SplitMix64::new(start);
    g.advance(index.wrapping_mul(2));
    g
}

/// Draw `index` of a uniform axis over `[lo, hi)` (finite bounds, `lo < hi`): always in
/// that interval, whatever the bounds' magnitude.
pub(crate) fn uniform(seed: u64, key: &str, index: u64, lo: f64, hi: f64) -> f64 {
    let u = generator(seed, key, index).uniform();
    // Where `hi − lo` overflows (−1e308 to 1e308), (1 − u)·lo + u·hi is finite. Either
    // sum's rounding may reach `hi`, which the interval excludes: the largest number below
    // it then (never below `lo`, as `lo < hi`).
    let span = hi - lo;
    let x = if span.is_finite() {
        lo + span * u
    } else {
        (1.0 - u) * lo + u * hi
    };
    if x < hi { x.max(lo) } else { hi.next_down() }
}

/// Farthest a normal draw lies from its mean, in standard deviations: √(−2 ln 2⁻⁵³) = 8.57
/// for the smallest `1 − u` of a draw, rounded up.
pub(crate) const NORMAL_REACH: f64 = 9.0;

/// Draw `index` of a normal axis of mean `mean` and standard deviation `sd` (Box–Muller on
/// the draw's two numbers): within [`NORMAL_REACH`] standard deviations of the mean, finite
/// if `|mean| + NORMAL_REACH·sd` is (the sweep file's reader checks it).
pub(crate) fn normal(seed: u64, key: &str, index: u64, mean: f64, sd: f64) -> f64 {
    let mut g = generator(seed, key, index);
    // 1 − u is in (0, 1]: its logarithm is finite.
    let (u1, u2) = (1.0 - g.uniform(), g.uniform());
    let z = libm::sqrt(-2.0 * libm::log(u1)) * libm::cos(TAU * u2);
    mean + sd * z
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn fnv1a_reference_values() {
        // The published FNV-1a 64 test vectors.
        assert_eq!(fnv1a(b""), 0xCBF2_9CE4_8422_2325);
        assert_eq!(fnv1a(b"a"), 0xAF63_DC4C_8601_EC8C);
        assert_eq!(fnv1a(b"foobar"), 0x8594_4171_F739_67E8);
    }

    #[test]
    fn a_draw_depends_on_seed_key_and_index_only() {
        let forward: Vec<f64> = (0..100)
            .map(|k| uniform(7, "ground.friction", k, 0.5, 1.0))
            .collect();
        let backward: Vec<f64> = (0..100)
            .rev()
            .map(|k| uniform(7, "ground.friction", k, 0.5, 1.0))
            .collect();
        assert!(forward.iter().eq(backward.iter().rev()));
        assert!(forward.iter().all(|x| (0.5..1.0).contains(x)));
        // Another key or seed: other numbers.
        assert_ne!(forward[0], uniform(7, "ground.frictio", 0, 0.5, 1.0));
        assert_ne!(forward[0], uniform(8, "ground.friction", 0, 0.5, 1.0));
        // Draw k takes numbers 2k and 2k + 1 of the axis's stream.
        let start = SplitMix64::new(7 ^ fnv1a(b"ground.friction")).next_u64();
        let mut stream = SplitMix64::new(start);
        stream.advance(6);
        assert_eq!(0.5 + 0.5 * stream.uniform(), forward[3]);
    }

    #[test]
    fn uniform_draws_of_any_span_stay_in_the_half_open_interval() {
        for k in 0..1000 {
            let x = uniform(5, "gravity", k, -1e308, 1e308);
            assert!(x.is_finite() && (-1e308..1e308).contains(&x), "{x}");
            let y = uniform(5, "gravity", k, 1.0, 1.0 + f64::EPSILON);
            assert_eq!(y, 1.0);
        }
    }

    #[test]
    fn normal_draws_have_their_mean_and_spread() {
        let n = 20_000;
        let xs: Vec<f64> = (0..n)
            .map(|k| normal(3, "vehicle.mass", k, 2000.0, 100.0))
            .collect();
        let mean = xs.iter().sum::<f64>() / n as f64;
        let var = xs.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / (n - 1) as f64;
        // Standard errors: of the mean 100/√n ≈ 0.71 kg, of the standard deviation
        // 100/√(2n) ≈ 0.5 kg; 5 of each.
        assert!((mean - 2000.0).abs() < 3.6, "{mean}");
        assert!((var.sqrt() - 100.0).abs() < 2.5, "{}", var.sqrt());
        assert!(xs.iter().all(|x| x.is_finite()));
    }
}
