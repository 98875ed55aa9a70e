//! The `VehicleWheel` parameter checks, in the PROTO's order, with typed warnings.

use core::fmt;

use ackermann::Real;

use super::params::{WheelParams, WheelPhysics};
use crate::plausible::{self, Compact, Plausible};

/// Largest accepted `subdivision` (not a Webots limit: Webots only prints an info message above
/// 200). Keeps every vertex index of the tyre mesh within `u32`.
pub const MAX_SUBDIVISION: i32 = 10_000;
/// Largest accepted `edgeSubdivision` (not a Webots limit: Webots only prints an info message
/// above 24).
pub const MAX_EDGE_SUBDIVISION: i32 = 1_000;
/// Largest accepted `rimBeamNumber` (not a Webots limit; Webots has no upper bound).
pub const MAX_RIM_BEAM_NUMBER: i32 = 1_000;

/// A `VehicleWheel` field named in a [`WheelWarning`].
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum WheelField {
    /// Webots field `subdivision`.
    Subdivision,
    /// Webots field `edgeSubdivision`.
    EdgeSubdivision,
    /// Webots field `rimBeamNumber`.
    RimBeamNumber,
    /// Webots field `thickness` (m).
    Thickness,
    /// Webots field `rimBeamThickness` (m).
    RimBeamThickness,
    /// Webots field `tireRadius` (m).
    TireRadius,
    /// Webots field `curvatureFactor`.
    CurvatureFactor,
    /// Webots field `rimRadius` (m).
    RimRadius,
    /// Webots field `rimBeamWidth` (m).
    RimBeamWidth,
    /// Webots field `centralInnerRadius` (m).
    CentralInnerRadius,
    /// Webots field `centralOuterRadius` (m).
    CentralOuterRadius,
    /// Webots field `rimBeamOffset` (m).
    RimBeamOffset,
    /// Webots field `physics` (the mass in kg or density in kg/m³ of its `Physics` node).
    Physics,
}

impl WheelField {
    /// The Webots field name (`"subdivision"`, `"rimBeamOffset"`, …).
    pub const fn webots_name(self) -> &'static str {
        match self {
            WheelField::Subdivision => "subdivision",
            WheelField::EdgeSubdivision => "edgeSubdivision",
            WheelField::RimBeamNumber => "rimBeamNumber",
            WheelField::Thickness => "thickness",
            WheelField::RimBeamThickness => "rimBeamThickness",
            WheelField::TireRadius => "tireRadius",
            WheelField::CurvatureFactor => "curvatureFactor",
            WheelField::RimRadius => "rimRadius",
            WheelField::RimBeamWidth => "rimBeamWidth",
            WheelField::CentralInnerRadius => "centralInnerRadius",
            WheelField::CentralOuterRadius => "centralOuterRadius",
            WheelField::RimBeamOffset => "rimBeamOffset",
            WheelField::Physics => "physics",
        }
    }

    /// The plausible range of the field's value ([`WheelRule::Implausible`]), `None` for the
    /// integer fields (bounded by their own limits) and `physics` (a mass in
    /// [`plausible::MASS`] or a density in [`plausible::DENSITY`]).
    pub const fn plausible(self) -> Option<Plausible> {
        match self {
            WheelField::Subdivision
            | WheelField::EdgeSubdivision
            | WheelField::RimBeamNumber
            | WheelField::Physics => None,
            WheelField::CurvatureFactor => Some(Plausible {
                min: 0.0,
                max: 1.0,
                unit: "",
            }),
            WheelField::RimBeamOffset => Some(plausible::OFFSET),
            _ => Some(plausible::LENGTH),
        }
    }
}

impl fmt::Display for WheelField {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(self.webots_name())
    }
}

