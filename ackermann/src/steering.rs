//! Ackermann steering: the right and left front-wheel angles of a central steering angle, and the
//! inverse.
//!
//! The central angle δ is the angle of a virtual wheel at the centre of the front axle
//! (rad, positive = right). With `k = Tf / (2L)`, Webots (`wbu_driver_set_steering_angle`,
//! after Jazar, *Vehicle Dynamics*, 2009) computes
//!
//! ```text
//! δR = atan(1 / (cot δ − k)),   δL = atan(1 / (cot δ + k))
//! ```
//!
//! This crate evaluates the same geometry as `δR = atan2(sin δ, cos δ − k·sin δ)` and
//! `δL = atan2(sin δ, cos δ + k·sin δ)`: identical to Webots wherever the denominator is
//! positive, and continuous beyond (see [`Geometry::wheel_angles`]).

use crate::geometry::{Geometry, WheelAngles};
use crate::real::Real;

/// The steering angle the geometry functions of this crate actually use for a requested central
/// angle `delta` (rad, positive = right).
///
/// * NaN → 0 (straight ahead): a missing command must not steer the car;
/// * values beyond ±π/2 (including ±∞) → ±π/2: at π/2 the virtual front wheel is perpendicular
///   to the car and the car pivots about its rear-axle centre; beyond it the front axle would
///   roll backwards while the rear axle rolls forwards, which is the same motion as a smaller
///   angle driven in reverse, so no steering mechanism goes there;
/// * everything else unchanged.
///
/// ```
/// use ackermann::effective_steering_angle;
/// assert_eq!(effective_steering_angle(0.3_f64), 0.3);
/// assert_eq!(effective_steering_angle(f64::NAN), 0.0);
/// assert_eq!(effective_steering_angle(-4.0_f32), -core::f32::consts::FRAC_PI_2);
/// ```
#[inline]
pub fn effective_steering_angle<T: Real>(delta: T) -> T {
    if delta.is_nan() {
        T::ZERO
    } else {
        delta.clamp(-T::FRAC_PI_2, T::FRAC_PI_2)
    }
}

/// `(sin δ, cos δ)` of the effective angle of `delta`, with `cos δ` exactly 0 at ±π/2 (so that
/// `f32`, whose `FRAC_PI_2` rounds above π/2, does not see a tiny negative cosine) and never
/// negative.
#[inline]
pub(crate) fn sin_cos<T: Real>(delta: T) -> (T, T) {
    let d = effective_steering_angle(delta);
    if d.abs() >= T::FRAC_PI_2 {
        (d.sign(), T::ZERO)
    } else {
        (d.sin(), d.cos().max(T::ZERO))
    }
}

impl<T: Real> Geometry<T> {
    /// `k·x` with `k = Tf / (2L)` (dimensionless), in an order that keeps it finite or ±∞ but
    /// never NaN (`Tf·x` is finite for |x| ≤ 1, and 0 stays 0 even if `2L` overflows).
    #[inline]
    pub(crate) fn half_track_ratio_times(&self, x: T) -> T {
        self.track_front() * x / (T::TWO * self.wheelbase())
    }

    /// The right and left front-wheel angles (rad, positive = right) for the central steering
    /// angle `delta` (rad, positive = right), so that all four wheels roll about one common
    /// centre on the rear-axle line (Webots: `wbu_driver_set_steering_angle`), with
    /// `k = Tf/(2L)`: `δR = atan2(sin δ, cos δ − k·sin δ)`, `δL = atan2(sin δ, cos δ + k·sin δ)`.
    ///
    /// `delta` first goes through [`effective_steering_angle`] (NaN → 0, clamp to ±π/2).
    /// δ = 0 gives exactly 0 and 0.
    ///
    /// Large angles: once the turning centre comes inside the front track
    /// (`tan |δ| > 2L/Tf`, |δ| > 1.305 rad for a BMW X5) the inner wheel has to turn past 90°.
    /// Webots' `atan` form then jumps by −π (the inner wheel suddenly points the other way);
    /// this function keeps turning it smoothly past π/2, up to `π − atan(2L/Tf)` at δ = ±π/2,
    /// so the wheel keeps rolling forward about the same centre. The results are always finite
    /// and within [−π, π] (±π only for a track absurdly wider than the wheelbase).
    ///
    /// ```
    /// use ackermann::Geometry;
    /// let g = Geometry::new(2.995_f64, 1.628, 1.628, 0.374, 0.374).unwrap();
    /// let a = g.wheel_angles(0.2);
    /// assert!(a.right > 0.2 && a.left < 0.2); // the inner (right) wheel turns more
    /// assert!((a.right - 0.211_326_185_553_853).abs() < 1e-12);
    /// ```
    pub fn wheel_angles(&self, delta: T) -> WheelAngles<T> {
        let (s, c) = sin_cos(delta);
        let ks = self.half_track_ratio_times(s);
        WheelAngles {
            right: s.atan2(c - ks),
            left: s.atan2(c + ks),
        }
    }

