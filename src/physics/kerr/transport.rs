//! The polarization's independent reference: the electric vector
//! parallel-transported step by step along the light path in Cartesian
//! Kerr-Schild coordinates (schild.rs), from the Christoffel symbols of the
//! metric g = eta + F l l alone. Nothing here uses the Walker-Penrose
//! constant, lambda, eta or Mino time.
//!
//! Parallel transport keeps inner products, so instead of guessing the
//! electric vector at the camera, the sky's north n and west w (covectors,
//! both across the photon there) are carried backwards to the disk; the
//! emitted vector f_e = c1 n + c2 w + c3 p there gives c1 = f_e . n, c2 =
//! f_e . w, and chi = atan2(-c2, c1). The gas's frame at the crossing comes
//! by Gram-Schmidt in these coordinates: u along d_T + Omega d_Phi, e_(phi)
//! from d_Phi, e_(z) along +Z, e_(r) from the cylindrical radial direction.

use glam::DVec3;

use super::schild::{
    backward, bl_r, falling_covector, kerr_schild_start, metric_parts, schild_covector,
};
use super::{
    KerrDisk, KerrObserver, LocalFrame, PlacementError, in_falling_band, observer_velocity,
    r_horizon,
};
use crate::physics::polarization::{Emission, Seen, Stokes, boost, emitted_intensity, sky_basis};

/// The metric's inner product of two vectors at X.
fn dot(x: DVec3, a: f64, u: [f64; 4], v: [f64; 4]) -> f64 {
    let (f, l, _) = metric_parts(x, a);
    let lv = |v: [f64; 4]| v[0] + l[0].v * v[1] + l[1].v * v[2] + l[2].v * v[3];
    -u[0] * v[0] + u[1] * v[1] + u[2] * v[2] + u[3] * v[3] + f.v * lv(u) * lv(v)
}

/// A covector raised: g^mn = eta^mn - F l^m l^n, l^m = (-1, l_X, l_Y, l_Z).
fn raise(f: f64, l: [f64; 4], v: [f64; 4]) -> [f64; 4] {
    let lu = [-1.0, l[1], l[2], l[3]];
    let lv = lu[0] * v[0] + lu[1] * v[1] + lu[2] * v[2] + lu[3] * v[3];
    std::array::from_fn(|m| if m == 0 { -v[0] } else { v[m] } - f * lu[m] * lv)
}

/// d f_m / d lambda = Gamma^n_(m a) p^a f_n for the covector `c` along the
/// photon `p` (covector), with g = eta + F l l:
/// (1/2)(d_m g_(la) f^l p^a + p^a d_a g_(lm) f^l - f^l d_l g_(ma) p^a).
pub(super) fn transport_rate(x: DVec3, a: f64, p: [f64; 4], c: [f64; 4]) -> [f64; 4] {
    let (fd, ld, _) = metric_parts(x, a);
    let l = [1.0, ld[0].v, ld[1].v, ld[2].v];
    let (pu, cu) = (raise(fd.v, l, p), raise(fd.v, l, c));
    let contract = |u: [f64; 4]| l[0] * u[0] + l[1] * u[1] + l[2] * u[2] + l[3] * u[3];
    let (lp, lc) = (contract(pu), contract(cu));
    let sp = DVec3::new(pu[1], pu[2], pu[3]);
    let sc = DVec3::new(cu[1], cu[2], cu[3]);
    // Gradients of l_m (l_T = 1 has none) and directional derivatives.
    let grad = |m: usize| if m == 0 { DVec3::ZERO } else { ld[m - 1].d };
    let dl_dot = |dir: DVec3, u: [f64; 4]| (1..4).map(|i| grad(i).dot(dir) * u[i]).sum::<f64>();
    let f = fd.v;
    std::array::from_fn(|m| {
        let term1 = if m == 0 {
            0.0
        } else {
            let k = m - 1;
            let e = DVec3::AXES[k];
            fd.d[k] * lc * lp + f * dl_dot(e, cu) * lp + f * lc * dl_dot(e, pu)
        };
        let term2 = fd.d.dot(sp) * lc * l[m] + f * dl_dot(sp, cu) * l[m] + f * lc * grad(m).dot(sp);
        let term3 = fd.d.dot(sc) * l[m] * lp + f * grad(m).dot(sc) * lp + f * l[m] * dl_dot(sc, pu);
        0.5 * (term1 + term2 - term3)
    })
}

