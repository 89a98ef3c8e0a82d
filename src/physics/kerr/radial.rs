//! The radial motion r(tau) of a backward ray in Mino time (Gralla &
//! Lupsasca 2020): the roots of the quartic R(r), the four cases, where the
//! ray ends (the horizon or infinity), and the radial part I_phi of its
//! azimuth. M = 1.

use num_complex::Complex64;

use super::elliptic::{f_sc, k_of, pi_of_xi, pi_sc, rc, sn_cn_dn};
use super::frame::{r_horizon, r_inner_horizon};

/// R(r) = (r^2 + a^2 - a lambda)^2 - Delta (eta + (lambda - a)^2).
pub fn r_potential(r: f64, a: f64, lambda: f64, eta: f64) -> f64 {
    (r * r + a * a - a * lambda).powi(2) - (r * r - 2.0 * r + a * a) * (eta + (lambda - a).powi(2))
}

/// Where a path's roots take [`far_roots`]: lambda^2 + eta - a^2 (-A) at
/// least this.
pub const FAR_ROOTS: f64 = 1e5;

/// The four roots of R(r), GL 2020 eqs. (79)-(95), in their order
/// (r1 <= r2 <= r3 <= r4 where real); for a large lambda^2 + eta,
/// [`far_roots`].
pub fn radial_roots(a: f64, lambda: f64, eta: f64) -> [Complex64; 4] {
    let big_a = a * a - eta - lambda * lambda;
    let big_b = 2.0 * (eta + (lambda - a).powi(2));
    let big_c = -a * a * eta;
    if -big_a >= FAR_ROOTS {
        return far_roots(big_a, big_b, big_c).map(|r| Complex64::new(r, 0.0));
    }
    cardano_roots(big_a, big_b, big_c)
}

/// The roots of r^4 + A r^2 + B r + C through the resolvent cubic
/// (Cardano), GL 2020 eqs. (79)-(95).
fn cardano_roots(big_a: f64, big_b: f64, big_c: f64) -> [Complex64; 4] {
    let p = -big_a * big_a / 12.0 - big_c;
    let q = -big_a / 3.0 * ((big_a / 6.0).powi(2) - big_c) - big_b * big_b / 8.0;
    let sq = Complex64::new((p / 3.0).powi(3) + (q / 2.0).powi(2), 0.0).sqrt();
    let cbrt = |z: Complex64| {
        if z.im.abs() < 1e-14 * z.re.abs().max(1.0) {
            Complex64::new(z.re.cbrt(), 0.0)
        } else {
            z.powf(1.0 / 3.0)
        }
    };
    let half_q = Complex64::new(-q / 2.0, 0.0);
    let (wp, wm) = (cbrt(half_q + sq), cbrt(half_q - sq));
    let z = ((wp + wm) / 2.0 - big_a / 6.0).sqrt();
    let t1 = (-big_a / 2.0 - z * z + big_b / (4.0 * z)).sqrt();
    let t2 = (-big_a / 2.0 - z * z - big_b / (4.0 * z)).sqrt();
    [-z - t1, -z + t1, z - t2, z + t2]
}

/// The roots of R(r) = r^4 + A r^2 + B r + C where -A is large (a photon
/// of energy near zero, lambda = L / E and eta = Q / E^2 unbounded as E ->
/// 0; a far camera's wide rays): two roots near +-sqrt(-A), two near the
/// hole. The resolvent's two largest roots almost coincide there, and
/// Cardano's z keeps few of the small pair's digits; the small pair comes
/// instead from A r^2 + B r + C = 0 (R without r^4, relatively 1 / -A
/// smaller near the hole), polished by Newton's method on R, and the large
/// pair from Vieta's sums. All four are real (A r^2 + B r + C's
/// discriminant is 4 (eta + lambda^2)(eta (1 - a^2) + lambda^2) to leading
/// order), r1 < 0 < r2 < r3 < r4.
pub fn far_roots(big_a: f64, big_b: f64, big_c: f64) -> [f64; 4] {
    let t = -0.5 * (big_b + (big_b * big_b - 4.0 * big_a * big_c).max(0.0).sqrt());
    let polish = |mut r: f64| {
        for _ in 0..4 {
            let f = ((r * r + big_a) * r + big_b) * r + big_c;
            let df = (4.0 * r * r + 2.0 * big_a) * r + big_b;
            r -= f / df;
        }
        r
    };
    let (s_a, s_b) = (
        polish(t / big_a),
        polish(if t != 0.0 { big_c / t } else { 0.0 }),
    );
    let (s1, s2) = (s_a.min(s_b), s_a.max(s_b));
    let sum = s1 + s2;
    let product = (s1 * s2 * sum - big_b) / sum;
    let r4 = 0.5 * ((sum * sum - 4.0 * product).sqrt() - sum);
    [product / r4, s1, s2, r4]
}

