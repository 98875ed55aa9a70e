//! The Webots-compatible C API of the vehicle simulator: `libcar.so` (this crate, lib name
//! `car`) and `libdriver.so` (a C shim over it), with the headers of `capi/include`.
//!
//! A Webots car controller written in C or C++ runs unchanged against these libraries (Python
//! controllers run on the Python package, whose `vehicle` module calls these functions):
//! `wbu_driver_init()`, a `while (wbu_driver_step() != -1)` loop of `wbu_driver_*` and
//! `wbu_car_*` calls, `wbu_driver_cleanup()`. The robot it drives is the car of a world file
//! (or the DifferentialWheels robot of one), simulated by the `sim` crate on rapier3d; the
//! driver and car libraries' logic is `vehicle_model::Driver`. The world is chosen by the
//! environment variable `VEHICLE_WORLD` when the robot is initialised: a world file path or a
//! shipped model name (`VEHICLE_WORLD=ToyotaPrius`); unset means the default world, a BmwX5 on
//! flat ground with `basicTimeStep` 10 ms.
//!
//! Exported functions (see the headers for the full contracts):
//!
//! * `webots/robot.h`: `wb_robot_init`, `wb_robot_step`, `wb_robot_get_time`,
//!   `wb_robot_get_basic_time_step`, `wb_robot_cleanup`, `wb_robot_get_device`;
//! * `webots/vehicle/car.h`: every `wbu_car_*` function;
//! * `webots/vehicle/driver.h`: every `wbu_driver_*` function (and the old names
//!   `wbu_driver_set_brake`, `..._get_brake`, `..._set_wipers_mode`, `..._get_wipers_mode`,
//!   `..._set_indicator_warning`, `initialization_is_possible`), exported by `libdriver` and
//!   implemented here as `vehicle_capi_driver_*`;
//! * `webots/differential_wheels.h`: every `wb_differential_wheels_*` function;
//! * `webots/gps.h`, `webots/inertial_unit.h`, `webots/gyro.h`, `webots/accelerometer.h`,
//!   `webots/compass.h`: the sensors a world file puts on the car (`[[vehicle.device]]`),
//!   measured by `sim::devices`; `webots/device.h` and `wb_robot_get_number_of_devices`,
//!   `wb_robot_get_device_by_index` to list the robot's devices;
//! * `webots/distance_sensor.h`, `webots/radar.h` (`WbRadarTarget`), `webots/lidar.h`
//!   (`WbLidarPoint`): the ray devices (`sim::devices::rays`);
//! * `webots/camera.h` and `webots/camera_recognition_object.h`: the camera and its
//!   Recognition, rendered by `sim::devices::camera`;
//! * `webots/display.h`: drawing into a car's `Display` (`sim::devices::display`);
//! * `webots/keyboard.h`: the keys the world's programme presses (`sim::keyboard`).
//!
//! Arguments and results follow the C ABI of the headers: C `bool` is one byte (any non-zero
//! value is true; results are 0 or 1), enumerations are `int` (out-of-range values are refused
//! with a warning), floating-point values are `double`. Warnings and errors are printed on
//! stderr with Webots' texts. No panic crosses the C boundary: every entry point catches it,
//! prints an error and returns 0.
//!
//! Build and install the libraries, headers and pkg-config file with `capi/stage.sh PREFIX`
//! (see the crate README). The Rust items are the same functions, callable from Rust for
//! testing:
//!
//! ```
//! // The default world: a BmwX5 (unless VEHICLE_WORLD names another world).
//! # unsafe { std::env::remove_var("VEHICLE_WORLD") };
//! car::vehicle_capi_driver_init(); // wbu_driver_init()
//! assert_eq!(car::wbu_car_get_wheelbase(), 2.995); // m
//! car::vehicle_capi_driver_set_cruising_speed(20.0); // km/h
//! for _ in 0..300 {
//!     assert_eq!(car::vehicle_capi_driver_step(), 0); // 10 ms each
//! }
//! assert!((car::wb_robot_get_time() - 3.0).abs() < 1e-9); // s
//! // 20 km/h on 0.374 m tyres is 14.85 rad/s.
//! let speed = car::wbu_car_get_wheel_speed(0); // front right, rad/s
//! assert!((speed - 20.0 / 3.6 / 0.374).abs() < 0.3, "{speed}");
//! car::vehicle_capi_driver_cleanup();
//! ```

// FFI needs `unsafe`: the exported symbols are `#[unsafe(no_mangle)]`, and
// `wb_robot_get_device` reads the C string it is given. Everything else is safe code.
#![allow(unsafe_code)]

#[macro_use]
mod guard;

mod abi;
mod battery_api;
mod camera_api;
mod car_api;
mod controller;
pub mod controllers;
mod device_api;
mod devices;
mod differential_wheels_api;
mod display_api;
mod distance_sensor_api;
mod driver_api;
mod keyboard_api;
mod lidar_api;
mod message;
mod radar_api;
mod road_sensor_api;
mod robot;
mod robot_api;
mod sensor;
mod sensor_api;
mod session;
pub mod supervisor;

pub use abi::WbDeviceTag;
pub use battery_api::*;
pub use camera_api::*;
pub use car_api::*;
pub use device_api::*;
pub use differential_wheels_api::*;
pub use display_api::*;
pub use distance_sensor_api::*;
pub use driver_api::*;
pub use keyboard_api::*;
pub use lidar_api::*;
pub use radar_api::*;
pub use road_sensor_api::*;
pub use robot::WORLD_VARIABLE;
pub use robot_api::*;
pub use sensor::WbRadarTarget;
pub use sensor_api::*;
pub use session::load_world;
pub use sim::devices::LidarPoint as WbLidarPoint;
