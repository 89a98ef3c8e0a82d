//! The f64 physics a teacher asks for, without a GPU: a hole's horizons,
//! photon orbits, ISCO and the shadow's critical rays, from the crate's
//! spacetime door.

use numpy::PyArrayMethods;
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use blackhole::spacetime::radii;

/// The spin and size as the scene keys allow them (|a*| <= 0.9999, rs > 0).
fn checked(spin: f64, rs: f64) -> PyResult<()> {
    if !(spin.is_finite() && spin.abs() <= 0.9999) {
        return Err(PyValueError::new_err(format!(
            "spin = {spin}: must be a number in [-0.9999, 0.9999]"
        )));
    }
    if !(rs.is_finite() && rs > 0.0) {
        return Err(PyValueError::new_err(format!(
            "rs = {rs}: must be a positive number"
        )));
    }
    Ok(())
}

/// The outer and inner horizons (Boyer-Lindquist r, in the unit of `rs`) of
/// a hole spinning at `spin`: (rs, 0) at spin 0.
#[pyfunction]
#[pyo3(signature = (spin, rs = 1.0))]
fn horizons(spin: f64, rs: f64) -> PyResult<(f64, f64)> {
    checked(spin, rs)?;
    Ok((radii::horizon(rs, spin), radii::inner_horizon(rs, spin)))
}

/// The equatorial circular photon orbits (prograde, retrograde), in the unit
/// of `rs`: 1.5 rs both at spin 0.
#[pyfunction]
#[pyo3(signature = (spin, rs = 1.0))]
fn photon_orbits(spin: f64, rs: f64) -> PyResult<(f64, f64)> {
    checked(spin, rs)?;
    Ok((
        radii::photon_orbit(rs, spin, true),
        radii::photon_orbit(rs, spin, false),
    ))
}

/// The innermost stable circular orbit of a disk turning the way the
/// scene's disk does (prograde for spin > 0): 3 rs at spin 0.
#[pyfunction]
#[pyo3(signature = (spin, rs = 1.0))]
fn isco(spin: f64, rs: f64) -> PyResult<f64> {
    checked(spin, rs)?;
    Ok(radii::isco(rs, spin))
}

/// The photon constant lambda = L / E (in M) of the critical rays winding
/// onto the equatorial photon orbits (prograde, retrograde): +-3 sqrt(3) at
/// spin 0. Seen from far away in the disk's plane the shadow spans them:
/// its width is |prograde - retrograde| M.
#[pyfunction]
fn critical_lambdas(spin: f64) -> PyResult<(f64, f64)> {
    checked(spin, 1.0)?;
    Ok((
        radii::critical_lambda(spin, true),
        radii::critical_lambda(spin, false),
    ))
}

/// The shadow's outline seen from far away at `inclination` degrees from
/// the spin axis: a float64 (2 n, 2) array of (alpha, beta) on the sky in
/// units of `rs` (impact parameters: angles times the distance), closed
/// around the shadow; alpha across the projected spin axis (Bardeen's
/// sign: the side where light turns with the hole at alpha < 0), beta
/// along it. A circle of radius 3 sqrt(3) / 2 rs at spin 0.
#[pyfunction]
#[pyo3(signature = (spin, inclination, n = 256, rs = 1.0))]
fn shadow_outline<'py>(
    py: Python<'py>,
    spin: f64,
    inclination: f64,
    n: i64,
    rs: f64,
) -> PyResult<Bound<'py, numpy::PyArray2<f64>>> {
    checked(spin, rs)?;
    if !(inclination.is_finite() && (0.0..=180.0).contains(&inclination)) {
        return Err(PyValueError::new_err(format!(
            "inclination = {inclination}: must be in [0, 180] degrees"
        )));
    }
    if !(4..=100_000).contains(&n) {
        return Err(PyValueError::new_err(format!(
            "n = {n}: must be in [4, 100000]"
        )));
    }
    let pts = radii::shadow_outline(spin, inclination, n as usize);
    let flat: Vec<f64> = pts.iter().flat_map(|&(x, y)| [x * rs, y * rs]).collect();
    numpy::PyArray1::from_vec(py, flat).reshape([pts.len(), 2])
}

