//! The coefficients of the slip-based tyre, their ranges and the default sets.

use core::fmt;

use ackermann::Real;

use super::MagicFormula;

/// One direction's force–slip characteristic of a [`TyreParams`] (longitudinal: force against
/// slip ratio κ; lateral: force against slip angle α).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct SlipCurve<T> {
    /// Peak friction coefficient at the nominal load on a road of friction 1 (dimensionless):
    /// the Magic Formula `D / F_z`. The road's friction (the ground's `friction`, Webots'
    /// `coulombFriction`) multiplies it.
    pub peak_friction: T,
    /// Slip stiffness per unit load at the nominal load, the slope of the force at zero slip
    /// over the load: `B·C·D / F_z` (1 per unit slip ratio longitudinally, 1/rad laterally).
    pub stiffness: T,
    /// Magic Formula shape factor `C` (dimensionless, 1 < C < 2): with the curvature, where
    /// the peak lies and how far the force falls after it (to `sin(C·π/2)` of the peak).
    pub shape: T,
    /// Magic Formula curvature factor `E` (dimensionless, < 1): larger values move the peak to
    /// larger slip and keep the force near the peak for longer.
    pub curvature: T,
    /// Relaxation length (m): the distance the tyre rolls while its force builds up to a
    /// change of slip (63 %).
    pub relaxation_length: T,
}

/// The coefficients of the slip-based tyre ([`MagicFormula`]); validate them with
/// [`TyreParams::validate`].
///
/// Every force scales with the load `F_z` on the tyre. The peak friction falls with load
/// (`load_sensitivity`) and the cornering stiffness grows less than linearly with load, with
/// its maximum at `cornering_saturation` × the nominal load (Pacejka's
/// `C_α = p₁·F_z0·sin(2·atan(F_z / (p₂·F_z0)))`); the longitudinal stiffness is proportional to
/// the load.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TyreParams<T> {
    /// Force against slip ratio.
    pub longitudinal: SlipCurve<T>,
    /// Force against slip angle.
    pub lateral: SlipCurve<T>,
    /// The load at which the curves' friction and stiffness are given (N, > 0): normally the
    /// tyre's static load on the car.
    pub nominal_load: T,
    /// Fall of the peak friction per unit of relative extra load (dimensionless, ≥ 0):
    /// `μ(F_z) = μ·(1 − ε·(F_z − F_z0)/F_z0)`, kept within [0.5, 1.5]·μ.
    pub load_sensitivity: T,
    /// Load over the nominal load at which the cornering stiffness peaks (dimensionless, > 0;
    /// Pacejka's `p₂`).
    pub cornering_saturation: T,
    /// Rolling-resistance coefficient (dimensionless, ≥ 0): a torque of `c_rr·F_z·r` against
    /// the wheel's rotation that holds a stopped wheel, like a brake.
    pub rolling_resistance: T,
    /// Damping time of the tyre's carcass at walking pace and below (s, ≥ 0): the contact
    /// patch's spring (the slip stiffness over the relaxation length) gets a parallel damper
    /// of this time constant, fading out by [`super::LOW_SPEED`].
    pub low_speed_damping: T,
}

/// The kind of tyre a default set is made for.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum TyreClass {
    /// Passenger-car radials on dry asphalt.
    PassengerCar,
    /// Van, bus and truck tyres (higher pressure, lower friction and stiffness per unit load).
    Commercial,
    /// Agricultural tractor tyres on a firm surface.
    Tractor,
}

