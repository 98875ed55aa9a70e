//! The coefficients of [`super`]'s polynomials and rationals, fitted for this crate (see
//! [`super`] for how).

/// `R` of `atan(x) = x − x³·R` for `z = x²` in [0, 1/2], in the basis its evaluation uses:
/// `R = Σ (c[2i] + c[2i+1]·z)·s^(2i)`, `s = z − 1/4`. The shifted variable keeps the
/// coefficients falling where those in `z` alone would not; the pairs in `z` start as soon as `z`
/// is known, a step before `s`. The exact leading `x` leaves the rounding errors of the sum to a
/// term below 0.15·x. Two halves of [0, 1] in `z`, 16 terms each, take one Estrin level less
/// than the 20 terms the whole interval needs for the same accuracy. Fit error 9.1e-19 relative
/// to `atan(x)`.
#[rustfmt::skip]
pub(super) const ATAN_LO_F64: [f64; 16] = [
    0.3270478199838777,
    -0.1449147679613066,
    0.09790998624745378,
    -0.053344585763684726,
    0.04125833547436594,
    -0.024030798151466276,
    0.019721173157208307,
    -0.011876191222813196,
    0.010078972692248543,
    -0.006192811853986142,
    0.005370611521611569,
    -0.0033419395883401387,
    0.002936247999979227,
    -0.0018766235459306286,
    0.0018134179832217565,
    -0.0010005221273994421,
];

/// As [`ATAN_LO_F64`] for `z` in [1/2, 1], `s = z − 3/4` (a term below 0.22·x): fit error
/// 2.5e-19 relative to `atan(x)`.
#[rustfmt::skip]
pub(super) const ATAN_HI_F64: [f64; 16] = [
    0.30049263221265493,
    -0.08801315338917157,
    0.05089945818133536,
    -0.01740587548579843,
    0.011418024053603388,
    -0.004106112373867438,
    0.0028516369938872267,
    -0.0010519552046394213,
    0.0007550867668339006,
    -0.0002829005922822956,
    0.00020749689756151144,
    -7.854307727721617e-05,
    5.856980647698406e-05,
    -2.2496374022372745e-05,
    1.733725028058471e-05,
    -6.023959772335727e-06,
];

/// `R` of `atan(x) = x − x³·R(x² − 1/2)` for x in [0, 1], `f32`: fit error 4.9e-9 relative to
/// `atan(x)`.
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
