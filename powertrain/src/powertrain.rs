//! Engine plus gearbox: the engine-speed estimate and the wheel-side output torque.

use ackermann::{PerWheel, Real};

use crate::engine::Engine;
use crate::gearbox::{Gear, Gearbox};

/// Wheel angular acceleration (rad/s²) above which the output torque is scaled down (Webots:
/// `ACCELERATION_THRESHOLD` in `driver.c`), to stop an airborne driven wheel from spinning up
/// without bound.
pub const WHEEL_ACCELERATION_LIMIT: f64 = 50.0;

/// rad/s → rev/min.
#[inline]
fn rad_s_to_rpm<T: Real>(w: T) -> T {
    w * T::from_f64(60.0) / T::TAU
}

/// The mean of the four wheel speeds (rad/s), NaN if any is NaN (Webots uses all four wheels,
/// driven or not, for the engine-speed estimate).
#[inline]
pub fn mean_wheel_speed<T: Real>(wheel_speeds: &PerWheel<T>) -> T {
    let [a, b, c, d] = *wheel_speeds.as_array();
    (a + b + c + d) / T::from_f64(4.0)
}

/// The signed wheel acceleration (rad/s²) with the largest magnitude, as Webots selects the
/// input of the wheel-acceleration limiter (spec §2.2): NaN values never win, and 0 is
/// returned if all are NaN or zero.
pub fn max_signed_acceleration<T: Real>(wheel_accelerations: &PerWheel<T>) -> T {
    wheel_accelerations.iter().fold(
        T::ZERO,
        |best, &a| if a.abs() > best.abs() { a } else { best },
    )
}

/// The factor (dimensionless, in [0, 1]) the output torque is multiplied by for a given signed
/// maximum wheel acceleration (rad/s²): 1 up to [`WHEEL_ACCELERATION_LIMIT`], then
/// `50 / |a|`. NaN counts as no acceleration (factor 1), ±∞ gives 0.
#[inline]
pub fn acceleration_limit_factor<T: Real>(max_wheel_acceleration: T) -> T {
    let limit = T::from_f64(WHEEL_ACCELERATION_LIMIT);
    let a = max_wheel_acceleration.abs();
    if a > limit { limit / a } else { T::ONE }
}

/// The gear Webots pretends to be in for the engine sound in speed (cruise-control) mode,
/// where no gear is engaged (spec §3.5).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct VirtualGear<T: Real> {
    /// Reverse when the car rolls backwards, else the lowest forward gear that keeps the
    /// engine below `(2·engineMinRPM + engineMaxRPM)/3`, or the highest gear if none does.
    pub gear: Gear,
    /// The engine speed in that gear (rpm, ≥ 0, not limited to `engineMaxRPM`).
    pub rpm: T,
}

/// An engine and its gearbox: turns wheel speeds into an engine speed and throttle into a
/// wheel-side torque, as the Webots driver library does in torque mode (spec §2.3–§2.4).
///
/// ```
/// use ackermann::PerWheel;
/// use powertrain::{Engine, EngineParams, Gear, Gearbox, Powertrain};
/// let pt = Powertrain::new(Engine::<f64>::default(), Gearbox::default());
/// // 10 rad/s on every wheel in first gear (ratio 10): 10·60/(2π)·10 = 954.93 rpm.
/// let rpm = pt.rpm(&PerWheel::splat(10.0), Gear::FIRST);
/// assert!((rpm - 954.929_658_55).abs() < 1e-6);
/// // Below engineMinRPM the default combustion engine gives f(1000) = 250 N·m;
/// // half throttle through ratio 10: 1250 N·m at the wheels.
/// assert!((pt.output_torque(rpm, 0.5, Gear::FIRST, 0.0) - 1250.0).abs() < 1e-9);
/// ```
#[derive(Debug, Clone, PartialEq, Default)]
pub struct Powertrain<T: Real> {
    engine: Engine<T>,
    gearbox: Gearbox<T>,
}

