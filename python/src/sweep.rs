//! `_native.Sweep`: a sweep file loaded, its cases by index, and one case run into the row
//! that `vehicle-sim sweep` writes for it (the values and the CSV line, byte for byte), so
//! that any Python scheduler (Ray, Dask, a process pool) can spread the cases and write the
//! same `results.csv`.

use std::path::PathBuf;

use pyo3::exceptions::PyIndexError;
use pyo3::prelude::*;
use pyo3::types::PyList;

use sim::sweep::{AxisValue, Cell, Row, Sweep as Inner, SweepError};

use crate::WorldError;

/// A loaded sweep. Immutable and shareable between threads; running a case releases the GIL.
#[pyclass(module = "webots_vehicle._native", frozen)]
pub(crate) struct Sweep {
    inner: Inner,
}

/// `WorldError` for a sweep file or base world that cannot be loaded, with the `file`,
/// `line`, `column` and `key` attributes (`None` where unknown); `IndexError` for a case
/// index past the last.
fn sweep_error(py: Python<'_>, e: &SweepError) -> PyErr {
    if let SweepError::NoSuchCase { .. } = e {
        return PyIndexError::new_err(e.to_string());
    }
    let err = WorldError::new_err(e.to_string());
    let value = err.value(py);
    let located = e.file_error();
    let (line, column) = located
        .and_then(|f| f.location)
        .map(|l| (l.line, l.column))
        .unzip();
    let file = match e {
        SweepError::Io { file, .. } => Some(file.as_str()),
        _ => located.map(|f| f.file.as_str()),
    };
    // Setting attributes on a fresh exception instance cannot fail in practice; if it did, the
    // message still says everything.
    let _ = value.setattr("file", file);
    let _ = value.setattr("line", line);
    let _ = value.setattr("column", column);
    let _ = value.setattr("key", located.and_then(|f| f.key.as_deref()));
    err
}

/// An axis value as a Python value: int, float, bool, str or list.
fn axis_value<'py>(py: Python<'py>, v: &AxisValue) -> PyResult<Bound<'py, PyAny>> {
    Ok(match v {
        AxisValue::Integer(i) => i.into_pyobject(py)?.into_any(),
        AxisValue::Float(x) => x.into_pyobject(py)?.into_any(),
        AxisValue::Bool(b) => b.into_pyobject(py)?.to_owned().into_any(),
        AxisValue::Text(s) => s.into_pyobject(py)?.into_any(),
        AxisValue::List(items) => {
            let values = items
                .iter()
                .map(|i| axis_value(py, i))
                .collect::<PyResult<Vec<_>>>()?;
            PyList::new(py, values)?.into_any()
        }
    })
}

/// A row's cells as Python values, in column order: the case index, the axis values, the
/// metrics (float, bool, None when empty), the notes and the error (None when empty).
fn row_values<'py>(py: Python<'py>, row: &Row) -> PyResult<Vec<Bound<'py, PyAny>>> {
    let mut out = Vec::with_capacity(row.values.len() + row.metrics.len() + 4);
    out.push(row.case.into_pyobject(py)?.into_any());
    for v in &row.values {
        out.push(axis_value(py, v)?);
    }
    for c in &row.metrics {
        out.push(match c {
            Cell::Number(x) => x.into_pyobject(py)?.into_any(),
            Cell::Bool(b) => b.into_pyobject(py)?.to_owned().into_any(),
            Cell::Empty => py.None().into_bound(py),
        });
    }
    let notes = (!row.notes.is_empty()).then(|| row.notes.join("; "));
    out.push(notes.into_pyobject(py)?.into_any());
    let error = row.error.as_ref().map(ToString::to_string);
    out.push(error.into_pyobject(py)?.into_any());
    out.push(row.checksum().into_pyobject(py)?.into_any());
    Ok(out)
}

#[pymethods]
impl Sweep {
    /// Loads the sweep file at `path` (a relative `world` path is relative to the file).
    #[new]
    fn new(py: Python<'_>, path: PathBuf) -> PyResult<Sweep> {
        py.detach(|| Inner::load(&path))
            .map(|inner| Sweep { inner })
            .map_err(|e| sweep_error(py, &e))
    }

    /// Parses sweep-file `text`; `name` names it in messages, `directory` is where a relative
    /// `world` path starts.
    #[staticmethod]
    fn parse(py: Python<'_>, name: &str, text: &str, directory: PathBuf) -> PyResult<Sweep> {
        py.detach(|| Inner::parse(name, text, &directory))
            .map(|inner| Sweep { inner })
            .map_err(|e| sweep_error(py, &e))
    }

    /// The sweep file, as given.
    #[getter]
    fn file(&self) -> &str {
        self.inner.file()
    }

    /// The base world: its path, or the default world's name.
    #[getter]
    fn world(&self) -> &str {
        self.inner.world_source()
    }

    /// The scenario each case runs.
    #[getter]
    fn scenario(&self) -> &'static str {
        self.inner.scenario().name()
    }

    /// The fingerprint of the sweep (16 hexadecimal digits), as in `sweep.json`.
    #[getter]
    fn fingerprint(&self) -> String {
        self.inner.fingerprint().to_string()
    }

    /// The axes' keys, in the sweep file's order.
    #[getter]
    fn axes(&self) -> Vec<String> {
        self.inner.columns().axes.clone()
    }

    /// The metric columns.
    #[getter]
    fn metrics(&self) -> Vec<String> {
        self.inner.columns().metrics.clone()
    }

    /// Every column of `results.csv`, in order.
    #[getter]
    fn columns(&self) -> Vec<String> {
        self.inner
            .columns()
            .names()
            .into_iter()
            .map(str::to_string)
            .collect()
    }

    /// The base world's warnings.
    #[getter]
    fn warnings(&self) -> Vec<String> {
        self.inner
            .warnings()
            .iter()
            .map(ToString::to_string)
            .collect()
    }

    /// The number of cases.
    fn __len__(&self) -> usize {
        self.inner.len()
    }

    /// The header line of `results.csv`, with its line end.
    fn csv_header(&self) -> String {
        self.inner.columns().csv_header()
    }

    /// Case `index`'s axis values, in the axes' order.
    fn values<'py>(&self, py: Python<'py>, index: usize) -> PyResult<Vec<Bound<'py, PyAny>>> {
        let values = self.inner.values(index).map_err(|e| sweep_error(py, &e))?;
        values.iter().map(|v| axis_value(py, v)).collect()
    }

    /// Runs case `index` (without the GIL) and returns its cells as Python values, in column
    /// order, and its `results.csv` line.
    fn run_case<'py>(
        &self,
        py: Python<'py>,
        index: usize,
    ) -> PyResult<(Vec<Bound<'py, PyAny>>, String)> {
        let row = py
            .detach(|| self.inner.run_case(index))
            .map_err(|e| sweep_error(py, &e))?;
        Ok((row_values(py, &row)?, row.csv_line()))
    }
}

pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<Sweep>()
}
