//! The thin disk's Stokes parameters seen by the camera falling from rest
//! at infinity between a spinning hole's horizons, or just outside them
//! (within `FALLING_FRAME_BAND` of r+), on its own frame: the photon from
//! that frame (schild.rs, `falling_photon`), the path continued through r+
//! as interior.rs does, the emission as outside, and the Walker-Penrose
//! constant solved at the camera on the falling frame.
//!
//! No ZAMO exists there, and Boyer-Lindquist components of the falling
//! frame grow as 1 / Delta at r+. The constant's parts have the same form
//! in ingoing Kerr coordinates (v, r, theta, phi~), dv = dt + (r^2 + a^2) /
//! Delta dr, dphi~ = dphi + a / Delta dr: X = v^t - a sin^2 v^phi gains
//! -(Sigma / Delta) v^r, which cancels in A = X(p) Y(f) - Y(p) X(f), and
//! Z = (r^2 + a^2) v^phi - a v^t is unchanged. In those coordinates every
//! axis of the falling frame is finite through r+ ([`falling_parts`]).

use glam::DVec3;

use super::super::angular::Ordinary;
use super::super::frame::{LocalFrame, r_horizon};
use super::super::interior::{FallingRay, falling_ray};
use super::super::radial::Radial;
use super::super::{KerrDisk, disk_g_of_constants, first_disk_crossing};
use super::{equatorial_photon, polar_sign_at};
use crate::physics::polarization::{
    Emission, Seen, Stokes, Zamo, angle_of, emit, emitted_intensity, sky_basis, walker_penrose,
};
use num_complex::Complex64;

/// The falling frame's axes u, e_r, e_theta, e_phi at Boyer-Lindquist (r,
/// cos theta = c) of spin a as the parts of the Walker-Penrose constant, in
/// ingoing Kerr components: [X, Y, sin(theta) Z, W] with X = v^v - a sin^2
/// v^phi~, Y = v^r, Z = (r^2 + a^2) v^phi~ - a v^v, W = v^theta. With q =
/// sqrt(r^2 + a^2), f = sqrt(2 r) (u^r = -q f / Sigma) and Delta = (q -
/// f)(q + f), every 1 / Delta cancels: X(u) = q / (q + f), Z(u) = -a,
/// X(e_r) = (q^3 - a^2 s^2 (q + f)) / ((q + f) sqrt(A)), Z(e_r) = a q f /
/// sqrt(A).
pub fn falling_parts(r: f64, c: f64, a: f64) -> [[f64; 4]; 4] {
    let s = (1.0 - c * c).max(0.0).sqrt();
    let q = (r * r + a * a).sqrt();
    let fall = (2.0 * r).sqrt();
    let sigma = r * r + a * a * c * c;
    let delta = r * r - 2.0 * r + a * a;
    let big_a = q.powi(4) - a * a * delta * s * s;
    let (sa, k) = (big_a.sqrt(), (sigma / big_a).sqrt());
    [
        [q / (q + fall), -q * fall / sigma, -a * s, 0.0],
        [
            (q.powi(3) - a * a * s * s * (q + fall)) / ((q + fall) * sa),
            sa / sigma,
            s * a * q * fall / sa,
            0.0,
        ],
        [0.0, 0.0, 0.0, 1.0 / sigma.sqrt()],
        [-a * s * k, 0.0, q * q * k, 0.0],
    ]
}

/// The Walker-Penrose constant of p and f, given on the falling frame (v0,
/// v_r, v_theta, v_phi) at (r, c) of spin a: finite through r+.
pub fn falling_kappa(r: f64, c: f64, a: f64, p: [f64; 4], f: [f64; 4]) -> Complex64 {
    let axes = falling_parts(r, c, a);
    let part = |v: [f64; 4], j: usize| (0..4).map(|i| v[i] * axes[i][j]).sum::<f64>();
    let big_a = part(p, 0) * part(f, 1) - part(p, 1) * part(f, 0);
    let big_b = part(p, 2) * part(f, 3) - part(p, 3) * part(f, 2);
    Complex64::new(big_a, -big_b) * Complex64::new(r, -a * c)
}