/// The state carried backwards: position, the photon's spatial covector
/// (p_T is conserved) and the two transported covectors.
#[derive(Clone, Copy, Debug)]
struct State {
    x: DVec3,
    p: DVec3,
    n: [f64; 4],
    w: [f64; 4],
}

impl State {
    fn rate(&self, p_t: f64, a: f64) -> State {
        let (vx, vp) = backward(self.x, self.p, p_t, a);
        let p4 = [p_t, self.p.x, self.p.y, self.p.z];
        let back = |c: [f64; 4]| transport_rate(self.x, a, p4, c).map(|v| -v);
        State {
            x: vx,
            p: vp,
            n: back(self.n),
            w: back(self.w),
        }
    }

    fn axpy(&self, h: f64, d: &State) -> State {
        let add = |u: [f64; 4], v: [f64; 4]| std::array::from_fn(|i| u[i] + h * v[i]);
        State {
            x: self.x + h * d.x,
            p: self.p + h * d.p,
            n: add(self.n, d.n),
            w: add(self.w, d.w),
        }
    }

    fn rk4(&self, p_t: f64, a: f64, h: f64) -> State {
        let k1 = self.rate(p_t, a);
        let k2 = self.axpy(0.5 * h, &k1).rate(p_t, a);
        let k3 = self.axpy(0.5 * h, &k2).rate(p_t, a);
        let k4 = self.axpy(h, &k3).rate(p_t, a);
        let mut out = self.axpy(h / 6.0, &k1);
        out = out.axpy(h / 3.0, &k2);
        out = out.axpy(h / 3.0, &k3);
        out.axpy(h / 6.0, &k4)
    }
}

/// A ZAMO-frame 4-vector (t, r, theta, phi) at frame `f` as a Kerr-Schild
/// covector (T, X, Y, Z).
fn zamo_covector(f: &LocalFrame, a: f64, v: [f64; 4]) -> [f64; 4] {
    // Boyer-Lindquist: v_t = -alpha v0 - omega varpi v_phi, v_r = sqrt(Sigma
    // / Delta) v_r, v_theta = sqrt(Sigma) v_theta, v_phi = varpi v_phi.
    let vt = -f.alpha * v[0] - f.omega * f.varpi * v[3];
    let vr = (f.sigma / f.delta).sqrt() * v[1];
    let (vth, vph) = (f.sigma.sqrt() * v[2], f.varpi * v[3]);
    schild_covector(f, a, [vt, vr, vth, vph])
}

/// The gas's orthonormal frame at the point X, circling at angular
/// velocity `om`: u, e_(r), e_(phi), e_(z), Kerr-Schild vectors; e_(z) is
/// -d_theta (at fixed T, r and the Kerr-Schild azimuth: (-X c / s, -Y c /
/// s, r s), c = Z / r), +Z on the equator.
fn gas_frame(x: DVec3, a: f64, om: f64) -> [[f64; 4]; 4] {
    let r = bl_r(x, a);
    let c = x.z / r;
    let s = (1.0 - c * c).max(0.0).sqrt();
    let dphi = [0.0, -x.y, x.x, 0.0];
    let scale = |v: [f64; 4], s: f64| v.map(|c| c * s);
    let sub =
        |u: [f64; 4], v: [f64; 4], s: f64| -> [f64; 4] { std::array::from_fn(|i| u[i] - s * v[i]) };
    let unit = |v: [f64; 4]| scale(v, 1.0 / dot(x, a, v, v).abs().sqrt());
    let u = unit([1.0, -om * x.y, om * x.x, 0.0]);
    // Spacelike v minus its part along u: v + (v . u) u.
    let e_phi = unit(sub(dphi, u, -dot(x, a, dphi, u)));
    let e_z = unit([0.0, -x.x * c / s, -x.y * c / s, r * s]);
    let mut e_r = [0.0, x.x, x.y, 0.0];
    e_r = sub(e_r, u, -dot(x, a, e_r, u));
    e_r = sub(e_r, e_phi, dot(x, a, e_r, e_phi));
    e_r = sub(e_r, e_z, dot(x, a, e_r, e_z));
    [u, unit(e_r), e_phi, e_z]
}

