//! Plausible physical ranges: the bounds every crate of the workspace checks a world's numbers
//! against, in one place.
//!
//! Webots accepts any positive number and lets a car of 10³⁰⁰ kg fail at its first step (or, worse,
//! produce meaningless results, such as a negative stop distance). These ranges are wide enough
//! for anything from a desk robot to a mining truck, and narrow enough that the physics (rapier
//! in `f32`, the tyre model, the fixed-step integrators) stays well-conditioned. A value outside
//! its range is refused with a warning naming the field, the value and the range.

use core::fmt;

/// A closed range `[min, max]` of plausible values for a physical quantity, with its unit.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Plausible {
    /// Smallest plausible value (unit [`Plausible::unit`]).
    pub min: f64,
    /// Largest plausible value (unit [`Plausible::unit`]).
    pub max: f64,
    /// The unit, as printed in messages (`"m"`, `"kg"`, …).
    pub unit: &'static str,
}

impl Plausible {
    /// True if `value` is finite and within `[min, max]`.
    #[inline]
    pub fn contains(&self, value: f64) -> bool {
        value.is_finite() && value >= self.min && value <= self.max
    }
}

impl fmt::Display for Plausible {
    /// `"0.001 to 1000 m"`: each bound as [`Compact`], then the unit.
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} to {}", Compact(self.min), Compact(self.max))?;
        if self.unit.is_empty() {
            Ok(())
        } else {
            write!(f, " {}", self.unit)
        }
    }
}

/// A number as a person reads it in a message: plainly between 1e-4 and 1e16, in exponent
/// form beyond (so −1e308 is `-1e308`, not 309 digits); `NaN`, `inf`, `-inf` as such.
///
/// ```
/// use proto_geom::plausible::Compact;
/// assert_eq!(Compact(1e300).to_string(), "1e300");
/// assert_eq!(Compact(2.5e-7).to_string(), "2.5e-7");
/// assert_eq!(Compact(-0.25).to_string(), "-0.25");
/// assert_eq!(Compact(0.0).to_string(), "0");
/// ```
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct Compact(pub f64);

impl fmt::Display for Compact {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let v = self.0;
        let magnitude = if v < 0.0 { -v } else { v };
        if v.is_finite() && v != 0.0 && !(1e-4..1e16).contains(&magnitude) {
            write!(f, "{v:e}")
        } else {
            write!(f, "{v}")
        }
    }
}

/// A body or wheel mass (kg): a 1 g part up to a 1,000 t vehicle.
pub const MASS: Plausible = Plausible {
    min: 1e-3,
    max: 1e6,
    unit: "kg",
};

/// A density (kg/m³): lighter than any foam below, denser than osmium (22,600) above.
pub const DENSITY: Plausible = Plausible {
    min: 1.0,
    max: 1e5,
    unit: "kg/m³",
};

/// A size of a body or a wheel, or a distance between wheels (m): 1 mm to 1 km.
pub const LENGTH: Plausible = Plausible {
    min: 1e-3,
    max: 1e3,
    unit: "m",
};

/// A position coordinate in the world (m). Beyond 10 km, rapier's `f32` positions resolve
/// no better than a millimetre, which a tyre contact needs.
pub const POSITION: Plausible = Plausible {
    min: -1e4,
    max: 1e4,
    unit: "m",
};

/// An offset inside a body, such as a centre of mass (m): within [`LENGTH`]'s largest size.
pub const OFFSET: Plausible = Plausible {
    min: -1e3,
    max: 1e3,
    unit: "m",
};

/// An inertia-matrix entry (kg·m²): the largest mass times the square of the largest length.
pub const INERTIA: Plausible = Plausible {
    min: -1e12,
    max: 1e12,
    unit: "kg·m²",
};

/// A suspension spring constant (N/m), 0 for none. The shipped trucks use 10⁶.
pub const SPRING: Plausible = Plausible {
    min: 0.0,
    max: 1e8,
    unit: "N/m",
};