/// Which check a field failed (spec §4.4; the PROTO's `console.error`/`console.info` calls).
#[derive(Debug, Clone, Copy, PartialEq, Eq, Hash)]
pub enum WheelRule {
    /// Information only, value kept: `subdivision` > 200 or `edgeSubdivision` > 24 ("can slow
    /// down the simulation").
    HighValue,
    /// `subdivision` ≤ 8 → 8 (8 itself triggers the message in Webots too).
    SubdivisionTooLow,
    /// `edgeSubdivision` < 1 → default 3.
    EdgeSubdivisionTooLow,
    /// `rimBeamNumber` < 3 → 3.
    RimBeamNumberTooLow,
    /// Above this crate's hard limit ([`MAX_SUBDIVISION`], [`MAX_EDGE_SUBDIVISION`],
    /// [`MAX_RIM_BEAM_NUMBER`]) → the limit. Not a Webots check.
    AboveLimit,
    /// NaN or ±∞ → the field's "≤ 0" fallback (for `curvatureFactor` and `rimBeamOffset`, the
    /// default clamped by the other rules). Not a Webots check: Webots lets NaN through.
    NotFinite,
    /// ≤ 0 → default (`rimRadius`: `tireRadius`/2; `physics`: density 1000 kg/m³).
    NotPositive,
    /// Positive but outside the field's plausible range ([`WheelField::plausible`]; for
    /// `physics`, [`plausible::MASS`] or [`plausible::DENSITY`]) → the "≤ 0" fallback. Not a
    /// Webots check: Webots accepts a 10³⁰⁰ m tyre and fails at the first step.
    Implausible,
    /// `rimBeamThickness` > `thickness` → `thickness`.
    RimBeamThicknessAboveThickness,
    /// `curvatureFactor` ∉ [0, 1] → default 0.35.
    CurvatureOutOfRange,
    /// `rimRadius` > `tireRadius` − (`thickness`/2)·`curvatureFactor` → `tireRadius`/2.
    RimRadiusTooLarge,
    /// `rimBeamWidth` ≥ `rimRadius` → default 0.1.
    RimBeamWidthTooLarge,
    /// `centralOuterRadius` ≤ `centralInnerRadius` → `centralInnerRadius`.
    CentralOuterNotAboveInner,
    /// `centralOuterRadius` ≥ `rimRadius` → `rimRadius`.
    CentralOuterNotBelowRim,
    /// `rimBeamOffset` > (`thickness` − `rimBeamThickness`)/2 → that maximum.
    RimBeamOffsetTooLarge,
}

/// One rejected (or, for [`WheelRule::HighValue`], merely reported) `VehicleWheel` field value.
///
/// `Display` prints a message in the form of the Webots console error (`'subdivision' must be
/// greater or equal to 8. Value reset to 8.`).
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct WheelWarning {
    /// The field.
    pub field: WheelField,
    /// The failed check.
    pub rule: WheelRule,
    /// The value given (the field's unit; `f64`, exact for `f32` and `i32`). For `physics`,
    /// the given mass (kg) or density (kg/m³).
    pub value: f64,
    /// The value used instead (same unit; equal to `value` for [`WheelRule::HighValue`]). For
    /// `physics`, the replacement density 1000 kg/m³.
    pub replacement: f64,
}

impl WheelWarning {
    /// True for the information-only messages (Webots `console.info`): the value was kept.
    #[inline]
    pub fn is_info(&self) -> bool {
        self.rule == WheelRule::HighValue
    }

    /// The rule the value broke, as a sentence without the replacement (`"'tireRadius' must be
    /// in 0.001 to 1000 m (value 1e300)."`): what a world file that refuses the value says.
    #[inline]
    pub fn requirement(&self) -> Requirement<'_> {
        Requirement(self)
    }
}

