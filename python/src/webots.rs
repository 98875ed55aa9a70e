//! The Webots C API, callable from Python under its C names.
//!
//! Each function forwards to the `capi` crate's entry point of the same name (the driver
//! functions are `vehicle_capi_driver_*` there, as `libdriver` re-exports them): the session,
//! the warnings on stderr and the neutral values before initialisation are the C library's own.
//! C `bool` arguments and results are `int` 0/1 here; the Python modules convert (as Webots'
//! ctypes binding does). Only `wb_robot_init` differs: a world that cannot be loaded raises
//! `WorldError` instead of ending the process.

use pyo3::prelude::*;

use crate::WorldError;

/// Defines one `#[pyfunction]` per line, forwarding its arguments to `target`, and
/// `add_forwarded` registering them all.
macro_rules! forward {
    ($( $(#[$doc:meta])* fn $name:ident($($arg:ident: $ty:ty),*) $(-> $ret:ty)? = $target:path; )*) => {
        $(
            $(#[$doc])*
            #[pyfunction]
            fn $name($($arg: $ty),*) $(-> $ret)? {
                $target($($arg),*)
            }
        )*

        /// Adds every forwarded function to `m`.
        fn add_forwarded(m: &Bound<'_, PyModule>) -> PyResult<()> {
            $( m.add_function(wrap_pyfunction!($name, m)?)?; )*
            Ok(())
        }
    };
}

forward! {
    /// Advances `duration` ms rounded up to whole steps without the driver library; 0, or -1
    /// once the world's duration has elapsed.
    fn wb_robot_step(duration: i32) -> i32 = car::wb_robot_step;
    /// Simulated time (s).
    fn wb_robot_get_time() -> f64 = car::wb_robot_get_time;
    /// The world's basicTimeStep (ms).
    fn wb_robot_get_basic_time_step() -> f64 = car::wb_robot_get_basic_time_step;
    /// Frees the robot; the next call that needs it reloads the world at t = 0.
    fn wb_robot_cleanup() = car::wb_robot_cleanup;
    /// Samples the battery's energy every `period` ms (0 disables; negative: Webots' error).
    fn wb_robot_battery_sensor_enable(period: i32) = car::wb_robot_battery_sensor_enable;
    /// Stops sampling the battery.
    fn wb_robot_battery_sensor_disable() = car::wb_robot_battery_sensor_disable;
    /// The battery sensor's period (ms), 0 when disabled.
    fn wb_robot_battery_sensor_get_sampling_period() -> i32 =
        car::wb_robot_battery_sensor_get_sampling_period;
    /// The battery's energy at the last sample (J); NaN before it and without a battery.
    fn wb_robot_battery_sensor_get_value() -> f64 = car::wb_robot_battery_sensor_get_value;

    /// 1 if the world's robot is a car.
    fn wbu_driver_initialization_is_possible() -> u8 =
        car::vehicle_capi_driver_initialization_is_possible;
    /// Initialises the car and driver libraries.
    fn wbu_driver_init() = car::vehicle_capi_driver_init;
    /// Frees the libraries and the robot.
    fn wbu_driver_cleanup() = car::vehicle_capi_driver_cleanup;
    /// One driver step and one basicTimeStep of physics; 0, or -1 at the end.
    fn wbu_driver_step() -> i32 = car::vehicle_capi_driver_step;
    /// Steering angle (rad, positive right).
    fn wbu_driver_set_steering_angle(steering_angle: f64) =
        car::vehicle_capi_driver_set_steering_angle;
    /// Steering angle (rad).
    fn wbu_driver_get_steering_angle() -> f64 = car::vehicle_capi_driver_get_steering_angle;
    /// Cruising speed (km/h); selects SPEED mode.
    fn wbu_driver_set_cruising_speed(speed: f64) = car::vehicle_capi_driver_set_cruising_speed;
    /// Target cruising speed (km/h).
    fn wbu_driver_get_target_cruising_speed() -> f64 =
        car::vehicle_capi_driver_get_target_cruising_speed;
    /// Speed estimated from the driven wheels (km/h).
    fn wbu_driver_get_current_speed() -> f64 = car::vehicle_capi_driver_get_current_speed;
    /// Throttle (0 to 1); selects TORQUE mode.
    fn wbu_driver_set_throttle(throttle: f64) = car::vehicle_capi_driver_set_throttle;
    /// Throttle (0 to 1).
    fn wbu_driver_get_throttle() -> f64 = car::vehicle_capi_driver_get_throttle;
    /// Brake intensity (0 to 1).
    fn wbu_driver_set_brake_intensity(intensity: f64) =
        car::vehicle_capi_driver_set_brake_intensity;
    /// Brake intensity (0 to 1).
    fn wbu_driver_get_brake_intensity() -> f64 = car::vehicle_capi_driver_get_brake_intensity;
    /// Indicator: 0 OFF, 1 RIGHT, 2 LEFT.
    fn wbu_driver_set_indicator(state: i32) = car::vehicle_capi_driver_set_indicator;
    /// Indicator: 0 OFF, 1 RIGHT, 2 LEFT.
    fn wbu_driver_get_indicator() -> i32 = car::vehicle_capi_driver_get_indicator;
    /// Hazard flashers (0/1).
    fn wbu_driver_set_hazard_flashers(state: u8) = car::vehicle_capi_driver_set_hazard_flashers;
    /// Hazard flashers (0/1).
    fn wbu_driver_get_hazard_flashers() -> u8 = car::vehicle_capi_driver_get_hazard_flashers;
    /// Dipped beams (0/1).
    fn wbu_driver_set_dipped_beams(state: u8) = car::vehicle_capi_driver_set_dipped_beams;
    /// Dipped beams (0/1).
    fn wbu_driver_get_dipped_beams() -> u8 = car::vehicle_capi_driver_get_dipped_beams;
    /// Antifog lights (0/1).
    fn wbu_driver_set_antifog_lights(state: u8) = car::vehicle_capi_driver_set_antifog_lights;
    /// Antifog lights (0/1).
    fn wbu_driver_get_antifog_lights() -> u8 = car::vehicle_capi_driver_get_antifog_lights;
    /// Engine speed (rpm).
    fn wbu_driver_get_rpm() -> f64 = car::vehicle_capi_driver_get_rpm;
    /// Engaged gear (-1 reverse, 0 neutral, 1.. forward).
    fn wbu_driver_get_gear() -> i32 = car::vehicle_capi_driver_get_gear;
    /// Gear (-1 reverse, 0 neutral, 1.. forward).
    fn wbu_driver_set_gear(gear: i32) = car::vehicle_capi_driver_set_gear;
    /// Entries of gearRatio, reverse included.
    fn wbu_driver_get_gear_number() -> i32 = car::vehicle_capi_driver_get_gear_number;
    /// -1 undefined, 0 SPEED, 1 TORQUE.
    fn wbu_driver_get_control_mode() -> i32 = car::vehicle_capi_driver_get_control_mode;
    /// Wiper mode: 0 DOWN, 1 SLOW, 2 NORMAL, 3 FAST.
    fn wbu_driver_set_wiper_mode(mode: i32) = car::vehicle_capi_driver_set_wiper_mode;
    /// Wiper mode: 0 DOWN to 3 FAST.
    fn wbu_driver_get_wiper_mode() -> i32 = car::vehicle_capi_driver_get_wiper_mode;

    /// 0 traction, 1 propulsion, 2 four-by-four.
    fn wbu_car_get_type() -> i32 = car::wbu_car_get_type;
    /// 0 combustion, 1 electric, 2 parallel hybrid, 3 power-split hybrid.
    fn wbu_car_get_engine_type() -> i32 = car::wbu_car_get_engine_type;
    /// Indicator period (s).
    fn wbu_car_set_indicator_period(period: f64) = car::wbu_car_set_indicator_period;
    /// Indicator period (s).
    fn wbu_car_get_indicator_period() -> f64 = car::wbu_car_get_indicator_period;
    /// Reversing lights (0/1).
    fn wbu_car_get_backwards_lights() -> u8 = car::wbu_car_get_backwards_lights;
    /// Brake lights (0/1).
    fn wbu_car_get_brake_lights() -> u8 = car::wbu_car_get_brake_lights;
    /// Front track (m).
    fn wbu_car_get_track_front() -> f64 = car::wbu_car_get_track_front;
    /// Rear track (m).
    fn wbu_car_get_track_rear() -> f64 = car::wbu_car_get_track_rear;
    /// Wheelbase (m).
    fn wbu_car_get_wheelbase() -> f64 = car::wbu_car_get_wheelbase;
    /// Front tyre radius (m).
    fn wbu_car_get_front_wheel_radius() -> f64 = car::wbu_car_get_front_wheel_radius;
    /// Rear tyre radius (m).
    fn wbu_car_get_rear_wheel_radius() -> f64 = car::wbu_car_get_rear_wheel_radius;
    /// Wheel rotation (rad) of wheel 0 FR, 1 FL, 2 RR, 3 RL.
    fn wbu_car_get_wheel_encoder(wheel_index: i32) -> f64 = car::wbu_car_get_wheel_encoder;
    /// Wheel speed (rad/s) of wheel 0 FR, 1 FL, 2 RR, 3 RL.
    fn wbu_car_get_wheel_speed(wheel_index: i32) -> f64 = car::wbu_car_get_wheel_speed;
    /// Front left steering angle (rad).
    fn wbu_car_set_left_steering_angle(angle: f64) = car::wbu_car_set_left_steering_angle;
    /// Front right steering angle (rad).
    fn wbu_car_set_right_steering_angle(angle: f64) = car::wbu_car_set_right_steering_angle;
    /// Front right steering angle (rad), measured.
    fn wbu_car_get_right_steering_angle() -> f64 = car::wbu_car_get_right_steering_angle;
    /// Front left steering angle (rad), measured.
    fn wbu_car_get_left_steering_angle() -> f64 = car::wbu_car_get_left_steering_angle;
    /// Limited-slip differential on (1) or off (0).
    fn wbu_car_enable_limited_slip_differential(enable: u8) =
        car::wbu_car_enable_limited_slip_differential;
    /// Indicator auto-cancelling on (1) or off (0).
    fn wbu_car_enable_indicator_auto_disabling(enable: u8) =
        car::wbu_car_enable_indicator_auto_disabling;
}

/// Loads the world named by `VEHICLE_WORLD` (a world file or a model name; unset: the default
/// world) unless a robot is loaded, as `wb_robot_init` does; a world that cannot be loaded
/// raises `WorldError` with the file, line and key instead of ending the process.
#[pyfunction]
fn wb_robot_init() -> PyResult<()> {
    car::load_world().map_err(WorldError::new_err)
}

/// The tag of the robot's device `name`, 0 if it has none (`wb_robot_get_device`).
#[pyfunction]
fn wb_robot_get_device(name: &str) -> u16 {
    // A name with a NUL byte cannot name a device (nor be passed to C).
    match std::ffi::CString::new(name) {
        // SAFETY: the pointer is a NUL-terminated string that lives until the call returns.
        #[allow(unsafe_code)]
        Ok(c) => unsafe { car::wb_robot_get_device(c.as_ptr()) },
        Err(_) => 0,
    }
}

/// Runs `wbu_driver_step` `steps` times from Rust and returns the wall-clock time they took
/// (s): the benchmark `python/bench/driver_step.py` times the same steps through
/// `Driver.step()` in the same process, so that the difference is the cost of the Python call.
#[pyfunction]
fn bench_driver_steps(steps: u64) -> f64 {
    let start = std::time::Instant::now();
    for _ in 0..steps {
        car::vehicle_capi_driver_step();
    }
    start.elapsed().as_secs_f64()
}

/// Adds the Webots functions to the module.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    add_forwarded(m)?;
    m.add_function(wrap_pyfunction!(wb_robot_init, m)?)?;
    m.add_function(wrap_pyfunction!(wb_robot_get_device, m)?)?;
    m.add_function(wrap_pyfunction!(bench_driver_steps, m)?)?;
    Ok(())
}
