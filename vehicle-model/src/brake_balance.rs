//! How the brake torque is shared between the front and rear axles.
//!
//! Webots gives every wheel the same brake torque, `intensity · brakeCoefficient`
//! ([`BrakeBalance::Equal`], the default). A car's load moves forward as it brakes, so with
//! equal torques its rear wheels reach their grip first: a car braking on locked rear wheels
//! and rolling front ones has no side grip behind its centre of mass and turns round (on the
//! slip-based tyre the yaw grows about five-fold every half second, from whatever asymmetry
//! there is). Real cars share their brake torque toward the front for that reason (a fixed
//! proportioning, set so that the front axle locks first); [`BrakeBalance::Proportioned`] does
//! the same with the same total torque, `4 · intensity · brakeCoefficient`.

use core::fmt;

use ackermann::{Real, Wheel};
use proto_geom::{WheelParams, WheelPhysics};

use crate::params::CarParams;

/// Gravity (m/s²): Webots' `WorldInfo.gravity` default, which the deceleration of
/// [`proportioned_front_share`] is measured in.
const GRAVITY: f64 = 9.81;

/// The highest deceleration (in g) [`proportioned_front_share`] designs for: a road tyre's peak
/// friction on a dry road (the passenger tyre's 1.0 on Webots' default friction 1). Brakes able
/// to stop the car harder lock its wheels there.
const DESIGN_DECELERATION: f64 = 1.0;

/// How the brake torque of `4 · intensity · brakeCoefficient` (N·m) is shared between the
/// axles; each axle's share is split equally between its two wheels.
#[derive(Debug, Clone, Copy, PartialEq, Default)]
pub enum BrakeBalance<T: Real> {
    /// Every wheel brakes with `intensity · brakeCoefficient`, as in Webots. The default.
    #[default]
    Equal,
    /// The front axle's share is the load it carries when the car brakes at its full brake
    /// torque, or at 1 g if its brakes can do more ([`proportioned_front_share`]): below that
    /// deceleration the front wheels reach their grip before the rear ones, on any ground.
    Proportioned,
    /// The front axle takes this share of the total (dimensionless, in [0, 1]).
    FrontShare(T),
}

/// A [`BrakeBalance::FrontShare`] outside [0, 1] or not a number: the balance was not changed.
/// Its `Display` names the share.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BrakeBalanceError {
    /// The refused share.
    pub share: f64,
}

impl fmt::Display for BrakeBalanceError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(
            f,
            "brake balance front share {} is not in [0, 1]; the balance is unchanged",
            self.share
        )
    }
}

impl core::error::Error for BrakeBalanceError {}

impl<T: Real> BrakeBalance<T> {
    /// The front axle's share of the total brake torque (dimensionless, in [0, 1]) for the car
    /// of `params`.
    ///
    /// # Errors
    /// [`BrakeBalanceError`] for a [`BrakeBalance::FrontShare`] outside [0, 1] or NaN.
    pub fn front_share(&self, params: &CarParams<T>) -> Result<T, BrakeBalanceError> {
        match *self {
            BrakeBalance::Proportioned => Ok(proportioned_front_share(params)),
            BrakeBalance::Equal => Ok(T::HALF),
            BrakeBalance::FrontShare(s) if s >= T::ZERO && s <= T::ONE => Ok(s),
            BrakeBalance::FrontShare(s) => Err(BrakeBalanceError { share: s.to_f64() }),
        }
    }
}

/// The factor (dimensionless) on `intensity · brakeCoefficient` of a wheel of `wheel`'s axle
/// when the front axle takes `front_share` of the total: `2·front_share` at the front,
/// `2·(1 − front_share)` at the rear (1 for both at an equal share, exactly).
pub fn axle_brake_factor<T: Real>(front_share: T, wheel: Wheel) -> T {
    let share = if wheel.is_front() {
        front_share
    } else {
        T::ONE - front_share
    };
    T::TWO * share
}

/// The front axle's share of the brake torque (dimensionless, in [0, 1]) that is its share of
/// the car's load when it brakes at its full brake torque: `φ = (l_r + z·h)/L`, with `l_r` the
/// centre of mass' distance ahead of the rear axle (m), `h` its height over the ground (m),
/// `L` the wheelbase (m) and `z` the deceleration in g of the full brake torque shared so,
/// `z = 4·brakeCoefficient·(φ/r_f + (1 − φ)/r_r)/(M·g)` (linear in φ, solved exactly), at most
/// 1 g (a road tyre's peak friction on a dry road: brakes able to stop the car harder lock
/// its wheels there).
///
/// The mass `M` and centre of mass are the body's and the wheels' (each wheel at its axle,
/// with the mass its `physics` gives; none for `physics NULL`). At any lower deceleration the
/// front axle brakes more than its load share, so on ground too slippery for the full brake
/// torque the front wheels lock first and the car goes straight on. Non-finite inputs (never
/// after [`CarParams::validate`]) give 0.5.
pub fn proportioned_front_share<T: Real>(params: &CarParams<T>) -> T {
    let length = params.wheelbase;
    let (rf, rr) = (params.radius_front(), params.radius_rear());
    let body = &params.body;
    let mut mass = body.mass;
    // Moments of the mass about the rear axle (kg·m) and about the ground (kg·m).
    let mut ahead = body.mass * body.center_of_mass[0];
    let mut high = body.mass * (body.center_of_mass[2] + rr);
    for w in Wheel::ALL {
        let m = wheel_mass(&params.wheels[w]);
        let (x, r) = if w.is_front() {
            (length, rf)
        } else {
            (T::ZERO, rr)
        };
        mass += m;
        ahead += m * x;
        high += m * r;
    }
    let (l_rear, height) = (ahead / mass, high / mass);
    let design = T::from_f64(DESIGN_DECELERATION);
    // z = a + b·φ
    let k = T::from_f64(4.0) * params.brake_coefficient / (mass * T::from_f64(GRAVITY));
    let (a, b) = (k / rr, k * (T::ONE / rf - T::ONE / rr));
    let denominator = length - height * b;
    let mut share = (l_rear + height * a) / denominator;
    // No share that is its own load share (a tall car on small front tyres with strong
    // brakes: the denominator is not positive), or one beyond the design deceleration: the
    // share at the design deceleration.
    if denominator <= T::ZERO || !share.is_finite() || a + b * share > design {
        share = (l_rear + height * design) / length;
    }
    if share.is_finite() {
        share.clamp(T::ZERO, T::ONE)
    } else {
        T::HALF
    }
}

/// A wheel's mass (kg) as its `physics` gives it (density × the tyre's cylinder for a
/// density), 0 for `physics NULL`.
pub(crate) fn wheel_mass<T: Real>(w: &WheelParams<T>) -> T {
    match w.physics {
        WheelPhysics::None => T::ZERO,
        WheelPhysics::Mass(m) => m,
        WheelPhysics::Density(d) => d * T::PI * w.tire_radius * w.tire_radius * w.thickness,
    }
}
