//! `webots/vehicle/driver.h`: the driver library, exported from `libcar` under the internal
//! names `vehicle_capi_driver_*` and re-exported as `wbu_driver_*` by `libdriver` (a C shim,
//! `capi/driver/driver.c`), so that each library has its own Webots symbols and linking both
//! never defines a symbol twice.
//!
//! Every function but init, cleanup and `initialization_is_possible` needs `wbu_driver_init`
//! first; otherwise it prints `Warning: 'wbu_driver_init()' should be called before to use
//! '<function>()'.` and returns 0, false, `OFF`, `UNDEFINED_CONTROL_MODE` or, for the wiper
//! mode, -1 (setters do nothing). Units: rad (positive steers right), km/h, rpm, s.

use std::ffi::c_int;

use vehicle_model::{ControlMode, IndicatorState, Warning, WiperMode};

use crate::abi::c_bool;
use crate::message::{self, report};
use crate::session::{self, with_driver, with_driver_robot, with_robot};

entry_points! {
    /// `wbu_driver_initialization_is_possible` (and the older `initialization_is_possible`):
    /// loads the world (`wb_robot_init`) and returns 1 if its robot is a car, 0 otherwise.
    fn vehicle_capi_driver_initialization_is_possible() -> u8 {
        with_robot(|robot| c_bool(robot.is_car()))
    }

    /// `wbu_driver_init`: initialises the car library, then the driver library (no-op if
    /// already done). Exits with status 1 if the robot is not a car.
    fn vehicle_capi_driver_init() {
        session::init_driver()
    }

    /// `wbu_driver_cleanup`: frees the driver and car libraries and the simulation.
    fn vehicle_capi_driver_cleanup() {
        session::cleanup()
    }

    /// `wbu_driver_step`: runs the driver library's step and advances the simulation by one
    /// `basicTimeStep`. Returns 0, or -1 once the world's `duration` has elapsed. Before
    /// `wbu_driver_init` it warns and returns 0 without stepping.
    fn vehicle_capi_driver_step() -> c_int {
        with_driver_robot("wbu_driver_step()", 0, |robot, _| robot.driver_step())
    }

    /// `wbu_driver_set_steering_angle`: Ackermann steering to `steering_angle` rad (positive =
    /// right), applied to the steering motors at once. NaN (Webots' warning) and ±∞ are
    /// refused.
    fn vehicle_capi_driver_set_steering_angle(steering_angle: f64) {
        with_driver_robot("wbu_driver_set_steering_angle()", (), |robot, id| {
            if let Ok(d) = robot.simulation.driver_mut(id) {
                report(d.set_steering_angle(steering_angle));
            }
        })
    }

    /// `wbu_driver_get_steering_angle`: the mean of the two front steering sensors (rad) after
    /// the last step.
    fn vehicle_capi_driver_get_steering_angle() -> f64 {
        with_driver_robot("wbu_driver_get_steering_angle()", 0.0, |robot, id| {
            robot
                .simulation
                .world()
                .vehicle(id)
                .map_or(0.0, |v| v.state().steering.mean())
        })
    }

    /// `wbu_driver_set_cruising_speed`: SPEED mode at `speed` km/h (negative: backwards).
    /// NaN and ±∞ are refused with a warning.
    fn vehicle_capi_driver_set_cruising_speed(speed: f64) {
        with_driver("wbu_driver_set_cruising_speed()", (), |d| report(d.set_cruising_speed(speed)))
    }

    /// `wbu_driver_get_target_cruising_speed`: the last cruising speed set (km/h).
    fn vehicle_capi_driver_get_target_cruising_speed() -> f64 {
        with_driver("wbu_driver_get_target_cruising_speed()", 0.0, |d| d.target_cruising_speed())
    }

    /// `wbu_driver_get_current_speed`: the speed estimated from the driven wheels (km/h).
    fn vehicle_capi_driver_get_current_speed() -> f64 {
        with_driver("wbu_driver_get_current_speed()", 0.0, |d| d.current_speed())
    }

    /// `wbu_driver_set_throttle`: TORQUE mode with throttle in [0, 1] (clamped with Webots'
    /// warnings; NaN refused).
    fn vehicle_capi_driver_set_throttle(throttle: f64) {
        with_driver("wbu_driver_set_throttle()", (), |d| report(d.set_throttle(throttle)))
    }

    /// `wbu_driver_get_throttle`: the stored throttle.
    fn vehicle_capi_driver_get_throttle() -> f64 {
        with_driver("wbu_driver_get_throttle()", 0.0, |d| d.throttle())
    }

    /// `wbu_driver_set_brake_intensity`: brake in [0, 1] (clamped with Webots' warnings; NaN
    /// refused); lights the brake lights iff above 0.
    fn vehicle_capi_driver_set_brake_intensity(intensity: f64) {
        with_driver("wbu_driver_set_brake_intensity()", (), |d| {
            report(d.set_brake_intensity(intensity))
        })
    }

    /// `wbu_driver_get_brake_intensity`: the stored brake intensity.
    fn vehicle_capi_driver_get_brake_intensity() -> f64 {
        with_driver("wbu_driver_get_brake_intensity()", 0.0, |d| d.brake_intensity())
    }

    /// `wbu_driver_set_indicator`: 0 OFF, 1 RIGHT, 2 LEFT; other values are refused with a
    /// warning (Webots stores them).
    fn vehicle_capi_driver_set_indicator(state: c_int) {
        with_driver("wbu_driver_set_indicator()", (), |d| {
            match IndicatorState::try_from_webots_value(state) {
                Ok(s) => d.set_indicator(s),
                Err(w) => message::warning(&w),
            }
        })
    }

    /// `wbu_driver_set_hazard_flashers`: any non-zero byte switches them on.
    fn vehicle_capi_driver_set_hazard_flashers(state: u8) {
        with_driver("wbu_driver_set_hazard_flashers()", (), |d| d.set_hazard_flashers(state != 0))
    }

    /// `wbu_driver_get_indicator`: 0 OFF, 1 RIGHT, 2 LEFT.
    fn vehicle_capi_driver_get_indicator() -> c_int {
        with_driver("wbu_driver_get_indicator()", 0, |d| d.indicator().webots_value())
    }

    /// `wbu_driver_get_hazard_flashers`: 1 if on. (Webots names this function without
    /// parentheses in its warning.)
    fn vehicle_capi_driver_get_hazard_flashers() -> u8 {
        with_driver("wbu_driver_get_hazard_flashers", 0, |d| c_bool(d.hazard_flashers()))
    }

    /// `wbu_driver_set_dipped_beams`: front and rear lights together.
    fn vehicle_capi_driver_set_dipped_beams(state: u8) {
        with_driver("wbu_driver_set_dipped_beams()", (), |d| d.set_dipped_beams(state != 0))
    }

    /// `wbu_driver_set_antifog_lights`.
    fn vehicle_capi_driver_set_antifog_lights(state: u8) {
        with_driver("wbu_driver_set_antifog_lights()", (), |d| d.set_antifog_lights(state != 0))
    }

    /// `wbu_driver_get_dipped_beams`: the stored state.
    fn vehicle_capi_driver_get_dipped_beams() -> u8 {
        with_driver("wbu_driver_get_dipped_beams()", 0, |d| c_bool(d.dipped_beams()))
    }

    /// `wbu_driver_get_antifog_lights`: the LED state.
    fn vehicle_capi_driver_get_antifog_lights() -> u8 {
        with_driver("wbu_driver_get_antifog_lights()", 0, |d| c_bool(d.antifog_lights()))
    }

    /// `wbu_driver_get_rpm`: the engine speed estimated at the last step (rpm); in SPEED mode
    /// Webots' warning and 0.
    fn vehicle_capi_driver_get_rpm() -> f64 {
        with_driver("wbu_driver_get_rpm()", 0.0, |d| {
            d.rpm().unwrap_or_else(|w| {
                message::warning(&w);
                0.0
            })
        })
    }

    /// `wbu_driver_get_gear`: -1 reverse, 0 neutral, k forward; in SPEED mode Webots' warning
    /// and 0.
    fn vehicle_capi_driver_get_gear() -> c_int {
        with_driver("wbu_driver_get_gear()", 0, |d| match d.gear() {
            Ok(g) => g.number(),
            Err(w) => {
                message::warning(&w);
                0
            }
        })
    }

    /// `wbu_driver_set_gear`: clamped to -1 ..= gear_number - 1, with Webots' warnings above
    /// gear_number and below -1. Exactly gear_number (which Webots accepts silently, reading
    /// past its ratio table) engages gear_number - 1 silently.
    fn vehicle_capi_driver_set_gear(gear: c_int) {
        with_driver("wbu_driver_set_gear()", (), |d| {
            let warning = d.set_gear(gear);
            let webots_accepts = usize::try_from(gear).is_ok_and(|g| g == d.gear_number());
            if !webots_accepts {
                report(warning);
            }
        })
    }

    /// `wbu_driver_get_gear_number`: entries of `gearRatio`, reverse included.
    fn vehicle_capi_driver_get_gear_number() -> c_int {
        with_driver("wbu_driver_get_gear_number()", 0, |d| {
            c_int::try_from(d.gear_number()).unwrap_or(c_int::MAX)
        })
    }

    /// `wbu_driver_get_control_mode`: -1 undefined, 0 SPEED, 1 TORQUE.
    fn vehicle_capi_driver_get_control_mode() -> c_int {
        with_driver(
            "wbu_driver_get_control_mode()",
            ControlMode::Undefined.webots_value(),
            |d| d.control_mode().webots_value(),
        )
    }

    /// `wbu_driver_set_wiper_mode`: 0 DOWN, 1 SLOW, 2 NORMAL, 3 FAST (ignored by a car
    /// without wipers); other values are refused with a warning (Webots stores them).
    fn vehicle_capi_driver_set_wiper_mode(mode: c_int) {
        with_driver("wbu_driver_set_wiper_mode()", (), |d| set_wiper_mode(d, mode))
    }

    /// `wbu_driver_get_wiper_mode`: 0 DOWN to 3 FAST; -1 before `wbu_driver_init`.
    fn vehicle_capi_driver_get_wiper_mode() -> c_int {
        with_driver("wbu_driver_get_wiper_mode()", -1, |d| d.wiper_mode().webots_value())
    }

    /// `wbu_driver_set_brake` (deprecated in Webots 8.6): Webots' deprecation warning, then
    /// `wbu_driver_set_brake_intensity`.
    fn vehicle_capi_driver_set_brake(brake: f64) {
        message::warning(&Warning::Deprecated {
            function: "wbu_driver_set_brake",
            replacement: "wbu_driver_set_brake_intensity",
        });
        vehicle_capi_driver_set_brake_intensity(brake)
    }

    /// `wbu_driver_get_brake` (deprecated in Webots 8.6): Webots' deprecation warning, then
    /// `wbu_driver_get_brake_intensity`.
    fn vehicle_capi_driver_get_brake() -> f64 {
        message::warning(&Warning::Deprecated {
            function: "wbu_driver_get_brake",
            replacement: "wbu_driver_get_brake_intensity",
        });
        vehicle_capi_driver_get_brake_intensity()
    }

    /// `wbu_driver_set_indicator_warning` (the Webots 2014 name of the hazard flashers): same
    /// as `wbu_driver_set_hazard_flashers`, silently.
    fn vehicle_capi_driver_set_indicator_warning(state: u8) {
        vehicle_capi_driver_set_hazard_flashers(state)
    }

    /// `wbu_driver_set_wipers_mode` (deprecated in R2018a): same as
    /// `wbu_driver_set_wiper_mode`, silently as in Webots' C library.
    fn vehicle_capi_driver_set_wipers_mode(mode: c_int) {
        vehicle_capi_driver_set_wiper_mode(mode)
    }

    /// `wbu_driver_get_wipers_mode` (deprecated in R2018a): same as
    /// `wbu_driver_get_wiper_mode`, silently.
    fn vehicle_capi_driver_get_wipers_mode() -> c_int {
        vehicle_capi_driver_get_wiper_mode()
    }
}

/// Sets the wiper mode from a raw `WbuDriverWiperMode`, refusing values outside 0..=3.
fn set_wiper_mode(d: &mut vehicle_model::Driver<f64>, mode: c_int) {
    match WiperMode::try_from_webots_value(mode) {
        Ok(m) => d.set_wiper_mode(m),
        Err(w) => message::warning(&w),
    }
}
