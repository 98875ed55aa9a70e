//! A small deterministic pseudo-random generator for the noise models.
//!
//! Webots draws its slip and encoder noise from its own generator; the exact stream cannot be
//! reproduced, so the simulator uses SplitMix64 (Steele, Lea and Flood, 2014): 64 bits of state,
//! full period 2⁶⁴, and the same stream for the same seed on every platform. Each robot owns its
//! generator, so adding a robot never changes the noise of another. A sweep's random axes draw
//! from it too (`sweep::draw`), each draw at a fixed place in its axis's stream.

/// SplitMix64: a seedable generator whose output depends only on the seed and the number of
/// draws.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct SplitMix64 {
    state: u64,
}

impl SplitMix64 {
    /// A generator started from `seed` (any value, 0 included).
    pub const fn new(seed: u64) -> Self {
        SplitMix64 { state: seed }
    }

    /// The increment of the state per draw (the golden ratio's 64-bit fraction, odd).
    const GAMMA: u64 = 0x9E37_79B9_7F4A_7C15;

    /// Skips `n` draws at once: the stream goes on as after `n` calls of
    /// [`next_u64`](Self::next_u64) (the state advances by a constant per draw), so that draw
    /// `k` of a stream is reached without the `k` before it.
    pub fn advance(&mut self, n: u64) {
        self.state = self.state.wrapping_add(n.wrapping_mul(Self::GAMMA));
    }

    /// The next 64 random bits.
    pub fn next_u64(&mut self) -> u64 {
        self.state = self.state.wrapping_add(Self::GAMMA);
        let mut z = self.state;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        z ^ (z >> 31)
    }

    /// A uniform draw in [0, 1) with 53 random bits (Webots: `wb_random_get_uniform()`).
    pub fn uniform(&mut self) -> f64 {
        // 2⁻⁵³: the top 53 bits become the mantissa of a value in [0, 1).
        const SCALE: f64 = 1.0 / (1u64 << 53) as f64;
        (self.next_u64() >> 11) as f64 * SCALE
    }

    /// `1 − noise + 2·noise·U` with `U` uniform in [0, 1): the multiplicative white noise of the
    /// Webots `slipNoise` and `encoderNoise` fields (a factor in [1 − noise, 1 + noise)).
    pub fn noise_factor(&mut self, noise: f64) -> f64 {
        1.0 - noise + 2.0 * noise * self.uniform()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn splitmix64_reference_stream() {
        // Reference values of SplitMix64 seeded with 0 (Vigna's splitmix64.c).
        let mut r = SplitMix64::new(0);
        assert_eq!(r.next_u64(), 0xE220_A839_7B1D_CDAF);
        assert_eq!(r.next_u64(), 0x6E78_9E6A_A1B9_65F4);
        assert_eq!(r.next_u64(), 0x06C4_5D18_8009_454F);
    }

    #[test]
    fn advance_skips_draws() {
        let mut walked = SplitMix64::new(99);
        for _ in 0..1000 {
            walked.next_u64();
        }
        let mut jumped = SplitMix64::new(99);
        jumped.advance(1000);
        assert_eq!(jumped, walked);
        assert_eq!(jumped.next_u64(), walked.next_u64());
    }

    #[test]
    fn uniform_is_in_unit_interval_and_centred() {
        let mut r = SplitMix64::new(42);
        let n = 100_000;
        let mut sum = 0.0;
        for _ in 0..n {
            let u = r.uniform();
            assert!((0.0..1.0).contains(&u));
            sum += u;
        }
        // Mean of U(0,1) is 0.5 with standard error 1/sqrt(12 n) ≈ 0.0009.
        assert!((sum / n as f64 - 0.5).abs() < 0.005);
    }

    #[test]
    fn noise_factor_bounds() {
        let mut r = SplitMix64::new(7);
        for _ in 0..10_000 {
            let f = r.noise_factor(0.1);
            assert!((0.9..1.1).contains(&f));
        }
        assert_eq!(r.noise_factor(0.0), 1.0);
    }
}