    /// The central steering angle (rad, positive = right) whose Ackermann right-wheel angle is
    /// `right` (rad): the inverse of [`Geometry::wheel_angles`] for the right wheel,
    /// `δ = atan2(sin δR, cos δR + k·sin δR)`.
    ///
    /// `right` is taken modulo 2π. A wheel angle that no central angle in [−π/2, π/2] produces
    /// (beyond a steering lock) saturates at ±π/2. NaN gives 0 and ±∞ gives ±π/2. The result
    /// is always within [−π/2, π/2].
    pub fn central_angle_from_right(&self, right: T) -> T {
        self.central_angle_from(right, T::ONE)
    }

    /// The central steering angle (rad, positive = right) whose Ackermann left-wheel angle is
    /// `left` (rad): the inverse of [`Geometry::wheel_angles`] for the left wheel,
    /// `δ = atan2(sin δL, cos δL − k·sin δL)`.
    ///
    /// Same domain rules as [`Geometry::central_angle_from_right`].
    pub fn central_angle_from_left(&self, left: T) -> T {
        self.central_angle_from(left, -T::ONE)
    }

    /// The central steering angle (rad, positive = right) best matching two measured front-wheel
    /// angles: the mean of [`Geometry::central_angle_from_right`] and
    /// [`Geometry::central_angle_from_left`]. Exact for Ackermann-consistent angles.
    ///
    /// Use this rather than the plain mean `(δR + δL)/2` (what Webots'
    /// `wbu_driver_get_steering_angle` returns), which overestimates |δ| by roughly `k²·|δ|³`
    /// (7 mrad at δ = 0.5 rad for a BMW X5).
    pub fn central_angle_from_wheel_angles(&self, angles: WheelAngles<T>) -> T {
        (self.central_angle_from_right(angles.right) + self.central_angle_from_left(angles.left))
            * T::HALF
    }

    /// The central angle (rad) of a front wheel with angle `wheel` (rad); `side` is +1 for the
    /// right wheel, −1 for the left one.
    fn central_angle_from(&self, wheel: T, side: T) -> T {
        if wheel.is_nan() {
            return T::ZERO;
        }
        if !wheel.is_finite() {
            return wheel.sign() * T::FRAC_PI_2;
        }
        let s = wheel.sin();
        let delta = s.atan2(wheel.cos() + side * self.half_track_ratio_times(s));
        // The shear maps the half-plane cos δ ≥ 0 onto the reachable wheel angles; anything in
        // the other half is beyond a lock and saturates.
        delta.clamp(-T::FRAC_PI_2, T::FRAC_PI_2)
    }

    /// The central steering angle (rad, positive = right) that makes the rear-axle centre follow
    /// a circle of curvature `curvature` (1/m, positive = centre on the right):
    /// `δ = atan(L·κ)`. 0 gives 0; ±∞ gives ±π/2 (pivot about the rear-axle centre); NaN gives
    /// 0. This is the inverse of [`Geometry::turning`] for path followers (pure pursuit,
    /// Stanley…), which output a curvature.
    ///
    /// Note: ROS `geometry_msgs`/REP 103 curvature is positive to the *left*; negate it.
    pub fn steering_angle_for_curvature(&self, curvature: T) -> T {
        if curvature.is_nan() {
            T::ZERO
        } else {
            (self.wheelbase() * curvature).atan()
        }
    }
}
