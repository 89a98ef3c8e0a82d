//! The volumetric disk's polarized light in closed form, one sample at a
//! time (the GPU's twin: pol_volume_kerr in
//! shaders/include/polarization.glsl): the photon at the sample's
//! Boyer-Lindquist (r, theta) from its constants and the signs of its
//! backward motion there, the gas circling at the Keplerian angular
//! velocity of the equatorial radius at its distance from the axis, the
//! emission as the thin disk's (the field on the gas frame's e_r, e_phi
//! and -e_theta) per unit length, and the Walker-Penrose constant solved
//! at the camera. Its reference is transport.rs's
//! `volume_sample_transported`.

use glam::DVec3;

use super::super::radial::r_potential;
use super::super::{
    KerrObserver, PlacementError, frame::Constants, observer_velocity, to_zamo_frame,
};
use super::camera_angle;
use crate::physics::polarization::{
    Emission, Seen, Stokes, Zamo, emit_at, gas_speed_at, walker_penrose,
};

/// The photon of constants (lambda, eta) at `z` with backward signs s_r,
/// s_theta, per unit |E| (`turn` = the sign of E): ZAMO components,
/// future-pointing. Theta = eta + (a^2 - lambda^2 / sin^2) cos^2.
pub fn photon_at(z: &Zamo, lambda: f64, eta: f64, s_r: f64, s_th: f64, turn: f64) -> [f64; 4] {
    let (r, a, c) = (z.r, z.a, z.cos_theta);
    let s2 = (z.sin_theta * z.sin_theta).max(1e-300);
    let big_r = r_potential(r, a, lambda, eta).max(0.0);
    let big_th = (eta + (a * a - lambda * lambda / s2) * c * c).max(0.0);
    [
        turn * (1.0 - z.omega * lambda) / z.alpha,
        -s_r * (big_r / (z.sigma * z.delta)).sqrt(),
        -s_th * (big_th / z.sigma).sqrt(),
        turn * lambda / z.varpi,
    ]
}

/// A volume sample's place on the path: Boyer-Lindquist r (M), cos theta
/// and the backward motion's signs of dr and d theta there.
#[derive(Clone, Copy, Debug)]
pub struct SamplePoint {
    pub r: f64,
    pub cos_theta: f64,
    pub s_r: f64,
    pub s_theta: f64,
}

/// The Stokes parameters, as the camera sees them, of one sample of the
/// volumetric disk at `at` on the path of the pixel along `d` (as
/// [`super::stokes`]; a camera outside the horizon): I = g^(2 + alpha) (r
/// / rs)^-n sin(theta_B)^(1 + alpha) per unit density and length, P =
/// fraction I. `inner`: the disk's inner radius (rs), the least radius
/// whose Keplerian speed the gas takes.
#[allow(clippy::too_many_arguments)]
pub fn sample_stokes(
    position: DVec3,
    d: DVec3,
    up: DVec3,
    spin: f64,
    observer: KerrObserver,
    at: SamplePoint,
    inner: f64,
    em: &Emission,
) -> Result<Seen, PlacementError> {
    let a = spin;
    let beta = observer_velocity(observer, 2.0 * position, a)?;
    let (dz, doppler) = to_zamo_frame(d, beta);
    let cc = Constants::of(2.0 * position, dz, a);
    if cc.energy == 0.0 || cc.eta <= 0.0 {
        return Ok(Seen::default());
    }
    let z = Zamo::at(at.r, at.cos_theta, a);
    let p = photon_at(
        &z,
        cc.lambda,
        cc.eta,
        at.s_r,
        at.s_theta,
        cc.energy.signum(),
    );
    let (r, c) = (at.r, at.cos_theta);
    let x = (r * r * (1.0 - c * c) - a * a * c * c)
        .max(0.0)
        .sqrt()
        .max(2.0 * inner);
    let e = emit_at(p, em.field, gas_speed_at(&z, 1.0 / (x.powf(1.5) + a)));
    if e.sin_b <= 0.0 {
        return Ok(Seen::default());
    }
    // g: the camera's energy over the gas's (e.energy is per the photon's
    // ZAMO energy p[0], per unit |E|; |E| per unit camera ZAMO energy).
    let g = doppler / (cc.energy.abs() * e.energy * p[0]);
    let j = (0.5 * r).powf(-em.emissivity_index) * e.sin_b.powf(1.0 + em.spectral_index);
    let i = g.powf(2.0 + em.spectral_index) * j;
    let chi = camera_angle(&cc.frame, a, d, up, beta, walker_penrose(&z, p, e.f));
    Ok(Seen {
        stokes: Stokes::linear(i, em.fraction, chi),
        sin_b: e.sin_b,
        k_z: e.k_z,
    })
}