impl TyreClass {
    /// The default coefficients of this class for a tyre of `radius` (m) carrying
    /// `nominal_load` (N). The relaxation lengths scale with the radius.
    ///
    /// The relaxation lengths and the nominal load saturate at the bounds that
    /// [`TyreParams::validate`] accepts (0.001–10 m, 1–1e6 N), so every plausible car (tyres of
    /// up to 1000 m, up to 1e6 kg) gets a valid default set.
    ///
    /// Where the numbers come from (textbook ranges; each set is one point inside them):
    /// * passenger car (Pacejka, *Tire and Vehicle Dynamics*; Gillespie, *Fundamentals of
    ///   Vehicle Dynamics*): cornering stiffness 15–25 `F_z` per rad (here 18), longitudinal
    ///   stiffness larger (here 25 `F_z`), peak friction 1.0–1.1 on dry asphalt with a locked
    ///   wheel at 0.7–0.8 of it (here 1.0 and 0.75 at κ = −1: `C = 1.65`, `E = 0.7`, peak at
    ///   κ ≈ 0.14), lateral `C ≈ 1.3` (peak at α ≈ 8.4°), relaxation length of the order of the
    ///   radius laterally and shorter longitudinally, rolling resistance 0.010–0.015 (0.012);
    /// * commercial: lower friction (0.8–0.85) and cornering stiffness (≈ 10 `F_z` per rad)
    ///   at their high loads, longer relaxation, rolling resistance 0.005–0.008 (0.007);
    /// * tractor (Wong, *Theory of Ground Vehicles*): soft, large tyres, cornering stiffness
    ///   ≈ 6 `F_z` per rad, friction 0.7–0.8 on a firm surface, rolling resistance 0.02–0.04
    ///   on firm ground (0.03).
    ///
    /// The load sensitivity (0.1: the peak friction drops 1 % per 10 % of extra load) and the
    /// cornering-stiffness saturation (at twice the nominal load) are those of Pacejka's
    /// example MF data sets (`p_Dy2/p_Dy1 ≈ −0.1`, `p_Ky2 ≈ 2`).
    pub fn params<T: Real>(self, radius: T, nominal_load: T) -> TyreParams<T> {
        let f = T::from_f64;
        let within = |field: TyreField, v: T| {
            let (lo, hi) = field.range();
            v.clamp(f(lo), f(hi))
        };
        let nominal_load = within(TyreField::NominalLoad, nominal_load);
        // (μ, stiffness, C, E, relaxation length / radius) per direction, then c_rr.
        let (long, lat, rolling) = match self {
            TyreClass::PassengerCar => (
                (1.0, 25.0, 1.65, 0.7, 0.4),
                (0.95, 18.0, 1.3, -0.5, 1.0),
                0.012,
            ),
            TyreClass::Commercial => (
                (0.85, 18.0, 1.65, 0.7, 0.5),
                (0.8, 10.0, 1.3, -0.5, 1.5),
                0.007,
            ),
            TyreClass::Tractor => ((0.8, 10.0, 1.5, 0.5, 0.5), (0.7, 6.0, 1.3, -0.5, 1.2), 0.03),
        };
        let curve = |(mu, k, c, e, sigma): (f64, f64, f64, f64, f64)| SlipCurve {
            peak_friction: f(mu),
            stiffness: f(k),
            shape: f(c),
            curvature: f(e),
            relaxation_length: within(
                TyreField::RelaxationLength(Direction::Longitudinal),
                f(sigma) * radius,
            ),
        };
        TyreParams {
            longitudinal: curve(long),
            lateral: curve(lat),
            nominal_load,
            load_sensitivity: f(0.1),
            cornering_saturation: f(2.0),
            rolling_resistance: f(rolling),
            low_speed_damping: f(0.02),
        }
    }

    /// The class's name in world files: `passenger-car`, `commercial`, `tractor`.
    pub const fn name(self) -> &'static str {
        match self {
            TyreClass::PassengerCar => "passenger-car",
            TyreClass::Commercial => "commercial",
            TyreClass::Tractor => "tractor",
        }
    }

    /// Every class.
    pub const ALL: [TyreClass; 3] = [
        TyreClass::PassengerCar,
        TyreClass::Commercial,
        TyreClass::Tractor,
    ];
}

