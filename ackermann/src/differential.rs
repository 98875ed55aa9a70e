//! Geometric differential ratios: how the driven torque or speed is split between wheels.

use crate::geometry::{Geometry, WheelAngles};
use crate::real::Real;
use crate::steering::{effective_steering_angle, sin_cos};

/// The geometric differential ratios of Webots' driver library (spec §2.4), each nominally in
/// [0, 1] and dimensionless.
///
/// * `front`: share of the front axle going to the front-right wheel;
/// * `rear`: share of the rear axle going to the rear-right wheel;
/// * `central`: share of the total going to the front axle (4x4 only).
///
/// Webots: `front_ratio`, `rear_ratio`, `central_ratio` in `driver.c`.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct DifferentialRatios<T: Real> {
    /// Front-right share of the front axle (dimensionless).
    pub front: T,
    /// Rear-right share of the rear axle (dimensionless).
    pub rear: T,
    /// Front-axle share of the total, 4x4 only (dimensionless).
    pub central: T,
}

impl<T: Real> DifferentialRatios<T> {
    /// All three ratios 0.5: an even split, what Webots uses when driving straight (δ = 0).
    pub const EVEN: Self = DifferentialRatios {
        front: T::HALF,
        rear: T::HALF,
        central: T::HALF,
    };

    /// Builds from the front, rear and central ratios (dimensionless).
    #[inline]
    pub const fn new(front: T, rear: T, central: T) -> Self {
        DifferentialRatios {
            front,
            rear,
            central,
        }
    }

    /// Same as [`DifferentialRatios::EVEN`].
    #[inline]
    pub const fn even() -> Self {
        Self::EVEN
    }
}

impl<T: Real> Default for DifferentialRatios<T> {
    /// [`DifferentialRatios::EVEN`].
    #[inline]
    fn default() -> Self {
        Self::EVEN
    }
}

impl<T: Real> Geometry<T> {
    /// The geometric differential ratios of Webots' driver library (spec §2.4) for the driver's
    /// central steering angle `delta` (rad, positive = right) and the stored front-wheel angles
    /// `angles` (rad), which are normally [`Geometry::wheel_angles`]`(delta)` but may have been
    /// set directly (Webots: `wbu_car_set_right_steering_angle` / `..._left_...`).
    ///
    /// * δ exactly 0 (or NaN): all three are 0.5, whatever `angles` say (as in Webots).
    /// * front: `Rr / (Rl + Rr)` with `Rr = L / sin δR`, `Rl = L / sin δL`, evaluated as
    ///   `sin δL / (sin δR + sin δL)`, which is the same number without the overflow of `L / sin`
    ///   for a straight wheel.
    /// * rear: `Rr / (Rl + Rr)` with `Rr = L/tan δ − Tr/2`, `Rl = L/tan δ + Tr/2`, evaluated as
    ///   `1/2 − Tr·sin δ / (4L·cos δ)`.
    /// * central: `Rf / (Rf + Rb)` with `Rf = L / sin δ`, `Rb = L / tan δ` (the front axle's
    ///   share of the distance the two axle centres travel), evaluated as `1 / (1 + cos δ)`;
    ///   it tends to 0.5 as δ → 0. Webots multiplies it by `q = rr / rf`, which jumps to `q/2`
    ///   as soon as δ ≠ 0 and, on a 4x4 car with unequal tyres, drives one axle against the
    ///   other; the split is fixed here (see `COMPATIBILITY.md`). The tyre radii do not belong
    ///   in a speed split: each axle's ground speed is turned into a wheel speed by its own
    ///   radius afterwards ([`Geometry::wheel_speed_targets`]).
    ///
    /// `delta` goes through [`crate::effective_steering_angle`] (clamp to ±π/2).
    ///
    /// Degenerate cases, where Webots divides by zero and produces ±∞ or NaN, return 0.5 for
    /// that ratio (an even split):
    /// * front, when `sin δR + sin δL = 0` (e.g. both stored angles 0 while δ ≠ 0, or the two
    ///   wheels toed by opposite angles), or when the quotient is not finite (non-finite angles,
    ///   or a denominator so small that it overflows);
    /// * rear, at δ = ±π/2, where the car pivots about the rear-axle centre and `Rl + Rr = 0`.
    ///
    /// Near those points the ratios are finite but can be far outside [0, 1], as in Webots.
    ///
    /// ```
    /// use ackermann::{DifferentialRatios, Geometry};
    /// let g = Geometry::new(2.995_f64, 1.628, 1.628, 0.374, 0.374).unwrap();
    /// assert_eq!(g.differential_ratios(0.0, g.wheel_angles(0.0)), DifferentialRatios::EVEN);
    /// let r = g.differential_ratios(0.2, g.wheel_angles(0.2));
    /// assert!(r.front < 0.5 && r.rear < 0.5); // the inner (right) wheels get less
    /// ```
    pub fn differential_ratios(&self, delta: T, angles: WheelAngles<T>) -> DifferentialRatios<T> {
        let delta = effective_steering_angle(delta);
        if delta == T::ZERO {
            return DifferentialRatios::EVEN;
        }
        let (s, c) = sin_cos(delta);
        self.ratios_from(s, c, angles.right.sin(), angles.left.sin())
    }

