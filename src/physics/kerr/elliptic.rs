//! The elliptic functions of the Kerr light paths in f64: Carlson's R_F,
//! R_J and R_C (from the `ellip` crate, R_C with its Cauchy principal
//! value), the Legendre forms built on them with the amplitude given by its
//! sine and squared cosine, the third kind continued past its pole and
//! quasi-periodically past K, and Jacobi's sn, cn, dn by the AGM.

/// R_F(x, y, z); NaN where the crate refuses the arguments.
pub fn rf(x: f64, y: f64, z: f64) -> f64 {
    ellip::elliprf(x, y, z).unwrap_or(f64::NAN)
}

/// R_J(x, y, z, p).
pub fn rj(x: f64, y: f64, z: f64, p: f64) -> f64 {
    ellip::elliprj(x, y, z, p).unwrap_or(f64::NAN)
}

/// R_C(x, y), x >= 0, y != 0; the Cauchy principal value for y < 0.
pub fn rc(x: f64, y: f64) -> f64 {
    ellip::elliprc(x, y).unwrap_or(f64::NAN)
}

/// K(m), the complete integral of the first kind.
pub fn k_of(m: f64) -> f64 {
    rf(0.0, 1.0 - m, 1.0)
}

/// F(phi | m) for |phi| <= pi/2 from s = sin(phi) (signed) and c2 = cos^2.
pub fn f_sc(s: f64, c2: f64, m: f64) -> f64 {
    s * rf(c2, 1.0 - m * s * s, 1.0)
}

/// Pi(n; phi | m) for |phi| <= pi/2, n <= 1 (DLMF 19.25.14).
pub fn pi_sc(n: f64, s: f64, c2: f64, m: f64) -> f64 {
    let d2 = 1.0 - m * s * s;
    s * rf(c2, d2, 1.0) + n / 3.0 * s * s * s * rj(c2, d2, 1.0, 1.0 - n * s * s)
}

/// Pi(-N; phi | m) for 0 <= phi <= pi/2, N >= 0, stable for large N
/// (DLMF 19.7.8 with the partner characteristic -m/N).
pub fn pi_neg(big_n: f64, s: f64, c2: f64, m: f64) -> f64 {
    let d2 = 1.0 - m * s * s;
    if big_n <= m.sqrt() || big_n == 0.0 {
        return pi_sc(-big_n, s, c2, m);
    }
    let np = -m / big_n;
    s * rc(c2 * d2, (1.0 + big_n * s * s) * (1.0 - np * s * s))
        + (-np / 3.0) * s * s * s * rj(c2, d2, 1.0, 1.0 - np * s * s)
}

/// The integral of 1 / (1 + N sn^2) from 0 to any real psi (quasi-periodic
/// continuation of [`pi_neg`] with period 2K).
pub fn pi_neg_continued(big_n: f64, psi: f64, m: f64, k: f64) -> f64 {
    let j = ((psi + k) / (2.0 * k)).floor();
    let pr = psi - 2.0 * j * k;
    let (sn, cn, _) = sn_cn_dn(pr.abs(), m);
    let complete = pi_neg(big_n, 1.0, 0.0, m);
    2.0 * j * complete + pr.signum() * pi_neg(big_n, sn, cn * cn, m)
}

/// Pi(n; phi | m) for |phi| <= pi/2 from s = sin, c = cos >= 0, any n: the
/// principal value past the pole for n > 1 (DLMF 19.7.8, partner m / n).
pub fn pi_any(n: f64, s: f64, c: f64, m: f64) -> f64 {
    if n <= 1.0 {
        return pi_sc(n, s, c * c, m);
    }
    let d2 = 1.0 - m * s * s;
    let n2 = m / n;
    f_sc(s, c * c, m) - pi_sc(n2, s, c * c, m)
        + s * rc(c * c * d2, (1.0 - n * s * s) * (1.0 - n2 * s * s))
}

/// The complete Pi(n | m), principal value for n > 1.
pub fn pi_complete_any(n: f64, m: f64) -> f64 {
    if n <= 1.0 {
        return rf(0.0, 1.0 - m, 1.0) + n / 3.0 * rj(0.0, 1.0 - m, 1.0, 1.0 - n);
    }
    let n2 = m / n;
    k_of(m) - (rf(0.0, 1.0 - m, 1.0) + n2 / 3.0 * rj(0.0, 1.0 - m, 1.0, 1.0 - n2))
}

/// The integral of 1 / (1 - n sn^2) from 0 to xi in [0, 2K] (amplitude in
/// [0, pi]); principal value for n > 1.
pub fn pi_of_xi(n: f64, xi: f64, m: f64, k: f64) -> f64 {
    if xi <= k {
        let (sn, cn, _) = sn_cn_dn(xi, m);
        return pi_any(n, sn, cn.abs(), m);
    }
    let (sn, cn, _) = sn_cn_dn(2.0 * k - xi, m);
    2.0 * pi_complete_any(n, m) - pi_any(n, sn, cn.abs(), m)
}

/// Jacobi's sn, cn, dn of any real u for 0 <= m < 1, by the arithmetic-
/// geometric mean and the descending Landen transformation (Abramowitz &
/// Stegun 16.4).
pub fn sn_cn_dn(u: f64, m: f64) -> (f64, f64, f64) {
    if m.sqrt() <= f64::EPSILON {
        return (u.sin(), u.cos(), 1.0);
    }
    // a_i, c_i of the AGM of 1 and sqrt(1 - m), until c_i / a_i is round-off.
    const MAX: usize = 12;
    let (mut a, mut c) = ([0.0f64; MAX], [0.0f64; MAX]);
    let (mut b, mut i, mut twon) = ((1.0 - m).sqrt(), 0, 1.0);
    a[0] = 1.0;
    c[0] = m.sqrt();
    while (c[i] / a[i]).abs() > f64::EPSILON && i + 1 < MAX {
        let ai = a[i];
        i += 1;
        c[i] = 0.5 * (ai - b);
        a[i] = 0.5 * (ai + b);
        b = (ai * b).sqrt();
        twon *= 2.0;
    }
    let mut phi = twon * a[i] * u;
    while i > 0 {
        phi = 0.5 * ((c[i] * phi.sin() / a[i]).asin() + phi);
        i -= 1;
    }
    let (s, cn) = phi.sin_cos();
    // dn > 0 for m < 1; from sn, not cos(phi_0) / cos(phi_1 - phi_0),
    // which loses its digits where cn passes 0.
    (s, cn, (1.0 - m * s * s).sqrt())
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn sn_cn_dn_satisfy_their_identities_and_the_period() {
        for &m in &[0.0, 0.1, 0.5, 0.9, 0.999] {
            let k = k_of(m);
            for i in -20..20 {
                let u = 0.37 * f64::from(i);
                let (s, c, d) = sn_cn_dn(u, m);
                assert!((s * s + c * c - 1.0).abs() < 1e-14, "m {m} u {u}");
                assert!((d * d + m * s * s - 1.0).abs() < 1e-14, "m {m} u {u}");
                // F(am u) = u on the first quarter period.
                if u >= 0.0 && u <= k {
                    assert!((f_sc(s, c * c, m) - u).abs() < 1e-13, "m {m} u {u}");
                }
                let (s4, c4, _) = sn_cn_dn(u + 4.0 * k, m);
                assert!(
                    (s4 - s).abs() < 1e-11 && (c4 - c).abs() < 1e-11,
                    "m {m} u {u}"
                );
            }
        }
    }
}
