//! Light paths of a spinning hole integrated step by step in Cartesian
//! Kerr-Schild coordinates, from the metric alone: an independent reference
//! for the closed form in another formulation. Nothing here uses lambda,
//! eta, Mino time or a root of the radial quartic, and nothing divides by
//! the photon's energy, so photons with E <= 0 (inside the ergoregion) are
//! traced as any other, and the coordinates go through the horizons (they
//! are the ingoing ones).
//!
//! With M = 1 and the spin a along +Z, g_mn = eta_mn + f l_m l_n,
//! f = 2 r^3 / (r^4 + a^2 Z^2), l = (1, (r X + a Y) / (r^2 + a^2),
//! (r Y - a X) / (r^2 + a^2), Z / r), r the Boyer-Lindquist radius
//! (X^2 + Y^2) / (r^2 + a^2) + Z^2 / r^2 = 1. A null geodesic is the flow of
//! H = (eta^mn p_m p_n - f (l^m p_m)^2) / 2 (p_T = -E conserved); the
//! gradient of H in X comes from dual numbers. Boyer-Lindquist t, phi are
//! T - int 2r / Delta dr and Phi - int a / Delta dr, so p_r picks up
//! -p_t 2r / Delta - p_phi a / Delta; X + iY = (r + i a) e^(i Phi) sin(theta),
//! Z = r cos(theta). The hole's frame (x = e1, y = the spin axis, z = e2)
//! is X = x, Y = -z, Z = y.

use std::ops::{Add, Div, Mul, Sub};

use glam::DVec3;

use super::frame::{LocalFrame, r_horizon};
use super::{KerrDisk, KerrOutcome, disk_g_of_constants};

/// A number and its gradient in (X, Y, Z).
#[derive(Clone, Copy, Debug)]
pub(super) struct Dual {
    pub(super) v: f64,
    pub(super) d: DVec3,
}

impl Dual {
    pub(super) fn var(v: f64, i: usize) -> Dual {
        let mut d = DVec3::ZERO;
        d[i] = 1.0;
        Dual { v, d }
    }
    pub(super) fn c(v: f64) -> Dual {
        Dual { v, d: DVec3::ZERO }
    }
    pub(super) fn sqrt(self) -> Dual {
        let s = self.v.sqrt();
        Dual {
            v: s,
            d: self.d / (2.0 * s),
        }
    }
}

impl Add for Dual {
    type Output = Dual;
    fn add(self, o: Dual) -> Dual {
        Dual {
            v: self.v + o.v,
            d: self.d + o.d,
        }
    }
}

impl Sub for Dual {
    type Output = Dual;
    fn sub(self, o: Dual) -> Dual {
        Dual {
            v: self.v - o.v,
            d: self.d - o.d,
        }
    }
}

impl Mul for Dual {
    type Output = Dual;
    fn mul(self, o: Dual) -> Dual {
        Dual {
            v: self.v * o.v,
            d: self.d * o.v + o.d * self.v,
        }
    }
}

impl Div for Dual {
    type Output = Dual;
    fn div(self, o: Dual) -> Dual {
        Dual {
            v: self.v / o.v,
            d: (self.d * o.v - o.d * self.v) / (o.v * o.v),
        }
    }
}

/// f and l_X, l_Y, l_Z at X (with their gradients), and r: the metric's
/// parts, the one place they are written (the polarization's transport,
/// transport.rs, differentiates them too).
pub(super) fn metric_parts(x: DVec3, a: f64) -> (Dual, [Dual; 3], f64) {
    let (xx, yy, zz) = (Dual::var(x.x, 0), Dual::var(x.y, 1), Dual::var(x.z, 2));
    let a2 = Dual::c(a * a);
    let w = xx * xx + yy * yy + zz * zz - a2;
    let r2 = (w + (w * w + Dual::c(4.0 * a * a) * zz * zz).sqrt()) * Dual::c(0.5);
    let r = r2.sqrt();
    let f = Dual::c(2.0) * r2 * r / (r2 * r2 + a2 * zz * zz);
    let ra = r2 + a2;
    let ac = Dual::c(a);
    let l = [(r * xx + ac * yy) / ra, (r * yy - ac * xx) / ra, zz / r];
    (f, l, r.v)
}

/// f and l_s . p at X (with their gradients), and r.
fn field(x: DVec3, p: DVec3, a: f64) -> (Dual, Dual, f64) {
    let (f, [lx, ly, lz], r) = metric_parts(x, a);
    (
        f,
        lx * Dual::c(p.x) + ly * Dual::c(p.y) + lz * Dual::c(p.z),
        r,
    )
}

