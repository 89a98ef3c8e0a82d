//! A falling camera between a spinning hole's horizons, in f64: the closed
//! form continued through the outer horizon. The photon's constants come
//! from the falling frame built from the metric (schild.rs,
//! `falling_photon`); r(tau) and theta(tau) are the exterior's closed forms
//! (Radial, Angular: no root lies between the horizons, so the backward ray,
//! which moves outward there, runs on the same branch through r+); the
//! azimuth is carried in its ingoing form phi~ = phi + a / (r+ - r-)
//! ln|(r - r+) / (r - r-)|, whose radial rate along an outward backward
//! path, a (sqrt(R) - s_E (2r - a lambda)) / Delta, is finite at r+ and is
//! taken as a (2 (2r - a lambda) + Delta - eta - (lambda - a)^2) /
//! (sqrt(R) + s_E (2r - a lambda)) there; it is integrated in Mino time
//! (adaptive Gauss-Legendre), the polar part in closed form. A path that
//! leaves through the other universe's horizon (P(r+) <= 0) is None.

use glam::DVec3;

use super::angular::{Ordinary, Vortical};
use super::frame::{LocalFrame, r_horizon};
use super::radial::{Radial, adaptive_gauss, r_potential};
use super::schild::{Photon, falling_photon};
use super::{KerrDisk, KerrOutcome, disk_g_of_constants, first_disk_crossing};

/// ln|(r - r+) / (r - r-)| a / (r+ - r-): phi~ - phi.
fn ingoing_shift(r: f64, a: f64) -> f64 {
    if a == 0.0 || r.is_infinite() {
        return 0.0;
    }
    let s = (1.0 - a * a).sqrt();
    a / (2.0 * s) * ((r - 1.0 - s) / (r - 1.0 + s)).abs().ln()
}

/// The polar motion of either kind.
enum Polar {
    Ordinary(Ordinary),
    Vortical(Vortical),
}

impl Polar {
    fn cos_theta_at(&self, tau: f64) -> f64 {
        match self {
            Polar::Ordinary(o) => o.cos_theta_at(tau),
            Polar::Vortical(v) => v.cos_theta_at(tau),
        }
    }
    fn lambda_g_phi(&self, lambda: f64, tau: f64) -> f64 {
        match self {
            Polar::Ordinary(o) => o.lambda_g_phi(lambda, tau),
            Polar::Vortical(v) => v.lambda_g_phi(lambda, tau),
        }
    }
}

/// The photon of the camera falling from rest at infinity at `f`, seen
/// along `d` (its frame through the flat triad), and its constants.
pub(crate) struct FallingRay {
    pub photon: Photon,
    pub lambda: f64,
    pub eta: f64,
    /// The backward ray's polar sign (against p_theta) and (p_theta / E)^2.
    pub s_th: f64,
    pub theta_potential: f64,
}

/// [`FallingRay`] at `f`, outside or between the horizons; None at E = 0
/// and, between the horizons, for light from the other universe (P(r+) = E
/// (r+^2 + a^2) - a L <= 0).
pub(crate) fn falling_ray(f: &LocalFrame, d: DVec3, a: f64) -> Option<FallingRay> {
    let ph = falling_photon(f, d, a);
    let (rp, e, l) = (r_horizon(a), ph.energy, ph.p_phi);
    if e == 0.0 || (f.r < rp && e * (rp * rp + a * a) - a * l <= 0.0) {
        return None;
    }
    let (c2, s2) = (f.cos_theta * f.cos_theta, f.sin_theta * f.sin_theta);
    Some(FallingRay {
        photon: ph,
        lambda: l / e,
        eta: (ph.p_th * ph.p_th + c2 * (l * l / s2 - a * a * e * e)) / (e * e),
        s_th: -1f64.copysign(ph.p_th),
        theta_potential: (ph.p_th / e).powi(2),
    })
}