/// A suspension damping constant (N·s/m), 0 for none.
pub const DAMPER: Plausible = Plausible {
    min: 0.0,
    max: 1e7,
    unit: "N·s/m",
};

/// A torque limit or brake torque (N·m), 0 for none.
pub const TORQUE: Plausible = Plausible {
    min: 0.0,
    max: 1e6,
    unit: "N·m",
};

/// A rotational damping constant (N·m·s/rad).
pub const ROTATIONAL_DAMPING: Plausible = Plausible {
    min: 0.0,
    max: 1e4,
    unit: "N·m·s/rad",
};

/// An engine power (W): up to 100 MW.
pub const POWER: Plausible = Plausible {
    min: 0.0,
    max: 1e8,
    unit: "W",
};

/// An engine speed (rpm).
pub const ENGINE_SPEED: Plausible = Plausible {
    min: 0.0,
    max: 1e5,
    unit: "rpm",
};

/// An engine's minimum speed (rpm): a fifth of [`ENGINE_SPEED`]'s limit, so that
/// `5·engineMinRPM`, the value an `engineMaxRPM` not above the minimum falls back to, is
/// itself plausible.
pub const ENGINE_MIN_SPEED: Plausible = Plausible {
    min: 0.0,
    max: 2e4,
    unit: "rpm",
};

/// A vehicle or wheel-surface speed (m/s): a little under Mach 3.
pub const SPEED: Plausible = Plausible {
    min: 0.0,
    max: 1e3,
    unit: "m/s",
};

/// A 0–100 km/h time (s): 0.1 s is 28 g, far beyond what any tyre transmits.
pub const TIME_0_TO_100: Plausible = Plausible {
    min: 0.1,
    max: 1e4,
    unit: "s",
};

/// A steering-angle limit (rad): within ±1.5 rad (86°), where the Ackermann geometry's
/// `tan` stays finite and meaningful.
pub const STEERING_ANGLE: Plausible = Plausible {
    min: -1.5,
    max: 1.5,
    unit: "rad",
};

/// The magnitude of a total engine-to-wheel gear ratio: the steepest gear of a road or farm
/// vehicle is below 100, the tallest overdrive above 0.1.
pub const GEAR_RATIO: Plausible = Plausible {
    min: 0.1,
    max: 100.0,
    unit: "",
};

/// An engine-function coefficient (N·m per rpmⁿ).
pub const COEFFICIENT: Plausible = Plausible {
    min: -1e6,
    max: 1e6,
    unit: "",
};

/// A Coulomb friction coefficient (dimensionless) of a surface: the ground's, an obstacle's,
/// a body's. Rubber grips dry asphalt at about 1, racing slicks and soft silicone reach 2 to
/// 4: 100 leaves room for a surface meant never to slide while keeping the physics finite.
/// rapier multiplies two surfaces' coefficients in f32 (at most 10⁴ here), and the tyre's
/// force is the coefficient times the load; a coefficient past `f32::MAX` (`1e39`) became
/// infinite in rapier and the tyre gripped nothing at all.
pub const FRICTION: Plausible = Plausible {
    min: 0.0,
    max: 100.0,
    unit: "",
};

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn bounds_are_inclusive_and_refuse_non_finite() {
        assert!(MASS.contains(1e-3) && MASS.contains(1e6));
        assert!(!MASS.contains(1e-300) && !MASS.contains(1e300));
        assert!(!LENGTH.contains(f64::NAN) && !POSITION.contains(f64::INFINITY));
        assert!(SPRING.contains(0.0) && !SPRING.contains(-1.0));
    }

    #[test]
    fn display_names_the_range_and_unit() {
        extern crate std;
        use std::string::ToString;
        assert_eq!(LENGTH.to_string(), "0.001 to 1000 m");
        assert_eq!(GEAR_RATIO.to_string(), "0.1 to 100");
    }
}
