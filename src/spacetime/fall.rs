//! A camera's fall from rest into the first hole, straight along the line
//! from its centre through the start: the distance and the Boyer-Lindquist
//! radius along that line, the falling observers' proper time, the deepest
//! the camera may go and where the fall ends. The animation's clock
//! (`[animation] camera = "fall"`) and the window's fall (F) ask here; the
//! free-fall law and the falling frame are [`crate::physics`]'s (the rain
//! form of a non-rotating hole, `physics::kerr`'s falling observer and
//! floor). Lengths in the scene's units, radii in rs.

use glam::DVec3;

use super::placement::{EndRefusal, FALLING_MIN_R};
use super::{Metric, Spacetime, radii};
use crate::physics::kerr;
use crate::physics::observer::ObserverKind;

/// Where a fall into a non-rotating hole ends by default (rs): the closest
/// a falling camera may come to the singularity.
pub const FALL_END_DEFAULT: f64 = FALLING_MIN_R;

/// Where a fall stops outside a hole by default (an observer other than
/// `"falling"`, several holes, gravity off): this factor times the horizon's
/// distance from the centre (sqrt(r+^2 + a^2) for a spinning hole).
pub const FALL_END_OUTSIDE: f64 = 1.05;

/// Where a falling camera's fall into a spinning hole ends by default: this
/// factor times the deepest Boyer-Lindquist r it may reach
/// ([`kerr::falling_floor`]: just outside the inner horizon r-, or 0.05 rs
/// for a slowly turning hole), on the line of the fall.
pub const FALL_END_INNER: f64 = 1.01;

/// A fall from `start` (its distance from the first hole's centre) along
/// `line` (unit, from the centre), held by an observer that goes through
/// the horizon (`interior`: a falling observer around one hole with gravity
/// on) or stops outside it.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Fall {
    centre: DVec3,
    rs: f64,
    spin: f64,
    /// The spin axis (the disk's normal), unit.
    axis: DVec3,
    interior: bool,
    start: f64,
    line: DVec3,
}

impl Spacetime {
    /// The fall from `start` (distance from the first hole's centre) along
    /// `line` held by `observer`. Without a hole: a unit hole at the origin
    /// that the fall stops outside of.
    pub fn fall(&self, start: f64, line: DVec3, observer: ObserverKind) -> Fall {
        let first = self.holes().first();
        let one_hole = matches!(self.metric, Metric::Schwarzschild(_) | Metric::Kerr(_));
        Fall {
            centre: first.map_or(DVec3::ZERO, |h| h.position),
            rs: first.map_or(1.0, |h| h.rs),
            spin: self.spin(),
            axis: self.axis.normalize_or(DVec3::Y),
            interior: observer == ObserverKind::Falling && one_hole,
            start,
            line,
        }
    }

    /// The fall from `position`: along the line from the first hole's centre
    /// through it (`fallback` where it is the centre).
    pub fn fall_from(&self, position: DVec3, observer: ObserverKind, fallback: DVec3) -> Fall {
        let centre = self.holes().first().map_or(DVec3::ZERO, |h| h.position);
        let rel = position - centre;
        self.fall(rel.length(), rel.normalize_or(fallback), observer)
    }
}

impl Fall {
    /// The hole's centre, its rs, the spin a*, the start's distance and the
    /// line (unit, from the centre).
    pub fn centre(&self) -> DVec3 {
        self.centre
    }

    pub fn rs(&self) -> f64 {
        self.rs
    }

    pub fn spin(&self) -> f64 {
        self.spin
    }

    pub fn start(&self) -> f64 {
        self.start
    }

    pub fn line(&self) -> DVec3 {
        self.line
    }

    /// Whether the camera goes through the horizon.
    pub fn interior(&self) -> bool {
        self.interior
    }

    /// The point at `distance` from the centre on the line.
    pub fn point(&self, distance: f64) -> DVec3 {
        self.centre + self.line * distance
    }

    /// The distance from the centre (scene units) at which the line reaches
    /// Boyer-Lindquist r (rs): r^2 + a^2 sin^2 theta, cos theta = y / r.
    pub fn distance_at(&self, r: f64) -> f64 {
        distance_of(r, 0.5 * self.spin, self.line.dot(self.axis)) * self.rs
    }

    /// The Boyer-Lindquist r (rs) at `distance` (scene units) from the
    /// centre along the line.
    pub fn radius_at(&self, distance: f64) -> f64 {
        let (a, rho) = (0.5 * self.spin, distance / self.rs);
        kerr::boyer_lindquist_r(rho * rho, rho * self.line.dot(self.axis), a)
    }

    /// Whether the point at `distance` is inside the outer horizon.
    pub fn inside_horizon(&self, distance: f64) -> bool {
        self.radius_at(distance) <= radii::horizon(1.0, self.spin.abs())
    }

