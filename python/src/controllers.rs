//! Several controllers in one process, one per car of the world: the `capi` crate's
//! `controllers` extension (no Webots counterpart) for `webots_vehicle.controllers`, which the
//! ROS node uses to serve every car of a world.

use pyo3::prelude::*;

use crate::WorldError;

/// The world's cars in file order as `(name, programmed)`: the loaded world's, or those of the
/// world `VEHICLE_WORLD` names (read, not loaded). A world file that cannot be read raises
/// `WorldError`.
#[pyfunction]
fn controllers_cars() -> PyResult<Vec<(String, bool)>> {
    car::controllers::cars()
        .map(|cars| cars.into_iter().map(|c| (c.name, c.programmed)).collect())
        .map_err(WorldError::new_err)
}

/// Makes the controller of car `name` current, loading the world for it first if needed; a
/// world that cannot be loaded, or a name it has no car of, raises `WorldError`.
#[pyfunction]
fn controllers_select(name: &str) -> PyResult<()> {
    car::controllers::select(name).map_err(WorldError::new_err)
}

/// The name of the current controller's car; None before a world is loaded.
#[pyfunction]
fn controllers_current() -> Option<String> {
    car::controllers::current()
}

/// Adds the functions to the module.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(controllers_cars, m)?)?;
    m.add_function(wrap_pyfunction!(controllers_select, m)?)?;
    m.add_function(wrap_pyfunction!(controllers_current, m)?)?;
    Ok(())
}
