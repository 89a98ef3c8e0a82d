//! Polarized light of the thin disk, in f64: the emitter's synchrotron-like
//! model (the field in the gas's frame, the emitted electric vector and
//! intensity) and the Walker-Penrose constant that carries the electric
//! vector along the light path in closed form, for one hole of any spin
//! (a = 0 is the non-rotating hole). Units M = 1; vectors are 4-vectors of
//! components on a ZAMO's orthonormal tetrad (e_t, e_r, e_theta, e_phi),
//! the static frame at a = 0.
//!
//! The Walker-Penrose constant of a photon p and a polarization f (f.p =
//! 0) is kappa = (A - i B)(r - i a cos(theta)) with, in Boyer-Lindquist
//! components, A = X(p) Y(f) - Y(p) X(f), B = sin(theta) (Z(p) W(f) -
//! W(p) Z(f)), X(v) = v^t - a sin^2(theta) v^phi, Y(v) = v^r, Z(v) = (r^2 +
//! a^2) v^phi - a v^t, W(v) = v^theta (Chandrasekhar 1983, section 63). It
//! is linear in f and vanishes for f = p, so at the camera the two real
//! equations it gives fix f's two components across the ray.

use glam::DVec3;
use num_complex::Complex64;

/// The `[polarization]` model (docs/polarization.md).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Emission {
    /// The field's direction on the gas frame's (e_(r), e_(phi), e_(z)),
    /// unit.
    pub field: DVec3,
    pub spectral_index: f64,
    pub emissivity_index: f64,
    pub fraction: f64,
}

impl Default for Emission {
    fn default() -> Self {
        Emission {
            field: DVec3::new(0.87, 0.5, 0.0).normalize(),
            spectral_index: 1.0,
            emissivity_index: 2.0,
            fraction: 0.7,
        }
    }
}

/// Stokes parameters; V is always 0 here (no circular part).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Stokes {
    pub i: f64,
    pub q: f64,
    pub u: f64,
    pub v: f64,
}

impl Stokes {
    /// Linear polarization of intensity `i`, polarized share `fraction`,
    /// electric vector at `chi` east of north.
    pub fn linear(i: f64, fraction: f64, chi: f64) -> Stokes {
        let p = fraction * i;
        Stokes {
            i,
            q: p * (2.0 * chi).cos(),
            u: p * (2.0 * chi).sin(),
            v: 0.0,
        }
    }

    /// The polarized intensity sqrt(Q^2 + U^2).
    pub fn polarized(&self) -> f64 {
        self.q.hypot(self.u)
    }

    /// The electric vector's angle east of north, in (-pi/2, pi/2].
    pub fn angle(&self) -> f64 {
        0.5 * self.u.atan2(self.q)
    }
}

/// A pixel's Stokes parameters and, where its ray ends on the disk, the
/// emission's sin(theta_B) and k_z (the accuracy goals hold where both are
/// above 1e-2 in size).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Seen {
    pub stokes: Stokes,
    pub sin_b: f64,
    pub k_z: f64,
}

impl Seen {
    /// Where the goals hold: a disk hit with sin(theta_B) and |k_z| above
    /// 1e-2.
    pub fn well_defined(&self) -> bool {
        self.stokes.i > 0.0 && self.sin_b > 1e-2 && self.k_z.abs() > 1e-2
    }
}

/// What turns a ZAMO-frame 4-vector into Boyer-Lindquist components at a
/// point (M = 1): its lapse, frame-drag, cylindrical radius.
#[derive(Clone, Copy, Debug)]
pub struct Zamo {
    pub r: f64,
    pub cos_theta: f64,
    pub sin_theta: f64,
    pub a: f64,
    pub alpha: f64,
    pub omega: f64,
    pub varpi: f64,
    pub sigma: f64,
    pub delta: f64,
}

impl Zamo {
    /// At Boyer-Lindquist (r, theta) of a hole of spin a, outside the
    /// horizon.
    pub fn at(r: f64, cos_theta: f64, a: f64) -> Zamo {
        let sin_theta = (1.0 - cos_theta * cos_theta).max(0.0).sqrt();
        let sigma = r * r + a * a * cos_theta * cos_theta;
        let delta = r * r - 2.0 * r + a * a;
        let big_a = (r * r + a * a).powi(2) - a * a * delta * sin_theta * sin_theta;
        Zamo {
            r,
            cos_theta,
            sin_theta,
            a,
            alpha: (sigma * delta / big_a).sqrt(),
            omega: 2.0 * a * r / big_a,
            varpi: (big_a / sigma).sqrt() * sin_theta,
            sigma,
            delta,
        }
    }

