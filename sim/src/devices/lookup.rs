//! Webots' `lookupTable` (spec §2.1): a piecewise-linear response with relative noise.

use crate::error::ParamError;
use crate::rng::SplitMix64;

use super::noise::gaussian;

/// A `lookupTable`: rows `[input, output, noise]` with strictly increasing inputs. Empty is the
/// identity without noise.
///
/// Below the first input the first row's output and noise apply, above the last input the
/// last row's (clamped, no extrapolation); between two rows output and noise are both
/// interpolated linearly. The noise is relative: the value `v` becomes `v·(1 + noise·N(0,1))`.
#[derive(Debug, Clone, PartialEq, Default)]
pub struct LookupTable {
    rows: Vec<[f64; 3]>,
}

impl LookupTable {
    /// A table of `rows` (`[input, output, noise]`, inputs strictly increasing, every value
    /// finite).
    ///
    /// # Errors
    /// A [`ParamError`] naming `lookupTable` and the first value that is not finite, or the
    /// first input not above the one before it. (Webots warns and goes on with a table whose
    /// interpolation is then meaningless.)
    pub fn new(rows: Vec<[f64; 3]>) -> Result<Self, ParamError> {
        for row in &rows {
            for &v in row {
                ParamError::finite("lookupTable", v)?;
            }
        }
        for pair in rows.windows(2) {
            let [previous, row] = [pair[0], pair[1]];
            ParamError::check(
                "lookupTable",
                row[0],
                "an input above the row before it (inputs strictly increasing)",
                |input| input > previous[0],
            )?;
        }
        Ok(LookupTable { rows })
    }

    /// The rows `[input, output, noise]`, in order.
    pub fn rows(&self) -> &[[f64; 3]] {
        &self.rows
    }

    /// The response to `x` and its relative noise: `(output, noise)`.
    fn interpolate(&self, x: f64) -> (f64, f64) {
        let (Some(first), Some(last)) = (self.rows.first(), self.rows.last()) else {
            return (x, 0.0);
        };
        if x <= first[0] {
            return (first[1], first[2]);
        }
        if x >= last[0] {
            return (last[1], last[2]);
        }
        // x is strictly inside: some row's input exceeds it, and the row before is below.
        let upper = self.rows.iter().position(|r| r[0] > x).unwrap_or(0).max(1);
        let (a, b) = (self.rows[upper - 1], self.rows[upper]);
        let s = (x - a[0]) / (b[0] - a[0]);
        (a[1] + s * (b[1] - a[1]), a[2] + s * (b[2] - a[2]))
    }

    /// The table's value for the measured `x`, noise drawn from `rng` when the interpolated
    /// noise is not 0 (no draw otherwise, as Webots). NaN stays NaN.
    pub(crate) fn apply(&self, x: f64, rng: &mut SplitMix64) -> f64 {
        if x.is_nan() {
            return x;
        }
        let (value, noise) = self.interpolate(x);
        if noise == 0.0 {
            value
        } else {
            value * (1.0 + noise * gaussian(rng))
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn interpolation_and_clamping() {
        let t =
            LookupTable::new(vec![[-1.0, -10.0, 0.0], [0.0, 0.0, 0.0], [2.0, 40.0, 0.0]]).unwrap();
        let mut rng = SplitMix64::new(0);
        // Tolerance 1e-12: one interpolation in f64.
        let close = |a: f64, b: f64| (a - b).abs() < 1e-12;
        assert!(close(t.apply(-0.5, &mut rng), -5.0));
        assert!(close(t.apply(0.5, &mut rng), 10.0)); // 0 + 0.25·40
        assert!(close(t.apply(1.5, &mut rng), 30.0));
        assert_eq!(t.apply(-7.0, &mut rng), -10.0); // clamped to row 0
        assert_eq!(t.apply(9.0, &mut rng), 40.0); // clamped to the last row
        assert_eq!(t.apply(2.0, &mut rng), 40.0);
        assert_eq!(rng, SplitMix64::new(0), "no noise, no draw");
        let identity = LookupTable::default();
        assert_eq!(identity.apply(-3.25, &mut rng), -3.25);
    }

    #[test]
    fn noise_is_relative_and_interpolated() {
        // Noise 0 at input 0, 0.2 at input 10: at input 5 the noise is 0.1 of the value.
        let t = LookupTable::new(vec![[0.0, 0.0, 0.0], [10.0, 100.0, 0.2]]).unwrap();
        let (value, noise) = t.interpolate(5.0);
        assert_eq!((value, noise), (50.0, 0.1));
        let mut rng = SplitMix64::new(11);
        let mut expected_rng = SplitMix64::new(11);
        let y = t.apply(5.0, &mut rng);
        let expected = 50.0 * (1.0 + 0.1 * gaussian(&mut expected_rng));
        assert_eq!(y, expected);
    }

    #[test]
    fn invalid_tables_are_refused() {
        let e = LookupTable::new(vec![[0.0, 0.0, 0.0], [0.0, 1.0, 0.0]]).unwrap_err();
        assert_eq!(e.field, "lookupTable");
        assert_eq!(e.value, 0.0);
        let e = LookupTable::new(vec![[0.0, f64::NAN, 0.0]]).unwrap_err();
        assert!(e.value.is_nan());
    }
}
