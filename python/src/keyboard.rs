//! The keyboard functions of the Webots C API (`webots/keyboard.h`) for the Python
//! `controller` module: the C entry points, over `sim::keyboard`.

use pyo3::prelude::*;

/// Samples the keys every `period` ms (0 disables; negative: Webots' error).
#[pyfunction]
fn wb_keyboard_enable(period: i32) {
    car::wb_keyboard_enable(period);
}

/// The keyboard's period (ms), 0 when disabled.
#[pyfunction]
fn wb_keyboard_get_sampling_period() -> i32 {
    car::wb_keyboard_get_sampling_period()
}

/// The next key of the last sample, −1 when none is left.
#[pyfunction]
fn wb_keyboard_get_key() -> i32 {
    car::wb_keyboard_get_key()
}

/// Adds the keyboard functions to the module.
pub(crate) fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(wb_keyboard_enable, m)?)?;
    m.add_function(wrap_pyfunction!(wb_keyboard_get_sampling_period, m)?)?;
    m.add_function(wrap_pyfunction!(wb_keyboard_get_key, m)?)?;
    Ok(())
}
