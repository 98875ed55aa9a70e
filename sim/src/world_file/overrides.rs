//! Values set by dotted key in a world file's parsed document before it is read: how a sweep
//! makes each case's world from its base world, so that the case goes through the same reader
//! (and gets the same errors, naming the key) as a world file.

use core::fmt;
use std::borrow::Cow;

use toml::Spanned;
use toml::de::{DeTable, DeValue};

/// One step of a [`KeyPath`]: a key, and for an array of tables (`[[box]]`) which table.
#[derive(Debug, Clone, PartialEq, Eq)]
struct Segment {
    name: String,
    /// 0-based index into the array of tables named `name`; written 1-based (`box[1]`) as the
    /// world file's messages name them.
    index: Option<usize>,
}

/// A dotted key of a world file: `ground.friction`, `vehicle.tyre.lateral.shape`,
/// `vehicle.wheels.mass`, or into an array of tables by its 1-based position, as the
/// world-file messages name it: `box[2].friction`, `vehicle[1].mass`.
#[derive(Debug, Clone, PartialEq, Eq)]
pub struct KeyPath {
    text: String,
    segments: Vec<Segment>,
}

impl KeyPath {
    /// Parses `text`.
    ///
    /// # Errors
    /// Why `text` is not a key path (an empty segment, a bad or zero index), as a sentence.
    pub fn parse(text: &str) -> Result<KeyPath, String> {
        let mut segments = Vec::new();
        for part in text.split('.') {
            let (name, index) = match part.split_once('[') {
                None => (part, None),
                Some((name, rest)) => {
                    let number = rest.strip_suffix(']').ok_or_else(|| {
                        format!("'{part}' in '{text}': an index is written [n], e.g. box[1]")
                    })?;
                    let n: usize = number.parse().ok().filter(|&n| n >= 1).ok_or_else(|| {
                        format!(
                            "'{part}' in '{text}': the index counts tables from 1, as the \
                             world file's messages do"
                        )
                    })?;
                    (name, Some(n - 1))
                }
            };
            if name.is_empty() || name.contains([']', '[', ' ']) {
                return Err(format!(
                    "'{text}' is not a dotted key (e.g. 'ground.friction')"
                ));
            }
            segments.push(Segment {
                name: name.to_string(),
                index,
            });
        }
        Ok(KeyPath {
            text: text.to_string(),
            segments,
        })
    }

    /// The path as written.
    pub fn as_str(&self) -> &str {
        &self.text
    }

    /// True when `key` (a dotted key of a world-file message, e.g. `vehicle.wheels.mass`) is
    /// this path, inside it, or one of the tables on it.
    pub fn covers(&self, key: &str) -> bool {
        let (a, b) = (self.text.as_str(), key);
        let nested = |long: &str, short: &str| {
            long.strip_prefix(short)
                .is_some_and(|rest| rest.is_empty() || rest.starts_with(['.', '[']))
        };
        nested(a, b) || nested(b, a)
    }
}

impl fmt::Display for KeyPath {
    fn fmt(&self, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        f.write_str(&self.text)
    }
}

/// A key name as the document stores it.
fn key(name: &str) -> Spanned<Cow<'static, str>> {
    Spanned::new(0..0, Cow::Owned(name.to_string()))
}

