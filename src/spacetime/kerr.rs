//! The spinning hole's arm of the spacetime seam: the scene's world frame to
//! the hole's (x = the disk's e1, y = the spin axis, z = e2; lengths in rs)
//! and back, around the f64 closed form of [`crate::physics::kerr`].

use glam::DVec3;

use crate::physics::geodesic::disk_basis;
use crate::physics::kerr::{self, KerrDisk, KerrObserver, KerrOutcome};
use crate::physics::observer::ObserverKind;
use crate::physics::{Disk, Hole, Outcome};

/// One spinning hole: its place and size, the signed spin a* and its axis
/// (the disk's normal).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct SpinningHole {
    pub hole: Hole,
    pub spin: f64,
    pub axis: DVec3,
}

impl SpinningHole {
    /// World vector to the hole's axes (rs units for positions relative to
    /// its centre).
    fn local(&self, v: DVec3) -> DVec3 {
        let (e1, e2) = disk_basis(self.axis);
        DVec3::new(v.dot(e1), v.dot(self.axis.normalize()), v.dot(e2)) / self.hole.rs
    }

    fn world(&self, v: DVec3) -> DVec3 {
        let (e1, e2) = disk_basis(self.axis);
        (v.x * e1 + v.y * self.axis.normalize() + v.z * e2) * self.hole.rs
    }

    /// The closed form's ray from `x0` along `d` (world), in the hole's frame.
    fn trace_local(&self, disk: Option<&Disk>, x0: DVec3, d: DVec3) -> kerr::KerrRay {
        let local = self.local(x0 - self.hole.position);
        let dir = self.local(d).normalize();
        let disk = disk.map(|d| KerrDisk {
            inner: d.inner / self.hole.rs,
            outer: d.outer / self.hole.rs,
        });
        kerr::trace_zamo(local, dir, self.spin, disk)
    }

    /// Where the backward ray from `x0` along `d` (the ZAMO's frame there,
    /// world axes) ends.
    pub fn trace(&self, disk: Option<&Disk>, x0: DVec3, d: DVec3) -> Outcome {
        match self.trace_local(disk, x0, d).outcome {
            KerrOutcome::Captured => Outcome::Captured { hole: 0 },
            KerrOutcome::Escaped(v) => Outcome::Escaped {
                direction: self.world(v).normalize(),
            },
            KerrOutcome::Disk { r, phi, .. } => {
                // rho = sqrt(r^2 + a^2) in the plane, azimuth phi.
                let a = 0.5 * self.spin;
                let rho = (r * r + a * a).sqrt();
                let p = DVec3::new(rho * phi.cos(), 0.0, rho * phi.sin());
                Outcome::Disk {
                    position: self.hole.position + self.world(p),
                    velocity: d,
                }
            }
        }
    }

    /// Whether the split ray march's trace pass leaves this ray to its second
    /// pass (`shaders/include/metric/kerr.glsl`, `KERR_COMMON_ONLY`): a polar
    /// motion that never crosses the equator, the radial case 4, or a path
    /// that reaches the disk or the sky on any case but 2. (The GPU also
    /// defers a case-2 path that meets the disk on its way into the horizon,
    /// and one within a hair of the shadow's edge, r4 - r3 < r4 / 10; this
    /// estimate, for [`crate::passes::raymarch::split_pays`], counts them as
    /// common.)
    pub fn defers(&self, disk: Option<&Disk>, x0: DVec3, d: DVec3) -> bool {
        let ray = self.trace_local(disk, x0, d);
        let reaches = !matches!(ray.outcome, KerrOutcome::Captured);
        ray.case == 4 || ray.eta < 0.0 || (reaches && ray.case != 2)
    }

    /// The observer's velocity relative to the ZAMO at `position` (world
    /// axes), or why it cannot stand there.
    pub fn observer_velocity(
        &self,
        kind: ObserverKind,
        position: DVec3,
    ) -> Result<DVec3, kerr::PlacementError> {
        let kind = match kind {
            ObserverKind::Zamo => KerrObserver::Zamo,
            ObserverKind::Static | ObserverKind::Flat => KerrObserver::Static,
            ObserverKind::Falling => KerrObserver::Falling,
            ObserverKind::Orbiting => KerrObserver::Orbiting,
        };
        let local = 2.0 * self.local(position - self.hole.position);
        let beta = kerr::observer_velocity(kind, local, self.spin)?;
        Ok(self.world(beta) / self.hole.rs)
    }

    /// The outer horizon, the prograde equatorial photon orbit and the
    /// disk's ISCO (prograde for a* > 0, retrograde for a* < 0), in rs.
    pub fn horizon(&self) -> f64 {
        0.5 * kerr::r_horizon(self.spin) * self.hole.rs
    }

    pub fn photon_orbit(&self) -> f64 {
        0.5 * kerr::r_photon_equatorial(self.spin.abs(), true) * self.hole.rs
    }

    pub fn isco(&self) -> f64 {
        0.5 * kerr::r_isco(self.spin) * self.hole.rs
    }
}