/// The photon paths `blackhole trace` draws for the scene's first hole, in
/// its equatorial plane (units of rs, the hole at the origin, rays coming
/// in from the left along +x): a list of dicts with the impact parameter
/// `b` (rs), whether the path is `captured`, and its `pieces`, float64
/// (N, 2) arrays of (x, y) inside the square of half-width `extent`.
#[pyfunction]
#[pyo3(signature = (scene, extent = 10.0))]
fn photon_paths<'py>(
    py: Python<'py>,
    scene: &crate::scene::Scene,
    extent: f64,
) -> PyResult<Vec<Bound<'py, pyo3::types::PyDict>>> {
    if !(extent.is_finite() && extent > 0.0 && extent <= 1e4) {
        return Err(PyValueError::new_err(format!(
            "extent = {extent}: must be a number of rs in (0, 1e4]"
        )));
    }
    let paths =
        py.allow_threads(|| blackhole::cli::trace::scene_photon_paths(&scene.inner, extent));
    paths
        .into_iter()
        .map(|p| {
            let d = pyo3::types::PyDict::new(py);
            d.set_item("b", p.b)?;
            d.set_item("captured", p.captured)?;
            let pieces = p
                .pieces
                .iter()
                .map(|piece| {
                    let flat: Vec<f64> = piece.iter().flat_map(|&(x, y)| [x, y]).collect();
                    numpy::PyArray1::from_vec(py, flat).reshape([piece.len(), 2])
                })
                .collect::<PyResult<Vec<_>>>()?;
            d.set_item("pieces", pieces)?;
            Ok(d)
        })
        .collect()
}

/// One pixel's light path, traced backward from the camera in f64 without
/// a GPU: pixel (`x`, `y`) (column, row from the top) of a `width` x
/// `height` image of `scene`. Returns a dict: `points`, a float64 (N, 3)
/// array of world positions (the camera's first) up to where the path
/// ends; `outcome`, "escaped", "captured" or "disk" (as OUTCOMES names
/// them); and `end`, the escape direction (a unit vector), the disk point
/// or the last point before the horizon. One hole, spinning or not, is in
/// closed form (`samples` points evenly spaced in Mino time, crowding
/// where the path bends; stopped at 1.001 times the horizon's radius, where
/// the Boyer-Lindquist azimuth winds without end); several holes and the
/// "flat" mapping are integrated (a point per step); gravity off, a straight
/// line. An outgoing path stops at `reach` from the first hole (default:
/// twice the camera's distance, at least 20 rs). A camera inside a horizon
/// raises ValueError.
#[pyfunction]
#[pyo3(signature = (scene, x, y, width, height, *, samples = 1000, reach = None))]
#[allow(clippy::too_many_arguments)]
fn light_path<'py>(
    py: Python<'py>,
    scene: &crate::scene::Scene,
    x: i64,
    y: i64,
    width: i64,
    height: i64,
    samples: i64,
    reach: Option<f64>,
) -> PyResult<Bound<'py, pyo3::types::PyDict>> {
    use crate::values::whole;
    use blackhole::physics::Outcome;
    let (x, y) = (whole("x", x, 0)?, whole("y", y, 0)?);
    let (width, height) = (whole("width", width, 1)?, whole("height", height, 1)?);
    let samples = whole("samples", samples, 0)? as usize;
    let inner = &scene.inner;
    let path = py
        .allow_threads(|| inner.light_path((x, y), (width, height), samples, reach))
        .map_err(crate::to_py)?;
    let last = path.points.last().copied().unwrap_or_default();
    let (outcome, end) = match path.outcome {
        Outcome::Escaped { direction } => ("escaped", direction),
        Outcome::Captured { .. } => ("captured", last),
        Outcome::Disk { position, .. } => ("disk", position),
        Outcome::NoSteps => ("no steps", last),
    };
    let d = pyo3::types::PyDict::new(py);
    let flat: Vec<f64> = path.points.iter().flat_map(|p| p.to_array()).collect();
    d.set_item(
        "points",
        numpy::PyArray1::from_vec(py, flat).reshape([path.points.len(), 3])?,
    )?;
    d.set_item("outcome", outcome)?;
    d.set_item(
        "end",
        numpy::PyArray1::from_vec(py, end.to_array().to_vec()),
    )?;
    Ok(d)
}

pub fn register(m: &Bound<'_, PyModule>) -> PyResult<()> {
    m.add_function(wrap_pyfunction!(light_path, m)?)?;
    m.add_function(wrap_pyfunction!(horizons, m)?)?;
    m.add_function(wrap_pyfunction!(photon_orbits, m)?)?;
    m.add_function(wrap_pyfunction!(isco, m)?)?;
    m.add_function(wrap_pyfunction!(critical_lambdas, m)?)?;
    m.add_function(wrap_pyfunction!(photon_paths, m)?)?;
    m.add_function(wrap_pyfunction!(shadow_outline, m)?)?;
    Ok(())
}