impl fmt::Display for Requirement<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        let w = self.0;
        let name = w.field.webots_name();
        let r = Compact(w.replacement);
        match w.rule {
            WheelRule::HighValue => {
                write!(
                    f,
                    "High value for '{name}'. This can slow down the simulation."
                )?;
            }
            WheelRule::SubdivisionTooLow => write!(f, "'{name}' must be greater or equal to 8.")?,
            WheelRule::EdgeSubdivisionTooLow => {
                write!(f, "'{name}' must be greater or equal to 1.")?;
            }
            WheelRule::RimBeamNumberTooLow => write!(f, "'{name}' must be greater or equal to 3.")?,
            WheelRule::AboveLimit => write!(f, "'{name}' must be at most {r}.")?,
            WheelRule::NotFinite => write!(f, "'{name}' must be a finite number.")?,
            WheelRule::NotPositive => write!(f, "'{name}' must be strictly positive.")?,
            WheelRule::Implausible => match w.field.plausible() {
                Some(range) => write!(
                    f,
                    "'{name}' must be within {range} (value {}).",
                    Compact(w.value)
                )?,
                None => write!(
                    f,
                    "'{name}' must have a mass of {} or a density of {} (value {}).",
                    plausible::MASS,
                    plausible::DENSITY,
                    Compact(w.value)
                )?,
            },
            WheelRule::RimBeamThicknessAboveThickness => {
                write!(f, "'{name}' must be smaller or equal to 'thickness'.")?;
            }
            WheelRule::CurvatureOutOfRange => write!(f, "'{name}' must be in the interval [0,1].")?,
            WheelRule::RimRadiusTooLarge => write!(
                f,
                "'{name}' must be smaller than 'tireRadius' minus half of the 'thickness' \
                 multiplied by the 'curvatureFactor'."
            )?,
            WheelRule::RimBeamWidthTooLarge => {
                write!(f, "'{name}' must be smaller than 'rimRadius'.")?;
            }
            WheelRule::CentralOuterNotAboveInner => {
                write!(f, "'{name}' must be greater than 'centralInnerRadius'.")?;
            }
            WheelRule::CentralOuterNotBelowRim => {
                write!(f, "'{name}' must be smaller than 'rimRadius'.")?;
            }
            WheelRule::RimBeamOffsetTooLarge => write!(
                f,
                "'{name}' must be smaller or equal to 'thickness' minus 'rimBeamThickness', \
                 divided by two."
            )?,
        }
        Ok(())
    }
}

impl fmt::Display for WheelWarning {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        write!(f, "{}", self.requirement())?;
        let r = Compact(self.replacement);
        match (self.rule, self.field) {
            (WheelRule::HighValue, _) => Ok(()),
            (_, WheelField::Physics) => write!(f, " Value reset to density {r}."),
            _ => write!(f, " Value reset to {r}."),
        }
    }
}

/// The rule a [`WheelWarning`]'s value broke, without what replaced it ([`WheelWarning::requirement`]).
#[derive(Debug, Clone, Copy)]
pub struct Requirement<'a>(&'a WheelWarning);

/// Capacity of [`WheelWarnings`]: at most one warning per checked field.
pub const MAX_WHEEL_WARNINGS: usize = 13;

/// The warnings of one [`WheelParams::validate`] call, in the PROTO's checking order
/// (fixed capacity, no allocation).
#[derive(Debug, Clone, PartialEq, Default)]
pub struct WheelWarnings(heapless::Vec<WheelWarning, MAX_WHEEL_WARNINGS>);

impl WheelWarnings {
    /// No warnings.
    #[inline]
    pub const fn new() -> Self {
        WheelWarnings(heapless::Vec::new())
    }

    /// The warnings as a slice.
    #[inline]
    pub fn as_slice(&self) -> &[WheelWarning] {
        &self.0
    }

    /// Iterates over the warnings in checking order.
    #[inline]
    pub fn iter(&self) -> core::slice::Iter<'_, WheelWarning> {
        self.0.iter()
    }

    /// Number of warnings (including information-only ones).
    #[inline]
    pub fn len(&self) -> usize {
        self.0.len()
    }

    /// True if no field was reported.
    #[inline]
    pub fn is_empty(&self) -> bool {
        self.0.is_empty()
    }

    /// The warning about `field`, if any.
    pub fn get(&self, field: WheelField) -> Option<&WheelWarning> {
        self.0.iter().find(|w| w.field == field)
    }

    /// True if some value was replaced (ignores information-only messages).
    pub fn has_errors(&self) -> bool {
        self.0.iter().any(|w| !w.is_info())
    }

    fn push(&mut self, field: WheelField, rule: WheelRule, value: f64, replacement: f64) {
        // Each field is checked once, so the capacity (one per field) cannot be exceeded;
        // a full list would only drop the report, never the correction.
        let _ = self.0.push(WheelWarning {
            field,
            rule,
            value,
            replacement,
        });
    }
}

