//! The f64 reference against closed forms computed here, independently:
//! the exact deflection integral (our own quadrature), the weak-field series,
//! the critical impact parameter, the capture angle of a pinhole camera, and
//! the limits of the disk redshift.

use blackhole::physics::geodesic::{Hole, Outcome, TraceOptions, photon_lambda, trace};
use blackhole::physics::redshift::{disk_redshift, max_photon_lambda};
use glam::DVec3;

const RS: f64 = 1.0;

fn b_crit() -> f64 {
    1.5 * 3f64.sqrt() * RS
}

fn hole() -> [Hole; 1] {
    [Hole {
        position: DVec3::ZERO,
        rs: RS,
    }]
}

/// Adaptive Simpson on [a, b] to absolute tolerance `eps`.
fn simpson(f: &dyn Fn(f64) -> f64, a: f64, b: f64, eps: f64) -> f64 {
    #[allow(clippy::too_many_arguments)]
    fn rec(
        f: &dyn Fn(f64) -> f64,
        a: f64,
        b: f64,
        fa: f64,
        fm: f64,
        fb: f64,
        whole: f64,
        eps: f64,
        depth: u32,
    ) -> f64 {
        let m = 0.5 * (a + b);
        let (lm, rm) = (0.5 * (a + m), 0.5 * (m + b));
        let (flm, frm) = (f(lm), f(rm));
        let left = (m - a) / 6.0 * (fa + 4.0 * flm + fm);
        let right = (b - m) / 6.0 * (fm + 4.0 * frm + fb);
        let delta = left + right - whole;
        if depth == 0 || delta.abs() <= 15.0 * eps {
            return left + right + delta / 15.0;
        }
        rec(f, a, m, fa, flm, fm, left, 0.5 * eps, depth - 1)
            + rec(f, m, b, fm, frm, fb, right, 0.5 * eps, depth - 1)
    }
    let (fa, fb, fm) = (f(a), f(b), f(0.5 * (a + b)));
    let whole = (b - a) / 6.0 * (fa + 4.0 * fm + fb);
    rec(f, a, b, fa, fm, fb, whole, eps, 50)
}

/// Exact deflection: alpha(b) = 2 ∫_{r0}^∞ dr / (r² sqrt(1/b² - (1 - rs/r)/r²)) - π.
/// With u = 1/r and u = u0 (1 - t²), the integrand becomes the smooth
/// 2 sqrt(u0) / sqrt(G(u)), G(u) = (u + u0) - rs (u² + u u0 + u0²).
fn exact_deflection(b: f64) -> f64 {
    // Closest approach: largest root of r³ - b² r + b² rs = 0.
    let r0 = 2.0 * b / 3f64.sqrt() * ((-(1.5 * 3f64.sqrt()) * RS / b).acos() / 3.0).cos();
    assert!(
        (b - r0 / (1.0 - RS / r0).sqrt()).abs() < 1e-9 * b,
        "closest approach"
    );
    let u0 = 1.0 / r0;
    let f = |t: f64| {
        let u = u0 * (1.0 - t * t);
        let g = (u + u0) - RS * (u * u + u * u0 + u0 * u0);
        2.0 * u0.sqrt() / g.sqrt()
    };
    2.0 * simpson(&f, 0.0, 1.0, 1e-15) - std::f64::consts::PI
}

/// Deflection by the f64 tracer: a ray from far away with impact parameter b.
fn traced_deflection(b: f64) -> f64 {
    let d = 1e8;
    let v0 = DVec3::X;
    let r = trace(
        &hole(),
        None,
        DVec3::new(-d, b, 0.0),
        v0,
        &TraceOptions::default(),
    );
    match r.outcome {
        Outcome::Escaped { direction } => v0.cross(direction).length().atan2(v0.dot(direction)),
        other => panic!("b = {b}: {other:?}"),
    }
}

#[test]
fn deflection_matches_the_exact_integral_to_1e8_relative() {
    let mut worst: f64 = 0.0;
    for b in [
        2.7, 2.8, 3.0, 3.5, 4.0, 5.0, 7.0, 10.0, 15.0, 20.0, 35.0, 50.0, 75.0, 100.0,
    ] {
        let exact = exact_deflection(b);
        let traced = traced_deflection(b);
        let rel = ((traced - exact) / exact).abs();
        worst = worst.max(rel);
        assert!(
            rel <= 1e-8,
            "b = {b}: traced {traced:.15} exact {exact:.15} rel {rel:.2e}"
        );
    }
    println!("deflection: worst relative error {worst:.2e} for b in [2.7, 100]");
}

