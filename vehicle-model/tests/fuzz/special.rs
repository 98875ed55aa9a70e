//! The numbers that broke things before, which every fuzzer weights its inputs towards: NaN,
//! ±∞, the extremes, zeros of both signs, subnormals and a few ordinary values.
//!
//! One list for the property tests (`strategies.rs` here, `capi/tests/fuzz`), the bad-input
//! tests (`tests/bad_input.rs`) and the coverage-guided targets
//! (`fuzz/fuzz_targets/values.rs`), which include this file by path.

/// The special values, drawn often by every hostile-number generator.
pub const SPECIAL: [f64; 19] = [
    f64::NAN,
    f64::INFINITY,
    f64::NEG_INFINITY,
    1e300,
    -1e300,
    f64::MAX,
    f64::MIN,
    -1e308,
    3.5e38,
    -0.0,
    0.0,
    f64::MIN_POSITIVE,
    1e-300,
    5e-324,
    0.5,
    1.0,
    -1.0,
    30.0,
    -7.0,
];
