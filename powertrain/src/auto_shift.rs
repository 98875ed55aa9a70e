//! An optional automatic gearbox (not in Webots).

use ackermann::Real;

use crate::engine::Engine;
use crate::error::{Field, PowertrainError, below, finite, positive};
use crate::gearbox::{Gear, Gearbox};

/// Tuning of [`AutoShift`].
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AutoShiftParams<T: Real> {
    /// Shift up when the engine speed reaches this (rpm, > `downshift_rpm`,
    /// < `engineMaxRPM`).
    pub upshift_rpm: T,
    /// Shift down when the engine speed falls to this (rpm, > 0). The gap to `upshift_rpm` is
    /// the hysteresis.
    pub downshift_rpm: T,
    /// Minimum time between two shifts (s, ≥ 0).
    pub min_shift_interval: T,
}

impl<T: Real> AutoShiftParams<T> {
    /// Defaults derived from an engine's speed range `[min, max]` (rpm): up-shift at
    /// `min + 0.85·(max − min)`, down-shift at `min + 0.25·(max − min)`, at most one shift per
    /// second. Valid for that engine unless `engineMinRPM` and `engineMaxRPM` are so close
    /// that `T` cannot represent distinct thresholds between them (e.g. 1000 and 1000.0001 rpm
    /// in `f32`); [`AutoShift::new`] then reports it.
    pub fn for_engine(engine: &Engine<T>) -> Self {
        let min = engine.min_rpm();
        let span = engine.max_rpm() - min;
        AutoShiftParams {
            upshift_rpm: min + T::from_f64(0.85) * span,
            downshift_rpm: min + T::from_f64(0.25) * span,
            min_shift_interval: T::ONE,
        }
    }
}

/// An automatic gearbox for torque mode, beyond Webots (which has none). Opt-in: nothing
/// shifts unless the caller runs [`AutoShift::update`] and engages the gear it returns, so
/// Webots behaviour is unchanged by default.
///
/// It only acts in forward gears and never selects neutral or reverse: it shifts up at
/// `upshift_rpm`, down at `downshift_rpm` (only when the lower gear would stay below
/// `upshift_rpm`, so a shift never triggers the opposite shift), and waits
/// `min_shift_interval` between shifts.
///
/// ```
/// use powertrain::{AutoShift, AutoShiftParams, Engine, Gear, Gearbox};
/// let engine = Engine::<f64>::default(); // 1000 to 4500 rpm
/// let gearbox = Gearbox::default(); // R, 10, 6.5, 4.5, 3.5, 2.75
/// let mut auto = AutoShift::new(AutoShiftParams::for_engine(&engine), &engine)?;
/// // Up-shift threshold 1000 + 0.85·3500 = 3975 rpm.
/// assert_eq!(auto.update(0.01, 4000.0, Gear::FIRST, &gearbox), Gear::forward(2));
/// // Too soon after that shift (1 s minimum): nothing.
/// assert_eq!(auto.update(0.01, 4000.0, Gear::forward(2).unwrap(), &gearbox), None);
/// # Ok::<(), powertrain::PowertrainError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct AutoShift<T: Real> {
    params: AutoShiftParams<T>,
    /// Time since the last shift (s), saturated at `min_shift_interval`.
    since_shift: T,
}

impl<T: Real> AutoShift<T> {
    /// Validates `params` against `engine`; ready to shift immediately.
    ///
    /// # Errors
    /// [`PowertrainError`] naming the field: `upshift_rpm` and `downshift_rpm` must be finite
    /// and > 0, `downshift_rpm < upshift_rpm < engineMaxRPM` (the engine-speed estimate never
    /// exceeds `engineMaxRPM`), and `min_shift_interval` must be finite and ≥ 0.
    pub fn new(params: AutoShiftParams<T>, engine: &Engine<T>) -> Result<Self, PowertrainError> {
        positive(Field::UpshiftRpm, params.upshift_rpm)?;
        positive(Field::DownshiftRpm, params.downshift_rpm)?;
        below(
            Field::DownshiftRpm,
            params.downshift_rpm,
            Field::UpshiftRpm,
            params.upshift_rpm,
        )?;
        below(
            Field::UpshiftRpm,
            params.upshift_rpm,
            Field::EngineMaxRpm,
            engine.max_rpm(),
        )?;
        let interval = finite(Field::MinShiftInterval, params.min_shift_interval)?;
        if interval < T::ZERO {
            return Err(PowertrainError::Negative {
                field: Field::MinShiftInterval,
                value: interval.to_f64(),
            });
        }
        Ok(AutoShift {
            params,
            since_shift: interval,
        })
    }

