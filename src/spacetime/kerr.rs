//! The spinning hole's arm of the spacetime seam: the scene's world frame to
//! the hole's (x = the disk's e1, y = the spin axis, z = e2; lengths in rs)
//! and back, around the f64 closed form of [`crate::physics::kerr`].

use glam::DVec3;

use super::placement::Refusal;
use super::radii;
use crate::physics::geodesic::disk_basis;
use crate::physics::kerr::{self, KerrDisk, KerrObserver, KerrOutcome, PlacementError};
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

    /// The backward ray from `x0` along `d` (the ZAMO's frame there, world
    /// axes) as `samples` points (world), to the disk, to just outside the
    /// horizon or to `reach` from the hole (world units), and how it ends.
    pub fn path(
        &self,
        disk: Option<&Disk>,
        x0: DVec3,
        d: DVec3,
        reach: f64,
        samples: usize,
    ) -> Option<(Vec<DVec3>, Outcome)> {
        let local = self.local(x0 - self.hole.position);
        let dir = self.local(d).normalize();
        let kdisk = disk.map(|d| KerrDisk {
            inner: d.inner / self.hole.rs,
            outer: d.outer / self.hole.rs,
        });
        let path =
            kerr::path::path_zamo(local, dir, self.spin, kdisk, reach / self.hole.rs, samples)?;
        let points = path
            .points
            .iter()
            .map(|p| self.hole.position + self.world(*p))
            .collect();
        Some((points, self.trace(disk, x0, d)))
    }

    /// Whether the split ray march's trace pass leaves this ray to its second
    /// pass (`shaders/include/metric/kerr.glsl`, `KERR_COMMON_ONLY`): a polar
    /// motion that never crosses the equator, the radial case 4, or a path
    /// that reaches the disk or the sky on any case but 2. (The GPU also
    /// defers a case-2 path that meets the disk on its way into the horizon,
    /// and one within a hair of the shadow's edge, r4 - r3 < r4 / 10; this
    /// estimate, for the split's policy (src/deferred.rs, `pays`), counts them as
    /// common.)
    pub fn defers(&self, disk: Option<&Disk>, x0: DVec3, d: DVec3) -> bool {
        let ray = self.trace_local(disk, x0, d);
        let reaches = !matches!(ray.outcome, KerrOutcome::Captured);
        ray.case == 4 || ray.eta < 0.0 || (reaches && ray.case != 2)
    }

    /// The observer's velocity relative to the ZAMO at `position` (world
    /// axes), or why it cannot stand there.
    pub fn observer_velocity(&self, kind: ObserverKind, position: DVec3) -> Result<DVec3, Refusal> {
        let kind = match kind {
            ObserverKind::Zamo => KerrObserver::Zamo,
            ObserverKind::Static | ObserverKind::Flat => KerrObserver::Static,
            ObserverKind::Falling => KerrObserver::Falling,
            ObserverKind::Orbiting => KerrObserver::Orbiting,
        };
        let local = 2.0 * self.local(position - self.hole.position);
        let half = 0.5 * self.hole.rs;
        match kerr::observer_velocity(kind, local, self.spin) {
            Ok(beta) => Ok(self.world(beta) / self.hole.rs),
            Err(PlacementError::InsideHorizon(r)) => Err(Refusal::InsideHorizon {
                hole: 0,
                r: r * half / self.hole.rs,
                horizon: self.horizon() / self.hole.rs,
            }),
            Err(PlacementError::TooDeep(r, floor)) => Err(Refusal::FallingTooDeep {
                r: r * half,
                floor: floor * half,
                inner: radii::inner_horizon(self.hole.rs, self.spin),
            }),
            Err(PlacementError::StaticInErgoregion(r, r_ergo)) => {
                Err(Refusal::StaticInErgoregion {
                    r: r * half,
                    r_ergo: r_ergo * half,
                })
            }
            Err(PlacementError::OrbitTooFast(v, r)) => {
                Err(Refusal::OrbitTooFast { v, r: r * half })
            }
        }
    }

    /// The Boyer-Lindquist r (M) of `position` (world).
    pub fn radius_of(&self, position: DVec3) -> f64 {
        let local = 2.0 * self.local(position - self.hole.position);
        kerr::LocalFrame::at(local, self.spin).r
    }

    /// The outer horizon r+ in M.
    pub fn r_plus_m(&self) -> f64 {
        kerr::r_horizon(self.spin)
    }

    /// The outer horizon, the prograde equatorial photon orbit and the
    /// disk's ISCO (prograde for a* > 0, retrograde for a* < 0), in rs.
    pub fn horizon(&self) -> f64 {
        radii::horizon(self.hole.rs, self.spin)
    }

    pub fn photon_orbit(&self) -> f64 {
        radii::photon_orbit(self.hole.rs, self.spin, true)
    }

    pub fn isco(&self) -> f64 {
        radii::isco(self.hole.rs, self.spin)
    }
}

/// An equatorial photon path around a hole spinning at `spin`, forward in
/// time from Boyer-Lindquist (r, phi) = `start` (r in M) moving inward, with
/// angular momentum `lambda` (M) and eta = 0: r and phi in closed form from
/// Mino time (phi = phi_o + I_phi + lambda tau). Points in units of rs
/// (x = r cos phi / 2, y = r sin phi / 2), `samples` along the path, kept
/// where they lie more than `spacing` rs from the last one; stopped just
/// outside the horizon, where Boyer-Lindquist phi winds without end.
pub fn equatorial_path(
    spin: f64,
    lambda: f64,
    start: (f64, f64),
    samples: u32,
    spacing: f64,
) -> (Vec<(f64, f64)>, bool) {
    let (r_o, phi_o) = start;
    let rad = kerr::radial::Radial::new(spin, lambda, 0.0, r_o, -1.0);
    let mut points: Vec<(f64, f64)> = Vec::new();
    for i in 0..=samples {
        let tau = rad.tau_end * f64::from(i) / f64::from(samples) * (1.0 - 1e-9);
        let r = rad.r_at(tau);
        if !r.is_finite() || r < 1.01 * rad.r_plus {
            break;
        }
        let phi = phi_o + rad.i_phi(tau) + lambda * tau;
        let p = (0.5 * r * phi.cos(), 0.5 * r * phi.sin());
        let far = points
            .last()
            .is_none_or(|q: &(f64, f64)| (p.0 - q.0).hypot(p.1 - q.1) > spacing);
        if far && p.0.is_finite() && p.1.is_finite() {
            points.push(p);
        }
    }
    (points, rad.captured)
}
