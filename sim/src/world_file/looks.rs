//! `color` and `recognitionColors` of the world's boxes, ramps, dynamic boxes, cars and robot
//! (see [`crate::appearance`]).

use proto_geom::plausible::Compact;

use super::error::{WorldFileError, WorldFileErrorKind};
use super::read::Section;
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
        Some(v) => Some(s.triples(
            "recognitionColors",
            v,
            "a list of [red, green, blue] colours",
            "colour",
        )?),
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
