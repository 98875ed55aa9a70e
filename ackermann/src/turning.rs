//! Turning radii: where the turning centre is, and how far each wheel is from it.
//!
//! Sign convention: a radius is positive when the turning centre is on the right of the car
//! (right turn, δ > 0) and negative when it is on the left, so that every radius has the sign of
//! δ. In the vehicle frame (x forward, y left, origin at the rear-axle centre) the centre is at
//! `(0, −R)` where `R` is [`TurningRadii::rear_axle`].

use crate::geometry::Geometry;
use crate::real::Real;
use crate::steering::sin_cos;
use crate::wheel::{PerWheel, Wheel};

/// The signed turning radii of one steering angle (m; positive = turning centre on the right).
///
/// For Ackermann-consistent motion, every point of the car moves with the same yaw rate, so the
/// ground speed of wheel `w` is `v · wheels[w] / rear_axle`, where `v` is the speed of the
/// rear-axle centre.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TurningRadii<T: Real> {
    /// Radius of the rear-axle centre, `R = L / tan δ` (m). 0 at δ = ±π/2 (pivot).
    pub rear_axle: T,
    /// Radius of the virtual front wheel at the front-axle centre, `L / sin δ` (m). Its
    /// magnitude is never below `L`.
    pub front_virtual: T,
    /// Radius of each wheel's contact point (m). Front wheels: `L / sin δR` and `L / sin δL`
    /// (Webots' `Rr`, `Rl` of the front differential), magnitude never below `L`. Rear wheels:
    /// `R − Tr/2` and `R + Tr/2`; the inner rear wheel's radius changes sign (it rolls
    /// backwards) once the centre comes inside the rear track.
    pub wheels: PerWheel<T>,
}

impl<T: Real> TurningRadii<T> {
    /// The signed radius of `wheel` (m).
    #[inline]
    pub fn wheel(&self, wheel: Wheel) -> T {
        self.wheels[wheel]
    }

    /// Signed curvature of the rear-axle centre's path, `1 / R = tan δ / L` (1/m, positive =
    /// right), or `None` at the pivot (R = 0), where it is infinite (or if it exceeds the range
    /// of `T`).
    #[inline]
    pub fn curvature(&self) -> Option<T> {
        let k = T::ONE / self.rear_axle;
        k.is_finite().then_some(k)
    }
}

/// How a steering angle makes the car move: straight on, or around a circle.
///
/// A straight line has no finite radius; it is a variant of its own rather than an infinite or
/// overflowed radius.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum Turning<T: Real> {
    /// δ = 0, or a circle too wide for `T` to represent: all wheels roll in a straight line.
    Straight,
    /// The car turns about a centre on the rear-axle line.
    Circle(TurningRadii<T>),
}

impl<T: Real> Turning<T> {
    /// True for [`Turning::Straight`].
    #[inline]
    pub fn is_straight(&self) -> bool {
        matches!(self, Turning::Straight)
    }

    /// The radii, or `None` when driving straight.
    #[inline]
    pub fn radii(&self) -> Option<TurningRadii<T>> {
        match self {
            Turning::Straight => None,
            Turning::Circle(r) => Some(*r),
        }
    }

    /// Signed curvature of the rear-axle centre's path (1/m, positive = right): 0 when straight,
    /// `None` at the pivot (δ = ±π/2) where it is infinite.
    #[inline]
    pub fn curvature(&self) -> Option<T> {
        match self {
            Turning::Straight => Some(T::ZERO),
            Turning::Circle(r) => r.curvature(),
        }
    }
}

impl<T: Real> Geometry<T> {
    /// The turning centre and radii for the central steering angle `delta` (rad, positive =
    /// right), assuming Ackermann wheel angles ([`Geometry::wheel_angles`]).
    ///
    /// `delta` first goes through [`crate::effective_steering_angle`] (NaN → 0, clamp to ±π/2).
    /// Returns [`Turning::Straight`] for δ = 0 and whenever a radius is not representable in `T`
    /// (for angles below about `L / T::MAX`, or dimensions near `T::MAX`): such a circle is a
    /// straight line to `T`'s precision. Every radius returned is finite.
    ///
    /// ```
    /// use ackermann::{Geometry, Turning, Wheel};
    /// let g = Geometry::new(2.995_f64, 1.628, 1.628, 0.374, 0.374).unwrap();
    /// assert_eq!(g.turning(0.0), Turning::Straight);
    /// let Turning::Circle(r) = g.turning(-0.5) else { panic!() };
    /// assert!(r.rear_axle < 0.0); // left turn: centre on the left
    /// assert!((r.rear_axle + 2.995 / 0.5_f64.tan()).abs() < 1e-12);
    /// assert!(r.wheel(Wheel::RearLeft).abs() < r.wheel(Wheel::RearRight).abs());
    /// ```
    pub fn turning(&self, delta: T) -> Turning<T> {
        let (s, c) = sin_cos(delta);
        if s == T::ZERO {
            return Turning::Straight;
        }
        let l = self.wheelbase();
        let r = l * c / s;
        if !r.is_finite() {
            return Turning::Straight;
        }
        // Distances through hypot rather than L / sin: identical, and they do not overflow
        // unless the distance itself does.
        let side = s.sign();
        let half_front = self.track_front() * T::HALF;
        let half_rear = self.track_rear() * T::HALF;
        let radii = TurningRadii {
            rear_axle: r,
            front_virtual: side * l.hypot(r),
            wheels: PerWheel::new(
                side * l.hypot(r - half_front),
                side * l.hypot(r + half_front),
                r - half_rear,
                r + half_rear,
            ),
        };
        // A circle wider than `T` can represent is, to `T`'s precision, a straight line.
        if radii.front_virtual.is_finite() && radii.wheels.iter().all(|w| w.is_finite()) {
            Turning::Circle(radii)
        } else {
            Turning::Straight
        }
    }
}
