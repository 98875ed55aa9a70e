//! The driveline and wheel losses of a rolling car, as torques on each wheel's spin: the
//! "road-load" alternative to Webots' single viscous `wheelsDampingConstant`. With the tyres'
//! rolling resistance ([`crate::TyreParams::rolling_resistance`]) and the air
//! ([`crate::Aero`]) they make up what slows a coasting car.
//!
//! Per wheel spinning at `ω` (rad/s):
//! * a constant drag torque `T₀` (N·m) against the spin: brake pads that rub when released,
//!   seals, bearings; like a brake it stops a wheel and never turns it back;
//! * a viscous drag torque `b·ω` (N·m): gear and bearing churning, which grows with speed.
//!
//! A car coasting at `v` (m/s) on flat ground is then slowed by
//! `F(v) = D(v) + c_rr·m·g + Σ_w (T₀ + b·v/r_w)/r_w` (N), the physical counterpart of the
//! `A + B·v + C·v²` a coast-down test fits: `A` holds the rolling resistance and `T₀`, `B`
//! the viscous drag, `C` the air.
//!
//! A set may also carry the tyres' rolling resistance coefficient `c_rr`
//! ([`RoadLoad::rolling_resistance`]), which then replaces the tyre's own: each shipped model's
//! set ([`crate::Model::road_load`]) takes it from the US EPA's coast-down coefficients of
//! the real car, since a tyre class's single value cannot be every car's.

use ackermann::Real;

/// The driveline and wheel losses of a car (each wheel has the same).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoadLoad<T> {
    /// Constant drag torque `T₀` of each wheel's brake, bearing and seals (N·m, in [0, 100]).
    pub drag_torque: T,
    /// Viscous drag `b` of each wheel's driveline and bearing (N·m·s/rad, in [0, 10]): takes
    /// the place of Webots' `wheelsDampingConstant`.
    pub viscous_drag: T,
    /// The tyres' rolling resistance coefficient `c_rr` (dimensionless, in [0, 0.5], the
    /// tyre's own range), replacing [`crate::TyreParams::rolling_resistance`] of every tyre
    /// of the car; `None`: the tyre's own.
    pub rolling_resistance: Option<T>,
}

/// Which field of a [`RoadLoad`] is out of range, and its value.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct RoadLoadError {
    /// The field's name as world files spell it, e.g. `"drag_torque"`.
    pub field: &'static str,
    /// The rejected value.
    pub value: f64,
    /// What the field must satisfy, completing "must be …".
    pub rule: &'static str,
}

impl core::fmt::Display for RoadLoadError {
    fn fmt(&self, f: &mut core::fmt::Formatter<'_>) -> core::fmt::Result {
        write!(
            f,
            "invalid {} = {}: must be {}",
            self.field, self.value, self.rule
        )
    }
}

impl core::error::Error for RoadLoadError {}

/// Largest constant drag torque per wheel accepted (N·m): a released brake drags a few, a
/// seized one hundreds; 100 is a fault, not a loss.
const MAX_DRAG_TORQUE: f64 = 100.0;
/// Largest viscous drag accepted (N·m·s/rad): Webots' models use 1 to 30 as
/// `wheelsDampingConstant`; 10 already takes 3 kN from a car's four wheels at 100 km/h.
const MAX_VISCOUS_DRAG: f64 = 10.0;
/// Largest rolling resistance coefficient accepted: the tyre's own bound for
/// `rolling_resistance` (a tractor tyre in soft soil reaches 0.2; 0.5 is no rolling tyre).
const MAX_ROLLING_RESISTANCE: f64 = 0.5;

/// A released disc brake's residual drag and a wheel bearing's (N·m per wheel): residual
/// brake drag is commonly quoted at 0.5 to 3 N·m per corner, the bearing's a fraction of 1.
const DEFAULT_DRAG_TORQUE: f64 = 1.0;
/// The driveline's and bearings' churning per wheel (N·m·s/rad): 1 N·m at 80 rad/s, about
/// 100 km/h on a 0.35 m tyre, so the four wheels lose about 0.3 kW there, the order of a
/// single-speed drive unit's spin loss. An estimate: no shipped model's is published.
const DEFAULT_VISCOUS_DRAG: f64 = 0.0125;

impl<T: Real> Default for RoadLoad<T> {
    /// The estimates of 1 N·m of constant drag and 0.0125 N·m·s/rad of viscous drag per
    /// wheel (their reasons are at their constants in the source) and the tyre's own rolling
    /// resistance: the set of a car without published coast-down coefficients.
    fn default() -> Self {
        RoadLoad {
            drag_torque: T::from_f64(DEFAULT_DRAG_TORQUE),
            viscous_drag: T::from_f64(DEFAULT_VISCOUS_DRAG),
            rolling_resistance: None,
        }
    }
}

impl<T: Real> RoadLoad<T> {
    /// Checks every field: `T₀` in [0, 100] N·m, `b` in [0, 10] N·m·s/rad, `c_rr` (when
    /// given) in [0, 0.5] (the bounds' reasons are at their constants).
    ///
    /// # Errors
    /// The first [`RoadLoadError`] in field order.
    pub fn validated(self) -> Result<Self, RoadLoadError> {
        let check = |field, value: T, max: f64, rule| {
            let v = value.to_f64();
            if v.is_finite() && (0.0..=max).contains(&v) {
                Ok(())
            } else {
                Err(RoadLoadError {
                    field,
                    value: v,
                    rule,
                })
            }
        };
        check(
            "drag_torque",
            self.drag_torque,
            MAX_DRAG_TORQUE,
            "within [0, 100] N·m",
        )?;
        check(
            "viscous_drag",
            self.viscous_drag,
            MAX_VISCOUS_DRAG,
            "within [0, 10] N·m·s/rad",
        )?;
        if let Some(c) = self.rolling_resistance {
            check(
                "rolling_resistance",
                c,
                MAX_ROLLING_RESISTANCE,
                "within [0, 0.5]",
            )?;
        }
        Ok(self)
    }

    /// The resisting force (N) at the road of one wheel of `radius` (m, > 0) rolling without
    /// slip at `speed` (m/s, ≥ 0): its loss torques over the radius.
    pub fn wheel_force(&self, radius: T, speed: T) -> T {
        (self.drag_torque + self.viscous_drag * speed / radius) / radius
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_default_is_valid_and_bad_fields_are_refused_by_name() {
        let ok = RoadLoad::<f64>::default();
        assert_eq!(ok.validated(), Ok(ok));
        let bad = RoadLoad {
            drag_torque: -1.0,
            ..ok
        };
        assert_eq!(bad.validated().unwrap_err().field, "drag_torque");
        let bad = RoadLoad {
            viscous_drag: f64::NAN,
            ..ok
        };
        assert_eq!(bad.validated().unwrap_err().field, "viscous_drag");
        let bad = RoadLoad {
            rolling_resistance: Some(0.6),
            ..ok
        };
        assert_eq!(bad.validated().unwrap_err().field, "rolling_resistance");
    }

    #[test]
    fn the_wheel_force_is_the_torques_over_the_radius() {
        let r = RoadLoad {
            drag_torque: 2.0,
            viscous_drag: 0.5,
            rolling_resistance: None,
        };
        // 2 N·m / 0.4 m + 0.5 N·m·s/rad · (20 / 0.4) rad/s / 0.4 m.
        let expected = 5.0 + 0.5 * 50.0 / 0.4;
        assert!((r.wheel_force(0.4, 20.0) - expected).abs() < 1e-12);
    }
}
