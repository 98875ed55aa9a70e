//! Telemetry handed to Python: how much a run keeps (`record=`), and the recorded rows as a
//! read-only buffer that numpy views without a copy.
//!
//! A car's [`TelemetryLog`] keeps its rows in memory as `SAMPLE_COLUMNS` f64 values each,
//! row after row ([`SharedRows`]); [`TelemetryRows`] exports them through Python's buffer
//! protocol (2-D, float64, C order, read-only) and holds them alive, so `numpy.frombuffer`
//! (the Python `Telemetry`) shows the recorded memory itself. The log never writes rows it
//! has shared (it copies its block first), so the view's values never change under it.
//! Rows already moved to the log's temporary file (a run kept whole past
//! [`sim::telemetry::MEMORY_ROWS`] rows) are read back into a fresh `bytearray` instead.

use std::ffi::c_int;
use std::num::NonZeroUsize;

use pyo3::exceptions::{PyBufferError, PyOSError, PyValueError};
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyByteArray, PyBytes};

use sim::telemetry::{Retention, SAMPLE_COLUMNS, Sample, SharedRows, TelemetryLog};

/// Bytes of one value (f64).
const VALUE_BYTES: usize = 8;

/// A log's rows in memory, exported read-only through the buffer protocol: see the module
/// docs. `frozen`: nothing in it changes after creation, so the shape and strides the buffer
/// points at stay where they are while a consumer holds the buffer (and with it this object).
#[pyclass(module = "webots_vehicle._native", frozen)]
pub(crate) struct TelemetryRows {
    rows: SharedRows,
    /// Rows, columns.
    shape: [isize; 2],
    /// Bytes from one row to the next, from one column to the next.
    strides: [isize; 2],
}

impl TelemetryRows {
    fn new(rows: SharedRows) -> PyResult<TelemetryRows> {
        let too_large = || PyBufferError::new_err("the telemetry table is too large to export");
        let n = isize::try_from(rows.rows()).map_err(|_| too_large())?;
        // SAMPLE_COLUMNS (43) and its row bytes (344) fit an isize on every platform.
        let columns = SAMPLE_COLUMNS as isize;
        let value = VALUE_BYTES as isize;
        n.checked_mul(columns * value).ok_or_else(too_large)?;
        Ok(TelemetryRows {
            rows,
            shape: [n, columns],
            strides: [columns * value, value],
        })
    }
}

#[pymethods]
impl TelemetryRows {
    /// The number of rows.
    fn __len__(&self) -> usize {
        self.rows.rows()
    }

    /// The rows as a read-only buffer: float64 ("d"), 2-D (rows × columns), C order, when the
    /// consumer asks for a format; otherwise the same memory as plain bytes. A writable
    /// buffer is refused (BufferError).
    #[allow(unsafe_code)]
    unsafe fn __getbuffer__(
        slf: Bound<'_, Self>,
        view: *mut pyo3::ffi::Py_buffer,
        flags: c_int,
    ) -> PyResult<()> {
        if flags & pyo3::ffi::PyBUF_WRITABLE != 0 {
            return Err(PyBufferError::new_err(
                "telemetry arrays are read-only (they show the recorded memory); copy one to \
                 change it",
            ));
        }
        let this = slf.get();
        let len = this.shape[0] * this.strides[0];
        let data = this.rows.as_ptr().cast_mut().cast();
        let (shape, strides) = (this.shape.as_ptr(), this.strides.as_ptr());
        let py = slf.py();
        // SAFETY: `view` is the Py_buffer CPython passes to bf_getbuffer. PyBuffer_FillInfo
        // fills it for `len` read-only bytes at `data` as the flags ask and stores a new
        // reference to this object in view->obj (released with the buffer), which holds the
        // SharedRows and so keeps `data` valid and unchanged; it fails only for a writable
        // request, refused above. The format, shape and strides written after it are a
        // static C string and this frozen object's fields, which live as long as view->obj.
        unsafe {
            if pyo3::ffi::PyBuffer_FillInfo(view, slf.as_ptr(), data, len, 1, flags) != 0 {
                return Err(PyErr::fetch(py));
            }
            if flags & pyo3::ffi::PyBUF_FORMAT == pyo3::ffi::PyBUF_FORMAT {
                (*view).format = c"d".as_ptr().cast_mut();
                (*view).itemsize = VALUE_BYTES as isize;
                if flags & pyo3::ffi::PyBUF_ND == pyo3::ffi::PyBUF_ND {
                    (*view).ndim = 2;
                    (*view).shape = shape.cast_mut();
                }
                if flags & pyo3::ffi::PyBUF_STRIDES == pyo3::ffi::PyBUF_STRIDES {
                    (*view).strides = strides.cast_mut();
                }
            }
        }
        Ok(())
    }