/// A coefficient of [`TyreParams`], named as in world files (`[vehicle.tyre]`, with the
/// curve coefficients in `[vehicle.tyre.longitudinal]` and `[vehicle.tyre.lateral]`).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum TyreField {
    /// [`SlipCurve::peak_friction`] of the longitudinal or lateral curve.
    PeakFriction(Direction),
    /// [`SlipCurve::stiffness`].
    Stiffness(Direction),
    /// [`SlipCurve::shape`].
    Shape(Direction),
    /// [`SlipCurve::curvature`].
    Curvature(Direction),
    /// [`SlipCurve::relaxation_length`].
    RelaxationLength(Direction),
    /// [`TyreParams::nominal_load`].
    NominalLoad,
    /// [`TyreParams::load_sensitivity`].
    LoadSensitivity,
    /// [`TyreParams::cornering_saturation`].
    CorneringSaturation,
    /// [`TyreParams::rolling_resistance`].
    RollingResistance,
    /// [`TyreParams::low_speed_damping`].
    LowSpeedDamping,
}

/// A direction of the tyre's force.
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum Direction {
    /// Along the wheel's heading (slip ratio).
    Longitudinal,
    /// Along the wheel's axis (slip angle).
    Lateral,
}

impl Direction {
    /// `longitudinal` or `lateral`: the sub-table of `[vehicle.tyre]`.
    pub const fn name(self) -> &'static str {
        match self {
            Direction::Longitudinal => "longitudinal",
            Direction::Lateral => "lateral",
        }
    }
}

impl TyreField {
    /// The names of the curve coefficients, keys of `[vehicle.tyre.longitudinal]` and
    /// `[vehicle.tyre.lateral]`.
    pub const CURVE_NAMES: [&'static str; 5] = [
        "peak_friction",
        "stiffness",
        "shape",
        "curvature",
        "relaxation_length",
    ];
    /// The names of the tyre-wide coefficients, keys of `[vehicle.tyre]`.
    pub const TYRE_NAMES: [&'static str; 5] = [
        "nominal_load",
        "load_sensitivity",
        "cornering_saturation",
        "rolling_resistance",
        "low_speed_damping",
    ];

    /// The field of a tyre-wide key, or of a curve key in `direction`'s sub-table.
    pub fn from_name(name: &str, direction: Option<Direction>) -> Option<TyreField> {
        Some(match (direction, name) {
            (Some(d), "peak_friction") => TyreField::PeakFriction(d),
            (Some(d), "stiffness") => TyreField::Stiffness(d),
            (Some(d), "shape") => TyreField::Shape(d),
            (Some(d), "curvature") => TyreField::Curvature(d),
            (Some(d), "relaxation_length") => TyreField::RelaxationLength(d),
            (None, "nominal_load") => TyreField::NominalLoad,
            (None, "load_sensitivity") => TyreField::LoadSensitivity,
            (None, "cornering_saturation") => TyreField::CorneringSaturation,
            (None, "rolling_resistance") => TyreField::RollingResistance,
            (None, "low_speed_damping") => TyreField::LowSpeedDamping,
            _ => return None,
        })
    }