#[test]
fn quadrature_itself_matches_the_weak_field_series() {
    // Guards the test's own quadrature: at large b it must approach the series.
    for b in [1e3, 1e4] {
        let x = RS / b;
        let series = 2.0 * x + 15.0 * std::f64::consts::PI / 16.0 * x * x;
        assert!(
            (exact_deflection(b) - series).abs() < 20.0 * x * x * x,
            "b = {b}"
        );
    }
}

#[test]
fn weak_field_deflection_follows_the_series() {
    for b in [200.0, 1e3, 1e4] {
        let x = RS / b;
        let series = 2.0 * x + 15.0 * std::f64::consts::PI / 16.0 * x * x;
        let traced = traced_deflection(b);
        // The next term of the series is O((rs/b)³).
        assert!(
            (traced - series).abs() < 20.0 * x * x * x,
            "b = {b}: {traced} vs {series}"
        );
        // And the second-order term is really there: the first-order result is off by it.
        assert!((traced - 2.0 * x).abs() > 0.5 * 15.0 * std::f64::consts::PI / 16.0 * x * x);
    }
}

#[test]
fn critical_impact_parameter_separates_capture_from_escape() {
    let bc = b_crit();
    for eps in [1e-3, 1e-5, 1e-7] {
        let inside = trace(
            &hole(),
            None,
            DVec3::new(-1e4, bc * (1.0 - eps), 0.0),
            DVec3::X,
            &TraceOptions::default(),
        );
        assert!(
            matches!(inside.outcome, Outcome::Captured { .. }),
            "b_c(1-{eps}): {:?}",
            inside.outcome
        );
        let outside = trace(
            &hole(),
            None,
            DVec3::new(-1e4, bc * (1.0 + eps), 0.0),
            DVec3::X,
            &TraceOptions::default(),
        );
        assert!(
            matches!(outside.outcome, Outcome::Escaped { .. }),
            "b_c(1+{eps}): {:?}",
            outside.outcome
        );
    }
}

#[test]
fn pinhole_capture_angle_matches_the_closed_form() {
    let bc = b_crit();
    for d in [10.0, 15.0, 30.0] {
        let expected = (bc / (d * d + RS * bc * bc / d).sqrt()).asin();
        let captured = |psi: f64| {
            let dir = DVec3::new(psi.cos(), psi.sin(), 0.0);
            let r = trace(
                &hole(),
                None,
                DVec3::new(-d, 0.0, 0.0),
                dir,
                &TraceOptions::default(),
            );
            matches!(r.outcome, Outcome::Captured { .. })
        };
        let (mut lo, mut hi) = (0.0f64, 1.2f64);
        assert!(captured(lo) && !captured(hi));
        while hi - lo > 1e-10 {
            let mid = 0.5 * (lo + hi);
            if captured(mid) { lo = mid } else { hi = mid }
        }
        let psi = 0.5 * (lo + hi);
        println!("D = {d}: capture half-angle {psi:.10} rad, closed form {expected:.10}");
        assert!(
            (psi - expected).abs() < 1e-6,
            "D = {d}: {psi} vs {expected}"
        );
    }
}

#[test]
fn redshift_spans_sqrt2_over_3_to_sqrt2_at_3_rs() {
    let r = 3.0 * RS;
    let lmax = max_photon_lambda(r, RS);
    let lo = disk_redshift(r, RS, -lmax);
    let hi = disk_redshift(r, RS, lmax);
    assert!((lo - 2f64.sqrt() / 3.0).abs() < 1e-12, "{lo}");
    assert!((hi - 2f64.sqrt()).abs() < 1e-12, "{hi}");
    // Monotonic in between, and the transverse photon sees sqrt(1 - 1.5 rs / r).
    let mut last = 0.0;
    for i in 0..=100 {
        let g = disk_redshift(r, RS, lmax * (2.0 * f64::from(i) / 100.0 - 1.0));
        assert!(g > last);
        last = g;
    }
    assert!((disk_redshift(r, RS, 0.0) - 0.5f64.sqrt()).abs() < 1e-12);
}

#[test]
fn tangential_photon_at_the_disk_has_the_largest_angular_momentum() {
    // A backwards ray at (3, 0, 0) moving along -z: the photon moves along +z,
    // which for a disk turning counter-clockwise seen from +y is... x̂ × ẑ = -ŷ:
    // counter-rotating, so λ = -λmax.
    let hole = hole()[0];
    let r = 3.0;
    let l = photon_lambda(
        &hole,
        DVec3::Y,
        DVec3::new(r, 0.0, 0.0),
        DVec3::new(0.0, 0.0, -1.0),
    );
    assert!((l + max_photon_lambda(r, RS)).abs() < 1e-12, "{l}");
    // The speed normalisation does not matter.
    let l2 = photon_lambda(
        &hole,
        DVec3::Y,
        DVec3::new(r, 0.0, 0.0),
        DVec3::new(0.0, 0.0, -7.0),
    );
    assert!((l - l2).abs() < 1e-12);
}
