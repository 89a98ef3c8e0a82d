//! Where a camera's observer may stand in each spacetime: the one place the
//! rules live (scene validation asks here and words the refusals). Lengths
//! in the scene's units (each hole's rs).

use glam::DVec3;

use super::Spacetime;
use crate::physics::observer::ObserverKind;

/// The closest a `"falling"` camera may come to a non-rotating hole, in rs
/// (closer, its speed is within 32-bit rounding of light's; the fall
/// animation ends at 1.05 rs).
pub const FALLING_MIN_R: f64 = 1.01;

/// Why an observer cannot stand where a camera puts it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Refusal {
    /// Inside the horizon of hole `hole` (any hole but a spinning one; with
    /// gravity off too, where the holes still absorb).
    InsideHorizon { hole: usize },
    /// `"orbiting"` inside the photon sphere `photon` of the nearest hole
    /// (the camera at `r`): no circular orbit there.
    InsidePhotonSphere { r: f64, photon: f64 },
    /// `"orbiting"` on the disk's axis, where an orbit has no direction.
    OnDiskAxis,
    /// `"falling"` at `r` from a non-rotating hole of size `rs`, closer than
    /// [`FALLING_MIN_R`].
    FallingTooClose { r: f64, rs: f64 },
    /// `"flat"` around a spinning hole (it is the Schwarzschild comparison
    /// mapping).
    FlatAroundSpin,
    /// Inside a spinning hole's outer horizon `horizon`.
    InsideSpinningHorizon { horizon: f64 },
    /// `"static"` inside a spinning hole's ergoregion (`r`, `r_ergo`).
    StaticInErgoregion { r: f64, r_ergo: f64 },
    /// `"orbiting"` around a spinning hole, faster than light (`v` in c) at
    /// `r`.
    OrbitTooFast { v: f64, r: f64 },
}

impl Spacetime {
    /// Whether an observer of `kind` may stand at `position` (the disk's
    /// `disk_normal` sets an orbit's axis), or why not.
    pub fn placement(
        &self,
        kind: ObserverKind,
        position: DVec3,
        disk_normal: DVec3,
    ) -> Result<(), Refusal> {
        if let Spacetime::Kerr(k) = self {
            if kind == ObserverKind::Flat {
                return Err(Refusal::FlatAroundSpin);
            }
            return k.observer_velocity(kind, position).map(|_| ());
        }
        let mut nearest: Option<(DVec3, f64, f64)> = None;
        for (i, h) in self.holes().iter().enumerate() {
            let rel = position - h.position;
            let r = rel.length();
            if r <= h.rs {
                return Err(Refusal::InsideHorizon { hole: i });
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
                let axis = disk_normal.normalize_or_zero();
                if axis != DVec3::ZERO && axis.cross(rel / r).length() <= 1e-6 {
                    return Err(Refusal::OnDiskAxis);
                }
                Ok(())
            }
            ObserverKind::Falling
                if !matches!(self, Spacetime::Flat(_)) && r < FALLING_MIN_R * rs =>
            {
                Err(Refusal::FallingTooClose { r, rs })
            }
            _ => Ok(()),
        }
    }
}
