//! The functions of the Webots C API's ray devices (`webots/distance_sensor.h`, `radar.h`,
//! `lidar.h`) for the Python `controller` module: scalar functions are the C entry points,
//! those whose C result is a pointer the C API's Rust twins (same messages, values returned).

use pyo3::prelude::*;

/// A radar target: `(distance m, received power dBm, radial speed m/s, azimuth rad)`.
type Target = (f64, f64, f64, f64);
/// A lidar point: `(x, y, z m, layer, time s)`.
type Point = (f32, f32, f32, i32, f32);

fn points(cloud: Option<Vec<car::WbLidarPoint>>) -> Option<Vec<Point>> {
    cloud.map(|c| {
        c.iter()
            .map(|p| (p.x, p.y, p.z, p.layer_id, p.time))
            .collect()
    })
}

/// The distance sensor's value.
#[pyfunction]
fn wb_distance_sensor_get_value(tag: u16) -> f64 {
    car::wb_distance_sensor_get_value(tag)
}

/// The largest value of its lookup table.
#[pyfunction]
fn wb_distance_sensor_get_max_value(tag: u16) -> f64 {
    car::wb_distance_sensor_get_max_value(tag)
}

/// The smallest value of its lookup table.
#[pyfunction]
fn wb_distance_sensor_get_min_value(tag: u16) -> f64 {
    car::wb_distance_sensor_get_min_value(tag)
}

/// Its aperture (rad).
#[pyfunction]
fn wb_distance_sensor_get_aperture(tag: u16) -> f64 {
    car::wb_distance_sensor_get_aperture(tag)
}

/// Its lookup table, flat (3 values per row); empty if none.
#[pyfunction]
fn wb_distance_sensor_get_lookup_table(tag: u16) -> Vec<f64> {
    car::distance_sensor_lookup_table(tag).unwrap_or_default()
}

/// Its type (`WbDistanceSensorType`).
#[pyfunction]
fn wb_distance_sensor_get_type(tag: u16) -> i32 {
    car::wb_distance_sensor_get_type(tag)
}

/// The radar's targets of the last sample.
#[pyfunction]
fn wb_radar_get_targets(tag: u16) -> Vec<Target> {
    car::radar_targets(tag)
        .iter()
        .map(|t| (t.distance, t.received_power, t.speed, t.azimuth))
        .collect()
}

/// The number of targets of the last sample.
#[pyfunction]
fn wb_radar_get_number_of_targets(tag: u16) -> i32 {
    car::wb_radar_get_number_of_targets(tag)
}

/// A radar field by name: `min_range`, `max_range` (m), `horizontal_fov`, `vertical_fov`
/// (rad).
#[pyfunction]
fn radar_get_field(field: &str, tag: u16) -> PyResult<f64> {
    Ok(match field {
        "min_range" => car::wb_radar_get_min_range(tag),
        "max_range" => car::wb_radar_get_max_range(tag),
        "horizontal_fov" => car::wb_radar_get_horizontal_fov(tag),
        "vertical_fov" => car::wb_radar_get_vertical_fov(tag),
        other => {
            return Err(pyo3::exceptions::PyValueError::new_err(format!(
                "no radar field {other:?}"
            )));
        }
    })
}

/// The lidar's range image (m), `None` for a wrong tag.
#[pyfunction]
fn wb_lidar_get_range_image(tag: u16) -> Option<Vec<f32>> {
    car::lidar_values::range_image(tag)
}

/// One layer of the range image, `None` on Webots' errors.
#[pyfunction]
fn wb_lidar_get_layer_range_image(tag: u16, layer: i32) -> Option<Vec<f32>> {
    car::lidar_values::layer_range_image(tag, layer)
}

/// The point cloud, `None` on Webots' errors.
#[pyfunction]
fn wb_lidar_get_point_cloud(tag: u16) -> Option<Vec<Point>> {
    points(car::lidar_values::point_cloud(tag))
}

/// One layer of the point cloud, `None` on Webots' errors.
#[pyfunction]
fn wb_lidar_get_layer_point_cloud(tag: u16, layer: i32) -> Option<Vec<Point>> {
    points(car::lidar_values::layer_point_cloud(tag, layer))
}

