//! Device names, tags and node types (`wb_robot_get_device`, `webots/device.h`).
//!
//! A tag identifies a device of the world's robot; 0 means "no such device". A car's tags are
//! first the 1-based positions of its car-library devices in a fixed table
//! ([`sim::devices::CAR_DEVICE_NAMES`]: the same tag in every world and run; the devices a
//! model lacks leave holes), then its world-file sensors in file order. A DifferentialWheels
//! robot's are its two wheels.

use std::ffi::CString;

use sim::devices::{CAR_DEVICE_NAMES, DeviceKind};
use vehicle_model::{CarParams, DriveType};

use crate::abi::WbDeviceTag;

/// The two wheels of a DifferentialWheels robot (Webots: its `Solid` children).
const DIFFERENTIAL_WHEELS_DEVICES: [&str; 2] = ["left wheel", "right wheel"];

/// The number of tags of a car's fixed table; its sensors' tags follow.
pub(crate) const CAR_TAGS: usize = CAR_DEVICE_NAMES.len();

/// `WbNodeType` values (`webots/nodes.h`, R2023b numbering) of the devices there are.
pub(crate) mod node {
    /// `WB_NODE_NO_NODE`.
    pub(crate) const NO_NODE: i32 = 0;
    /// `WB_NODE_ACCELEROMETER`.
    pub(crate) const ACCELEROMETER: i32 = 35;
    /// `WB_NODE_BRAKE`.
    pub(crate) const BRAKE: i32 = 37;
    /// `WB_NODE_CAMERA`.
    pub(crate) const CAMERA: i32 = 38;
    /// `WB_NODE_COMPASS`.
    pub(crate) const COMPASS: i32 = 39;
    /// `WB_NODE_DISPLAY`.
    pub(crate) const DISPLAY: i32 = 41;
    /// `WB_NODE_DISTANCE_SENSOR`.
    pub(crate) const DISTANCE_SENSOR: i32 = 42;
    /// `WB_NODE_GPS`.
    pub(crate) const GPS: i32 = 44;
    /// `WB_NODE_GYRO`.
    pub(crate) const GYRO: i32 = 45;
    /// `WB_NODE_INERTIAL_UNIT`.
    pub(crate) const INERTIAL_UNIT: i32 = 46;
    /// `WB_NODE_LED`.
    pub(crate) const LED: i32 = 47;
    /// `WB_NODE_LIDAR`.
    pub(crate) const LIDAR: i32 = 48;
    /// `WB_NODE_POSITION_SENSOR`.
    pub(crate) const POSITION_SENSOR: i32 = 52;
    /// `WB_NODE_RADAR`.
    pub(crate) const RADAR: i32 = 54;
    /// `WB_NODE_ROTATIONAL_MOTOR`.
    pub(crate) const ROTATIONAL_MOTOR: i32 = 57;
    /// `WB_NODE_SPEAKER`.
    pub(crate) const SPEAKER: i32 = 59;
    /// `WB_NODE_SOLID`.
    pub(crate) const SOLID: i32 = 80;
    /// `VEHICLE_NODE_ROAD_SENSOR` (`webots/vehicle/road_sensor.h`): the project's RoadSensor,
    /// which no Webots node type names; 1000, far past Webots' numbering.
    pub(crate) const VEHICLE_ROAD_SENSOR: i32 = 1000;
}

/// The node type of a sensor of `kind`.
pub(crate) fn sensor_node_type(kind: DeviceKind) -> i32 {
    match kind {
        DeviceKind::Gps => node::GPS,
        DeviceKind::InertialUnit => node::INERTIAL_UNIT,
        DeviceKind::Gyro => node::GYRO,
        DeviceKind::Accelerometer => node::ACCELEROMETER,
        DeviceKind::Compass => node::COMPASS,
        DeviceKind::Camera => node::CAMERA,
        DeviceKind::Display => node::DISPLAY,
        DeviceKind::DistanceSensor => node::DISTANCE_SENSOR,
        DeviceKind::Radar => node::RADAR,
        DeviceKind::Lidar => node::LIDAR,
        DeviceKind::RoadSensor => node::VEHICLE_ROAD_SENSOR,
    }
}

/// The node type of the car-library device `name` (the Car PROTO's motors, position sensors,
/// brakes, LEDs and speaker).
fn car_node_type(name: &str) -> i32 {
    if name.ends_with("_sensor") {
        node::POSITION_SENSOR
    } else if name.ends_with("_brake") {
        node::BRAKE
    } else if name.ends_with("_lights") || name.ends_with("_indicators") {
        node::LED
    } else if name == "engine_speaker" {
        node::SPEAKER
    } else {
        node::ROTATIONAL_MOTOR
    }
}

