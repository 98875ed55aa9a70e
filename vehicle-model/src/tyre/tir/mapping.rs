//! How a Magic Formula 5.2 / PAC2002 coefficient set maps onto [`TyreParams`].
//!
//! The project's tyre ([`super::super::MagicFormula`]) is a Magic Formula in pure slip: each
//! curve is `F = D·sin(C·atan(B·x − E·(B·x − atan(B·x))))` with `D = μ(F_z)·F_z` and
//! `B·C·D` the slip stiffness, at `x = κ` and `x = tan α` (MF 5.2's `α* = tan α`). With
//! `F'_z0 = FNOMIN·LFZO` and `df_z = (F_z − F'_z0)/F'_z0`, MF 5.2 writes (zero camber, no
//! shifts):
//!
//! | MF 5.2 | model | mapping |
//! |---|---|---|
//! | `C_x = PCX1·LCX` | `longitudinal.shape` | same |
//! | `μ_x = (PDX1 + PDX2·df_z)·LMUX` | `longitudinal.peak_friction·(1 − ε·df_z)` | `PDX1·LMUX`, `ε = −PDY2/PDY1` |
//! | `E_x = (PEX1 + PEX2·df_z + PEX3·df_z²)(1 − PEX4·sgn κ)·LEX` | `longitudinal.curvature` | `PEX1·LEX` |
//! | `K_x = F_z·(PKX1 + PKX2·df_z)·e^(PKX3·df_z)·LKX` | `longitudinal.stiffness·F_z` | `PKX1·LKX` |
//! | `C_y = PCY1·LCY` | `lateral.shape` | same |
//! | `μ_y = (PDY1 + PDY2·df_z)·LMUY` | `lateral.peak_friction·(1 − ε·df_z)` | `PDY1·LMUY`, `ε = −PDY2/PDY1` |
//! | `E_y = (PEY1 + PEY2·df_z)(1 − PEY3·sgn α)·LEY` | `lateral.curvature` | `PEY1·LEY` |
//! | `K_y = PKY1·F'_z0·sin(2·atan(F_z/(PKY2·F'_z0)))·LKY` | `lateral.stiffness·F_z·(1 + z₀²)/(1 + z²)`, `z = F_z/(p₂·F'_z0)` | `|PKY1|·sin(2·atan(1/PKY2))·LKY`, `p₂ = PKY2` |
//! | `σ_κ = F_z·(PTX1 + PTX2·df_z)·e^(−PTX3·df_z)·R₀/F_z0·LSGKP` | `longitudinal.relaxation_length` | `PTX1·R₀·LFZO·LSGKP` (at `F'_z0`) |
//! | `σ_α = PTY1·sin(2·atan(F_z/(PTY2·F'_z0)))·R₀·LFZO·LSGAL` | `lateral.relaxation_length` | `PTY1·sin(2·atan(1/PTY2))·R₀·LFZO·LSGAL` (at `F'_z0`) |
//! | `M_y = R₀·F_z·(QSY1 + …)·LMY` | `rolling_resistance·F_z·r` | `QSY1·LMY` |
//!
//! (`sin(2·atan z) = 2z/(1 + z²)`: the model's lateral law is MF's exactly.) So the pure-slip
//! forces are MF 5.2's exactly when `PKX2 = PKX3 = PEX2 = PEX3 = PEX4 = PEY2 = PEY3 = 0`,
//! `PDX2/PDX1 = PDY2/PDY1`, the shifts (`PHX*`, `PVX*`, `PHY*`, `PVY*`) are zero and the camber
//! is zero; the relaxation lengths are MF's at the nominal load. `PKY1`'s sign is the file's
//! sign convention (negative in ISO/TYDEX files, where a positive slip angle pushes right);
//! the model's lateral curve is odd in `tan α` with its own sign convention, so only the
//! magnitude is taken. The combined-slip coefficients (`RBX*`, `RCX*`, `RBY*`, …) have no
//! counterpart: the model combines the two slips through one curve variable of its own
//! ([`super::super::MagicFormula::force`]); they are reported as ignored.

use ackermann::Real;
use heapless::Vec;

use super::{TirError, TirErrorKind, TirFile};
use crate::tyre::{Direction, MagicFormula, TyreField, TyreParams};

/// The coefficients whose effect the model cannot follow when they are not zero: load
/// dependence of the stiffness, curvature and relaxation, and the curvature's asymmetry.
const LOAD_DEPENDENT: [&str; 9] = [
    "PKX2", "PKX3", "PEX2", "PEX3", "PEX4", "PEY2", "PEY3", "PTX2", "PTX3",
];

/// The keys every mapped file must give.
const REQUIRED: [&str; 9] = [
    "FNOMIN",
    "UNLOADED_RADIUS",
    "PCX1",
    "PDX1",
    "PKX1",
    "PCY1",
    "PDY1",
    "PKY1",
    "PKY2",
];

/// Relative difference of the load sensitivities `PDX2/PDX1` and `PDY2/PDY1` below which they
/// are one (the model has one): a file written with one value rounds it to a few digits.
const SAME_SENSITIVITY: f64 = 1e-9;

