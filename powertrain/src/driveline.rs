//! The rotating inertia of the engine and driveline, as the driven wheels feel it through a
//! closed clutch: what bounds a driven wheel's spin-up in a real car (issue #35).

use ackermann::{DriveType, PerWheel, Real, Wheel};

/// Wong's rotational-mass coefficient of the engine side (dimensionless): J. Y. Wong, *Theory
/// of Ground Vehicles* (4th ed., 2008), §3.1, gives the mass factor of a passenger car as
/// `γ_m = 1.04 + 0.0025·ξ₀²`, `ξ₀` the overall gear ratio (gearbox × final drive). The `1.04`
/// are the wheels; the term in `ξ₀²` is the engine and gearbox input reflected through the
/// ratio, `J_e·ξ₀² / (m·r²)`, so `J_e = 0.0025·m·r²` (kg·m²) for a car of mass `m` on wheels
/// of radius `r`.
pub const ENGINE_MASS_FACTOR: f64 = 0.0025;

/// How the driven wheels of a torque-mode car are driven.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash, Default)]
pub enum DrivelineModel {
    /// Webots' driver library exactly: the wheels carry only their own inertia and the output
    /// torque is scaled by the wheel-acceleration limiter
    /// ([`acceleration_limit_factor`](crate::acceleration_limit_factor)). A wheel spinning past
    /// its grip makes the limiter
    /// switch the torque on and off from one step to the next (issue #35). The default: what a
    /// controller on Webots itself gets.
    #[default]
    Webots,
    /// The engine and gearbox input turn with the driven wheels through the closed clutch:
    /// their inertia, reflected through the gear ratio, is added to the driven wheels'
    /// ([`Driveline::wheel_inertia`]) and the host integrates it with the wheel (implicitly,
    /// with the tyre), so a wheel past its grip spins up at the rate the engine's inertia
    /// allows; the limiter is not applied. The engine's torque is taken at the driven
    /// wheels' speed ([`engine_side_speeds`]), which it turns with (the reported rpm stays
    /// Webots' mean of all four), and the torque meets `engineMaxRPM` on a
    /// governor's droop line ([`governor_factor`]) rather than being cut there. Below the
    /// droop, the torque of a wheel that holds is Webots' for the same engine speed.
    Inertial,
}

/// The engine (+ gearbox input) inertia of a car, and its share on each driven wheel.
///
/// ```
/// use powertrain::Driveline;
/// // 1500 kg on 0.3 m wheels: J_e = 0.0025·1500·0.09 = 0.3375 kg·m².
/// let d = Driveline::<f64>::from_mass_factor(1500.0, 0.3).unwrap();
/// assert!((d.engine_inertia() - 0.3375).abs() < 1e-12);
/// // Through an overall ratio of 12 on two driven wheels: 0.3375·144/2 = 24.3 kg·m² each.
/// assert!((d.wheel_inertia(12.0, 2) - 24.3).abs() < 1e-9);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Driveline<T: Real> {
    /// Engine plus gearbox-input inertia about the crankshaft (kg·m², > 0, finite).
    engine_inertia: T,
}

impl<T: Real> Driveline<T> {
    /// The driveline of a car of `vehicle_mass` (kg) on driven wheels of radius
    /// `wheel_radius` (m) by Wong's mass factor ([`ENGINE_MASS_FACTOR`]): `J_e = 0.0025·m·r²`.
    /// The same for every engine type: Wong's figure is for combustion engines; an electric
    /// motor's rotor is lighter, so for electric cars this overstates the inertia (it then
    /// slows a grip-limited launch by up to `0.0025·ξ₀²` of the car's mass, a few per cent in
    /// first gear). `None` unless both are finite and > 0.
    pub fn from_mass_factor(vehicle_mass: T, wheel_radius: T) -> Option<Self> {
        let positive = |x: T| x.is_finite() && x > T::ZERO;
        if !(positive(vehicle_mass) && positive(wheel_radius)) {
            return None;
        }
        let engine_inertia =
            T::from_f64(ENGINE_MASS_FACTOR) * vehicle_mass * wheel_radius * wheel_radius;
        positive(engine_inertia).then_some(Driveline { engine_inertia })
    }

    /// Engine plus gearbox-input inertia (kg·m²).
    #[inline]
    pub fn engine_inertia(&self) -> T {
        self.engine_inertia
    }

    /// The engine inertia each of `driven_wheels` wheels carries through the overall ratio
    /// `ratio` (dimensionless; its sign is ignored): `J_e·ratio²/driven_wheels` (kg·m²), the
    /// engine's kinetic energy `½·J_e·(ratio·ω)²` shared equally by wheels turning at `ω`.
    /// Shared per wheel, the inertia also resists a difference of the driven wheels' spins,
    /// which an open differential leaves free: a departure of the model (COMPATIBILITY.md).
    /// 0 for no driven wheel; never NaN or ∞.
    pub fn wheel_inertia(&self, ratio: T, driven_wheels: usize) -> T {
        if driven_wheels == 0 {
            return T::ZERO;
        }
        let n = T::from_f64(driven_wheels as f64);
        let inertia = self.engine_inertia * ratio * ratio / n;
        if inertia.is_nan() {
            T::ZERO
        } else {
            inertia.min(T::MAX)
        }
    }
}