/// The Stokes parameters of the pixel along `d` (unit, the falling frame,
/// hole-frame axes) of the falling camera at `position` (rs) with up `up`:
/// zero unless the ray ends on the disk (nothing from the other universe).
pub fn stokes_falling(
    position: DVec3,
    d: DVec3,
    up: DVec3,
    a: f64,
    disk: KerrDisk,
    em: &Emission,
) -> Seen {
    let f = LocalFrame::at(2.0 * position, a);
    let Some(FallingRay {
        photon: ph,
        lambda,
        eta,
        s_th,
        theta_potential,
    }) = falling_ray(&f, d, a)
    else {
        return Seen::default();
    };
    if eta <= 0.0 {
        return Seen::default();
    }
    let (e, l) = (ph.energy, ph.p_phi);
    // Backward: outward between the horizons; outside against the photon's
    // dr (p_r = g_rr p^r, g_rr > 0 there).
    let s_r = if f.r < r_horizon(a) || ph.p_r < 0.0 {
        1.0
    } else {
        -1.0
    };
    let rad = Radial::new(a, lambda, eta, f.r, s_r);
    let ang = Ordinary::new(a, lambda, eta, f.cos_theta, theta_potential, s_th);
    let Some((n, tc, rc)) = first_disk_crossing(&rad, &ang, Some(disk)) else {
        return Seen::default();
    };
    let ze = Zamo::at(rc, 0.0, a);
    let pe = equatorial_photon(
        &ze,
        lambda,
        eta,
        rad.backward_r_sign(tc),
        polar_sign_at(&ang, n),
        e.signum(),
    );
    let emitted = emit(&ze, pe, em.field);
    let g = disk_g_of_constants(rc, a, e, l);
    let i = g.powf(3.0 + em.spectral_index) * emitted_intensity(em, rc, emitted.sin_b, emitted.k_z);
    if i == 0.0 {
        return Seen::default();
    }
    let kappa = walker_penrose(&ze, pe, emitted.f);
    let (nn, ww) = sky_basis(d, up);
    let on = |v0: f64, v: DVec3| [v0, v.dot(f.e_r), v.dot(f.e_theta), v.dot(f.e_phi)];
    let (r, c, p) = (f.r, f.cos_theta, on(1.0, -d));
    let chi = angle_of(
        kappa,
        falling_kappa(r, c, a, p, on(0.0, nn)),
        falling_kappa(r, c, a, p, on(0.0, ww)),
    );
    Seen {
        stokes: Stokes::linear(i, em.fraction, chi),
        sin_b: emitted.sin_b,
        k_z: emitted.k_z,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::kerr::schild::falling_covector;
    use crate::physics::polarization::walker_penrose_coordinates;

    /// The falling frame's parts in ingoing coordinates give the constant
    /// of its Boyer-Lindquist components (built from the metric, schild.rs)
    /// by the definition, outside, in the band and between the horizons.
    #[test]
    fn the_falling_frames_parts_are_its_constant() {
        for (a, at) in [
            (0.9, DVec3::new(0.3, 0.2, -0.5)),
            (0.9, DVec3::new(1.0, -0.4, 2.0)),
            (0.0, DVec3::new(0.2, 0.3, 0.3)),
            (-0.7, DVec3::new(0.5, 0.45, 0.1)),
            (0.99, DVec3::new(0.0, 0.5, -0.05)),
        ] {
            let f = LocalFrame::at(2.0 * at, a);
            // Boyer-Lindquist components from the covector: raise by hand.
            let raise = |v: [f64; 4]| {
                let (r, s2, sig, del) = (f.r, f.sin_theta.powi(2), f.sigma, f.delta);
                let big_a = (r * r + a * a).powi(2) - a * a * del * s2;
                let (g_tt, g_tp, g_pp) = (
                    -big_a / (sig * del),
                    -2.0 * a * r / (sig * del),
                    (del - a * a * s2) / (sig * del * s2),
                );
                [
                    g_tt * v[0] + g_tp * v[3],
                    del / sig * v[1],
                    v[2] / sig,
                    g_tp * v[0] + g_pp * v[3],
                ]
            };
            let z = Zamo::at(f.r, f.cos_theta, a);
            let vecs = [
                (1.0, DVec3::new(0.3, -0.5, 0.6)),
                (0.0, DVec3::new(-0.2, 0.9, 0.1)),
                (0.4, DVec3::new(0.7, 0.1, -0.3)),
            ];
            for (i, &(p0, pv)) in vecs.iter().enumerate() {
                let (q0, qv) = vecs[(i + 1) % 3];
                let on = |v0: f64, v: DVec3| [v0, v.dot(f.e_r), v.dot(f.e_theta), v.dot(f.e_phi)];
                let got = falling_kappa(f.r, f.cos_theta, a, on(p0, pv), on(q0, qv));
                let want = walker_penrose_coordinates(
                    &z,
                    raise(falling_covector(&f, a, p0, pv)),
                    raise(falling_covector(&f, a, q0, qv)),
                );
                assert!(
                    (got - want).norm() < 1e-10 * (1.0 + want.norm()),
                    "a {a} r {}: {got} vs {want}",
                    f.r
                );
            }
        }
    }
}