    /// The validated tuning.
    #[inline]
    pub const fn params(&self) -> &AutoShiftParams<T> {
        &self.params
    }

    /// Forgets the last shift, so the next [`AutoShift::update`] may shift at once.
    #[inline]
    pub fn reset(&mut self) {
        self.since_shift = self.params.min_shift_interval;
    }

    /// Advances the shift timer by `dt` (s; NaN, ∞ or negative count as 0) and returns the gear
    /// to engage, or `None` to keep `gear`, given the current engine speed `rpm` (rpm, sign
    /// ignored, e.g. from [`crate::Powertrain::rpm`]).
    ///
    /// Returns `None` in neutral, in reverse, in a gear `gearbox` does not have, for a NaN
    /// `rpm`, and until `min_shift_interval` has elapsed since the last shift.
    pub fn update(&mut self, dt: T, rpm: T, gear: Gear, gearbox: &Gearbox<T>) -> Option<Gear> {
        let dt = if dt.is_finite() && dt > T::ZERO {
            dt
        } else {
            T::ZERO
        };
        // Engine speed is a magnitude, as in `Engine::torque`.
        let rpm = rpm.abs();
        let interval = self.params.min_shift_interval;
        self.since_shift = (self.since_shift + dt).min(interval);
        if !gear.is_forward() || !gearbox.has(gear) || rpm.is_nan() || self.since_shift < interval {
            return None;
        }
        let next = if rpm >= self.params.upshift_rpm {
            gear.up().filter(|&g| gearbox.has(g))
        } else if rpm <= self.params.downshift_rpm {
            gear.down().filter(|&g| {
                let lower_rpm = rpm * (gearbox.ratio(g) / gearbox.ratio(gear)).abs();
                lower_rpm < self.params.upshift_rpm
            })
        } else {
            None
        };
        if next.is_some() {
            self.since_shift = T::ZERO;
        }
        next
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::EngineParams;

    fn setup(interval: f64) -> (AutoShift<f64>, Gearbox<f64>) {
        let engine = Engine::default();
        let params = AutoShiftParams {
            min_shift_interval: interval,
            ..AutoShiftParams::for_engine(&engine)
        };
        (AutoShift::new(params, &engine).unwrap(), Gearbox::default())
    }

    fn g(n: u8) -> Gear {
        Gear::forward(n).unwrap()
    }

    #[test]
    fn for_engine_thresholds() {
        let p = AutoShiftParams::for_engine(&Engine::<f64>::default());
        // 1000 + 0.85·3500 = 3975; 1000 + 0.25·3500 = 1875.
        assert!((p.upshift_rpm - 3975.0).abs() < 1e-9);
        assert!((p.downshift_rpm - 1875.0).abs() < 1e-9);
        assert_eq!(p.min_shift_interval, 1.0);
    }

    #[test]
    fn shifts_up_and_down_with_hysteresis() {
        let (mut a, gb) = setup(0.0);
        assert_eq!(a.update(0.01, 3975.0, g(1), &gb), Some(g(2)));
        assert_eq!(a.update(0.01, 3974.0, g(2), &gb), None);
        assert_eq!(a.update(0.01, 2000.0, g(2), &gb), None); // inside the band
        // 1875 in 2nd (6.5) would be 1875·10/6.5 = 2884.6 in 1st < 3975: down.
        assert_eq!(a.update(0.01, 1875.0, g(2), &gb), Some(g(1)));
        // Never below first, never above the highest.
        assert_eq!(a.update(0.01, 0.0, g(1), &gb), None);
        assert_eq!(a.update(0.01, 4500.0, g(5), &gb), None);
    }

    #[test]
    fn downshift_that_would_overrev_is_refused() {
        let engine = Engine::default();
        // Wide ratio gap (10 → 2): 1800 rpm in 2nd would be 9000 in 1st.
        let gb = Gearbox::new(&[-10.0, 10.0, 2.0]).unwrap();
        let mut a = AutoShift::new(AutoShiftParams::for_engine(&engine), &engine).unwrap();
        assert_eq!(a.update(0.0, 1800.0, g(2), &gb), None);
        // 700 rpm in 2nd → 3500 in 1st < 3975: allowed.
        assert_eq!(a.update(0.0, 700.0, g(2), &gb), Some(g(1)));
    }

    #[test]
    fn waits_between_shifts() {
        let (mut a, gb) = setup(0.5);
        assert_eq!(a.update(0.0, 4000.0, g(1), &gb), Some(g(2)));
        assert_eq!(a.update(0.3, 4000.0, g(2), &gb), None); // 0.3 s
        assert_eq!(a.update(f64::NAN, 4000.0, g(2), &gb), None); // still 0.3 s
        assert_eq!(a.update(-5.0, 4000.0, g(2), &gb), None);
        assert_eq!(a.update(0.2, 4000.0, g(2), &gb), Some(g(3))); // 0.5 s
        assert_eq!(a.update(f64::INFINITY, 4000.0, g(3), &gb), None);
        a.reset();
        assert_eq!(a.update(0.0, 4000.0, g(3), &gb), Some(g(4)));
    }

    #[test]
    fn never_leaves_neutral_or_reverse() {
        let (mut a, gb) = setup(0.0);
        for rpm in [0.0, 1000.0, 4400.0] {
            assert_eq!(a.update(1.0, rpm, Gear::NEUTRAL, &gb), None);
            assert_eq!(a.update(1.0, rpm, Gear::REVERSE, &gb), None);
        }
        assert_eq!(a.update(1.0, f64::NAN, g(1), &gb), None);
        // Negative speeds count by magnitude: −4000 rpm shifts up like 4000.
        assert_eq!(a.update(1.0, -4000.0, g(1), &gb), Some(g(2)));
        // A gear this gearbox does not have is left alone.
        assert_eq!(a.update(1.0, 0.0, g(9), &gb), None);
    }

    #[test]
    fn invalid_params_are_rejected() {
        let engine = Engine::<f64>::new(EngineParams::default()).unwrap();
        let ok = AutoShiftParams::for_engine(&engine);
        let err = |p| AutoShift::new(p, &engine).unwrap_err();
        assert_eq!(
            err(AutoShiftParams {
                upshift_rpm: 4500.0,
                ..ok
            }),
            PowertrainError::NotBelow {
                field: Field::UpshiftRpm,
                value: 4500.0,
                limit_field: Field::EngineMaxRpm,
                limit: 4500.0
            }
        );
        assert_eq!(
            err(AutoShiftParams {
                downshift_rpm: 4000.0,
                ..ok
            })
            .field(),
            Some(Field::DownshiftRpm)
        );
        assert_eq!(
            err(AutoShiftParams {
                downshift_rpm: f64::NAN,
                ..ok
            })
            .field(),
            Some(Field::DownshiftRpm)
        );
        assert_eq!(
            err(AutoShiftParams {
                min_shift_interval: -1.0,
                ..ok
            }),
            PowertrainError::Negative {
                field: Field::MinShiftInterval,
                value: -1.0
            }
        );
        assert_eq!(
            err(AutoShiftParams {
                min_shift_interval: f64::INFINITY,
                ..ok
            })
            .field(),
            Some(Field::MinShiftInterval)
        );
    }
}
