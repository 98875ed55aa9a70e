//! An electric machine's losses over torque and speed, motoring and generating.
//!
//! The loss model is the usual four-term one of machine design (e.g. Hendershot & Miller,
//! *Design of Brushless Permanent-Magnet Machines*, 2010, ch. 10):
//! `P_loss(T, ω) = k_c·T² + k_i·|ω| + k_w·|ω|³ + P₀` (W), with
//! * copper loss `k_c·T²` (the current is proportional to the torque, its heat to its square),
//! * iron loss `k_i·|ω|` (hysteresis, proportional to the frequency),
//! * windage and friction `k_w·|ω|³`,
//! * a constant `P₀` for the inverter's switching and the controller.
//!
//! The electrical power is `P_e = T·ω + P_loss` (W) both ways: motoring, the machine draws the
//! mechanical power plus its losses; generating (`T·ω < 0`), it returns the mechanical power
//! less them. Same losses for the same `|T|` and `|ω|`, which is what a machine's efficiency
//! map, measured both ways, shows to within a point or two.

use ackermann::Real;

/// A machine's loss coefficients (see the module).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MotorLosses<T> {
    /// Copper-loss coefficient `k_c` (W/(N·m)², ≥ 0).
    pub copper: T,
    /// Iron-loss coefficient `k_i` (W·s/rad, ≥ 0).
    pub iron: T,
    /// Windage coefficient `k_w` (W·s³/rad³, ≥ 0).
    pub windage: T,
    /// Constant loss `P₀` (W, ≥ 0).
    pub constant: T,
}

/// Which field of a [`MotorLosses`] is out of range, and its value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct MotorError {
    /// The field's name as world files spell it, e.g. `"copper"`.
    pub field: &'static str,
    /// The rejected value.
    pub value: f64,
}

impl core::fmt::Display for MotorError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "invalid {} = {}: must be finite and >= 0",
            self.field, self.value
        )
    }
}

impl core::error::Error for MotorError {}

/// The share of each loss in the rated loss of [`MotorLosses::rated`]
/// `[copper, iron, windage, constant]`: a permanent-magnet traction machine at full torque
/// loses most in its copper, a little in its iron, to windage (at its top speed) and to its
/// inverter's fixed part (an assumed split). With it the efficiency peaks about a point
/// above the rated point's, at half torque near the corner speed.
const RATED_SPLIT: [f64; 4] = [0.75, 0.15, 0.05, 0.05];
/// The efficiency at the rated point (maximum torque at the corner speed, dimensionless):
/// traction machines and their inverters together reach 0.90–0.93 there (and real ones peak
/// at 0.95–0.97 at part load, higher than this model's peak: an inverter's switching loss
/// falls with the current, which the constant term leaves out).
const RATED_EFFICIENCY: f64 = 0.92;

impl<T: Real> MotorLosses<T> {
    /// The losses of a machine of `max_torque` (N·m, > 0), `max_power` (W, > 0) and top
    /// speed `max_speed` (rad/s, > 0): at its rated point (full torque at the corner speed
    /// `ω_b = P/T`) it loses `L = P·(1/η − 1)` with η = 0.92, 75 % of `L` in its copper,
    /// 15 % in its iron and 5 % as the constant there, and 5 % of `L` to windage at its top
    /// speed (windage grows with the cube of the speed, and a machine is
    /// designed so that it stays small where it spins fastest).
    pub fn rated(max_torque: T, max_power: T, max_speed: T) -> Self {
        let corner = max_power / max_torque;
        let f = T::from_f64;
        let loss = max_power * (T::ONE / f(RATED_EFFICIENCY) - T::ONE);
        let [c, i, w, k] = RATED_SPLIT.map(|s| loss * f(s));
        let top = max_speed.max(corner);
        MotorLosses {
            copper: c / (max_torque * max_torque),
            iron: i / corner,
            windage: w / (top * top * top),
            constant: k,
        }
    }

    /// Checks every coefficient is finite and non-negative.
    ///
    /// # Errors
    /// The first [`MotorError`] in field order.
    pub fn validated(self) -> Result<Self, MotorError> {
        for (field, v) in [
            ("copper", self.copper),
            ("iron", self.iron),
            ("windage", self.windage),
            ("constant", self.constant),
        ] {
            let v = v.to_f64();
            if !(v.is_finite() && v >= 0.0) {
                return Err(MotorError { field, value: v });
            }
        }
        Ok(self)
    }

