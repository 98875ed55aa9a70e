//! The `VehicleWheel` parameter checks, in the PROTO's order, with typed warnings.

use ackermann::Real;

use super::params::{DEFAULT_WHEEL_DENSITY, WheelParams, WheelPhysics};
use super::warning::{WheelField, WheelRule, WheelWarnings};
use crate::plausible::{self, Plausible};

/// Largest accepted `subdivision` (not a Webots limit: Webots only prints an info message above
/// 200). Keeps every vertex index of the tyre mesh within `u32`.
pub const MAX_SUBDIVISION: i32 = 10_000;
/// Largest accepted `edgeSubdivision` (not a Webots limit: Webots only prints an info message
/// above 24).
pub const MAX_EDGE_SUBDIVISION: i32 = 1_000;
/// Largest accepted `rimBeamNumber` (not a Webots limit; Webots has no upper bound).
pub const MAX_RIM_BEAM_NUMBER: i32 = 1_000;

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
            let density = T::from_f64(DEFAULT_WHEEL_DENSITY);
            if check_in(&mut w, WheelField::Physics, v, density, Some(range)).is_some() {
                p.physics = fallback;
            }
        }

        (ValidWheel { params: p }, w)
    }
}
