//! Webots' Supervisor subset for the Python `controller` module: the `capi` crate's supervisor
//! functions (the session's world), with their errors as Python exceptions.

use pyo3::exceptions::{PyRuntimeError, PyValueError};
use pyo3::prelude::*;

use car::supervisor::{self, NodeRef};
use sim::SimError;

/// `(kind, index)` of a node as the Python side holds it: "car" or "body".
fn node(kind: &str, index: usize) -> PyResult<NodeRef> {
    match kind {
        "car" => Ok(NodeRef::Car(index)),
        "body" => Ok(NodeRef::Body(index)),
        other => Err(PyValueError::new_err(format!(
            "kind must be 'car' or 'body', not {other:?}"
        ))),
    }
}

fn error(e: &SimError) -> PyErr {
    match e {
        SimError::Param(p) => PyValueError::new_err(p.to_string()),
        other => PyRuntimeError::new_err(other.to_string()),
    }
}

/// The node of DEF name `def` as `(kind, index)`, None if there is none.
#[pyfunction]
fn supervisor_node_from_def(def: &str) -> Option<(&'static str, usize)> {
    supervisor::node_from_def(def).map(|n| match n {
        NodeRef::Car(i) => ("car", i),
        NodeRef::Body(i) => ("body", i),
    })
}

/// Translation (m), rotation (axis, rad), velocity (m/s), angular velocity (rad/s).
#[pyfunction]
#[allow(clippy::type_complexity)]
fn supervisor_placement(
    kind: &str,
    index: usize,
) -> PyResult<([f64; 3], [f64; 4], [f64; 3], [f64; 3])> {
    let p = supervisor::placement(node(kind, index)?).map_err(|e| error(&e))?;
    Ok((
        p.position.coords.into(),
        p.axis_angle(),
        p.velocity.into(),
        p.angular_velocity.into(),
    ))
}

/// Puts the node at `translation` (m) turned by `rotation` (axis, rad).
#[pyfunction]
fn supervisor_set_pose(
    kind: &str,
    index: usize,
    translation: [f64; 3],
    rotation: [f64; 4],
) -> PyResult<()> {
    supervisor::set_pose(node(kind, index)?, translation, rotation).map_err(|e| error(&e))
}

/// Gives the node the velocity `linear` (m/s) and `angular` (rad/s).
#[pyfunction]
fn supervisor_set_velocity(
    kind: &str,
    index: usize,
    linear: [f64; 3],
    angular: [f64; 3],
) -> PyResult<()> {
    supervisor::set_velocity(node(kind, index)?, linear, angular).map_err(|e| error(&e))
}

/// The world back as loaded.
#[pyfunction]
fn supervisor_simulation_reset() -> PyResult<()> {
    supervisor::simulation_reset().map_err(PyRuntimeError::new_err)
}

/// Adds the functions to the module.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(supervisor_node_from_def, m)?)?;
    m.add_function(wrap_pyfunction!(supervisor_placement, m)?)?;
    m.add_function(wrap_pyfunction!(supervisor_set_pose, m)?)?;
    m.add_function(wrap_pyfunction!(supervisor_set_velocity, m)?)?;
    m.add_function(wrap_pyfunction!(supervisor_simulation_reset, m)?)?;
    Ok(())
}
