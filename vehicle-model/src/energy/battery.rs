//! A traction battery as an open-circuit voltage behind an internal resistance (the
//! "Rint" equivalent circuit), with its state of charge, capacity and current limits.
//!
//! For a terminal power `P` (W, positive discharging) the current solves
//! `P = (V_oc − R·I)·I`, i.e. `I = (V_oc − √(V_oc² − 4·R·P)) / (2·R)` (A), the root nearer
//! zero; the power a battery can give at most is `V_oc²/(4·R)` (at `I = V_oc/(2R)`). The
//! resistance dissipates `R·I²` either way, and the state of charge moves by
//! `−I·dt / (3600·capacity)`.

use ackermann::Real;

/// The number of points of an open-circuit-voltage table.
pub const OCV_POINTS: usize = 11;

/// A battery pack.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Battery<T> {
    /// The open-circuit voltage (V, increasing) at states of charge 0, 0.1, …, 1.
    pub ocv: [T; OCV_POINTS],
    /// The internal resistance (Ω, > 0).
    pub resistance: T,
    /// The capacity (A·h, > 0).
    pub capacity: T,
    /// The largest discharge current (A, > 0).
    pub max_discharge_current: T,
    /// The largest charge current (A, > 0).
    pub max_charge_current: T,
}

/// Which field of a [`Battery`] is out of range, and its value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BatteryError {
    /// The field's name as world files spell it, e.g. `"capacity"`.
    pub field: &'static str,
    /// The rejected value.
    pub value: f64,
    /// What the field must satisfy, completing "must be …".
    pub rule: &'static str,
}

impl core::fmt::Display for BatteryError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "invalid {} = {}: must be {}",
            self.field, self.value, self.rule
        )
    }
}

impl core::error::Error for BatteryError {}

/// What one step of a [`Battery`] did.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct BatteryStep<T> {
    /// The power at the terminals (W; positive given, negative taken), within the limits.
    pub power: T,
    /// The current (A; positive discharging).
    pub current: T,
    /// The heat in the internal resistance (W, ≥ 0).
    pub loss: T,
    /// The state of charge after the step (dimensionless, in [0, 1]).
    pub soc: T,
}

/// A lithium-ion NMC cell's open-circuit voltage at states of charge 0, 0.1, …, 1 (V): a
/// typical curve of the chemistry (3.0 V empty, a plateau near 3.6–3.7 V, 4.2 V full), as
/// cell makers' data sheets draw it.
const NMC_CELL_OCV: [f64; OCV_POINTS] =
    [3.0, 3.45, 3.55, 3.6, 3.65, 3.7, 3.78, 3.88, 3.98, 4.08, 4.2];
/// A nickel-metal-hydride cell's open-circuit voltage at states of charge 0, 0.1, …, 1 (V):
/// flat about its nominal 1.2 V.
const NIMH_CELL_OCV: [f64; OCV_POINTS] = [
    1.1, 1.18, 1.2, 1.21, 1.22, 1.23, 1.24, 1.25, 1.26, 1.28, 1.35,
];

impl<T: Real> Battery<T> {
    /// A pack of `series` cells of `cell_ocv` (V), `capacity` (A·h), `resistance` (Ω) and
    /// limits of `max_c_rate` times the capacity both ways.
    fn pack(
        cell_ocv: [f64; OCV_POINTS],
        series: f64,
        capacity: f64,
        resistance: f64,
        max_c_rate: f64,
    ) -> Self {
        let f = T::from_f64;
        Battery {
            ocv: cell_ocv.map(|v| f(v * series)),
            resistance: f(resistance),
            capacity: f(capacity),
            max_discharge_current: f(capacity * max_c_rate),
            max_charge_current: f(capacity * max_c_rate),
        }
    }

    /// A battery-electric car's pack: 96 NMC cells in series (about 355 V nominal, the
    /// usual 400 V-class pack), 210 A·h (about 75 kWh), 0.1 Ω, 3 C.
    pub fn electric_car() -> Self {
        Self::pack(NMC_CELL_OCV, 96.0, 210.0, 0.1, 3.0)
    }

    /// A hybrid's pack: 168 NiMH cells in series (201.6 V nominal), 6.5 A·h, 0.3 Ω, 15 C:
    /// the figures Toyota gives for the Prius' pack.
    pub fn hybrid() -> Self {
        Self::pack(NIMH_CELL_OCV, 168.0, 6.5, 0.3, 15.0)
    }

