//! Typed, located access to the parsed TOML: every value read knows its key and its place in
//! the file, so each error can name both.

use core::ops::{Range, RangeInclusive};

use proto_geom::plausible::Compact;
use toml::de::{DeTable, DeValue};

use super::error::{Location, NameSet, WorldFileError, WorldFileErrorKind, WorldWarning, closest};

/// The file being read: its name (for messages) and its text (for line numbers).
#[derive(Debug, Clone, Copy)]
pub(crate) struct Source<'a> {
    pub(crate) file: &'a str,
    pub(crate) text: &'a str,
}

impl Source<'_> {
    /// An error at byte range `span` about `key`.
    pub(crate) fn error(
        &self,
        span: Option<Range<usize>>,
        key: Option<String>,
        kind: WorldFileErrorKind,
    ) -> WorldFileError {
        WorldFileError {
            file: self.file.to_string(),
            location: span.map(|s| Location::of_offset(self.text, s.start)),
            key,
            kind,
        }
    }

    /// A warning at byte range `span` about `key`.
    pub(crate) fn warning(
        &self,
        span: Option<Range<usize>>,
        key: Option<String>,
        message: String,
    ) -> WorldWarning {
        WorldWarning {
            file: self.file.to_string(),
            location: span.map(|s| Location::of_offset(self.text, s.start)),
            key,
            message,
        }
    }
}

/// A TOML table with its dotted path (`""` for the document, `vehicle`, `box[1]`).
#[derive(Clone)]
pub(crate) struct Section<'a, 'i> {
    pub(crate) src: Source<'a>,
    path: String,
    table: &'a DeTable<'i>,
    /// Where the table starts (its header, or the key that opened it).
    span: Option<Range<usize>>,
}

/// What a value looks like, for "found …" in messages.
pub(crate) fn describe(v: &DeValue<'_>) -> String {
    match v {
        DeValue::Array(a) => format!("a list of {} values", a.len()),
        DeValue::Table(_) => "a table".to_string(),
        other => {
            let t = other.type_str();
            let article = if t.starts_with(['a', 'e', 'i', 'o', 'u']) {
                "an"
            } else {
                "a"
            };
            format!("{article} {t}")
        }
    }
}

/// The value of a TOML integer or float as `f64` (a decimal integer beyond 64 bits is
/// rounded), `None` for other types.
pub(crate) fn as_f64(v: &DeValue<'_>) -> Option<f64> {
    match v {
        DeValue::Integer(i) => match i64::from_str_radix(i.as_str(), i.radix()) {
            Ok(n) => Some(n as f64),
            Err(_) if i.radix() == 10 => i.as_str().parse().ok(),
            Err(_) => u64::from_str_radix(i.as_str(), i.radix())
                .ok()
                .map(|n| n as f64),
        },
        DeValue::Float(f) => f.as_str().parse().ok(),
        _ => None,
    }
}

impl<'a, 'i> Section<'a, 'i> {
    /// The whole document.
    pub(crate) fn root(src: Source<'a>, table: &'a DeTable<'i>) -> Self {
        Section {
            src,
            path: String::new(),
            table,
            span: None,
        }
    }

    /// The section's dotted path, e.g. `vehicle.tyre`.
    pub(crate) fn path(&self) -> &str {
        &self.path
    }

    /// The dotted path of `key` in this section.
    pub(crate) fn key_path(&self, key: &str) -> String {
        if self.path.is_empty() {
            key.to_string()
        } else {
            format!("{}.{key}", self.path)
        }
    }

    /// Where this section starts.
    pub(crate) fn span(&self) -> Option<Range<usize>> {
        self.span.clone()
    }

    /// The section's keys with their values, in file order.
    pub(crate) fn entries(&self) -> Vec<(&'a str, &'a DeValue<'i>, Range<usize>, Range<usize>)> {
        let mut v: Vec<_> = self
            .table
            .iter()
            .map(|(k, v)| (k.get_ref().as_ref(), v.get_ref(), k.span(), v.span()))
            .collect();
        v.sort_by_key(|e| e.2.start);
        v
    }

