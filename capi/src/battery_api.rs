//! `webots/robot.h`'s battery sensor: the energy left in the robot's battery (J), sampled by
//! `sim::battery_sensor`. A car's battery is its traction battery when its world file accounts
//! its energy (`battery = [energy, maxEnergy, chargingRate]`, `[vehicle.battery]` or
//! `energy = true`); a DifferentialWheels robot has none here and reads NaN.

use std::ffi::c_int;

use sim::battery_sensor::BatterySensor;

use crate::message;
use crate::robot::{Body, Robot};
use crate::session::with_robot;

/// The robot's battery sensor: its car's, or the DifferentialWheels robot's own.
fn sensor(robot: &Robot) -> BatterySensor {
    match robot.body() {
        Body::Car { id, .. } => robot
            .simulation
            .battery_sensor(id)
            .copied()
            .unwrap_or_default(),
        Body::DifferentialWheels(_) => robot.controller().robot_battery,
    }
}

/// Enables the sensor with `period_ms` (0 disables); a negative period is refused with
/// Webots' error naming `function`.
fn enable(robot: &mut Robot, period_ms: c_int, function: &str) {
    let Some(period) = message::sampling_period(period_ms, function) else {
        return;
    };
    match robot.body() {
        Body::Car { id, .. } => {
            // The robot's own car: it exists.
            let _ = robot.simulation.enable_battery_sensor(id, period);
        }
        Body::DifferentialWheels(_) => {
            let now_ms = robot.simulation.world().time_ms();
            robot.controller_mut().robot_battery.enable(period, now_ms);
        }
    }
}

entry_points! {
    /// Samples the battery's energy every `sampling_period` ms. Webots:
    /// `wb_robot_battery_sensor_enable`.
    fn wb_robot_battery_sensor_enable(sampling_period: c_int) {
        with_robot(|r| enable(r, sampling_period, "wb_robot_battery_sensor_enable"))
    }

    /// Stops sampling the battery. Webots: `wb_robot_battery_sensor_disable`.
    fn wb_robot_battery_sensor_disable() {
        with_robot(|r| enable(r, 0, "wb_robot_battery_sensor_disable"))
    }

    /// The sensor's period (ms), 0 when disabled. Webots:
    /// `wb_robot_battery_sensor_get_sampling_period`.
    fn wb_robot_battery_sensor_get_sampling_period() -> c_int {
        with_robot(|r| c_int::try_from(sensor(r).period_ms()).unwrap_or(c_int::MAX))
    }

    /// The battery's energy at the last sample (J); NaN before the first sample and without
    /// a battery. Disabled: Webots' error, and the last reading. Webots:
    /// `wb_robot_battery_sensor_get_value`.
    fn wb_robot_battery_sensor_get_value() -> f64 {
        with_robot(|r| {
            let s = sensor(r);
            if s.period_ms() == 0 {
                message::error(
                    "wb_robot_battery_sensor_get_value() called for a disabled device! Please \
                     use: wb_robot_battery_sensor_enable().",
                );
            }
            s.value()
        })
    }
}
