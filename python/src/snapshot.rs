//! `_native.Snapshot`: what `Simulation.snapshot()` returns and `restore` takes.

use pyo3::prelude::*;

/// `Simulation.snapshot()`'s opaque state: the engine's [`sim::Snapshot`] and how many cars and
/// warnings the simulation had then.
#[pyclass(module = "webots_vehicle._native", unsendable)]
pub(crate) struct Snapshot {
    pub(crate) state: sim::Snapshot,
    pub(crate) cars: usize,
    pub(crate) warnings: usize,
}

#[pymethods]
impl Snapshot {
    /// Simulated time when the snapshot was taken (s).
    #[getter]
    fn time(&self) -> f64 {
        self.state.time_ms() as f64 / 1000.0
    }

    fn __repr__(&self) -> String {
        format!("<Snapshot at t = {} s>", self.time())
    }
}

/// Adds the class to the module.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Snapshot>()?;
    Ok(())
}