    /// The key's name (without its sub-table).
    pub const fn name(self) -> &'static str {
        match self {
            TyreField::PeakFriction(_) => "peak_friction",
            TyreField::Stiffness(_) => "stiffness",
            TyreField::Shape(_) => "shape",
            TyreField::Curvature(_) => "curvature",
            TyreField::RelaxationLength(_) => "relaxation_length",
            TyreField::NominalLoad => "nominal_load",
            TyreField::LoadSensitivity => "load_sensitivity",
            TyreField::CorneringSaturation => "cornering_saturation",
            TyreField::RollingResistance => "rolling_resistance",
            TyreField::LowSpeedDamping => "low_speed_damping",
        }
    }

    /// The full dotted name, e.g. `tyre.lateral.shape` or `tyre.nominal_load`.
    pub const fn path(self) -> &'static str {
        use Direction::{Lateral as Y, Longitudinal as X};
        match self {
            TyreField::PeakFriction(X) => "tyre.longitudinal.peak_friction",
            TyreField::Stiffness(X) => "tyre.longitudinal.stiffness",
            TyreField::Shape(X) => "tyre.longitudinal.shape",
            TyreField::Curvature(X) => "tyre.longitudinal.curvature",
            TyreField::RelaxationLength(X) => "tyre.longitudinal.relaxation_length",
            TyreField::PeakFriction(Y) => "tyre.lateral.peak_friction",
            TyreField::Stiffness(Y) => "tyre.lateral.stiffness",
            TyreField::Shape(Y) => "tyre.lateral.shape",
            TyreField::Curvature(Y) => "tyre.lateral.curvature",
            TyreField::RelaxationLength(Y) => "tyre.lateral.relaxation_length",
            TyreField::NominalLoad => "tyre.nominal_load",
            TyreField::LoadSensitivity => "tyre.load_sensitivity",
            TyreField::CorneringSaturation => "tyre.cornering_saturation",
            TyreField::RollingResistance => "tyre.rolling_resistance",
            TyreField::LowSpeedDamping => "tyre.low_speed_damping",
        }
    }

    /// The curve's direction, `None` for a tyre-wide field.
    pub const fn direction(self) -> Option<Direction> {
        match self {
            TyreField::PeakFriction(d)
            | TyreField::Stiffness(d)
            | TyreField::Shape(d)
            | TyreField::Curvature(d)
            | TyreField::RelaxationLength(d) => Some(d),
            _ => None,
        }
    }

    /// The accepted range `[lo, hi]`, both included unless said in [`TyreField::rule`].
    const fn range(self) -> (f64, f64) {
        match self {
            TyreField::PeakFriction(_) => (0.01, 5.0),
            TyreField::Stiffness(_) => (0.1, 200.0),
            TyreField::Shape(_) => (1.0, 2.0),
            TyreField::Curvature(_) => (-10.0, 1.0),
            TyreField::RelaxationLength(_) => (0.001, 10.0),
            TyreField::NominalLoad => (1.0, 1e6),
            TyreField::LoadSensitivity => (0.0, 1.0),
            TyreField::CorneringSaturation => (0.1, 10.0),
            TyreField::RollingResistance => (0.0, 0.5),
            TyreField::LowSpeedDamping => (0.0, 1.0),
        }
    }

    /// What the value must be, for messages.
    pub const fn rule(self) -> &'static str {
        match self {
            TyreField::PeakFriction(_) => "must be in [0.01, 5]",
            TyreField::Stiffness(_) => "must be in [0.1, 200] (per unit load)",
            TyreField::Shape(_) => "must be in (1, 2)",
            TyreField::Curvature(_) => "must be in [-10, 1)",
            TyreField::RelaxationLength(_) => "must be in [0.001, 10] m",
            TyreField::NominalLoad => "must be in [1, 1e6] N",
            TyreField::LoadSensitivity => "must be in [0, 1]",
            TyreField::CorneringSaturation => "must be in [0.1, 10]",
            TyreField::RollingResistance => "must be in [0, 0.5]",
            TyreField::LowSpeedDamping => "must be in [0, 1] s",
        }
    }

    /// True if `v` is acceptable.
    fn accepts(self, v: f64) -> bool {
        let (lo, hi) = self.range();
        let open_top = matches!(self, TyreField::Shape(_) | TyreField::Curvature(_));
        let open_bottom = matches!(self, TyreField::Shape(_));
        v.is_finite()
            && (if open_bottom { v > lo } else { v >= lo })
            && (if open_top { v < hi } else { v <= hi })
    }
}

impl fmt::Display for TyreField {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.path())
    }
}

/// A tyre coefficient out of its range.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TyreError {
    /// The coefficient.
    pub field: TyreField,
    /// Its value (as f64).
    pub value: f64,
}

impl fmt::Display for TyreError {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{} = {} {}", self.field, self.value, self.field.rule())
    }
}

