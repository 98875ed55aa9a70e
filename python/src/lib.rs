//! `webots_vehicle._native`: the compiled half of the Python package.
//!
//! * The Webots C API's entry points under their C names (`wbu_driver_*`, `wbu_car_*`,
//!   `wb_robot_*`), forwarded to the `capi` crate's Rust functions: the pure-Python `controller`
//!   and `vehicle` modules call them as Webots' own binding calls `libdriver`/`libcar` through
//!   ctypes, so every warning, clamp and returned value is the C API's (module `webots`).
//! * `Simulation`, the core of the Pythonic `webots_vehicle.Simulation`: a world of
//!   `sim::Simulation`, cars added at will, per-step telemetry, the `vehicle-sim` scenarios
//!   (module `simulation`).
//! * `Sweep`, the core of `webots_vehicle.Sweep`: a sweep file's cases by index, each run into
//!   the row `vehicle-sim sweep` writes for it (module `sweep`).
//!
//! Units: m, rad (positive steers right), rad/s, s; km/h and ms where the Webots API uses them.

mod ray_sensors;
mod sensors;
mod simulation;
mod sweep;
mod webots;

use pyo3::prelude::*;

// Qualified as `webots_vehicle.WorldError`, where the package re-exports it.
pyo3::create_exception!(
    webots_vehicle,
    WorldError,
    pyo3::exceptions::PyRuntimeError,
    "A world that cannot be loaded: the message names the file, line, key and value."
);

/// The extension module.
#[pymodule]
#[pyo3(name = "_native")]
fn native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("WorldError", m.py().get_type::<WorldError>())?;
    webots::register(m)?;
    sensors::register(m)?;
    ray_sensors::register(m)?;
    simulation::register(m)?;
    sweep::register(m)?;
    Ok(())
}