    /// Checks the table increases and every value is finite and positive.
    ///
    /// # Errors
    /// The first [`BatteryError`].
    pub fn validated(self) -> Result<Self, BatteryError> {
        let positive = |field, v: T| {
            let v = v.to_f64();
            if v.is_finite() && v > 0.0 {
                Ok(())
            } else {
                Err(BatteryError {
                    field,
                    value: v,
                    rule: "finite and > 0",
                })
            }
        };
        let mut last = 0.0;
        for v in self.ocv {
            positive("ocv", v)?;
            if v.to_f64() <= last {
                return Err(BatteryError {
                    field: "ocv",
                    value: v.to_f64(),
                    rule: "greater than the voltage before it",
                });
            }
            last = v.to_f64();
        }
        positive("resistance", self.resistance)?;
        positive("capacity", self.capacity)?;
        positive("max_discharge_current", self.max_discharge_current)?;
        positive("max_charge_current", self.max_charge_current)?;
        Ok(self)
    }

    /// The open-circuit voltage (V) at state of charge `soc` (clamped to [0, 1]), linear
    /// between the table's points.
    pub fn open_circuit_voltage(&self, soc: T) -> T {
        let x = soc.finite_or(T::ZERO).clamp(T::ZERO, T::ONE) * T::from_f64(10.0);
        let i = x.floor().to_f64().clamp(0.0, 9.0) as usize;
        let frac = x - T::from_f64(i as f64);
        self.ocv[i] + (self.ocv[i + 1] - self.ocv[i]) * frac
    }

    /// The stored energy (J) at `soc`: `∫ V_oc dq` from empty, by the trapezoids of the
    /// table.
    pub fn energy(&self, soc: T) -> T {
        let soc = soc.finite_or(T::ZERO).clamp(T::ZERO, T::ONE);
        let coulombs_per_tenth = self.capacity * T::from_f64(360.0);
        let mut e = T::ZERO;
        for i in 0..OCV_POINTS - 1 {
            let lo = T::from_f64(i as f64 / 10.0);
            if soc <= lo {
                break;
            }
            let share = ((soc - lo) * T::from_f64(10.0)).min(T::ONE);
            let v_end = self.open_circuit_voltage(lo + share / T::from_f64(10.0));
            e += T::HALF * (self.ocv[i] + v_end) * coulombs_per_tenth * share;
        }
        e
    }

    /// The most power (W, ≥ 0) the battery gives at its terminals at `soc`, as
    /// [`Battery::step`] limits it: at the current `min(V_oc/(2R), max_discharge_current)`,
    /// `(V_oc − R·I)·I`; 0 when empty.
    pub fn max_discharge_power(&self, soc: T) -> T {
        let soc = soc.finite_or(T::ZERO);
        if soc <= T::ZERO {
            return T::ZERO;
        }
        let v = self.open_circuit_voltage(soc);
        let i = (v / (T::TWO * self.resistance)).min(self.max_discharge_current);
        ((v - self.resistance * i) * i).max(T::ZERO)
    }

    /// The most power (W, ≥ 0) the battery takes at its terminals at `soc`, as
    /// [`Battery::step`] limits it: at the current `max_charge_current`, `(V_oc + R·I)·I`;
    /// 0 when full.
    pub fn max_charge_power(&self, soc: T) -> T {
        let soc = soc.finite_or(T::ONE);
        if soc >= T::ONE {
            return T::ZERO;
        }
        let v = self.open_circuit_voltage(soc);
        let i = self.max_charge_current;
        (v + self.resistance * i) * i
    }

