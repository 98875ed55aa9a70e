//! What the `VehicleWheel` checks report: the field, the broken rule, the value and its
//! replacement, in the PROTO's message form.

use core::fmt;

use crate::plausible::{self, Compact, Plausible};

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
            WheelField::TireRadius | WheelField::Thickness => Some(plausible::LENGTH),
            // The rim's sizes fall back to fractions of the tyre's (rimRadius = tireRadius/2),
            // which a 1 mm tyre puts below 1 mm: only the upper bound applies to them.
            _ => Some(Plausible {
                min: 0.0,
                ..plausible::LENGTH
            }),
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
    /// Above this crate's hard limit ([`MAX_SUBDIVISION`](super::MAX_SUBDIVISION), [`MAX_EDGE_SUBDIVISION`](super::MAX_EDGE_SUBDIVISION),
    /// [`MAX_RIM_BEAM_NUMBER`](super::MAX_RIM_BEAM_NUMBER)) → the limit. Not a Webots check.
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

/// The warnings of one [`WheelParams::validate`](super::WheelParams::validate) call, in the PROTO's checking order
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

    pub(super) fn push(
        &mut self,
        field: WheelField,
        rule: WheelRule,
        value: f64,
        replacement: f64,
    ) {
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
