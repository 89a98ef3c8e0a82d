//! The thin disk's Stokes parameters seen by a camera outside a spinning
//! hole, in closed form: the first crossing of the disk's annulus
//! (mod.rs), the photon's ZAMO-frame momentum there from its constants and
//! the signs of the backward motion, the emission (physics/polarization.rs)
//! and the Walker-Penrose constant solved at the camera (a falling camera
//! between the horizons or just outside them on its own frame: inside.rs).
//! The GPU's twin is
//! shaders/include/polarization.glsl; the independent reference,
//! transport.rs, integrates the parallel transport instead.

use glam::DVec3;
use num_complex::Complex64;

use super::angular::Ordinary;
use super::radial::{Radial, r_potential};
use super::{
    KerrDisk, KerrObserver, first_disk_crossing, in_falling_band, observer_velocity, to_zamo_frame,
};
use super::{LocalFrame, PlacementError, disk_g, frame::Constants};
mod inside;
pub mod volume;

use crate::physics::polarization::{
    Emission, Seen, Stokes, Zamo, angle_at_camera, boost, emit, emitted_intensity, sky_basis,
    walker_penrose,
};

/// A ZAMO-frame 4-vector from its time part and a world vector on the
/// frame's triad.
pub fn on_triad(f: &LocalFrame, v0: f64, v: DVec3) -> [f64; 4] {
    [v0, v.dot(f.e_r), v.dot(f.e_theta), v.dot(f.e_phi)]
}

/// The electric vector's angle east of north of constant `kappa` at a
/// camera at frame `f` moving at `beta` through the ZAMO's, for the pixel
/// along `d` with up `up`: the photon, north and west boosted into the
/// ZAMO's frame.
pub fn camera_angle(
    f: &LocalFrame,
    a: f64,
    d: DVec3,
    up: DVec3,
    beta: DVec3,
    kappa: Complex64,
) -> f64 {
    let (nn, ww) = sky_basis(d, up);
    let zc = Zamo::at(f.r, f.cos_theta, a);
    let lift = |v0: f64, v: DVec3| {
        let (t, s) = boost(beta, v0, v);
        on_triad(f, t, s)
    };
    angle_at_camera(&zc, kappa, lift(1.0, -d), lift(0.0, nn), lift(0.0, ww))
}

/// The photon of constants (lambda, eta) crossing the equator at r (M)
/// with backward signs s_r, s_theta, per unit |E| (`turn` = the sign of
/// E): ZAMO components, future-pointing.
pub fn equatorial_photon(
    z: &Zamo,
    lambda: f64,
    eta: f64,
    s_r: f64,
    s_th: f64,
    turn: f64,
) -> [f64; 4] {
    let r = z.r;
    let big_r = r_potential(r, z.a, lambda, eta).max(0.0);
    [
        turn * (1.0 - z.omega * lambda) / z.alpha,
        -s_r * big_r.sqrt() / (r * z.delta.sqrt()),
        -s_th * eta.max(0.0).sqrt() / r,
        turn * lambda / z.varpi,
    ]
}

/// The photon's backward polar sign at the n-th crossing of the equator:
/// s_theta (-1)^(n + h), h = 1 where the path starts away from it.
fn polar_sign_at(ang: &Ordinary, n: u32) -> f64 {
    let h = u32::from(ang.s_theta * ang.f_o <= 0.0);
    if (n + h) % 2 == 0 {
        ang.s_theta
    } else {
        -ang.s_theta
    }
}

/// The Stokes parameters of the pixel along `d` (unit, the observer's
/// frame, hole-frame axes) of a camera of `observer` at `position` (rs)
/// with up `up`: zero unless the ray ends on the disk.
pub fn stokes(
    position: DVec3,
    d: DVec3,
    up: DVec3,
    spin: f64,
    observer: KerrObserver,
    disk: KerrDisk,
    em: &Emission,
) -> Result<Seen, PlacementError> {
    let a = spin;
    let beta = observer_velocity(observer, 2.0 * position, a)?;
    if observer == KerrObserver::Falling && in_falling_band(2.0 * position, a) {
        return Ok(inside::stokes_falling(position, d, up, a, disk, em));
    }
    let (dz, doppler) = to_zamo_frame(d, beta);
    let cc = Constants::of(2.0 * position, dz, a);
    if cc.energy == 0.0 || cc.eta <= 0.0 {
        return Ok(Seen::default());
    }
    let f = cc.frame;
    let rad = Radial::new(a, cc.lambda, cc.eta, f.r, cc.s_r);
    let ang = Ordinary::new(
        a,
        cc.lambda,
        cc.eta,
        f.cos_theta,
        cc.theta_potential,
        cc.s_theta,
    );
    let Some((n, tc, rc)) = first_disk_crossing(&rad, &ang, Some(disk)) else {
        return Ok(Seen::default());
    };
    let turn = cc.energy.signum();
    let s_th = polar_sign_at(&ang, n);
    let ze = Zamo::at(rc, 0.0, a);
    let pe = equatorial_photon(&ze, cc.lambda, cc.eta, rad.backward_r_sign(tc), s_th, turn);
    let e = emit(&ze, pe, em.field);
    let g = disk_g(rc, a, cc.lambda, f.alpha, f.omega) * doppler;
    let i = g.powf(3.0 + em.spectral_index) * emitted_intensity(em, rc, e.sin_b, e.k_z);
    if i == 0.0 {
        return Ok(Seen::default());
    }
    let chi = camera_angle(&f, a, d, up, beta, walker_penrose(&ze, pe, e.f));
    Ok(Seen {
        stokes: Stokes::linear(i, em.fraction, chi),
        sin_b: e.sin_b,
        k_z: e.k_z,
    })
}
