//! The sweep file's text: its keys read with their places in the file, so that every error
//! names the file, line, column and key as a world file's do.
//!
//! ```toml
//! world = "BmwX5"                 # a world file (relative to this file) or a model name
//! scenario = "brake"
//! combine = "product"             # or "zip"
//! color_by = "ground.friction"     # the plots' colours; or "none"
//! [set]                           # every case
//! duration = 30
//! [axes]
//! "ground.friction" = [0.6, 0.8, 1.0]
//! "vehicle.brakeCoefficient" = { from = 1000, to = 2000, steps = 5 }
//! "vehicle.mass" = { uniform = [1800, 2600], count = 4, seed = 1 }
//! ```

use core::ops::Range;

use toml::de::{DeTable, DeValue};

use crate::scenario::Scenario;
use crate::world_file::read::{Section, Source, describe};
use crate::world_file::{KeyPath, NameSet, WorldFileError, WorldFileErrorKind};

use super::axis::{self, ReadAxis};
use super::cases::Combine;
use super::value::AxisValue;

/// The keys of a sweep file.
const ROOT_KEYS: [&str; 6] = ["world", "scenario", "combine", "color_by", "set", "axes"];

/// A value of `[set]`: the same in every case.
pub(crate) struct Setting {
    pub(crate) key: KeyPath,
    pub(crate) value: AxisValue,
    /// Where its key is.
    pub(crate) span: Range<usize>,
}

/// A sweep file as written, with the places of its keys.
pub(crate) struct ReadSweep {
    /// `world` and where it is; `None`: the default world.
    pub(crate) world: Option<(String, Range<usize>)>,
    /// `scenario` and where it is; `None`: `vehicle-sim`'s default for the world.
    pub(crate) scenario: Option<(Scenario, Range<usize>)>,
    /// `combine` and where it is.
    pub(crate) combine: (Combine, Option<Range<usize>>),
    /// `color_by` and where it is; `None`: absent (the plots choose).
    pub(crate) color_by: Option<(String, Range<usize>)>,
    /// `[set]`, in file order.
    pub(crate) set: Vec<Setting>,
    /// `[axes]`, in file order.
    pub(crate) axes: Vec<ReadAxis>,
}

/// `key` under `prefix` (a dotted world-file key).
fn join(prefix: &str, key: &str) -> String {
    if prefix.is_empty() {
        key.to_string()
    } else {
        format!("{prefix}.{key}")
    }
}

/// Reads the sweep file `src`.
///
/// # Errors
/// Invalid TOML, an unknown key (with the closest names), a value of the wrong type or
/// shape, an unknown scenario or combination, at its file, line, column and key.
pub(crate) fn read(src: Source<'_>) -> Result<ReadSweep, WorldFileError> {
    let doc = DeTable::parse(src.text).map_err(|e| {
        src.error(
            e.span(),
            None,
            WorldFileErrorKind::Syntax(e.message().to_string()),
        )
    })?;
    let root = Section::root(src, doc.get_ref());
    root.check_keys(&ROOT_KEYS)?;
    let span = |key: &str| root.key_span(key).unwrap_or(0..0);
    let world = root
        .string("world")?
        .map(|w| (w.to_string(), span("world")));
    let scenario = match root.string("scenario")? {
        None => None,
        Some(name) => {
            let names = Scenario::ALL.map(Scenario::name);
            let s = Scenario::from_name(name)
                .ok_or_else(|| root.unknown_name("scenario", NameSet::Scenario, name, &names))?;
            Some((s, span("scenario")))
        }
    };
    let combine = match root.string("combine")? {
        None => (Combine::default(), None),
        Some(name) => {
            let c = Combine::from_name(name).ok_or_else(|| {
                root.unknown_name("combine", NameSet::Combine, name, &Combine::NAMES)
            })?;
            (c, Some(span("combine")))
        }
    };
    let color_by = root
        .string("color_by")?
        .map(|c| (c.to_string(), span("color_by")));
    let mut set = Vec::new();
    if let Some(s) = root.table("set")? {
        read_set(&s, "", &mut set)?;
    }
    let mut axes = Vec::new();
    if let Some(s) = root.table("axes")? {
        read_axes(&s, "", &mut axes)?;
    }
    let mut keys: Vec<&str> = Vec::new();
    for (key, span) in set
        .iter()
        .map(|s| (s.key.as_str(), &s.span))
        .chain(axes.iter().map(|a| (a.axis.key().as_str(), &a.key_span)))
    {
        if let Some(other) = keys
            .iter()
            .find(|k| KeyPath::parse(k).is_ok_and(|p| p.covers(key)))
        {
            return Err(src.error(
                Some(span.clone()),
                Some(key.to_string()),
                WorldFileErrorKind::Structure(format!(
                    "'{key}' overlaps '{other}': a key is set once, in [set] or in [axes]"
                )),
            ));
        }
        keys.push(key);
    }
    Ok(ReadSweep {
        world,
        scenario,
        combine,
        color_by,
        set,
        axes,
    })
}

