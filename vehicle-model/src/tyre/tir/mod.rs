//! Tyre property files (`.tir`) of the Magic Formula 5.2 / PAC2002 family (`FITTYP = 6`):
//! the reader, without heap, over the file's text.
//!
//! A `.tir` file is an INI-like text: `[SECTION]` headers, `KEY = value` lines, comments from
//! `$` or `!` to the end of the line, string values in single quotes, and tables (a `{…}`
//! header line followed by rows of numbers, e.g. `[SHAPE]`), which this reader skips. No
//! crate on crates.io reads the format without heap or with line numbers for every key (the
//! INI crates take neither the `$` comments nor the tables), and the format is a few rules, so
//! the reader is written here.
//!
//! [`TirFile::read`] keeps the coefficients that [`super::MagicFormula`] has a counterpart for
//! (see [`mapping`] for the formulas); every other key is reported by
//! [`TirFile::ignored`], and the coefficients whose effect the model cannot follow (load
//! dependence of the stiffness and curvature, for example) by [`TirFile::approximated`].
//!
//! ```
//! use vehicle_model::tyre::tir::TirFile;
//! let text = "[UNITS]\nLENGTH = 'meter'\nFORCE = 'newton'\n[MODEL]\nFITTYP = 6\n\
//!             [DIMENSION]\nUNLOADED_RADIUS = 0.3\n[VERTICAL]\nFNOMIN = 4000\n\
//!             [LONGITUDINAL_COEFFICIENTS]\nPCX1 = 1.65\nPDX1 = 1.0\nPKX1 = 20\n\
//!             [LATERAL_COEFFICIENTS]\nPCY1 = 1.3\nPDY1 = 0.9\nPKY1 = -20\nPKY2 = 2\nPHY1 = 0.002 $ shift\n";
//! let tir = TirFile::read(text).unwrap();
//! assert_eq!(tir.value("PKY1"), Some(-20.0));
//! let ignored: Vec<_> = tir.ignored().map(|(_, key)| key).collect();
//! assert_eq!(ignored, ["PHY1"]);
//! ```

pub mod mapping;

use core::fmt;

use super::TyreField;

/// The keys the reader keeps (the others are ignored): the file's model, the tyre's size and
/// nominal load, the scaling factors and the coefficients that [`mapping`] uses.
pub const KEYS: [&str; 39] = [
    "FITTYP",
    "UNLOADED_RADIUS",
    "FNOMIN",
    "LFZO",
    "LMUX",
    "LMUY",
    "LKX",
    "LKY",
    "LCX",
    "LCY",
    "LEX",
    "LEY",
    "LSGKP",
    "LSGAL",
    "LMY",
    "PCX1",
    "PDX1",
    "PDX2",
    "PEX1",
    "PEX2",
    "PEX3",
    "PEX4",
    "PKX1",
    "PKX2",
    "PKX3",
    "PCY1",
    "PDY1",
    "PDY2",
    "PEY1",
    "PEY2",
    "PEY3",
    "PKY1",
    "PKY2",
    "PTX1",
    "PTX2",
    "PTX3",
    "PTY1",
    "PTY2",
    "QSY1",
];

/// Sections whose keys describe the file, not the tyre: never reported as ignored.
const META_SECTIONS: [&str; 2] = ["MDI_HEADER", "UNITS"];

/// The Magic Formula variant this reader maps: `FITTYP = 6` (MF 5.2 / PAC2002).
pub const FITTYP_MF52: u32 = 6;

/// A value read: the number (in SI units for lengths and forces) and its line (1-based).
#[derive(Debug, Clone, Copy, PartialEq)]
struct Entry {
    value: f64,
    line: usize,
}

/// A `.tir` file read: the kept coefficients, each with its line.
#[derive(Debug, Clone)]
pub struct TirFile<'a> {
    text: &'a str,
    values: [Option<Entry>; KEYS.len()],
}

/// What is wrong in a `.tir` file.
#[derive(Debug, Clone, Copy, PartialEq)]
pub enum TirErrorKind {
    /// A line that is neither a section, a `KEY = value`, a comment nor a table row.
    Syntax,
    /// A kept key whose value is not a finite number.
    NotANumber,
    /// A kept key given twice; the line of the first.
    Duplicate(usize),
    /// A key the mapping needs is absent.
    Missing,
    /// A unit in `[UNITS]` the reader does not know (lengths: meter, millimeter, centimeter,
    /// kilometer, inch, foot; forces: newton, kilonewton, pound_force, kilogram_force;
    /// angles: radian).
    UnknownUnit,
    /// `FITTYP` other than 6: another Magic Formula variant, whose formulas differ.
    UnsupportedFittyp,
    /// A coefficient that maps to a value out of the model's range: the model's field and
    /// the value it would get.
    OutOfRange {
        /// The model's coefficient.
        field: TyreField,
        /// The value the file gives it.
        value: f64,
    },
}

