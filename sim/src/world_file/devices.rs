//! `[[vehicle.device]]`: the Webots sensor devices on a car (see [`crate::devices`]), with the
//! Webots fields of each node.

use proto_geom::SensorSlot;
use proto_geom::nalgebra::{Unit, UnitQuaternion, Vector3};
use proto_geom::plausible::{self, Compact};
use vehicle_model::Model;

use super::error::{NameSet, WorldFileError, WorldFileErrorKind};
use super::ray_devices::{
    DISTANCE_SENSOR, LIDAR, RADAR, read_distance_sensor, read_lidar, read_radar,
};
use super::read::{Section, missing};
use crate::devices::{
    Axes, CAR_DEVICE_NAMES, CameraSettings, DEFAULT_LOOKAHEAD, DeviceKind, DeviceSettings,
    DeviceSpec, DisplaySettings, GpsSettings, InertialUnitSettings, LookupTable,
    MAX_SAMPLING_PERIOD_MS, Occlusion, RecognitionSettings, RoadSensorSettings, TriaxialSettings,
};
use crate::error::ParamError;

/// The key of the devices in `[vehicle]`.
pub(crate) const DEVICE: &str = "device";

/// The keys every device has (`samplingPeriod`: a project extension, see [`read_period`]).
const COMMON: [&str; 6] = [
    "type",
    "name",
    "slot",
    "translation",
    "rotation",
    SAMPLING_PERIOD,
];
/// The key that enables a device from the start (ms).
const SAMPLING_PERIOD: &str = "samplingPeriod";
/// The `GPS` fields.
const GPS: [&str; 5] = [
    "accuracy",
    "noiseCorrelation",
    "resolution",
    "speedNoise",
    "speedResolution",
];
/// The `InertialUnit` fields.
const INERTIAL_UNIT: [&str; 5] = ["noise", "xAxis", "yAxis", "zAxis", "resolution"];
/// The `Gyro`, `Accelerometer` and `Compass` fields.
const TRIAXIAL: [&str; 5] = ["lookupTable", "xAxis", "yAxis", "zAxis", "resolution"];

/// The `Camera` fields (`recognition`: an inline table of the `Recognition` fields).
const CAMERA: [&str; 8] = [
    "fieldOfView",
    "width",
    "height",
    "near",
    "far",
    "noise",
    "projection",
    "recognition",
];
/// The `RoadSensor` fields (a project extension).
const ROAD_SENSOR: [&str; 1] = ["lookahead"];
/// The `Display` fields.
const DISPLAY: [&str; 2] = ["width", "height"];
/// The `Recognition` fields.
const RECOGNITION: [&str; 3] = ["maxRange", "maxObjects", "occlusion"];

/// The slots by their names in a world file.
const SLOTS: [(&str, SensorSlot); 4] = [
    ("front", SensorSlot::Front),
    ("top", SensorSlot::Top),
    ("rear", SensorSlot::Rear),
    ("center", SensorSlot::Centre),
];

/// Reads the `[[device]]` tables of the car section `s` of a `model` car, in file order.
pub(crate) fn read_devices(
    s: &Section<'_, '_>,
    model: Model,
) -> Result<Vec<DeviceSpec>, WorldFileError> {
    let mut out: Vec<DeviceSpec> = Vec::new();
    for d in s.tables(DEVICE)? {
        let spec = read_device(&d, model)?;
        let name = spec.device_name();
        let clash = if CAR_DEVICE_NAMES.contains(&name) {
            Some("is the name of one of the car's own devices (Webots' car library)")
        } else if out.iter().any(|o| o.device_name() == name) {
            Some("is taken by another device of this car: device names must be unique")
        } else {
            None
        };
        if let Some(why) = clash {
            return Err(d.error(
                "name",
                WorldFileErrorKind::InvalidValue(format!("\"{name}\" {why}")),
            ));
        }
        out.push(spec);
    }
    Ok(out)
}