    fn __repr__(&self) -> String {
        format!("<TelemetryRows: {} rows>", self.rows.rows())
    }
}

/// The [`Retention`] of `Simulation(record=...)`: True keeps every sample, False none but
/// the last, a whole number N ≥ 1 the last N steps' samples.
///
/// # Errors
/// ValueError naming `record` and the value for anything else (0, a negative number, a
/// float, a string).
pub(crate) fn retention(record: &Bound<'_, PyAny>) -> PyResult<Retention> {
    if let Ok(b) = record.cast::<PyBool>() {
        return Ok(if b.is_true() {
            Retention::All
        } else {
            Retention::Off
        });
    }
    let refused = || {
        let shown = record
            .repr()
            .map_or_else(|_| "?".to_string(), |r| r.to_string());
        PyValueError::new_err(format!(
            "record must be True (every step), False (none but the last) or a whole number \
             of steps N >= 1 (the last N), not {shown}"
        ))
    };
    // Only integers (int, numpy integers: anything with __index__), not floats.
    if record.hasattr("__index__")? {
        let n: i128 = record.extract().map_err(|_| refused())?;
        return usize::try_from(n)
            .ok()
            .and_then(NonZeroUsize::new)
            .map(Retention::Last)
            .ok_or_else(refused);
    }
    Err(refused())
}

/// The rows `log` holds, in time order: the recorded memory itself ([`TelemetryRows`]) while
/// it is all in memory, else a fresh `bytearray` of native-endian f64 values, row-major,
/// read back from the log's temporary file.
pub(crate) fn rows<'py>(py: Python<'py>, log: &TelemetryLog) -> PyResult<Bound<'py, PyAny>> {
    if let Some(shared) = log.shared_rows() {
        return Ok(Bound::new(py, TelemetryRows::new(shared)?)?.into_any());
    }
    let bytes = PyByteArray::new_with(
        py,
        log.len() * SAMPLE_COLUMNS * VALUE_BYTES,
        |bytes: &mut [u8]| {
            let mut cells = bytes.chunks_exact_mut(VALUE_BYTES);
            log.for_each(|row| {
                // The row first: zip asks its first iterator first, and a cell taken after the
                // row's end would be lost.
                for (v, cell) in row.iter().zip(cells.by_ref()) {
                    cell.copy_from_slice(&v.to_ne_bytes());
                }
            })
            .map_err(|e| PyOSError::new_err(e.to_string()))
        },
    )?;
    Ok(bytes.into_any())
}

/// `samples` as native-endian f64 bytes, row-major.
pub(crate) fn table<'py>(py: Python<'py>, samples: &[Sample]) -> Bound<'py, PyBytes> {
    let mut bytes = Vec::with_capacity(samples.len() * SAMPLE_COLUMNS * VALUE_BYTES);
    for s in samples {
        for v in s.values() {
            bytes.extend_from_slice(&v.unwrap_or(f64::NAN).to_ne_bytes());
        }
    }
    PyBytes::new(py, &bytes)
}

/// Adds the class to the module.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_class::<TelemetryRows>()?;
    Ok(())
}
