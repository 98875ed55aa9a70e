//! The fields of the ray-based devices in `[[vehicle.device]]`: `DistanceSensor`, `Radar` and
//! `Lidar`, and the `preset` that starts a radar or lidar from a real device's numbers.

use super::devices::read_table;
use super::error::{NameSet, WorldFileError, WorldFileErrorKind};
use super::read::Section;
use crate::devices::{
    DistanceSensorSettings, DistanceSensorType, LidarProjection, LidarSettings, LidarType,
    RadarSettings,
};

/// The `DistanceSensor` fields.
pub(super) const DISTANCE_SENSOR: [&str; 7] = [
    "lookupTable",
    SENSOR_TYPE,
    "numberOfRays",
    "aperture",
    "gaussianWidth",
    "resolution",
    "redColorSensitivity",
];
/// The `Radar` fields, and `preset`.
pub(super) const RADAR: [&str; 18] = [
    "preset",
    "minRange",
    "maxRange",
    "horizontalFieldOfView",
    "verticalFieldOfView",
    "minAbsoluteRadialSpeed",
    "minRadialSpeed",
    "maxRadialSpeed",
    "cellDistance",
    "cellSpeed",
    "rangeNoise",
    "speedNoise",
    "angularNoise",
    "antennaGain",
    "frequency",
    "transmittedPower",
    "minDetectableSignal",
    "occlusion",
];
/// The key of a `DistanceSensor`'s Webots field `type` (`type` names the device's node).
const SENSOR_TYPE: &str = "sensorType";

/// The `Lidar` fields, and `preset`; Webots' `type` is `sensorType` (`type` names the node).
/// `rotatingHead` is listed to be refused by name.
pub(super) const LIDAR: [&str; 17] = [
    "preset",
    SENSOR_TYPE,
    "rotatingHead",
    "tiltAngle",
    "horizontalResolution",
    "fieldOfView",
    "verticalFieldOfView",
    "numberOfLayers",
    "near",
    "minRange",
    "maxRange",
    "projection",
    "noise",
    "resolution",
    "defaultFrequency",
    "minFrequency",
    "maxFrequency",
];