/// Reads one device table.
fn read_device(d: &Section<'_, '_>, model: Model) -> Result<DeviceSpec, WorldFileError> {
    let type_name = d.string("type")?.ok_or_else(|| missing(d, "type"))?;
    let kind = DeviceKind::from_webots_name(type_name).ok_or_else(|| {
        let names = DeviceKind::ALL.map(DeviceKind::webots_name);
        d.unknown_name("type", NameSet::DeviceType, type_name, &names)
    })?;
    let fields: &[&str] = match kind {
        DeviceKind::Gps => &GPS,
        DeviceKind::InertialUnit => &INERTIAL_UNIT,
        DeviceKind::Gyro | DeviceKind::Accelerometer | DeviceKind::Compass => &TRIAXIAL,
        DeviceKind::Camera => &CAMERA,
        DeviceKind::Display => &DISPLAY,
        DeviceKind::DistanceSensor => &DISTANCE_SENSOR,
        DeviceKind::Radar => &RADAR,
        DeviceKind::Lidar => &LIDAR,
        DeviceKind::RoadSensor => &ROAD_SENSOR,
    };
    let allowed: Vec<&str> = COMMON.iter().chain(fields).copied().collect();
    d.check_keys(&allowed)?;
    let settings = match kind {
        DeviceKind::Gps => DeviceSettings::Gps(read_gps(d)?),
        DeviceKind::InertialUnit => DeviceSettings::InertialUnit(read_inertial_unit(d)?),
        DeviceKind::Gyro => DeviceSettings::Gyro(read_triaxial(d)?),
        DeviceKind::Accelerometer => DeviceSettings::Accelerometer(read_triaxial(d)?),
        DeviceKind::Compass => DeviceSettings::Compass(read_triaxial(d)?),
        DeviceKind::Camera => DeviceSettings::Camera(read_camera(d)?),
        DeviceKind::Display => {
            let defaults = DisplaySettings::default();
            DeviceSettings::Display(DisplaySettings {
                width: pixels(d, "width")?.unwrap_or(defaults.width),
                height: pixels(d, "height")?.unwrap_or(defaults.height),
            })
        }
        DeviceKind::DistanceSensor => DeviceSettings::DistanceSensor(read_distance_sensor(d)?),
        DeviceKind::Radar => DeviceSettings::Radar(read_radar(d)?),
        DeviceKind::Lidar => DeviceSettings::Lidar(read_lidar(d)?),
        DeviceKind::RoadSensor => DeviceSettings::RoadSensor(RoadSensorSettings {
            lookahead: d.number("lookahead")?.unwrap_or(DEFAULT_LOOKAHEAD),
        }),
    };
    settings.validate().map_err(|e| invalid(d, &e))?;
    let mut spec = DeviceSpec::new(settings);
    if let Some(name) = d.string("name")? {
        if name.is_empty() {
            return Err(d.error(
                "name",
                WorldFileErrorKind::InvalidValue("an empty name cannot be looked up".to_string()),
            ));
        }
        spec = spec.name(name);
    }
    if let Some(slot_name) = d.string("slot")? {
        let slot = SLOTS
            .iter()
            .find(|(n, _)| *n == slot_name)
            .map(|&(_, slot)| slot)
            .ok_or_else(|| {
                let names = SLOTS.map(|(n, _)| n);
                d.unknown_name("slot", NameSet::SensorSlot, slot_name, &names)
            })?;
        if model
            .shipped()
            .and_then(|v| v.sensor_slots::<f64>())
            .is_none()
        {
            return Err(d.error(
                "slot",
                WorldFileErrorKind::InvalidValue(format!(
                    "the {} model has no sensor slots; leave `slot` out to place the device \
                     in the car's frame (origin at the rear-axle centre)",
                    model.webots_name()
                )),
            ));
        }
        spec = spec.slot(slot);
    }
    if let Some(t) = d.array::<3>("translation")? {
        for v in t {
            ParamError::within("translation", v, plausible::POSITION)
                .map_err(|e| invalid(d, &e))?;
        }
        spec = spec.translation(Vector3::from(t));
    }
    if let Some([x, y, z, angle]) = d.array::<4>("rotation")? {
        let axis = Vector3::new(x, y, z);
        let valid = axis.iter().all(|c| c.is_finite()) && angle.is_finite();
        let Some(axis) = Unit::try_new(axis, 0.0).filter(|_| valid) else {
            return Err(d.error(
                "rotation",
                WorldFileErrorKind::InvalidValue(format!(
                    "[{}, {}, {}, {}]: the axis must be finite and not zero, the angle finite",
                    Compact(x),
                    Compact(y),
                    Compact(z),
                    Compact(angle)
                )),
            ));
        };
        spec = spec.rotation(UnitQuaternion::from_axis_angle(&axis, angle));
    }
    if let Some(period) = read_period(d)? {
        spec = spec.sampling_period(period);
    }
    Ok(spec)
}

/// `samplingPeriod`: the period (ms) the device is enabled with from the car's start, for
/// runs without a controller (Webots has no such field: its controllers enable devices with
/// `wb_<device>_enable(period)`). Webots' rules for that period: a whole number of ms, sent
/// as a 16-bit unsigned integer, so at most 65535; 0 would mean disabled, which leaving the
/// key out says. The effective period is rounded up to whole steps, as Webots does.
fn read_period(d: &Section<'_, '_>) -> Result<Option<u32>, WorldFileError> {
    let Some(v) = d.number(SAMPLING_PERIOD)? else {
        return Ok(None);
    };
    if v.fract() != 0.0 || !(1.0..=f64::from(MAX_SAMPLING_PERIOD_MS)).contains(&v) {
        return Err(d.error(
            SAMPLING_PERIOD,
            WorldFileErrorKind::InvalidValue(format!(
                "{} ms: must be a whole number of ms from 1 to 65535 (leave the key out to \
                 leave the device disabled until a controller enables it)",
                Compact(v)
            )),
        ));
    }
    Ok(Some(v as u32))
}

/// The file error of a field out of its range, at its key.
pub(super) fn invalid(d: &Section<'_, '_>, e: &ParamError) -> WorldFileError {
    d.error(
        e.field,
        WorldFileErrorKind::InvalidValue(format!("{}: must be {}", Compact(e.value), e.rule)),
    )
}