/// The radial case of a ray and what it needs to give r(tau).
#[derive(Clone, Copy, Debug)]
enum Motion {
    /// Case 2 (four real roots, camera beyond r4: X = X0 + g tau) and case
    /// 1 (camera inside the photon shell, bounded by r3).
    Real {
        bounded: bool,
        roots: [f64; 4],
        x0: f64,
    },
    /// Case 3: two real roots, a complex pair; xi(tau) = xi_o +- g tau.
    TwoReal(TwoReal),
    /// Case 4: no real root outside; Y(tau) = Y_o +- g tau.
    Complex { a2: f64, b1: f64, g0: f64, y_o: f64 },
}

/// Case 3's roots r1 < r2, A = |r3 - r2|, B = |r3 - r1| and xi at the
/// camera.
#[derive(Clone, Copy, Debug)]
struct TwoReal {
    r1: f64,
    r2: f64,
    big_a: f64,
    big_b: f64,
    xi_o: f64,
}

/// r(tau) of a backward ray from the camera at r_o with initial sign s_r.
#[derive(Clone, Copy, Debug)]
pub struct Radial {
    pub a: f64,
    pub lambda: f64,
    pub eta: f64,
    pub r_o: f64,
    pub s_r: f64,
    pub r_plus: f64,
    pub r_minus: f64,
    /// GL's radial case, 1 to 4.
    pub case: u8,
    /// The ray ends in the horizon (else at infinity).
    pub captured: bool,
    /// The Mino time at which it gets there.
    pub tau_end: f64,
    /// Elliptic parameter, its K and the rate d(argument)/dtau.
    pub m: f64,
    pub k: f64,
    pub rate: f64,
    motion: Motion,
}

impl Radial {
    pub fn new(a: f64, lambda: f64, eta: f64, r_o: f64, s_r: f64) -> Radial {
        let r_plus = r_horizon(a);
        let r_minus = r_inner_horizon(a);
        let roots = radial_roots(a, lambda, eta);
        let scale = roots.iter().map(|z| z.norm()).fold(1.0, f64::max);
        let real: Vec<bool> = roots.iter().map(|z| z.im.abs() < 1e-9 * scale).collect();
        let base = Radial {
            a,
            lambda,
            eta,
            r_o,
            s_r,
            r_plus,
            r_minus,
            case: 0,
            captured: false,
            tau_end: 0.0,
            m: 0.0,
            k: 0.0,
            rate: 0.0,
            motion: Motion::Complex {
                a2: 0.0,
                b1: 0.0,
                g0: 0.0,
                y_o: 0.0,
            },
        };
        if real.iter().all(|&x| x) {
            base.four_real(roots.map(|z| z.re))
        } else if real[0] && real[1] {
            base.two_real(roots[0].re, roots[1].re, roots[2], roots[3])
        } else {
            base.no_real(roots)
        }
    }

    fn four_real(mut self, [r1, r2, r3, r4]: [f64; 4]) -> Radial {
        let (r31, r32, r41, r42) = (r3 - r1, r3 - r2, r4 - r1, r4 - r2);
        self.m = r32 * r41 / (r31 * r42);
        self.rate = 0.5 * (r31 * r42).sqrt();
        self.k = k_of(self.m);
        let amplitude = |x2: f64| f_sc(x2.sqrt(), 1.0 - x2, self.m);
        let (x_end, fo);
        if self.r_o >= r4 {
            self.case = 2;
            fo = amplitude((self.r_o - r4) * r31 / ((self.r_o - r3) * r41));
            let f_inf = amplitude(r31 / r41);
            if r4 < self.r_plus {
                // Every root inside the horizon: no turning point outside.
                let fh = amplitude((self.r_plus - r4) * r31 / ((self.r_plus - r3) * r41));
                self.captured = self.s_r < 0.0;
                x_end = if self.captured { -fh } else { f_inf };
            } else {
                x_end = f_inf;
            }
        } else {
            self.case = 1;
            fo = amplitude((self.r_o - r2) * r31 / ((self.r_o - r1) * r32));
            let fh = amplitude((self.r_plus - r2) * r31 / ((self.r_plus - r1) * r32));
            self.captured = true;
            x_end = if self.s_r < 0.0 {
                -fh
            } else {
                2.0 * self.k - fh
            };
        }
        let x0 = self.s_r * fo;
        self.tau_end = (x_end - x0) / self.rate;
        self.motion = Motion::Real {
            bounded: self.case == 1,
            roots: [r1, r2, r3, r4],
            x0,
        };
        self
    }