    /// The ratios of [`Geometry::differential_ratios`] from `sin δ`, `cos δ` (δ ≠ 0, effective)
    /// and the sines of the two front-wheel angles.
    #[inline]
    fn ratios_from(&self, s: T, c: T, sin_right: T, sin_left: T) -> DifferentialRatios<T> {
        let sum = sin_right + sin_left;
        let front = if sum == T::ZERO {
            T::HALF
        } else {
            (sin_left / sum).finite_or(T::HALF)
        };

        let rear = if c == T::ZERO {
            T::HALF
        } else {
            let four_l = T::TWO * T::TWO * self.wheelbase();
            (T::HALF - self.track_rear() * s / (four_l * c)).finite_or(T::HALF)
        };

        // cos δ ≥ 0 for every effective δ (|δ| ≤ π/2): the share lies in [0.5, 1].
        let central = T::ONE / (T::ONE + c);

        DifferentialRatios {
            front,
            rear,
            central,
        }
    }

    /// [`Geometry::wheel_angles`] and [`Geometry::differential_ratios`] of the central steering
    /// angle `delta` (rad, positive = right) in one evaluation: what Webots'
    /// `wbu_driver_set_steering_angle` leaves the driver library with.
    ///
    /// The same numbers as the two calls (to a few units in the last place) for about half the
    /// cost: `sin δ` and `cos δ` are evaluated once, and the sines of the wheel angles come
    /// from the `atan2` arguments instead of a `sin` of the angles,
    /// `sin δR = sin δ / √(sin²δ + (cos δ − k·sin δ)²)` (likewise δL with `+k`), `k = Tf/(2L)`.
    /// For geometries so extreme that this root would leave the normal range (track more than
    /// ~10⁸ wheelbases in `f64`) the sines are taken of the angles, as in
    /// [`Geometry::differential_ratios`].
    ///
    /// ```
    /// use ackermann::Geometry;
    /// let g = Geometry::new(2.995_f64, 1.628, 1.628, 0.374, 0.374).unwrap();
    /// let (angles, ratios) = g.ackermann_steering(0.2);
    /// assert_eq!(angles, g.wheel_angles(0.2));
    /// let slow = g.differential_ratios(0.2, angles);
    /// assert!((ratios.front - slow.front).abs() < 1e-15);
    /// assert_eq!((ratios.rear, ratios.central), (slow.rear, slow.central));
    /// ```
    pub fn ackermann_steering(&self, delta: T) -> (WheelAngles<T>, DifferentialRatios<T>) {
        let (s, c) = sin_cos(delta);
        let ks = self.half_track_ratio_times(s);
        let (x_right, x_left) = (c - ks, c + ks);
        let angles = WheelAngles {
            right: s.atan2(x_right),
            left: s.atan2(x_left),
        };
        if effective_steering_angle(delta) == T::ZERO {
            return (angles, DifferentialRatios::EVEN);
        }
        // sin(atan2(s, x)) = s/√(s² + x²); `ks` may be ±∞ for absurd tracks, so check the root.
        let sine = |x: T, angle: T| {
            let r2 = s * s + x * x;
            if r2 > T::EPSILON && r2.is_finite() {
                s / r2.sqrt()
            } else {
                angle.sin()
            }
        };
        let ratios = self.ratios_from(s, c, sine(x_right, angles.right), sine(x_left, angles.left));
        (angles, ratios)
    }

    /// [`Geometry::differential_ratios`] with the Ackermann wheel angles of `delta`
    /// ([`Geometry::wheel_angles`]): what Webots uses after `wbu_driver_set_steering_angle`.
    ///
    /// Evaluated as [`Geometry::ackermann_steering`].
    pub fn ackermann_ratios(&self, delta: T) -> DifferentialRatios<T> {
        self.ackermann_steering(delta).1
    }
}