/// The backward ray of a falling camera at `position` (r_s, hole frame,
/// between the horizons, where every backward ray moves outward) along the unit direction `d` (its
/// frame through the flat triad), spin `spin`: the sky, the horizon, the
/// thin `disk`, or None for the other universe.
pub fn trace_falling_inside(
    position: DVec3,
    d: DVec3,
    spin: f64,
    disk: Option<KerrDisk>,
) -> Option<KerrOutcome> {
    let a = spin;
    let f = LocalFrame::at(2.0 * position, a);
    let FallingRay {
        photon: ph,
        lambda,
        eta,
        s_th,
        theta_potential,
    } = falling_ray(&f, d.normalize(), a)?;
    let (e, l) = (ph.energy, ph.p_phi);
    let turn = e.signum();
    let rad = Radial::new(a, lambda, eta, f.r, 1.0);
    let polar = if eta > 0.0 {
        Polar::Ordinary(Ordinary::new(
            a,
            lambda,
            eta,
            f.cos_theta,
            theta_potential,
            s_th,
        ))
    } else {
        Polar::Vortical(Vortical::new(a, lambda, eta, f.cos_theta, s_th))
    };
    // phi~'s radial rate along the backward path, at Mino time t.
    let rate = |t: f64| {
        let h = 1e-7 * (1.0 + t);
        let r = rad.r_at(t);
        if !r.is_finite() || r > 1e12 {
            return a; // the rate's limit at infinity
        }
        let ahead = rad.r_at((t + h).min(rad.tau_end));
        let out = !(ahead.is_finite() && ahead < rad.r_at((t - h).max(0.0)));
        let sq = r_potential(r, a, lambda, eta).max(0.0).sqrt();
        let x = 2.0 * r - a * lambda;
        let delta = r * r - 2.0 * r + a * a;
        if out && delta.abs() < 0.1 {
            a * (2.0 * x + delta - eta - (lambda - a).powi(2)) / (sq + turn * x)
        } else {
            a * ((if out { sq } else { -sq }) - turn * x) / delta
        }
    };
    let phi_at = |t: f64, r_end: f64| {
        let radial = adaptive_gauss(&rate, 0.0, t, 1e-13, 30);
        f.phi + ingoing_shift(f.r, a) + radial
            - turn * polar.lambda_g_phi(lambda, t)
            - ingoing_shift(r_end, a)
    };
    if let Polar::Ordinary(ang) = &polar
        && let Some((n, tc, rc)) = first_disk_crossing(&rad, ang, disk)
    {
        let phi = phi_at(tc, rc);
        return Some(KerrOutcome::Disk {
            r: rc / 2.0,
            phi: (-phi.sin()).atan2(phi.cos()),
            g: disk_g_of_constants(rc, a, e, l),
            crossings_before: n,
        });
    }
    if rad.captured || turn < 0.0 {
        return Some(KerrOutcome::Captured);
    }
    let t = rad.tau_end;
    let cos_th = polar.cos_theta_at(t);
    let phi = phi_at(t, f64::INFINITY);
    let sin_th = (1.0 - cos_th * cos_th).max(0.0).sqrt();
    Some(KerrOutcome::Escaped(DVec3::new(
        sin_th * phi.cos(),
        cos_th,
        -sin_th * phi.sin(),
    )))
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::kerr::same_outcome;
    use crate::physics::kerr::schild::{SchildObserver, trace_schild_as};
    use crate::physics::sphere_direction;

    /// Between the horizons of a* = 0.9, down to 1.002 r-, the closed form
    /// continued through r+ meets the Kerr-Schild integration: the same
    /// universe, and sky direction, disk radius, azimuth and g to 1e-6.
    #[test]
    fn the_closed_form_through_the_horizon_meets_the_integration() {
        let a = 0.9;
        let disk = Some(KerrDisk {
            inner: crate::physics::kerr::r_isco(a) / 2.0,
            outer: 8.0,
        });
        let mut seen = [0usize; 4];
        // Boyer-Lindquist r = 0.83, 0.77 (0.8 r+ and below), 0.61 M (1.07
        // r-) and 0.5652 M (1.002 r-): r+ = 1.436, r- = 0.564.
        for at in [
            DVec3::new(0.0, 0.2, -0.6),
            DVec3::new(0.5, -0.1, 0.3),
            DVec3::new(0.0, 0.05, -0.54),
            DVec3::new(0.0, 0.077_504_939_785, -0.511_015_902_982),
        ] {
            let r = LocalFrame::at(2.0 * at, a).r;
            assert!(r < r_horizon(a) && r > 2.0 - r_horizon(a), "{at}: r = {r}");
            for k in 0..150 {
                let d = sphere_direction(k, 150);
                let near = trace_schild_as(
                    SchildObserver::Falling,
                    at,
                    (d + 1e-6 * DVec3::X).normalize(),
                    a,
                    disk,
                );
                let want = trace_schild_as(SchildObserver::Falling, at, d, a, disk);
                if near.map(|o| std::mem::discriminant(&o))
                    != want.map(|o| std::mem::discriminant(&o))
                {
                    continue;
                }
                let what = format!("{at} {d}: closed form vs integrated");
                match (trace_falling_inside(at, d, a, disk), want) {
                    (None, None) => seen[3] += 1,
                    (Some(x), Some(y)) => seen[same_outcome(x, y, &what)] += 1,
                    (x, y) => panic!("{what}: {x:?} vs {y:?}"),
                }
            }
        }
        println!("escaped, disk, captured, other universe: {seen:?}");
        assert!(seen[0] > 10 && seen[3] > 10, "{seen:?}");
    }
}