fn read_gps(d: &Section<'_, '_>) -> Result<GpsSettings, WorldFileError> {
    let g = GpsSettings::default();
    Ok(GpsSettings {
        accuracy: d.number("accuracy")?.unwrap_or(g.accuracy),
        noise_correlation: d.number("noiseCorrelation")?.unwrap_or(g.noise_correlation),
        resolution: d.number("resolution")?.unwrap_or(g.resolution),
        speed_noise: d.number("speedNoise")?.unwrap_or(g.speed_noise),
        speed_resolution: d.number("speedResolution")?.unwrap_or(g.speed_resolution),
    })
}

fn read_camera(d: &Section<'_, '_>) -> Result<CameraSettings, WorldFileError> {
    let c = CameraSettings::default();
    if let Some(p) = d.string("projection")?
        && p != "planar"
    {
        return Err(d.error(
            "projection",
            WorldFileErrorKind::InvalidValue(format!(
                "\"{p}\": only the \"planar\" projection is rendered"
            )),
        ));
    }
    let recognition = match d.table("recognition")? {
        None => None,
        Some(r) => Some(read_recognition(&r)?),
    };
    Ok(CameraSettings {
        field_of_view: d.number("fieldOfView")?.unwrap_or(c.field_of_view),
        width: pixels(d, "width")?.unwrap_or(c.width),
        height: pixels(d, "height")?.unwrap_or(c.height),
        near: d.number("near")?.unwrap_or(c.near),
        far: d.number("far")?.unwrap_or(c.far),
        noise: d.number("noise")?.unwrap_or(c.noise),
        recognition,
    })
}

/// A whole number of pixels at `key` (1 to 4096: the range is checked with the others).
fn pixels(d: &Section<'_, '_>, key: &str) -> Result<Option<u32>, WorldFileError> {
    let Some(v) = d.number(key)? else {
        return Ok(None);
    };
    if v.fract() != 0.0 || !(1.0..=f64::from(crate::devices::camera::MAX_SIDE)).contains(&v) {
        return Err(d.error(
            key,
            WorldFileErrorKind::InvalidValue(format!(
                "{} px: must be a whole number from 1 to 4096",
                Compact(v)
            )),
        ));
    }
    Ok(Some(v as u32))
}

fn read_recognition(r: &Section<'_, '_>) -> Result<RecognitionSettings, WorldFileError> {
    r.check_keys(&RECOGNITION)?;
    let d = RecognitionSettings::default();
    let max_objects = match r.number("maxObjects")? {
        None => d.max_objects,
        Some(n) if n.fract() == 0.0 && n >= -1.0 && n <= f64::from(i32::MAX) => n as i32,
        Some(n) => {
            return Err(r.error(
                "maxObjects",
                WorldFileErrorKind::InvalidValue(format!(
                    "{}: must be -1 (all) or a whole number >= 0",
                    Compact(n)
                )),
            ));
        }
    };
    let occlusion = match r.number("occlusion")? {
        None => d.occlusion,
        Some(0.0) => Occlusion::Off,
        Some(1.0) => Occlusion::Centre,
        Some(2.0) => Occlusion::Outline,
        Some(n) => {
            return Err(r.error(
                "occlusion",
                WorldFileErrorKind::InvalidValue(format!(
                    "{}: must be 0 (off), 1 (centre visible) or 2 (outline)",
                    Compact(n)
                )),
            ));
        }
    };
    Ok(RecognitionSettings {
        max_range: r.number("maxRange")?.unwrap_or(d.max_range),
        max_objects,
        occlusion,
    })
}

fn read_axes(d: &Section<'_, '_>) -> Result<Axes, WorldFileError> {
    Ok(Axes {
        x: d.boolean("xAxis")?.unwrap_or(true),
        y: d.boolean("yAxis")?.unwrap_or(true),
        z: d.boolean("zAxis")?.unwrap_or(true),
    })
}

fn read_inertial_unit(d: &Section<'_, '_>) -> Result<InertialUnitSettings, WorldFileError> {
    let u = InertialUnitSettings::default();
    Ok(InertialUnitSettings {
        noise: d.number("noise")?.unwrap_or(u.noise),
        axes: read_axes(d)?,
        resolution: d.number("resolution")?.unwrap_or(u.resolution),
    })
}

/// The `lookupTable` of `d` (present).
pub(super) fn read_table(d: &Section<'_, '_>) -> Result<LookupTable, WorldFileError> {
    match d.value("lookupTable") {
        None => Ok(LookupTable::default()),
        Some(v) => {
            let rows = d.triples(
                "lookupTable",
                v,
                "a list of [input, output, noise] rows",
                "row",
            )?;
            LookupTable::new(rows).map_err(|e| invalid(d, &e))
        }
    }
}

fn read_triaxial(d: &Section<'_, '_>) -> Result<TriaxialSettings, WorldFileError> {
    let lookup_table = read_table(d)?;
    Ok(TriaxialSettings {
        lookup_table,
        axes: read_axes(d)?,
        resolution: d.number("resolution")?.unwrap_or(-1.0),
    })
}