/// Reads the settings of `s` (`[set]` or a table in it) under the dotted key `prefix`.
fn read_set(
    s: &Section<'_, '_>,
    prefix: &str,
    out: &mut Vec<Setting>,
) -> Result<(), WorldFileError> {
    for (key, value, key_span, _) in s.entries() {
        let world_key = join(prefix, key);
        if let DeValue::Table(_) = value {
            if let Some(sub) = s.table(key)? {
                read_set(&sub, &world_key, out)?;
            }
            continue;
        }
        let path = KeyPath::parse(&world_key)
            .map_err(|m| s.error_at(key, key_span.clone(), WorldFileErrorKind::InvalidValue(m)))?;
        let value = AxisValue::from_toml(value).ok_or_else(|| {
            s.error_at(
                key,
                key_span.clone(),
                WorldFileErrorKind::WrongType {
                    expected: "a number, string, boolean or list".to_string(),
                    found: describe(value),
                },
            )
        })?;
        out.push(Setting {
            key: path,
            value,
            span: key_span,
        });
    }
    Ok(())
}

/// Reads the axes of `s` (`[axes]` or a level of a dotted key in it) under `prefix`: a table
/// that is no axis (`ground.friction = […]` written without quotes makes one) is a level of
/// the key.
fn read_axes(
    s: &Section<'_, '_>,
    prefix: &str,
    out: &mut Vec<ReadAxis>,
) -> Result<(), WorldFileError> {
    for (key, value, key_span, _) in s.entries() {
        let world_key = join(prefix, key);
        match value {
            DeValue::Table(t) if !axis::is_shape(t) => {
                if let Some(sub) = s.table(key)? {
                    read_axes(&sub, &world_key, out)?;
                }
            }
            _ => out.push(axis::read(s, key, &world_key, value, key_span)?),
        }
    }
    Ok(())
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::sweep::AxisValues;

    fn parse(text: &str) -> Result<ReadSweep, String> {
        read(Source {
            file: "s.toml",
            text,
        })
        .map_err(|e| e.to_string())
    }

    #[test]
    fn every_axis_shape_in_file_order() {
        let s = parse(
            "world = \"BmwX5\"\nscenario = \"brake\"\n[set]\nduration = 20\n\
             vehicle.tyre.model = \"webots\"\n[axes]\n\"ground.friction\" = [0.6, 0.8]\n\
             vehicle.brakeCoefficient = { from = 1000, to = 2000, steps = 3 }\n\
             \"vehicle.mass\" = { uniform = [1800, 2600], count = 4, seed = 1 }\n\
             \"box[1].friction\" = { normal = [0.8, 0.05], count = 2, seed = 3 }\n",
        )
        .unwrap();
        assert_eq!(s.world.unwrap().0, "BmwX5");
        assert_eq!(s.scenario.unwrap().0, Scenario::Brake);
        assert_eq!(s.combine.0, Combine::Product);
        let set: Vec<&str> = s.set.iter().map(|s| s.key.as_str()).collect();
        assert_eq!(set, ["duration", "vehicle.tyre.model"]);
        let keys: Vec<&str> = s.axes.iter().map(|a| a.axis.key().as_str()).collect();
        assert_eq!(
            keys,
            [
                "ground.friction",
                "vehicle.brakeCoefficient",
                "vehicle.mass",
                "box[1].friction"
            ]
        );
        assert_eq!(
            s.axes[2].axis.values(),
            &AxisValues::Uniform {
                lo: 1800.0,
                hi: 2600.0,
                count: 4,
                seed: 1
            }
        );
        assert_eq!(s.axes[0].value_spans.len(), 2);
    }

    #[test]
    fn errors_name_file_line_and_key() {
        let cases = [
            (
                "wrold = \"BmwX5\"\n",
                "s.toml:1:1: unknown key 'wrold'; did you mean 'world'?",
            ),
            (
                "scenario = \"brak\"\n",
                "s.toml:1:1: unknown scenario 'brak'; did you mean 'brake'?",
            ),
            (
                "combine = \"zipped\"\n",
                "s.toml:1:1: unknown way to combine the axes 'zipped'; did you mean 'zip'?",
            ),
            (
                "[axes]\n\"ground.friction\" = { from = 0.5, to = 1, step = 3 }\n",
                "s.toml:2:43: unknown key 'axes.ground.friction.step'; did you mean 'steps'?",
            ),
            (
                "[axes]\n\"ground.friction\" = { from = 0.5, to = 1 }\n",
                "s.toml:2:21: axis 'ground.friction': a range { from, to, steps } needs 'steps'",
            ),
            (
                "[axes]\n\"ground.friction\" = 0.5\n",
                "s.toml:2:1: 'axes.ground.friction' takes a list of values, { from, to, steps }, \
                 { uniform = [lo, hi], count, seed } or { normal = [mean, sd], count, seed }, \
                 found a float",
            ),
            (
                "[axes]\n\"ground.friction\" = []\n",
                "s.toml:2:1: invalid 'axes.ground.friction': an axis needs one value at least",
            ),
            (
                "[axes]\n\"vehicle.mass\" = { uniform = [2, 1], count = 3, seed = 1 }\n",
                "s.toml:2:20: invalid 'axes.vehicle.mass.uniform': [2, 1]: lo must be < hi",
            ),
            (
                "[axes]\n\"vehicle.mass\" = { uniform = [1, 2], normal = [1, 1], count = 3, seed = 1 }\n",
                "s.toml:2:18: axis 'vehicle.mass' mixes { from, to, steps }, uniform and normal: \
                 it takes one of them",
            ),
            (
                "[axes]\n\"vehicle.mass\" = { normal = [1, 1], count = 0, seed = 1 }\n",
                "s.toml:2:37: invalid 'axes.vehicle.mass.count': 0: must be an integer >= 1",
            ),
            (
                "[axes]\n\"box[0].friction\" = [1]\n",
                "s.toml:2:1: invalid 'axes.box[0].friction': 'box[0]' in 'box[0].friction': the \
                 index counts tables from 1, as the world file's messages do",
            ),
            (
                "[axes]\n\"ground.friction\" = [1, { a = 1 }]\n",
                "s.toml:2:25: 'axes.ground.friction' takes numbers, strings, booleans or lists \
                 (set a table's keys one by one, e.g. 'vehicle.tyre.model'), found a table in \
                 the list",
            ),
            (
                "[set]\nground.friction = 1\n[axes]\n\"ground\" = [1]\n",
                "s.toml:4:1: 'ground' overlaps 'ground.friction': a key is set once, in [set] \
                 or in [axes]",
            ),
            (
                "[axes\n",
                "s.toml:1:6: invalid TOML: unclosed table, expected `]`",
            ),
        ];
        let wrong: Vec<String> = cases
            .iter()
            .filter_map(|(text, expected)| {
                let got = parse(text).err();
                (got.as_deref() != Some(*expected)).then(|| format!("{text}: {got:?}"))
            })
            .collect();
        assert!(wrong.is_empty(), "{wrong:#?}");
    }
}
