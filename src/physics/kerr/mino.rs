//! An independent step-by-step integrator of a backward Kerr light ray, for
//! the tests of the closed form only: the second-order Mino-time system
//! r'' = R'(r) / 2, theta'' = Theta'(theta) / 2 (smooth through turning
//! points), phi' = -[a (2 r - a lambda) / Delta + lambda / sin^2 theta],
//! integrated with adaptive Dormand-Prince 5(4). It shares nothing with the
//! closed form but the constants of motion at the camera. M = 1.

use glam::DVec3;

use super::frame::{Constants, r_horizon};
use super::{KerrDisk, KerrOutcome, KerrRay, MAX_CROSSINGS, disk_g};
use crate::physics::geodesic::{DP_A, DP_B, DP_E};

type State = [f64; 5]; // r, dr/dtau, theta, dtheta/dtau, phi

/// Where the integrator stops an escaping ray (M units): its momentum's
/// direction there is the asymptotic one to about b / r^2.
pub const FAR: f64 = 1e7;

struct Ray {
    a: f64,
    lambda: f64,
    eta: f64,
}

impl Ray {
    fn derivative(&self, y: &State) -> State {
        let (a, l, eta) = (self.a, self.lambda, self.eta);
        let [r, pr, th, pth, _] = *y;
        let (s, c) = th.sin_cos();
        let delta = r * r - 2.0 * r + a * a;
        let dr_pot = 4.0 * r * (r * r + a * a - a * l) - (2.0 * r - 2.0) * (eta + (l - a).powi(2));
        let dth_pot = -2.0 * a * a * s * c + 2.0 * l * l * c / (s * s * s);
        let dphi = -(a * (2.0 * r - a * l) / delta + l / (s * s));
        [pr, 0.5 * dr_pot, pth, 0.5 * dth_pot, dphi]
    }

    /// One Dormand-Prince step: the new state and the scaled error.
    fn step(&self, y: &State, h: f64, rtol: f64) -> (State, f64) {
        let mut k: Vec<State> = Vec::with_capacity(7);
        k.push(self.derivative(y));
        let combine = |c: &[f64], k: &[State]| {
            let mut out = *y;
            for (ci, ki) in c.iter().zip(k) {
                for (o, v) in out.iter_mut().zip(ki) {
                    *o += h * ci * v;
                }
            }
            out
        };
        for coeffs in &DP_A[1..] {
            let yi = combine(coeffs, &k);
            k.push(self.derivative(&yi));
        }
        let yn = combine(&DP_B, &k);
        k.push(self.derivative(&yn));
        let mut err: f64 = 0.0;
        for i in 0..5 {
            let e: f64 = DP_E.iter().zip(&k).map(|(c, ki)| h * c * ki[i]).sum();
            let scale = 1e-14 + rtol * y[i].abs().max(yn[i].abs());
            err = err.max((e / scale).abs());
        }
        (yn, err)
    }
}

/// The world direction (hole frame) of the ray's motion at state `y`.
fn motion_direction(a: f64, y: &State, d: &State) -> DVec3 {
    let [r, _, th, _, ph] = *y;
    let rho = (r * r + a * a).sqrt();
    let (st, ct) = th.sin_cos();
    let (sp, cp) = ph.sin_cos();
    let dp_dr = DVec3::new(r / rho * st * cp, ct, -r / rho * st * sp);
    let dp_dth = DVec3::new(rho * ct * cp, -r * st, -rho * ct * sp);
    let dp_dph = DVec3::new(-rho * st * sp, 0.0, -rho * st * cp);
    (dp_dr * d[0] + dp_dth * d[2] + dp_dph * d[4]).normalize()
}

/// The system and its state at the camera for the constants `cc`.
fn start(cc: &Constants, a: f64) -> (Ray, State) {
    let f = cc.frame;
    let r_pot = super::radial::r_potential(f.r, a, cc.lambda, cc.eta).max(0.0);
    let ray = Ray {
        a,
        lambda: cc.lambda,
        eta: cc.eta,
    };
    let y = [
        f.r,
        cc.s_r * r_pot.sqrt(),
        f.theta,
        cc.s_theta * cc.theta_potential.max(0.0).sqrt(),
        f.phi,
    ];
    (ray, y)
}

