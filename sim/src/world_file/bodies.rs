//! `[[body]]`: dynamic boxes.

use crate::body::BodySpec;
use crate::config::WorldConfig;

use proto_geom::nalgebra::{Point3, Vector3};
use proto_geom::plausible::Compact;

use super::error::{WorldFileError, WorldFileErrorKind};
use super::read::Section;
use super::read::{missing, yaw_of};

/// Keys of each `[[body]]`.
pub(crate) const BODY_KEYS: [&str; 8] = [
    "translation",
    "size",
    "mass",
    "rotation",
    "friction",
    "color",
    "recognitionColors",
    "radarCrossSection",
];

/// Reads every `[[body]]` into `config.bodies`, each validated on its own so that an error
/// names the key of the section at fault.
pub(crate) fn read_bodies(
    root: &Section<'_, '_>,
    config: &mut WorldConfig,
) -> Result<(), WorldFileError> {
    for b in root.tables("body")? {
        b.check_keys(&BODY_KEYS)?;
        let center = b
            .array::<3>("translation")?
            .ok_or_else(|| missing(&b, "translation"))?;
        let size = b.array::<3>("size")?.ok_or_else(|| missing(&b, "size"))?;
        let mass = b.number("mass")?.ok_or_else(|| missing(&b, "mass"))?;
        let spec = BodySpec {
            center: Point3::from(center),
            size: Vector3::from(size),
            yaw: yaw_of(&b)?,
            mass,
            friction: b.number("friction")?,
            radar_cross_section: b.number("radarCrossSection")?.unwrap_or(0.0),
        };
        spec.validate().map_err(|e| {
            let key = match e.field {
                "body.center" => "translation",
                "body.size" => "size",
                "body.mass" => "mass",
                "body.yaw" => "rotation",
                "body.radarCrossSection" => "radarCrossSection",
                _ => "friction",
            };
            b.error(
                key,
                WorldFileErrorKind::InvalidValue(format!(
                    "{}: must be {}",
                    Compact(e.value),
                    e.rule
                )),
            )
        })?;
        config.bodies.push(spec);
    }
    Ok(())
}
