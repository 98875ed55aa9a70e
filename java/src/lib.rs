//! The native half of the Java binding: `libvehicle_java.so`, loaded by the classes of
//! `com.cyberbotics.webots.controller` and `com.cyberbotics.webots.controller.vehicle`
//! (`java/src/com/...`, packed into `vehicle.jar` by `capi/stage.sh`).
//!
//! Every native method is a thin marshalling of one function of the C API (`capi`, linked as
//! an rlib): `Driver.setCruisingSpeed(20.0)` is `wbu_driver_set_cruising_speed(20.0)`, so the
//! warnings on stderr, the clamping, the world selection (`VEHICLE_WORLD`) and the outputs
//! (`VEHICLE_OUT`) are the C API's own. Nothing here measures or decides anything: scalars
//! pass through unchanged (Java `boolean` is the C API's one-byte `bool`, `int` its `int`,
//! `double` its `double`), device tags are Java `int`s (a value outside the C API's
//! `WbDeviceTag` range becomes tag 0, which the C API refuses with its own warning), and the
//! arrays the C API returns are copied into new Java arrays (`null` where C returns NULL).
//!
//! The native methods are static methods of two package-private classes, `WebotsNative`
//! (robot and devices, `robot.rs`, `sensors.rs`, `display.rs`, `recognition.rs`, `point_cloud.rs`) and `VehicleNative` (driver and car,
//! `vehicle.rs`); the public Java classes wrap them with Webots' names and signatures.
//! Like Webots' controller library, the API is for one controller thread.

// JNI needs `unsafe`: the exported symbols carry `#[unsafe(export_name)]`, and the C API's
// device lookup and name results are C strings. Arrays come from the C API's Rust twins of
// its pointer getters (`car::values`, `car::lidar_values`), so no C array is read here.
#![allow(unsafe_code)]

use std::ffi::{CString, c_char};

use jni::JNIEnv;
use jni::objects::JString;
use jni::sys::{jdoubleArray, jfloatArray, jint, jintArray, jsize};

/// Defines JNI entry points of one Java class: each `fn name(args) -> ret => body;` becomes
/// `Java_<class>_<name>`, a static native method (`JNIEnv` and `jclass` first), whose body is
/// usually one C API call.
macro_rules! natives {
    ($class:literal; $( $(#[$doc:meta])* fn $name:ident($env:ident $(, $arg:ident: $ty:ty)*) $(-> $ret:ty)? => $body:expr; )*) => {
        $(
            $(#[$doc])*
            #[allow(non_snake_case, unused_mut, unused_variables)]
            #[unsafe(export_name = concat!("Java_", $class, "_", stringify!($name)))]
            pub extern "system" fn $name(
                mut $env: jni::JNIEnv<'_>,
                _class: jni::objects::JClass<'_>,
                $($arg: $ty),*
            ) $(-> $ret)? {
                $body
            }
        )*
    };
}

pub(crate) mod display;
pub(crate) mod point_cloud;
pub(crate) mod recognition;
pub(crate) mod robot;
pub(crate) mod sensors;
pub(crate) mod vehicle;

/// A Java device tag as the C API's `WbDeviceTag`; tag 0 (no device: the C API warns) when it
/// does not fit.
fn tag(tag: jint) -> car::WbDeviceTag {
    car::WbDeviceTag::try_from(tag).unwrap_or(0)
}

/// A Java array length for `len` items (an error past `jsize`'s range, which no device
/// reaches).
fn java_len(len: usize) -> jni::errors::Result<jsize> {
    jsize::try_from(len)
        .map_err(|_| jni::errors::Error::JniCall(jni::errors::JniError::InvalidArguments))
}

/// A new Java `double[]` holding `values`; `null` for `None` or when the JVM cannot allocate
/// it (an `OutOfMemoryError` is then pending in Java).
fn double_array(env: &mut JNIEnv<'_>, values: Option<&[f64]>) -> jdoubleArray {
    let Some(values) = values else {
        return std::ptr::null_mut();
    };
    let Ok(len) = jsize::try_from(values.len()) else {
        return std::ptr::null_mut();
    };
    match env.new_double_array(len) {
        Ok(array) if env.set_double_array_region(&array, 0, values).is_ok() => array.into_raw(),
        _ => std::ptr::null_mut(),
    }
}

/// A new Java `float[]` holding `values`; `null` for `None` or when the JVM cannot allocate
/// it.
fn float_array(env: &mut JNIEnv<'_>, values: Option<&[f32]>) -> jfloatArray {
    let Some(values) = values else {
        return std::ptr::null_mut();
    };
    let Ok(len) = jsize::try_from(values.len()) else {
        return std::ptr::null_mut();
    };
    match env.new_float_array(len) {
        Ok(array) if env.set_float_array_region(&array, 0, values).is_ok() => array.into_raw(),
        _ => std::ptr::null_mut(),
    }
}

/// A new Java `int[]` holding `values`; `null` for `None` or when the JVM cannot allocate it.
fn int_array(env: &mut JNIEnv<'_>, values: Option<&[i32]>) -> jintArray {
    let Some(values) = values else {
        return std::ptr::null_mut();
    };
    let Ok(len) = jsize::try_from(values.len()) else {
        return std::ptr::null_mut();
    };
    match env.new_int_array(len) {
        Ok(array) if env.set_int_array_region(&array, 0, values).is_ok() => array.into_raw(),
        _ => std::ptr::null_mut(),
    }
}

/// A Java string as a C string; `None` (the C API's NULL, which it refuses with its own
/// error or ignores as Webots does) for `null` or a string holding a NUL character.
fn c_string(env: &mut JNIEnv<'_>, text: &JString<'_>) -> Option<CString> {
    if text.is_null() {
        return None;
    }
    let text = env.get_string(text).ok()?;
    CString::new(String::from(text)).ok()
}

/// The pointer of `text`, NULL for `None`.
fn c_ptr(text: Option<&CString>) -> *const c_char {
    text.map_or(std::ptr::null(), |t| t.as_ptr())
}
