//! Webots' limited-slip differential: saturated integrators of the wheel-speed imbalance.

use ackermann::{DifferentialRatios, DriveType, Geometry, PerWheel, Real};

/// The limited-slip differential of the Webots car library (spec §2.4): three slip states
/// (dimensionless, always in [−1, 1]) that integrate the right/left (and front/rear) wheel
/// speed imbalance each step and scale the geometric differential ratios by `(1 − slip)`.
///
/// It is a pure integrator with saturation, not a torque-sensing differential: a wheel that
/// keeps spinning faster than its partner drives its state to ±1, which moves that axle's
/// torque to the other wheel. Enabled by default, as in Webots
/// (`wbu_car_enable_limited_slip_differential`). The states are kept, neither updated nor
/// used, while disabled.
///
/// The central state compares the two axles' ground speeds, `ω·r`, so a 4x4 car whose front
/// and rear tyres differ ([`LimitedSlip::for_geometry`]) reads rolling straight as no slip.
/// Webots compares their angular speeds, which on the Tractor's 0.38 m and 0.6 m tyres reads
/// straight rolling as the front axle slipping by 22 % per step, saturates the state within
/// five steps and moves all the torque to the rear axle; that is fixed here (see
/// `COMPATIBILITY.md`). With equal tyres the two are the same to the last bit.
///
/// ```
/// use ackermann::{DifferentialRatios, DriveType, PerWheel};
/// use powertrain::LimitedSlip;
/// let mut lsd = LimitedSlip::<f64>::new();
/// // Front-right wheel spinning at 30 rad/s, front-left at 10: r = 2·30/40 − 1 = 0.5.
/// lsd.update(DriveType::Traction, &PerWheel::new(30.0, 10.0, 20.0, 20.0));
/// assert_eq!(lsd.front(), 0.5);
/// // The right share of the front axle is halved: 0.5 · (1 − 0.5) = 0.25.
/// assert_eq!(lsd.apply(&DifferentialRatios::EVEN).front, 0.25);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct LimitedSlip<T: Real> {
    front: T,
    rear: T,
    central: T,
    enabled: bool,
    /// Rear over front tyre radius (dimensionless, positive): turns the rear axle's angular
    /// speed into the front's scale before the central comparison.
    rear_over_front: T,
}

impl<T: Real> LimitedSlip<T> {
    /// Enabled, all states 0 (Webots' state after `wbu_driver_init`), for a car with the same
    /// tyre radius front and rear.
    #[inline]
    pub const fn new() -> Self {
        LimitedSlip {
            front: T::ZERO,
            rear: T::ZERO,
            central: T::ZERO,
            enabled: true,
            rear_over_front: T::ONE,
        }
    }

    /// Like [`LimitedSlip::new`], for a car with `geometry`'s front and rear tyre radii: the
    /// central state compares the axles' ground speeds.
    ///
    /// ```
    /// use ackermann::{DriveType, Geometry, PerWheel};
    /// use powertrain::LimitedSlip;
    /// // The Tractor's tyres: rolling straight at 5 m/s, ω = v/r.
    /// let g = Geometry::new(2.0_f64, 1.5, 1.5, 0.38, 0.6).unwrap();
    /// let rolling = PerWheel::new(5.0 / 0.38, 5.0 / 0.38, 5.0 / 0.6, 5.0 / 0.6);
    /// let mut lsd = LimitedSlip::for_geometry(&g);
    /// lsd.update(DriveType::FourByFour, &rolling);
    /// assert!(lsd.central().abs() < 1e-15);
    /// ```
    #[inline]
    pub fn for_geometry(geometry: &Geometry<T>) -> Self {
        LimitedSlip {
            // Both radii are positive and finite; only absurd ones overflow the quotient.
            rear_over_front: (geometry.radius_rear() / geometry.radius_front()).min(T::MAX),
            ..Self::new()
        }
    }

    /// True if [`LimitedSlip::update`] and [`LimitedSlip::apply`] act.
    #[inline]
    pub const fn is_enabled(&self) -> bool {
        self.enabled
    }

    /// Turns the differential on or off without touching the states (Webots:
    /// `wbu_car_enable_limited_slip_differential`).
    #[inline]
    pub fn set_enabled(&mut self, enabled: bool) {
        self.enabled = enabled;
    }

    /// Front slip state (dimensionless, [−1, 1]): positive when the front-right wheel turns
    /// faster than the front-left.
    #[inline]
    pub const fn front(&self) -> T {
        self.front
    }

