//! `webots/robot.h`: the part of the Webots robot API every controller uses.
//!
//! Any of these functions loads the world first if `wb_robot_init` has not been called (Webots
//! requires that call first). Time is in s, durations and time steps in ms.

use std::ffi::{CStr, c_char, c_int};

use crate::abi::WbDeviceTag;
use crate::message;
use crate::session::{self, with_robot};

entry_points! {
    /// Loads the world named by `VEHICLE_WORLD` (a world file path or a shipped model name;
    /// unset: the default world, a BmwX5 on flat ground with `basicTimeStep` 10 ms). Further
    /// calls do nothing. Returns 1. An invalid world prints what is wrong and ends the process
    /// with status 1. Webots: `wb_robot_init`.
    fn wb_robot_init() -> c_int {
        with_robot(|_| 1)
    }

    /// Advances the simulation by `duration` ms, rounded up to whole basic time steps, keeping
    /// the commands in force (the driver library does not run: use `wbu_driver_step`).
    /// Returns 0, or -1 once the world's `duration` has elapsed (or the physics failed). A
    /// negative duration advances nothing, with a warning. Webots: `wb_robot_step`.
    fn wb_robot_step(duration: c_int) -> c_int {
        with_robot(|robot| {
            let step_ms = u64::from(robot.basic_time_step_ms().max(1));
            let steps = match u64::try_from(duration) {
                Ok(ms) => ms.div_ceil(step_ms),
                Err(_) => {
                    eprintln!(
                        "Warning: wb_robot_step() called with a negative duration ({duration} ms); \
                         the simulation does not advance."
                    );
                    0
                }
            };
            robot.advance(steps)
        })
    }

    /// Simulated time in s since the world was loaded. Webots: `wb_robot_get_time`.
    fn wb_robot_get_time() -> f64 {
        with_robot(|robot| robot.time())
    }

    /// The world's `basicTimeStep` in ms. Webots: `wb_robot_get_basic_time_step`.
    fn wb_robot_get_basic_time_step() -> f64 {
        with_robot(|robot| f64::from(robot.basic_time_step_ms()))
    }

    /// Frees the simulation; the car and driver libraries are uninitialised afterwards. Does
    /// nothing if no world is loaded. Webots: `wb_robot_cleanup`.
    fn wb_robot_cleanup() {
        session::cleanup()
    }
}

/// The tag of the robot's device `name` (e.g. `"right_steer"`, `"engine_speaker"`, or
/// `"left wheel"` on a DifferentialWheels robot), 0 if it has none or `name` is null or not
/// UTF-8. Tags are stable: the same name gives the same tag in every world. Webots:
/// `wb_robot_get_device`, with its messages: `Error: wb_robot_get_device() called with NULL
/// or empty argument.` for a null or empty name, `Warning: "<name>" device not found.` for a
/// name no device has.
///
/// # Safety
/// `name` is null or points to a NUL-terminated string that stays valid during the call.
#[unsafe(no_mangle)]
pub unsafe extern "C" fn wb_robot_get_device(name: *const c_char) -> WbDeviceTag {
    crate::guard::call("wb_robot_get_device", move || {
        // SAFETY: non-null, and the caller guarantees a NUL-terminated string valid for the
        // duration of the call; it is only read.
        let name = (!name.is_null()).then(|| unsafe { CStr::from_ptr(name) });
        let Some(name) = name.filter(|n| !n.is_empty()) else {
            message::error("wb_robot_get_device() called with NULL or empty argument.");
            return 0;
        };
        let tag = match name.to_str() {
            Ok(name) => with_robot(|robot| robot.device(name)),
            Err(_) => 0,
        };
        if tag == 0 {
            eprintln!("Warning: \"{}\" device not found.", name.to_string_lossy());
        }
        tag
    })
}