/// Integrates the backward ray from a ZAMO camera at `position` (r_s)
/// along `d` (ZAMO frame), as [`super::trace_zamo`] does in closed form.
/// `rtol`: the relative tolerance per step (1e-12 gives about 1e-9 on
/// ordinary rays).
pub fn integrate(
    position: DVec3,
    d: DVec3,
    spin: f64,
    disk: Option<KerrDisk>,
    rtol: f64,
) -> KerrRay {
    let a = spin;
    let cc = Constants::of(2.0 * position, d, a);
    let done = |outcome| KerrRay {
        outcome,
        case: 0,
        lambda: cc.lambda,
        eta: cc.eta,
    };
    if cc.energy <= 0.0 {
        return done(KerrOutcome::Captured);
    }
    let f = cc.frame;
    let (ray, mut y) = start(&cc, a);
    let horizon = r_horizon(a) * (1.0 + 1e-6);
    let mut h = 1e-3 / (1.0 + f.r);
    let mut crossings = 0;
    for _ in 0..2_000_000 {
        let (yn, err) = ray.step(&y, h, rtol);
        if err.is_nan() || err > 1.0 {
            h *= (0.9 * err.powf(-0.2)).clamp(0.1, 0.5);
            continue;
        }
        let side = |s: &State| s[2] - std::f64::consts::FRAC_PI_2;
        if side(&y) * side(&yn) < 0.0 {
            let yc = crossing(&ray, &y, h, rtol);
            let r = yc[0];
            if let Some(disk) = disk
                && (2.0 * disk.inner..=2.0 * disk.outer).contains(&r)
            {
                let phi = yc[4];
                return done(KerrOutcome::Disk {
                    r: r / 2.0,
                    phi: (-phi.sin()).atan2(phi.cos()),
                    g: disk_g(r, a, cc.lambda, f.alpha, f.omega),
                    crossings_before: crossings,
                });
            }
            crossings += 1;
            if crossings >= MAX_CROSSINGS {
                break;
            }
        }
        y = yn;
        if y[0] < horizon {
            return done(KerrOutcome::Captured);
        }
        if y[0] > FAR {
            let dy = ray.derivative(&y);
            return done(KerrOutcome::Escaped(motion_direction(a, &y, &dy)));
        }
        h *= (0.9 * err.max(1e-10).powf(-0.2)).clamp(0.2, 5.0);
    }
    done(KerrOutcome::Captured)
}

/// The state where theta = pi/2 within the accepted step of length `h`
/// from `y` (bisection on the step's length, each trial one step from y).
fn crossing(ray: &Ray, y: &State, h: f64, rtol: f64) -> State {
    let side = |s: &State| s[2] - std::f64::consts::FRAC_PI_2;
    let (mut lo, mut hi) = (0.0, h);
    let s0 = side(y);
    let mut best = *y;
    for _ in 0..80 {
        let mid = 0.5 * (lo + hi);
        let (ym, _) = ray.step(y, mid, rtol);
        if side(&ym) * s0 > 0.0 {
            lo = mid;
        } else {
            hi = mid;
        }
        best = ym;
        if hi - lo <= 1e-15 * h.abs() {
            break;
        }
    }
    best
}

/// The backward ray's Boyer-Lindquist (r, theta, phi) at each Mino time of
/// `taus` (ascending, from 0 at the camera), integrated as [`integrate`]
/// does (the tests of the closed-form path, path.rs).
pub fn states_at(position: DVec3, d: DVec3, spin: f64, taus: &[f64], rtol: f64) -> Vec<[f64; 3]> {
    let a = spin;
    let cc = Constants::of(2.0 * position, d, a);
    let f = cc.frame;
    let (ray, mut y) = start(&cc, a);
    // (Along a photon of E < 0 the azimuth turns the other way: phi_o -
    // turn (I_phi + lambda G_phi), as the closed form.)
    let turn = cc.energy.signum();
    let (mut t, mut h) = (0.0, 1e-3 / (1.0 + f.r));
    let mut out = Vec::with_capacity(taus.len());
    let mut budget = 5_000_000usize;
    for &target in taus {
        while t < target && budget > 0 {
            budget -= 1;
            let step = h.min(target - t);
            if t + step == t {
                break;
            }
            let (yn, err) = ray.step(&y, step, rtol);
            if err.is_nan() || err > 1.0 {
                h = step * (0.9 * err.powf(-0.2)).clamp(0.1, 0.5);
                continue;
            }
            y = yn;
            t += step;
            if step == h {
                h *= (0.9 * err.max(1e-10).powf(-0.2)).clamp(0.2, 5.0);
            }
        }
        out.push([y[0], y[2], f.phi + turn * (y[4] - f.phi)]);
    }
    out
}