/// Sets `value` at `path` in `doc`, creating the tables on the way; the value replaces what
/// was there.
///
/// # Errors
/// Why the path leads nowhere (a value on the way that is not a table, an index past the
/// tables of the file), as a sentence naming the key.
pub(crate) fn set<'i>(
    doc: &mut DeTable<'i>,
    path: &KeyPath,
    value: DeValue<'i>,
) -> Result<(), String> {
    let mut table = doc;
    let mut walked = String::new();
    let last = path.segments.len().saturating_sub(1);
    for (i, seg) in path.segments.iter().enumerate() {
        if !walked.is_empty() {
            walked.push('.');
        }
        walked.push_str(&seg.name);
        if i == last && seg.index.is_none() {
            table.insert(key(&seg.name), Spanned::new(0..0, value));
            return Ok(());
        }
        if seg.index.is_some() && !table.contains_key(seg.name.as_str()) {
            return Err(format!(
                "cannot set '{path}': the world has no [[{walked}]] tables"
            ));
        }
        let slot = table
            .entry(key(&seg.name))
            .or_insert_with(|| Spanned::new(0..0, DeValue::Table(DeTable::new())));
        let slot = if matches!(slot.get_ref(), DeValue::Array(_)) {
            let DeValue::Array(items) = slot.get_mut() else {
                return Err(format!(
                    "cannot set '{path}': '{walked}' is not an array of tables"
                ));
            };
            let count = items.len();
            let k = match seg.index {
                Some(k) => k,
                // A single [[vehicle]] is "the vehicle": no index needed.
                None if count == 1 => 0,
                None => {
                    return Err(format!(
                        "cannot set '{path}': the world has {count} [[{walked}]] tables; name \
                         one by its position, e.g. '{walked}[1]'"
                    ));
                }
            };
            items.get_mut(k).ok_or_else(|| {
                format!(
                    "cannot set '{path}': the world has {count} [[{walked}]] table{}",
                    if count == 1 { "" } else { "s" }
                )
            })?
        } else if seg.index.is_some() {
            return Err(format!(
                "cannot set '{path}': '{walked}' is not an array of tables"
            ));
        } else {
            slot
        };
        if i == last {
            *slot = Spanned::new(0..0, value);
            return Ok(());
        }
        table = match slot.get_mut() {
            DeValue::Table(t) => t,
            other => {
                return Err(format!(
                    "cannot set '{path}': '{walked}' is {}, not a table",
                    super::read::describe(other)
                ));
            }
        };
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;

    fn apply(text: &str, path: &str, value: &str) -> Result<String, String> {
        let mut doc = DeTable::parse(text).unwrap().into_inner();
        let value = DeValue::parse(value).unwrap().into_inner();
        set(&mut doc, &KeyPath::parse(path)?, value)?;
        Ok(format!("{doc:?}"))
    }

    #[test]
    fn paths_parse_with_one_based_indices() {
        let p = KeyPath::parse("box[2].friction").unwrap();
        assert_eq!(p.segments[0].index, Some(1));
        assert_eq!(p.segments[1].name, "friction");
        for bad in ["", "a..b", "box[0].x", "box[x].y", "box[1", "a b"] {
            assert!(KeyPath::parse(bad).is_err(), "{bad}");
        }
        let p = KeyPath::parse("vehicle.wheels").unwrap();
        assert!(p.covers("vehicle.wheels.mass"));
        assert!(p.covers("vehicle"));
        assert!(!p.covers("vehicle.wheelsX"));
        assert!(KeyPath::parse("box[1].friction").unwrap().covers("box[1]"));
    }

    #[test]
    fn values_go_where_the_path_says() {
        let text = "[vehicle]\nmodel = \"BmwX5\"\n[[box]]\nsize = [1, 1, 1]\n";
        // A new table on the way is created; an existing value replaced.
        let d = apply(text, "vehicle.tyre.lateral.shape", "1.5").unwrap();
        assert!(d.contains("\"shape\"") && d.contains("1.5"), "{d}");
        let d = apply(text, "vehicle.model", "\"ToyotaPrius\"").unwrap();
        assert!(d.contains("ToyotaPrius") && !d.contains("BmwX5"), "{d}");
        let d = apply(text, "box[1].friction", "0.5").unwrap();
        assert!(d.contains("\"friction\""), "{d}");
        assert_eq!(
            apply(text, "box[2].friction", "0.5").unwrap_err(),
            "cannot set 'box[2].friction': the world has 1 [[box]] table"
        );
        assert_eq!(
            apply(text, "box.friction", "0.5").unwrap(),
            apply(text, "box[1].friction", "0.5").unwrap()
        );
        let two = format!("{text}[[box]]\nsize = [2, 2, 2]\n");
        assert_eq!(
            apply(&two, "box.friction", "0.5").unwrap_err(),
            "cannot set 'box.friction': the world has 2 [[box]] tables; name one by its \
             position, e.g. 'box[1]'"
        );
        assert_eq!(
            apply(text, "vehicle.model.x", "1").unwrap_err(),
            "cannot set 'vehicle.model.x': 'vehicle.model' is a string, not a table"
        );
        assert_eq!(
            apply(text, "ramp[1].height", "1").unwrap_err(),
            "cannot set 'ramp[1].height': the world has no [[ramp]] tables"
        );
    }
}