    fn two_real(mut self, r1: f64, r2: f64, r3: Complex64, r4: Complex64) -> Radial {
        self.case = 3;
        let big_a = ((r3 - r2) * (r4 - r2)).re.sqrt();
        let big_b = ((r3 - r1) * (r4 - r1)).re.sqrt();
        self.m = ((big_a + big_b).powi(2) - (r2 - r1).powi(2)) / (4.0 * big_a * big_b);
        self.rate = (big_a * big_b).sqrt();
        self.k = k_of(self.m);
        let (m, k) = (self.m, self.k);
        // cn(xi) = x, xi in [0, 2K].
        let xi_of_cn = |x: f64| {
            let f = f_sc((1.0 - x * x).max(0.0).sqrt(), x * x, m);
            if x >= 0.0 { f } else { 2.0 * k - f }
        };
        let xi_of = |r: f64| {
            xi_of_cn((big_a * (r - r1) - big_b * (r - r2)) / (big_a * (r - r1) + big_b * (r - r2)))
        };
        let xi_o = xi_of(self.r_o);
        let xi_inf = xi_of_cn((big_a - big_b) / (big_a + big_b));
        let xi_h = xi_of(self.r_plus);
        self.captured = self.s_r < 0.0;
        self.tau_end = if self.captured {
            (xi_o - xi_h) / self.rate
        } else {
            (xi_inf - xi_o) / self.rate
        };
        self.motion = Motion::TwoReal(TwoReal {
            r1,
            r2,
            big_a,
            big_b,
            xi_o,
        });
        self
    }

    fn no_real(mut self, [r1, r2, r3, r4]: [Complex64; 4]) -> Radial {
        self.case = 4;
        self.captured = self.s_r < 0.0;
        let c = ((r3 - r1) * (r4 - r2)).re.sqrt();
        let d = ((r3 - r2) * (r4 - r1)).re.sqrt();
        let a2 = ((r2 - r1) / 2.0).im.abs();
        let b1 = ((r3 + r4) / 2.0).re;
        self.m = 4.0 * c * d / (c + d).powi(2);
        let g0 = ((4.0 * a2 * a2 - (c - d).powi(2)) / ((c + d).powi(2) - 4.0 * a2 * a2))
            .max(0.0f64)
            .sqrt();
        self.rate = (c + d) / 2.0;
        self.k = k_of(self.m);
        let y_o = self.f_amplitude(((self.r_o + b1) / a2).atan() + g0.atan());
        let y_inf = self.f_amplitude(std::f64::consts::FRAC_PI_2 + g0.atan());
        let y_h = self.f_amplitude(((self.r_plus + b1) / a2).atan() + g0.atan());
        self.tau_end = if self.captured {
            (y_o - y_h) / self.rate
        } else {
            (y_inf - y_o) / self.rate
        };
        self.motion = Motion::Complex { a2, b1, g0, y_o };
        self
    }

    /// F(phi | m) for any real amplitude.
    fn f_amplitude(&self, phi: f64) -> f64 {
        let pi = std::f64::consts::PI;
        let j = ((phi + pi / 2.0) / pi).floor();
        let pr = phi - j * pi;
        2.0 * j * self.k + f_sc(pr.sin(), pr.cos().powi(2), self.m)
    }

    /// The sign-carrying Mino-time argument of cases 3 and 4.
    fn signed(&self, tau: f64) -> f64 {
        if self.s_r > 0.0 {
            self.rate * tau
        } else {
            -self.rate * tau
        }
    }

