//! `webots/vehicle/car.h`: the car library (`wbu_car_*`).
//!
//! Every function but `wbu_car_init` and `wbu_car_cleanup` needs the car library initialised
//! (by `wbu_car_init` or `wbu_driver_init`); otherwise it prints
//! `Warning: 'wbu_car_init()' should be called before to use '<function>()'.` and returns 0 or
//! false (setters do nothing). Units: m, rad (positive steers right), rad/s, s.

use std::ffi::c_int;

use vehicle_model::wheel_from_webots_index;

use crate::abi::c_bool;
use crate::message::{self, report};
use crate::session::{self, with_car, with_car_robot, with_car_state};

/// The wheel of a raw `WbuCarWheelIndex`, or `None` after Webots' warning
/// `Warning: maximum wheel index is 4.` (also for negative indices, which Webots reads
/// out of bounds).
fn wheel(index: c_int) -> Option<vehicle_model::Wheel> {
    match wheel_from_webots_index(i64::from(index)) {
        Ok(w) => Some(w),
        Err(w) => {
            message::warning(&w);
            None
        }
    }
}

entry_points! {
    /// Initialises the car library (and loads the world, `wb_robot_init`); further calls do
    /// nothing. The driven wheels are held at 0 rad/s until a control mode is chosen. A robot
    /// that is not a car prints `Error: Only nodes based on the 'Car' node can use the car
    /// library.` and ends the process with status 1. Webots: `wbu_car_init`.
    fn wbu_car_init() {
        session::init_car()
    }

    /// Frees the car and driver libraries and the simulation (`wb_robot_cleanup`). Webots:
    /// `wbu_car_cleanup`.
    fn wbu_car_cleanup() {
        session::cleanup()
    }

    /// Driven axle(s): 0 traction (front), 1 propulsion (rear), 2 four-by-four. Webots:
    /// `wbu_car_get_type`.
    fn wbu_car_get_type() -> c_int {
        with_car("wbu_car_get_type()", 0, |d| d.drive_type() as c_int)
    }

    /// Engine model: 0 combustion, 1 electric, 2 parallel hybrid, 3 power-split hybrid.
    /// Webots: `wbu_car_get_engine_type`.
    fn wbu_car_get_engine_type() -> c_int {
        with_car("wbu_car_get_engine_type()", 0, |d| d.engine_type() as c_int)
    }

    /// Sets the duration (s) of each on and each off phase of the indicators. NaN, ±∞, 0 and
    /// negative periods are refused with a warning (Webots stores them). Webots:
    /// `wbu_car_set_indicator_period`.
    fn wbu_car_set_indicator_period(period: f64) {
        with_car("wbu_car_set_indicator_period()", (), |d| report(d.set_indicator_period(period)))
    }

    /// The indicator period (s), 0.34 by default. Webots: `wbu_car_get_indicator_period`.
    fn wbu_car_get_indicator_period() -> f64 {
        with_car("wbu_car_get_indicator_period()", 0.0, |d| d.indicator_period())
    }

    /// State of the reversing lights (lit by the driver step in TORQUE mode with gear -1 and
    /// in SPEED mode with a negative cruising speed). Webots: `wbu_car_get_backwards_lights`.
    fn wbu_car_get_backwards_lights() -> u8 {
        with_car("wbu_car_get_backwards_lights()", 0, |d| c_bool(d.backwards_lights()))
    }

    /// State of the brake lights (lit while the brake intensity is above 0). Webots:
    /// `wbu_car_get_brake_lights`.
    fn wbu_car_get_brake_lights() -> u8 {
        with_car("wbu_car_get_brake_lights()", 0, |d| c_bool(d.brake_lights()))
    }

    /// Distance between the front wheels (m). Webots: `wbu_car_get_track_front`.
    fn wbu_car_get_track_front() -> f64 {
        with_car("wbu_car_get_track_front()", 0.0, |d| d.track_front())
    }

    /// Distance between the rear wheels (m). Webots: `wbu_car_get_track_rear`.
    fn wbu_car_get_track_rear() -> f64 {
        with_car("wbu_car_get_track_rear()", 0.0, |d| d.track_rear())
    }

    /// Distance between the axles (m). Webots: `wbu_car_get_wheelbase`.
    fn wbu_car_get_wheelbase() -> f64 {
        with_car("wbu_car_get_wheelbase()", 0.0, |d| d.wheelbase())
    }

    /// Front tyre radius (m). Webots: `wbu_car_get_front_wheel_radius`.
    fn wbu_car_get_front_wheel_radius() -> f64 {
        with_car("wbu_car_get_front_wheel_radius()", 0.0, |d| d.front_wheel_radius())
    }

    /// Rear tyre radius (m). Webots: `wbu_car_get_rear_wheel_radius`.
    fn wbu_car_get_rear_wheel_radius() -> f64 {
        with_car("wbu_car_get_rear_wheel_radius()", 0.0, |d| d.rear_wheel_radius())
    }

    /// Rotation of wheel `wheel_index` (rad, continuous, positive rolling forward): its
    /// position sensor after the last step (0 before the first step; Webots: NaN). An index
    /// outside 0..=3 prints `Warning: maximum wheel index is 4.` and returns 0. Webots:
    /// `wbu_car_get_wheel_encoder`.
    fn wbu_car_get_wheel_encoder(wheel_index: c_int) -> f64 {
        with_car_state("wbu_car_get_wheel_encoder()", 0.0, |s| {
            wheel(wheel_index).map_or(0.0, |w| s.wheel_angles[w])
        })
    }

    /// Rotation speed of wheel `wheel_index` (rad/s, positive rolling forward) measured by the
    /// last `wbu_driver_step` (0 before it can be measured and with the car library alone).
    /// Index check as `wbu_car_get_wheel_encoder`. Webots: `wbu_car_get_wheel_speed`.
    fn wbu_car_get_wheel_speed(wheel_index: c_int) -> f64 {
        with_car("wbu_car_get_wheel_speed()", 0.0, |d| {
            wheel(wheel_index).map_or(0.0, |w| d.wheel_speed(w))
        })
    }

    /// Steers the front left wheel to `angle` (rad, positive = right) at once, without
    /// Ackermann geometry and without changing the driver's steering angle. NaN and ±∞ are
    /// refused with a warning (Webots refuses NaN only). Webots:
    /// `wbu_car_set_left_steering_angle`.
    fn wbu_car_set_left_steering_angle(angle: f64) {
        with_car_robot("wbu_car_set_left_steering_angle()", (), |robot, id| {
            if let Ok(d) = robot.simulation.driver_mut(id) {
                report(d.set_left_steering_angle(angle));
            }
        })
    }

    /// Steers the front right wheel to `angle` (rad); see `wbu_car_set_left_steering_angle`.
    /// Webots: `wbu_car_set_right_steering_angle`.
    fn wbu_car_set_right_steering_angle(angle: f64) {
        with_car_robot("wbu_car_set_right_steering_angle()", (), |robot, id| {
            if let Ok(d) = robot.simulation.driver_mut(id) {
                report(d.set_right_steering_angle(angle));
            }
        })
    }

    /// Steering angle of the front right wheel (rad): its position sensor after the last step.
    /// Webots: `wbu_car_get_right_steering_angle`.
    fn wbu_car_get_right_steering_angle() -> f64 {
        with_car_state("wbu_car_get_right_steering_angle()", 0.0, |s| s.steering.right)
    }

    /// Steering angle of the front left wheel (rad): its position sensor after the last step.
    /// Webots: `wbu_car_get_left_steering_angle`.
    fn wbu_car_get_left_steering_angle() -> f64 {
        with_car_state("wbu_car_get_left_steering_angle()", 0.0, |s| s.steering.left)
    }

    /// Switches the limited-slip differential on (non-zero, the default) or off (0). Webots:
    /// `wbu_car_enable_limited_slip_differential`.
    fn wbu_car_enable_limited_slip_differential(enable: u8) {
        with_car("wbu_car_enable_limited_slip_differential()", (), |d| {
            d.enable_limited_slip_differential(enable != 0)
        })
    }

    /// Switches the indicator auto-cancelling on (non-zero, the default) or off (0). Webots:
    /// `wbu_car_enable_indicator_auto_disabling`.
    fn wbu_car_enable_indicator_auto_disabling(enable: u8) {
        with_car("wbu_car_enable_indicator_auto_disabling()", (), |d| {
            d.enable_indicator_auto_disabling(enable != 0)
        })
    }
}
