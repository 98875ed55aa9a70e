//! The engine's rotating inertia as the driven wheels feel it through the engaged gear.
//!
//! Webots' driver library has no engine state: its engine speed is read off the wheels and its
//! torque goes straight onto them, so a driven wheel spins up with its own inertia alone
//! (about 1 kg·m²) under the several kN·m of first gear. A real wheel drags the engine along:
//! turning the wheel by `ω` turns the engine by `ξ·ω` (`ξ` the overall engine-to-wheel
//! ratio), so the wheel carries the engine's inertia `J_e` as `J_e·ξ²`. Without it the wheel
//! of a car beyond its grip spins up at thousands of rad/s² and Webots' wheel-acceleration
//! limiter switches the torque on and off every step (ARCHITECTURE.md, "Launch chatter";
//! issue #35). A host that solves the wheels' spin adds [`Driveline::reflected_inertia`] to
//! the torque-driven wheels; the [`Driver`](crate::Driver) hands it over in
//! [`Commands::driveline`](crate::Commands::driveline) each step.
//!
//! # Source
//!
//! J. Y. Wong, *Theory of Ground Vehicles*, Wiley, chapter 3, "Performance characteristics of
//! road vehicles" (2nd ed. 1993, p. 211, as <http://hpwizard.com/car-weight.html> cites it;
//! the same relation is used across the vehicle-performance literature): the mass factor of a
//! passenger car, the ratio of the mass it accelerates as to its mass, is empirically
//! `γ_m = 1.04 + 0.0025·ξ₀²`, `ξ₀` the overall gear ratio. Its `ξ₀²` term is
//! the engine's inertia reflected through the gears, `J_e·ξ₀²/(m·r²)`, hence
//! `J_e = 0.0025·m·r²` (`m` the vehicle's mass, `r` the driven wheels' radius). Its constant
//! 0.04 is the wheels and the driveline turning at wheel speed; the simulator already gives
//! the wheels their own inertia and this module adds nothing for the rest (no source splits
//! the 0.04 between them).
//!
//! The correlation is for combustion-engined passenger cars. The project has no verified
//! rotor inertia of an electric machine, so electric and hybrid cars take the same
//! correlation as an assumption (their single reduction gears of 6–9 make the reflected term
//! the larger part of it), and so do the van, bus, truck and tractor models.

use ackermann::Real;

/// Wong's engine term of the passenger-car mass factor (dimensionless, per squared overall
/// ratio): `γ_m = 1.04 + 0.0025·ξ₀²` (module docs), so the engine's inertia is this times
/// `m·r²`.
pub const ENGINE_MASS_FACTOR: f64 = 0.0025;

/// The engine's rotating inertia and the overall ratio it is engaged through for one step.
///
/// ```
/// use vehicle_model::Driveline;
/// // A 1500 kg car on 0.3 m wheels: J_e = 0.0025·1500·0.09 = 0.3375 kg·m².
/// let engine = Driveline::<f64>::engine_inertia_of(1500.0, 0.3);
/// assert!((engine - 0.3375).abs() < 1e-12);
/// // In a first gear of overall ratio 10 the driven wheels carry 0.3375·100 = 33.75 kg·m².
/// let first = Driveline { engine_inertia: engine, ratio: 10.0 };
/// assert!((first.reflected_inertia() - 33.75).abs() < 1e-9);
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Driveline<T: Real> {
    /// The engine's rotating inertia about its crankshaft or rotor axis (kg·m², ≥ 0).
    pub engine_inertia: T,
    /// The overall engine-to-wheel ratio engaged (dimensionless; negative in reverse; 0: no
    /// gear engaged, the wheels turn free of the engine).
    pub ratio: T,
}

impl<T: Real> Driveline<T> {
    /// No gear engaged (neutral, or the driver's speed mode, where Webots' motors follow a
    /// speed and no engine is modelled): the wheels carry no engine inertia.
    pub const DISENGAGED: Driveline<T> = Driveline {
        engine_inertia: T::ZERO,
        ratio: T::ZERO,
    };

    /// Wong's engine inertia (kg·m², ≥ 0) of a car of mass `mass` (kg) on driven wheels of
    /// radius `radius` (m): `0.0025·m·r²` (module docs). 0 for a negative, NaN or infinite
    /// input, or a result beyond the float range.
    pub fn engine_inertia_of(mass: T, radius: T) -> T {
        let inertia = T::from_f64(ENGINE_MASS_FACTOR) * mass * radius * radius;
        if inertia.is_finite() && inertia > T::ZERO {
            inertia
        } else {
            T::ZERO
        }
    }

