//! TOML values to Python objects and back (a scene key's value).

use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;
use pyo3::types::{PyBool, PyDict, PyFloat, PyInt, PyList, PyString, PyTuple};

/// A TOML value as the Python object of its kind (tables as dicts).
pub fn to_object<'py>(py: Python<'py>, v: &toml::Value) -> PyResult<Bound<'py, PyAny>> {
    Ok(match v {
        toml::Value::String(s) => PyString::new(py, s).into_any(),
        toml::Value::Integer(i) => i.into_pyobject(py)?.into_any(),
        toml::Value::Float(f) => PyFloat::new(py, *f).into_any(),
        toml::Value::Boolean(b) => PyBool::new(py, *b).to_owned().into_any(),
        toml::Value::Datetime(d) => PyString::new(py, &d.to_string()).into_any(),
        toml::Value::Array(a) => {
            let items = a
                .iter()
                .map(|x| to_object(py, x))
                .collect::<PyResult<Vec<_>>>()?;
            PyList::new(py, items)?.into_any()
        }
        toml::Value::Table(t) => {
            let d = PyDict::new(py);
            for (k, x) in t {
                d.set_item(k, to_object(py, x)?)?;
            }
            d.into_any()
        }
    })
}

/// A Python object as a TOML value: bool, int, float, str, a sequence
/// (list, tuple, a numpy array's `tolist()`) or a dict of them.
pub fn from_object(key: &str, o: &Bound<'_, PyAny>) -> PyResult<toml::Value> {
    if o.is_instance_of::<PyBool>() {
        return Ok(toml::Value::Boolean(o.extract()?));
    }
    if o.is_instance_of::<PyInt>() {
        return Ok(toml::Value::Integer(o.extract()?));
    }
    if o.is_instance_of::<PyFloat>() {
        return Ok(toml::Value::Float(o.extract()?));
    }
    if o.is_instance_of::<PyString>() {
        return Ok(toml::Value::String(o.extract()?));
    }
    if let Ok(d) = o.downcast::<PyDict>() {
        let mut t = toml::Table::new();
        for (k, v) in d.iter() {
            let k: String = k.extract()?;
            let v = from_object(&format!("{key}.{k}"), &v)?;
            t.insert(k, v);
        }
        return Ok(toml::Value::Table(t));
    }
    if o.is_instance_of::<PyList>() || o.is_instance_of::<PyTuple>() || o.hasattr("tolist")? {
        let seq = if o.hasattr("tolist")? {
            o.call_method0("tolist")?
        } else {
            o.clone()
        };
        if !seq.is_instance_of::<PyList>() && !seq.is_instance_of::<PyTuple>() {
            return from_object(key, &seq);
        }
        let items = seq
            .try_iter()?
            .map(|x| from_object(key, &x?))
            .collect::<PyResult<Vec<_>>>()?;
        return Ok(toml::Value::Array(items));
    }
    if let Ok(f) = o.extract::<f64>() {
        // (numpy scalars and other numbers)
        return Ok(toml::Value::Float(f));
    }
    Err(PyValueError::new_err(format!(
        "{key}: a {} is not a scene value (a bool, int, float, str, list or dict)",
        o.get_type().name()?
    )))
}

/// A whole-number argument `name` (an image side, a sample or frame count,
/// a pixel's column) as the u32 the crate takes: below `lo` or past u32 is
/// a ValueError naming it (PyO3's own conversion would raise an
/// OverflowError that does not say which argument), the rest the crate
/// checks as the command line's do.
pub fn whole(name: &str, v: i64, lo: i64) -> PyResult<u32> {
    if v < lo {
        return Err(PyValueError::new_err(format!(
            "{name} = {v}: must be at least {lo}"
        )));
    }
    u32::try_from(v)
        .map_err(|_| PyValueError::new_err(format!("{name} = {v}: must be at most {}", u32::MAX)))
}