    /// Gives `power` (W; positive discharging, negative charging) for `dt` s from `soc`,
    /// within the current limits, the most power the cells can give (`V_oc²/4R`), and the
    /// charge left: an empty battery gives nothing, a full one takes nothing.
    pub fn step(&self, soc: T, power: T, dt: T) -> BatteryStep<T> {
        let soc = soc.finite_or(T::ZERO).clamp(T::ZERO, T::ONE);
        let power = power.finite_or(T::ZERO);
        let v = self.open_circuit_voltage(soc);
        let r = self.resistance;
        let most = v * v / (T::from_f64(4.0) * r);
        let p = power.min(most);
        let root = (v * v - T::from_f64(4.0) * r * p).max(T::ZERO).sqrt();
        let mut current = (v - root) / (T::TWO * r);
        current = current.clamp(-self.max_charge_current, self.max_discharge_current);
        // The charge there is to move this step (A), either way.
        let dt = dt.max(T::ZERO);
        let coulombs = self.capacity * T::from_f64(3600.0);
        if dt > T::ZERO {
            let available = soc * coulombs / dt;
            let room = (T::ONE - soc) * coulombs / dt;
            current = current.clamp(-room, available);
        }
        let soc = (soc - current * dt / coulombs).clamp(T::ZERO, T::ONE);
        BatteryStep {
            power: (v - r * current) * current,
            current,
            loss: r * current * current,
            soc,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_power_given_is_the_voltage_under_load_times_the_current() {
        let b = Battery::<f64>::electric_car();
        let s = b.step(0.5, 50_000.0, 0.01);
        assert!((s.power - 50_000.0).abs() < 1e-6, "{s:?}");
        let v = b.open_circuit_voltage(0.5);
        // Energy balance: the cells give V_oc·I, the terminals P, the resistance the rest.
        assert!((v * s.current - s.power - s.loss).abs() < 1e-6, "{s:?}");
        // The charge moved: I·dt over the capacity in coulombs.
        let expected = 0.5 - s.current * 0.01 / (210.0 * 3600.0);
        assert!((s.soc - expected).abs() < 1e-15);
    }

    #[test]
    fn limits_hold_and_the_charge_stays_in_zero_to_one() {
        let b = Battery::<f64>::hybrid();
        // 1 MW asked of a 6.5 A·h pack: the 15 C limit, 97.5 A.
        let s = b.step(0.5, 1e6, 0.01);
        assert!((s.current - 97.5).abs() < 1e-9, "{s:?}");
        let s = b.step(0.5, -1e6, 0.01);
        assert!((s.current + 97.5).abs() < 1e-9, "{s:?}");
        // Empty: nothing more comes out; full: nothing more goes in.
        let s = b.step(0.0, 10_000.0, 0.01);
        assert_eq!((s.current, s.soc), (0.0, 0.0));
        let s = b.step(1.0, -10_000.0, 0.01);
        assert_eq!((s.current, s.soc), (0.0, 1.0));
        // A step that would overdraw the last charge takes exactly it.
        let s = b.step(1e-6, 10_000.0, 10.0);
        assert_eq!(s.soc, 0.0);
    }

    #[test]
    fn the_stored_energy_is_the_integral_of_the_voltage_over_the_charge() {
        let b = Battery::<f64>::electric_car();
        // Full: the trapezoids of the table; the NMC pack holds about 75 kWh.
        let kwh = b.energy(1.0) / 3.6e6;
        assert!((70.0..80.0).contains(&kwh), "{kwh}");
        // Half a tenth at the bottom: a trapezoid from 3.0 to 3.225 V per cell.
        let expected = 0.5 * (b.ocv[0] + b.open_circuit_voltage(0.05)) * 210.0 * 180.0;
        assert!((b.energy(0.05) - expected).abs() < 1e-6);
    }

    #[test]
    fn a_falling_table_or_a_zero_capacity_is_refused_by_name() {
        let mut b = Battery::<f64>::electric_car();
        b.ocv[3] = b.ocv[2];
        assert_eq!(b.validated().unwrap_err().field, "ocv");
        let b = Battery {
            capacity: 0.0,
            ..Battery::<f64>::electric_car()
        };
        assert_eq!(b.validated().unwrap_err().field, "capacity");
    }
    #[test]
    fn the_power_limits_are_the_current_limits_through_the_resistance() {
        let b = Battery::<f64>::electric_car();
        // Half charged, V_oc from the table; the pack's 3 C limit, 630 A, is below
        // V_oc/(2R), so it is the current the most power flows at.
        let v = b.open_circuit_voltage(0.5);
        let i = b.max_discharge_current;
        assert!(i < v / (2.0 * b.resistance));
        let most = (v - b.resistance * i) * i;
        assert!((b.max_discharge_power(0.5) - most).abs() < 1e-6);
        // A step asked for more gives exactly that.
        let s = b.step(0.5, 1e7, 0.01);
        assert!((s.power - most).abs() < 1e-6, "{s:?}");
        let i = b.max_charge_current;
        let taken = (v + b.resistance * i) * i;
        assert!((b.max_charge_power(0.5) - taken).abs() < 1e-6);
        assert!((b.step(0.5, -1e7, 0.01).power + taken).abs() < 1e-6);
        assert_eq!(b.max_discharge_power(0.0), 0.0);
        assert_eq!(b.max_charge_power(1.0), 0.0);
        assert_eq!(b.max_discharge_power(f64::NAN), 0.0);
    }
}
