//! The RoadSensor extension (`webots/vehicle/road_sensor.h`) for the Python `controller`
//! module: the C entry points themselves (`car::vehicle_road_sensor_*`), so Python prints
//! the same messages. The measurement is the engine's (`sim::devices::RoadSensorReading`).

use pyo3::prelude::*;

/// Enables the road sensor with `tag` every `period` ms (0 disables; negative: the error).
#[pyfunction]
fn vehicle_road_sensor_enable(tag: u16, period: i32) {
    car::vehicle_road_sensor_enable(tag, period);
}

/// Disables the road sensor with `tag`.
#[pyfunction]
fn vehicle_road_sensor_disable(tag: u16) {
    car::vehicle_road_sensor_disable(tag);
}

/// The sampling period (ms) of the road sensor with `tag`, 0 when disabled.
#[pyfunction]
fn vehicle_road_sensor_get_sampling_period(tag: u16) -> i32 {
    car::vehicle_road_sensor_get_sampling_period(tag)
}

/// The road index (−1 off the roads) and lane (0 off the roads) of the road sensor `tag`.
#[pyfunction]
fn vehicle_road_sensor_get_place(tag: u16, which: &str) -> PyResult<i32> {
    match which {
        "road" => Ok(car::vehicle_road_sensor_get_road(tag)),
        "lane" => Ok(car::vehicle_road_sensor_get_lane(tag)),
        other => Err(pyo3::exceptions::PyValueError::new_err(format!(
            "which must be 'road' or 'lane', not {other:?}"
        ))),
    }
}

/// One number of the road sensor `tag` (m, rad or 1/m; NaN off the roads): `which` is
/// the C getter's name without `vehicle_road_sensor_get_`.
#[pyfunction]
fn vehicle_road_sensor_get_number(tag: u16, which: &str) -> PyResult<f64> {
    Ok(match which {
        "lookahead" => car::vehicle_road_sensor_get_lookahead(tag),
        "station" => car::vehicle_road_sensor_get_station(tag),
        "lateral_offset" => car::vehicle_road_sensor_get_lateral_offset(tag),
        "heading_error" => car::vehicle_road_sensor_get_heading_error(tag),
        "curvature" => car::vehicle_road_sensor_get_curvature(tag),
        "curvature_ahead" => car::vehicle_road_sensor_get_curvature_ahead(tag),
        "left_line_distance" => car::vehicle_road_sensor_get_left_line_distance(tag),
        "right_line_distance" => car::vehicle_road_sensor_get_right_line_distance(tag),
        "left_edge_distance" => car::vehicle_road_sensor_get_left_edge_distance(tag),
        "right_edge_distance" => car::vehicle_road_sensor_get_right_edge_distance(tag),
        "lane_width" => car::vehicle_road_sensor_get_lane_width(tag),
        other => {
            return Err(pyo3::exceptions::PyValueError::new_err(format!(
                "no road sensor getter {other:?}"
            )));
        }
    })
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(vehicle_road_sensor_enable, m)?)?;
    m.add_function(wrap_pyfunction!(vehicle_road_sensor_disable, m)?)?;
    m.add_function(wrap_pyfunction!(
        vehicle_road_sensor_get_sampling_period,
        m
    )?)?;
    m.add_function(wrap_pyfunction!(vehicle_road_sensor_get_place, m)?)?;
    m.add_function(wrap_pyfunction!(vehicle_road_sensor_get_number, m)?)?;
    Ok(())
}
