//! `WebotsNative`, robot part: `wb_robot_*` (the battery sensor's included), `wb_keyboard_*` and `wb_device_*` for
//! `com.cyberbotics.webots.controller.Robot`, `Keyboard` and `Device`. Times in s, steps in ms.

use std::ffi::{CStr, c_char};

use jni::JNIEnv;
use jni::objects::JString;
use jni::sys::{jdouble, jint, jstring};

use crate::tag;

natives! { "com_cyberbotics_webots_controller_WebotsNative";
    /// `wb_robot_init`: loads the world `VEHICLE_WORLD` names (exits with its error otherwise).
    fn robotInit(env) -> jint => car::wb_robot_init();
    /// `wb_robot_cleanup`: writes `VEHICLE_OUT`'s outputs and frees the simulation.
    fn robotCleanup(env) => car::wb_robot_cleanup();
    /// `wb_robot_step` (ms): 0, or -1 once the world's duration has elapsed.
    fn robotStep(env, duration: jint) -> jint => car::wb_robot_step(duration);
    /// `wb_robot_get_time` (s).
    fn robotGetTime(env) -> jdouble => car::wb_robot_get_time();
    /// `wb_robot_get_basic_time_step` (ms).
    fn robotGetBasicTimeStep(env) -> jdouble => car::wb_robot_get_basic_time_step();
    /// `wb_robot_get_number_of_devices`.
    fn robotGetNumberOfDevices(env) -> jint => car::wb_robot_get_number_of_devices();
    /// `wb_robot_get_device_by_index`: the tag, 0 for an index out of range.
    fn robotGetDeviceByIndex(env, index: jint) -> jint => jint::from(car::wb_robot_get_device_by_index(index));
    /// `wb_robot_get_device`: the tag of the device `name`, 0 if the robot has none.
    fn robotGetDevice(env, name: JString<'_>) -> jint => device_by_name(&mut env, &name);
    /// `wb_robot_battery_sensor_enable` (ms).
    fn robotBatterySensorEnable(env, period: jint) => car::wb_robot_battery_sensor_enable(period);
    /// `wb_robot_battery_sensor_disable`.
    fn robotBatterySensorDisable(env) => car::wb_robot_battery_sensor_disable();
    /// `wb_robot_battery_sensor_get_sampling_period` (ms).
    fn robotBatterySensorGetSamplingPeriod(env) -> jint => car::wb_robot_battery_sensor_get_sampling_period();
    /// `wb_robot_battery_sensor_get_value` (J; NaN before the first sample and without a battery).
    fn robotBatterySensorGetValue(env) -> jdouble => car::wb_robot_battery_sensor_get_value();
    /// `wb_keyboard_enable` (ms).
    fn keyboardEnable(env, period: jint) => car::wb_keyboard_enable(period);
    /// `wb_keyboard_disable`.
    fn keyboardDisable(env) => car::wb_keyboard_disable();
    /// `wb_keyboard_get_sampling_period` (ms).
    fn keyboardGetSamplingPeriod(env) -> jint => car::wb_keyboard_get_sampling_period();
    /// `wb_keyboard_get_key`: the next key pressed (with modifier bits), -1 when none is left.
    fn keyboardGetKey(env) -> jint => car::wb_keyboard_get_key();
    /// `wb_device_get_node_type` (`WB_NODE_*`).
    fn deviceGetNodeType(env, device: jint) -> jint => car::wb_device_get_node_type(tag(device));
    /// `wb_device_get_name`; `null` for a wrong tag.
    fn deviceGetName(env, device: jint) -> jstring => java_string(&mut env, car::wb_device_get_name(tag(device)));
    /// `wb_device_get_model`; `null` for a wrong tag.
    fn deviceGetModel(env, device: jint) -> jstring => java_string(&mut env, car::wb_device_get_model(tag(device)));
}

/// The tag `wb_robot_get_device` gives for a Java string; 0 for `null` or a name with a NUL
/// character (neither can name a device).
fn device_by_name(env: &mut JNIEnv<'_>, name: &JString<'_>) -> jint {
    let Some(name) = crate::c_string(env, name) else {
        return 0;
    };
    // SAFETY: a NUL-terminated string that lives until the call returns.
    jint::from(unsafe { car::wb_robot_get_device(name.as_ptr()) })
}

/// A new Java string from a C API string result; `null` for NULL.
fn java_string(env: &mut JNIEnv<'_>, text: *const c_char) -> jstring {
    if text.is_null() {
        return std::ptr::null_mut();
    }
    // SAFETY: a non-NULL result is a NUL-terminated string in the robot's storage, valid until
    // the robot is freed, which the one controller thread cannot do during this call.
    let text = unsafe { CStr::from_ptr(text) }.to_string_lossy();
    env.new_string(text)
        .map_or(std::ptr::null_mut(), JString::into_raw)
}
