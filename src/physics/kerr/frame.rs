//! Where a point of the hole's frame is in Boyer-Lindquist coordinates, the
//! zero-angular-momentum observer (ZAMO) there and its tetrad as world
//! vectors, the other observers as velocities relative to it, and a pixel
//! direction's photon constants (lambda, eta and the signs of the backward
//! ray). Units M = 1; the hole's frame has x = e1, y = the spin axis,
//! z = e1 x n.

use glam::DVec3;

/// Boyer-Lindquist coordinates, the flat triad (world vectors) and the ZAMO
/// quantities at a point.
#[derive(Clone, Copy, Debug)]
pub struct LocalFrame {
    pub r: f64,
    pub theta: f64,
    pub phi: f64,
    /// cos(theta) (exactly 0 in the equatorial plane) and sin(theta).
    pub cos_theta: f64,
    pub sin_theta: f64,
    /// Unit triad: e_r, e_theta, e_phi (e_r x e_theta = e_phi).
    pub e_r: DVec3,
    pub e_theta: DVec3,
    pub e_phi: DVec3,
    pub sigma: f64,
    pub delta: f64,
    /// The ZAMO's lapse, frame-dragging angular velocity and cylindrical
    /// radius.
    pub alpha: f64,
    pub omega: f64,
    pub varpi: f64,
}

impl LocalFrame {
    /// The frame at world point `p` (M units) of a hole of spin a (= a* in
    /// M = 1 units).
    pub fn at(p: DVec3, a: f64) -> LocalFrame {
        let r = boyer_lindquist_r(p.length_squared(), p.y, a);
        let theta = (p.y / r).clamp(-1.0, 1.0).acos();
        let phi = (-p.z).atan2(p.x);
        let s = theta.sin();
        let c = if p.y != 0.0 { theta.cos() } else { 0.0 };
        let (sp, cp) = phi.sin_cos();
        let rho = (r * r + a * a).sqrt();
        let sigma = r * r + a * a * c * c;
        let root = sigma.sqrt();
        let delta = r * r - 2.0 * r + a * a;
        let big_a = (r * r + a * a).powi(2) - a * a * delta * s * s;
        LocalFrame {
            r,
            theta,
            phi,
            cos_theta: c,
            sin_theta: s,
            e_r: DVec3::new(r * s * cp, rho * c, -r * s * sp) / root,
            e_theta: DVec3::new(rho * c * cp, -r * s, -rho * c * sp) / root,
            e_phi: DVec3::new(-sp, 0.0, -cp),
            sigma,
            delta,
            alpha: (sigma * delta / big_a).sqrt(),
            omega: 2.0 * a * r / big_a,
            varpi: (big_a / sigma).sqrt() * s,
        }
    }
}

/// The Boyer-Lindquist r of a point at squared distance `d2` from the
/// centre and height `y` along the spin axis (Kerr-Schild's x^2 + y^2 + z^2
/// = r^2 + a^2 sin^2 theta, y = r cos theta solved for r): the one place
/// it is written. Any units, as long as `a` is in the same (a = a* M).
pub fn boyer_lindquist_r(d2: f64, y: f64, a: f64) -> f64 {
    let w = d2 - a * a;
    (0.5 * (w + (w * w + 4.0 * a * a * y * y).sqrt())).sqrt()
}

/// The photon constants of one pixel: what the closed form starts from.
#[derive(Clone, Copy, Debug)]
pub struct Constants {
    /// The camera's frame.
    pub frame: LocalFrame,
    /// Energy and angular momentum of the physical photon (ZAMO frame, per
    /// its own energy 1).
    pub energy: f64,
    pub lambda: f64,
    pub eta: f64,
    /// Signs of dr/dtau and dtheta/dtau of the backward ray.
    pub s_r: f64,
    pub s_theta: f64,
    /// Sigma d_theta^2 / E^2: Theta(theta_o) without cancellation.
    pub theta_potential: f64,
}

impl Constants {
    /// The constants of the backward ray leaving the camera at `p` (M
    /// units) along the unit direction `d`, measured by the ZAMO there.
    pub fn of(p: DVec3, d: DVec3, a: f64) -> Constants {
        let f = LocalFrame::at(p, a);
        let (dr, dt, dp) = (d.dot(f.e_r), d.dot(f.e_theta), d.dot(f.e_phi));
        let energy = f.alpha - f.omega * f.varpi * dp;
        let l = -f.varpi * dp;
        let p_theta = f.sigma.sqrt() * dt;
        let s2 = f.sin_theta * f.sin_theta;
        let c2 = f.cos_theta * f.cos_theta;
        let q = p_theta * p_theta + c2 * (l * l / s2 - a * a * energy * energy);
        Constants {
            frame: f,
            energy,
            lambda: l / energy,
            eta: q / (energy * energy),
            s_r: 1f64.copysign(dr),
            s_theta: 1f64.copysign(dt),
            theta_potential: (p_theta / energy).powi(2),
        }
    }
}

/// The camera's observer (docs/physics.md's observers, as velocities relative to
/// the ZAMO).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum KerrObserver {
    Zamo,
    Static,
    Falling,
    Orbiting,
}

