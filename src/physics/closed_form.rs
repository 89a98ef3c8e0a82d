//! Closed-form Schwarzschild light paths (f64): a ray's whole fate in
//! constant time, the method the shader uses for one hole, here in f64 so the
//! tests can hold both the shader and this code against the step-by-step
//! integrator of [`super::geodesic`].
//!
//! In units of rs, with u = rs / r and φ the angle in the orbit plane,
//! Binet's equation integrates once to
//!
//! ```text
//! (du/dφ)² = G(u) = u³ - u² + c,   c = (rs / b)²
//! ```
//!
//! (Darwin 1959; Chandrasekhar, *The Mathematical Theory of Black Holes*,
//! §20). The roots of G fix everything:
//!
//! - c < 4/27 (b above the critical b_c = 3√3/2 rs): three real roots
//!   u1 < 0 < u2 ≤ u3. A ray outside the photon sphere (u ≤ u2) is
//!   scattered: u = u1 + (u2 - u1) sn²(w, k), k² = (u2 - u1) / (u3 - u1),
//!   w = w0 ± φ √(u3 - u1) / 2; its periapsis is u2 (w = K), it escapes
//!   where u = 0. A ray inside it (u ≥ u3) is trapped:
//!   u = u3 + (u3 - u2) sn²/cn²(w, k), turning at u3 and falling in.
//! - c > 4/27: one real root u1 < 0 and a complex pair m ± in. With
//!   A² = (m - u1)² + n², k² = (A + m - u1) / (2A):
//!   u = u1 + A (1 - cn(w, k)) / (1 + cn(w, k)), w = w0 ± φ √A;
//!   inward rays are captured, outward rays escape.
//!
//! (Byrd & Friedman, *Handbook of Elliptic Integrals*, 236.00, 238.00,
//! 259.00.) The starting argument w0 and the arguments of escape and capture
//! are incomplete elliptic integrals of the first kind, evaluated with
//! Carlson's R_F (Carlson 1995); sn and cn by the arithmetic-geometric mean
//! (Abramowitz & Stegun 16.4). Root differences are taken from trigonometric
//! forms rather than by subtracting roots, so they keep their precision near
//! b_c (where u2 meets u3) and for far rays (where u1 and u2 meet at 0).
//!
//! Disk crossings are where the orbit plane meets the disk plane, at
//! φ0 + jπ; u there comes straight from the formula, with no search.

use std::f64::consts::{FRAC_PI_3, PI};

use glam::DVec3;

use super::geodesic::{Disk, Hole, Outcome};

/// Carlson's symmetric elliptic integral of the first kind,
/// R_F(x, y, z) = ½ ∫₀^∞ dt / √((t + x)(t + y)(t + z)), x, y, z ≥ 0, at most
/// one of them zero. Duplication until the arguments agree to `1e-3`
/// (relative error below 1e-16), then the fifth-order series.
pub fn carlson_rf(mut x: f64, mut y: f64, mut z: f64) -> f64 {
    for _ in 0..64 {
        let a = (x + y + z) / 3.0;
        let (dx, dy, dz) = (1.0 - x / a, 1.0 - y / a, 1.0 - z / a);
        if dx.abs().max(dy.abs()).max(dz.abs()) < 1e-3 {
            let e2 = dx * dy - dz * dz;
            let e3 = dx * dy * dz;
            return (1.0 - e2 / 10.0 + e3 / 14.0 + e2 * e2 / 24.0 - 3.0 * e2 * e3 / 44.0)
                / a.sqrt();
        }
        let (sx, sy, sz) = (x.sqrt(), y.sqrt(), z.sqrt());
        let l = sx * (sy + sz) + sy * sz;
        x = 0.25 * (x + l);
        y = 0.25 * (y + l);
        z = 0.25 * (z + l);
    }
    let a = (x + y + z) / 3.0;
    1.0 / a.sqrt()
}

/// The complete elliptic integral K(k) for the parameter m = k², given as
/// the complementary parameter m' = 1 - m (precise when m is near 1).
pub fn ellip_k(m_complement: f64) -> f64 {
    carlson_rf(0.0, m_complement, 1.0)
}

/// F(ϕ, k) for |ϕ| ≤ π/2 from sin²ϕ, cos²ϕ and 1 - k² sin²ϕ (each given
/// directly, so the caller can form them without cancellation).
fn incomplete_f(sin2: f64, cos2: f64, delta2: f64) -> f64 {
    sin2.max(0.0).sqrt() * carlson_rf(cos2.max(0.0), delta2.max(0.0), 1.0)
}