fn pair(c: [f64; 4], v: [f64; 4]) -> f64 {
    c[0] * v[0] + c[1] * v[1] + c[2] * v[2] + c[3] * v[3]
}

/// The Stokes parameters of the pixel along `d` of a camera of `observer`
/// at `position` (rs, hole frame) with up `up`, by parallel transport: the
/// reference for physics/kerr/polarized.rs and the GPU. Zero unless the
/// ray's first crossing of the equator inside the annulus comes before the
/// horizon or the sky.
pub fn stokes_transported(
    position: DVec3,
    d: DVec3,
    up: DVec3,
    spin: f64,
    observer: KerrObserver,
    disk: KerrDisk,
    em: &Emission,
) -> Result<Seen, PlacementError> {
    let beta = observer_velocity(observer, 2.0 * position, spin)?;
    if observer == KerrObserver::Falling && in_falling_band(2.0 * position, spin) {
        return Ok(stokes_transported_falling(position, d, up, spin, disk, em));
    }
    Ok(stokes_transported_moving(
        position, d, up, spin, beta, disk, em,
    ))
}

/// [`stokes_transported`] for a camera moving at `beta` (world axes)
/// through the ZAMO's frame (the static frame at a = 0), outside the
/// horizon.
pub fn stokes_transported_moving(
    position: DVec3,
    d: DVec3,
    up: DVec3,
    spin: f64,
    beta: DVec3,
    disk: KerrDisk,
    em: &Emission,
) -> Seen {
    let f = LocalFrame::at(2.0 * position, spin);
    transported(&f, spin, moving_covectors(&f, spin, d, up, beta), disk, em)
}

/// The photon along `d` and the sky's north and west across it, of a
/// camera at frame `f` moving at `beta` through the ZAMO's: Kerr-Schild
/// covectors.
fn moving_covectors(f: &LocalFrame, a: f64, d: DVec3, up: DVec3, beta: DVec3) -> [[f64; 4]; 3] {
    let (nn, ww) = sky_basis(d, up);
    let lift = |v0: f64, v: DVec3| {
        let (t, s) = boost(beta, v0, v);
        zamo_covector(f, a, [t, s.dot(f.e_r), s.dot(f.e_theta), s.dot(f.e_phi)])
    };
    [lift(1.0, -d), lift(0.0, nn), lift(0.0, ww)]
}

/// [`stokes_transported`] for the camera falling from rest at infinity,
/// outside the horizon or between the horizons: `d` in its own frame
/// (schild.rs, [`falling_covector`]), the metric's components lowered and
/// taken to Kerr-Schild coordinates, which are regular through r+. Zero
/// for light from the other universe (P(r+) = E (r+^2 + a^2) - a L <= 0
/// between the horizons).
pub fn stokes_transported_falling(
    position: DVec3,
    d: DVec3,
    up: DVec3,
    spin: f64,
    disk: KerrDisk,
    em: &Emission,
) -> Seen {
    let a = spin;
    let f = LocalFrame::at(2.0 * position, a);
    let (nn, ww) = sky_basis(d, up);
    let p = falling_covector(&f, a, 1.0, -d);
    let rp = r_horizon(a);
    if f.r < rp && -p[0] * (rp * rp + a * a) - a * p[3] <= 0.0 {
        return Seen::default();
    }
    let lift = |v0: f64, v: DVec3| schild_covector(&f, a, falling_covector(&f, a, v0, v));
    transported(
        &f,
        a,
        [lift(1.0, -d), lift(0.0, nn), lift(0.0, ww)],
        disk,
        em,
    )
}

