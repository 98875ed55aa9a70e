//! The metrics of the standard handling manoeuvres, computed from recorded signals: ISO 7401
//! step steer, ISO 4138 steady-state circular driving, FMVSS 126 sine with dwell. Pure
//! functions of time series, so that each is checked on signals whose answer is known.
//!
//! Signs: steering and yaw rate positive to the left (the car turns the way the steering
//! points), so a manoeuvre to the right gives the same numbers negated.

/// ISO 7401 step-steer response of the yaw rate.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct StepResponse {
    /// Time from 50 % of the steering step to 90 % of the steady-state yaw rate (s).
    pub response_time: f64,
    /// Time from 50 % of the steering step to the yaw rate's peak (s).
    pub peak_response_time: f64,
    /// Overshoot of the yaw rate over its steady state, `(peak − steady)/steady`
    /// (dimensionless, 0 for a response without overshoot).
    pub overshoot: f64,
    /// Steady-state yaw rate over the steady-state road-wheel steering angle (1/s).
    pub steady_yaw_gain: f64,
}

/// The step-steer metrics of samples `(time s, steering rad, yaw rate rad/s)` of a step from
/// zero steering, with the steady state taken as the mean over the last `steady_window`
/// seconds; `None` when the samples hold no step or no steady yaw rate.
pub fn step_response(samples: &[(f64, f64, f64)], steady_window: f64) -> Option<StepResponse> {
    let (t_end, _, _) = *samples.last()?;
    let steady: Vec<&(f64, f64, f64)> = samples
        .iter()
        .filter(|s| s.0 >= t_end - steady_window)
        .collect();
    let n = steady.len() as f64;
    let steer_ss = steady.iter().map(|s| s.1).sum::<f64>() / n;
    let yaw_ss = steady.iter().map(|s| s.2).sum::<f64>() / n;
    if steer_ss == 0.0 || yaw_ss == 0.0 || !(steer_ss.is_finite() && yaw_ss.is_finite()) {
        return None;
    }
    // The reference instant: the steering crosses half its final value, interpolated.
    let t50 = crossing(samples, |s| s.1 / steer_ss, 0.5)?;
    let t90 = crossing(samples, |s| s.2 / yaw_ss, 0.9)?;
    let peak = samples
        .iter()
        .filter(|s| s.0 >= t50)
        .max_by(|a, b| (a.2 / yaw_ss).total_cmp(&(b.2 / yaw_ss)))?;
    Some(StepResponse {
        response_time: t90 - t50,
        peak_response_time: peak.0 - t50,
        overshoot: (peak.2 / yaw_ss - 1.0).max(0.0),
        steady_yaw_gain: yaw_ss / steer_ss,
    })
}

/// The first time at which `value(sample)` rises through `level`, linearly interpolated.
fn crossing<S>(
    samples: &[(f64, S, S)],
    value: impl Fn(&(f64, S, S)) -> f64,
    level: f64,
) -> Option<f64>
where
    S: Copy,
{
    samples.windows(2).find_map(|w| {
        let (a, b) = (value(&w[0]), value(&w[1]));
        (a < level && b >= level).then(|| w[0].0 + (w[1].0 - w[0].0) * (level - a) / (b - a))
    })
}

/// Least-squares line `y = slope·x + intercept` through `points`; `None` for fewer than two
/// distinct `x`.
pub fn fit_line(points: &[(f64, f64)]) -> Option<(f64, f64)> {
    let n = points.len() as f64;
    if points.len() < 2 {
        return None;
    }
    let (mx, my) = points
        .iter()
        .fold((0.0, 0.0), |(sx, sy), p| (sx + p.0 / n, sy + p.1 / n));
    let (sxx, sxy) = points.iter().fold((0.0, 0.0), |(a, b), p| {
        (a + (p.0 - mx).powi(2), b + (p.0 - mx) * (p.1 - my))
    });
    (sxx > 0.0).then(|| (sxy / sxx, my - sxy / sxx * mx))
}

/// ISO 4138 understeer gradient (rad per m/s²): the slope of the road-wheel steering angle
/// beyond the kinematic (Ackermann) angle against the lateral acceleration, over steady
/// states `(steering rad, lateral acceleration m/s², path curvature 1/m)` of a car of
/// `wheelbase` (m). On a constant radius the kinematic angle `L/R` is constant and this is the
/// slope of steering against lateral acceleration the standard takes; subtracting the measured
/// `L/R` keeps the small drift of a driven circle's radius out of the slope.
pub fn understeer_gradient(steady_states: &[(f64, f64, f64)], wheelbase: f64) -> Option<f64> {
    let points: Vec<(f64, f64)> = steady_states
        .iter()
        .map(|&(steer, ay, curvature)| (ay, steer - wheelbase * curvature))
        .collect();
    fit_line(&points).map(|(slope, _)| slope)
}