/// Jacobi sn(w, k) and cn(w, k) for the parameter m = k² (m' = 1 - m given),
/// by the arithmetic-geometric mean and the descent by arcsines (Abramowitz
/// & Stegun 16.4). The shader takes Bulirsch's descending recurrence instead
/// (lightpath.glsl, `jacobi_sn_cn`): the descent's error grows as 2^n times
/// f32's resolution, harmless here in f64, so the two methods check each
/// other.
pub fn jacobi_sn_cn(w: f64, m_complement: f64) -> (f64, f64) {
    let mut a = [0.0f64; 16];
    let mut c = [0.0f64; 16];
    a[0] = 1.0;
    let mut b = m_complement.max(0.0).sqrt();
    c[0] = (1.0 - m_complement).max(0.0).sqrt();
    let mut n = 0;
    while n < 15 && c[n].abs() > 1e-16 {
        a[n + 1] = 0.5 * (a[n] + b);
        c[n + 1] = 0.5 * (a[n] - b);
        b = (a[n] * b).sqrt();
        n += 1;
    }
    let mut phi = 2f64.powi(n as i32) * a[n] * w;
    for i in (1..=n).rev() {
        phi = 0.5 * (phi + (c[i] * phi.sin() / a[i]).clamp(-1.0, 1.0).asin());
    }
    (phi.sin(), phi.cos())
}

/// Which closed form a ray follows.
#[derive(Clone, Copy, Debug, PartialEq)]
enum Kind {
    /// Three real roots, outside the photon sphere: scattered, escapes.
    Scattered,
    /// Three real roots, inside the photon sphere: falls in.
    Trapped,
    /// One real root: escapes if it starts outward, else falls in.
    Plunging,
}

/// A light path in its orbit plane: u(φ) for every φ up to `phi_end`, where
/// the ray escapes (u = 0) or reaches the horizon (u = 1).
#[derive(Clone, Copy, Debug)]
pub struct LightPath {
    kind: Kind,
    u1: f64,
    /// Scattered/Trapped: u2 - u1 and u3 - u2; Plunging: A and unused.
    d21: f64,
    d32: f64,
    u3: f64,
    /// 1 - k².
    m_complement: f64,
    /// K(k).
    k_complete: f64,
    /// Elliptic argument at the camera, and dw/dφ (signed).
    w0: f64,
    rate: f64,
    /// Angle swept from the camera to escape or capture.
    pub phi_end: f64,
    /// Escapes (true) or is captured (false).
    pub escapes: bool,
}

impl LightPath {
    /// A path from its roots `[u1, d21, d32, u3]`, its modulus, where it
    /// starts on its elliptic argument `(w0, dw/dphi, sweep to the end)`.
    fn from_parts(
        kind: Kind,
        [u1, d21, d32, u3]: [f64; 4],
        m_complement: f64,
        k_complete: f64,
        (w0, rate, phi_end): (f64, f64, f64),
        escapes: bool,
    ) -> LightPath {
        LightPath {
            kind,
            u1,
            d21,
            d32,
            u3,
            m_complement,
            k_complete,
            w0,
            rate,
            phi_end: phi_end.max(0.0),
            escapes,
        }
    }