    /// The span of `key`, if present.
    pub(crate) fn key_span(&self, key: &str) -> Option<Range<usize>> {
        self.table
            .iter()
            .find(|(k, _)| k.get_ref().as_ref() == key)
            .map(|(k, _)| k.span())
    }

    /// The raw value at `key`, if present: for keys that take more than one type.
    pub(crate) fn value(&self, key: &str) -> Option<&'a DeValue<'i>> {
        self.get(key).map(|(v, _)| v)
    }

    fn get(&self, key: &str) -> Option<(&'a DeValue<'i>, Range<usize>)> {
        self.table
            .iter()
            .find(|(k, _)| k.get_ref().as_ref() == key)
            .map(|(_, v)| (v.get_ref(), v.span()))
    }

    /// An unknown `name` of the set `what` (whose names are `names`) at `key`: the closest
    /// names as suggestions, or all of them when none is close.
    pub(crate) fn unknown_name(
        &self,
        key: &str,
        what: NameSet,
        name: &str,
        names: &[&str],
    ) -> WorldFileError {
        let mut suggestions = closest(name, names.iter().copied());
        if suggestions.is_empty() {
            suggestions = names.iter().map(|n| n.to_string()).collect();
        }
        self.error(
            key,
            WorldFileErrorKind::UnknownName {
                what,
                name: name.to_string(),
                suggestions,
            },
        )
    }

    /// An error about `key` of this section, located at the key (or the section).
    pub(crate) fn error(&self, key: &str, kind: WorldFileErrorKind) -> WorldFileError {
        let span = self.key_span(key).or_else(|| self.span.clone());
        self.src.error(span, Some(self.key_path(key)), kind)
    }

    /// An error about `key` located at `span`.
    pub(crate) fn error_at(
        &self,
        key: &str,
        span: Range<usize>,
        kind: WorldFileErrorKind,
    ) -> WorldFileError {
        self.src.error(Some(span), Some(self.key_path(key)), kind)
    }

    fn wrong_type(&self, key: &str, expected: &str, found: &DeValue<'_>) -> WorldFileError {
        self.error(
            key,
            WorldFileErrorKind::WrongType {
                expected: expected.to_string(),
                found: describe(found),
            },
        )
    }

    /// Fails on the first key (in file order) that is not in `allowed`, suggesting the
    /// closest allowed names.
    pub(crate) fn check_keys(&self, allowed: &[&str]) -> Result<(), WorldFileError> {
        self.check_keys_with(allowed, |_| false)
    }

    /// As [`Section::check_keys`], also accepting every key for which `extra` is true.
    pub(crate) fn check_keys_with(
        &self,
        allowed: &[&str],
        extra: impl Fn(&str) -> bool,
    ) -> Result<(), WorldFileError> {
        for (key, _, key_span, _) in self.entries() {
            if !allowed.contains(&key) && !extra(key) {
                return Err(self.error_at(
                    key,
                    key_span,
                    WorldFileErrorKind::UnknownKey {
                        suggestions: closest(key, allowed.iter().copied()),
                    },
                ));
            }
        }
        Ok(())
    }

    /// The number at `key` (integer or float), if present.
    pub(crate) fn number(&self, key: &str) -> Result<Option<f64>, WorldFileError> {
        match self.get(key) {
            None => Ok(None),
            Some((v, _)) => as_f64(v)
                .map(Some)
                .ok_or_else(|| self.wrong_type(key, "a number", v)),
        }
    }