    /// The Boyer-Lindquist components (t, r, theta, phi) of a vector of
    /// ZAMO-frame components `v`.
    pub fn to_coordinates(&self, v: [f64; 4]) -> [f64; 4] {
        let vt = v[0] / self.alpha;
        [
            vt,
            v[1] * (self.delta / self.sigma).sqrt(),
            v[2] / self.sigma.sqrt(),
            self.omega * vt + v[3] / self.varpi,
        ]
    }
}

/// The Walker-Penrose constant of photon `p` and polarization `f` (ZAMO
/// components at `z`), written through the bivector p ^ f so that it stays
/// finite on the polar axis (sin theta = 0), where any e_theta, e_phi
/// across e_r will do.
pub fn walker_penrose(z: &Zamo, p: [f64; 4], f: [f64; 4]) -> Complex64 {
    let (r, a, s) = (z.r, z.a, z.sin_theta);
    let rho2 = r * r + a * a;
    // The bivector p ^ f on the tetrad: m_ij = p_i f_j - p_j f_i.
    let m = |i: usize, j: usize| p[i] * f[j] - p[j] * f[i];
    // A = sqrt(Delta / Sigma) ((1 - a s^2 omega) / alpha m_tr + a s^2 /
    // varpi m_rphi), B = (s / sqrt(Sigma)) (((r^2 + a^2) omega - a) / alpha
    // m_ttheta + (r^2 + a^2) / varpi m_phitheta), with s / varpi =
    // sqrt(Sigma / A): finite on the axis.
    let big_a = rho2 * rho2 - a * a * z.delta * s * s;
    let s_over_varpi = (z.sigma / big_a).sqrt();
    let big_a_part = (z.delta / z.sigma).sqrt()
        * ((1.0 - a * s * s * z.omega) / z.alpha * m(0, 1) + a * s * s_over_varpi * m(1, 3));
    let big_b = (s / z.sigma.sqrt()) * (rho2 * z.omega - a) / z.alpha * m(0, 2)
        + rho2 * s_over_varpi / z.sigma.sqrt() * m(3, 2);
    Complex64::new(big_a_part, -big_b) * Complex64::new(r, -a * z.cos_theta)
}

/// The Walker-Penrose constant straight from Boyer-Lindquist components:
/// the definition, for tests of [`walker_penrose`].
pub fn walker_penrose_coordinates(z: &Zamo, p: [f64; 4], f: [f64; 4]) -> Complex64 {
    let (r, a, s) = (z.r, z.a, z.sin_theta);
    let x = |v: [f64; 4]| v[0] - a * s * s * v[3];
    let zz = |v: [f64; 4]| (r * r + a * a) * v[3] - a * v[0];
    let big_a = x(p) * f[1] - p[1] * x(f);
    let big_b = s * (zz(p) * f[2] - p[2] * zz(f));
    Complex64::new(big_a, -big_b) * Complex64::new(r, -a * z.cos_theta)
}

/// The Keplerian gas's speed on the ZAMO's e_phi at equatorial r, and its
/// Lorentz factor.
pub fn gas_speed(z: &Zamo) -> (f64, f64) {
    gas_speed_at(z, 1.0 / (z.r.powf(1.5) + z.a))
}

/// The speed on the ZAMO's e_phi of gas circling at angular velocity `om`
/// at `z`, and its Lorentz factor.
pub fn gas_speed_at(z: &Zamo, om: f64) -> (f64, f64) {
    let beta = z.varpi * (om - z.omega) / z.alpha;
    (beta, 1.0 / (1.0 - beta * beta).sqrt())
}

/// What the disk emits towards a photon.
#[derive(Clone, Copy, Debug)]
pub struct Emitted {
    /// The electric vector, ZAMO components.
    pub f: [f64; 4],
    /// sin(theta_B) and the photon's cosine to the disk's normal k_z, in
    /// the gas's frame.
    pub sin_b: f64,
    pub k_z: f64,
    /// The photon's energy in the gas's frame, per its ZAMO energy p[0].
    pub energy: f64,
}

/// The emission at the equatorial point `z` towards the photon `p` (ZAMO
/// components, future-pointing): the gas's frame is the ZAMO's boosted
/// along e_phi, its vertical e_(z) = -e_theta.
pub fn emit(z: &Zamo, p: [f64; 4], field: DVec3) -> Emitted {
    emit_at(p, field, gas_speed(z))
}

/// [`emit`] by gas moving on the ZAMO's e_phi at (beta, gamma) of
/// [`gas_speed_at`], anywhere (the volumetric disk's): the gas's vertical
/// is -e_theta.
pub fn emit_at(p: [f64; 4], field: DVec3, (beta, gamma): (f64, f64)) -> Emitted {
    let pt = gamma * (p[0] - beta * p[3]);
    let k = DVec3::new(p[1], gamma * (p[3] - beta * p[0]), -p[2]) / pt;
    let kb = k.cross(field);
    let sin_b = kb.length();
    let fe = if sin_b > 0.0 { kb / sin_b } else { DVec3::ZERO };
    Emitted {
        f: [gamma * beta * fe.y, fe.x, -fe.z, gamma * fe.y],
        sin_b,
        k_z: k.z,
        energy: pt / p[0],
    }
}