impl<T: Real> Powertrain<T> {
    /// Combines a validated engine and gearbox.
    #[inline]
    pub const fn new(engine: Engine<T>, gearbox: Gearbox<T>) -> Self {
        Powertrain { engine, gearbox }
    }

    /// The engine.
    #[inline]
    pub const fn engine(&self) -> &Engine<T> {
        &self.engine
    }

    /// The gearbox.
    #[inline]
    pub const fn gearbox(&self) -> &Gearbox<T> {
        &self.gearbox
    }

    /// Estimated engine speed (rpm, in [0, `engineMaxRPM`]) from the four wheel speeds (rad/s)
    /// in `gear` (Webots: spec §2.3): the mean wheel speed in rev/min times the gear's ratio
    /// magnitude, 0 in neutral (no idle model), 0 if NaN, saturated at `engineMaxRPM` (also
    /// for infinite speeds).
    pub fn rpm(&self, wheel_speeds: &PerWheel<T>, gear: Gear) -> T {
        if gear.is_neutral() {
            return T::ZERO;
        }
        let wheel_rpm = rad_s_to_rpm(mean_wheel_speed(wheel_speeds));
        let rpm = (wheel_rpm * self.gearbox.ratio(gear)).abs();
        if rpm.is_nan() {
            T::ZERO
        } else {
            rpm.min(self.engine.max_rpm())
        }
    }

    /// Wheel-side output torque (N·m, to be split between the driven wheels) for engine speed
    /// `rpm` (rpm, normally from [`Powertrain::rpm`]), `throttle` (dimensionless), `gear` and
    /// the signed maximum wheel acceleration (rad/s², see [`max_signed_acceleration`])
    /// (Webots: `compute_output_torque`, spec §2.4):
    ///
    /// `engine.torque(rpm) · throttle · ratio(gear) · acceleration_limit_factor(acc)`.
    ///
    /// Zero in neutral and at or above `engineMaxRPM`; negative in reverse for a negative
    /// reverse ratio. `throttle` is clamped to [0, 1] (NaN → 0), as Webots' setter does for
    /// finite values. Never NaN or ±∞.
    pub fn output_torque(&self, rpm: T, throttle: T, gear: Gear, max_wheel_acceleration: T) -> T {
        if gear.is_neutral() {
            return T::ZERO;
        }
        let throttle = if throttle.is_nan() {
            T::ZERO
        } else {
            throttle.clamp(T::ZERO, T::ONE)
        };
        let out = self.engine.torque(rpm) * throttle * self.gearbox.ratio(gear);
        (out * acceleration_limit_factor(max_wheel_acceleration)).finite_or(T::ZERO)
    }

    /// The wheel speed (rad/s, > 0) at which the engine reaches `engineMaxRPM` in `gear`:
    /// `engineMaxRPM·2π/60/|ratio|`. Above it the rpm estimate saturates and the output torque
    /// is 0, so this is the top speed of the gear (multiply by the tyre radius for m/s).
    /// `None` in neutral. Saturates at `T::MAX` when the quotient overflows (a ratio so close
    /// to 0 that the gear has no representable top speed), so it is never ∞.
    pub fn saturation_wheel_speed(&self, gear: Gear) -> Option<T> {
        if gear.is_neutral() {
            return None;
        }
        let w = self.engine.max_rpm() * T::TAU / T::from_f64(60.0) / self.gearbox.ratio(gear).abs();
        Some(w.min(T::MAX))
    }