    /// The list of numbers at `key` with a length in `len`, if present.
    pub(crate) fn numbers(
        &self,
        key: &str,
        len: RangeInclusive<usize>,
    ) -> Result<Option<Vec<f64>>, WorldFileError> {
        let expected = if len.start() == len.end() {
            format!("a list of {} numbers", len.start())
        } else {
            format!("a list of {} to {} numbers", len.start(), len.end())
        };
        let Some((v, _)) = self.get(key) else {
            return Ok(None);
        };
        let DeValue::Array(items) = v else {
            return Err(self.wrong_type(key, &expected, v));
        };
        let mut out = Vec::with_capacity(items.len());
        for item in items.iter() {
            match as_f64(item.get_ref()) {
                Some(x) => out.push(x),
                None => {
                    return Err(self.error_at(
                        key,
                        item.span(),
                        WorldFileErrorKind::WrongType {
                            expected: expected.clone(),
                            found: format!("{} in the list", describe(item.get_ref())),
                        },
                    ));
                }
            }
        }
        if len.contains(&out.len()) {
            Ok(Some(out))
        } else {
            Err(self.wrong_type(key, &expected, v))
        }
    }

    /// A fixed-size list of numbers at `key`, if present.
    pub(crate) fn array<const N: usize>(
        &self,
        key: &str,
    ) -> Result<Option<[f64; N]>, WorldFileError> {
        Ok(self
            .numbers(key, N..=N)?
            .and_then(|v| <[f64; N]>::try_from(v).ok()))
    }

    /// `v`, the value at `key`, as a list of three-number lists (a `lookupTable`'s rows,
    /// `recognitionColors`). A wrong shape is an error at `key` expecting `expected`, naming
    /// the first bad entry as `item` and its 1-based position.
    pub(crate) fn triples(
        &self,
        key: &str,
        v: &DeValue<'_>,
        expected: &str,
        item: &str,
    ) -> Result<Vec<[f64; 3]>, WorldFileError> {
        let wrong = |found: String| {
            self.error(
                key,
                WorldFileErrorKind::WrongType {
                    expected: expected.to_string(),
                    found,
                },
            )
        };
        let DeValue::Array(rows) = v else {
            return Err(wrong(describe(v)));
        };
        let mut out = Vec::with_capacity(rows.len());
        for (i, row) in rows.iter().enumerate() {
            let numbers: Option<Vec<f64>> = match row.get_ref() {
                DeValue::Array(items) => items.iter().map(|x| as_f64(x.get_ref())).collect(),
                _ => None,
            };
            match numbers.and_then(|n| <[f64; 3]>::try_from(n).ok()) {
                Some(r) => out.push(r),
                None => {
                    return Err(wrong(format!(
                        "{} at {item} {}",
                        describe(row.get_ref()),
                        i + 1
                    )));
                }
            }
        }
        Ok(out)
    }