/// The backward flow at (X, p): dX/ds = -dH/dp, dp/ds = dH/dX.
pub(super) fn backward(x: DVec3, p: DVec3, p_t: f64, a: f64) -> (DVec3, DVec3) {
    let (f, lp, r) = field(x, p, a);
    let q = -p_t + lp.v;
    // l_s: the gradient of l_s . p in p.
    let ra = r * r + a * a;
    let l = DVec3::new((r * x.x + a * x.y) / ra, (r * x.y - a * x.x) / ra, x.z / r);
    let dh_dp = p - f.v * q * l;
    let dh_dx = -0.5 * (f.d * q * q + 2.0 * f.v * q * lp.d);
    (-dh_dp, dh_dx)
}

fn rk4(x: DVec3, p: DVec3, p_t: f64, a: f64, h: f64) -> (DVec3, DVec3) {
    let (k1x, k1p) = backward(x, p, p_t, a);
    let (k2x, k2p) = backward(x + 0.5 * h * k1x, p + 0.5 * h * k1p, p_t, a);
    let (k3x, k3p) = backward(x + 0.5 * h * k2x, p + 0.5 * h * k2p, p_t, a);
    let (k4x, k4p) = backward(x + h * k3x, p + h * k3p, p_t, a);
    (
        x + h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x),
        p + h / 6.0 * (k1p + 2.0 * k2p + 2.0 * k3p + k4p),
    )
}

/// Boyer-Lindquist r of a Kerr-Schild point.
pub(super) fn bl_r(x: DVec3, a: f64) -> f64 {
    let w = x.length_squared() - a * a;
    (0.5 * (w + (w * w + 4.0 * a * a * x.z * x.z).sqrt())).sqrt()
}

/// int a / Delta dr, zero at infinity: Phi - phi_BL.
pub(super) fn phi_shift(r: f64, a: f64) -> f64 {
    if a == 0.0 {
        return 0.0;
    }
    let s = (1.0 - a * a).sqrt();
    let (rp, rm) = (1.0 + s, 1.0 - s);
    a / (rp - rm) * ((r - rp) / (r - rm)).abs().ln()
}

/// A photon's Boyer-Lindquist covector per unit of the frequency its
/// observer sees: p_t = -energy, p_r, p_theta, p_phi.
#[derive(Clone, Copy, Debug)]
pub struct Photon {
    pub energy: f64,
    pub p_r: f64,
    pub p_th: f64,
    pub p_phi: f64,
}

/// The photon seen along the unit direction `d` by the ZAMO of frame `f`:
/// k = e_t - d in its tetrad.
fn zamo_photon(f: &LocalFrame, d: DVec3) -> Photon {
    let (dr, dth, dph) = (d.dot(f.e_r), d.dot(f.e_theta), d.dot(f.e_phi));
    Photon {
        energy: f.alpha - f.omega * f.varpi * dph,
        p_r: -(f.sigma / f.delta).sqrt() * dr,
        p_th: -f.sigma.sqrt() * dth,
        p_phi: -f.varpi * dph,
    }
}

/// The photon seen along `d` by the observer falling from rest at
/// infinity (E = 1, L = 0, Q = 0), at `f`, outside or between the horizons:
/// k = u - d on its frame ([`falling_covector`]). The pixel's components
/// come through the flat oblate triad, as for every observer.
pub fn falling_photon(f: &LocalFrame, d: DVec3, a: f64) -> Photon {
    let k = falling_covector(f, a, 1.0, -d);
    Photon {
        energy: -k[0],
        p_r: k[1],
        p_th: k[2],
        p_phi: k[3],
    }
}

