//! `webots/device.h` and the device enumeration of `webots/robot.h`.

use std::ffi::{c_char, c_int};

use crate::abi::WbDeviceTag;
use crate::devices::node;
use crate::guard::call_pointer;
use crate::message;
use crate::session::with_robot;

entry_points! {
    /// The number of devices of the robot (its own tag 0 excluded): a car's fixed table of
    /// car-library devices, then its sensors. Webots: `wb_robot_get_number_of_devices`.
    fn wb_robot_get_number_of_devices() -> c_int {
        with_robot(|r| c_int::try_from(r.device_count()).unwrap_or(c_int::MAX))
    }

    /// The tag of device `index` (`index + 1`); out of range: Webots' error and 0. Webots:
    /// `wb_robot_get_device_by_index`.
    fn wb_robot_get_device_by_index(index: c_int) -> WbDeviceTag {
        with_robot(|r| {
            match usize::try_from(index).ok().filter(|&i| i < r.device_count()) {
                Some(i) => WbDeviceTag::try_from(i + 1).unwrap_or(0),
                None => {
                    message::error(
                        "The index of wb_robot_get_device_by_index() is out of the bounds.",
                    );
                    0
                }
            }
        })
    }

    /// The device's node type (`WbNodeType`), `WB_NODE_NO_NODE` for a tag the robot does not
    /// have. Webots: `wb_device_get_node_type`.
    fn wb_device_get_node_type(tag: WbDeviceTag) -> c_int {
        with_robot(|r| r.device_entry(tag).map_or(node::NO_NODE, |e| e.node_type))
    }
}

/// The device's name (library storage), NULL for a tag the robot does not have. Webots:
/// `wb_device_get_name`.
#[unsafe(no_mangle)]
pub extern "C" fn wb_device_get_name(tag: WbDeviceTag) -> *const c_char {
    call_pointer("wb_device_get_name", || {
        with_robot(|r| r.device_entry(tag).map(|e| e.name.as_ptr()))
    })
}

/// The device's `model` field: `""` for every device here; NULL for a tag the robot does not
/// have. Webots: `wb_device_get_model`.
#[unsafe(no_mangle)]
pub extern "C" fn wb_device_get_model(tag: WbDeviceTag) -> *const c_char {
    call_pointer("wb_device_get_model", || {
        with_robot(|r| r.device_entry(tag).map(|_| c"".as_ptr()))
    })
}