    /// The path of a ray starting at u0 = rs/r with du/dφ = `du` (in units of
    /// rs; `du` > 0 moving inward). `c` = (rs/b)² = du² + u0² - u0³.
    pub fn new(u0: f64, du: f64) -> LightPath {
        let c = du * du + u0 * u0 - u0 * u0 * u0;
        let e = 4.0 / 27.0 - c;
        let inward = du > 0.0;
        if e > 0.0 {
            // Three real roots: u_k = 1/3 + 2/3 cos(θ/3 - 2πk/3),
            // θ = acos(1 - 27c/2) = 2 asin(√(27c/4)), π - θ = 2 asin(√(27e/4)).
            let theta = 2.0 * (27.0 * c / 4.0).sqrt().min(1.0).asin();
            let theta_c = 2.0 * (27.0 * e / 4.0).sqrt().min(1.0).asin();
            let t = theta / 3.0;
            let s3 = 3f64.sqrt();
            let d21 = 2.0 / s3 * t.sin();
            let d31 = 2.0 / s3 * (t + FRAC_PI_3).sin();
            let d32 = 2.0 / s3 * (theta_c / 3.0).sin();
            let sum12 = 4.0 / 3.0 * (theta / 6.0).sin().powi(2); // u1 + u2 = 1 - u3
            let u1 = 0.5 * (sum12 - d21);
            let u2 = u1 + d21;
            let u3 = 1.0 - sum12;
            let m_complement = d32 / d31;
            let k_complete = ellip_k(m_complement);
            let rate = 0.5 * d31.sqrt();
            let g0 = du * du; // = (u0 - u1)(u0 - u2)(u0 - u3)
            let (kind, w0, rate, phi_end, escapes) = if u0 < 2.0 / 3.0 {
                // W(u) = F(asin √((u - u1)/(u2 - u1)), k).
                let w_of = |u: f64, u2_minus_u: f64| {
                    incomplete_f((u - u1) / d21, u2_minus_u / d21, (u3 - u) / d31)
                };
                let u2_minus_u0 = if u0 - u1 > 0.0 && u3 - u0 > 0.0 {
                    g0 / ((u0 - u1) * (u3 - u0))
                } else {
                    u2 - u0
                };
                let w0 = w_of(u0, u2_minus_u0.max(0.0));
                let w_esc = w_of(0.0, u2);
                let (phi_end, rate) = if inward {
                    ((2.0 * k_complete - w_esc - w0) / rate, rate)
                } else {
                    ((w0 - w_esc) / rate, -rate)
                };
                (Kind::Scattered, w0, rate, phi_end, true)
            } else {
                // W3(u) = F(asin √((u - u3)/(u - u2)), k).
                let w_of = |u: f64, u_minus_u3: f64| {
                    let up2 = u_minus_u3 + d32;
                    incomplete_f(u_minus_u3 / up2, d32 / up2, d32 * (u - u1) / (d31 * up2))
                };
                let u0_minus_u3 = if u0 - u1 > 0.0 && u0 - u2 > 0.0 {
                    g0 / ((u0 - u1) * (u0 - u2))
                } else {
                    u0 - u3
                };
                let w0 = w_of(u0, u0_minus_u3.max(0.0));
                let w_h = w_of(1.0, 1.0 - u3);
                let (phi_end, rate) = if inward {
                    ((w_h - w0) / rate, rate)
                } else {
                    ((w_h + w0) / rate, -rate)
                };
                (Kind::Trapped, w0, rate, phi_end, false)
            };
            LightPath::from_parts(
                kind,
                [u1, d21, d32, u3],
                m_complement,
                k_complete,
                (w0, rate, phi_end),
                escapes,
            )
        } else {
            // One real root: u1 = 1/3 - 2/3 cosh(α/3), α = acosh(27c/2 - 1)
            // = 2 asinh(√(-27e/4)). The complex pair m ± in has
            // m - u1 = cosh(α/3) and n² = sinh²(α/3) / 3.
            let alpha = 2.0 * (-6.75 * e).sqrt().asinh();
            let (ch, sh) = ((alpha / 3.0).cosh(), (alpha / 3.0).sinh());
            let u1 = 1.0 / 3.0 - 2.0 / 3.0 * ch;
            let n2 = sh * sh / 3.0;
            let a = (ch * ch + n2).sqrt();
            // 1 - k² = (A - (m - u1)) / (2A) = n² / (2A (A + m - u1)).
            let m_complement = n2 / (2.0 * a * (a + ch));
            let k_complete = ellip_k(m_complement);
            let rate = a.sqrt();
            // W1(u) = F(acos((A - v)/(A + v)), k), v = u - u1; past ϕ = π/2
            // (v > A), F = 2K - F(π - ϕ).
            let w_of = |u: f64| {
                let v = u - u1;
                let cphi = (a - v) / (a + v);
                let sin2 = 4.0 * a * v / ((a + v) * (a + v));
                let f = incomplete_f(sin2, cphi * cphi, 1.0 - (1.0 - m_complement) * sin2);
                if v > a { 2.0 * k_complete - f } else { f }
            };
            let w0 = w_of(u0);
            let (phi_end, rate, escapes) = if inward {
                ((w_of(1.0) - w0) / rate, rate, false)
            } else {
                ((w0 - w_of(0.0)) / rate, -rate, true)
            };
            LightPath::from_parts(
                Kind::Plunging,
                [u1, a, 0.0, 0.0],
                m_complement,
                k_complete,
                (w0, rate, phi_end),
                escapes,
            )
        }
    }