    /// The speed-mode "virtual gear" and engine speed Webots uses for the engine sound
    /// (spec §3.5): wheel speed in rev/min `n` from the mean of the four wheel speeds (rad/s);
    /// reverse if `n < 0`, else the first forward gear `k` with
    /// `|n·ratio(k)| < (2·engineMinRPM + engineMaxRPM)/3`, or the highest gear if none.
    /// `None` when the mean wheel speed is NaN (Webots skips the sound update) or infinite.
    pub fn speed_mode_virtual_gear(&self, wheel_speeds: &PerWheel<T>) -> Option<VirtualGear<T>> {
        let n = rad_s_to_rpm(mean_wheel_speed(wheel_speeds));
        if !n.is_finite() {
            return None;
        }
        let gear = if n < T::ZERO {
            Gear::REVERSE
        } else {
            let threshold =
                (T::TWO * self.engine.min_rpm() + self.engine.max_rpm()) / T::from_f64(3.0);
            let highest = self.gearbox.highest_gear();
            let mut gear = Gear::FIRST;
            while (n * self.gearbox.ratio(gear)).abs() >= threshold && gear < highest {
                gear = gear.up().unwrap_or(highest);
            }
            gear
        };
        let rpm = (n * self.gearbox.ratio(gear)).abs();
        rpm.is_finite().then_some(VirtualGear { gear, rpm })
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::engine::{EngineParams, EngineType};

    fn prius() -> Powertrain<f64> {
        let engine = Engine::new(EngineParams {
            engine_type: EngineType::PowerSplitHybrid,
            max_torque: 350.0,
            max_power: 33_000.0,
            min_rpm: 1200.0,
            max_rpm: 6500.0,
            function_coefficients: [65.0, 0.0225, -0.000_002_5],
            hybrid_power_split_ratio: 0.2778,
            hybrid_power_split_rpm: 3000.0,
        })
        .unwrap();
        Powertrain::new(engine, Gearbox::new(&[-6.0, 6.0]).unwrap())
    }

    #[test]
    fn max_signed_acceleration_follows_webots() {
        let a = PerWheel::new(3.0_f64, -70.0, f64::NAN, 60.0);
        assert_eq!(max_signed_acceleration(&a), -70.0);
        assert_eq!(max_signed_acceleration(&PerWheel::splat(f64::NAN)), 0.0);
        let b = PerWheel::new(f64::NEG_INFINITY, 1.0, 2.0, 3.0);
        assert_eq!(max_signed_acceleration(&b), f64::NEG_INFINITY);
    }

    #[test]
    fn acceleration_limiter() {
        assert_eq!(acceleration_limit_factor(50.0_f64), 1.0);
        assert_eq!(acceleration_limit_factor(-10.0_f64), 1.0);
        // 50/200 = 0.25, whatever the sign.
        assert_eq!(acceleration_limit_factor(200.0_f64), 0.25);
        assert_eq!(acceleration_limit_factor(-200.0_f64), 0.25);
        assert_eq!(acceleration_limit_factor(f64::NAN), 1.0);
        assert_eq!(acceleration_limit_factor(f32::INFINITY), 0.0);
    }

    #[test]
    fn rpm_estimate() {
        let pt = prius();
        // Mean of (1, 2, 3, 6) = 3 rad/s → 3·60/(2π) = 28.6479 rev/min; ×6 = 171.887 rpm.
        let w = PerWheel::new(1.0, 2.0, 3.0, 6.0);
        let expected = 3.0 * 60.0 / (2.0 * core::f64::consts::PI) * 6.0;
        assert!((pt.rpm(&w, Gear::FIRST) - expected).abs() < 1e-9);
        // Reverse uses −gearRatio[0] = 6 and the result is a magnitude.
        assert!((pt.rpm(&w, Gear::REVERSE) - expected).abs() < 1e-9);
        assert!((pt.rpm(&w.map(|x| -x), Gear::REVERSE) - expected).abs() < 1e-9);
        assert_eq!(pt.rpm(&w, Gear::NEUTRAL), 0.0);
        // Saturated at engineMaxRPM = 6500, including for infinite speeds.
        assert_eq!(pt.rpm(&PerWheel::splat(1000.0), Gear::FIRST), 6500.0);
        assert_eq!(pt.rpm(&PerWheel::splat(f64::INFINITY), Gear::FIRST), 6500.0);
        assert_eq!(
            pt.rpm(&PerWheel::new(f64::NAN, 1.0, 1.0, 1.0), Gear::FIRST),
            0.0
        );
        let inf_minus_inf = PerWheel::new(f64::INFINITY, f64::NEG_INFINITY, 0.0, 0.0);
        assert_eq!(pt.rpm(&inf_minus_inf, Gear::FIRST), 0.0);
    }

    #[test]
    fn output_torque_pipeline() {
        let pt = prius();
        // rpm 0: electric part only, 350 N·m; full throttle × ratio 6 = 2100 N·m.
        assert!((pt.output_torque(0.0, 1.0, Gear::FIRST, 0.0) - 2100.0).abs() < 1e-9);
        // Reverse: × −6 = −2100 N·m for positive throttle.
        assert!((pt.output_torque(0.0, 1.0, Gear::REVERSE, 0.0) + 2100.0).abs() < 1e-9);
        // Limiter at 100 rad/s²: × 50/100.
        assert!((pt.output_torque(0.0, 1.0, Gear::FIRST, -100.0) - 1050.0).abs() < 1e-9);
        assert_eq!(pt.output_torque(0.0, 1.0, Gear::NEUTRAL, 0.0), 0.0);
        // Saturated estimate: zero.
        assert_eq!(pt.output_torque(6500.0, 1.0, Gear::FIRST, 0.0), 0.0);
        // Throttle clamped: 2 → 1, −1 → 0, NaN → 0, ∞ → 1.
        assert!((pt.output_torque(0.0, 2.0, Gear::FIRST, 0.0) - 2100.0).abs() < 1e-9);
        assert_eq!(pt.output_torque(0.0, -1.0, Gear::FIRST, 0.0), 0.0);
        assert_eq!(pt.output_torque(0.0, f64::NAN, Gear::FIRST, 0.0), 0.0);
        assert!((pt.output_torque(0.0, f64::INFINITY, Gear::FIRST, 0.0) - 2100.0).abs() < 1e-9);
        assert_eq!(pt.output_torque(0.0, 1.0, Gear::FIRST, f64::INFINITY), 0.0);
    }

    #[test]
    fn virtual_gear_for_engine_sound() {
        // Default engine: threshold (2·1000 + 4500)/3 = 2166.67 rpm; ratios 10 6.5 4.5 3.5 2.75.
        let pt = Powertrain::<f64>::default();
        let to_rad_s = |wheel_rpm: f64| wheel_rpm * 2.0 * core::f64::consts::PI / 60.0;
        // n = 100 rev/min: first gear gives 1000 < 2166.67 → gear 1, 1000 rpm.
        let v = pt
            .speed_mode_virtual_gear(&PerWheel::splat(to_rad_s(100.0)))
            .unwrap();
        assert_eq!(v.gear, Gear::FIRST);
        assert!((v.rpm - 1000.0).abs() < 1e-9);
        // n = 400: 4000, 2600, 1800 → gear 3, 1800 rpm.
        let v = pt
            .speed_mode_virtual_gear(&PerWheel::splat(to_rad_s(400.0)))
            .unwrap();
        assert_eq!(v.gear, Gear::forward(3).unwrap());
        assert!((v.rpm - 1800.0).abs() < 1e-9);
        // n = 1000: even 2.75 gives 2750 ≥ threshold → highest gear kept, 2750 rpm.
        let v = pt
            .speed_mode_virtual_gear(&PerWheel::splat(to_rad_s(1000.0)))
            .unwrap();
        assert_eq!(v.gear, Gear::forward(5).unwrap());
        assert!((v.rpm - 2750.0).abs() < 1e-9);
        // n = −50: reverse, |−50·−12| = 600 rpm.
        let v = pt
            .speed_mode_virtual_gear(&PerWheel::splat(to_rad_s(-50.0)))
            .unwrap();
        assert_eq!(v.gear, Gear::REVERSE);
        assert!((v.rpm - 600.0).abs() < 1e-9);
        assert_eq!(pt.speed_mode_virtual_gear(&PerWheel::splat(f64::NAN)), None);
        assert_eq!(
            pt.speed_mode_virtual_gear(&PerWheel::splat(f64::INFINITY)),
            None
        );
    }
}
