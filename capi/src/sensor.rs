//! What every sensor function of the C API does around the engine's measurement: finding the
//! sensor a tag names (with Webots' messages for a wrong tag), enabling with a period, the
//! "disabled device" error, and the storage the `const double *` results point into.
//!
//! The measurements themselves are the engine's (`sim::devices`); this only marshals them.

use std::ffi::c_int;

use sim::VehicleId;
use sim::devices::{Device, DeviceKind, DeviceSettings, LidarPoint, Reading};

use crate::abi::WbDeviceTag;
use crate::camera_api::RecognitionStore;
use crate::message;
use crate::robot::Robot;

/// One sensor's result storage: what the last getter call copied from the engine's sample.
#[derive(Debug, Default)]
pub(crate) struct Slot {
    /// A GPS's position, an inertial unit's quaternion `[x, y, z, w]`, or a three-axis
    /// sensor's values (first three).
    pub(crate) values: [f64; 4],
    /// A GPS's speed vector (m/s).
    pub(crate) speed_vector: [f64; 3],
    /// A radar's targets, as the last `wb_radar_get_targets` copied them.
    pub(crate) targets: Vec<WbRadarTarget>,
    /// A lidar's range image (m), as the last getter copied it.
    pub(crate) range_image: Vec<f32>,
    /// A lidar's point cloud (m), as the last getter converted it.
    pub(crate) point_cloud: Vec<LidarPoint>,
    /// A lidar's frequency (Hz): `defaultFrequency` until `wb_lidar_set_frequency`.
    pub(crate) frequency: f64,
}

/// Webots' `WbRadarTarget` (`webots/radar_target.h`): 32 bytes.
#[derive(Debug, Clone, Copy, PartialEq)]
#[repr(C)]
pub struct WbRadarTarget {
    /// Distance (m).
    pub distance: f64,
    /// Received power (dBm).
    pub received_power: f64,
    /// Radial speed (m/s, > 0 receding).
    pub speed: f64,
    /// Azimuth (rad, > 0 to the right).
    pub azimuth: f64,
}

/// The storage of every sensor of the robot, and the one roll/pitch/yaw array that Webots
/// shares between all inertial units.
#[derive(Debug)]
pub(crate) struct Buffers {
    /// One slot per sensor, in a boxed slice that never grows: the pointers handed out stay
    /// put until the robot is freed.
    slots: Box<[Slot]>,
    /// Each sensor's `lookupTable`, row after row (empty for none).
    tables: Vec<Box<[f64]>>,
    pub(crate) roll_pitch_yaw: Box<[f64; 3]>,
    /// Each sensor's recognition objects (empty but for cameras).
    recognition: Box<[RecognitionStore]>,
}

impl Buffers {
    /// Storage for `sensors` (NaN until read: Webots' values before a first sample).
    pub(crate) fn new(sensors: &[Device]) -> Buffers {
        Buffers {
            slots: sensors
                .iter()
                .map(|d| Slot {
                    values: [f64::NAN; 4],
                    speed_vector: [f64::NAN; 3],
                    frequency: match d.settings() {
                        DeviceSettings::Lidar(s) => s.default_frequency,
                        _ => f64::NAN,
                    },
                    ..Slot::default()
                })
                .collect(),
            tables: sensors.iter().map(|d| table_of(d.settings())).collect(),
            roll_pitch_yaw: Box::new([f64::NAN; 3]),
            recognition: sensors
                .iter()
                .map(|_| RecognitionStore::default())
                .collect(),
        }
    }

    /// The storage of sensor `index`.
    pub(crate) fn slot(&mut self, index: usize) -> Option<&mut Slot> {
        self.slots.get_mut(index)
    }

    /// The recognition storage of sensor `index`.
    pub(crate) fn recognition(&mut self, index: usize) -> Option<&mut RecognitionStore> {
        self.recognition.get_mut(index)
    }

    /// The lookup table of sensor `index` (empty if none).
    pub(crate) fn table(&self, index: usize) -> &[f64] {
        self.tables.get(index).map_or(&[], |t| t)
    }
}

/// A three-axis or distance sensor's lookup table, row-major.
fn table_of(settings: &DeviceSettings) -> Box<[f64]> {
    match settings {
        DeviceSettings::Gyro(s) | DeviceSettings::Accelerometer(s) | DeviceSettings::Compass(s) => {
            s.lookup_table.rows().iter().flatten().copied().collect()
        }
        DeviceSettings::DistanceSensor(s) => {
            s.lookup_table.rows().iter().flatten().copied().collect()
        }
        DeviceSettings::Gps(_)
        | DeviceSettings::InertialUnit(_)
        | DeviceSettings::Camera(_)
        | DeviceSettings::Display(_)
        | DeviceSettings::Radar(_)
        | DeviceSettings::Lidar(_)
        | DeviceSettings::RoadSensor(_) => Box::new([]),
    }
}