/// True if a car with parameters `params` has the car-library device `name` (every car has
/// the steering motors and sensors, the wheel sensors and brakes, the lights and the speaker;
/// the wheel motors of its driven axle(s); the wiper motors and sensor if it has wipers).
fn car_has(params: &CarParams<f64>, name: &str) -> bool {
    let front = params.drive_type != DriveType::Propulsion;
    let rear = params.drive_type != DriveType::Traction;
    match name {
        "right_front_wheel" | "left_front_wheel" => front,
        "right_rear_wheel" | "left_rear_wheel" => rear,
        "right_wiper_motor" | "left_wiper_motor" | "wiper_sensor" => params.wipers.is_some(),
        _ => true,
    }
}

/// A device of the robot, for `webots/device.h`: its name (NUL-terminated, library storage)
/// and node type; `None` in the table for a car-library device the model lacks.
pub(crate) struct DeviceEntry {
    pub(crate) name: CString,
    pub(crate) node_type: i32,
}

/// The devices of a car with parameters `params` and sensors `sensors` (name and kind), in tag
/// order (tag = index + 1).
pub(crate) fn car_table(
    params: &CarParams<f64>,
    sensors: impl Iterator<Item = (String, DeviceKind)>,
) -> Vec<Option<DeviceEntry>> {
    let car = CAR_DEVICE_NAMES.iter().map(|&name| {
        car_has(params, name).then(|| DeviceEntry {
            name: c_string(name),
            node_type: car_node_type(name),
        })
    });
    let sensors = sensors.map(|(name, kind)| {
        Some(DeviceEntry {
            name: c_string(&name),
            node_type: sensor_node_type(kind),
        })
    });
    car.chain(sensors).collect()
}

/// The devices of a DifferentialWheels robot, in tag order.
pub(crate) fn differential_wheels_table() -> Vec<Option<DeviceEntry>> {
    DIFFERENTIAL_WHEELS_DEVICES
        .iter()
        .map(|&name| {
            Some(DeviceEntry {
                name: c_string(name),
                node_type: node::SOLID,
            })
        })
        .collect()
}

/// `name` as a C string; the world file's names hold no NUL (TOML strings may: cut there).
fn c_string(name: &str) -> CString {
    let bytes: Vec<u8> = name.bytes().take_while(|&b| b != 0).collect();
    CString::new(bytes).unwrap_or_default()
}

/// The tag of device `name` in `table`, 0 if absent.
pub(crate) fn tag_of(table: &[Option<DeviceEntry>], name: &str) -> WbDeviceTag {
    table
        .iter()
        .position(|e| {
            e.as_ref()
                .is_some_and(|e| e.name.as_bytes() == name.as_bytes())
        })
        .and_then(|i| WbDeviceTag::try_from(i + 1).ok())
        .unwrap_or(0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use vehicle_model::Model;

    #[test]
    fn car_devices_follow_the_model() {
        let none = std::iter::empty();
        let bmw = car_table(&Model::BmwX5.params::<f64>(), none); // traction, with wipers
        assert_eq!(tag_of(&bmw, "right_steer"), 1);
        assert_eq!(tag_of(&bmw, "left_steer"), 2);
        assert_eq!(tag_of(&bmw, "right_front_wheel"), 5);
        assert_eq!(tag_of(&bmw, "right_rear_wheel"), 0);
        assert_eq!(tag_of(&bmw, "engine_speaker"), 24);
        assert_eq!(tag_of(&bmw, "wiper_sensor"), 27);
        assert_eq!(tag_of(&bmw, "no such device"), 0);
        assert_eq!(tag_of(&bmw, "left wheel"), 0);
        assert_eq!(tag_of(&bmw, ""), 0);
        let tesla = car_table(&Model::TeslaModel3.params::<f64>(), std::iter::empty());
        assert_eq!(tag_of(&tesla, "right_front_wheel"), 0);
        assert_eq!(tag_of(&tesla, "left_rear_wheel"), 8);
        let mut four = Model::Car.params::<f64>();
        four.drive_type = DriveType::FourByFour;
        four.wipers = None;
        let sensors = [("gps".to_string(), DeviceKind::Gps)].into_iter();
        let four = car_table(&four, sensors);
        assert_eq!(tag_of(&four, "left_front_wheel"), 6);
        assert_eq!(tag_of(&four, "right_rear_wheel"), 7);
        assert_eq!(tag_of(&four, "right_wiper_motor"), 0);
        assert_eq!(tag_of(&four, "gps"), 28);
        let node_type = |tag: usize| four[tag - 1].as_ref().map(|e| e.node_type);
        assert_eq!(node_type(1), Some(node::ROTATIONAL_MOTOR));
        assert_eq!(node_type(3), Some(node::POSITION_SENSOR));
        assert_eq!(node_type(13), Some(node::BRAKE));
        assert_eq!(node_type(17), Some(node::LED));
        assert_eq!(node_type(24), Some(node::SPEAKER));
        assert_eq!(node_type(25), None);
        assert_eq!(node_type(28), Some(node::GPS));
    }

    #[test]
    fn differential_wheels_devices() {
        let table = differential_wheels_table();
        assert_eq!(tag_of(&table, "left wheel"), 1);
        assert_eq!(tag_of(&table, "right wheel"), 2);
        assert_eq!(tag_of(&table, "right_steer"), 0);
    }
}