    /// r at Mino time tau (0 <= tau <= tau_end).
    pub fn r_at(&self, tau: f64) -> f64 {
        match self.motion {
            Motion::Real {
                bounded,
                roots: [r1, r2, r3, r4],
                x0,
            } => {
                let (sn, _, _) = sn_cn_dn(x0 + self.rate * tau, self.m);
                let s2 = sn * sn;
                if bounded {
                    (r2 * (r3 - r1) - r1 * (r3 - r2) * s2) / ((r3 - r1) - (r3 - r2) * s2)
                } else {
                    (r4 * (r3 - r1) - r3 * (r4 - r1) * s2) / ((r3 - r1) - (r4 - r1) * s2)
                }
            }
            Motion::TwoReal(t) => {
                let (_, cn, _) = sn_cn_dn(t.xi_o + self.signed(tau), self.m);
                let (a, b) = (t.big_a, t.big_b);
                ((b * t.r2 - a * t.r1) + (b * t.r2 + a * t.r1) * cn) / ((b - a) + (b + a) * cn)
            }
            Motion::Complex { a2, b1, g0, y_o } => {
                let (sn, cn, _) = sn_cn_dn(y_o + self.signed(tau), self.m);
                let sc = sn / cn;
                -a2 * (g0 - sc) / (1.0 + g0 * sc) - b1
            }
        }
    }

    /// The sign of dr/dtau of the backward ray at Mino time tau: in cases 1
    /// and 2 r grows with sn^2(X), X = x0 + rate tau, so the sign is that of
    /// sn cn; in cases 3 and 4 r is monotonic in the signed argument, so it
    /// is s_r throughout (no turning point outside the horizon).
    pub fn backward_r_sign(&self, tau: f64) -> f64 {
        match self.motion {
            Motion::Real { x0, .. } => {
                let (sn, cn, _) = sn_cn_dn(x0 + self.rate * tau, self.m);
                1f64.copysign(sn * cn)
            }
            _ => self.s_r,
        }
    }

    /// I_phi(tau), the integral of a (2 r - a lambda) / Delta over Mino
    /// time: the radial part of the azimuth's change.
    pub fn i_phi(&self, tau: f64) -> f64 {
        if self.a == 0.0 {
            return 0.0;
        }
        let mut out = 0.0;
        for (rh, sign) in [(self.r_plus, 1.0), (self.r_minus, -1.0)] {
            let ah = sign * (2.0 * rh - self.a * self.lambda) / (self.r_plus - self.r_minus);
            out += self.a * ah * self.j_horizon(rh, tau);
        }
        out
    }

    /// I_phi(t1) - I_phi(t0): the closed forms' difference, or in case 4
    /// the quadrature over [t0, t1] alone (a path's points add these up,
    /// path.rs, where a quadrature from 0 for each would be slow).
    pub fn i_phi_between(&self, t0: f64, t1: f64) -> f64 {
        if self.a == 0.0 || t1 == t0 {
            return 0.0;
        }
        if !matches!(self.motion, Motion::Complex { .. }) {
            // (At tau = 0 the forms are 0 / 0; I_phi(0) = 0.)
            let at = |t: f64| if t == 0.0 { 0.0 } else { self.i_phi(t) };
            return at(t1) - at(t0);
        }
        let mut out = 0.0;
        for (rh, sign) in [(self.r_plus, 1.0), (self.r_minus, -1.0)] {
            let ah = sign * (2.0 * rh - self.a * self.lambda) / (self.r_plus - self.r_minus);
            let j = adaptive_gauss(&|t| 1.0 / (self.r_at(t) - rh), t0, t1, 1e-13, 12);
            out += self.a * ah * j;
        }
        out
    }

