//! Cruise control: the wheel angular-speed targets of Webots' speed mode (spec §2.9).

use crate::differential::DifferentialRatios;
use crate::drive::DriveType;
use crate::geometry::Geometry;
use crate::real::Real;
use crate::wheel::PerWheel;

/// `x` forced into the finite range: NaN → 0, ±∞ → ±`T::MAX`.
#[inline]
pub(crate) fn saturate<T: Real>(x: T) -> T {
    if x.is_nan() {
        T::ZERO
    } else {
        x.clamp(-T::MAX, T::MAX)
    }
}

impl<T: Real> Geometry<T> {
    /// The target angular speed of each driven wheel (rad/s, positive = rolling forward) for the
    /// cruising speed `speed` (m/s, negative = reverse), split by `ratios`
    /// (Webots: `wbu_driver_set_cruising_speed`, which takes km/h: pass `v_kmh / 3.6`).
    /// Non-driven wheels are `None`.
    ///
    /// With `ρf, ρr, ρc = ratios.front, ratios.rear, ratios.central`:
    /// * front wheels (traction, 4x4): `ωFR = 2·v·ρf / rf`, `ωFL = 2·v·(1 − ρf) / rf`, both
    ///   multiplied by `2·ρc` in 4x4;
    /// * rear wheels (propulsion, 4x4): `ωRR = 2·v·ρr / rr`, `ωRL = 2·v·(1 − ρr) / rr`, both
    ///   multiplied by `2·(1 − ρc)` in 4x4.
    ///
    /// So `v` is the mean ground speed of the driven wheels (for propulsion, exactly the
    /// rear-axle centre's speed).
    ///
    /// Never returns NaN or ∞: a NaN `speed` counts as 0, a non-finite ratio as 0.5, and results
    /// beyond the range of `T` saturate at ±`T::MAX`.
    ///
    /// ```
    /// use ackermann::{DriveType, Geometry, Wheel};
    /// let g = Geometry::new(2.995_f64, 1.628, 1.628, 0.374, 0.374).unwrap();
    /// let w = g.wheel_speed_targets(20.0 / 3.6, DriveType::Propulsion, g.ackermann_ratios(0.0));
    /// assert_eq!(w[Wheel::FrontRight], None);
    /// let omega = w[Wheel::RearLeft].unwrap(); // 20 km/h on a 0.374 m tyre
    /// assert!((omega - 20.0 / 3.6 / 0.374).abs() < 1e-12);
    /// ```
    pub fn wheel_speed_targets(
        &self,
        speed: T,
        drive: DriveType,
        ratios: DifferentialRatios<T>,
    ) -> PerWheel<Option<T>> {
        let two_v = saturate(T::TWO * saturate(speed));
        let front = ratios.front.finite_or(T::HALF);
        let rear = ratios.rear.finite_or(T::HALF);
        let central = ratios.central.finite_or(T::HALF);
        let (front_share, rear_share) = match drive {
            DriveType::FourByFour => (
                saturate(T::TWO * central),
                saturate(T::TWO * (T::ONE - central)),
            ),
            DriveType::Traction | DriveType::Propulsion => (T::ONE, T::ONE),
        };
        // Saturating after every product keeps each operand finite, so no ∞·0 can make a NaN.
        // The operands are finite, so a finite plain result means no product overflowed and
        // every saturation would have been the identity: only the rare overflow pays for them.
        let target = |ratio: T, share: T, radius: T| {
            let plain = two_v * ratio * share / radius;
            if plain.is_finite() {
                plain
            } else {
                saturate(saturate(saturate(two_v * ratio) * share) / radius)
            }
        };
        let front_driven = drive.front_driven();
        let rear_driven = drive.rear_driven();
        let radius_front = self.radius_front();
        let radius_rear = self.radius_rear();
        PerWheel::new(
            front_driven.then(|| target(front, front_share, radius_front)),
            front_driven.then(|| target(T::ONE - front, front_share, radius_front)),
            rear_driven.then(|| target(rear, rear_share, radius_rear)),
            rear_driven.then(|| target(T::ONE - rear, rear_share, radius_rear)),
        )
    }
}
