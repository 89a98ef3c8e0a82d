//! The f64 CPU reference, the floor of the physics side: light paths around
//! non-rotating holes (closed form, integrated, and in the rain form through
//! the horizon) and spinning ones (`kerr/`, Mino time), the observers, the
//! thin disk's redshift and colour. Used by the spacetime seam above it
//! (which re-exports the constants below), by the tests (against closed
//! forms, and against the GPU ray by ray) and to draw photon paths. It
//! imports nothing of the crate above it.

pub mod blackbody;
pub mod closed_form;
pub mod disk;
pub mod geodesic;
pub mod kerr;
pub mod observer;
pub mod polarization;
pub mod rain;
pub mod redshift;
pub mod river;

pub use geodesic::{Disk, Hole, Outcome, TraceOptions, TraceResult, trace};

/// The closest a `"falling"` camera may come to the centre of a
/// non-rotating hole, in rs: it falls through the horizon, and its closed-form
/// paths hold the accuracy goals down to here (docs/inside-the-horizon.md
/// says why no closer). A spinning hole's floor never goes below it
/// ([`kerr::falling_floor`]).
pub const FALLING_MIN_R: f64 = 0.05;

/// The `k`-th of `n` directions spread evenly over the sphere (a Fibonacci
/// spiral from +y down), for the tests that sweep a camera's view.
#[cfg(test)]
pub(crate) fn sphere_direction(k: u32, n: u32) -> glam::DVec3 {
    let y = 1.0 - 2.0 * (f64::from(k) + 0.5) / f64::from(n);
    let az = 2.399_963 * f64::from(k);
    let s = (1.0 - y * y).sqrt();
    glam::DVec3::new(s * az.cos(), y, s * az.sin())
}
