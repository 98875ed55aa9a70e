//! `[vehicle.tyre] file = "tyre.tir"`: a Magic Formula 5.2 / PAC2002 tyre property file,
//! relative to the world file, read by [`vehicle_model::TirFile`] and mapped onto the
//! slip-based tyre's coefficients (the mapping: `vehicle_model::tyre::tir::mapping`).

use vehicle_model::{TirFile, TyreField, TyreParams};

use super::error::{WorldFileError, WorldFileErrorKind, WorldWarning};
use super::read::Section;
use super::shipped;

/// The key in `[vehicle.tyre]`.
pub(crate) const FILE: &str = "file";

/// Reads the file that `file` of `t` names and applies its coefficients to `probe` (which
/// must be valid), returning the fields it set; the keys it ignores and those it can follow
/// only at the nominal load become warnings at `file`.
///
/// # Errors
/// At `file` of `t`: the file cannot be read, or its error (file, line and key in the
/// message).
pub(crate) fn read_tyre_file(
    t: &Section<'_, '_>,
    probe: &mut TyreParams<f64>,
    warnings: &mut Vec<WorldWarning>,
) -> Result<Vec<(TyreField, f64)>, WorldFileError> {
    let Some(name) = t.string(FILE)? else {
        return Ok(Vec::new());
    };
    let path = shipped::include_path(t.src.file, name);
    let shown = path.display().to_string();
    let fail = |message: String| t.error(FILE, WorldFileErrorKind::InvalidValue(message));
    // A shipped world's includes are embedded with it.
    let text = shipped::read_included(&path).map_err(|e| fail(format!("{shown}: {e}")))?;
    let located = |e: vehicle_model::TirError<'_>| fail(format!("{shown}: {e}"));
    let tir = TirFile::read(&text).map_err(located)?;
    tir.apply(probe).map_err(located)?;
    let set = tir.mapped().map_err(located)?;
    let list = |keys: Vec<String>| keys.join(", ");
    let ignored: Vec<String> = tir.ignored().map(|(_, k)| k.to_string()).collect();
    if !ignored.is_empty() {
        warnings.push(t.src.warning(
            t.key_span(FILE),
            Some(t.key_path(FILE)),
            format!(
                "{shown}: {} keys ignored (the tyre model has no counterpart): {}",
                ignored.len(),
                list(ignored)
            ),
        ));
    }
    let approximated: Vec<String> = tir
        .approximated()
        .map(|(line, k)| format!("{k} (line {line})"))
        .collect();
    if !approximated.is_empty() {
        warnings.push(t.src.warning(
            t.key_span(FILE),
            Some(t.key_path(FILE)),
            format!(
                "{shown}: taken at the nominal load only (the tyre model has one load \
                 sensitivity and load-independent curvature, longitudinal stiffness per unit \
                 load and relaxation): {}",
                list(approximated)
            ),
        ));
    }
    Ok(set.into_iter().map(|(f, v, _)| (f, v)).collect())
}
