//! The rotating inertia of the engine and driveline, as the driven wheels feel it through a
//! closed clutch: what bounds a driven wheel's spin-up in a real car (issue #35).

use ackermann::Real;

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
    /// torque is scaled by the wheel-acceleration limiter ([`acceleration_limit_factor`]
    /// (crate::acceleration_limit_factor)). A wheel spinning past its grip makes the limiter
    /// switch the torque on and off from one step to the next (issue #35). The default: what a
    /// controller on Webots itself gets.
    #[default]
    Webots,
    /// The engine and gearbox input turn with the driven wheels through the closed clutch:
    /// their inertia, reflected through the gear ratio, is added to the driven wheels'
    /// ([`Driveline::wheel_inertia`]) and the host integrates it with the wheel (implicitly,
    /// with the tyre), so a wheel past its grip spins up at the rate the engine's inertia
    /// allows; the limiter is not applied. The torque of a wheel that holds is Webots'.
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
    fn refuses_implausible_input() {
        for (m, r) in [(0.0, 0.3), (-1.0, 0.3), (1e3, f64::NAN), (f64::INFINITY, 0.3)] {
            assert_eq!(Driveline::from_mass_factor(m, r), None);
        }
    }
}