/// Turns the point cloud on (true) or off.
#[pyfunction]
fn lidar_set_point_cloud(tag: u16, on: bool) {
    if on {
        car::wb_lidar_enable_point_cloud(tag);
    } else {
        car::wb_lidar_disable_point_cloud(tag);
    }
}

/// True if the point cloud is on.
#[pyfunction]
fn wb_lidar_is_point_cloud_enabled(tag: u16) -> bool {
    car::wb_lidar_is_point_cloud_enabled(tag)
}

/// A lidar count by name: `number_of_points`, `horizontal_resolution`, `number_of_layers`.
#[pyfunction]
fn lidar_get_count(field: &str, tag: u16) -> PyResult<i32> {
    Ok(match field {
        "number_of_points" => car::wb_lidar_get_number_of_points(tag),
        "horizontal_resolution" => car::wb_lidar_get_horizontal_resolution(tag),
        "number_of_layers" => car::wb_lidar_get_number_of_layers(tag),
        other => {
            return Err(pyo3::exceptions::PyValueError::new_err(format!(
                "no lidar count {other:?}"
            )));
        }
    })
}

/// A lidar field by name: `frequency`, `min_frequency`, `max_frequency` (Hz), `fov`,
/// `vertical_fov` (rad), `min_range`, `max_range` (m).
#[pyfunction]
fn lidar_get_field(field: &str, tag: u16) -> PyResult<f64> {
    Ok(match field {
        "frequency" => car::wb_lidar_get_frequency(tag),
        "min_frequency" => car::wb_lidar_get_min_frequency(tag),
        "max_frequency" => car::wb_lidar_get_max_frequency(tag),
        "fov" => car::wb_lidar_get_fov(tag),
        "vertical_fov" => car::wb_lidar_get_vertical_fov(tag),
        "min_range" => car::wb_lidar_get_min_range(tag),
        "max_range" => car::wb_lidar_get_max_range(tag),
        other => {
            return Err(pyo3::exceptions::PyValueError::new_err(format!(
                "no lidar field {other:?}"
            )));
        }
    })
}

/// Sets the frequency (Hz; outside its range Webots' error).
#[pyfunction]
fn wb_lidar_set_frequency(tag: u16, frequency: f64) {
    car::wb_lidar_set_frequency(tag, frequency);
}

/// Adds the ray devices' functions to the module.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(wb_distance_sensor_get_value, m)?)?;
    m.add_function(wrap_pyfunction!(wb_distance_sensor_get_max_value, m)?)?;
    m.add_function(wrap_pyfunction!(wb_distance_sensor_get_min_value, m)?)?;
    m.add_function(wrap_pyfunction!(wb_distance_sensor_get_aperture, m)?)?;
    m.add_function(wrap_pyfunction!(wb_distance_sensor_get_lookup_table, m)?)?;
    m.add_function(wrap_pyfunction!(wb_distance_sensor_get_type, m)?)?;
    m.add_function(wrap_pyfunction!(wb_radar_get_targets, m)?)?;
    m.add_function(wrap_pyfunction!(wb_radar_get_number_of_targets, m)?)?;
    m.add_function(wrap_pyfunction!(radar_get_field, m)?)?;
    m.add_function(wrap_pyfunction!(wb_lidar_get_range_image, m)?)?;
    m.add_function(wrap_pyfunction!(wb_lidar_get_layer_range_image, m)?)?;
    m.add_function(wrap_pyfunction!(wb_lidar_get_point_cloud, m)?)?;
    m.add_function(wrap_pyfunction!(wb_lidar_get_layer_point_cloud, m)?)?;
    m.add_function(wrap_pyfunction!(lidar_set_point_cloud, m)?)?;
    m.add_function(wrap_pyfunction!(wb_lidar_is_point_cloud_enabled, m)?)?;
    m.add_function(wrap_pyfunction!(lidar_get_count, m)?)?;
    m.add_function(wrap_pyfunction!(lidar_get_field, m)?)?;
    m.add_function(wrap_pyfunction!(wb_lidar_set_frequency, m)?)?;
    Ok(())
}
