//! Wheel brakes as friction torques.

use ackermann::Real;

use crate::error::{Field, PowertrainError, positive};

/// Brake torque per wheel at full intensity (N·m), the Webots `Car` PROTO default of field
/// `brakeCoefficient`.
pub const DEFAULT_BRAKE_COEFFICIENT: f64 = 700.0;

/// A friction brake on each wheel (all four, driven or not), with peak torque
/// `brakeCoefficient` (N·m).
///
/// Webots emulates braking with a joint damping constant of `intensity·brakeCoefficient/|ω|`
/// (spec §2.5), i.e. a torque of constant magnitude `intensity·brakeCoefficient` opposing the
/// rotation, with an infinite damping at ω = 0. This type models what that is physically: a
/// dry-friction (Coulomb) brake of capacity `intensity·brakeCoefficient` that opposes rotation
/// and holds a stopped wheel. See [`Brake::friction_torque`] for how a simulator applies it.
///
/// ```
/// use powertrain::Brake;
/// let brake = Brake::new(1800.0_f64)?; // BmwX5
/// assert_eq!(brake.torque(0.5), 900.0); // N·m
/// // Rolling wheel that would need −5000 N·m to stop this step: the brake gives −900 N·m.
/// assert_eq!(brake.friction_torque(0.5, -5000.0), -900.0);
/// // Parked wheel pushed by 300 N·m of drive torque: the brake cancels it exactly.
/// assert_eq!(brake.friction_torque(0.5, -300.0), -300.0);
/// # Ok::<(), powertrain::PowertrainError>(())
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Brake<T: Real> {
    coefficient: T,
}

impl<T: Real> Brake<T> {
    /// A brake of `coefficient` N·m at full intensity (Webots field `brakeCoefficient`).
    ///
    /// # Errors
    /// [`PowertrainError`] for `brakeCoefficient` if it is not finite or not > 0.
    pub fn new(coefficient: T) -> Result<Self, PowertrainError> {
        Ok(Brake {
            coefficient: positive(Field::BrakeCoefficient, coefficient)?,
        })
    }

    /// Peak brake torque per wheel (N·m); Webots field `brakeCoefficient`.
    #[inline]
    pub const fn coefficient(&self) -> T {
        self.coefficient
    }

    /// Brake capacity per wheel (N·m, ≥ 0) at `intensity` (dimensionless): the magnitude of
    /// the friction torque, `intensity·brakeCoefficient`. The intensity is clamped to [0, 1]
    /// (NaN → 0), as Webots' `wbu_driver_set_brake_intensity` does for finite values.
    #[inline]
    pub fn torque(&self, intensity: T) -> T {
        let intensity = if intensity.is_nan() {
            T::ZERO
        } else {
            intensity.clamp(T::ZERO, T::ONE)
        };
        intensity * self.coefficient
    }

    /// The signed brake torque (N·m, about the wheel axis) to apply during one simulation step,
    /// given `torque_to_stop` (N·m, signed): the torque the brake alone would have to apply so
    /// the wheel ends the step at rest, e.g. `−(I·ω/dt + τ_other)` for a wheel of inertia `I`
    /// (kg·m²) turning at ω (rad/s) under the other axle torques `τ_other` (N·m) with step `dt`
    /// (s).
    ///
    /// The result is `torque_to_stop` limited to ± [`Brake::torque`]: a moving wheel is slowed
    /// by the full capacity, opposing its rotation; a wheel that the capacity can stop within
    /// the step is stopped exactly (no overshoot, no chatter); a stopped wheel is held as long
    /// as the other torques stay within the capacity. NaN counts as 0 (no torque).
    #[inline]
    pub fn friction_torque(&self, intensity: T, torque_to_stop: T) -> T {
        coulomb_torque(torque_to_stop, self.torque(intensity))
    }
}

/// The torque (N·m) a dry-friction (Coulomb) element of `capacity` (N·m) applies during one
/// step, given `torque_to_stop` (N·m, signed): the torque it alone would have to apply so the
/// part it acts on ends the step at rest.
///
/// `torque_to_stop` limited to ±`capacity`: a moving part is slowed by the full capacity, one
/// that the capacity can stop within the step is stopped exactly (no overshoot, no chatter),
/// and a stopped one is held while the other torques stay within the capacity. This is the
/// rule of [`Brake::friction_torque`], for any friction (a brake, a clutch, a joint's static
/// friction). A NaN `torque_to_stop` gives 0; a negative or NaN capacity counts as 0, an
/// infinite one as the largest finite value, so the result is never NaN or ±∞.
///
/// ```
/// use powertrain::coulomb_torque;
/// assert_eq!(coulomb_torque(-5000.0_f64, 900.0), -900.0);
/// assert_eq!(coulomb_torque(-300.0_f64, 900.0), -300.0);
/// ```
#[inline]
pub fn coulomb_torque<T: Real>(torque_to_stop: T, capacity: T) -> T {
    if torque_to_stop.is_nan() {
        return T::ZERO;
    }
    let capacity = capacity.max(T::ZERO).min(T::MAX);
    torque_to_stop.clamp(-capacity, capacity)
}

