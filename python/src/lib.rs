//! `webots_vehicle._native`: the compiled half of the Python package.
//!
//! * The Webots C API's entry points under their C names (`wbu_driver_*`, `wbu_car_*`,
//!   `wb_robot_*`), forwarded to the `capi` crate's Rust functions: the pure-Python `controller`
//!   and `vehicle` modules call them as Webots' own binding calls `libdriver`/`libcar` through
//!   ctypes, so every warning, clamp and returned value is the C API's (module `webots`).
//! * `Simulation`, the core of the Pythonic `webots_vehicle.Simulation`: a world of
//!   `sim::Simulation`, cars added at will, per-step telemetry, the `vehicle-sim` scenarios
//!   (module `simulation`), its telemetry shown to numpy without a copy (module `telemetry`), its snapshots (module
//!   `snapshot`).
//! * Several controllers in one process, one per car (`controllers_*`), the `capi` crate's
//!   `controllers` extension for `webots_vehicle.controllers` (module `controllers`).
//! * Webots' Supervisor subset (`supervisor_*`), the `capi` crate's `supervisor` functions on
//!   the controller's world, for `controller.Supervisor` (module `supervisor`).
//! * `Sweep`, the core of `webots_vehicle.Sweep`: a sweep file's cases by index, each run into
//!   the row `vehicle-sim sweep` writes for it (module `sweep`).
//! * `VecSim`, the core of `webots_vehicle.gym.VectorEnv`: many copies of a gym world stepped
//!   with one call on numpy arrays (module `vec_env`); `GymEnv`, the core of the single
//!   environments of `webots_vehicle.gym`: one environment on a `Simulation`, one call per
//!   step (module `gym_env`).
//!
//! Units: m, rad (positive steers right), rad/s, s; km/h and ms where the Webots API uses them.

mod camera;
mod controllers;
mod display;
mod gym_env;
mod keyboard;
mod ray_sensors;
mod road_sensor;
mod sensors;
mod simulation;
mod snapshot;
mod supervisor;
mod sweep;
mod telemetry;
mod vec_env;
mod webots;

use pyo3::prelude::*;

// Qualified as `webots_vehicle.WorldError`, where the package re-exports it.
pyo3::create_exception!(
    webots_vehicle,
    WorldError,
    pyo3::exceptions::PyRuntimeError,
    "A world that cannot be loaded: the message names the file, line, key and value."
);

// Qualified as `webots_vehicle.SimulationError`. A RuntimeError, as these errors were before
// it existed, so that `except RuntimeError` keeps catching them.
pyo3::create_exception!(
    webots_vehicle,
    SimulationError,
    pyo3::exceptions::PyRuntimeError,
    "A simulation that cannot go on or a request it refuses: a vehicle added after recording \
     started, a name taken twice, a run that diverged, or a failure inside the engine (a bug, \
     caught and reported with the vehicle and the time rather than as a PanicException)."
);

/// The extension module.
#[pymodule]
#[pyo3(name = "_native")]
fn native(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add("WorldError", m.py().get_type::<WorldError>())?;
    m.add("SimulationError", m.py().get_type::<SimulationError>())?;
    webots::register(m)?;
    controllers::register(m)?;
    sensors::register(m)?;
    camera::register(m)?;
    display::register(m)?;
    keyboard::register(m)?;
    ray_sensors::register(m)?;
    road_sensor::register(m)?;
    simulation::register(m)?;
    snapshot::register(m)?;
    supervisor::register(m)?;
    sweep::register(m)?;
    telemetry::register(m)?;
    vec_env::register(m)?;
    gym_env::register(m)?;
    Ok(())
}
