//! `color` and `recognitionColors` of the world's boxes, ramps, dynamic boxes, cars and robot
//! (see [`crate::appearance`]).

use proto_geom::plausible::Compact;
use toml::de::DeValue;

use super::error::{WorldFileError, WorldFileErrorKind};
use super::read::{Section, as_f64, describe};
use crate::appearance::{Appearance, SceneObject};

/// The look section `s` gives `object` (whose default colour is `default`), if it gives one.
pub(crate) fn read_look(
    s: &Section<'_, '_>,
    object: SceneObject,
    default: [f64; 3],
) -> Result<Option<(SceneObject, Appearance)>, WorldFileError> {
    let color = s.array::<3>("color")?;
    let recognition_colors = match s.value("recognitionColors") {
        None => None,
        Some(v) => Some(read_colors(s, v)?),
    };
    if color.is_none() && recognition_colors.is_none() {
        return Ok(None);
    }
    let look = Appearance {
        color: color.unwrap_or(default),
        recognition_colors: recognition_colors.unwrap_or_default(),
        model: String::new(),
    };
    look.validate().map_err(|e| {
        s.error(
            e.field,
            WorldFileErrorKind::InvalidValue(format!("{}: must be {}", Compact(e.value), e.rule)),
        )
    })?;
    Ok(Some((object, look)))
}

/// A list of `[r, g, b]` colours.
fn read_colors(s: &Section<'_, '_>, v: &DeValue<'_>) -> Result<Vec<[f64; 3]>, WorldFileError> {
    let wrong = |found: String| {
        s.error(
            "recognitionColors",
            WorldFileErrorKind::WrongType {
                expected: "a list of [red, green, blue] colours".to_string(),
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
            Some(c) => out.push(c),
            None => {
                return Err(wrong(format!(
                    "{} at colour {}",
                    describe(row.get_ref()),
                    i + 1
                )));
            }
        }
    }
    Ok(out)
}
