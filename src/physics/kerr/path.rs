//! One backward light ray of a spinning hole (any spin, a* = 0 included) as
//! points, in closed form: r(tau), theta(tau) and phi(tau) of the same
//! Mino-time solution [`super::trace_zamo`] ends (radial.rs, angular.rs),
//! sampled along tau and turned into the hole's frame. No stepping: each
//! point is exact to the closed form's f64 (a point at Mino time tau does
//! not depend on the points before it). M = 1 inside, points in r_s.

use glam::DVec3;

use super::angular::{Ordinary, Vortical};
use super::frame::{Constants, r_horizon};
use super::radial::Radial;
use super::{KerrDisk, KerrOutcome, first_disk_crossing};

/// Where a path stops short of the horizon: Boyer-Lindquist phi winds
/// without end as r -> r+, so the last point is at r = (1 + this) r+.
pub const HORIZON_STOP: f64 = 1e-3;

/// The backward ray from a ZAMO camera as points.
#[derive(Clone, Debug)]
pub struct KerrPath {
    /// Points in the hole's frame (r_s), the camera's first.
    pub points: Vec<DVec3>,
    /// Their Mino times (M units; 0 at the camera).
    pub tau: Vec<f64>,
    /// How the ray ends (as [`super::trace_zamo`] says).
    pub outcome: KerrOutcome,
}

/// The polar motion of one ray: theta and the angular part of phi.
enum Polar {
    Ordinary(Ordinary),
    Vortical(Vortical),
    /// eta = 0 in the equatorial plane: it stays there.
    Equatorial,
}

impl Polar {
    fn at(&self, lambda: f64, tau: f64) -> (f64, f64) {
        match self {
            Polar::Ordinary(o) => (o.cos_theta_at(tau), o.lambda_g_phi(lambda, tau)),
            Polar::Vortical(v) => (v.cos_theta_at(tau), v.lambda_g_phi(lambda, tau)),
            Polar::Equatorial => (0.0, lambda * tau),
        }
    }
}

/// One ray's closed form, able to place a point at any Mino time.
struct Ray {
    a: f64,
    lambda: f64,
    phi_o: f64,
    turn: f64,
    rad: Radial,
    polar: Polar,
}

impl Ray {
    /// Boyer-Lindquist r and the point (r_s, hole frame) at Mino time tau,
    /// whose radial part of the azimuth is `i_phi`.
    fn point(&self, tau: f64, i_phi: f64) -> (f64, DVec3) {
        let r = self.rad.r_at(tau);
        let (cos_th, g_phi) = self.polar.at(self.lambda, tau);
        // (At the camera the polar integral is 0; its forms are 0 / 0 there.)
        let g_phi = if tau == 0.0 { 0.0 } else { g_phi };
        let phi = self.phi_o - self.turn * (i_phi + g_phi);
        let sin_th = (1.0 - cos_th * cos_th).max(0.0).sqrt();
        let rho = (r * r + self.a * self.a).sqrt();
        let p = DVec3::new(
            rho * sin_th * phi.cos(),
            r * cos_th,
            -rho * sin_th * phi.sin(),
        );
        (r, 0.5 * p)
    }
}