impl<'a> IntoIterator for &'a WheelWarnings {
    type Item = &'a WheelWarning;
    type IntoIter = core::slice::Iter<'a, WheelWarning>;
    fn into_iter(self) -> Self::IntoIter {
        self.0.iter()
    }
}

/// [`WheelParams`] that passed the `VehicleWheel` checks: every length finite, `subdivision` in
/// 8..=[`MAX_SUBDIVISION`], `edgeSubdivision` in 1..=[`MAX_EDGE_SUBDIVISION`], `rimBeamNumber`
/// in 3..=[`MAX_RIM_BEAM_NUMBER`], and the relations of spec §4.4 as far as Webots enforces them.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct ValidWheel<T> {
    params: WheelParams<T>,
}

impl<T: Real> Default for ValidWheel<T> {
    /// The default `VehicleWheel` (valid as is).
    fn default() -> Self {
        ValidWheel {
            params: WheelParams::default(),
        }
    }
}

impl<T: Real> ValidWheel<T> {
    /// The validated field values.
    #[inline]
    pub const fn params(&self) -> &WheelParams<T> {
        &self.params
    }

    /// Consumes into the validated field values.
    #[inline]
    pub const fn into_params(self) -> WheelParams<T> {
        self.params
    }

    /// `subdivision`, in 8..=[`MAX_SUBDIVISION`].
    #[inline]
    pub fn subdivision(&self) -> u32 {
        self.params.subdivision.unsigned_abs()
    }

    /// `edgeSubdivision`, in 1..=[`MAX_EDGE_SUBDIVISION`].
    #[inline]
    pub fn edge_subdivision(&self) -> u32 {
        self.params.edge_subdivision.unsigned_abs()
    }

    /// `rimBeamNumber`, in 3..=[`MAX_RIM_BEAM_NUMBER`].
    #[inline]
    pub fn rim_beam_number(&self) -> u32 {
        self.params.rim_beam_number.unsigned_abs()
    }
}

/// A real field: non-finite, ≤ 0 or outside `range` → `fallback`. Returns `None` if the
/// value is kept.
fn check_positive<T: Real>(
    w: &mut WheelWarnings,
    field: WheelField,
    value: T,
    fallback: T,
) -> Option<T> {
    check_in(w, field, value, fallback, field.plausible())
}

/// [`check_positive`] with an explicit plausible range.
fn check_in<T: Real>(
    w: &mut WheelWarnings,
    field: WheelField,
    value: T,
    fallback: T,
    range: Option<Plausible>,
) -> Option<T> {
    let rule = if !value.is_finite() {
        WheelRule::NotFinite
    } else if value <= T::ZERO {
        WheelRule::NotPositive
    } else if range.is_some_and(|r| !r.contains(value.to_f64())) {
        WheelRule::Implausible
    } else {
        return None;
    };
    w.push(field, rule, value.to_f64(), fallback.to_f64());
    Some(fallback)
}

