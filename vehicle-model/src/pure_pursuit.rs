//! A path-following law: pure pursuit (Coulter, *Implementation of the Pure Pursuit Path
//! Tracking Algorithm*, CMU-RI-TR-92-01, 1992) for a car-like vehicle, the steering angle
//! that puts the rear-axle centre on the circle through a goal point on the path.
//!
//! Why pure pursuit rather than Stanley: it needs one input, the goal point in the car's
//! frame, which a firmware gets from any path representation (a lane centre, a list of
//! waypoints, a camera's lane fit); it is stable at every speed with a look-ahead growing
//! with speed, and on a path of constant curvature a car that rolls without slip has no
//! steady-state error (the circle through the car and a goal on the path is the path
//! itself). Stanley needs the cross-track error at the front axle and the path heading
//! separately, a softening constant at low speed, and is more sensitive to a noisy heading.
//! The price of pure pursuit is cutting corners where the curvature changes within the
//! look-ahead (a transient error of about `Δκ·L²/2`), small at the look-aheads used here.
//!
//! Frame and units: x forward, y left, z up, origin at the rear-axle centre; m, m/s, rad.
//! Positive steering turns right (Webots).
//!
//! ```
//! use vehicle_model::{Geometry, PurePursuit};
//! let geometry = Geometry::new(2.8, 1.6, 1.6, 0.35, 0.35)?; // m
//! let law = PurePursuit::<f64>::new(geometry, -0.6, 0.6)?; // steering limits rad
//! // A goal 10 m ahead and 1 m to the left: a left turn, i.e. a negative steering angle.
//! let delta = law.steering(10.0, 1.0);
//! let curvature: f64 = 2.0 * 1.0 / (10.0 * 10.0 + 1.0); // 1/m: 2·y / d²
//! assert!((delta + (2.8 * curvature).atan()).abs() < 1e-12);
//! # Ok::<(), Box<dyn std::error::Error>>(())
//! ```

use ackermann::{Geometry, Real};

/// Shortest look-ahead (m) [`PurePursuit::lookahead`] returns: below it the steering would
/// chase every centimetre of lateral error.
pub const MIN_LOOKAHEAD: f64 = 4.0;
/// Look-ahead time (s) of [`PurePursuit::lookahead`]: the goal is where the car will be in
/// 0.6 s (at 50 km/h, 8.3 m), within the 0.5 s to 1 s of human preview in lane keeping.
pub const LOOKAHEAD_TIME: f64 = 0.6;

/// Why a [`PurePursuit`] cannot be built: its steering limits (rad) are not finite with
/// `min < 0 < max`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PurePursuitError {
    /// The smallest steering angle asked for (rad).
    pub min: f64,
    /// The largest (rad).
    pub max: f64,
}

impl core::fmt::Display for PurePursuitError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "steering limits {} to {} rad: must be finite with min < 0 < max",
            self.min, self.max
        )
    }
}

impl core::error::Error for PurePursuitError {}

/// The pure-pursuit steering law of a car: its geometry (for the wheelbase) and steering
/// limits.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct PurePursuit<T: Real> {
    geometry: Geometry<T>,
    min_steering: T,
    max_steering: T,
}

impl<T: Real> PurePursuit<T> {
    /// The law for a car of `geometry` whose steering angle (rad, positive right) ranges from
    /// `min_steering` (< 0) to `max_steering` (> 0), as the `Car`'s `minSteeringAngle` and
    /// `maxSteeringAngle`.
    pub fn new(
        geometry: Geometry<T>,
        min_steering: T,
        max_steering: T,
    ) -> Result<Self, PurePursuitError> {
        if !(min_steering.is_finite()
            && max_steering.is_finite()
            && min_steering < T::ZERO
            && max_steering > T::ZERO)
        {
            return Err(PurePursuitError {
                min: min_steering.to_f64(),
                max: max_steering.to_f64(),
            });
        }
        Ok(PurePursuit {
            geometry,
            min_steering,
            max_steering,
        })
    }

    /// The look-ahead distance (m) at speed `speed` (m/s): [`LOOKAHEAD_TIME`] of travel, at
    /// least [`MIN_LOOKAHEAD`] (a NaN speed gives the minimum).
    pub fn lookahead(speed: T) -> T {
        let d = speed.abs() * T::from_f64(LOOKAHEAD_TIME);
        d.max(T::from_f64(MIN_LOOKAHEAD))
    }

    /// The curvature (1/m, positive turning left) of the circle through the rear-axle centre,
    /// tangent to the car's heading, and through the goal (`x`, `y`) (m, car frame):
    /// `2·y / (x² + y²)`; 0 for a goal at the car or not finite.
    pub fn curvature(x: T, y: T) -> T {
        let d2 = x * x + y * y;
        if !(d2.is_finite() && d2 > T::EPSILON) {
            return T::ZERO;
        }
        T::TWO * y / d2
    }

    /// The steering angle (rad, positive right) towards the goal (`x`, `y`) (m, car frame):
    /// the central angle `−atan(wheelbase·κ)` of [`PurePursuit::curvature`]
    /// ([`Geometry::steering_angle_for_curvature`], whose curvature is positive to the right),
    /// within the steering limits.
    pub fn steering(&self, x: T, y: T) -> T {
        let delta = self
            .geometry
            .steering_angle_for_curvature(-Self::curvature(x, y));
        delta.max(self.min_steering).min(self.max_steering)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A car of wheelbase `l` (m), 1.6 m tracks and 0.35 m wheels.
    fn geometry<T: Real>(l: T) -> Geometry<T> {
        Geometry::new(
            l,
            T::from_f64(1.6),
            T::from_f64(1.6),
            T::from_f64(0.35),
            T::from_f64(0.35),
        )
        .unwrap()
    }

    #[test]
    fn goal_on_a_circle_gives_its_curvature() {
        // A goal on the circle of radius R through the origin, centre (0, R): at angle φ
        // it is R·(sin φ, 1 − cos φ), and 2y/d² = 1/R for every φ.
        let r = 26.75;
        for phi in [0.05_f64, 0.3, 1.0] {
            let (x, y) = (r * phi.sin(), r * (1.0 - phi.cos()));
            let k = PurePursuit::curvature(x, y);
            assert!((k - 1.0 / r).abs() < 1e-12, "{k}");
        }
        let law = PurePursuit::new(geometry(2.8_f64), -0.5, 0.5).unwrap();
        assert!((law.steering(10.0, -0.5) - (2.8 * 2.0 * 0.5 / 100.25_f64).atan()).abs() < 1e-12);
    }

    #[test]
    fn limits_and_bad_input() {
        let law = PurePursuit::new(geometry(2.8_f32), -0.4, 0.5).unwrap();
        assert_eq!(law.steering(0.1, 5.0), -0.4); // a hard left, at the left limit
        assert_eq!(law.steering(0.1, -5.0), 0.5);
        assert_eq!(law.steering(0.0, 0.0), 0.0);
        assert_eq!(law.steering(f32::NAN, 1.0), 0.0);
        assert_eq!(PurePursuit::<f32>::lookahead(f32::NAN), 4.0);
        assert!((PurePursuit::<f64>::lookahead(50.0 / 3.6) - 8.333_333_333).abs() < 1e-6);
        assert_eq!(
            PurePursuit::new(geometry(2.0_f64), 0.1, 0.5),
            Err(PurePursuitError { min: 0.1, max: 0.5 })
        );
        assert!(PurePursuit::new(geometry(2.0_f64), -0.1, f64::NAN).is_err());
    }
}