/// The model's coefficients from a `.tir` file, each with the key it comes from (the one an
/// error names).
pub type Mapped = Vec<(TyreField, f64, &'static str), 14>;

impl<'a> TirFile<'a> {
    /// The value of `key`, or `default` (MF's: 0 for a coefficient, 1 for a scaling factor)
    /// when the file does not give it.
    fn or(&self, key: &str, default: f64) -> f64 {
        self.value(key).unwrap_or(default)
    }

    /// The model's coefficients the file sets, by the table of this module. The relaxation
    /// lengths and the rolling resistance are set only when the file gives `PTX1`, `PTY1` and
    /// `QSY1`; the low-speed damping never (MF 5.2 has no such coefficient).
    ///
    /// # Errors
    /// [`TirErrorKind::Missing`] for a required key the file lacks (`FNOMIN`,
    /// `UNLOADED_RADIUS`, `PCX1`, `PDX1`, `PKX1`, `PCY1`, `PDY1`, `PKY1`, `PKY2`).
    pub fn mapped(&self) -> Result<Mapped, TirError<'a>> {
        if let Some(key) = REQUIRED.into_iter().find(|k| self.value(k).is_none()) {
            return Err(TirError {
                line: 0,
                key,
                kind: TirErrorKind::Missing,
            });
        }
        let v = |k: &str| self.or(k, 0.0);
        let scale = |k: &str| self.or(k, 1.0);
        let (x, y) = (Direction::Longitudinal, Direction::Lateral);
        let lfzo = scale("LFZO");
        let radius = v("UNLOADED_RADIUS");
        let saturation = v("PKY2").abs();
        // sin(2·atan z), through `Real` (no_std has no inherent f64 functions).
        let sin_2atan = |z: f64| Real::sin(2.0 * Real::atan(z));
        let mut out = Mapped::new();
        let mut push = |field, value, key| {
            // 14 fields at most, one push each: the capacity holds them all.
            let _ = out.push((field, value, key));
        };
        push(TyreField::NominalLoad, v("FNOMIN") * lfzo, "FNOMIN");
        push(
            TyreField::PeakFriction(x),
            v("PDX1") * scale("LMUX"),
            "PDX1",
        );
        push(TyreField::Stiffness(x), v("PKX1") * scale("LKX"), "PKX1");
        push(TyreField::Shape(x), v("PCX1") * scale("LCX"), "PCX1");
        push(TyreField::Curvature(x), v("PEX1") * scale("LEX"), "PEX1");
        push(
            TyreField::PeakFriction(y),
            v("PDY1") * scale("LMUY"),
            "PDY1",
        );
        push(
            TyreField::Stiffness(y),
            v("PKY1").abs() * sin_2atan(1.0 / saturation) * scale("LKY"),
            "PKY1",
        );
        push(TyreField::Shape(y), v("PCY1") * scale("LCY"), "PCY1");
        push(TyreField::Curvature(y), v("PEY1") * scale("LEY"), "PEY1");
        push(TyreField::LoadSensitivity, -v("PDY2") / v("PDY1"), "PDY2");
        push(TyreField::CorneringSaturation, saturation, "PKY2");
        if let Some(ptx1) = self.value("PTX1") {
            let sigma = ptx1 * radius * lfzo * scale("LSGKP");
            push(TyreField::RelaxationLength(x), sigma, "PTX1");
        }
        if let Some(pty1) = self.value("PTY1") {
            let shape = sin_2atan(1.0 / v("PTY2"));
            let sigma = pty1 * shape * radius * lfzo * scale("LSGAL");
            push(TyreField::RelaxationLength(y), sigma, "PTY1");
        }
        if let Some(qsy1) = self.value("QSY1") {
            push(TyreField::RollingResistance, qsy1 * scale("LMY"), "QSY1");
        }
        Ok(out)
    }

    /// Sets the coefficients the file maps to in `params` and validates the result.
    ///
    /// # Errors
    /// As [`TirFile::mapped`]; [`TirErrorKind::OutOfRange`] at the key whose coefficient falls
    /// outside the model's range.
    pub fn apply(&self, params: &mut TyreParams<f64>) -> Result<MagicFormula<f64>, TirError<'a>> {
        let mapped = self.mapped()?;
        let mut tyre = params.validate();
        for &(field, value, key) in &mapped {
            params.set(field, value);
            tyre = params.validate();
            if let Err(e) = tyre {
                // The fields set before this one were accepted, so the failure is this one's,
                // or that of the file's field it names.
                let key = mapped.iter().find(|t| t.0 == e.field).map_or(key, |t| t.2);
                return Err(self.out_of_range(key, e.field, e.value));
            }
        }
        tyre.map_err(|e| self.out_of_range("FNOMIN", e.field, e.value))
    }

    fn out_of_range(&self, key: &'static str, field: TyreField, value: f64) -> TirError<'a> {
        TirError {
            line: self.line(key),
            key,
            kind: TirErrorKind::OutOfRange { field, value },
        }
    }

    /// The coefficients the file gives that the model cannot follow, with their lines: the
    /// load-dependent and asymmetric terms that are not zero (the model takes their value at
    /// the nominal load), and `PDX2` when `PDX2/PDX1` differs from `PDY2/PDY1` (the model
    /// has one load sensitivity, the lateral one).
    pub fn approximated(&self) -> impl Iterator<Item = (usize, &'static str)> + '_ {
        let (rx, ry) = (
            self.or("PDX2", 0.0) / self.or("PDX1", 1.0),
            self.or("PDY2", 0.0) / self.or("PDY1", 1.0),
        );
        let pdx2 = ((rx - ry).abs() > SAME_SENSITIVITY * rx.abs().max(ry.abs()))
            .then_some((self.line("PDX2"), "PDX2"));
        LOAD_DEPENDENT
            .into_iter()
            .filter(|k| self.value(k).is_some_and(|v| v != 0.0))
            .map(|k| (self.line(k), k))
            .chain(pdx2)
    }
}