    /// The engine's inertia as the driven wheels feel it together (kg·m², ≥ 0):
    /// `J_e·ξ²`, to be shared by the driven wheels. 0 when disengaged and for a non-finite or
    /// negative inertia or ratio product (never NaN or ∞).
    pub fn reflected_inertia(&self) -> T {
        self.per_wheel_speed(self.ratio * self.ratio)
    }

    /// The engine's angular momentum per unit of the driven wheels' speed (kg·m², ≥ 0):
    /// `J_e·|ξ|`. The engine turns `|ξ|` times as fast as the wheels, so this is what its
    /// change of spin takes from the chassis when the wheels change speed (where
    /// [`Driveline::reflected_inertia`] is what it takes from the drive torque). 0 when
    /// disengaged; never NaN or ∞.
    pub fn engine_momentum(&self) -> T {
        self.per_wheel_speed(self.ratio.abs())
    }

    /// `J_e·factor`, or 0 if that is not a finite non-negative number.
    fn per_wheel_speed(&self, factor: T) -> T {
        let j = self.engine_inertia * factor;
        if j.is_finite() && j > T::ZERO {
            j
        } else {
            T::ZERO
        }
    }

    /// True if both numbers are finite.
    pub fn is_finite(&self) -> bool {
        self.engine_inertia.is_finite() && self.ratio.is_finite()
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Golden numbers from Wong's `γ_m = 1.04 + 0.0025·ξ₀²` (module docs) worked by hand.
    #[test]
    fn wong_engine_inertia_and_its_reflection() {
        // 1500 kg on 0.3 m wheels: J_e = 0.0025·1500·0.3² = 0.3375 kg·m² (exact in decimal).
        let j_e = Driveline::<f64>::engine_inertia_of(1500.0, 0.3);
        assert!((j_e - 0.3375).abs() < 1e-12, "{j_e}");
        // Through ξ = 10: 33.75 kg·m² at the wheels, i.e. 0.0025·10² = 0.25 of m·r² = 135 kg·m²,
        // Wong's mass factor less its 1.04; the engine's momentum per wheel speed 3.375 kg·m².
        let first = Driveline {
            engine_inertia: j_e,
            ratio: 10.0,
        };
        assert!((first.reflected_inertia() - 33.75).abs() < 1e-9);
        assert!((first.reflected_inertia() / (1500.0 * 0.09) - 0.25).abs() < 1e-12);
        assert!((first.engine_momentum() - 3.375).abs() < 1e-12);
        // Reverse (ξ = −12): the same inertia as +12, 0.3375·144 = 48.6 kg·m².
        let reverse = Driveline {
            ratio: -12.0,
            ..first
        };
        assert!((reverse.reflected_inertia() - 48.6).abs() < 1e-9);
        assert!((reverse.engine_momentum() - 4.05).abs() < 1e-12);
        // f32 gives the same within its precision (relative 1e-6).
        let f = Driveline::<f32> {
            engine_inertia: Driveline::<f32>::engine_inertia_of(1500.0, 0.3),
            ratio: 10.0,
        };
        assert!((f.reflected_inertia() - 33.75).abs() < 33.75 * 1e-6);
    }

    #[test]
    fn disengaged_and_bad_input_carry_nothing() {
        assert_eq!(Driveline::<f64>::DISENGAGED.reflected_inertia(), 0.0);
        assert_eq!(Driveline::<f64>::DISENGAGED.engine_momentum(), 0.0);
        for (m, r) in [(-1.0, 0.3), (f64::NAN, 0.3), (1500.0, f64::INFINITY)] {
            assert_eq!(Driveline::engine_inertia_of(m, r), 0.0);
        }
        assert_eq!(Driveline::<f32>::engine_inertia_of(1e30, 1e10), 0.0);
        let bad = [
            (f64::NAN, 10.0),
            (0.3, f64::NAN),
            (-0.3, 10.0),
            (1e300, 1e300),
        ];
        for (engine_inertia, ratio) in bad {
            let d = Driveline {
                engine_inertia,
                ratio,
            };
            assert_eq!(d.reflected_inertia(), 0.0);
            assert!(d.engine_momentum() >= 0.0 && d.engine_momentum().is_finite());
        }
    }
}
