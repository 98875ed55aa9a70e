//! The four Webots engine models: engine-side torque as a function of engine speed.

use ackermann::Real;
use core::fmt;

use crate::error::{Field, PowertrainError, below, finite, positive};

/// The engine model (Webots: `WbuCarEngineType`, `Car` PROTO field `engineType`).
///
/// The discriminant is the Webots enum value.
#[repr(u8)]
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum EngineType {
    /// Combustion engine: torque `a + b·rpm + c·rpm²`, never below `engineMinRPM` (Webots
    /// `"combustion"`, `WBU_CAR_COMBUSTION_ENGINE` = 0; the PROTO default).
    #[default]
    Combustion = 0,
    /// Electric motor: torque `min(engineMaxTorque, engineMaxPower·60/(2π·rpm))` (Webots
    /// `"electric"`, `WBU_CAR_ELECTRIC_ENGINE` = 1).
    Electric = 1,
    /// Parallel hybrid: the combustion curve (only at or above `engineMinRPM`) plus the
    /// electric motor (Webots `"parallel hybrid"`, `WBU_CAR_PARALLEL_HYBRID_ENGINE` = 2).
    ParallelHybrid = 2,
    /// Power-split hybrid: the combustion engine runs at `hybridPowerSplitRPM` and gives a
    /// share `1 − hybridPowerSplitRatio` of its torque to the wheels (only at or above
    /// `engineMinRPM`), plus the electric motor (Webots `"power-split hybrid"`,
    /// `WBU_CAR_POWER_SPLIT_HYBRID_ENGINE` = 3).
    PowerSplitHybrid = 3,
}

impl EngineType {
    /// All four engine types in Webots enum order.
    pub const ALL: [EngineType; 4] = [
        EngineType::Combustion,
        EngineType::Electric,
        EngineType::ParallelHybrid,
        EngineType::PowerSplitHybrid,
    ];

    /// The Webots `WbuCarEngineType` value (0 to 3).
    #[inline]
    pub const fn webots_value(self) -> u8 {
        self as u8
    }

    /// The engine type with Webots `WbuCarEngineType` value `v`, or `None` if `v > 3`.
    #[inline]
    pub const fn from_webots_value(v: u8) -> Option<EngineType> {
        match v {
            0 => Some(EngineType::Combustion),
            1 => Some(EngineType::Electric),
            2 => Some(EngineType::ParallelHybrid),
            3 => Some(EngineType::PowerSplitHybrid),
            _ => None,
        }
    }

    /// The Webots PROTO field spelling: `"combustion"`, `"electric"`, `"parallel hybrid"` or
    /// `"power-split hybrid"`.
    #[inline]
    pub const fn webots_name(self) -> &'static str {
        match self {
            EngineType::Combustion => "combustion",
            EngineType::Electric => "electric",
            EngineType::ParallelHybrid => "parallel hybrid",
            EngineType::PowerSplitHybrid => "power-split hybrid",
        }
    }

    /// Parses the Webots PROTO field spelling (exact), or `None`.
    #[inline]
    pub fn from_webots_name(name: &str) -> Option<EngineType> {
        EngineType::ALL
            .into_iter()
            .find(|t| t.webots_name() == name)
    }

    /// The letter the `Car` PROTO writes into `customData` (token 8): `C`, `E`, `P` or `S`.
    #[inline]
    pub const fn letter(self) -> char {
        match self {
            EngineType::Combustion => 'C',
            EngineType::Electric => 'E',
            EngineType::ParallelHybrid => 'P',
            EngineType::PowerSplitHybrid => 'S',
        }
    }

    /// Decodes the `customData` engine letter as Webots' car library does: `E`, `P` and `S`
    /// select their models, anything else means combustion.
    #[inline]
    pub const fn from_letter(letter: char) -> EngineType {
        match letter {
            'E' => EngineType::Electric,
            'P' => EngineType::ParallelHybrid,
            'S' => EngineType::PowerSplitHybrid,
            _ => EngineType::Combustion,
        }
    }

    /// True if the combustion part obeys the `engineMinRPM` rule (combustion and both hybrids).
    #[inline]
    pub const fn has_combustion(self) -> bool {
        !matches!(self, EngineType::Electric)
    }

    /// True if the model has an electric part (electric and both hybrids).
    #[inline]
    pub const fn has_electric(self) -> bool {
        !matches!(self, EngineType::Combustion)
    }
}