impl<T: Real> TyreParams<T> {
    /// The value of `field`.
    pub fn get(&self, field: TyreField) -> T {
        match field {
            TyreField::NominalLoad => self.nominal_load,
            TyreField::LoadSensitivity => self.load_sensitivity,
            TyreField::CorneringSaturation => self.cornering_saturation,
            TyreField::RollingResistance => self.rolling_resistance,
            TyreField::LowSpeedDamping => self.low_speed_damping,
            TyreField::PeakFriction(d) => self.curve(d).peak_friction,
            TyreField::Stiffness(d) => self.curve(d).stiffness,
            TyreField::Shape(d) => self.curve(d).shape,
            TyreField::Curvature(d) => self.curve(d).curvature,
            TyreField::RelaxationLength(d) => self.curve(d).relaxation_length,
        }
    }

    /// Sets `field` to `value` (checked by [`TyreParams::validate`], not here).
    pub fn set(&mut self, field: TyreField, value: T) {
        let slot = match field {
            TyreField::NominalLoad => &mut self.nominal_load,
            TyreField::LoadSensitivity => &mut self.load_sensitivity,
            TyreField::CorneringSaturation => &mut self.cornering_saturation,
            TyreField::RollingResistance => &mut self.rolling_resistance,
            TyreField::LowSpeedDamping => &mut self.low_speed_damping,
            TyreField::PeakFriction(d) => &mut self.curve_mut(d).peak_friction,
            TyreField::Stiffness(d) => &mut self.curve_mut(d).stiffness,
            TyreField::Shape(d) => &mut self.curve_mut(d).shape,
            TyreField::Curvature(d) => &mut self.curve_mut(d).curvature,
            TyreField::RelaxationLength(d) => &mut self.curve_mut(d).relaxation_length,
        };
        *slot = value;
    }

    fn curve(&self, d: Direction) -> &SlipCurve<T> {
        match d {
            Direction::Longitudinal => &self.longitudinal,
            Direction::Lateral => &self.lateral,
        }
    }

    fn curve_mut(&mut self, d: Direction) -> &mut SlipCurve<T> {
        match d {
            Direction::Longitudinal => &mut self.longitudinal,
            Direction::Lateral => &mut self.lateral,
        }
    }

    /// Every field, in declaration order (longitudinal curve, lateral curve, then tyre-wide).
    pub const FIELDS: [TyreField; 15] = {
        use Direction::{Lateral, Longitudinal};
        [
            TyreField::PeakFriction(Longitudinal),
            TyreField::Stiffness(Longitudinal),
            TyreField::Shape(Longitudinal),
            TyreField::Curvature(Longitudinal),
            TyreField::RelaxationLength(Longitudinal),
            TyreField::PeakFriction(Lateral),
            TyreField::Stiffness(Lateral),
            TyreField::Shape(Lateral),
            TyreField::Curvature(Lateral),
            TyreField::RelaxationLength(Lateral),
            TyreField::NominalLoad,
            TyreField::LoadSensitivity,
            TyreField::CorneringSaturation,
            TyreField::RollingResistance,
            TyreField::LowSpeedDamping,
        ]
    };

    /// Checks every coefficient against its range and prepares the tyre.
    ///
    /// # Errors
    /// The first coefficient out of range (see [`TyreField::rule`]), with its value.
    ///
    /// ```
    /// use vehicle_model::{TyreClass, TyreField, Direction};
    /// let mut p = TyreClass::PassengerCar.params(0.35_f64, 4000.0);
    /// assert!(p.validate().is_ok());
    /// p.lateral.shape = 2.5;
    /// let e = p.validate().unwrap_err();
    /// assert_eq!(e.field, TyreField::Shape(Direction::Lateral));
    /// assert_eq!(e.to_string(), "tyre.lateral.shape = 2.5 must be in (1, 2)");
    /// ```
    pub fn validate(&self) -> Result<MagicFormula<T>, TyreError> {
        for field in Self::FIELDS {
            let value = self.get(field).to_f64();
            if !field.accepts(value) {
                return Err(TyreError { field, value });
            }
        }
        MagicFormula::new(*self).ok_or(TyreError {
            field: TyreField::Shape(Direction::Longitudinal),
            value: self.longitudinal.shape.to_f64(),
        })
    }
}