    /// The string at `key`, if present.
    pub(crate) fn string(&self, key: &str) -> Result<Option<&'a str>, WorldFileError> {
        match self.get(key) {
            None => Ok(None),
            Some((DeValue::String(s), _)) => Ok(Some(s.as_ref())),
            Some((v, _)) => Err(self.wrong_type(key, "a string", v)),
        }
    }

    /// The boolean at `key`, if present.
    pub(crate) fn boolean(&self, key: &str) -> Result<Option<bool>, WorldFileError> {
        match self.get(key) {
            None => Ok(None),
            Some((DeValue::Boolean(b), _)) => Ok(Some(*b)),
            Some((v, _)) => Err(self.wrong_type(key, "true or false", v)),
        }
    }

    /// The non-negative integer at `key` that fits in `u64`, if present.
    pub(crate) fn unsigned(&self, key: &str) -> Result<Option<u64>, WorldFileError> {
        match self.get(key) {
            None => Ok(None),
            Some((DeValue::Integer(i), _)) => u64::from_str_radix(i.as_str(), i.radix())
                .map(Some)
                .map_err(|_| {
                    self.error(
                        key,
                        WorldFileErrorKind::InvalidValue(format!(
                            "{i} is not an integer in 0 to {}",
                            u64::MAX
                        )),
                    )
                }),
            Some((v, _)) => Err(self.wrong_type(key, "a non-negative integer", v)),
        }
    }

    /// The table at `key` (a `[section]` or an inline table), if present.
    pub(crate) fn table(&self, key: &str) -> Result<Option<Section<'a, 'i>>, WorldFileError> {
        match self.get(key) {
            None => Ok(None),
            Some((DeValue::Table(t), span)) => Ok(Some(Section {
                src: self.src,
                path: self.key_path(key),
                table: t,
                span: Some(span),
            })),
            Some((v, _)) => Err(self.wrong_type(key, "a table", v)),
        }
    }

    /// The tables of the array of tables at `key` (`[[key]]`), empty if absent; the `i`-th
    /// (from 1, in file order) is named `key[i]` in messages.
    pub(crate) fn tables(&self, key: &str) -> Result<Vec<Section<'a, 'i>>, WorldFileError> {
        let Some((v, _)) = self.get(key) else {
            return Ok(Vec::new());
        };
        let DeValue::Array(items) = v else {
            return Err(self.wrong_type(key, &format!("tables ([[{key}]])"), v));
        };
        let mut out = Vec::with_capacity(items.len());
        for (i, item) in items.iter().enumerate() {
            match item.get_ref() {
                DeValue::Table(t) => out.push(Section {
                    src: self.src,
                    path: format!("{}[{}]", self.key_path(key), i + 1),
                    table: t,
                    span: Some(item.span()),
                }),
                other => {
                    return Err(self.error_at(
                        key,
                        item.span(),
                        WorldFileErrorKind::WrongType {
                            expected: format!("tables ([[{key}]])"),
                            found: describe(other),
                        },
                    ));
                }
            }
        }
        Ok(out)
    }
}

/// The error of a required `key` absent from `section`.
pub(crate) fn missing(section: &Section<'_, '_>, key: &str) -> WorldFileError {
    section.src.error(
        section.span(),
        Some(section.key_path(key)),
        WorldFileErrorKind::Structure(format!("missing key '{}'", section.key_path(key))),
    )
}

/// The heading (rad) of a Webots `rotation` (axis x, y, z, angle) about the vertical axis;
/// 0 when absent.
pub(crate) fn yaw_of(section: &Section<'_, '_>) -> Result<f64, WorldFileError> {
    let Some([x, y, z, angle]) = section.array::<4>("rotation")? else {
        return Ok(0.0);
    };
    let norm = (x * x + y * y + z * z).sqrt();
    let vertical = norm.is_finite() && norm > 0.0 && (x * x + y * y).sqrt() <= 1e-9 * norm;
    if !vertical || !angle.is_finite() {
        return Err(section.error(
            "rotation",
            WorldFileErrorKind::InvalidValue(format!(
                "[{}, {}, {}, {}]: only finite rotations about the vertical axis \
                 ([0, 0, 1, angle]) are supported here",
                Compact(x),
                Compact(y),
                Compact(z),
                Compact(angle)
            )),
        ));
    }
    Ok(angle * z.signum())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbers_in_every_toml_spelling() {
        let doc = DeTable::parse(
            "a = 1_000\nb = 0x10\nc = 1e3\nd = -2.5\ne = -inf\nf = 99999999999999999999\n\
             g = 0xffffffffffffffff\nh = \"1\"\n",
        )
        .unwrap();
        let get = |k: &str| {
            let (_, v) = doc
                .get_ref()
                .iter()
                .find(|(key, _)| key.get_ref() == k)
                .unwrap();
            as_f64(v.get_ref())
        };
        assert_eq!(get("a"), Some(1000.0));
        assert_eq!(get("b"), Some(16.0));
        assert_eq!(get("c"), Some(1000.0));
        assert_eq!(get("d"), Some(-2.5));
        assert_eq!(get("e"), Some(f64::NEG_INFINITY));
        assert_eq!(get("f"), Some(1e20));
        assert_eq!(get("g"), Some(u64::MAX as f64));
        assert_eq!(get("h"), None);
    }
}
