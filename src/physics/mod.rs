//! The f64 CPU reference: light paths around Schwarzschild holes, the thin
//! disk's redshift. Used by the tests (against closed forms, and against the
//! GPU ray by ray) and to draw photon paths.

pub mod blackbody;
pub mod closed_form;
pub mod disk;
pub mod geodesic;
pub mod kerr;
pub mod observer;
pub mod rain;
pub mod redshift;
pub mod river;

pub use geodesic::{Disk, Hole, Outcome, TraceOptions, TraceResult, trace};

/// The `k`-th of `n` directions spread evenly over the sphere (a Fibonacci
/// spiral from +y down), for the tests that sweep a camera's view.
#[cfg(test)]
pub(crate) fn sphere_direction(k: u32, n: u32) -> glam::DVec3 {
    let y = 1.0 - 2.0 * (f64::from(k) + 0.5) / f64::from(n);
    let az = 2.399_963 * f64::from(k);
    let s = (1.0 - y * y).sqrt();
    glam::DVec3::new(s * az.cos(), y, s * az.sin())
}