    /// Rear slip state (dimensionless, [−1, 1]): positive when the rear-right wheel turns
    /// faster than the rear-left.
    #[inline]
    pub const fn rear(&self) -> T {
        self.rear
    }

    /// Central slip state (dimensionless, [−1, 1], 4x4 only): positive when the front axle
    /// turns faster than the rear.
    #[inline]
    pub const fn central(&self) -> T {
        self.central
    }

    /// Sets all three states back to 0.
    #[inline]
    pub fn reset(&mut self) {
        self.front = T::ZERO;
        self.rear = T::ZERO;
        self.central = T::ZERO;
    }

    /// One integration step from the four wheel speeds (rad/s), for the axles `drive` drives
    /// (Webots: done at each torque-mode driver step while enabled; a no-op when disabled):
    ///
    /// * front (traction, 4x4): `front += 2·ω_FR/(ω_FR + ω_FL) − 1`;
    /// * rear (propulsion, 4x4): `rear += 2·ω_RR/(ω_RR + ω_RL) − 1`;
    /// * central (4x4): `central += 2·S_f/(S_f + q·S_r) − 1` with `S_f = ω_FR + ω_FL`,
    ///   `S_r = ω_RR + ω_RL` and `q` the rear over front tyre radius (1 from
    ///   [`LimitedSlip::new`]; Webots: always 1).
    ///
    /// Each state is then reset to 0 if NaN (e.g. both wheels stopped: 0/0) and clamped to
    /// [−1, 1], exactly as in Webots.
    pub fn update(&mut self, drive: DriveType, wheel_speeds: &PerWheel<T>) {
        if !self.enabled {
            return;
        }
        let [fr, fl, rr, rl] = *wheel_speeds.as_array();
        if drive.front_driven() {
            self.front = integrate(self.front, imbalance(fr, fl));
        }
        if drive.rear_driven() {
            self.rear = integrate(self.rear, imbalance(rr, rl));
        }
        if drive == DriveType::FourByFour {
            self.central = integrate(
                self.central,
                imbalance(fr + fl, self.rear_over_front * (rr + rl)),
            );
        }
    }

    /// The geometric ratios corrected by the slip states: each multiplied by `1 − slip`
    /// (computed as Webots writes it, `2·(1 − (slip + 1)/2)`), so each factor lies in [0, 2].
    /// Returns `ratios` unchanged when disabled.
    pub fn apply(&self, ratios: &DifferentialRatios<T>) -> DifferentialRatios<T> {
        if !self.enabled {
            return *ratios;
        }
        let factor = |slip: T| T::TWO * (T::ONE - (slip + T::ONE) / T::TWO);
        DifferentialRatios::new(
            ratios.front * factor(self.front),
            ratios.rear * factor(self.rear),
            ratios.central * factor(self.central),
        )
    }
}

impl<T: Real> Default for LimitedSlip<T> {
    /// Same as [`LimitedSlip::new`].
    #[inline]
    fn default() -> Self {
        Self::new()
    }
}

/// `2·a/(a + b) − 1` = `(a − b)/(a + b)`, written as Webots computes it.
#[inline]
fn imbalance<T: Real>(a: T, b: T) -> T {
    T::TWO * a / (a + b) - T::ONE
}