    /// u = rs / r at angle `phi` along the path (0 ≤ phi ≤ phi_end).
    pub fn u_at(&self, phi: f64) -> f64 {
        let w = self.w0 + self.rate * phi;
        let k2 = 2.0 * self.k_complete;
        match self.kind {
            Kind::Scattered | Kind::Trapped => {
                // sn² has period 2K and is even: reduce to [0, K].
                let mut wr = w.rem_euclid(k2);
                if wr > self.k_complete {
                    wr = k2 - wr;
                }
                let (sn, cn) = jacobi_sn_cn(wr, self.m_complement);
                if self.kind == Kind::Scattered {
                    self.u1 + self.d21 * sn * sn
                } else {
                    self.u3 + self.d32 * sn * sn / (cn * cn)
                }
            }
            Kind::Plunging => {
                // w in [0, 2K): cn(2K - w) = -cn(w).
                let (cn, flip) = if w > self.k_complete {
                    (jacobi_sn_cn(k2 - w, self.m_complement).1, -1.0)
                } else {
                    (jacobi_sn_cn(w.max(0.0), self.m_complement).1, 1.0)
                };
                let cn = flip * cn;
                self.u1 + self.d21 * (1.0 - cn) / (1.0 + cn)
            }
        }
    }
}

/// Where a ray from `x0` along `v0` (any length) goes around one hole, in
/// closed form; the same outcomes as [`super::geodesic::trace`] with that
/// one hole. The disk (centred on the hole) is opaque: the first crossing of
/// its plane within [inner, outer] counts.
pub fn trace_closed(hole: &Hole, disk: Option<&Disk>, x0: DVec3, v0: DVec3) -> Outcome {
    let rs = hole.rs;
    let rel = x0 - hole.position;
    let r0 = rel.length();
    let e1 = rel / r0;
    let d = v0.normalize();
    let axis = e1.cross(d);
    if axis.length() < 1e-12 {
        return if d.dot(e1) < 0.0 {
            Outcome::Captured { hole: 0 }
        } else {
            Outcome::Escaped { direction: d }
        };
    }
    let axis = axis.normalize();
    let e2 = axis.cross(e1);
    let u0 = rs / r0;
    let du = -(d.dot(e1) / d.dot(e2)) * u0;
    let path = LightPath::new(u0, du);
    let point = |phi: f64, u: f64| hole.position + (rs / u) * (phi.cos() * e1 + phi.sin() * e2);

    if let Some(disk) = disk {
        let n = disk.normal.normalize();
        let (a, b) = (e1.dot(n), e2.dot(n));
        if a.abs() + b.abs() > 1e-12 {
            // a cos φ + b sin φ = 0: the next crossing ahead of the camera.
            let mut phi = (-a).atan2(b);
            if phi <= 1e-9 {
                phi += PI;
            }
            while phi < path.phi_end {
                let u = path.u_at(phi);
                let r = rs / u;
                if r >= disk.inner && r <= disk.outer {
                    // Tangent dx/dφ in the direction of travel.
                    let dudphi = path.rate.signum()
                        * (u * u * u - u * u + path_c(u0, du)).max(0.0).sqrt()
                        * dudphi_sign(&path, phi);
                    let radial = phi.cos() * e1 + phi.sin() * e2;
                    let along = -phi.sin() * e1 + phi.cos() * e2;
                    let velocity = along / u - radial * dudphi / (u * u);
                    return Outcome::Disk {
                        position: point(phi, u),
                        velocity,
                    };
                }
                phi += PI;
            }
        }
    }
    if path.escapes {
        let phi = path.phi_end;
        Outcome::Escaped {
            direction: phi.cos() * e1 + phi.sin() * e2,
        }
    } else {
        Outcome::Captured { hole: 0 }
    }
}

fn path_c(u0: f64, du: f64) -> f64 {
    du * du + u0 * u0 - u0 * u0 * u0
}

/// The sign of du/dw at angle `phi` (times the sign of dw/dφ gives du/dφ).
fn dudphi_sign(path: &LightPath, phi: f64) -> f64 {
    let w = path.w0 + path.rate * phi;
    match path.kind {
        // u grows with w on (0, K) mod 2K and falls on (K, 2K).
        Kind::Scattered | Kind::Trapped => {
            if w.rem_euclid(2.0 * path.k_complete) < path.k_complete {
                1.0
            } else {
                -1.0
            }
        }
        Kind::Plunging => 1.0,
    }
}
