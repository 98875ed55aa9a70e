//! `[differential_wheels]`: the legacy Webots robot, its mode, noise seed and placement.

use crate::diff_wheels::{DifferentialWheelsParams, RobotBody, RobotMode, RobotPlacement};
use proto_geom::plausible::{Compact, POSITION};

use super::error::{WorldFileError, WorldFileErrorKind};
use super::programme::{PROGRAMME, read_robot_programme};
use super::read::Section;
use super::read::yaw_of;
use super::vehicle::NAME;
use crate::programme::{Programme, WheelSpeeds};

/// The `DifferentialWheels` node fields, by their Webots names.
pub(crate) const NODE_FIELDS: [&str; 10] = [
    "motorConsumption",
    "axleLength",
    "wheelRadius",
    "maxSpeed",
    "maxAcceleration",
    "speedUnit",
    "slipNoise",
    "encoderNoise",
    "encoderResolution",
    "maxForce",
];

/// The keys of `[differential_wheels]` that are the simulator's own, not node fields.
const SIM_KEYS: [&str; 12] = [
    NAME,
    "radarCrossSection",
    "color",
    "recognitionColors",
    PROGRAMME,
    "physics",
    "seed",
    "translation",
    "rotation",
    "bodyMass",
    "wheelMass",
    "wheelWidth",
];

/// A DifferentialWheels robot as a world file describes it.
#[derive(Debug, Clone, PartialEq)]
pub struct RobotDescription {
    /// The node fields (validated), including the noise seed.
    pub params: DifferentialWheelsParams,
    /// Kinematics, or physics with the body's masses.
    pub mode: RobotMode,
    /// Where the robot starts.
    pub placement: RobotPlacement,
    /// Its name in telemetry, plots and metrics (`name`, default `DifferentialWheels`).
    pub name: String,
    /// Its timed wheel speeds (`[[differential_wheels.programme]]`), empty if none.
    pub programme: Programme<WheelSpeeds>,
    /// Webots' `radarCrossSection` of its solid (m², ≥ 0; 0, the default: radars do not see
    /// it).
    pub radar_cross_section: f64,
}

/// The default name of the robot.
pub(crate) const ROBOT_NAME: &str = "DifferentialWheels";

impl Default for RobotDescription {
    /// The Webots defaults in kinematics mode, at the origin facing +x.
    fn default() -> Self {
        RobotDescription {
            params: DifferentialWheelsParams::default(),
            mode: RobotMode::Kinematics,
            placement: RobotPlacement::default(),
            name: ROBOT_NAME.to_string(),
            programme: Programme::default(),
            radar_cross_section: 0.0,
        }
    }
}

/// Reads `[differential_wheels]`.
pub(crate) fn read_robot(s: &Section<'_, '_>) -> Result<RobotDescription, WorldFileError> {
    let keys: Vec<&str> = NODE_FIELDS.iter().chain(&SIM_KEYS).copied().collect();
    s.check_keys(&keys)?;
    let mut p = DifferentialWheelsParams::default();
    for key in NODE_FIELDS {
        if let Some(v) = s.number(key)? {
            *field_mut(&mut p, key) = v;
        }
    }
    if let Some(seed) = s.unsigned("seed")? {
        p.seed = seed;
    }
    p.validate().map_err(|e| {
        s.error(
            e.field,
            WorldFileErrorKind::InvalidValue(format!("{}: must be {}", Compact(e.value), e.rule)),
        )
    })?;

    let physics = s.boolean("physics")?.unwrap_or(false);
    let mode = if physics {
        let mut body = RobotBody::default();
        for (key, slot) in [
            ("bodyMass", &mut body.body_mass),
            ("wheelMass", &mut body.wheel_mass),
            ("wheelWidth", &mut body.wheel_width),
        ] {
            if let Some(v) = s.number(key)? {
                if !(v.is_finite() && v > 0.0) {
                    return Err(s.error(
                        key,
                        WorldFileErrorKind::InvalidValue(format!(
                            "{}: must be finite and > 0",
                            Compact(v)
                        )),
                    ));
                }
                *slot = v;
            }
        }
        RobotMode::Physics(body)
    } else {
        if let Some(key) = ["bodyMass", "wheelMass", "wheelWidth"]
            .into_iter()
            .find(|k| s.key_span(k).is_some())
        {
            return Err(s.error(
                key,
                WorldFileErrorKind::Structure(format!(
                    "'{}' only applies with physics = true",
                    s.key_path(key)
                )),
            ));
        }
        RobotMode::Kinematics
    };

    let [x, y, z] = s.array::<3>("translation")?.unwrap_or([0.0; 3]);
    // The same bounds as the simulator's robot placement, so that a world that loads builds.
    if let Some(bad) = [x, y, z].into_iter().find(|v| !POSITION.contains(*v)) {
        return Err(s.error(
            "translation",
            WorldFileErrorKind::InvalidValue(format!(
                "{}: every coordinate must be within {POSITION}",
                Compact(bad)
            )),
        ));
    }
    let placement = RobotPlacement {
        x,
        y,
        z,
        heading: yaw_of(s)?,
    };
    let name = s.string(NAME)?.unwrap_or(ROBOT_NAME).to_string();
    let programme = read_robot_programme(s, p.max_speed / p.speed_unit)?;
    let radar_cross_section = s.number("radarCrossSection")?.unwrap_or(0.0);
    if !(radar_cross_section.is_finite() && radar_cross_section >= 0.0) {
        return Err(s.error(
            "radarCrossSection",
            WorldFileErrorKind::InvalidValue(format!(
                "{} m²: must be finite and >= 0",
                Compact(radar_cross_section)
            )),
        ));
    }
    Ok(RobotDescription {
        params: p,
        mode,
        placement,
        name,
        programme,
        radar_cross_section,
    })
}

/// The field of `p` with Webots name `key` (one of [`NODE_FIELDS`]).
fn field_mut<'p>(p: &'p mut DifferentialWheelsParams, key: &str) -> &'p mut f64 {
    match key {
        "motorConsumption" => &mut p.motor_consumption,
        "axleLength" => &mut p.axle_length,
        "wheelRadius" => &mut p.wheel_radius,
        "maxSpeed" => &mut p.max_speed,
        "maxAcceleration" => &mut p.max_acceleration,
        "speedUnit" => &mut p.speed_unit,
        "slipNoise" => &mut p.slip_noise,
        "encoderNoise" => &mut p.encoder_noise,
        "encoderResolution" => &mut p.encoder_resolution,
        _ => &mut p.max_force,
    }
}