impl<T: Real> Default for Brake<T> {
    /// [`DEFAULT_BRAKE_COEFFICIENT`] (700 N·m).
    #[inline]
    fn default() -> Self {
        Brake {
            coefficient: T::from_f64(DEFAULT_BRAKE_COEFFICIENT),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn capacity_is_linear_in_clamped_intensity() {
        let b = Brake::<f64>::default();
        assert_eq!(b.coefficient(), 700.0);
        assert_eq!(b.torque(0.0), 0.0);
        assert_eq!(b.torque(0.25), 175.0);
        assert_eq!(b.torque(1.0), 700.0);
        assert_eq!(b.torque(3.0), 700.0);
        assert_eq!(b.torque(-1.0), 0.0);
        assert_eq!(b.torque(f64::NAN), 0.0);
        assert_eq!(b.torque(f64::INFINITY), 700.0);
        assert_eq!(b.torque(f64::NEG_INFINITY), 0.0);
    }

    #[test]
    fn friction_opposes_and_holds() {
        let b = Brake::new(1000.0_f32).unwrap();
        // Wheel spinning forward, needs −4000 N·m to stop: full capacity −1000 N·m.
        assert_eq!(b.friction_torque(1.0, -4000.0), -1000.0);
        // Spinning backward: +1000 N·m.
        assert_eq!(b.friction_torque(1.0, 4000.0), 1000.0);
        // Small residual speed: exactly what is needed to stop, not more.
        assert_eq!(b.friction_torque(1.0, -12.5), -12.5);
        // At rest with no other torque: nothing.
        assert_eq!(b.friction_torque(1.0, 0.0), 0.0);
        // At rest against a 1500 N·m drive torque: holds only up to capacity.
        assert_eq!(b.friction_torque(1.0, -1500.0), -1000.0);
        // Released brake: no torque.
        assert_eq!(b.friction_torque(0.0, -4000.0), 0.0);
        assert_eq!(b.friction_torque(1.0, f32::NAN), 0.0);
        assert_eq!(b.friction_torque(0.5, f32::NEG_INFINITY), -500.0);
    }

    fn coulomb_clamps<T: Real>() {
        let r = T::from_f64;
        assert_eq!(coulomb_torque(r(-4000.0), r(1000.0)), r(-1000.0));
        assert_eq!(coulomb_torque(r(4000.0), r(1000.0)), r(1000.0));
        assert_eq!(coulomb_torque(r(-12.5), r(1000.0)), r(-12.5));
        assert_eq!(coulomb_torque(r(f64::NAN), r(1000.0)), T::ZERO);
        assert_eq!(coulomb_torque(-T::INFINITY, r(1000.0)), r(-1000.0));
        // Negative or NaN capacity: no friction.
        assert_eq!(coulomb_torque(r(-12.5), r(-1000.0)), T::ZERO);
        assert_eq!(coulomb_torque(r(-12.5), r(f64::NAN)), T::ZERO);
        // Infinite capacity: holds anything, and never returns ∞.
        assert_eq!(coulomb_torque(r(-12.5), T::INFINITY), r(-12.5));
        assert_eq!(coulomb_torque(T::INFINITY, T::INFINITY), T::MAX);
    }

    #[test]
    fn coulomb_f32_f64() {
        coulomb_clamps::<f32>();
        coulomb_clamps::<f64>();
    }

    #[test]
    fn invalid_coefficients_are_rejected() {
        assert_eq!(
            Brake::new(0.0_f64).unwrap_err(),
            PowertrainError::NotPositive {
                field: Field::BrakeCoefficient,
                value: 0.0
            }
        );
        assert_eq!(
            Brake::new(f64::INFINITY).unwrap_err(),
            PowertrainError::NotFinite {
                field: Field::BrakeCoefficient,
                value: f64::INFINITY
            }
        );
    }
}