/// A preset: its name and the settings it makes.
type Preset<T> = (&'static str, fn() -> T);

/// The radar presets: Webots' `DelphiEsr` PROTO in its two modes.
const RADAR_PRESETS: [Preset<RadarSettings>; 2] = [
    ("DelphiEsr", RadarSettings::delphi_esr),
    ("DelphiEsrLongRange", RadarSettings::delphi_esr_long_range),
];
/// The lidar presets: Webots' `SickLms291` and `VelodynePuck` PROTOs.
const LIDAR_PRESETS: [Preset<LidarSettings>; 2] = [
    ("SickLms291", LidarSettings::sick_lms_291),
    ("VelodyneVlp16", LidarSettings::velodyne_vlp16),
];

/// The settings of `preset` (default: the node's defaults).
fn preset<T>(
    d: &Section<'_, '_>,
    presets: &[Preset<T>],
    default: fn() -> T,
) -> Result<T, WorldFileError> {
    let Some(name) = d.string("preset")? else {
        return Ok(default());
    };
    presets
        .iter()
        .find(|(n, _)| *n == name)
        .map(|(_, make)| make())
        .ok_or_else(|| {
            let names: Vec<&str> = presets.iter().map(|(n, _)| *n).collect();
            d.unknown_name("preset", NameSet::DevicePreset, name, &names)
        })
}

/// A count field (`numberOfRays`, `horizontalResolution`, `numberOfLayers`): a non-negative
/// integer; its range is checked with the other fields.
fn count(d: &Section<'_, '_>, key: &str, default: u32) -> Result<u32, WorldFileError> {
    match d.unsigned(key)? {
        None => Ok(default),
        Some(n) => u32::try_from(n).map_err(|_| {
            d.error(
                key,
                WorldFileErrorKind::InvalidValue(format!("{n} is far too many")),
            )
        }),
    }
}

pub(super) fn read_distance_sensor(
    d: &Section<'_, '_>,
) -> Result<DistanceSensorSettings, WorldFileError> {
    let s = DistanceSensorSettings::default();
    let sensor_type = match d.string(SENSOR_TYPE)? {
        None => s.sensor_type,
        // Webots' other spelling.
        Some("infrared") => DistanceSensorType::InfraRed,
        Some(name) => DistanceSensorType::ALL
            .into_iter()
            .find(|t| t.webots_name() == name)
            .ok_or_else(|| {
                let names = DistanceSensorType::ALL.map(DistanceSensorType::webots_name);
                d.unknown_name(SENSOR_TYPE, NameSet::DistanceSensorType, name, &names)
            })?,
    };
    let lookup_table = match d.value("lookupTable") {
        None => s.lookup_table.clone(),
        Some(_) => read_table(d)?,
    };
    Ok(DistanceSensorSettings {
        lookup_table,
        sensor_type,
        number_of_rays: count(d, "numberOfRays", s.number_of_rays)?,
        aperture: d.number("aperture")?.unwrap_or(s.aperture),
        gaussian_width: d.number("gaussianWidth")?.unwrap_or(s.gaussian_width),
        resolution: d.number("resolution")?.unwrap_or(s.resolution),
        red_color_sensitivity: d
            .number("redColorSensitivity")?
            .unwrap_or(s.red_color_sensitivity),
    })
}

pub(super) fn read_radar(d: &Section<'_, '_>) -> Result<RadarSettings, WorldFileError> {
    let s = preset(d, &RADAR_PRESETS, RadarSettings::default)?;
    let n = |key: &str, default: f64| -> Result<f64, WorldFileError> {
        Ok(d.number(key)?.unwrap_or(default))
    };
    Ok(RadarSettings {
        min_range: n("minRange", s.min_range)?,
        max_range: n("maxRange", s.max_range)?,
        horizontal_field_of_view: n("horizontalFieldOfView", s.horizontal_field_of_view)?,
        vertical_field_of_view: n("verticalFieldOfView", s.vertical_field_of_view)?,
        min_absolute_radial_speed: n("minAbsoluteRadialSpeed", s.min_absolute_radial_speed)?,
        min_radial_speed: n("minRadialSpeed", s.min_radial_speed)?,
        max_radial_speed: n("maxRadialSpeed", s.max_radial_speed)?,
        cell_distance: n("cellDistance", s.cell_distance)?,
        cell_speed: n("cellSpeed", s.cell_speed)?,
        range_noise: n("rangeNoise", s.range_noise)?,
        speed_noise: n("speedNoise", s.speed_noise)?,
        angular_noise: n("angularNoise", s.angular_noise)?,
        antenna_gain: n("antennaGain", s.antenna_gain)?,
        frequency: n("frequency", s.frequency)?,
        transmitted_power: n("transmittedPower", s.transmitted_power)?,
        min_detectable_signal: n("minDetectableSignal", s.min_detectable_signal)?,
        occlusion: d.boolean("occlusion")?.unwrap_or(s.occlusion),
    })
}

pub(super) fn read_lidar(d: &Section<'_, '_>) -> Result<LidarSettings, WorldFileError> {
    let s = preset(d, &LIDAR_PRESETS, LidarSettings::default)?;
    let projection = match d.string("projection")? {
        None => s.projection,
        Some("cylindrical") => LidarProjection::Cylindrical,
        Some("planar") => LidarProjection::Planar,
        Some(other) => {
            let names = [LidarProjection::Cylindrical, LidarProjection::Planar]
                .map(LidarProjection::webots_name);
            return Err(d.unknown_name("projection", NameSet::LidarProjection, other, &names));
        }
    };
    let lidar_type = match d.string(SENSOR_TYPE)? {
        None => s.lidar_type,
        Some(name) => [LidarType::Fixed, LidarType::Rotating]
            .into_iter()
            .find(|t| t.webots_name() == name)
            .ok_or_else(|| {
                let names = [LidarType::Fixed, LidarType::Rotating].map(LidarType::webots_name);
                d.unknown_name(SENSOR_TYPE, NameSet::LidarType, name, &names)
            })?,
    };
    if d.value("rotatingHead").is_some() {
        return Err(d.error(
            "rotatingHead",
            WorldFileErrorKind::InvalidValue(
                "a rotating head's solid is not simulated: a rotating lidar's rays turn \
                 without one (leave rotatingHead out)"
                    .to_string(),
            ),
        ));
    }
    let n = |key: &str, default: f64| -> Result<f64, WorldFileError> {
        Ok(d.number(key)?.unwrap_or(default))
    };
    Ok(LidarSettings {
        lidar_type,
        tilt_angle: n("tiltAngle", s.tilt_angle)?,
        horizontal_resolution: count(d, "horizontalResolution", s.horizontal_resolution)?,
        field_of_view: n("fieldOfView", s.field_of_view)?,
        vertical_field_of_view: n("verticalFieldOfView", s.vertical_field_of_view)?,
        number_of_layers: count(d, "numberOfLayers", s.number_of_layers)?,
        near: n("near", s.near)?,
        min_range: n("minRange", s.min_range)?,
        max_range: n("maxRange", s.max_range)?,
        projection,
        noise: n("noise", s.noise)?,
        resolution: n("resolution", s.resolution)?,
        default_frequency: n("defaultFrequency", s.default_frequency)?,
        min_frequency: n("minFrequency", s.min_frequency)?,
        max_frequency: n("maxFrequency", s.max_frequency)?,
    })
}