/// Why an observer cannot stand where it was put.
#[derive(Clone, Debug, PartialEq)]
pub enum PlacementError {
    /// Inside the outer horizon (at Boyer-Lindquist r, M units), where only
    /// a falling observer can be.
    InsideHorizon(f64),
    /// A falling observer at Boyer-Lindquist r (the first value) at or
    /// below the second, the deepest it may go (`falling_floor`).
    TooDeep(f64, f64),
    /// A static observer inside the ergoregion: (r, r_ergo), M units.
    StaticInErgoregion(f64, f64),
    /// An orbiting observer faster than light: (v, r).
    OrbitTooFast(f64, f64),
}

/// The observer's velocity relative to the ZAMO at `p` (M units), a world
/// vector through the flat triad.
pub fn observer_velocity(kind: KerrObserver, p: DVec3, a: f64) -> Result<DVec3, PlacementError> {
    let f = LocalFrame::at(p, a);
    if f.r.partial_cmp(&r_horizon(a)) != Some(std::cmp::Ordering::Greater) {
        // Between the horizons no observer is at rest or on a ZAMO's
        // worldline: a falling camera's pixels are directions in its own
        // frame, built from the metric (interior.rs); no velocity.
        let floor = falling_floor(a);
        return match kind {
            KerrObserver::Falling if f.r > floor => Ok(DVec3::ZERO),
            KerrObserver::Falling => Err(PlacementError::TooDeep(f.r, floor)),
            _ => Err(PlacementError::InsideHorizon(f.r)),
        };
    }
    match kind {
        KerrObserver::Zamo => Ok(DVec3::ZERO),
        KerrObserver::Static => {
            let r_ergo = 1.0 + (1.0 - a * a * f.cos_theta * f.cos_theta).sqrt();
            if f.r > r_ergo {
                Ok(-(f.omega * f.varpi / f.alpha) * f.e_phi)
            } else {
                Err(PlacementError::StaticInErgoregion(f.r, r_ergo))
            }
        }
        KerrObserver::Falling => Ok(-(1.0 - f.alpha * f.alpha).sqrt() * f.e_r),
        KerrObserver::Orbiting => {
            let omega_k = 1.0 / (f.r.powf(1.5) + a);
            let v = f.varpi * (omega_k - f.omega) / f.alpha;
            if v.abs() < 1.0 {
                Ok(v * f.e_phi)
            } else {
                Err(PlacementError::OrbitTooFast(v, f.r))
            }
        }
    }
}

/// The observer's pixel direction `d` seen by the ZAMO (aberration by
/// `beta`) and the Doppler factor gamma (1 + beta . d_Z) on every g.
pub fn to_zamo_frame(d: DVec3, beta: DVec3) -> (DVec3, f64) {
    let b2 = beta.length_squared();
    if b2 == 0.0 {
        return (d, 1.0);
    }
    let gam = 1.0 / (1.0 - b2).sqrt();
    let bd = beta.dot(d);
    let dz = ((d / gam - beta + gam / (gam + 1.0) * bd * beta) / (1.0 - bd)).normalize();
    (dz, gam * (1.0 + beta.dot(dz)))
}

/// How far outside the outer horizon a falling camera's pixels still take
/// the frame built from the metric (the interior's, kerr/interior.glsl), as
/// a fraction of r+: nearer r+ the ZAMO's frame, which the exterior path
/// aberrates by the fall, degenerates (the fall's Lorentz factor relative to
/// it grows as 1 / sqrt(r - r+), and 32-bit aberration loses what the goals
/// ask; at 1e-8 rs every pixel was NaN).
pub const FALLING_FRAME_BAND: f64 = 5e-2;

/// Whether a falling camera at world point `p` (M units) of a hole of spin
/// `a` takes its photons from the falling frame built from the metric
/// (between the horizons, or within [`FALLING_FRAME_BAND`] of r+ outside)
/// instead of the ZAMO's.
pub fn in_falling_band(p: DVec3, a: f64) -> bool {
    LocalFrame::at(p, a).r < (1.0 + FALLING_FRAME_BAND) * r_horizon(a)
}

/// How far past the inner horizon's r- a falling camera may not go, as a
/// fraction of r-: the continued path's inner pole sits that close behind
/// the camera, and the quadrature of the azimuth (kerr/interior.glsl) keeps
/// its accuracy down to here.
pub const INNER_MARGIN: f64 = 1e-3;

/// The deepest Boyer-Lindquist r (M units) a falling camera of a hole of
/// spin a may reach: (1 + [`INNER_MARGIN`]) r-, and never closer than a
/// non-rotating hole's limit (0.05 rs = 0.1 M), so that the rule is
/// continuous in the spin.
pub fn falling_floor(a: f64) -> f64 {
    ((1.0 + INNER_MARGIN) * r_inner_horizon(a)).max(2.0 * crate::physics::FALLING_MIN_R)
}

/// The inner horizon r- = a^2 / r+ = 1 - sqrt(1 - a^2) (M units), in the
/// form that keeps its digits as a vanishes: the one place it is written.
pub fn r_inner_horizon(a: f64) -> f64 {
    a * a / r_horizon(a)
}

/// The outer horizon r+ = 1 + sqrt(1 - a^2) (M units).
pub fn r_horizon(a: f64) -> f64 {
    1.0 + (1.0 - a * a).sqrt()
}