    /// The same machine without its spin losses (iron and windage set to 0; copper and the
    /// constant kept): for a car whose driveline drag comes from a coast-down, which measured
    /// them already — the rotor turns with the wheels whether the machine drives or not, so
    /// its iron and windage losses slowed the coasting car ([`crate::RoadLoad`]).
    #[must_use]
    pub fn without_spin_losses(self) -> Self {
        MotorLosses {
            iron: T::ZERO,
            windage: T::ZERO,
            ..self
        }
    }

    /// The losses (W, ≥ 0) at `torque` (N·m) and `speed` (rad/s).
    pub fn loss(&self, torque: T, speed: T) -> T {
        let w = speed.abs();
        self.copper * torque * torque + self.iron * w + self.windage * w * w * w + self.constant
    }

    /// The electrical power (W; positive drawn, negative returned) at `torque` (N·m) and
    /// `speed` (rad/s): the mechanical power `T·ω` plus the losses.
    pub fn electrical_power(&self, torque: T, speed: T) -> T {
        torque * speed + self.loss(torque, speed)
    }

    /// The torque (N·m) at which the machine, turning at `speed` (rad/s, > 0), draws the
    /// electrical `power` (W; negative: returns it), the inverse of
    /// [`MotorLosses::electrical_power`]: the root of `k_c·T² + ω·T + S − P = 0` (`S` the
    /// speed's iron, windage and constant losses) on the branch through `T = (P − S)/ω`,
    /// written `2(P − S) / (ω + √(ω² + 4·k_c·(P − S)))` so that it holds for `k_c = 0`.
    /// `None` when standing or non-finite, or when generating more than the machine can
    /// return at that speed (`ω² + 4·k_c·(P − S) < 0`: the copper loss grows faster than
    /// the power).
    pub fn torque_for_electrical(&self, power: T, speed: T) -> Option<T> {
        let w = speed.abs();
        if !(w > T::ZERO && w.is_finite() && power.is_finite()) {
            return None;
        }
        let net = power - self.loss(T::ZERO, w);
        let discriminant = w * w + T::from_f64(4.0) * self.copper * net;
        if discriminant < T::ZERO {
            return None;
        }
        let torque = T::TWO * net / (w + discriminant.sqrt());
        // The torque's sign is that of the speed's direction.
        Some(if speed < T::ZERO { -torque } else { torque })
    }

    /// The largest generating torque (N·m, ≥ 0, braking the machine) at `speed` (rad/s,
    /// ≥ 0) whose returned electrical power stays within `charge` (W, what the battery
    /// takes): 0 when it takes nothing (`charge` ≤ 0 or NaN), the inverse of
    /// [`MotorLosses::electrical_power`] when it bounds the machine, and `None` when it does
    /// not (standing, or the machine returns less than `charge` at any torque at that speed):
    /// then the caller's own limit of the machine holds. Regenerative braking and a
    /// power-split hybrid's generator share it.
    pub fn generating_torque_within(&self, charge: T, speed: T) -> Option<T> {
        if charge.is_nan() || charge <= T::ZERO {
            return Some(T::ZERO);
        }
        self.torque_for_electrical(-charge, speed.abs())
            .map(|t| (-t).max(T::ZERO))
    }