/// FMVSS 126 (49 CFR 571.126) sine with dwell: the steering profile and the pass criteria.
pub mod sine_with_dwell {
    use core::f64::consts::PI;

    /// Frequency of the sine (Hz).
    pub const FREQUENCY: f64 = 0.7;
    /// Dwell at the second peak (s).
    pub const DWELL: f64 = 0.5;
    /// Largest yaw-rate ratio 1.0 s after the completion of steer (S5.2.1).
    pub const RATIO_1_0_LIMIT: f64 = 0.35;
    /// Largest yaw-rate ratio 1.75 s after the completion of steer (S5.2.2).
    pub const RATIO_1_75_LIMIT: f64 = 0.20;
    /// Smallest lateral displacement 1.07 s after the beginning of steer (m) for a vehicle
    /// of 3500 kg gross vehicle weight rating or less (S5.2.3).
    pub const DISPLACEMENT_LIMIT: f64 = 1.83;
    /// Time after the beginning of steer at which the displacement is measured (s).
    pub const DISPLACEMENT_TIME: f64 = 1.07;

    /// Time of the second peak (s after the beginning of steer), where the dwell starts:
    /// three quarters of a period.
    pub fn dwell_start() -> f64 {
        0.75 / FREQUENCY
    }

    /// Time of the completion of steer (s after the beginning of steer).
    pub fn completion() -> f64 {
        1.0 / FREQUENCY + DWELL
    }

    /// The steering angle (rad, positive left for a left-first run) `t` s after the
    /// beginning of steer for an `amplitude` (rad): `A·sin(2π·f·t)` to the second peak, `−A`
    /// for the dwell, then the last quarter period back to zero, and zero after.
    pub fn steering(t: f64, amplitude: f64) -> f64 {
        let w = 2.0 * PI * FREQUENCY;
        if t <= 0.0 || t >= completion() {
            0.0
        } else if t <= dwell_start() {
            amplitude * (w * t).sin()
        } else if t <= dwell_start() + DWELL {
            -amplitude
        } else {
            amplitude * (w * (t - DWELL)).sin()
        }
    }

    /// The yaw-rate ratios at 1.0 s and 1.75 s after the completion of steer, from
    /// `(time s after the beginning of steer, yaw rate rad/s)` of a left-first run: the yaw
    /// rate there over the first peak of the yaw rate after the steering changed sign (the
    /// peak of the dwell's direction, negative). `None` when the run is too short or has no
    /// such peak.
    pub fn yaw_ratios(samples: &[(f64, f64)]) -> Option<(f64, f64)> {
        let reversal = 0.5 / FREQUENCY;
        // The dwell turns the car right: its yaw rate is negative; the peak is the first
        // local minimum after the reversal, where the yaw rate has that sign.
        let after: Vec<&(f64, f64)> = samples.iter().filter(|s| s.0 >= reversal).collect();
        let peak = after
            .windows(3)
            .find(|w| w[1].1 < 0.0 && w[1].1 <= w[0].1 && w[1].1 < w[2].1)
            .map(|w| w[1].1)?;
        let at = |time: f64| {
            samples
                .windows(2)
                .find(|w| w[0].0 <= time && w[1].0 >= time)
                .map(|w| w[0].1 + (w[1].1 - w[0].1) * (time - w[0].0) / (w[1].0 - w[0].0))
        };
        let c = completion();
        Some((at(c + 1.0)? / peak, at(c + 1.75)? / peak))
    }

