//! Where a camera's observer may stand in each spacetime, and where a fall
//! may end ([`super::Fall::check_end`]): the one place the rules live
//! (scene validation asks here and words the refusals). Lengths in the
//! scene's units (each hole's rs).

use glam::DVec3;

use super::{Metric, Spacetime};
use crate::physics::observer::ObserverKind;

pub use crate::physics::FALLING_MIN_R;

/// Why an observer cannot stand where a camera puts it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Refusal {
    /// Inside the (outer) horizon of hole `hole`, non-rotating or
    /// spinning, with an observer other than `"falling"` (none other exists
    /// there): the camera at `r` (its distance from the centre, or a
    /// spinning hole's Boyer-Lindquist r), the horizon at `horizon`, both
    /// in units of the hole's rs.
    InsideHorizon { hole: usize, r: f64, horizon: f64 },
    /// Inside the horizon of hole `hole` of a scene with several holes
    /// (their summed paths say nothing about an interior), or with gravity
    /// off (the holes are absorbing spheres).
    InsideAbsorber { hole: usize, several: bool },
    /// `"orbiting"` inside the photon sphere `photon` of the nearest hole
    /// (the camera at `r`): no circular orbit there.
    InsidePhotonSphere { r: f64, photon: f64 },
    /// `"orbiting"` on the disk's axis, where an orbit has no direction.
    OnDiskAxis,
    /// `"falling"` at `r` from the centre of a non-rotating hole of size
    /// `rs`, closer than [`FALLING_MIN_R`].
    FallingTooClose { r: f64, rs: f64 },
    /// `"flat"` around a spinning hole (it is the Schwarzschild comparison
    /// mapping).
    FlatAroundSpin,
    /// `"falling"` between a spinning hole's horizons at Boyer-Lindquist
    /// `r`, at or below `floor`: (1 + 1e-3) times the inner horizon `inner`
    /// or [`FALLING_MIN_R`] rs, whichever is farther out (rs units).
    FallingTooDeep { r: f64, floor: f64, inner: f64 },
    /// `"static"` inside a spinning hole's ergoregion (`r`, `r_ergo`).
    StaticInErgoregion { r: f64, r_ergo: f64 },
    /// `"orbiting"` around a spinning hole, faster than light (`v` in c) at
    /// `r`.
    OrbitTooFast { v: f64, r: f64 },
}

/// Why a fall cannot end where `[animation] fall_end_radius` puts it
/// ([`super::Fall::check_end`]).
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum EndRefusal {
    /// Inside a spinning hole's horizon (`horizon`, rs) for an observer that
    /// does not go through it.
    Inside { horizon: f64 },
    /// A falling camera's fall into a spinning hole ending at
    /// Boyer-Lindquist `r`, at or below `floor`, just outside the inner
    /// horizon `inner` (rs).
    TooDeep { r: f64, floor: f64, inner: f64 },
    /// A falling camera's fall into a non-rotating hole ending closer to
    /// the singularity than [`FALLING_MIN_R`].
    TooClose,
    /// At or beyond where the fall starts (`start`, the camera's distance
    /// from the hole's centre, rs): a fall only goes inward.
    NotInward { start: f64 },
}

impl Spacetime {
    /// Whether an observer of `kind` may stand at `position` (the disk's
    /// axis sets an orbit's), or why not.
    pub fn placement(&self, kind: ObserverKind, position: DVec3) -> Result<(), Refusal> {
        let disk_normal = self.axis;
        if let Metric::Kerr(k) = &self.metric {
            if kind == ObserverKind::Flat {
                return Err(Refusal::FlatAroundSpin);
            }
            // The axis rule holds for every spin, so that it is continuous
            // at spin 0 (at 1e-9 an orbit on the axis once passed).
            let rel = position - k.hole.position;
            if kind == ObserverKind::Orbiting && on_axis(disk_normal, rel) {
                return Err(Refusal::OnDiskAxis);
            }
            return k.observer_velocity(kind, position).map(|_| ());
        }
        let mut nearest: Option<(DVec3, f64, f64)> = None;
        let one = matches!(self.metric, Metric::Schwarzschild(_));
        for (i, h) in self.holes().iter().enumerate() {
            let rel = position - h.position;
            let r = rel.length();
            if r <= h.rs && !one {
                let several = matches!(self.metric, Metric::Summed(_));
                return Err(Refusal::InsideAbsorber { hole: i, several });
            }
            if r <= h.rs && kind != ObserverKind::Falling {
                return Err(Refusal::InsideHorizon {
                    hole: i,
                    r: r / h.rs,
                    horizon: 1.0,
                });
            }
            if nearest.is_none_or(|(_, best, _)| r < best) {
                nearest = Some((rel, r, h.rs));
            }
        }
        let Some((rel, r, rs)) = nearest else {
            return Ok(());
        };
        match kind {
            ObserverKind::Orbiting => {
                if r <= 1.5 * rs {
                    return Err(Refusal::InsidePhotonSphere {
                        r,
                        photon: 1.5 * rs,
                    });
                }
                if on_axis(disk_normal, rel) {
                    return Err(Refusal::OnDiskAxis);
                }
                Ok(())
            }
            ObserverKind::Falling if one && r < FALLING_MIN_R * rs => {
                Err(Refusal::FallingTooClose { r, rs })
            }
            _ => Ok(()),
        }
    }
}

/// Whether `rel` (from the hole) lies on the disk's axis `normal`, where an
/// orbit has no direction (within 1e-6 rad).
fn on_axis(normal: DVec3, rel: DVec3) -> bool {
    let (axis, r) = (normal.normalize_or_zero(), rel.length());
    axis != DVec3::ZERO && r > 0.0 && axis.cross(rel / r).length() <= 1e-6
}