/// The emitted intensity of [`Emission`] at BL radius r (M): (r / rs)^-n
/// sin(theta_B)^(1 + alpha) / |k_z|, 0 where the angle is undefined.
pub fn emitted_intensity(e: &Emission, r: f64, sin_b: f64, k_z: f64) -> f64 {
    if sin_b <= 0.0 || k_z == 0.0 {
        return 0.0;
    }
    (0.5 * r).powf(-e.emissivity_index) * sin_b.powf(1.0 + e.spectral_index) / k_z.abs()
}

/// The electric vector's angle east of north at the camera: kappa (of the
/// photon and polarization at the emitter) = c1 kappa(p, n) + c2 kappa(p, w)
/// solved for real c1, c2 (the gauge part along p drops out), then chi =
/// atan2(-c2, c1). `p`, `n`, `w`: the photon and the sky's north and west,
/// ZAMO components at `z`.
pub fn angle_at_camera(z: &Zamo, kappa: Complex64, p: [f64; 4], n: [f64; 4], w: [f64; 4]) -> f64 {
    angle_of(kappa, walker_penrose(z, p, n), walker_penrose(z, p, w))
}

/// The angle east of north of the electric vector whose constant is
/// `kappa`, given kappa(p, n) = `kn` and kappa(p, w) = `kw` at the camera
/// in any frame (see [`angle_at_camera`]).
pub fn angle_of(kappa: Complex64, kn: Complex64, kw: Complex64) -> f64 {
    let det = kn.re * kw.im - kw.re * kn.im;
    let c1 = (kappa.re * kw.im - kw.re * kappa.im) / det;
    let c2 = (kn.re * kappa.im - kappa.re * kn.im) / det;
    (-c2).atan2(c1)
}

/// A 4-vector of an observer moving at `beta` relative to a frame, in that
/// frame's components (the boost taking (v0, v) to (gamma (v0 + beta.v),
/// v + (gamma - 1)(b.v) b + gamma beta v0), b = beta / |beta|).
pub fn boost(beta: DVec3, v0: f64, v: DVec3) -> (f64, DVec3) {
    let b2 = beta.length_squared();
    if b2 == 0.0 {
        return (v0, v);
    }
    let gamma = 1.0 / (1.0 - b2).sqrt();
    let bv = beta.dot(v);
    (
        gamma * (v0 + bv),
        v + ((gamma - 1.0) * bv / b2 + gamma * v0) * beta,
    )
}

/// The sky's north and west at a pixel looking along `d` (unit) of a camera
/// whose up is `up`: n = normalize(up - (up.d) d), w = n x d.
pub fn sky_basis(d: DVec3, up: DVec3) -> (DVec3, DVec3) {
    let n = (up - up.dot(d) * d).normalize();
    (n, n.cross(d))
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The tetrad form of the constant is the coordinate definition.
    #[test]
    fn the_tetrad_form_is_the_definition() {
        for (r, c, a) in [
            (6.0, 0.3, 0.9),
            (3.0, 0.0, -0.5),
            (12.0, -0.9, 0.0),
            (2.5, 0.99, 0.998),
        ] {
            let z = Zamo::at(r, c, a);
            let p = [1.3, -0.4, 0.7, 0.8];
            let f = [0.2, 0.5, -0.3, 0.9];
            let (x, y) = (
                walker_penrose(&z, p, f),
                walker_penrose_coordinates(&z, z.to_coordinates(p), z.to_coordinates(f)),
            );
            assert!(
                (x - y).norm() < 1e-12 * (1.0 + y.norm()),
                "{r} {c} {a}: {x} {y}"
            );
        }
    }

    /// The emitted electric vector is across the photon and the field in the
    /// gas's frame, and orthogonal to the photon's 4-momentum.
    #[test]
    fn the_electric_vector_is_across_photon_and_field() {
        let z = Zamo::at(8.0, 0.0, 0.7);
        let (p0, dir) = (1.0, DVec3::new(0.3, -0.5, 0.6).normalize());
        let p = [p0, dir.x, dir.y, dir.z];
        let e = emit(&z, p, DVec3::new(0.87, 0.5, 0.0).normalize());
        let dot = -p[0] * e.f[0] + p[1] * e.f[1] + p[2] * e.f[2] + p[3] * e.f[3];
        let norm = -e.f[0] * e.f[0] + e.f[1] * e.f[1] + e.f[2] * e.f[2] + e.f[3] * e.f[3];
        assert!(
            dot.abs() < 1e-14 && (norm - 1.0).abs() < 1e-14,
            "{dot} {norm}"
        );
    }
}