/// Adds `r` to `state`; NaN resets to 0, then saturates to [−1, 1].
#[inline]
fn integrate<T: Real>(state: T, r: T) -> T {
    let s = state + r;
    if s.is_nan() {
        T::ZERO
    } else {
        s.clamp(-T::ONE, T::ONE)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn integrates_and_saturates() {
        let mut lsd = LimitedSlip::<f64>::new();
        // Rear: 2·30/(30 + 10) − 1 = 0.5 per step → 0.5, 1.0, then saturated at 1.
        let w = PerWheel::new(10.0, 10.0, 30.0, 10.0);
        lsd.update(DriveType::Propulsion, &w);
        assert_eq!(lsd.rear(), 0.5);
        lsd.update(DriveType::Propulsion, &w);
        assert_eq!(lsd.rear(), 1.0);
        lsd.update(DriveType::Propulsion, &w);
        assert_eq!(lsd.rear(), 1.0);
        // Front and central are untouched for rear-wheel drive.
        assert_eq!((lsd.front(), lsd.central()), (0.0, 0.0));
        // A saturated state moves all the axle torque to the slower wheel.
        let r = lsd.apply(&DifferentialRatios::EVEN);
        assert_eq!((r.front, r.rear, r.central), (0.5, 0.0, 0.5));
    }

    #[test]
    fn four_by_four_updates_all_three() {
        let mut lsd = LimitedSlip::<f64>::new();
        // front: 2·12/(12+8) − 1 = 0.2; rear: 2·9/(9+11) − 1 = −0.1;
        // central: S_f = 20, S_r = 20 → 0.
        lsd.update(DriveType::FourByFour, &PerWheel::new(12.0, 8.0, 9.0, 11.0));
        assert!((lsd.front() - 0.2).abs() < 1e-15);
        assert!((lsd.rear() + 0.1).abs() < 1e-15);
        assert_eq!(lsd.central(), 0.0);
        // central: S_f = 30, S_r = 10 → 2·30/40 − 1 = 0.5.
        lsd.update(DriveType::FourByFour, &PerWheel::new(15.0, 15.0, 5.0, 5.0));
        assert!((lsd.central() - 0.5).abs() < 1e-15);
    }

    #[test]
    fn central_state_compares_ground_speeds() {
        // Front 0.38 m, rear 0.6 m, rolling straight at 5 m/s: ω_f = 13.16, ω_r = 8.33 rad/s.
        let g = Geometry::new(2.0, 1.5, 1.5, 0.38, 0.6).unwrap();
        let rolling = PerWheel::new(5.0 / 0.38, 5.0 / 0.38, 5.0 / 0.6, 5.0 / 0.6);
        let mut lsd = LimitedSlip::<f64>::for_geometry(&g);
        for _ in 0..10 {
            lsd.update(DriveType::FourByFour, &rolling);
        }
        assert!(lsd.central().abs() < 1e-14, "{}", lsd.central());
        // The front axle really slipping 10 % faster over the ground:
        // 2·1.1/(1.1 + 1) − 1 = 0.047619… per step.
        let slipping = PerWheel::new(5.5 / 0.38, 5.5 / 0.38, 5.0 / 0.6, 5.0 / 0.6);
        lsd.update(DriveType::FourByFour, &slipping);
        assert!(
            (lsd.central() - 1.0 / 21.0).abs() < 1e-14,
            "{}",
            lsd.central()
        );
        // Webots' angular comparison reads the straight rolling as 2·0.6/0.98 − 1 = 0.2245 per
        // step and saturates in five: all the torque to the rear axle.
        let mut webots = LimitedSlip::<f64>::new();
        for _ in 0..5 {
            webots.update(DriveType::FourByFour, &rolling);
        }
        assert_eq!(webots.central(), 1.0);
        assert_eq!(webots.apply(&DifferentialRatios::EVEN).central, 0.0);
        // Resetting keeps the radii.
        lsd.reset();
        lsd.update(DriveType::FourByFour, &rolling);
        assert!(lsd.central().abs() < 1e-14);
    }

    #[test]
    fn nan_resets_and_infinity_saturates() {
        let mut lsd = LimitedSlip::<f32>::new();
        lsd.update(DriveType::Traction, &PerWheel::new(30.0, 10.0, 0.0, 0.0));
        assert_eq!(lsd.front(), 0.5);
        // Both front wheels stopped: 0/0 = NaN → reset to 0 (Webots behaviour).
        lsd.update(DriveType::Traction, &PerWheel::splat(0.0));
        assert_eq!(lsd.front(), 0.0);
        // ω_FR + ω_FL = 0 with ω_FR ≠ 0: r = ±∞ → saturated.
        lsd.update(DriveType::Traction, &PerWheel::new(5.0, -5.0, 0.0, 0.0));
        assert_eq!(lsd.front(), 1.0);
        lsd.update(DriveType::Traction, &PerWheel::new(-5.0, 5.0, 0.0, 0.0));
        // r = 2·(−5)/0 − 1 = −∞; 1 + (−∞) = −∞ → saturated at −1.
        assert_eq!(lsd.front(), -1.0);
    }

    #[test]
    fn disabled_keeps_states_and_ratios() {
        let mut lsd = LimitedSlip::<f64>::new();
        lsd.update(DriveType::Traction, &PerWheel::new(30.0, 10.0, 0.0, 0.0));
        lsd.set_enabled(false);
        assert!(!lsd.is_enabled());
        lsd.update(DriveType::Traction, &PerWheel::new(30.0, 10.0, 0.0, 0.0));
        assert_eq!(lsd.front(), 0.5);
        let r = DifferentialRatios::new(0.3, 0.4, 0.6);
        assert_eq!(lsd.apply(&r), r);
        lsd.set_enabled(true);
        assert_eq!(lsd.apply(&r).front, 0.3 * 0.5);
        lsd.reset();
        assert_eq!(lsd, LimitedSlip::default());
    }
}
