//! `webots/keyboard.h`: the keys the world's programme presses for the controller
//! (`[[vehicle.programme]] key = "A"`), sampled by `sim::keyboard`.

use std::ffi::c_int;

use sim::keyboard::Keyboard;

use crate::message;
use crate::robot::{Body, Robot};
use crate::session::with_robot;

/// The keyboard of the robot: its car's, or the DifferentialWheels robot's own.
fn period(robot: &Robot) -> u32 {
    match robot.body() {
        Body::Car { id, .. } => robot.simulation.keyboard(id).map_or(0, Keyboard::period_ms),
        Body::DifferentialWheels(_) => robot.controller().robot_keyboard.period_ms(),
    }
}

/// Enables the keyboard with `period_ms` (0 disables); a negative period is refused with
/// Webots' error naming `function`.
fn enable(robot: &mut Robot, period_ms: c_int, function: &str) {
    let Some(period) = message::sampling_period(period_ms, function) else {
        return;
    };
    match robot.body() {
        Body::Car { id, .. } => {
            // The robot's own car: it exists.
            let _ = robot.simulation.enable_keyboard(id, period);
        }
        Body::DifferentialWheels(_) => {
            let now_ms = robot.simulation.world().time_ms();
            robot.controller_mut().robot_keyboard.enable(period, now_ms);
        }
    }
}

entry_points! {
    /// Samples the keys every `sampling_period` ms. Webots: `wb_keyboard_enable`.
    fn wb_keyboard_enable(sampling_period: c_int) {
        with_robot(|r| enable(r, sampling_period, "wb_keyboard_enable"))
    }

    /// Stops sampling the keys. Webots: `wb_keyboard_disable`.
    fn wb_keyboard_disable() {
        with_robot(|r| enable(r, 0, "wb_keyboard_disable"))
    }

    /// The keyboard's period (ms), 0 when disabled. Webots: `wb_keyboard_get_sampling_period`.
    fn wb_keyboard_get_sampling_period() -> c_int {
        with_robot(|r| c_int::try_from(period(r)).unwrap_or(c_int::MAX))
    }

    /// The next key of the last sample (ASCII or `WB_KEYBOARD_*`, with the modifier bits), −1
    /// when none is left; −1 with Webots' error while disabled. Webots: `wb_keyboard_get_key`.
    fn wb_keyboard_get_key() -> c_int {
        with_robot(|r| {
            if period(r) == 0 {
                message::error(
                    "wb_keyboard_get_key() called for a disabled device! Please use: \
                     wb_keyboard_enable().",
                );
                return -1;
            }
            match r.body() {
                Body::Car { id, .. } => r.simulation.next_key(id).unwrap_or(-1),
                Body::DifferentialWheels(_) => r.controller_mut().robot_keyboard.next_key(),
            }
        })
    }
}
