//! The world itself: `WorldInfo`-like top-level keys, `[ground]`, `[[box]]` and `[[ramp]]`
//! (and, through [`super::cone`] and [`super::bodies`], `[[cone]]` and `[[body]]`).

use crate::config::{MAX_GRAVITY, Obstacle, WorldConfig};
use proto_geom::nalgebra::{Point2, Point3, Vector3};
use proto_geom::plausible::Compact;

use super::error::{WorldFileError, WorldFileErrorKind};
use super::read::{Section, missing, yaw_of};

/// Keys of `[ground]`.
pub(crate) const GROUND_KEYS: [&str; 1] = ["friction"];
/// Keys of each `[[box]]`.
pub(crate) const BOX_KEYS: [&str; 7] = [
    "translation",
    "size",
    "rotation",
    "friction",
    "color",
    "recognitionColors",
    "radarCrossSection",
];
/// Keys of each `[[ramp]]`.
pub(crate) const RAMP_KEYS: [&str; 9] = [
    "start",
    "rotation",
    "length",
    "width",
    "height",
    "friction",
    "color",
    "recognitionColors",
    "radarCrossSection",
];

/// The top-level key of the wind (m/s, world frame, `[x, y, z]`).
pub(crate) const WIND: &str = "wind";

/// Reads `basicTimeStep`, `gravity`, `wind`, `[ground]`, `[[box]]` and `[[ramp]]` into a validated
/// [`WorldConfig`]; absent keys keep the defaults of [`WorldConfig::default`].
pub(crate) fn read_world(root: &Section<'_, '_>) -> Result<WorldConfig, WorldFileError> {
    let mut config = WorldConfig::default();
    if let Some(ms) = root.number("basicTimeStep")? {
        config.basic_time_step_ms = whole_ms(ms).ok_or_else(|| {
            root.error(
                "basicTimeStep",
                WorldFileErrorKind::InvalidValue(format!(
                    "{} ms: must be a whole number of milliseconds from 1 to 1000",
                    Compact(ms)
                )),
            )
        })?;
    }
    if let Some(g) = root.number("gravity")? {
        // Webots' `WorldInfo.gravity`: the magnitude of a gravity pointing down.
        if !(g.is_finite() && (0.0..=MAX_GRAVITY).contains(&g)) {
            return Err(root.error(
                "gravity",
                WorldFileErrorKind::InvalidValue(format!(
                    "{} m/s²: must be from 0 to {MAX_GRAVITY} (the magnitude of a gravity \
                     pointing down)",
                    Compact(g)
                )),
            ));
        }
        config.gravity = Vector3::new(0.0, 0.0, -g);
    }
    if let Some([x, y, z]) = root.array::<3>(WIND)? {
        config.wind = Vector3::new(x, y, z);
        located(root, WIND, &config)?;
    }
    if let Some(ground) = root.table("ground")? {
        ground.check_keys(&GROUND_KEYS)?;
        if let Some(mu) = ground.number("friction")? {
            config.ground_friction = mu;
            located(&ground, "friction", &config)?;
        }
    }
    for b in root.tables("box")? {
        b.check_keys(&BOX_KEYS)?;
        let center = required_array::<3>(&b, "translation")?;
        let size = required_array::<3>(&b, "size")?;
        let yaw = yaw_of(&b)?;
        config.obstacles.push(Obstacle::Box {
            center: Point3::from(center),
            half_extents: Vector3::from(size.map(|s| s / 2.0)),
            yaw,
            friction: b.number("friction")?,
            radar_cross_section: b.number("radarCrossSection")?.unwrap_or(0.0),
        });
        validate_last_obstacle(&b, &config)?;
    }
    for r in root.tables("ramp")? {
        r.check_keys(&RAMP_KEYS)?;
        let start = required_array::<2>(&r, "start")?;
        let yaw = yaw_of(&r)?;
        let mut dims = [0.0; 3];
        for (d, key) in dims.iter_mut().zip(["length", "width", "height"]) {
            *d = r.number(key)?.ok_or_else(|| missing(&r, key))?;
        }
        let [length, width, height] = dims;
        config.obstacles.push(Obstacle::Ramp {
            start: Point2::from(start),
            yaw,
            length,
            width,
            height,
            friction: r.number("friction")?,
            radar_cross_section: r.number("radarCrossSection")?.unwrap_or(0.0),
        });
        validate_last_obstacle(&r, &config)?;
    }
    super::cone::read_cones(root, &mut config)?;
    super::bodies::read_bodies(root, &mut config)?;
    config.validate().map_err(|e| {
        root.src.error(
            None,
            Some(e.field.to_string()),
            WorldFileErrorKind::InvalidValue(e.to_string()),
        )
    })?;
    Ok(config)
}

/// `ms` as a whole number of milliseconds in 1..=1000.
fn whole_ms(ms: f64) -> Option<u32> {
    (ms.fract() == 0.0 && (1.0..=1000.0).contains(&ms)).then_some(ms as u32)
}

/// Runs the world's validation and, on failure, blames `key` of `section`.
fn located(
    section: &Section<'_, '_>,
    key: &str,
    config: &WorldConfig,
) -> Result<(), WorldFileError> {
    config.validate().map_err(|e| {
        section.error(
            key,
            WorldFileErrorKind::InvalidValue(format!("{}: must be {}", Compact(e.value), e.rule)),
        )
    })
}

/// Validates the obstacle just pushed (alone, so an earlier error cannot be blamed on it) and,
/// on failure, blames the key of `section` that the simulator's field name points to.
fn validate_last_obstacle(
    section: &Section<'_, '_>,
    config: &WorldConfig,
) -> Result<(), WorldFileError> {
    let alone = WorldConfig {
        obstacles: config.obstacles.last().cloned().into_iter().collect(),
        ..WorldConfig::default()
    };
    alone.validate().map_err(|e| {
        let key = match e.field.rsplit('.').next().unwrap_or("") {
            "center" => "translation",
            "half_extents" => "size",
            "yaw" => "rotation",
            other => other,
        };
        let message = match key {
            // The simulator checks half sizes; the file gives full sizes.
            "size" => format!(
                "{} m: every size must be finite and > 0",
                Compact(2.0 * e.value)
            ),
            _ => format!("{}: must be {}", Compact(e.value), e.rule),
        };
        section.error(key, WorldFileErrorKind::InvalidValue(message))
    })
}

fn required_array<const N: usize>(
    section: &Section<'_, '_>,
    key: &str,
) -> Result<[f64; N], WorldFileError> {
    section
        .array::<N>(key)?
        .ok_or_else(|| missing(section, key))
}
