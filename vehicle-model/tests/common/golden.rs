//! Helpers shared by the scenario tests.

use vehicle_model::{Driver, Model, PerWheel, Sensors, WheelAngles};

/// `a ≈ b` within `tol`, relative for |b| > 1.
pub fn close(a: f64, b: f64, tol: f64) -> bool {
    (a - b).abs() <= tol * b.abs().max(1.0)
}

/// A driver for `model` at 10 ms, asserting its params are valid.
pub fn driver(model: Model) -> Driver<f64> {
    let (d, report) = Driver::new(model.params(), 10);
    assert!(report.is_empty(), "{model}: {report:?}");
    d
}

/// Readings at time `t` (s) with every encoder and steering angle at 0.
pub fn sensors_at(t: f64) -> Sensors<f64> {
    Sensors {
        time: t,
        wheel_angles: PerWheel::splat(0.0),
        steering: WheelAngles::STRAIGHT,
        wiper: None,
    }
}