impl fmt::Display for EngineType {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.webots_name())
    }
}

/// The engine fields of the Webots `Car` PROTO. [`Default`] gives the PROTO defaults.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct EngineParams<T: Real> {
    /// Engine model; Webots field `engineType` (default combustion).
    pub engine_type: EngineType,
    /// Cap of the electric torque (N·m, > 0); Webots field `engineMaxTorque` (default 250).
    pub max_torque: T,
    /// Electric power, which sets the electric torque above the base speed (W, > 0); Webots
    /// field `engineMaxPower` (default 50 000).
    pub max_power: T,
    /// Idle speed: the combustion curve is evaluated no lower than this, and hybrids start
    /// their combustion engine here (rpm, > 0); Webots field `engineMinRPM` (default 1000).
    pub min_rpm: T,
    /// Rev limit: no torque at or above this speed, and the rpm estimate saturates here
    /// (rpm, > `min_rpm`); Webots field `engineMaxRPM` (default 4500).
    pub max_rpm: T,
    /// Combustion torque curve `[a, b, c]` of `a + b·rpm + c·rpm²` (N·m, N·m/rpm, N·m/rpm²,
    /// finite); Webots field `engineFunctionCoefficients` (default `[150, 0.1, 0]`).
    pub function_coefficients: [T; 3],
    /// Share of the combustion torque a power-split hybrid sends to its generator
    /// (dimensionless, in [0, 1]); Webots field `hybridPowerSplitRatio` (default 0.25).
    pub hybrid_power_split_ratio: T,
    /// Constant combustion-engine speed of a power-split hybrid (rpm, > 0); Webots field
    /// `hybridPowerSplitRPM` (default 3000).
    pub hybrid_power_split_rpm: T,
}

impl EngineParams<f64> {
    /// The Webots `Car` PROTO defaults: combustion, 250 N·m, 50 000 W, 1000 to 4500 rpm,
    /// torque `150 + 0.1·rpm`, split ratio 0.25 at 3000 rpm. A constant, for tables of
    /// presets; [`Default`] gives it in any scalar type.
    pub const DEFAULT: Self = EngineParams {
        engine_type: EngineType::Combustion,
        max_torque: 250.0,
        max_power: 50_000.0,
        min_rpm: 1000.0,
        max_rpm: 4500.0,
        function_coefficients: [150.0, 0.1, 0.0],
        hybrid_power_split_ratio: 0.25,
        hybrid_power_split_rpm: 3000.0,
    };
}

impl<T: Real> EngineParams<T> {
    /// The same fields in scalar type `U` (each value rounded to the nearest `U`).
    pub fn cast<U: Real>(self) -> EngineParams<U> {
        let f = |v: T| U::from_f64(v.to_f64());
        EngineParams {
            engine_type: self.engine_type,
            max_torque: f(self.max_torque),
            max_power: f(self.max_power),
            min_rpm: f(self.min_rpm),
            max_rpm: f(self.max_rpm),
            function_coefficients: self.function_coefficients.map(f),
            hybrid_power_split_ratio: f(self.hybrid_power_split_ratio),
            hybrid_power_split_rpm: f(self.hybrid_power_split_rpm),
        }
    }
}

impl<T: Real> Default for EngineParams<T> {
    /// [`EngineParams::DEFAULT`], the Webots `Car` PROTO defaults.
    fn default() -> Self {
        EngineParams::DEFAULT.cast()
    }
}

