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