/// The backward ray from a ZAMO camera at `position` (r_s, hole frame)
/// along the unit direction `d` (the ZAMO's frame), spin `spin`, as
/// `samples` points evenly spaced in Mino time (points crowd where the ray
/// bends), up to where it ends: the thin `disk`'s first crossing, (1 +
/// [`HORIZON_STOP`]) r+ on the way into the horizon, or `reach` (r_s, at
/// least the camera's own distance) on the way out. None for a ray of no
/// defined path (E = 0, eta = 0 off the equatorial plane, a ray through
/// the centre: null sets).
pub fn path_zamo(
    position: DVec3,
    d: DVec3,
    spin: f64,
    disk: Option<KerrDisk>,
    reach: f64,
    samples: usize,
) -> Option<KerrPath> {
    let a = spin;
    let cc = Constants::of(2.0 * position, d, a);
    let f = cc.frame;
    if cc.energy == 0.0 || !cc.lambda.is_finite() || !cc.eta.is_finite() {
        return None;
    }
    let (lambda, eta) = (cc.lambda, cc.eta);
    let rad = Radial::new(a, lambda, eta, f.r, cc.s_r);
    let polar = if eta > 0.0 {
        Polar::Ordinary(Ordinary::new(
            a,
            lambda,
            eta,
            f.cos_theta,
            cc.theta_potential,
            cc.s_theta,
        ))
    } else if eta < 0.0 {
        Polar::Vortical(Vortical::new(a, lambda, eta, f.cos_theta, cc.s_theta))
    } else if f.cos_theta == 0.0 {
        Polar::Equatorial
    } else {
        return None;
    };
    let outcome = super::trace_zamo(position, d, spin, disk).outcome;
    let crossing = match &polar {
        Polar::Ordinary(o) => first_disk_crossing(&rad, o, disk).map(|(_, tc, _)| tc),
        _ => None,
    };
    let ray = Ray {
        a,
        lambda,
        phi_o: f.phi,
        turn: cc.energy.signum(),
        rad,
        polar,
    };
    let r_far = (2.0 * reach).max(f.r);
    let r_near = (1.0 + HORIZON_STOP) * r_horizon(a);
    // Past the end (the path leaves [r_near, r_far]).
    let beyond = |r: f64| !r.is_finite() || r > r_far || r < r_near;
    let tau_end = crossing.unwrap_or(ray.rad.tau_end);
    let n = samples.max(2);
    let mut path = KerrPath {
        points: Vec::with_capacity(n + 1),
        tau: Vec::with_capacity(n + 1),
        outcome,
    };
    // The last point's Mino time and I_phi (added up along the path).
    let (mut last, mut i_last) = (0.0, 0.0);
    let i_phi = |t: f64, from: (f64, f64)| from.1 + ray.rad.i_phi_between(from.0, t);
    for i in 0..=n {
        let tau = tau_end * (i as f64 / n as f64);
        // (The ends of an escape or a capture lie at r = infinity or r+.)
        let at_end = i == n && crossing.is_none();
        let r = ray.rad.r_at(tau);
        if at_end || (i > 0 && beyond(r)) {
            // The boundary between the last point inside and this one.
            let (mut lo, mut hi) = (last, tau);
            for _ in 0..200 {
                let mid = 0.5 * (lo + hi);
                if beyond(ray.rad.r_at(mid)) {
                    hi = mid;
                } else {
                    lo = mid;
                }
                if hi - lo <= 1e-15 * hi.abs() {
                    break;
                }
            }
            path.tau.push(lo);
            path.points.push(ray.point(lo, i_phi(lo, (last, i_last))).1);
            break;
        }
        let ip = i_phi(tau, (last, i_last));
        path.tau.push(tau);
        path.points.push(ray.point(tau, ip).1);
        (last, i_last) = (tau, ip);
    }
    // (A ray through the centre, b = 0, is a null set the forms do not
    // reach: four roots at r = 0 when a = 0.)
    path.points.iter().all(|p| p.is_finite()).then_some(path)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::kerr::{mino, trace_zamo};

    /// Boyer-Lindquist (r, theta, phi) of a hole-frame point (r_s).
    fn bl(p: DVec3, a: f64) -> [f64; 3] {
        let f = crate::physics::kerr::LocalFrame::at(2.0 * p, a);
        [f.r, f.theta, f.phi]
    }

    fn dir(x: f64, y: f64, z: f64) -> DVec3 {
        DVec3::new(x, y, z).normalize()
    }

    const DISK: Option<KerrDisk> = Some(KerrDisk {
        inner: 3.0,
        outer: 12.0,
    });

    /// Rays of every kind: to the disk, above it and under it, captured,
    /// escaping, a vortical one near the axis, a camera in the ergoregion.
    fn rays() -> Vec<(f64, DVec3, DVec3)> {
        let toward = |p: DVec3, dx: f64, dy: f64| dir(-p.x + dx, -p.y + dy, -p.z);
        let far = DVec3::new(0.5, 3.0, -15.0);
        vec![
            (0.9, far, toward(far, 0.3, 0.0)),
            (0.9, far, toward(far, 2.5, 0.3)),
            (0.9, far, toward(far, -1.0, -3.2)),
            (-0.6, far, toward(far, 4.0, 6.0)),
            (0.0, far, toward(far, 3.1, 1.0)),
            (0.0, far, toward(far, 0.4, 0.1)),
            (0.99, DVec3::new(0.1, 8.0, -0.3), dir(0.05, -1.0, 0.02)),
            (0.99, DVec3::new(0.8, 0.1, 0.2), dir(-0.3, -0.1, 1.0)),
        ]
    }

    #[test]
    fn every_point_is_the_integrated_ray_at_its_mino_time() {
        let mut kinds = [0usize; 3];
        for (a, at, d) in rays() {
            let path = path_zamo(at, d, a, DISK, 40.0, 400).expect("a path");
            assert!(path.points.len() > 3, "a {a} {at} {d}: {path:?}");
            assert!(
                (path.points[0] - at).length() < 1e-12,
                "starts at the camera: {} vs {at}, {:?} {:?}",
                path.points[0],
                bl(path.points[0], a),
                bl(at, a)
            );
            let states = mino::states_at(at, d, a, &path.tau, 1e-13);
            let mut worst: f64 = 0.0;
            for (p, s) in path.points.iter().zip(&states) {
                let c = bl(*p, a);
                let dphi = (c[2] - s[2] + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU)
                    - std::f64::consts::PI;
                // (phi is not defined on the axis, and winds as ln(r - r+)
                // at the horizon: weighted by sin theta and Delta / r^2.)
                let delta = (s[0] * s[0] - 2.0 * s[0] + a * a) / (s[0] * s[0]);
                let e = ((c[0] - s[0]) / s[0])
                    .abs()
                    .max((c[1] - s[1]).abs())
                    .max((dphi * s[1].sin() * delta.min(1.0)).abs());
                worst = worst.max(e);
            }
            assert!(worst < 1e-8, "a {a} {at} {d}: worst {worst:e}");
            kinds[match path.outcome {
                KerrOutcome::Escaped(_) => 0,
                KerrOutcome::Captured => 1,
                KerrOutcome::Disk { .. } => 2,
            }] += 1;
        }
        assert!(
            kinds.iter().all(|&k| k > 0),
            "every outcome among the rays: {kinds:?}"
        );
    }

    #[test]
    fn a_path_ends_where_its_ray_does() {
        for (a, at, d) in rays() {
            let path = path_zamo(at, d, a, DISK, 40.0, 300).expect("a path");
            let end = *path.points.last().expect("points");
            let what = format!("a {a} {at} {d}");
            match trace_zamo(at, d, a, DISK).outcome {
                KerrOutcome::Disk { r, phi, .. } => {
                    let rho = (r * r + 0.25 * a * a).sqrt();
                    let want = DVec3::new(rho * phi.cos(), 0.0, rho * phi.sin());
                    assert!((end - want).length() < 1e-9, "{what}: {end} vs {want}");
                }
                KerrOutcome::Captured => {
                    let r = bl(end, a)[0];
                    let want = (1.0 + HORIZON_STOP) * r_horizon(a);
                    assert!((r - want).abs() < 1e-9, "{what}: r {r} vs {want}");
                }
                KerrOutcome::Escaped(v) => {
                    // At 40 r_s the path runs along its asymptote to ~b / r.
                    let r = bl(end, a)[0] / 2.0;
                    assert!((r - 40.0).abs() < 1e-9, "{what}: r {r}");
                    let n = path.points.len();
                    let last = (end - path.points[n - 2]).normalize();
                    assert!(last.dot(v) > 0.99, "{what}: {last} vs {v}");
                }
            }
        }
    }

    #[test]
    fn a_ray_aimed_at_the_centre_has_a_finite_path() {
        // lambda ~ 1e-15, eta < 0: the vortical motion over the pole, whose
        // azimuth's characteristic 1 - n was 0 in f64 (a NaN path).
        let far = DVec3::new(0.5, 3.0, -15.0);
        let path = path_zamo(far, -far.normalize(), 0.9, DISK, 40.0, 200).expect("a path");
        assert!(path.points.iter().all(|p| p.is_finite()), "{path:?}");
        assert!(matches!(path.outcome, KerrOutcome::Captured));
        // Looking the other way it escapes, its direction finite too.
        let away = trace_zamo(far, far.normalize(), 0.9, DISK).outcome;
        assert!(
            matches!(away, KerrOutcome::Escaped(v) if v.is_finite()),
            "{away:?}"
        );
    }
}