/// A validated engine model (spec §2.4). Built with [`Engine::new`].
///
/// ```
/// use powertrain::{Engine, EngineParams, EngineType};
/// // Tesla Model 3: electric, 639 N·m, 147 kW.
/// let tesla = Engine::new(EngineParams {
///     engine_type: EngineType::Electric,
///     max_torque: 639.0_f64,
///     max_power: 147_000.0,
///     max_rpm: 25_000.0,
///     ..EngineParams::default()
/// })?;
/// assert_eq!(tesla.torque(0.0), 639.0); // full torque from standstill
/// // 147 000 W · 60 / (2π · 5000 rpm) = 280.749 N·m: power limited.
/// assert!((tesla.torque(5000.0) - 280.749_319_614).abs() < 1e-6);
/// # Ok::<(), powertrain::PowertrainError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Engine<T: Real> {
    params: EngineParams<T>,
}

impl<T: Real> Engine<T> {
    /// Validates `params`.
    ///
    /// # Errors
    /// [`PowertrainError`] naming the first offending field: `engineMaxTorque`,
    /// `engineMaxPower`, `engineMinRPM`, `engineMaxRPM` and `hybridPowerSplitRPM` must be finite
    /// and > 0, `engineMinRPM < engineMaxRPM`, the coefficients must be finite and
    /// `hybridPowerSplitRatio` must lie in [0, 1]. All fields are checked whatever the engine
    /// type, so a model can switch type without becoming invalid.
    pub fn new(params: EngineParams<T>) -> Result<Self, PowertrainError> {
        let limits = [
            (Field::EngineMaxTorque, params.max_torque),
            (Field::EngineMaxPower, params.max_power),
            (Field::EngineMinRpm, params.min_rpm),
            (Field::EngineMaxRpm, params.max_rpm),
        ];
        for (field, value) in limits {
            positive(field, value)?;
        }
        below(
            Field::EngineMinRpm,
            params.min_rpm,
            Field::EngineMaxRpm,
            params.max_rpm,
        )?;
        for c in params.function_coefficients {
            finite(Field::EngineFunctionCoefficients, c)?;
        }
        let ratio = finite(
            Field::HybridPowerSplitRatio,
            params.hybrid_power_split_ratio,
        )?;
        if !(T::ZERO..=T::ONE).contains(&ratio) {
            return Err(PowertrainError::OutOfRange {
                field: Field::HybridPowerSplitRatio,
                value: ratio.to_f64(),
                min: 0.0,
                max: 1.0,
            });
        }
        positive(Field::HybridPowerSplitRpm, params.hybrid_power_split_rpm)?;
        Ok(Engine { params })
    }

    /// The validated parameters.
    #[inline]
    pub const fn params(&self) -> &EngineParams<T> {
        &self.params
    }

    /// The engine model.
    #[inline]
    pub const fn engine_type(&self) -> EngineType {
        self.params.engine_type
    }

    /// Idle / engine-on speed (rpm); Webots field `engineMinRPM`.
    #[inline]
    pub const fn min_rpm(&self) -> T {
        self.params.min_rpm
    }

    /// Rev limit (rpm); Webots field `engineMaxRPM`.
    #[inline]
    pub const fn max_rpm(&self) -> T {
        self.params.max_rpm
    }

