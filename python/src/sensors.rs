//! The sensor functions of the Webots C API (`webots/gps.h`, `inertial_unit.h`, `gyro.h`,
//! `accelerometer.h`, `compass.h`, `device.h`) for the Python `controller` module, and the
//! enabling of every sensor (the ray devices' other functions are in `ray_sensors`).
//!
//! Scalar functions are the C entry points themselves; those whose C result is a pointer call
//! the C API's Rust twins (`car::values`), which print the same messages and return the
//! values (`None` where C returns NULL). The measurements are the engine's (`sim::devices`).

use pyo3::prelude::*;
use sim::devices::DeviceKind;

/// Three-axis sensor kinds by the name the Python module passes.
fn triaxial(kind: &str) -> PyResult<DeviceKind> {
    match kind {
        "gyro" => Ok(DeviceKind::Gyro),
        "accelerometer" => Ok(DeviceKind::Accelerometer),
        "compass" => Ok(DeviceKind::Compass),
        other => Err(pyo3::exceptions::PyValueError::new_err(format!(
            "kind must be 'gyro', 'accelerometer' or 'compass', not {other:?}"
        ))),
    }
}

/// Enables (period in ms; 0 disables, negative: Webots' error) the sensor `kind` ("gps",
/// "inertial_unit", "gyro", "accelerometer", "compass", "distance_sensor", "radar", "lidar")
/// with `tag`.
#[pyfunction]
fn sensor_enable(kind: &str, tag: u16, period: i32) -> PyResult<()> {
    match kind {
        "gps" => car::wb_gps_enable(tag, period),
        "inertial_unit" => car::wb_inertial_unit_enable(tag, period),
        "distance_sensor" => car::wb_distance_sensor_enable(tag, period),
        "radar" => car::wb_radar_enable(tag, period),
        "lidar" => car::wb_lidar_enable(tag, period),
        _ => match triaxial(kind)? {
            DeviceKind::Gyro => car::wb_gyro_enable(tag, period),
            DeviceKind::Accelerometer => car::wb_accelerometer_enable(tag, period),
            _ => car::wb_compass_enable(tag, period),
        },
    }
    Ok(())
}

/// Disables the sensor `kind` with `tag`.
#[pyfunction]
fn sensor_disable(kind: &str, tag: u16) -> PyResult<()> {
    match kind {
        "gps" => car::wb_gps_disable(tag),
        "inertial_unit" => car::wb_inertial_unit_disable(tag),
        "distance_sensor" => car::wb_distance_sensor_disable(tag),
        "radar" => car::wb_radar_disable(tag),
        "lidar" => car::wb_lidar_disable(tag),
        _ => match triaxial(kind)? {
            DeviceKind::Gyro => car::wb_gyro_disable(tag),
            DeviceKind::Accelerometer => car::wb_accelerometer_disable(tag),
            _ => car::wb_compass_disable(tag),
        },
    }
    Ok(())
}

/// The sampling period (ms) of the sensor `kind` with `tag`, 0 when disabled.
#[pyfunction]
fn sensor_get_sampling_period(kind: &str, tag: u16) -> PyResult<i32> {
    Ok(match kind {
        "gps" => car::wb_gps_get_sampling_period(tag),
        "inertial_unit" => car::wb_inertial_unit_get_sampling_period(tag),
        "distance_sensor" => car::wb_distance_sensor_get_sampling_period(tag),
        "radar" => car::wb_radar_get_sampling_period(tag),
        "lidar" => car::wb_lidar_get_sampling_period(tag),
        _ => match triaxial(kind)? {
            DeviceKind::Gyro => car::wb_gyro_get_sampling_period(tag),
            DeviceKind::Accelerometer => car::wb_accelerometer_get_sampling_period(tag),
            _ => car::wb_compass_get_sampling_period(tag),
        },
    })
}

/// The values (rad/s, m/s², unitless) of the gyro, accelerometer or compass with `tag`.
#[pyfunction]
fn triaxial_get_values(kind: &str, tag: u16) -> PyResult<Option<[f64; 3]>> {
    Ok(car::values::triaxial_values(triaxial(kind)?, tag))
}

/// The lookup table (flat, 3 values per row) of the gyro, accelerometer or compass with `tag`.
#[pyfunction]
fn triaxial_get_lookup_table(kind: &str, tag: u16) -> PyResult<Vec<f64>> {
    Ok(car::values::triaxial_lookup_table(triaxial(kind)?, tag).unwrap_or_default())
}