    /// J_h(tau): the integral of 1 / (r - r_h) over Mino time.
    fn j_horizon(&self, rh: f64, tau: f64) -> f64 {
        match self.motion {
            Motion::Real {
                bounded: false,
                roots: [r1, _, r3, r4],
                x0,
            } => {
                let (r31, r41, r43) = (r3 - r1, r4 - r1, r4 - r3);
                let x1 = x0 + self.rate * tau;
                let (s0, c0, _) = sn_cn_dn(x0, self.m);
                let (s1, c1, _) = sn_cn_dn(x1, self.m);
                let n = r41 * (r3 - rh) / (r31 * (r4 - rh));
                let p = pi_sc(n, s1, c1 * c1, self.m) - pi_sc(n, s0, c0 * c0, self.m);
                tau / (r3 - rh) - r43 / (self.rate * (r4 - rh) * (r3 - rh)) * p
            }
            Motion::Real {
                bounded: true,
                roots: [r1, r2, r3, _],
                x0,
            } => {
                let (r21, r31, r32) = (r2 - r1, r3 - r1, r3 - r2);
                if (rh - r2).abs() < 1e-6 * r21 {
                    return self.j_quadrature(rh, tau);
                }
                let x1 = x0 + self.rate * tau;
                let n = r32 * (r1 - rh) / (r31 * (r2 - rh));
                let p = |x: f64| x.signum() * pi_of_xi(n, x.abs(), self.m, self.k);
                tau / (r1 - rh) - r21 / (self.rate * (r2 - rh) * (r1 - rh)) * (p(x1) - p(x0))
            }
            Motion::TwoReal(TwoReal {
                r1,
                r2,
                big_a,
                big_b,
                xi_o,
            }) => {
                if (rh - r2).abs() < 1e-6 * (r2 - r1) {
                    return self.j_quadrature(rh, tau);
                }
                let (a, b) = (big_a, big_b);
                let dm = b * (rh - r2) - a * (rh - r1);
                let dp = b * (rh - r2) + a * (rh - r1);
                let al = dp / dm;
                let c1 = -(b + a) / dp;
                let c2 = -((b - a) - (b + a) * dm / dp) / dm;
                let n = al * al / (al * al - 1.0);
                let gam = self.m + al * al / (1.0 - al * al);
                let r1_of = |xi: f64| {
                    let (sn, _, dn) = sn_cn_dn(xi, self.m);
                    let w = sn / dn;
                    (pi_of_xi(n, xi, self.m, self.k) - al * w * rc_pv(1.0, 1.0 + gam * w * w))
                        / (1.0 - al * al)
                };
                let xi1 = xi_o + self.signed(tau);
                (c1 * (xi1 - xi_o) + c2 * (r1_of(xi1) - r1_of(xi_o))) / self.rate
                    * self.s_r.signum()
            }
            // Case 4 needs I_phi only to infinity (outward rays):
            // `outward_i_phi` there.
            Motion::Complex { .. } => self.j_quadrature(rh, tau),
        }
    }

    /// J_h by adaptive quadrature along the closed-form r(tau), where the
    /// closed form is 0/0 (r_h = r_- next to r2).
    fn j_quadrature(&self, rh: f64, tau: f64) -> f64 {
        adaptive_gauss(&|t| 1.0 / (self.r_at(t) - rh), 0.0, tau, 1e-14, 30)
    }
}

/// R_C with its Cauchy principal value for y < 0 (DLMF 19.2.20).
fn rc_pv(x: f64, y: f64) -> f64 {
    if y > 0.0 {
        rc(x, y)
    } else {
        (x / (x - y)).sqrt() * rc(x - y, -y)
    }
}

/// Gauss-Legendre nodes and weights on [-1, 1] (Newton on P_n).
pub fn gauss_legendre(n: usize) -> Vec<(f64, f64)> {
    (0..n)
        .map(|i| {
            let mut x = (std::f64::consts::PI * (i as f64 + 0.75) / (n as f64 + 0.5)).cos();
            let mut dp = 1.0;
            for _ in 0..100 {
                let (mut p0, mut p1) = (1.0, x);
                for k in 2..=n {
                    let p2 = ((2 * k - 1) as f64 * x * p1 - (k - 1) as f64 * p0) / k as f64;
                    p0 = p1;
                    p1 = p2;
                }
                dp = n as f64 * (x * p1 - p0) / (x * x - 1.0);
                let dx = p1 / dp;
                x -= dx;
                if dx.abs() < 1e-16 {
                    break;
                }
            }
            (x, 2.0 / ((1.0 - x * x) * dp * dp))
        })
        .collect()
}