    /// Engine-side torque (N·m) at engine speed `rpm` (rev/min), before throttle and gear
    /// ratio (Webots: `compute_output_torque` in `driver.c`, spec §2.4).
    ///
    /// * Combustion: `f(max(rpm, engineMinRPM))` with `f(x) = a + b·x + c·x²`.
    /// * Electric: `min(engineMaxTorque, engineMaxPower·60/(2π·rpm))`, which is
    ///   `engineMaxTorque` at 0 rpm.
    /// * Parallel hybrid: `f(rpm)` if `rpm ≥ engineMinRPM` (else 0), plus the electric part.
    /// * Power-split hybrid: `(1 − hybridPowerSplitRatio)·f(hybridPowerSplitRPM)` if
    ///   `rpm ≥ engineMinRPM` (else 0), plus the electric part.
    ///
    /// At or above `engineMaxRPM` the torque is 0 for every model: Webots zeroes the output
    /// when its (saturated) rpm estimate reaches `engineMaxRPM`, which is the same condition.
    /// The sign of `rpm` is ignored (Webots' estimate is never negative) and NaN counts as 0 rpm.
    /// The combustion curve is not clamped, so a curve that goes negative gives a negative
    /// (braking) torque, as in Webots. A result that overflows the scalar type (only possible
    /// with absurd coefficients) is returned as 0.
    pub fn torque(&self, rpm: T) -> T {
        let p = &self.params;
        let real = if rpm.is_nan() { T::ZERO } else { rpm.abs() };
        if real >= p.max_rpm {
            return T::ZERO;
        }
        let engine_on = real >= p.min_rpm;
        let combustion = match p.engine_type {
            EngineType::Combustion => self.curve(real.max(p.min_rpm)),
            EngineType::Electric => T::ZERO,
            EngineType::ParallelHybrid if engine_on => self.curve(real),
            EngineType::PowerSplitHybrid if engine_on => {
                (T::ONE - p.hybrid_power_split_ratio) * self.curve(p.hybrid_power_split_rpm)
            }
            EngineType::ParallelHybrid | EngineType::PowerSplitHybrid => T::ZERO,
        };
        let electric = if p.engine_type.has_electric() {
            self.electric(real)
        } else {
            T::ZERO
        };
        (combustion + electric).finite_or(T::ZERO)
    }

    /// The combustion curve `a + b·x + c·x²` (N·m) at `x` rpm.
    #[inline]
    fn curve(&self, x: T) -> T {
        let [a, b, c] = self.params.function_coefficients;
        a + b * x + c * x * x
    }

    /// The electric part (N·m) at `rpm` ≥ 0: constant torque up to the base speed, then
    /// constant power.
    #[inline]
    fn electric(&self, rpm: T) -> T {
        let p = &self.params;
        if rpm <= T::ZERO {
            return p.max_torque;
        }
        (p.max_power * T::from_f64(60.0) / (T::TAU * rpm)).min(p.max_torque)
    }
}