/// An error in a `.tir` file: its line (0 when the key is absent), key and kind.
#[derive(Debug, Clone, Copy, PartialEq)]
pub struct TirError<'a> {
    /// The line (1-based), 0 for a missing key.
    pub line: usize,
    /// The key (the line's text for a syntax error).
    pub key: &'a str,
    /// What is wrong.
    pub kind: TirErrorKind,
}

impl fmt::Display for TirError<'_> {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        if self.line > 0 {
            write!(f, "line {}: ", self.line)?;
        }
        match self.kind {
            TirErrorKind::Syntax => write!(f, "expected KEY = value, found '{}'", self.key),
            TirErrorKind::NotANumber => write!(f, "{}: not a finite number", self.key),
            TirErrorKind::Duplicate(first) => {
                write!(f, "{}: given again (first on line {first})", self.key)
            }
            TirErrorKind::Missing => write!(f, "{}: missing (the mapping needs it)", self.key),
            TirErrorKind::UnknownUnit => write!(f, "{}: unknown unit", self.key),
            TirErrorKind::UnsupportedFittyp => write!(
                f,
                "{}: only FITTYP = 6 (Magic Formula 5.2 / PAC2002) is read",
                self.key
            ),
            TirErrorKind::OutOfRange { field, value } => write!(
                f,
                "{}: gives {field} = {value}, which {}",
                self.key,
                field.rule()
            ),
        }
    }
}

/// One `KEY = value` line: its line number, section, key and value text (quotes removed).
#[derive(Debug, Clone, Copy)]
struct RawEntry<'a> {
    line: usize,
    section: &'a str,
    key: &'a str,
    value: &'a str,
}

/// The `KEY = value` lines of a text, in order, with their section; skipping comments, blank
/// lines and tables.
struct Entries<'a> {
    lines: core::iter::Enumerate<core::str::Lines<'a>>,
    section: &'a str,
    in_table: bool,
}

impl<'a> Entries<'a> {
    fn new(text: &'a str) -> Self {
        Entries {
            lines: text.lines().enumerate(),
            section: "",
            in_table: false,
        }
    }
}

/// The line without its comment (from the first `$` or `!` outside quotes), trimmed.
fn strip_comment(line: &str) -> &str {
    let mut quoted = false;
    for (i, c) in line.char_indices() {
        match c {
            '\'' | '"' => quoted = !quoted,
            '$' | '!' if !quoted => return line[..i].trim(),
            _ => {}
        }
    }
    line.trim()
}

impl<'a> Iterator for Entries<'a> {
    type Item = Result<RawEntry<'a>, TirError<'a>>;

    fn next(&mut self) -> Option<Self::Item> {
        for (i, raw) in self.lines.by_ref() {
            let line = strip_comment(raw);
            if line.is_empty() {
                continue;
            }
            if let Some(name) = line.strip_prefix('[').and_then(|l| l.strip_suffix(']')) {
                self.section = name.trim();
                self.in_table = false;
                continue;
            }
            if line.starts_with('{') {
                self.in_table = true;
                continue;
            }
            let Some((key, value)) = line.split_once('=') else {
                if self.in_table {
                    continue;
                }
                return Some(Err(TirError {
                    line: i + 1,
                    key: line,
                    kind: TirErrorKind::Syntax,
                }));
            };
            let value = value.trim();
            let value = value
                .strip_prefix('\'')
                .and_then(|v| v.strip_suffix('\''))
                .unwrap_or(value);
            return Some(Ok(RawEntry {
                line: i + 1,
                section: self.section,
                key: key.trim(),
                value: value.trim(),
            }));
        }
        None
    }
}