impl<T: Real> WheelParams<T> {
    /// Applies the `VehicleWheel` parameter checks (spec §4.4), in the PROTO's order, each
    /// using the already-corrected values of the fields checked before it:
    ///
    /// * `subdivision` > 200 → info; ≤ 8 → 8. `edgeSubdivision` > 24 → info; < 1 → 3.
    ///   `rimBeamNumber` < 3 → 3.
    /// * `thickness` ≤ 0 → 0.3. `rimBeamThickness` ≤ 0 → 0.2, else > thickness → thickness.
    /// * `tireRadius` ≤ 0 → 0.4. `curvatureFactor` ∉ [0, 1] → 0.35.
    /// * `rimRadius` ≤ 0, or > tireRadius − (thickness/2)·curvatureFactor → tireRadius/2.
    /// * `rimBeamWidth` ≤ 0 or ≥ rimRadius → 0.1.
    /// * `centralInnerRadius` ≤ 0 → 0.09. `centralOuterRadius` ≤ 0 → 0.13, else ≤ inner →
    ///   inner, else ≥ rimRadius → rimRadius.
    /// * `rimBeamOffset` > (thickness − rimBeamThickness)/2 → that maximum.
    ///
    /// Like Webots, a fallback value is not re-checked by the rule that replaced it (e.g. a
    /// `rimBeamThickness` reset to 0.2 may still exceed a thin `thickness`). Additions to
    /// Webots, each reported the same way: NaN and ±∞ are invalid (fallback as for ≤ 0), the
    /// integer fields have upper limits ([`MAX_SUBDIVISION`], …), and a `physics` mass or
    /// density ≤ 0 becomes the default `Physics {}` (density 1000 kg/m³).
    ///
    /// Never fails and never panics: the result is always a usable wheel.
    pub fn validate(&self) -> (ValidWheel<T>, WheelWarnings) {
        let d = WheelParams::<T>::default();
        let mut p = *self;
        let mut w = WheelWarnings::new();

        let s = p.subdivision;
        if s > MAX_SUBDIVISION {
            p.subdivision = MAX_SUBDIVISION;
            w.push(
                WheelField::Subdivision,
                WheelRule::AboveLimit,
                f64::from(s),
                f64::from(MAX_SUBDIVISION),
            );
        } else if s > 200 {
            w.push(
                WheelField::Subdivision,
                WheelRule::HighValue,
                f64::from(s),
                f64::from(s),
            );
        } else if s <= 8 {
            p.subdivision = 8;
            w.push(
                WheelField::Subdivision,
                WheelRule::SubdivisionTooLow,
                f64::from(s),
                8.0,
            );
        }

        let e = p.edge_subdivision;
        if e > MAX_EDGE_SUBDIVISION {
            p.edge_subdivision = MAX_EDGE_SUBDIVISION;
            w.push(
                WheelField::EdgeSubdivision,
                WheelRule::AboveLimit,
                f64::from(e),
                f64::from(MAX_EDGE_SUBDIVISION),
            );
        } else if e > 24 {
            w.push(
                WheelField::EdgeSubdivision,
                WheelRule::HighValue,
                f64::from(e),
                f64::from(e),
            );
        } else if e < 1 {
            p.edge_subdivision = d.edge_subdivision;
            w.push(
                WheelField::EdgeSubdivision,
                WheelRule::EdgeSubdivisionTooLow,
                f64::from(e),
                f64::from(d.edge_subdivision),
            );
        }

        let n = p.rim_beam_number;
        if n < 3 {
            p.rim_beam_number = 3;
            w.push(
                WheelField::RimBeamNumber,
                WheelRule::RimBeamNumberTooLow,
                f64::from(n),
                3.0,
            );
        } else if n > MAX_RIM_BEAM_NUMBER {
            p.rim_beam_number = MAX_RIM_BEAM_NUMBER;
            w.push(
                WheelField::RimBeamNumber,
                WheelRule::AboveLimit,
                f64::from(n),
                f64::from(MAX_RIM_BEAM_NUMBER),
            );
        }

        if let Some(v) = check_positive(&mut w, WheelField::Thickness, p.thickness, d.thickness) {
            p.thickness = v;
        }

        if let Some(v) = check_positive(
            &mut w,
            WheelField::RimBeamThickness,
            p.rim_beam_thickness,
            d.rim_beam_thickness,
        ) {
            p.rim_beam_thickness = v;
        } else if p.rim_beam_thickness > p.thickness {
            w.push(
                WheelField::RimBeamThickness,
                WheelRule::RimBeamThicknessAboveThickness,
                p.rim_beam_thickness.to_f64(),
                p.thickness.to_f64(),
            );
            p.rim_beam_thickness = p.thickness;
        }

        if let Some(v) =
            check_positive(&mut w, WheelField::TireRadius, p.tire_radius, d.tire_radius)
        {
            p.tire_radius = v;
        }

        let c = p.curvature_factor;
        let c_rule = if !c.is_finite() {
            Some(WheelRule::NotFinite)
        } else if c < T::ZERO || c > T::ONE {
            Some(WheelRule::CurvatureOutOfRange)
        } else {
            None
        };
        if let Some(rule) = c_rule {
            p.curvature_factor = d.curvature_factor;
            w.push(
                WheelField::CurvatureFactor,
                rule,
                c.to_f64(),
                d.curvature_factor.to_f64(),
            );
        }

        let half_tire = p.tire_radius * T::HALF;
        if let Some(v) = check_positive(&mut w, WheelField::RimRadius, p.rim_radius, half_tire) {
            p.rim_radius = v;
        } else if p.rim_radius > p.tire_radius - p.thickness * T::HALF * p.curvature_factor {
            w.push(
                WheelField::RimRadius,
                WheelRule::RimRadiusTooLarge,
                p.rim_radius.to_f64(),
                half_tire.to_f64(),
            );
            p.rim_radius = half_tire;
        }

        if let Some(v) = check_positive(
            &mut w,
            WheelField::RimBeamWidth,
            p.rim_beam_width,
            d.rim_beam_width,
        ) {
            p.rim_beam_width = v;
        } else if p.rim_beam_width >= p.rim_radius {
            w.push(
                WheelField::RimBeamWidth,
                WheelRule::RimBeamWidthTooLarge,
                p.rim_beam_width.to_f64(),
                d.rim_beam_width.to_f64(),
            );
            p.rim_beam_width = d.rim_beam_width;
        }

        if let Some(v) = check_positive(
            &mut w,
            WheelField::CentralInnerRadius,
            p.central_inner_radius,
            d.central_inner_radius,
        ) {
            p.central_inner_radius = v;
        }

        if let Some(v) = check_positive(
            &mut w,
            WheelField::CentralOuterRadius,
            p.central_outer_radius,
            d.central_outer_radius,
        ) {
            p.central_outer_radius = v;
        } else if p.central_outer_radius <= p.central_inner_radius {
            w.push(
                WheelField::CentralOuterRadius,
                WheelRule::CentralOuterNotAboveInner,
                p.central_outer_radius.to_f64(),
                p.central_inner_radius.to_f64(),
            );
            p.central_outer_radius = p.central_inner_radius;
        } else if p.central_outer_radius >= p.rim_radius {
            w.push(
                WheelField::CentralOuterRadius,
                WheelRule::CentralOuterNotBelowRim,
                p.central_outer_radius.to_f64(),
                p.rim_radius.to_f64(),
            );
            p.central_outer_radius = p.rim_radius;
        }

        let max_offset = (p.thickness - p.rim_beam_thickness) * T::HALF;
        let off = p.rim_beam_offset;
        if !off.is_finite() {
            let v = d.rim_beam_offset.min(max_offset);
            w.push(
                WheelField::RimBeamOffset,
                WheelRule::NotFinite,
                off.to_f64(),
                v.to_f64(),
            );
            p.rim_beam_offset = v;
        } else if off > max_offset {
            w.push(
                WheelField::RimBeamOffset,
                WheelRule::RimBeamOffsetTooLarge,
                off.to_f64(),
                max_offset.to_f64(),
            );
            p.rim_beam_offset = max_offset;
        }

        let physics_value = match p.physics {
            WheelPhysics::None => None,
            WheelPhysics::Density(v) => Some((v, plausible::DENSITY)),
            WheelPhysics::Mass(v) => Some((v, plausible::MASS)),
        };
        if let Some((v, range)) = physics_value {
            let fallback = WheelPhysics::<T>::webots_default();
            let density = T::from_f64(1000.0);
            if check_in(&mut w, WheelField::Physics, v, density, Some(range)).is_some() {
                p.physics = fallback;
            }
        }

        (ValidWheel { params: p }, w)
    }
}