/// The governor's droop (dimensionless share of `engineMaxRPM`): in
/// [`DrivelineModel::Inertial`] the full-throttle torque falls linearly to 0 over the last
/// 5 % of the engine speed below `engineMaxRPM` ([`governor_factor`]), as an engine governor's
/// droop line does (the regulation of engine governors is a few per cent to 10 % of rated
/// speed), where Webots cuts it from full to 0 at `engineMaxRPM`. With the engine's inertia
/// on the wheels that cut is a delayed on/off switch again, at the top of every gear a spinning
/// wheel reaches: the engine speed bounces on it. On the droop line the engine speed's error
/// is multiplied by `1 − g` each step, `g = T·dt/(J_e·0.05·ω_max)` (`T` the engine torque
/// there, N·m; `dt` the step, s; `ω_max` the maximum engine speed, rad/s), since the torque
/// follows the speed the driver read at the end of the last step: it settles monotonically
/// for `g ≤ 1` — every shipped model at 10 ms (`g` ≤ 0.41) and most at 32 ms — and with a
/// decaying alternation for `1 < g < 2` (the Car, LincolnMKZ and MercedesBenzSprinter at
/// 32 ms, `g` = 1.15–1.31).
pub const GOVERNOR_DROOP: f64 = 0.05;

/// The factor (dimensionless, in [0, 1]) the engine torque is multiplied by at engine speed
/// `rpm` (rpm) for an engine of maximum speed `max_rpm` (rpm, > 0) in
/// [`DrivelineModel::Inertial`]: 1 up to `(1 − GOVERNOR_DROOP)·max_rpm`, then falling
/// linearly to 0 at `max_rpm`. 1 for a NaN engine speed (the torque is then 0 elsewhere).
pub fn governor_factor<T: Real>(rpm: T, max_rpm: T) -> T {
    let band = T::from_f64(GOVERNOR_DROOP) * max_rpm;
    let factor = (max_rpm - rpm) / band;
    if factor.is_nan() {
        T::ONE
    } else {
        factor.clamp(T::ZERO, T::ONE)
    }
}

/// The wheel speeds (rad/s) the engine turns with in [`DrivelineModel::Inertial`]: every
/// wheel at the mean of the driven wheels' speeds, so that
/// [`Powertrain::rpm`](crate::Powertrain::rpm)'s mean of four is the speed the engine turns
/// at through the closed clutch (the driver still reports Webots' estimate as its rpm). (Webots' mean of all four wheels reads a driven wheel
/// spinning in the air at half its speed on a two-wheel-drive car: the engine would give
/// torque beyond `engineMaxRPM` and power beyond `engineMaxPower`, into the inertia it now
/// turns.) NaN if a driven wheel's speed is NaN.
pub fn engine_side_speeds<T: Real>(wheel_speeds: &PerWheel<T>, drive: DriveType) -> PerWheel<T> {
    let (sum, count) = Wheel::ALL
        .into_iter()
        .filter(|&w| drive.drives(w))
        .fold((T::ZERO, T::ZERO), |(s, n), w| {
            (s + wheel_speeds[w], n + T::ONE)
        });
    PerWheel::splat(sum / count)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn wong_mass_factor() {
        // γ_m − 1.04 = J_e·ξ²/(m·r²) = 0.0025·ξ²: for ξ = 10 the engine side adds 25 % of the
        // car's mass, the textbook first-gear figure.
        let (m, r, xi) = (1200.0_f64, 0.31, 10.0);
        let d = Driveline::from_mass_factor(m, r).unwrap();
        let per_wheel = d.wheel_inertia(xi, 2);
        let equivalent_mass = 2.0 * per_wheel / (r * r);
        assert!((equivalent_mass / m - 0.25).abs() < 1e-12);
        // f32 too, and the sign of the ratio (reverse) does not matter.
        let d32 = Driveline::from_mass_factor(1200.0_f32, 0.31).unwrap();
        assert!((d32.wheel_inertia(-10.0, 4) - d32.wheel_inertia(10.0, 4)).abs() < 1e-6);
        assert_eq!(d.wheel_inertia(10.0, 0), 0.0);
    }

    #[test]
    fn engine_side_speeds_are_the_driven_wheels_mean() {
        // Front-driven: (10 + 30)/2 = 20 rad/s on every wheel; the rear wheels do not count.
        let w = PerWheel::new(10.0_f64, 30.0, 2.0, 2.0);
        assert_eq!(
            engine_side_speeds(&w, DriveType::Traction),
            PerWheel::splat(20.0)
        );
        assert_eq!(
            engine_side_speeds(&w, DriveType::Propulsion),
            PerWheel::splat(2.0)
        );
        assert_eq!(
            engine_side_speeds(&w, DriveType::FourByFour),
            PerWheel::splat(11.0)
        );
    }

    #[test]
    fn governor_droop() {
        // engineMaxRPM 6000: full torque to 5700 rpm, half at 5850, none from 6000.
        assert_eq!(governor_factor(5700.0_f64, 6000.0), 1.0);
        assert_eq!(governor_factor(1000.0_f64, 6000.0), 1.0);
        assert!((governor_factor(5850.0_f64, 6000.0) - 0.5).abs() < 1e-12);
        assert_eq!(governor_factor(6000.0_f64, 6000.0), 0.0);
        assert_eq!(governor_factor(7000.0_f32, 6000.0), 0.0);
        assert_eq!(governor_factor(f64::NAN, 6000.0), 1.0);
    }

    #[test]
    fn refuses_implausible_input() {
        for (m, r) in [
            (0.0, 0.3),
            (-1.0, 0.3),
            (1e3, f64::NAN),
            (f64::INFINITY, 0.3),
        ] {
            assert_eq!(Driveline::from_mass_factor(m, r), None);
        }
    }
}