/// The Boyer-Lindquist covector (t, r, theta, phi) of the vector v0 u +
/// v_r e_r + v_theta e_theta + v_phi e_phi of the observer falling from
/// rest at infinity at `f` (v's parts on the flat triad there), outside or
/// between the horizons: its frame e_theta = d_theta / sqrt(Sigma), e_phi =
/// d_phi / sqrt(g_phiphi) and e_r orthogonal to u, e_theta and e_phi with
/// dr(e_r) > 0 (the falling frame of docs/inside-the-horizon.md), built from
/// the metric's components.
pub fn falling_covector(f: &LocalFrame, a: f64, v0: f64, v: DVec3) -> [f64; 4] {
    let (r, s2) = (f.r, f.sin_theta * f.sin_theta);
    let (sigma, delta) = (f.sigma, f.delta);
    let big_a = (r * r + a * a).powi(2) - a * a * delta * s2;
    // Boyer-Lindquist metric (t, r, theta, phi), nonzero parts.
    let (g_tt, g_tp, g_pp) = (
        -(1.0 - 2.0 * r / sigma),
        -2.0 * a * r * s2 / sigma,
        big_a * s2 / sigma,
    );
    let (g_rr, g_hh) = (sigma / delta, sigma);
    // u: u_t = -1, u_r from the geodesic, dr/dtau = -sqrt(2 r (r^2 + a^2)) / Sigma.
    let ur_up = -(2.0 * r * (r * r + a * a)).sqrt() / sigma;
    let u_r = g_rr * ur_up;
    let det = g_tt * g_pp - g_tp * g_tp;
    let (u_t_up, u_p_up) = (-g_pp / det, g_tp / det); // g^tt (-1), g^tphi (-1)
    // e_r = c (u_r d_t + d_r - u_r (g_tphi / g_phiphi) d_phi), normalised.
    let (ct, cp) = (u_r, -u_r * g_tp / g_pp);
    let norm = (ct * ct * g_tt + 2.0 * ct * cp * g_tp + cp * cp * g_pp + g_rr).sqrt();
    let e_r = [ct / norm, 1.0 / norm, 0.0, cp / norm];
    let (vr, vth, vph) = (v.dot(f.e_r), v.dot(f.e_theta), v.dot(f.e_phi));
    let k = [
        v0 * u_t_up + vr * e_r[0],
        v0 * ur_up + vr * e_r[1],
        vth / g_hh.sqrt(),
        v0 * u_p_up + vr * e_r[3] + vph / g_pp.sqrt(),
    ];
    [
        g_tt * k[0] + g_tp * k[3],
        g_rr * k[1],
        g_hh * k[2],
        g_tp * k[0] + g_pp * k[3],
    ]
}

/// A Boyer-Lindquist covector (t, r, theta, phi) at frame `f` as a
/// Kerr-Schild one (T, X, Y, Z): ingoing T = t + int 2r / Delta, Phi = phi
/// + int a / Delta move a part of v_t and v_phi onto v_r.
pub(super) fn schild_covector(f: &LocalFrame, a: f64, v: [f64; 4]) -> [f64; 4] {
    let vr_ks = v[1] - (v[0] * 2.0 * f.r + v[3] * a) / f.delta;
    let (_, to_cartesian) = kerr_schild_start(f, a);
    let c = to_cartesian * DVec3::new(vr_ks, v[2], v[3]);
    [v[0], c.x, c.y, c.z]
}

/// The Kerr-Schild point of frame `f` and the map from a covector's
/// (r, theta, Phi) parts to its Cartesian ones (the inverse of the
/// Jacobian's transpose).
pub(super) fn kerr_schild_start(f: &LocalFrame, a: f64) -> (DVec3, glam::DMat3) {
    let big_phi = f.phi + phi_shift(f.r, a);
    let (st, ct) = (f.sin_theta, f.cos_theta);
    let (sp, cp) = big_phi.sin_cos();
    let x0 = DVec3::new((f.r * cp - a * sp) * st, (f.r * sp + a * cp) * st, f.r * ct);
    let d_r = DVec3::new(cp * st, sp * st, ct);
    let d_th = DVec3::new(
        (f.r * cp - a * sp) * ct,
        (f.r * sp + a * cp) * ct,
        -f.r * st,
    );
    let d_ph = DVec3::new(-(f.r * sp + a * cp) * st, (f.r * cp - a * sp) * st, 0.0);
    // p_cart solves J^T p_cart = (p_r, p_theta, p_Phi).
    let jt = glam::DMat3::from_cols(d_r, d_th, d_ph).transpose();
    (x0, jt.inverse())
}

/// Who holds the camera of [`trace_schild`].
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum SchildObserver {
    Zamo,
    /// Falling from rest at infinity: outside or between the horizons.
    Falling,
}

/// The backward ray of a ZAMO camera at `position` (r_s, hole frame) along
/// the unit direction `d` (the ZAMO's frame, hole-frame axes through the
/// flat triad), spin `spin`, to the sky, the horizon or the thin `disk`.
pub fn trace_schild(position: DVec3, d: DVec3, spin: f64, disk: Option<KerrDisk>) -> KerrOutcome {
    trace_schild_as(SchildObserver::Zamo, position, d, spin, disk).unwrap_or(KerrOutcome::Captured)
}