/// The integral of f over [a, b] by 16-point Gauss-Legendre, halving the
/// interval where two halves disagree with the whole by more than `tol`.
pub fn adaptive_gauss(f: &dyn Fn(f64) -> f64, a: f64, b: f64, tol: f64, depth: u32) -> f64 {
    let rule = gauss_legendre(16);
    fn gl(rule: &[(f64, f64)], f: &dyn Fn(f64) -> f64, a: f64, b: f64) -> f64 {
        let (h, c) = (0.5 * (b - a), 0.5 * (a + b));
        rule.iter().map(|(x, w)| w * f(c + h * x)).sum::<f64>() * h
    }
    fn go(
        rule: &[(f64, f64)],
        f: &dyn Fn(f64) -> f64,
        a: f64,
        b: f64,
        whole: f64,
        tol: f64,
        depth: u32,
    ) -> f64 {
        let m = 0.5 * (a + b);
        let (l, r) = (gl(rule, f, a, m), gl(rule, f, m, b));
        if depth == 0 || (l + r - whole).abs() <= tol * (l + r).abs().max(1e-300) {
            l + r
        } else {
            go(rule, f, a, m, l, tol, depth - 1) + go(rule, f, m, b, r, tol, depth - 1)
        }
    }
    let whole = gl(&rule, f, a, b);
    go(&rule, f, a, b, whole, tol, depth)
}

/// Mino time and I_phi of an outward ray from r_o to infinity, by
/// Gauss-Legendre in u = 1/r (smooth there: no turning point).
pub fn outward_u_quadrature(a: f64, lambda: f64, eta: f64, r_o: f64) -> (f64, f64) {
    let uo = 1.0 / r_o;
    let (mut tau, mut i_phi) = (0.0, 0.0);
    for (x, w) in gauss_legendre(16) {
        let u = 0.5 * uo * (x + 1.0);
        let w = 0.5 * uo * w;
        let rt = 1.0 - (eta + lambda * lambda - a * a) * u * u
            + 2.0 * (eta + (lambda - a).powi(2)) * u.powi(3)
            - a * a * eta * u.powi(4);
        tau += w / rt.sqrt();
        i_phi +=
            w * a * (2.0 * u - a * lambda * u * u) / ((1.0 - 2.0 * u + a * a * u * u) * rt.sqrt());
    }
    (tau, i_phi)
}

#[cfg(test)]
mod tests {
    use super::*;

    /// A quartic built from chosen roots (two near the hole, two at
    /// +-1e3 to +-1e9, summing to zero as R's do) gives them back: from
    /// its coefficients by Vieta, not from R's constants.
    #[test]
    fn far_roots_give_back_the_roots_a_quartic_was_built_from() {
        for (s1, s2) in [
            (0.0144635, 1.9855853),
            (-0.3, 1.7),
            (0.02, 0.05),
            (0.0, 2.0),
        ] {
            for big in [1e3, 3.7e4, 1e6, 1e9] {
                let r1 = -big;
                let r4 = big - s1 - s2;
                let roots = [r1, s1, s2, r4];
                let e2 = r1 * (s1 + s2 + r4) + s1 * (s2 + r4) + s2 * r4;
                let e3 = r1 * s1 * s2 + r1 * s1 * r4 + r1 * s2 * r4 + s1 * s2 * r4;
                let e4 = r1 * s1 * s2 * r4;
                let got = far_roots(e2, -e3, e4);
                for (g, r) in got.iter().zip(roots) {
                    let tol = 1e-14 * r.abs().max(1.0) + 1e-15 * big.sqrt();
                    assert!((g - r).abs() <= tol, "{roots:?}: {got:?}");
                }
            }
        }
    }

    /// Around the threshold both forms give the same roots, so that a
    /// path's case and values do not jump there.
    #[test]
    fn the_far_form_meets_cardanos_at_its_threshold() {
        for (a, lambda, eta) in [
            (0.99, 301.0, 1e4),
            (0.5, -100.0, 9.01e4),
            (0.9999, 316.5, 200.0),
        ] {
            let big_a: f64 = a * a - eta - lambda * lambda;
            let big_b = 2.0 * (eta + (lambda - a) * (lambda - a));
            let big_c = -a * a * eta;
            assert!(-big_a >= FAR_ROOTS && -big_a < 1.1 * FAR_ROOTS);
            let far = far_roots(big_a, big_b, big_c);
            let cardano = cardano_roots(big_a, big_b, big_c);
            for (f, c) in far.iter().zip(cardano) {
                assert!(c.im.abs() < 1e-9 * big_a.abs().sqrt(), "{cardano:?}");
                assert!(
                    (f - c.re).abs() <= 1e-9 * f.abs().max(1.0),
                    "{far:?} {cardano:?}"
                );
            }
        }
    }
}