/// The C name of a kind in function names: `wb_<prefix>_enable`.
pub(crate) fn prefix(kind: DeviceKind) -> &'static str {
    match kind {
        DeviceKind::Gps => "gps",
        DeviceKind::InertialUnit => "inertial_unit",
        DeviceKind::Gyro => "gyro",
        DeviceKind::Accelerometer => "accelerometer",
        DeviceKind::Compass => "compass",
        DeviceKind::Camera => "camera",
        DeviceKind::Display => "display",
        DeviceKind::DistanceSensor => "distance_sensor",
        DeviceKind::Radar => "radar",
        DeviceKind::Lidar => "lidar",
        DeviceKind::RoadSensor => "road_sensor",
    }
}

/// The prefix of a kind's C functions: `wb_<prefix>` for Webots' devices, the project's
/// `vehicle_road_sensor` for its RoadSensor extension.
pub(crate) fn function_prefix(kind: DeviceKind) -> String {
    match kind {
        DeviceKind::RoadSensor => "vehicle_road_sensor".to_string(),
        _ => format!("wb_{}", prefix(kind)),
    }
}

/// The car and sensor index of the `kind` sensor with `tag`, for `function`. Otherwise prints
/// Webots' messages: `Error: device with tag=<n> not found.` for a tag past the last, then
/// (when `report` is true) `Error: <function>(): invalid device tag.`
pub(crate) fn find(
    robot: &Robot,
    tag: WbDeviceTag,
    kind: DeviceKind,
    function: &str,
    report: bool,
) -> Option<(VehicleId, usize)> {
    if usize::from(tag) > robot.device_count() {
        message::error(format_args!("device with tag={tag} not found."));
    }
    let found = robot.sensor_of(tag).filter(|&(car, index)| {
        robot
            .simulation
            .devices(car)
            .is_ok_and(|d| d.get(index).is_some_and(|d| d.kind() == kind))
    });
    if found.is_none() && report {
        message::error(format_args!("{function}(): invalid device tag."));
    }
    found
}

/// The device of a found sensor.
pub(crate) fn device(robot: &Robot, (car, index): (VehicleId, usize)) -> Option<&Device> {
    robot.simulation.devices(car).ok()?.get(index)
}

/// `wb_<kind>_enable(tag, period)` (`function` is its name; also `wb_<kind>_disable` with 0):
/// a negative period is refused with Webots' error.
pub(crate) fn enable(
    robot: &mut Robot,
    kind: DeviceKind,
    function: &str,
    tag: WbDeviceTag,
    period_ms: c_int,
) {
    let Some(period) = message::sampling_period(period_ms, function) else {
        return;
    };
    if let Some((car, index)) = find(robot, tag, kind, function, true) {
        // The sensor was found on this car: enabling it cannot fail.
        let _ = robot.simulation.enable_device(car, index, period);
    }
}

/// `wb_<kind>_get_sampling_period(tag)`: the period (ms), 0 when disabled or for a wrong tag.
pub(crate) fn sampling_period(robot: &Robot, kind: DeviceKind, tag: WbDeviceTag) -> c_int {
    let function = format!("{}_get_sampling_period", function_prefix(kind));
    find(robot, tag, kind, &function, true)
        .and_then(|found| device(robot, found))
        .map_or(0, |d| c_int::try_from(d.period_ms()).unwrap_or(c_int::MAX))
}

/// The last sample of the `kind` sensor with `tag` for the getter `function`, with its index;
/// a disabled sensor prints Webots' error and still gives its last sample. `report`: whether a
/// wrong tag prints `invalid device tag` (the accelerometer's getter does not).
pub(crate) fn read(
    robot: &Robot,
    kind: DeviceKind,
    function: &str,
    tag: WbDeviceTag,
    report: bool,
) -> Option<(usize, Reading)> {
    let found = find(robot, tag, kind, function, report)?;
    let d = device(robot, found)?;
    if d.period_ms() == 0 {
        message::error(format_args!(
            "{function}() called for a disabled device! Please use: {}_enable().",
            function_prefix(kind)
        ));
    }
    Some((found.1, d.reading().clone()))
}