    /// True when the ratios and the displacement (m, its size) meet FMVSS 126.
    pub fn passes(ratios: (f64, f64), displacement: f64) -> bool {
        ratios.0 <= RATIO_1_0_LIMIT
            && ratios.1 <= RATIO_1_75_LIMIT
            && displacement.abs() >= DISPLACEMENT_LIMIT
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A first-order yaw response of time constant `tau` (s) to a steering step `delta`
    /// (rad) at `t = 1` s, with gain `gain` (1/s), sampled every millisecond for 6 s.
    fn first_order(tau: f64, delta: f64, gain: f64) -> Vec<(f64, f64, f64)> {
        (0..=6000)
            .map(|i| {
                let t = f64::from(i) * 1e-3;
                let on = t >= 1.0;
                let r = if on {
                    gain * delta * (1.0 - (-(t - 1.0) / tau).exp())
                } else {
                    0.0
                };
                (t, if on { delta } else { 0.0 }, r)
            })
            .collect()
    }

    #[test]
    fn step_response_of_a_first_order_system() {
        let (tau, delta, gain) = (0.15, 0.02, 8.0);
        let r = step_response(&first_order(tau, delta, gain), 1.0).unwrap();
        // 90 % of a first-order step after τ·ln 10; the steering step is one sample, so its
        // 50 % crossing lies half a sample (0.5 ms) before the step: the response time is
        // τ·ln 10 + 0.5 ms, to the 1 ms sampling (linear interpolation of an exponential).
        let expected = tau * 10f64.ln() + 0.5e-3;
        assert!((r.response_time - expected).abs() < 1e-3, "{r:?}");
        // The tail (5 s = 33 τ) is steady to e^-33: the gain and no overshoot.
        assert!((r.steady_yaw_gain - gain).abs() < 1e-9 && r.overshoot < 1e-9);
    }

    #[test]
    fn step_response_overshoot_and_peak_of_a_second_order_system() {
        // ω_n = 6 rad/s, ζ = 0.5: overshoot e^(−πζ/√(1−ζ²)) = 16.3 %, peak at π/ω_d.
        let (wn, zeta) = (6.0_f64, 0.5_f64);
        let wd = wn * (1.0 - zeta * zeta).sqrt();
        let samples: Vec<_> = (0..=8000)
            .map(|i| {
                let t = f64::from(i) * 1e-3;
                let s = (t - 1.0).max(0.0);
                let phi = (zeta / (1.0 - zeta * zeta).sqrt()).atan();
                let y = if t >= 1.0 {
                    1.0 - (-zeta * wn * s).exp() * (wd * s - phi).cos() / phi.cos()
                } else {
                    0.0
                };
                (t, if t >= 1.0 { 0.01 } else { 0.0 }, 0.1 * y)
            })
            .collect();
        let r = step_response(&samples, 1.0).unwrap();
        let overshoot = (-PI * zeta / (1.0 - zeta * zeta).sqrt()).exp();
        // Sampled at 1 ms: the peak's time within a sample, its value to 1e-5 (flat top).
        assert!(
            (r.overshoot - overshoot).abs() < 1e-4,
            "{r:?} vs {overshoot}"
        );
        assert!(
            (r.peak_response_time - (PI / wd + 0.5e-3)).abs() < 1.5e-3,
            "{r:?}"
        );
        assert!((r.steady_yaw_gain - 10.0).abs() < 1e-6);
    }

    use core::f64::consts::PI;

    #[test]
    fn understeer_gradient_of_the_steady_state_relation() {
        // δ = L/R + K·a_y on a 40 m circle (L = 2.8 m, K = 0.004 rad per m/s²), a few
        // speeds, with the radius drifting by up to 1 m: the fit returns K to rounding.
        let (l, k) = (2.8, 0.004);
        let states: Vec<_> = [(1.0, 40.0), (2.0, 40.5), (3.0, 41.0), (4.0, 39.6)]
            .iter()
            .map(|&(ay, r)| (l / r + k * ay, ay, 1.0 / r))
            .collect();
        assert!((understeer_gradient(&states, l).unwrap() - k).abs() < 1e-12);
        assert!(understeer_gradient(&states[..1], l).is_none());
    }

    #[test]
    fn sine_with_dwell_profile_and_ratios() {
        use sine_with_dwell::*;
        let a = 0.1;
        // Peak at a quarter period, −A through the dwell, zero at completion (1/f + dwell).
        assert!((steering(0.25 / FREQUENCY, a) - a).abs() < 1e-12);
        assert_eq!(steering(dwell_start() + 0.2, a), -a);
        assert!((completion() - (1.0 / 0.7 + 0.5)).abs() < 1e-12);
        assert!(steering(completion() - 1e-9, a).abs() < 1e-8);
        assert_eq!(steering(completion() + 0.1, a), 0.0);
        // A yaw rate that turns right from 1 s (time constant 50 ms) to −0.4 rad/s at the
        // completion of steer, then decays with time constant 0.5 s: its first peak after
        // the reversal is at completion, and the ratios are e^(−1/0.5) and e^(−1.75/0.5).
        let c = completion();
        let peak = -0.4 * (1.0 - (-(c - 1.0) / 0.05).exp());
        let samples: Vec<(f64, f64)> = (0..=6000)
            .map(|i| {
                let t = f64::from(i) * 1e-3;
                let r = if t < 1.0 {
                    0.0
                } else if t < c {
                    -0.4 * (1.0 - (-(t - 1.0) / 0.05).exp())
                } else {
                    peak * (-(t - c) / 0.5).exp()
                };
                (t, r)
            })
            .collect();
        let (r1, r2) = yaw_ratios(&samples).unwrap();
        // The 1 ms samples hold the peak within one sample (e^(−0.002)); interpolation is exact
        // to 1e-6 between samples of an exponential of 0.5 s.
        assert!((r1 - (-2.0_f64).exp()).abs() < 1e-3, "{r1}");
        assert!((r2 - (-3.5_f64).exp()).abs() < 1e-3, "{r2}");
        assert!(passes((r1, r2), 2.0) && !passes((0.4, 0.1), 2.0) && !passes((r1, r2), 1.5));
    }
}
