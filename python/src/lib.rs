//! The Python package `blackhole`: the renderer, its scenes, AOVs and exact
//! light paths as numpy arrays, over the crate's public API (no logic of
//! its own beyond the conversions). The Python side (`blackhole/`) adds the
//! iterators and type stubs.

use pyo3::create_exception;
use pyo3::exceptions::{PyException, PyKeyboardInterrupt, PyValueError};
use pyo3::prelude::*;

mod physics;
mod render;
mod scene;
mod values;

create_exception!(
    _blackhole,
    Error,
    PyException,
    "The base of the package's exceptions (bad input raises ValueError)."
);
create_exception!(
    _blackhole,
    DeviceError,
    Error,
    "The Vulkan device failed or is missing (the message says what was being done)."
);
create_exception!(
    _blackhole,
    FileError,
    Error,
    "Reading or writing a file failed (the message names the file)."
);

/// The crate's error as the Python exception of its kind, with its message:
/// bad input (a scene, a size, a name) `ValueError`, files `FileError`,
/// a stop between samples `KeyboardInterrupt`, the rest `DeviceError`.
pub(crate) fn to_py(e: blackhole::Error) -> PyErr {
    use blackhole::Error as E;
    let msg = e.to_string();
    match e {
        E::Scene(_) | E::Usage(_) => PyValueError::new_err(msg),
        E::Io { .. } | E::Image { .. } => FileError::new_err(msg),
        E::Interrupted => PyKeyboardInterrupt::new_err("rendering stopped"),
        _ => DeviceError::new_err(msg),
    }
}

#[pymodule]
fn _blackhole(m: &Bound<'_, PyModule>) -> PyResult<()> {
    let py = m.py();
    m.add("Error", py.get_type::<Error>())?;
    m.add("DeviceError", py.get_type::<DeviceError>())?;
    m.add("FileError", py.get_type::<FileError>())?;
    m.add_class::<scene::Scene>()?;
    m.add_class::<render::Renderer>()?;
    physics::register(m)?;
    Ok(())
}