impl<T: Real> Default for Engine<T> {
    /// The Webots `Car` PROTO default engine (see [`EngineParams::default`]).
    fn default() -> Self {
        Engine {
            params: EngineParams::default(),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn engine(p: EngineParams<f64>) -> Result<Engine<f64>, PowertrainError> {
        Engine::new(p)
    }

    #[test]
    fn default_params_are_valid_and_match_the_proto() {
        let e = engine(EngineParams::default()).unwrap();
        assert_eq!(e, Engine::default());
        // 150 + 0.1·1000 = 250 N·m at idle (the min-rpm rule applies at 0 rpm too).
        assert!((e.torque(0.0) - 250.0).abs() < 1e-12);
        // 150 + 0.1·2000 = 350 N·m.
        assert!((e.torque(2000.0) - 350.0).abs() < 1e-12);
    }

    #[test]
    fn engine_letters_and_names_round_trip() {
        for t in EngineType::ALL {
            assert_eq!(EngineType::from_letter(t.letter()), t);
            assert_eq!(EngineType::from_webots_name(t.webots_name()), Some(t));
            assert_eq!(EngineType::from_webots_value(t.webots_value()), Some(t));
        }
        assert_eq!(EngineType::from_letter('x'), EngineType::Combustion);
        assert_eq!(EngineType::from_webots_value(4), None);
        assert_eq!(EngineType::from_webots_name("hybrid"), None);
    }

    #[test]
    fn invalid_params_name_the_field() {
        let bad = |p: EngineParams<f64>| engine(p).unwrap_err();
        let d = EngineParams::default();
        assert_eq!(
            bad(EngineParams {
                max_torque: -1.0,
                ..d
            }),
            PowertrainError::NotPositive {
                field: Field::EngineMaxTorque,
                value: -1.0
            }
        );
        assert_eq!(
            bad(EngineParams {
                max_power: f64::NAN,
                ..d
            })
            .field(),
            Some(Field::EngineMaxPower)
        );
        assert_eq!(
            bad(EngineParams {
                min_rpm: 5000.0,
                ..d
            }),
            PowertrainError::NotBelow {
                field: Field::EngineMinRpm,
                value: 5000.0,
                limit_field: Field::EngineMaxRpm,
                limit: 4500.0
            }
        );
        assert_eq!(
            bad(EngineParams {
                max_rpm: 1000.0,
                ..d
            })
            .field(),
            Some(Field::EngineMinRpm)
        );
        assert_eq!(
            bad(EngineParams {
                function_coefficients: [1.0, f64::INFINITY, 0.0],
                ..d
            })
            .field(),
            Some(Field::EngineFunctionCoefficients)
        );
        assert_eq!(
            bad(EngineParams {
                hybrid_power_split_ratio: 1.5,
                ..d
            }),
            PowertrainError::OutOfRange {
                field: Field::HybridPowerSplitRatio,
                value: 1.5,
                min: 0.0,
                max: 1.0
            }
        );
        assert_eq!(
            bad(EngineParams {
                hybrid_power_split_rpm: 0.0,
                ..d
            })
            .field(),
            Some(Field::HybridPowerSplitRpm)
        );
    }

    #[test]
    fn error_display_uses_webots_field_names() {
        extern crate std;
        use std::string::ToString;
        let e = engine(EngineParams {
            min_rpm: 5000.0,
            ..EngineParams::default()
        })
        .unwrap_err();
        assert_eq!(
            e.to_string(),
            "invalid engineMinRPM: 5000 rpm (must be < engineMaxRPM = 4500 rpm)"
        );
        let e = engine(EngineParams {
            max_torque: 0.0,
            ..EngineParams::default()
        })
        .unwrap_err();
        assert_eq!(
            e.to_string(),
            "invalid engineMaxTorque: 0 N·m (must be > 0)"
        );
    }

    #[test]
    fn split_ratio_bounds_are_inclusive() {
        for r in [0.0, 1.0] {
            let e = engine(EngineParams {
                engine_type: EngineType::PowerSplitHybrid,
                hybrid_power_split_ratio: r,
                ..EngineParams::default()
            })
            .unwrap();
            // Default curve at 3000 rpm: 150 + 300 = 450 N·m; at 2000 rpm the electric part is
            // min(250, 50 000·60/(2π·2000)) = 238.732 N·m.
            let electric = 50_000.0 * 60.0 / (core::f64::consts::TAU * 2000.0);
            let expected = (1.0 - r) * 450.0 + electric;
            assert!((e.torque(2000.0) - expected).abs() < 1e-9);
        }
    }

    #[test]
    fn negative_and_nan_rpm_are_handled() {
        let e = engine(EngineParams {
            engine_type: EngineType::Electric,
            ..EngineParams::default()
        })
        .unwrap();
        assert_eq!(e.torque(-2000.0), e.torque(2000.0));
        assert_eq!(e.torque(f64::NAN), 250.0);
        assert_eq!(e.torque(f64::INFINITY), 0.0);
        assert_eq!(e.torque(f64::NEG_INFINITY), 0.0);
    }

    #[test]
    fn overflowing_curve_gives_zero_not_infinity() {
        let e = Engine::<f32>::new(EngineParams {
            function_coefficients: [3.0e38, 3.0e38, 0.0],
            ..EngineParams::default()
        })
        .unwrap();
        assert_eq!(e.torque(2000.0), 0.0);
    }
}
