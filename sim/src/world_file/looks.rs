//! `color` and `recognitionColors` of the world's boxes, ramps, dynamic boxes, cars and robot
//! (see [`crate::appearance`]).

use proto_geom::plausible::Compact;

use super::cone;
use super::error::{WorldFileError, WorldFileErrorKind};
use super::read::Section;
use crate::appearance::{
    Appearance, Appearances, BODY_COLOR, OBSTACLE_COLOR, PALETTE, SceneObject,
};
use crate::world::CONE_COLOR;

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

/// The looks of the boxes, ramps, cones (in `config.obstacles`' order: boxes, ramps, then
/// each `[[cone]]`'s `count` cones), dynamic boxes, cars and robot.
pub(super) fn read_looks(
    root: &Section<'_, '_>,
    cars: &[Section<'_, '_>],
    robot: Option<&Section<'_, '_>>,
) -> Result<Appearances, WorldFileError> {
    let mut found = Vec::new();
    let obstacles = root.tables("box")?.into_iter().chain(root.tables("ramp")?);
    let mut next = 0;
    for s in obstacles {
        found.push(read_look(&s, SceneObject::Obstacle(next), OBSTACLE_COLOR)?);
        next += 1;
    }
    for s in root.tables("cone")? {
        let look = read_look(&s, SceneObject::Obstacle(next), CONE_COLOR)?;
        // Validated when the world was read.
        let count = cone::count_of(&s)? as usize;
        if let Some((_, look)) = look {
            found.extend(
                (next..next + count).map(|i| Some((SceneObject::Obstacle(i), look.clone()))),
            );
        }
        next += count;
    }
    for (i, s) in root.tables("body")?.iter().enumerate() {
        found.push(read_look(s, SceneObject::Body(i), BODY_COLOR)?);
    }
    for (i, s) in cars.iter().enumerate() {
        found.push(read_look(
            s,
            SceneObject::Car(i),
            PALETTE[i % PALETTE.len()],
        )?);
    }
    if let Some(s) = robot {
        let colour = PALETTE[cars.len() % PALETTE.len()];
        found.push(read_look(s, SceneObject::Robot(0), colour)?);
    }
    let mut appearances = Appearances::default();
    for (object, look) in found.into_iter().flatten() {
        // Validated by `read_look`.
        let _ = appearances.set(object, look);
    }
    Ok(appearances)
}