/// The factor to SI of a unit of `[UNITS]` `quantity` (`LENGTH`, `FORCE`, `ANGLE`), `None`
/// for a unit not known; `Some(None)` for a quantity the mapping does not use.
fn unit_factor(quantity: &str, unit: &str) -> Option<Option<f64>> {
    let u = |names: &[&str]| names.iter().any(|n| n.eq_ignore_ascii_case(unit));
    let factor = if quantity.eq_ignore_ascii_case("LENGTH") {
        if u(&["meter", "metre", "m"]) {
            1.0
        } else if u(&["millimeter", "millimetre", "mm"]) {
            1e-3
        } else if u(&["centimeter", "centimetre", "cm"]) {
            1e-2
        } else if u(&["kilometer", "kilometre", "km"]) {
            1e3
        } else if u(&["inch", "in"]) {
            0.0254
        } else if u(&["foot", "ft"]) {
            0.3048
        } else {
            return None;
        }
    } else if quantity.eq_ignore_ascii_case("FORCE") {
        if u(&["newton", "n"]) {
            1.0
        } else if u(&["kilonewton", "kilo_newton", "kn"]) {
            1e3
        } else if u(&["pound_force", "lbf"]) {
            4.448_221_615_260_5
        } else if u(&["kilogram_force", "kgf"]) {
            9.806_65
        } else {
            return None;
        }
    } else if quantity.eq_ignore_ascii_case("ANGLE") {
        // The coefficients are per radian in MF 5.2; a file in degrees would need every
        // angle coefficient converted, which the reader does not do.
        if u(&["radian", "radians", "rad"]) {
            1.0
        } else {
            return None;
        }
    } else {
        return Some(None);
    };
    Some(Some(factor))
}

/// The index of `key` in [`KEYS`] (case-insensitive).
fn index(key: &str) -> Option<usize> {
    KEYS.iter().position(|k| k.eq_ignore_ascii_case(key))
}

impl<'a> TirFile<'a> {
    /// Reads the text of a `.tir` file: every kept key's number, lengths and forces converted
    /// to m and N by the file's `[UNITS]` (which must come before them, as in every `.tir`).
    ///
    /// # Errors
    /// The first malformed line, non-numeric kept value, duplicate kept key, unknown unit, or
    /// `FITTYP` other than 6.
    pub fn read(text: &'a str) -> Result<Self, TirError<'a>> {
        let mut values: [Option<Entry>; KEYS.len()] = [None; KEYS.len()];
        let (mut length, mut force) = (1.0, 1.0);
        for entry in Entries::new(text) {
            let e = entry?;
            let err = |kind| TirError {
                line: e.line,
                key: e.key,
                kind,
            };
            if e.section.eq_ignore_ascii_case("UNITS") {
                match unit_factor(e.key, e.value) {
                    None => return Err(err(TirErrorKind::UnknownUnit)),
                    Some(Some(f)) if e.key.eq_ignore_ascii_case("LENGTH") => length = f,
                    Some(Some(f)) if e.key.eq_ignore_ascii_case("FORCE") => force = f,
                    Some(_) => {}
                }
                continue;
            }
            let Some(i) = index(e.key) else { continue };
            if let Some(first) = values[i] {
                return Err(err(TirErrorKind::Duplicate(first.line)));
            }
            let value: f64 = match e.value.parse() {
                Ok(v) if f64::is_finite(v) => v,
                _ => return Err(err(TirErrorKind::NotANumber)),
            };
            let value = match KEYS[i] {
                "UNLOADED_RADIUS" => value * length,
                "FNOMIN" => value * force,
                // An integer code: compared as written, not as a float.
                "FITTYP" if e.value.parse::<u32>() != Ok(FITTYP_MF52) => {
                    return Err(err(TirErrorKind::UnsupportedFittyp));
                }
                _ => value,
            };
            values[i] = Some(Entry {
                value,
                line: e.line,
            });
        }
        Ok(TirFile { text, values })
    }

    /// The value of kept `key` (SI units), `None` if the file does not give it or the key
    /// is not kept.
    pub fn value(&self, key: &str) -> Option<f64> {
        self.entry(key).map(|e| e.value)
    }

    /// The line of kept `key` (1-based), 0 if the file does not give it.
    pub fn line(&self, key: &str) -> usize {
        self.entry(key).map_or(0, |e| e.line)
    }

    fn entry(&self, key: &str) -> Option<Entry> {
        index(key).and_then(|i| self.values[i])
    }

    /// The keys of the file that the model has no counterpart for, with their lines, in file
    /// order: every key outside `[MDI_HEADER]` and `[UNITS]` that is not in [`KEYS`].
    pub fn ignored(&self) -> impl Iterator<Item = (usize, &'a str)> + 'a {
        Entries::new(self.text)
            .filter_map(Result::ok)
            .filter(|e| {
                !META_SECTIONS
                    .iter()
                    .any(|s| s.eq_ignore_ascii_case(e.section))
                    && index(e.key).is_none()
            })
            .map(|e| (e.line, e.key))
    }
}

#[cfg(test)]
mod tests;
