//! The polar motion theta(tau) of a backward ray in Mino time: the
//! ordinary motion (eta > 0) crossing the equator at an arithmetic
//! progression of Mino times, the vortical motion (eta < 0) that never
//! does, and the angular part lambda G_phi of the azimuth. M = 1.

use std::f64::consts::PI;

use super::elliptic::{f_sc, k_of, pi_neg_continued, rf, rj, sn_cn_dn};

/// cos(theta) = sqrt(u+) cn(psi | m), psi = w tau + s_theta (K - F_o).
#[derive(Clone, Copy, Debug)]
pub struct Ordinary {
    pub w: f64,
    pub u_plus: f64,
    /// 1 - u+ without cancellation.
    pub one_minus_u_plus: f64,
    pub m: f64,
    pub k: f64,
    /// The signed phase from the equator at the camera (north > 0).
    pub f_o: f64,
    pub s_theta: f64,
}

impl Ordinary {
    /// `cos_o`: cos(theta) at the camera; `theta_potential`: Theta there.
    pub fn new(
        a: f64,
        lambda: f64,
        eta: f64,
        cos_o: f64,
        theta_potential: f64,
        s_theta: f64,
    ) -> Self {
        let h = eta + lambda * lambda - a * a;
        let s = (h * h + 4.0 * a * a * eta).sqrt();
        let w = s.sqrt();
        let u_plus = if h >= 0.0 {
            2.0 * eta / (h + s)
        } else {
            (s - h) / (2.0 * a * a)
        };
        let um = (h + s) / 2.0; // -a^2 u-, >= 0
        let one_minus_u_plus = if a * a + um > 0.0 {
            lambda * lambda / (a * a + um)
        } else {
            1.0 - u_plus
        };
        let m = a * a * u_plus / s;
        let s_o2 = 1.0 - cos_o * cos_o;
        let den = a * a * cos_o * cos_o + um;
        let up_minus_c2 = if den > 0.0 {
            theta_potential * s_o2 / den
        } else {
            u_plus - cos_o * cos_o
        };
        let (sin2, cos2) = if u_plus > 0.0 {
            (
                cos_o * cos_o * s / (u_plus * den),
                um * up_minus_c2 / (u_plus * den),
            )
        } else {
            (0.0, 1.0)
        };
        let y = if den > 0.0 { um / den } else { 1.0 };
        let f_o = 1f64.copysign(cos_o) * sin2.max(0.0).sqrt() * rf(cos2.max(0.0), y, 1.0);
        Ordinary {
            w,
            u_plus,
            one_minus_u_plus,
            m,
            k: k_of(m),
            f_o,
            s_theta,
        }
    }

    /// The Mino time of the n-th (0, 1, ...) equatorial crossing.
    pub fn crossing_tau(&self, n: u32) -> f64 {
        let sf = self.s_theta * self.f_o;
        let h = if sf > 0.0 { 0.0 } else { 1.0 };
        (2.0 * (f64::from(n) + h) * self.k + sf) / self.w
    }

    fn psi0(&self) -> f64 {
        self.s_theta * (self.k - self.f_o)
    }

    /// cos(theta(tau)).
    pub fn cos_theta_at(&self, tau: f64) -> f64 {
        let (_, cn, _) = sn_cn_dn(self.w * tau + self.psi0(), self.m);
        self.u_plus.sqrt() * cn
    }

    /// lambda G_phi(tau) = lambda times the integral of 1 / sin^2 theta.
    pub fn lambda_g_phi(&self, lambda: f64, tau: f64) -> f64 {
        let psi0 = self.psi0();
        let psi1 = self.w * tau + psi0;
        if lambda == 0.0 {
            // In a meridian plane: pi at each passage over the axis.
            let k2 = 2.0 * self.k;
            return PI * ((psi1 / k2).floor() - (psi0 / k2).floor());
        }
        let n = self.u_plus / self.one_minus_u_plus;
        lambda / (self.w * self.one_minus_u_plus)
            * (pi_neg_continued(n, psi1, self.m, self.k)
                - pi_neg_continued(n, psi0, self.m, self.k))
    }
}

/// The vortical motion (eta < 0): theta stays on one side of the equator,
/// cos(theta) = h sqrt(u-) / dn(v0 + w tau | k).
#[derive(Clone, Copy, Debug)]
pub struct Vortical {
    u_minus: f64,
    /// 1 - n of the azimuth's characteristic n = m / (1 - u-), formed
    /// without cancellation: it is ~ lambda^2 as the ray passes near the
    /// axis (and 0 in f64 from 1 - n itself at lambda ~ 1e-8).
    one_minus_n: f64,
    m: f64,
    k: f64,
    w: f64,
    v0: f64,
    hemisphere: f64,
}

impl Vortical {
    pub fn new(a: f64, lambda: f64, eta: f64, cos_o: f64, s_theta: f64) -> Self {
        let h = eta + lambda * lambda - a * a;
        let s = (h * h + 4.0 * a * a * eta).sqrt();
        let (a2up, a2um) = ((s - h) / 2.0, (-h - s) / 2.0);
        let (up, um) = (a2up / (a * a), a2um / (a * a));
        let m = 1.0 - um / up;
        // 1 - u+ = 2 lambda^2 / (a^2 + eta + lambda^2 + s), exactly; 1 - n
        // = u- (1 - u+) / (u+ (1 - u-)).
        let one_minus_up = 2.0 * lambda * lambda / (a * a + eta + lambda * lambda + s);
        let one_minus_n = um * one_minus_up / (up * (1.0 - um));
        let sn2 = ((cos_o * cos_o - um) * up / (cos_o * cos_o * (up - um))).clamp(0.0, 1.0);
        let fv = f_sc(sn2.sqrt(), 1.0 - sn2, m);
        let away = s_theta * 1f64.copysign(cos_o) < 0.0;
        Vortical {
            u_minus: um,
            one_minus_n,
            m,
            k: k_of(m),
            w: a2up.sqrt(),
            v0: if away { fv } else { -fv },
            hemisphere: 1f64.copysign(cos_o),
        }
    }

    pub fn cos_theta_at(&self, tau: f64) -> f64 {
        let (_, _, dn) = sn_cn_dn(self.v0 + self.w * tau, self.m);
        self.hemisphere * self.u_minus.sqrt() / dn
    }

    pub fn lambda_g_phi(&self, lambda: f64, tau: f64) -> f64 {
        let (um, m, k) = (self.u_minus, self.m, self.k);
        let n = m / (1.0 - um);
        // Pi(n; phi | m) (DLMF 19.25.14) with 1 - n sin^2 = (1 - n) + n cos^2.
        let pi_of = |s: f64, c2: f64| {
            let d2 = 1.0 - m * s * s;
            s * rf(c2, d2, 1.0) + n / 3.0 * s * s * s * rj(c2, d2, 1.0, self.one_minus_n + n * c2)
        };
        let complete = pi_of(1.0, 0.0);
        let p = |v: f64| {
            let j = ((v + k) / (2.0 * k)).floor();
            let vr = v - 2.0 * j * k;
            let (sn, cn, _) = sn_cn_dn(vr.abs(), m);
            2.0 * j * complete + vr.signum() * pi_of(sn, cn * cn)
        };
        let (v0, v1) = (self.v0, self.v0 + self.w * tau);
        if lambda == 0.0 {
            let k2 = 2.0 * k;
            return PI * (((v1 - k) / k2).floor() - ((v0 - k) / k2).floor());
        }
        lambda / self.w * ((v1 - v0) + um / (1.0 - um) * (p(v1) - p(v0)))
    }
}