/// The same for a camera of `observer`; a falling camera may stand between
/// the horizons, and then None is light from the other universe (the
/// backward ray runs into the horizon it cannot cross in these ingoing
/// coordinates: that of the eternal hole's second exterior).
pub fn trace_schild_as(
    observer: SchildObserver,
    position: DVec3,
    d: DVec3,
    spin: f64,
    disk: Option<KerrDisk>,
) -> Option<KerrOutcome> {
    let a = spin;
    let f = LocalFrame::at(2.0 * position, a);
    let d = d.normalize();
    let ph = match observer {
        SchildObserver::Zamo => zamo_photon(&f, d),
        SchildObserver::Falling => falling_photon(&f, d, a),
    };
    let (energy, p_phi, p_th) = (ph.energy, ph.p_phi, ph.p_th);
    // Ingoing: p_r picks up -p_t 2r / Delta - p_phi a / Delta.
    let p_r = ph.p_r + (2.0 * f.r * energy - a * p_phi) / f.delta;
    let horizon = r_horizon(a);
    let (x0, to_cartesian) = kerr_schild_start(&f, a);
    let p0 = to_cartesian * DVec3::new(p_r, p_th, p_phi);
    let p_t = -energy;
    let (mut x, mut p) = (x0, p0);
    // Between the horizons the backward ray leaves through one of them: the
    // future horizon of our exterior, where these ingoing coordinates are
    // regular and it crosses at the radial rate P(r+) / Sigma, or that of
    // the eternal hole's second exterior, at their edge, which it nears as
    // its rate there falls to zero: P(r+) = E (r+^2 + a^2) - a L <= 0.
    if f.r < horizon && energy * (horizon * horizon + a * a) - a * p_phi <= 0.0 {
        return None;
    }
    for _ in 0..400_000 {
        let r = bl_r(x, a);
        let (vx, _) = backward(x, p, p_t, a);
        if r > 1e6 {
            let v = vx.normalize();
            return Some(KerrOutcome::Escaped(DVec3::new(v.x, v.z, -v.y)));
        }
        // Moving inward within 1% of the horizon from outside: the photon
        // came out of it (these ingoing coordinates reach the past horizon
        // only in the limit, winding in Phi; a path turns around that close
        // only where P(r+) = E (r+^2 + a^2) - a L nearly vanishes, an edge).
        if r > horizon && r < horizon * 1.01 && vx.dot(x) < 0.0 {
            return Some(KerrOutcome::Captured);
        }
        let h = 2e-3 * r.min((r - horizon).max(1e-3) * 50.0) / vx.length().max(1e-300);
        let (nx, np) = rk4(x, p, p_t, a, h);
        // (A camera in the disk's plane does not see its own point.)
        if let Some(disk) = disk
            && x.z != 0.0
            && (x.z > 0.0) != (nx.z > 0.0)
        {
            let (mut lo, mut hi) = (0.0, h);
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if (rk4(x, p, p_t, a, mid).0.z > 0.0) == (x.z > 0.0) {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            let (cx, _) = rk4(x, p, p_t, a, 0.5 * (lo + hi));
            let rc = bl_r(cx, a);
            if (2.0 * disk.inner..=2.0 * disk.outer).contains(&rc) {
                let phi_bl = cx.y.atan2(cx.x) - a.atan2(rc) - phi_shift(rc, a);
                return Some(KerrOutcome::Disk {
                    r: rc / 2.0,
                    phi: (-phi_bl.sin()).atan2(phi_bl.cos()),
                    g: disk_g_of_constants(rc, a, energy, p_phi),
                    crossings_before: 0,
                });
            }
        }
        (x, p) = (nx, np);
    }
    Some(KerrOutcome::Captured)
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::kerr::{same_outcome, trace_zamo};
    use crate::physics::sphere_direction;

    /// For photons of E > 0 the integrated paths and the closed form agree
    /// (sky direction, disk radius, azimuth and g to 1e-6), over cameras
    /// far out, near the hole and in the ergoregion of several spins: the
    /// coordinates, the covector's transformation and the disk's g are
    /// right. Near-edge pixels (a 1e-6 turn changes the closed form's
    /// outcome) are left out.
    #[test]
    fn integrated_paths_meet_the_closed_form_for_positive_energy() {
        let mut compared = [0usize; 3];
        for (spin, at) in [
            (0.9, DVec3::new(1.0, 2.0, -10.0)),
            (0.5, DVec3::new(0.3, 0.5, -3.0)),
            (-0.7, DVec3::new(2.0, -1.0, -6.0)),
            (0.99, DVec3::new(0.7, 0.1, 0.2)),
        ] {
            let disk = Some(KerrDisk {
                inner: crate::physics::kerr::r_isco(spin) / 2.0,
                outer: 8.0,
            });
            for k in 0..120 {
                let d = sphere_direction(k, 120);
                let want = trace_zamo(at, d, spin, disk);
                if want.lambda.is_nan() {
                    continue; // E <= 0: the next test's
                }
                let near = trace_zamo(at, (d + 1e-6 * DVec3::X).normalize(), spin, disk);
                if std::mem::discriminant(&near.outcome) != std::mem::discriminant(&want.outcome) {
                    continue;
                }
                let what = format!("{spin} {at} {d}: integrated vs closed form");
                compared[same_outcome(trace_schild(at, d, spin, disk), want.outcome, &what)] += 1;
            }
        }
        assert!(compared.iter().all(|&n| n > 10), "{compared:?}");
    }

    /// Photons with E < 0, seen from inside the ergoregion of holes that
    /// spin fast enough for the disk to reach into it (a* > 0.943): the
    /// closed form with the azimuth turned the other way meets the
    /// integrated paths, which know nothing of E's sign; they come from the
    /// disk or the horizon, never from the sky.
    #[test]
    fn negative_energy_photons_come_from_the_disk_or_the_horizon() {
        let mut seen = [0usize; 2];
        for (spin, at) in [
            // Boyer-Lindquist r = 0.74 rs above the disk; then 0.66 and
            // 0.64 rs (world distances 0.89, 0.83 and 0.81 rs).
            (0.99, DVec3::new(0.0, 0.1, -0.885)),
            (0.998, DVec3::new(0.8, 0.1, 0.2)),
            (0.998, DVec3::new(0.4, -0.05, -0.7)),
        ] {
            let disk = Some(KerrDisk {
                inner: crate::physics::kerr::r_isco(spin) / 2.0,
                outer: 8.0,
            });
            let frame = LocalFrame::at(2.0 * at, spin);
            for k in 0..2000 {
                let d = sphere_direction(k, 2000);
                let energy = frame.alpha - frame.omega * frame.varpi * d.dot(frame.e_phi);
                assert!(energy.is_finite(), "{spin} {at}: outside the horizon");
                if energy >= 0.0 {
                    continue;
                }
                let want = trace_zamo(at, d, spin, disk).outcome;
                let near = trace_zamo(at, (d + 1e-6 * DVec3::X).normalize(), spin, disk);
                if std::mem::discriminant(&near.outcome) != std::mem::discriminant(&want) {
                    continue;
                }
                let what = format!("{spin} {at} {d}: integrated vs closed form");
                match same_outcome(trace_schild(at, d, spin, disk), want, &what) {
                    0 => panic!("{what}: E < 0 from the sky"),
                    k => seen[k - 1] += 1,
                }
            }
        }
        assert!(seen[0] > 20 && seen[1] > 20, "{seen:?}");
    }

    /// At a = 0 the Kerr-Schild integration of a falling camera's rays and
    /// the Painleve-Gullstrand one (physics/river.rs) are two independent
    /// formulations of the same light paths: they agree outside, at and
    /// inside the horizon, on the sky, the disk and the other universe.
    #[test]
    fn falling_cameras_agree_with_the_river_at_zero_spin() {
        use crate::physics::river::{RiverDisk, RiverOutcome, trace_rain_to};
        let disk = KerrDisk {
            inner: 3.0,
            outer: 12.0,
        };
        let river_disk = Some(RiverDisk {
            inner: 3.0,
            outer: 12.0,
        });
        let mut seen = [0usize; 4];
        for r in [2.5, 1.001, 0.999, 0.5, 0.1] {
            let at = DVec3::new(0.0, 0.3 * r, -r * 0.91f64.sqrt());
            for k in 0..150 {
                let d = sphere_direction(k, 150);
                let river = trace_rain_to(1.0, at, d, river_disk);
                let near = trace_rain_to(1.0, at, (d + 1e-6 * DVec3::X).normalize(), river_disk);
                if std::mem::discriminant(&near) != std::mem::discriminant(&river) {
                    continue;
                }
                let got = trace_schild_as(SchildObserver::Falling, at, d, 0.0, Some(disk));
                match (got, river) {
                    (None, RiverOutcome::OtherUniverse) => seen[3] += 1,
                    (Some(KerrOutcome::Captured), RiverOutcome::Captured) => seen[1] += 1,
                    (Some(KerrOutcome::Escaped(a)), RiverOutcome::Escaped(b)) => {
                        assert!((a - b).length() < 1e-6, "r {r} {d}: {a} vs {b}");
                        seen[0] += 1;
                    }
                    (
                        Some(KerrOutcome::Disk { r: rc, phi, g, .. }),
                        RiverOutcome::Disk {
                            r: r2,
                            phi: p2,
                            g: g2,
                        },
                    ) => {
                        assert!(
                            (rc - r2).abs() < 1e-6
                                && (phi - p2).abs() < 1e-6
                                && (g - g2).abs() < 1e-6,
                            "r {r} {d}: {rc} {phi} {g} vs {r2} {p2} {g2}"
                        );
                        seen[2] += 1;
                    }
                    (a, b) => panic!("r {r} {d}: Kerr-Schild {a:?}, river {b:?}"),
                }
            }
        }
        assert!(seen.iter().all(|&n| n > 10), "{seen:?}");
    }

    /// A falling camera between the horizons of a spinning hole (the frame
    /// of the falling observer, built here from the metric): the
    /// backward rays with P(r+) > 0 cross the horizon into our exterior
    /// (these coordinates are regular there) and end at the sky or back in
    /// the hole; those with P(r+) < 0 came from the other universe; both
    /// kinds are seen.
    #[test]
    fn between_the_horizons_p_of_r_plus_decides_the_universe() {
        let a = 0.9;
        let rp = r_horizon(a);
        let mut seen = [0usize; 2];
        for at in [DVec3::new(0.0, 0.2, -0.6), DVec3::new(0.5, -0.1, 0.3)] {
            let f = LocalFrame::at(2.0 * at, a);
            assert!(f.r < rp && f.r > 2.0 - rp, "between the horizons: {}", f.r);
            for k in 0..200 {
                let d = sphere_direction(k, 200);
                let ph = falling_photon(&f, d, a);
                let big_p = ph.energy * (rp * rp + a * a) - a * ph.p_phi;
                if big_p.abs() < 1e-2 {
                    continue;
                }
                let got = trace_schild_as(SchildObserver::Falling, at, d, a, None);
                assert_eq!(
                    got.is_none(),
                    big_p < 0.0,
                    "{at} {d}: P(r+) {big_p}, {got:?}"
                );
                if let Some(end) = got {
                    assert!(
                        matches!(end, KerrOutcome::Escaped(_) | KerrOutcome::Captured),
                        "{end:?}"
                    );
                }
                seen[usize::from(big_p > 0.0)] += 1;
            }
        }
        assert!(seen.iter().all(|&n| n > 20), "{seen:?}");
    }

    /// Outside the horizon the falling frame built here from the metric is
    /// the one the renderer uses for a falling camera (the ZAMO's frame
    /// after aberration by the fall, physics/kerr/frame.rs): a pixel's
    /// photon has the same covector, up to the ratio of the two observers'
    /// frequencies (the Doppler factor), to 1e-12.
    #[test]
    fn the_falling_frame_outside_is_the_aberrated_zamo_frame() {
        use crate::physics::kerr::{KerrObserver, observer_velocity, to_zamo_frame};
        for (a, at) in [
            (0.9, DVec3::new(1.0, 2.0, -4.0)),
            (0.99, DVec3::new(0.0, 0.1, -0.885)),
            (-0.5, DVec3::new(3.0, -1.0, 1.0)),
        ] {
            let f = LocalFrame::at(2.0 * at, a);
            let beta = observer_velocity(KerrObserver::Falling, 2.0 * at, a).expect("outside");
            for k in 0..50 {
                let d = sphere_direction(k, 50);
                let (dz, doppler) = to_zamo_frame(d, beta);
                let z = zamo_photon(&f, dz);
                let fall = falling_photon(&f, d, a);
                let (mine, theirs) = (
                    [fall.energy, fall.p_r, fall.p_th, fall.p_phi],
                    [z.energy, z.p_r, z.p_th, z.p_phi].map(|v| v / doppler),
                );
                for (x, y) in mine.iter().zip(theirs) {
                    assert!(
                        (x - y).abs() < 1e-12 * (1.0 + y.abs()),
                        "{a} {at} {d}: {mine:?} vs {theirs:?}"
                    );
                }
            }
        }
    }
}
