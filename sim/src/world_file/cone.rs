//! `[[cone]]`: traffic cones, one or a line of `count` cones `spacing` apart (a slalom's or a
//! lane change's gate line in one table).

use proto_geom::nalgebra::{Point3, Vector2};
use proto_geom::plausible::Compact;

use super::error::{WorldFileError, WorldFileErrorKind};
use super::read::{Section, missing};
use crate::config::{Obstacle, WorldConfig};
use crate::world::{CONE_COLOR, Cone, DEFAULT_CONE_HEIGHT, DEFAULT_CONE_RADIUS, DEFAULT_CONE_RCS};

/// Keys of each `[[cone]]`.
pub(crate) const CONE_KEYS: [&str; 9] = [
    "translation",
    "height",
    "radius",
    "color",
    "recognitionColors",
    "radarCrossSection",
    "friction",
    "count",
    "spacing",
];

/// The most cones one `[[cone]]` may place: a 1 km course at a cone every metre.
pub(crate) const MAX_CONE_COUNT: u64 = 1000;

/// The number of cones `section` places (`count`, 1 when absent).
pub(crate) fn count_of(section: &Section<'_, '_>) -> Result<u64, WorldFileError> {
    let count = section.unsigned("count")?.unwrap_or(1);
    if !(1..=MAX_CONE_COUNT).contains(&count) {
        return Err(section.error(
            "count",
            WorldFileErrorKind::InvalidValue(format!(
                "{count}: must be from 1 to {MAX_CONE_COUNT} cones"
            )),
        ));
    }
    Ok(count)
}

/// Appends the cones of every `[[cone]]` of `root` to `config.obstacles`, in file order.
pub(crate) fn read_cones(
    root: &Section<'_, '_>,
    config: &mut WorldConfig,
) -> Result<(), WorldFileError> {
    for s in root.tables("cone")? {
        s.check_keys(&CONE_KEYS)?;
        let base = s
            .array::<3>("translation")?
            .ok_or_else(|| missing(&s, "translation"))?;
        let count = count_of(&s)?;
        let spacing = match s.array::<2>("spacing")? {
            Some(d) => Vector2::from(d),
            None if count > 1 => return Err(missing(&s, "spacing")),
            None => Vector2::zeros(),
        };
        let first = Cone {
            base: Point3::from(base),
            height: s.number("height")?.unwrap_or(DEFAULT_CONE_HEIGHT),
            radius: s.number("radius")?.unwrap_or(DEFAULT_CONE_RADIUS),
            color: s.array::<3>("color")?.unwrap_or(CONE_COLOR),
        };
        let obstacle = |cone: Cone| -> Result<Obstacle, WorldFileError> {
            Ok(Obstacle::Cone {
                cone,
                friction: s.number("friction")?,
                radar_cross_section: s.number("radarCrossSection")?.unwrap_or(DEFAULT_CONE_RCS),
            })
        };
        let alone = WorldConfig {
            obstacles: vec![obstacle(first.clone())?],
            ..WorldConfig::default()
        };
        alone.validate().map_err(|e| {
            let key = match e.field.rsplit('.').next().unwrap_or("") {
                "base" => "translation",
                other => other,
            };
            s.error(
                key,
                WorldFileErrorKind::InvalidValue(format!(
                    "{}: must be {}",
                    Compact(e.value),
                    e.rule
                )),
            )
        })?;
        if count > 1 {
            // Cones that overlap are a typo in `spacing`, not a course.
            let gap = spacing.norm();
            if !(gap.is_finite() && gap >= 2.0 * first.radius) {
                return Err(s.error(
                    "spacing",
                    WorldFileErrorKind::InvalidValue(format!(
                        "{} m apart: {count} cones of radius {} m must be at least {} m apart \
                         (their bases would overlap)",
                        Compact(gap),
                        Compact(first.radius),
                        Compact(2.0 * first.radius)
                    )),
                ));
            }
            let last = first.base.xy() + spacing * (count - 1) as f64;
            if let Some(c) = last
                .iter()
                .find(|c| c.abs() > proto_geom::plausible::POSITION.max)
            {
                return Err(s.error(
                    "spacing",
                    WorldFileErrorKind::InvalidValue(format!(
                        "the last of {count} cones would stand at {} m: every coordinate must be \
                         within {}",
                        Compact(*c),
                        proto_geom::plausible::POSITION
                    )),
                ));
            }
        }
        for k in 0..count {
            let offset = spacing * k as f64;
            let cone = Cone {
                base: first.base + offset.push(0.0),
                ..first.clone()
            };
            config.obstacles.push(obstacle(cone)?);
        }
    }
    Ok(())
}