    /// The falling observers' proper time (scene units, c = 1) from `near`
    /// to `far` (distances from the centre) along the line: dtau = Sigma dr
    /// / sqrt(2 r (r^2 + a^2)) (M = 1) in Boyer-Lindquist r, Sigma = r^2 +
    /// a^2 cos^2 theta where the line crosses each r, by Simpson's rule over
    /// 256 intervals (at spin 0 it is (2/3) (far^1.5 - near^1.5) / sqrt(rs),
    /// the law [`Fall::distance_after`] inverts).
    pub fn proper_time(&self, near: f64, far: f64) -> f64 {
        let (a, ny) = (self.spin, self.line.dot(self.axis));
        let (r0, r1) = (2.0 * self.radius_at(near), 2.0 * self.radius_at(far));
        let rate = |r: f64| {
            // cos theta = y / r, y = the line's height (M units).
            let y = 2.0 * self.distance_at(0.5 * r) / self.rs * ny;
            (r * r + a * a * (y / r).powi(2)) / (2.0 * r * (r * r + a * a)).sqrt()
        };
        let n = 256;
        let h = (r1 - r0) / f64::from(n);
        let inner: f64 = (1..n)
            .map(|i| f64::from(if i % 2 == 1 { 4 } else { 2 }) * rate(r0 + f64::from(i) * h))
            .sum();
        (rate(r0) + inner + rate(r1)) * h / 3.0 * (0.5 * self.rs)
    }

    /// For a falling camera of a non-rotating hole, the proper time (rs/c)
    /// it has left at its start before the singularity: (2/3) (r /
    /// rs)^(3/2). None for any other fall (a spinning hole's camera meets no
    /// singularity before r-).
    pub fn time_to_singularity(&self) -> Option<f64> {
        let r = self.start / self.rs;
        (self.interior && self.spin == 0.0).then(|| 2.0 / 3.0 * r.powf(1.5))
    }

    /// The deepest Boyer-Lindquist r (rs) a falling camera may reach.
    pub fn floor(&self) -> f64 {
        if self.spin == 0.0 {
            FALL_END_DEFAULT
        } else {
            0.5 * kerr::falling_floor(self.spin.abs())
        }
    }

    /// Where the fall ends (distance from the centre, scene units):
    /// `end_radius` (rs, `[animation] fall_end_radius`) or the default for
    /// its observer and hole.
    pub fn end(&self, end_radius: Option<f64>) -> f64 {
        if self.interior && self.spin != 0.0 && end_radius.is_none() {
            return self.distance_at(FALL_END_INNER * self.floor());
        }
        let default = if self.interior {
            FALL_END_DEFAULT
        } else if self.spin == 0.0 {
            FALL_END_OUTSIDE
        } else {
            let (r, a) = (radii::horizon(1.0, self.spin.abs()), 0.5 * self.spin);
            FALL_END_OUTSIDE * (r * r + a * a).sqrt()
        };
        end_radius.unwrap_or(default) * self.rs
    }

    /// The distance from the centre after `fraction` (0 to 1) of the fall's
    /// proper time to `end` (a distance): r^(3/2) = r0^(3/2) - (3/2) sqrt(rs)
    /// tau from rest at infinity, or for a falling camera of a spinning hole
    /// [`Fall::proper_time`] inverted by bisection.
    pub fn distance_after(&self, fraction: f64, end: f64) -> f64 {
        let (r0, rs) = (self.start, self.rs);
        if self.spin == 0.0 || !self.interior {
            let r_end = end.min(r0);
            let tau_total = (2.0 / 3.0) * (r0.powf(1.5) - r_end.powf(1.5)) / rs.sqrt();
            let tau = fraction * tau_total;
            return (r0.powf(1.5) - 1.5 * rs.sqrt() * tau)
                .max(r_end.powf(1.5))
                .powf(2.0 / 3.0);
        }
        let end = end.min(r0);
        if fraction >= 1.0 {
            return end;
        }
        let tau = fraction * self.proper_time(end, r0);
        let (mut lo, mut hi) = (end, r0);
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if self.proper_time(mid, r0) > tau {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }

    /// Whether the fall may end at `end_radius` (rs from the centre, as
    /// `[animation] fall_end_radius` says), or why not: not inside the
    /// start, inside a spinning
    /// hole's horizon for an observer that cannot go there, below a
    /// spinning hole's floor, or closer to a non-rotating hole's
    /// singularity than [`FALLING_MIN_R`].
    pub fn check_end(&self, end_radius: f64) -> Result<(), EndRefusal> {
        if end_radius * self.rs >= self.start {
            return Err(EndRefusal::NotInward {
                start: self.start / self.rs,
            });
        }
        let horizon = radii::horizon(1.0, self.spin.abs());
        if !(self.spin == 0.0 || self.interior || end_radius > 1.01 * horizon) {
            return Err(EndRefusal::Inside { horizon });
        }
        let (r, floor) = (self.radius_at(end_radius * self.rs), self.floor());
        if !(!self.interior || self.spin == 0.0 || r > floor) {
            return Err(EndRefusal::TooDeep {
                r,
                floor,
                inner: radii::inner_horizon(1.0, self.spin),
            });
        }
        if !(!self.interior || self.spin != 0.0 || end_radius >= FALLING_MIN_R) {
            return Err(EndRefusal::TooClose);
        }
        Ok(())
    }
}

/// The distance from the centre at which a line from it reaches
/// Boyer-Lindquist r around a hole of spin parameter `a` (the same units as
/// r), `ny` the cosine of the line's angle to the spin axis: the one place
/// a radius becomes a distance (the inverse of
/// [`kerr::boyer_lindquist_r`]).
pub(super) fn distance_of(r: f64, a: f64, ny: f64) -> f64 {
    ((r * r + a * a) / (1.0 + a * a * ny * ny / (r * r))).sqrt()
}

#[cfg(test)]
#[path = "fall_tests.rs"]
mod tests;
