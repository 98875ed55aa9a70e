//! Wheel-speed estimation from the encoders (spec §2.2), without Webots' NaN warm-up.

use ackermann::{PerWheel, Real};
use powertrain::max_signed_acceleration;

/// Finite-difference wheel speeds and accelerations over one step.
///
/// Webots differentiates the raw readings, so its speeds are NaN for two steps (and garbage if a
/// sensor was enabled early). Here a speed exists only once two consecutive valid samples do,
/// and an acceleration once two consecutive speeds do; until then the speed reads 0 and the
/// acceleration does not take part in the limiter, which is what Webots' NaN comparisons amount
/// to.
#[derive(Debug, Clone, Copy, PartialEq)]
pub(crate) struct WheelSpeedEstimator<T: Real> {
    /// Last valid encoder reading of each wheel (rad).
    encoder: PerWheel<Option<T>>,
    /// Reading of the previous step (rad); `None` if it was missing.
    previous_angle: PerWheel<Option<T>>,
    /// Speed over the previous step (rad/s); `None` while not measurable.
    speed: PerWheel<Option<T>>,
    /// The signed wheel acceleration of largest magnitude over the last step (rad/s²).
    max_acceleration: T,
}

impl<T: Real> WheelSpeedEstimator<T> {
    pub(crate) fn new() -> Self {
        WheelSpeedEstimator {
            encoder: PerWheel::splat(None),
            previous_angle: PerWheel::splat(None),
            speed: PerWheel::splat(None),
            max_acceleration: T::ZERO,
        }
    }

    /// One step with the encoder readings `angles` (rad; NaN or ±∞ = no sample) and the step
    /// length `dt_ms` (ms, > 0), computed as Webots does: `1000·(θ − θ_prev)/dt_ms`.
    pub(crate) fn update(&mut self, angles: &PerWheel<T>, dt_ms: T) {
        let ms_per_s = T::from_f64(super::MS_PER_S);
        // A wheel without an acceleration contributes 0, which never beats a measured one.
        let mut accelerations = PerWheel::splat(T::ZERO);
        for ((i, &reading), acceleration) in angles.iter_wheels().zip(accelerations.iter_mut()) {
            let angle = Some(reading).filter(|a| a.is_finite());
            let speed = match (angle, self.previous_angle[i]) {
                (Some(now), Some(before)) => {
                    Some(ms_per_s * (now - before) / dt_ms).filter(|s| s.is_finite())
                }
                _ => None,
            };
            if let (Some(now), Some(before)) = (speed, self.speed[i]) {
                *acceleration = ms_per_s * (now - before) / dt_ms;
            }
            self.previous_angle[i] = angle;
            self.speed[i] = speed;
            if angle.is_some() {
                self.encoder[i] = angle;
            }
        }
        self.max_acceleration = max_signed_acceleration(&accelerations).finite_or(T::ZERO);
    }

    /// Last valid encoder readings (rad), 0 before the first.
    pub(crate) fn encoders(&self) -> PerWheel<T> {
        self.encoder.map(|a| a.unwrap_or(T::ZERO))
    }

    /// Wheel speeds (rad/s), 0 while not measurable.
    pub(crate) fn speeds(&self) -> PerWheel<T> {
        self.speed.map(|s| s.unwrap_or(T::ZERO))
    }

    /// True once all four speeds are measured (Webots: their mean is no longer NaN).
    pub(crate) fn all_measured(&self) -> bool {
        self.speed.iter().all(Option::is_some)
    }

    /// The signed wheel acceleration of largest magnitude (rad/s²), 0 while not measurable.
    pub(crate) fn max_acceleration(&self) -> T {
        self.max_acceleration
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn one_step_lag_and_warm_up() {
        let mut e = WheelSpeedEstimator::<f64>::new();
        let dt = 10.0; // ms
        // Step 1: no sample yet (NaN).
        e.update(&PerWheel::splat(f64::NAN), dt);
        assert_eq!(e.speeds(), PerWheel::splat(0.0));
        assert_eq!(e.encoders(), PerWheel::splat(0.0));
        assert!(!e.all_measured());
        // Step 2: first sample; still no difference.
        e.update(&PerWheel::new(1.0, 1.0, 1.0, 1.0), dt);
        assert_eq!(e.speeds(), PerWheel::splat(0.0));
        assert_eq!(e.encoders(), PerWheel::splat(1.0));
        // Step 3: speed over the previous step: 1000·(1.2 − 1)/10 = 20 rad/s; no acceleration yet.
        e.update(&PerWheel::new(1.2, 1.1, 1.0, 1.2), dt);
        let s = e.speeds();
        assert!((s.0[0] - 20.0).abs() < 1e-9 && (s.0[1] - 10.0).abs() < 1e-9);
        assert_eq!(s.0[2], 0.0);
        assert!(e.all_measured());
        assert_eq!(e.max_acceleration(), 0.0);
        // Step 4: FR 20 → 10 rad/s (−1000 rad/s²), FL 10 → 30 rad/s (+2000 rad/s²).
        e.update(&PerWheel::new(1.3, 1.4, 1.0, 1.4), dt);
        assert!((e.max_acceleration() - 2000.0).abs() < 1e-6);
    }

    #[test]
    fn a_lost_sample_restarts_that_wheel() {
        let mut e = WheelSpeedEstimator::<f32>::new();
        e.update(&PerWheel::splat(0.0), 1.0);
        e.update(&PerWheel::splat(0.001), 1.0);
        assert!((e.speeds().0[3] - 1.0).abs() < 1e-4);
        e.update(&PerWheel::new(0.002, 0.002, 0.002, f32::INFINITY), 1.0);
        assert_eq!(e.speeds().0[3], 0.0);
        assert!(!e.all_measured());
        assert!((e.encoders().0[3] - 0.001).abs() < 1e-9); // last valid reading kept
    }
}
