//! The shadow's outline as a distant observer sees it: the image of the
//! spherical photon orbits (Bardeen 1973). A photon orbit of radius r has
//! constants (lambda, eta) ([`super::critical_lambda_eta`]); seen from
//! inclination theta_o (from the spin axis) far away, it lands at
//! alpha = -lambda / sin theta_o, beta = +-sqrt(Theta), Theta = eta + a^2
//! cos^2 theta_o - lambda^2 cot^2 theta_o, for the orbits with Theta >= 0.
//! At a* = 0 a circle of radius 3 sqrt(3) M. Units M = 1.

use super::{critical_lambda_eta, r_photon_equatorial};

/// Theta of the orbit of radius r seen from theta_o (cos, cot given).
fn theta_of(r: f64, a: f64, cos_o: f64, cot_o: f64) -> f64 {
    let (lambda, eta) = critical_lambda_eta(r, a);
    eta + a * a * cos_o * cos_o - lambda * lambda * cot_o * cot_o
}

/// The point where Theta changes sign between r0 (Theta < 0 or at an end)
/// and r1, by bisection to f64 resolution.
fn edge(mut inside: f64, mut outside: f64, f: &dyn Fn(f64) -> f64) -> f64 {
    for _ in 0..200 {
        let mid = 0.5 * (inside + outside);
        if mid == inside || mid == outside {
            break;
        }
        if f(mid) >= 0.0 {
            inside = mid;
        } else {
            outside = mid;
        }
    }
    inside
}

/// The outline as 2 `n` points (alpha, beta) in M, closed around the
/// shadow (upper half from one end of the visible orbits to the other, then
/// the lower half back), for spin `a` (|a| < 1) seen from `theta_o`
/// radians off the spin axis (kept 1e-6 from the poles, where alpha's
/// lambda / sin theta_o is 0 / 0). Bardeen's signs: the side where the
/// photons turn with the hole (lambda > 0) at alpha < 0.
pub fn outline(a: f64, theta_o: f64, n: usize) -> Vec<(f64, f64)> {
    let n = n.max(4);
    if a.abs() < 1e-9 {
        let r = 27f64.sqrt();
        return (0..2 * n)
            .map(|i| {
                let t = std::f64::consts::PI * i as f64 / n as f64;
                (r * t.cos(), r * t.sin())
            })
            .collect();
    }
    let th = theta_o.clamp(1e-6, std::f64::consts::PI - 1e-6);
    let (sin_o, cos_o) = th.sin_cos();
    let cot_o = cos_o / sin_o;
    let f = |r: f64| theta_of(r, a, cos_o, cot_o);
    // The photon orbits lie between the equatorial ones; Theta >= 0 on
    // one interval of them (the visible ones), which holds the orbit of
    // lambda = 0 (there Theta = eta + a^2 cos^2 theta_o > 0, from every
    // inclination): found by bisection on lambda (monotonic in r there),
    // then both ends of the interval bisected from it.
    let (lo, hi) = {
        let (p, q) = (
            r_photon_equatorial(a.abs(), true),
            r_photon_equatorial(a.abs(), false),
        );
        (p.min(q), p.max(q))
    };
    let lambda_at = |r: f64| critical_lambda_eta(r, a).0;
    let sign_lo = lambda_at(lo).signum();
    let inside = edge(lo, hi, &|r| lambda_at(r) * sign_lo);
    let start = edge(inside, lo, &f);
    let end = edge(inside, hi, &f);
    let point = |k: usize| {
        // Cosine spacing: dense at the ends, where beta turns fastest.
        let s = 0.5 * (1.0 - (std::f64::consts::PI * k as f64 / (n - 1) as f64).cos());
        let r = start + (end - start) * s;
        let (lambda, _) = critical_lambda_eta(r, a);
        (-lambda / sin_o, f(r).max(0.0).sqrt())
    };
    let upper: Vec<(f64, f64)> = (0..n).map(point).collect();
    let lower = upper.iter().rev().map(|&(x, y)| (x, -y));
    upper.iter().copied().chain(lower).collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_non_rotating_shadow_is_a_circle_of_radius_sqrt_27() {
        for (x, y) in outline(0.0, 1.0, 64) {
            assert!((x.hypot(y) - 27f64.sqrt()).abs() < 1e-12);
        }
    }

    /// Edge-on, the outline's ends on the equator are the equatorial
    /// photon orbits' critical rays, whose lambda has a closed form of its
    /// own (-a + 6 cos(acos(-+a) / 3), spacetime::radii::critical_lambda).
    #[test]
    fn edge_on_the_outline_spans_the_equatorial_critical_rays() {
        for a in [0.3, 0.7, 0.99] {
            let pts = outline(a, std::f64::consts::FRAC_PI_2, 400);
            let left = pts.iter().map(|p| p.0).fold(f64::INFINITY, f64::min);
            let right = pts.iter().map(|p| p.0).fold(f64::NEG_INFINITY, f64::max);
            let pro = -a + 6.0 * ((-a).acos() / 3.0).cos();
            let retro = -a - 6.0 * (a.acos() / 3.0).cos();
            assert!((left + pro).abs() < 1e-6, "a {a}: {left} vs {}", -pro);
            assert!((right + retro).abs() < 1e-6, "a {a}: {right} vs {}", -retro);
        }
    }

    /// Pole-on, the shadow is a circle again (axisymmetric view), of radius
    /// sqrt(eta + a^2) of the orbit with lambda = 0.
    #[test]
    fn pole_on_the_outline_is_a_circle() {
        let a = 0.9;
        let pts = outline(a, 0.0, 200);
        let r0: Vec<f64> = pts.iter().map(|p| p.0.hypot(p.1)).collect();
        let (min, max) = r0.iter().fold((f64::INFINITY, 0.0f64), |(lo, hi), &r| {
            (lo.min(r), hi.max(r))
        });
        assert!(max - min < 1e-3 * max, "{min} {max}");
        assert!(max > 4.0 && max < 27f64.sqrt(), "{max}");
    }
}
