//! The volumetric disk's reference: the sky's north and west carried
//! backwards by the parallel transport (as for the thin disk) to where the
//! path crosses a plane Z = height off the equator, and what gas there
//! emits, in the gas's frame built by Gram-Schmidt in Kerr-Schild
//! coordinates (no Walker-Penrose constant, no lambda or eta, no Mino
//! time). The backward motion's signs there come from the path itself.

use glam::DVec3;

use super::super::schild::{backward, bl_r};
use super::super::{KerrDisk, LocalFrame};
use super::{carried, gas_frame, moving_covectors, pair};
use crate::physics::polarization::{Emission, Stokes};

/// A sample the transport reached: its Boyer-Lindquist r (M) and cos
/// theta, the backward motion's signs of dr and d theta there, and its
/// Stokes parameters as the camera sees them (as the closed form's
/// `volume::sample_stokes`), with sin(theta_B).
#[derive(Clone, Copy, Debug)]
pub struct VolumeSeen {
    pub r: f64,
    pub cos_theta: f64,
    pub s_r: f64,
    pub s_theta: f64,
    pub stokes: Stokes,
    pub sin_b: f64,
}

/// The pixel along `d` of a camera at `position` (rs, outside the horizon)
/// moving at `beta` through the ZAMO's frame, with up `up`: the first
/// crossing of its backward path with the plane Z = `height` (M) inside
/// the annulus, and the emission there (I = g^(2 + alpha) (r / rs)^-n
/// sin(theta_B)^(1 + alpha)); none for the horizon, the sky or sin(theta_B)
/// = 0. The gas circles at the Keplerian angular velocity of the equatorial
/// radius sqrt(X^2 + Y^2 - a^2) at its distance from the axis, no nearer
/// than the inner edge.
#[allow(clippy::too_many_arguments)]
pub fn volume_sample_transported(
    position: DVec3,
    d: DVec3,
    up: DVec3,
    spin: f64,
    beta: DVec3,
    height: f64,
    disk: KerrDisk,
    em: &Emission,
) -> Option<VolumeSeen> {
    let a = spin;
    let f = LocalFrame::at(2.0 * position, a);
    let pnw = moving_covectors(&f, a, d, up, beta);
    let (c, p_t, r) = carried(&f, a, pnw, disk, height)?;
    let x = (c.x.x * c.x.x + c.x.y * c.x.y - a * a)
        .max(0.0)
        .sqrt()
        .max(2.0 * disk.inner);
    let [u, e_r, e_phi, e_z] = gas_frame(c.x, a, 1.0 / (x.powf(1.5) + a));
    let p = [p_t, c.p.x, c.p.y, c.p.z];
    let energy = -pair(p, u);
    let k = DVec3::new(pair(p, e_r), pair(p, e_phi), pair(p, e_z)) / energy;
    let kb = k.cross(em.field);
    let sin_b = kb.length();
    if sin_b == 0.0 {
        return None;
    }
    let j = (0.5 * r).powf(-em.emissivity_index) * sin_b.powf(1.0 + em.spectral_index);
    let i = energy.powf(-(2.0 + em.spectral_index)) * j;
    let fe = kb / sin_b;
    let fv: [f64; 4] = std::array::from_fn(|m| fe.x * e_r[m] + fe.y * e_phi[m] + fe.z * e_z[m]);
    let (c1, c2) = (pair(c.n, fv), pair(c.w, fv));
    // The signs: a short step along the backward flow (theta grows where
    // cos theta = Z / r falls).
    let (vx, _) = backward(c.x, c.p, p_t, a);
    let step = 1e-7 * r / vx.length();
    let ahead = c.x + step * vx;
    let r_ahead = bl_r(ahead, a);
    let sign = |v: f64| if v >= 0.0 { 1.0 } else { -1.0 };
    Some(VolumeSeen {
        r,
        cos_theta: c.x.z / r,
        s_r: sign(r_ahead - r),
        s_theta: sign(c.x.z / r - ahead.z / r_ahead),
        stokes: Stokes::linear(i, em.fraction, (-c2).atan2(c1)),
        sin_b,
    })
}
