//! A combustion engine's fuel use, by a Willans line: the fuel's power is the brake power plus
//! the engine's friction and pumping losses, over the indicated efficiency,
//! `ṁ_f = (T·ω + T_f(ω)·ω) / (η_i · Q_LHV)` (kg/s), with the friction torque
//! `T_f(ω) = T_f0 + k·ω²`. The brake-specific fuel consumption map it gives,
//! `BSFC(T, ω) = 3.6·10⁹ / (η_i·Q_LHV) · (1 + T_f(ω)/T)` (g/kWh), has the shape of measured
//! ones: high at light load, falling toward `3.6·10⁹/(η_i·Q_LHV)` at full load, and rising
//! again at high speed (Guzzella & Sciarretta, *Vehicle Propulsion Systems*, 2013, §3.2).

use ackermann::Real;

/// Lower heating value of petrol (J/kg): 43 MJ/kg (Heywood, *Internal Combustion Engine
/// Fundamentals*, 1988, app. D).
pub const PETROL_LHV: f64 = 43.0e6;
/// Density of petrol (kg/l), for litres: 0.745 kg/l (EN 228 allows 0.720–0.775).
pub const PETROL_DENSITY: f64 = 0.745;

/// A Willans-line fuel model of an engine.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct FuelModel<T> {
    /// Indicated efficiency `η_i` (dimensionless, in (0, 0.6]).
    pub indicated_efficiency: T,
    /// Friction torque at standstill `T_f0` (N·m, ≥ 0).
    pub friction_torque: T,
    /// Friction growth with speed `k` (N·m·s²/rad², ≥ 0).
    pub friction_speed: T,
    /// The fuel's lower heating value (J/kg, > 0).
    pub heating_value: T,
}

/// An engine's indicated efficiency: 0.38 for a modern port- or direct-injected petrol
/// engine (Heywood, ch. 5: gross indicated efficiencies of 0.35–0.42 at part load).
const INDICATED_EFFICIENCY: f64 = 0.38;
/// Friction mean effective pressure at low speed (Pa): 125 kPa, the middle of the 100–150 kPa
/// Heywood gives (ch. 13) for car engines. Friction is a property of the engine's size: a
/// mean effective pressure `p` over a four-stroke displacement `V_d` is the torque
/// `p·V_d/(4π)`.
const FRICTION_MEP: f64 = 125.0e3;
/// Full-load brake mean effective pressure of a naturally aspirated petrol engine (Pa):
/// 1.25 MPa (Heywood, ch. 13: 1.0–1.3 MPa). It gives the displacement a torque curve's peak
/// implies when the engine's own is not known ([`FuelModel::petrol`]), so that engine's
/// friction is a tenth of its peak torque.
const FULL_LOAD_BMEP: f64 = 1.25e6;
/// How much the friction grows up to the top speed (dimensionless): fmep roughly doubles
/// from idle to the rated speed.
const FRICTION_GROWTH: f64 = 1.0;
/// Radians per four-stroke cycle (two turns): a mean effective pressure `p` over a
/// displacement `V_d` does `p·V_d` of work per cycle, a torque of `p·V_d/(4π)`.
const RAD_PER_CYCLE: f64 = 4.0 * core::f64::consts::PI;

impl<T: Real> FuelModel<T> {
    /// A four-stroke petrol engine of `displacement` (m³, > 0) and top speed `max_speed`
    /// (rad/s): friction `FRICTION_MEP·V_d/(4π)` at low speed, doubling to the top speed, and
    /// the constants' efficiency and fuel. A non-finite or negative displacement gives no
    /// friction (a caller validates it first).
    ///
    /// ```
    /// use vehicle_model::energy::FuelModel;
    /// // 3.0 l: 125 kPa · 0.003 m³ / (4π) = 29.84 N·m.
    /// let e = FuelModel::<f64>::petrol_of_displacement(0.003, 680.0);
    /// assert!((e.friction_torque - 29.842).abs() < 1e-3);
    /// ```
    pub fn petrol_of_displacement(displacement: T, max_speed: T) -> Self {
        let f = T::from_f64;
        let t0 = (displacement * f(FRICTION_MEP / RAD_PER_CYCLE))
            .finite_or(T::ZERO)
            .max(T::ZERO);
        FuelModel {
            indicated_efficiency: f(INDICATED_EFFICIENCY),
            friction_torque: t0,
            friction_speed: (t0 * f(FRICTION_GROWTH) / (max_speed * max_speed)).finite_or(T::ZERO),
            heating_value: f(PETROL_LHV),
        }
    }

    /// A petrol engine whose displacement is not known, of `max_torque` (N·m, its curve's
    /// peak) and top speed `max_speed` (rad/s): the displacement that torque implies at a
    /// naturally aspirated engine's full-load bmep, `4π·T_max/1.25 MPa`, so its friction is a
    /// tenth of `max_torque` ([`FuelModel::petrol_of_displacement`]).
    pub fn petrol(max_torque: T, max_speed: T) -> Self {
        let displacement = max_torque * T::from_f64(RAD_PER_CYCLE / FULL_LOAD_BMEP);
        Self::petrol_of_displacement(displacement, max_speed)
    }