    /// The efficiency (dimensionless, in [0, 1)) at `torque` (N·m) and `speed` (rad/s):
    /// mechanical over electrical power motoring, electrical over mechanical generating; 0
    /// where no power flows out (standing, or generating less than the losses).
    pub fn efficiency(&self, torque: T, speed: T) -> T {
        let mechanical = torque * speed;
        let electrical = self.electrical_power(torque, speed);
        let eta = if mechanical > T::ZERO {
            mechanical / electrical
        } else if mechanical < T::ZERO && electrical < T::ZERO {
            electrical / mechanical
        } else {
            T::ZERO
        };
        eta.finite_or(T::ZERO)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A 300 N·m, 150 kW machine: corner speed 500 rad/s, top speed 1000 rad/s.
    fn machine() -> MotorLosses<f64> {
        MotorLosses::rated(300.0, 150_000.0, 1000.0)
    }

    /// The rated loss `L` of [`machine`] (W).
    const RATED_LOSS: f64 = 150_000.0 * (1.0 / RATED_EFFICIENCY - 1.0);

    #[test]
    fn the_rated_point_has_the_rated_efficiency_both_ways_round_the_losses() {
        let m = machine();
        // At the corner speed the windage is (500/1000)³ of its share.
        let loss = RATED_LOSS * (0.75 + 0.15 + 0.05 / 8.0 + 0.05);
        let eta = m.efficiency(300.0, 500.0);
        assert!(
            (eta - 150_000.0 / (150_000.0 + loss)).abs() < 1e-12,
            "{eta}"
        );
        // Generating at the same point loses the same: η = 1 − loss/P.
        let loss = m.loss(300.0, 500.0);
        let generating = m.efficiency(-300.0, 500.0);
        assert!(
            (generating - (1.0 - loss / 150_000.0)).abs() < 1e-12,
            "{generating}"
        );
        assert!(
            generating < eta,
            "generating returns less than motoring takes"
        );
    }

    #[test]
    fn part_load_is_more_efficient_than_the_rated_point_and_standstill_gives_nothing() {
        let m = machine();
        // Half torque at the corner speed: copper loss a quarter of the rated one, the others
        // unchanged.
        let loss = RATED_LOSS * (0.1875 + 0.15 + 0.05 / 8.0 + 0.05);
        let expected = 75_000.0 / (75_000.0 + loss);
        let eta = m.efficiency(150.0, 500.0);
        assert!((eta - expected).abs() < 1e-12, "{eta} vs {expected}");
        assert!(eta > RATED_EFFICIENCY);
        assert_eq!(m.efficiency(300.0, 0.0), 0.0);
        // Standing still at full torque draws the copper and constant losses only.
        let expected = m.copper * 300.0 * 300.0 + m.constant;
        assert!((m.electrical_power(300.0, 0.0) - expected).abs() < 1e-9);
    }

    #[test]
    fn without_spin_losses_a_machine_loses_its_copper_and_constant_alone() {
        let m = machine().without_spin_losses();
        assert_eq!((m.iron, m.windage), (0.0, 0.0));
        assert_eq!(
            (m.copper, m.constant),
            (machine().copper, machine().constant)
        );
        // At the rated point: the copper share and the constant of the rated loss.
        let expected = RATED_LOSS * (0.75 + 0.05);
        assert!((m.loss(300.0, 500.0) - expected).abs() < 1e-9);
        // Spinning without torque: the constant alone, at any speed.
        assert_eq!(m.loss(0.0, 900.0), m.constant);
    }

    #[test]
    fn negative_or_nan_coefficients_are_refused_by_name() {
        let bad = MotorLosses {
            iron: -1.0,
            ..machine()
        };
        assert_eq!(bad.validated().unwrap_err().field, "iron");
        let bad = MotorLosses {
            constant: f64::NAN,
            ..machine()
        };
        assert_eq!(bad.validated().unwrap_err().field, "constant");
    }
    #[test]
    fn the_torque_for_an_electrical_power_inverts_the_electrical_power() {
        let m = machine();
        // Motoring and generating, below and at the rated point, at two speeds.
        for (torque, speed) in [
            (120.0, 300.0),
            (300.0, 500.0),
            (-200.0, 400.0),
            (-30.0, 900.0),
        ] {
            let p = m.electrical_power(torque, speed);
            let back = m.torque_for_electrical(p, speed).unwrap();
            assert!((back - torque).abs() < 1e-9, "{torque} at {speed}: {back}");
        }
        // The spin losses alone at no torque.
        let idle = m.loss(0.0, 500.0);
        assert!(m.torque_for_electrical(idle, 500.0).unwrap().abs() < 1e-12);
        // Without copper loss the inverse is linear: (P − S)/ω.
        let linear = MotorLosses { copper: 0.0, ..m };
        let p = 40_000.0;
        let expected = (p - linear.loss(0.0, 400.0)) / 400.0;
        assert!((linear.torque_for_electrical(p, 400.0).unwrap() - expected).abs() < 1e-12);
        // More returned than the machine can give at that speed, standing, or NaN: none.
        assert_eq!(m.torque_for_electrical(-1e9, 100.0), None);
        assert_eq!(m.torque_for_electrical(1000.0, 0.0), None);
        assert_eq!(m.torque_for_electrical(f64::NAN, 100.0), None);
    }

    #[test]
    fn the_generating_torque_within_a_charge_returns_that_charge_or_is_unbounded() {
        let m = machine();
        // Within the machine's reach: the torque whose return is the charge, exactly.
        let torque = m.generating_torque_within(20_000.0, 400.0).unwrap();
        assert!(torque > 0.0);
        assert!((m.electrical_power(-torque, 400.0) + 20_000.0).abs() < 1e-6);
        // No room, or NaN: no generating torque.
        assert_eq!(m.generating_torque_within(0.0, 400.0), Some(0.0));
        assert_eq!(m.generating_torque_within(f64::NAN, 400.0), Some(0.0));
        // More than the machine returns at that speed, or standing: the battery does not
        // bound the torque.
        assert_eq!(m.generating_torque_within(1e9, 100.0), None);
        assert_eq!(m.generating_torque_within(1000.0, 0.0), None);
    }
}