/// The GPS position (m).
#[pyfunction]
fn wb_gps_get_values(tag: u16) -> Option<[f64; 3]> {
    car::values::wb_gps_get_values(tag)
}

/// The GPS speed (m/s).
#[pyfunction]
fn wb_gps_get_speed(tag: u16) -> f64 {
    car::wb_gps_get_speed(tag)
}

/// The GPS velocity (m/s).
#[pyfunction]
fn wb_gps_get_speed_vector(tag: u16) -> Option<[f64; 3]> {
    car::values::wb_gps_get_speed_vector(tag)
}

/// Always 0 (local coordinates).
#[pyfunction]
fn wb_gps_get_coordinate_system(tag: u16) -> i32 {
    car::wb_gps_get_coordinate_system(tag)
}

/// "D° M′ S″" of a decimal angle (degrees).
#[pyfunction]
fn wb_gps_convert_to_degrees_minutes_seconds(decimal_degrees: f64) -> String {
    car::values::wb_gps_convert_to_degrees_minutes_seconds(decimal_degrees)
}

/// Roll, pitch, yaw (rad).
#[pyfunction]
fn wb_inertial_unit_get_roll_pitch_yaw(tag: u16) -> [f64; 3] {
    car::values::wb_inertial_unit_get_roll_pitch_yaw(tag)
}

/// The quaternion [x, y, z, w].
#[pyfunction]
fn wb_inertial_unit_get_quaternion(tag: u16) -> Option<[f64; 4]> {
    car::values::wb_inertial_unit_get_quaternion(tag)
}

/// The inertial unit's noise field.
#[pyfunction]
fn wb_inertial_unit_get_noise(tag: u16) -> f64 {
    car::wb_inertial_unit_get_noise(tag)
}

/// The number of devices (car-library tags, then sensors).
#[pyfunction]
fn wb_robot_get_number_of_devices() -> i32 {
    car::wb_robot_get_number_of_devices()
}

/// The tag of device `index` (index + 1), 0 with Webots' error out of range.
#[pyfunction]
fn wb_robot_get_device_by_index(index: i32) -> u16 {
    car::wb_robot_get_device_by_index(index)
}

/// The node type (`WbNodeType`) of the device with `tag`, 0 if none.
#[pyfunction]
fn wb_device_get_node_type(tag: u16) -> i32 {
    car::wb_device_get_node_type(tag)
}

/// The name of the device with `tag`, `None` if none.
#[pyfunction]
fn wb_device_get_name(tag: u16) -> Option<String> {
    let p = car::wb_device_get_name(tag);
    if p.is_null() {
        return None;
    }
    // SAFETY: a non-null result points to a NUL-terminated name in the robot's storage, valid
    // until the robot is freed, which cannot happen during this call (it holds the GIL and
    // Python calls the C API one call at a time).
    #[allow(unsafe_code)]
    let name = unsafe { std::ffi::CStr::from_ptr(p) };
    Some(name.to_string_lossy().into_owned())
}

/// Adds the sensor functions to the module.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(sensor_enable, m)?)?;
    m.add_function(wrap_pyfunction!(sensor_disable, m)?)?;
    m.add_function(wrap_pyfunction!(sensor_get_sampling_period, m)?)?;
    m.add_function(wrap_pyfunction!(triaxial_get_values, m)?)?;
    m.add_function(wrap_pyfunction!(triaxial_get_lookup_table, m)?)?;
    m.add_function(wrap_pyfunction!(wb_gps_get_values, m)?)?;
    m.add_function(wrap_pyfunction!(wb_gps_get_speed, m)?)?;
    m.add_function(wrap_pyfunction!(wb_gps_get_speed_vector, m)?)?;
    m.add_function(wrap_pyfunction!(wb_gps_get_coordinate_system, m)?)?;
    m.add_function(wrap_pyfunction!(
        wb_gps_convert_to_degrees_minutes_seconds,
        m
    )?)?;
    m.add_function(wrap_pyfunction!(wb_inertial_unit_get_roll_pitch_yaw, m)?)?;
    m.add_function(wrap_pyfunction!(wb_inertial_unit_get_quaternion, m)?)?;
    m.add_function(wrap_pyfunction!(wb_inertial_unit_get_noise, m)?)?;
    m.add_function(wrap_pyfunction!(wb_robot_get_number_of_devices, m)?)?;
    m.add_function(wrap_pyfunction!(wb_robot_get_device_by_index, m)?)?;
    m.add_function(wrap_pyfunction!(wb_device_get_node_type, m)?)?;
    m.add_function(wrap_pyfunction!(wb_device_get_name, m)?)?;
    Ok(())
}