    /// The fuel mass rate (kg/s, ≥ 0) of the engine giving `torque` (N·m) at `speed` (rad/s,
    /// ≥ 0): a motored engine (negative torque) burns nothing (fuel cut on overrun), a
    /// stopped one nothing.
    pub fn fuel_rate(&self, torque: T, speed: T) -> T {
        let w = speed.finite_or(T::ZERO).max(T::ZERO);
        let t = torque.finite_or(T::ZERO);
        if t < T::ZERO || w <= T::ZERO {
            return T::ZERO;
        }
        let friction = self.friction_torque + self.friction_speed * w * w;
        ((t + friction) * w / (self.indicated_efficiency * self.heating_value)).max(T::ZERO)
    }

    /// The fuel mass rate (kg/s, ≥ 0) of the engine idling at `speed` (rad/s, ≥ 0) with no
    /// load: its friction's and pumping's power `T_f(ω)·ω` over the indicated efficiency,
    /// the Willans line's value at zero brake torque ([`FuelModel::fuel_rate`] of no torque).
    pub fn idle_rate(&self, speed: T) -> T {
        self.fuel_rate(T::ZERO, speed)
    }

    /// The brake-specific fuel consumption (g/kWh) at `torque` (N·m, > 0) and `speed`
    /// (rad/s, > 0); infinite at no load.
    pub fn bsfc(&self, torque: T, speed: T) -> T {
        self.fuel_rate(torque, speed) * T::from_f64(3.6e9) / (torque * speed)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_bsfc_map_falls_with_load_toward_the_indicated_limit() {
        // 250 N·m, 6500 rpm.
        let e = FuelModel::petrol(250.0, 6500.0 * crate::RAD_PER_S_PER_RPM);
        let w = 3000.0 * crate::RAD_PER_S_PER_RPM;
        let limit = 3.6e9 / (INDICATED_EFFICIENCY * PETROL_LHV);
        let full = e.bsfc(250.0, w);
        let light = e.bsfc(25.0, w);
        assert!(full > limit && full < 1.2 * limit, "{full} vs {limit}");
        assert!(light > 1.5 * full, "{light} vs {full}");
        // A modern petrol engine's best is 230–260 g/kWh.
        assert!((230.0..260.0).contains(&full), "{full}");
        // Fuel cut on overrun, nothing when stopped.
        assert_eq!(e.fuel_rate(-20.0, w), 0.0);
        assert_eq!(e.fuel_rate(100.0, 0.0), 0.0);
    }

    #[test]
    fn friction_is_the_friction_mep_over_the_displacement_and_a_tenth_of_an_unknown_engine_s_peak()
    {
        let top = 6000.0 * crate::RAD_PER_S_PER_RPM;
        // 5.0 l: 125 kPa · 0.005 m³ / (4π) = 49.736 N·m, doubling at the top speed.
        let v8 = FuelModel::petrol_of_displacement(0.005, top);
        let t0 = 125.0e3 * 0.005 / (4.0 * core::f64::consts::PI);
        assert!((v8.friction_torque - t0).abs() < 1e-12);
        assert!((v8.friction_speed * top * top - t0).abs() < 1e-9);
        // A curve peaking at 700 N·m implies 4π·700/1.25 MPa = 7.04 l: 70 N·m.
        let curve = FuelModel::petrol(700.0, top);
        assert!((curve.friction_torque - 70.0).abs() < 1e-9);
        // Bad displacements give no friction, never NaN; a zero top speed no growth.
        for d in [f64::NAN, -0.003, f64::INFINITY] {
            let e = FuelModel::petrol_of_displacement(d, top);
            assert_eq!((e.friction_torque, e.friction_speed), (0.0, 0.0), "{d}");
        }
        assert_eq!(
            FuelModel::petrol_of_displacement(0.003, 0.0).friction_speed,
            0.0
        );
        // f32 gives the same within its precision.
        let f = FuelModel::<f32>::petrol_of_displacement(0.005, top as f32);
        assert!((f64::from(f.friction_torque) - t0).abs() < t0 * 1e-6);
    }

    #[test]
    fn idling_burns_the_friction_power_over_the_indicated_efficiency() {
        // 250 N·m, 6500 rpm: at 1000 rpm the friction is 25·(1 + (1000/6500)²) N·m.
        let top = 6500.0 * crate::RAD_PER_S_PER_RPM;
        let e = FuelModel::petrol(250.0, top);
        let w = 1000.0 * crate::RAD_PER_S_PER_RPM;
        let friction = 25.0 * (1.0 + (1000.0_f64 / 6500.0).powi(2));
        let expected = friction * w / (INDICATED_EFFICIENCY * PETROL_LHV);
        assert!(
            (e.idle_rate(w) - expected).abs() < 1e-15,
            "{}",
            e.idle_rate(w)
        );
        // About 0.16 g/s (0.8 l/h): a 2–3 l petrol engine's idle is 0.6–1 l/h.
        assert!((1.4e-4..1.8e-4).contains(&expected), "{expected}");
        assert_eq!(e.idle_rate(f64::NAN), 0.0);
    }
}