/// The photon p and the sky's north n and west w (Kerr-Schild covectors at
/// frame `f`) carried backwards to the disk's first crossing inside the
/// annulus: its Stokes parameters there, or zero for the horizon or the sky.
fn transported(f: &LocalFrame, a: f64, pnw: [[f64; 4]; 3], disk: KerrDisk, em: &Emission) -> Seen {
    match carried(f, a, pnw, disk, 0.0) {
        Some((c, p_t, rc)) => emitted_at(c, p_t, a, rc, em),
        None => Seen::default(),
    }
}

/// The state carried backwards from frame `f` to the path's first crossing
/// of the plane Z = `height` (M) with Boyer-Lindquist r inside the annulus,
/// with p_T and that r; none for the horizon or the sky.
fn carried(
    f: &LocalFrame,
    a: f64,
    [p, n, w]: [[f64; 4]; 3],
    disk: KerrDisk,
    height: f64,
) -> Option<(State, f64, f64)> {
    let (x0, _) = kerr_schild_start(f, a);
    let mut s = State {
        x: x0,
        p: DVec3::new(p[1], p[2], p[3]),
        n,
        w,
    };
    let (p_t, horizon) = (p[0], r_horizon(a));
    let above = |s: &State| s.x.z - height > 0.0;
    for _ in 0..400_000 {
        let r = bl_r(s.x, a);
        let (vx, _) = backward(s.x, s.p, p_t, a);
        if r > 1e6 || (r > horizon && r < horizon * 1.01 && vx.dot(s.x) < 0.0) {
            return None;
        }
        let h = 2e-3 * r.min((r - horizon).max(1e-3) * 50.0) / vx.length().max(1e-300);
        let next = s.rk4(p_t, a, h);
        if s.x.z != height && above(&s) != above(&next) {
            let (mut lo, mut hi) = (0.0, h);
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if above(&s.rk4(p_t, a, mid)) == above(&s) {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            let c = s.rk4(p_t, a, 0.5 * (lo + hi));
            let rc = bl_r(c.x, a);
            if (2.0 * disk.inner..=2.0 * disk.outer).contains(&rc) {
                return Some((c, p_t, rc));
            }
        }
        s = next;
    }
    None
}

/// The Stokes parameters of the state at the disk's crossing.
fn emitted_at(c: State, p_t: f64, a: f64, rc: f64, em: &Emission) -> Seen {
    let [u, e_r, e_phi, e_z] = gas_frame(c.x, a, 1.0 / (rc.powf(1.5) + a));
    let p = [p_t, c.p.x, c.p.y, c.p.z];
    // p^(t) = -p.u, the rest p.e (the camera's observer measures 1).
    let energy = -pair(p, u);
    let k = DVec3::new(pair(p, e_r), pair(p, e_phi), pair(p, e_z)) / energy;
    let kb = k.cross(em.field);
    let sin_b = kb.length();
    let i = energy.powf(-(3.0 + em.spectral_index)) * emitted_intensity(em, rc, sin_b, k.z);
    if i == 0.0 {
        return Seen::default();
    }
    let fe = kb / sin_b;
    let fv: [f64; 4] = std::array::from_fn(|m| fe.x * e_r[m] + fe.y * e_phi[m] + fe.z * e_z[m]);
    let (c1, c2) = (pair(c.n, fv), pair(c.w, fv));
    Seen {
        stokes: Stokes::linear(i, em.fraction, (-c2).atan2(c1)),
        sin_b,
        k_z: k.z,
    }
}

mod volume;
pub use volume::{VolumeSeen, volume_sample_transported};

#[cfg(test)]
mod tests;
