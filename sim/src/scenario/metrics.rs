//! Metrics of any vehicle's motion, from its telemetry alone.

use core::f64::consts::{PI, TAU};
use std::collections::VecDeque;

use crate::telemetry::{Sample, Telemetry};

use super::Metric;

/// Window of the moving average applied to the accelerations (s): the body's acceleration is
/// a finite difference of the solver's velocities, whose step-to-step jitter is not a vehicle
/// behaviour.
pub(crate) const ACCEL_WINDOW: f64 = 0.1;

/// The largest and smallest 0.1 s moving average of a quantity, fed one value at a time
/// (a run of any length in the memory of one window).
#[derive(Debug, Clone, Default)]
struct SmoothedExtremes {
    /// The values of the current window: time (s) and value.
    window: VecDeque<(f64, f64)>,
    sum: f64,
    extremes: Option<[f64; 2]>,
}

impl SmoothedExtremes {
    /// Adds the value `v` at time `t` (s); a missing or non-finite value is skipped.
    fn push(&mut self, t: f64, v: Option<f64>) {
        let Some(v) = v.filter(|v| v.is_finite()) else {
            return;
        };
        self.window.push_back((t, v));
        self.sum += v;
        // The same arithmetic, in the same order, as a sum over a slice with a moving start.
        while let Some(&(t0, v0)) = self.window.front()
            && t - t0 >= ACCEL_WINDOW - 1e-9
        {
            self.sum -= v0;
            self.window.pop_front();
        }
        // The value just pushed is never evicted (t − t = 0): the window holds at least it.
        let mean = self.sum / self.window.len() as f64;
        let [lo, hi] = self.extremes.get_or_insert([mean, mean]);
        *lo = lo.min(mean);
        *hi = hi.max(mean);
    }
}

/// What [`motion_metrics`] measures, fed one sample at a time: a run of any length is
/// measured in constant memory ([`Simulation::report`](crate::Simulation::report) feeds it
/// from a [`TelemetryLog`](crate::telemetry::TelemetryLog)).
#[derive(Debug, Clone, Default)]
pub struct MotionMeter {
    last: Option<Sample>,
    distance: f64,
    lateral: SmoothedExtremes,
    longitudinal: SmoothedExtremes,
}

impl MotionMeter {
    /// A meter that has seen nothing.
    pub fn new() -> Self {
        MotionMeter::default()
    }

    /// Takes the next sample (in time order).
    pub fn push(&mut self, s: &Sample) {
        if let Some(a) = &self.last {
            self.distance += (s.x - a.x).hypot(s.y - a.y);
        }
        self.lateral.push(s.time, s.lateral_accel);
        self.longitudinal.push(s.time, s.longitudinal_accel);
        self.last = Some(*s);
    }

    /// The metrics of the samples so far ([`motion_metrics`]).
    pub fn metrics(&self) -> Vec<Metric> {
        let Some(last) = &self.last else {
            return Vec::new();
        };
        let heading = (last.yaw + PI).rem_euclid(TAU) - PI;
        let mut metrics = vec![
            Metric::number("distance_m", "distance travelled", "m", self.distance),
            Metric::number("final_x_m", "final x", "m", last.x),
            Metric::number("final_y_m", "final y", "m", last.y),
            Metric::number("final_heading_rad", "final heading", "rad", heading),
        ];
        if let Some([lo, hi]) = self.lateral.extremes {
            metrics.push(Metric::number(
                "max_lateral_accel_mps2",
                "peak lateral acceleration (0.1 s mean)",
                "m/s^2",
                lo.abs().max(hi.abs()),
            ));
        }
        if let Some([lo, hi]) = self.longitudinal.extremes {
            metrics.extend([
                Metric::number(
                    "max_accel_mps2",
                    "peak acceleration (0.1 s mean)",
                    "m/s^2",
                    hi.max(0.0),
                ),
                Metric::number(
                    "max_decel_mps2",
                    "peak deceleration (0.1 s mean)",
                    "m/s^2",
                    (-lo).max(0.0),
                ),
            ]);
        }
        metrics
    }
}

/// What any vehicle's telemetry tells: `distance_m` (path length of the origin),
/// `final_x_m`, `final_y_m`, `final_heading_rad` (in (−π, π]) and, for a car,
/// `max_lateral_accel_mps2` (largest |lateral acceleration|), `max_accel_mps2` (largest
/// forward acceleration) and `max_decel_mps2` (largest deceleration, positive), each a 0.1 s
/// moving average. Empty telemetry gives no metrics.
pub fn motion_metrics(t: &Telemetry) -> Vec<Metric> {
    let mut meter = MotionMeter::new();
    for s in &t.samples {
        meter.push(s);
    }
    meter.metrics()
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scenario::Value;

    fn value(m: &[Metric], key: &str) -> f64 {
        m.iter()
            .find(|m| m.key == key)
            .and_then(|m| m.value.as_f64())
            .unwrap_or(f64::NAN)
    }

    #[test]
    fn a_square_path_and_smoothed_peaks() {
        // Four 1 m sides, 0.01 s apart; a 1-sample spike of 10 m/s² in a steady 1 m/s² is
        // averaged over the 10 samples of 0.1 s: (9·1 + 10)/10 = 1.9.
        let corners = [[0.0, 0.0], [1.0, 0.0], [1.0, 1.0], [0.0, 1.0], [0.0, 0.0]];
        let samples: Vec<Sample> = (0..40)
            .map(|i| {
                let (k, f) = (i / 10, f64::from(i % 10) / 10.0);
                let [a, b] = [corners[k as usize], corners[k as usize + 1]];
                Sample {
                    time: 0.01 * f64::from(i),
                    x: a[0] + (b[0] - a[0]) * f,
                    y: a[1] + (b[1] - a[1]) * f,
                    yaw: 3.0 * PI / 2.0,
                    longitudinal_accel: Some(if i == 20 { 10.0 } else { 1.0 }),
                    lateral_accel: Some(-2.0),
                    ..Sample::default()
                }
            })
            .collect();
        let t = Telemetry {
            samples,
            ..Telemetry::default()
        };
        let m = motion_metrics(&t);
        // 39 segments of 0.1 m.
        assert!((value(&m, "distance_m") - 3.9).abs() < 1e-12);
        assert!((value(&m, "final_heading_rad") + PI / 2.0).abs() < 1e-12);
        assert!((value(&m, "max_accel_mps2") - 1.9).abs() < 1e-12);
        assert_eq!(value(&m, "max_decel_mps2"), 0.0);
        assert!((value(&m, "max_lateral_accel_mps2") - 2.0).abs() < 1e-12);
        // A robot has no accelerations: only the path metrics.
        let robot = Telemetry {
            samples: vec![Sample::default()],
            ..Telemetry::default()
        };
        let keys: Vec<&str> = motion_metrics(&robot).iter().map(|m| m.key).collect();
        assert_eq!(
            keys,
            ["distance_m", "final_x_m", "final_y_m", "final_heading_rad"]
        );
        assert_eq!(motion_metrics(&robot)[0].value, Value::Number(0.0));
    }
}
