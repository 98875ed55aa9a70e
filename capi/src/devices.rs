//! Device names and tags (`wb_robot_get_device`).
//!
//! A tag identifies a device of the world's robot; 0 means "no such device". Tags are the
//! 1-based position of the name in a fixed table per robot kind, so a device has the same tag
//! in every world and every run.

use vehicle_model::{CarParams, DriveType};

use crate::abi::WbDeviceTag;

/// The devices of a car (Webots car library, spec §1.5), in tag order.
const CAR_DEVICES: [&str; 27] = [
    "right_steer",
    "left_steer",
    "right_steer_sensor",
    "left_steer_sensor",
    "right_front_wheel",
    "left_front_wheel",
    "right_rear_wheel",
    "left_rear_wheel",
    "right_front_sensor",
    "left_front_sensor",
    "right_rear_sensor",
    "left_rear_sensor",
    "right_front_brake",
    "left_front_brake",
    "right_rear_brake",
    "left_rear_brake",
    "front_lights",
    "antifog_lights",
    "right_indicators",
    "left_indicators",
    "rear_lights",
    "backwards_lights",
    "brake_lights",
    "engine_speaker",
    "right_wiper_motor",
    "left_wiper_motor",
    "wiper_sensor",
];

/// The two wheels of a DifferentialWheels robot (Webots: its `Solid` children).
const DIFFERENTIAL_WHEELS_DEVICES: [&str; 2] = ["left wheel", "right wheel"];

/// The tag of device `name` of a car with parameters `params`, 0 if it has none.
///
/// Every car has the steering motors and sensors, the four wheel sensors and brakes, the
/// `VehicleLights` LEDs and the `engine_speaker`; the wheel motors of its driven axle(s); the
/// wiper motors and sensor if the model has wipers.
pub(crate) fn car_device(params: &CarParams<f64>, name: &str) -> WbDeviceTag {
    let front = params.drive_type != DriveType::Propulsion;
    let rear = params.drive_type != DriveType::Traction;
    let wipers = params.wipers.is_some();
    let present = match name {
        "right_front_wheel" | "left_front_wheel" => front,
        "right_rear_wheel" | "left_rear_wheel" => rear,
        "right_wiper_motor" | "left_wiper_motor" | "wiper_sensor" => wipers,
        _ => true,
    };
    if present { tag(&CAR_DEVICES, name) } else { 0 }
}

/// The tag of device `name` of a DifferentialWheels robot, 0 if it has none.
pub(crate) fn differential_wheels_device(name: &str) -> WbDeviceTag {
    tag(&DIFFERENTIAL_WHEELS_DEVICES, name)
}

/// 1 + the position of `name` in `table`, 0 if absent.
fn tag(table: &[&str], name: &str) -> WbDeviceTag {
    table
        .iter()
        .position(|n| *n == name)
        .and_then(|i| WbDeviceTag::try_from(i + 1).ok())
        .unwrap_or(0)
}

#[cfg(test)]
mod tests {
    use super::*;
    use vehicle_model::Model;

    #[test]
    fn car_devices_follow_the_model() {
        let bmw = Model::BmwX5.params::<f64>(); // traction, with wipers
        assert_eq!(car_device(&bmw, "right_steer"), 1);
        assert_eq!(car_device(&bmw, "left_steer"), 2);
        assert_eq!(car_device(&bmw, "right_front_wheel"), 5);
        assert_eq!(car_device(&bmw, "right_rear_wheel"), 0);
        assert_eq!(car_device(&bmw, "engine_speaker"), 24);
        assert_eq!(car_device(&bmw, "wiper_sensor"), 27);
        assert_eq!(car_device(&bmw, "no such device"), 0);
        assert_eq!(car_device(&bmw, "left wheel"), 0);
        assert_eq!(car_device(&bmw, ""), 0);
        let tesla = Model::TeslaModel3.params::<f64>(); // propulsion
        assert_eq!(car_device(&tesla, "right_front_wheel"), 0);
        assert_eq!(car_device(&tesla, "left_rear_wheel"), 8);
        let mut four = Model::Car.params::<f64>();
        four.drive_type = DriveType::FourByFour;
        four.wipers = None;
        assert_eq!(car_device(&four, "left_front_wheel"), 6);
        assert_eq!(car_device(&four, "right_rear_wheel"), 7);
        assert_eq!(car_device(&four, "right_wiper_motor"), 0);
    }

    #[test]
    fn differential_wheels_devices() {
        assert_eq!(differential_wheels_device("left wheel"), 1);
        assert_eq!(differential_wheels_device("right wheel"), 2);
        assert_eq!(differential_wheels_device("right_steer"), 0);
    }
}
