//! A hole's characteristic radii and its thin disk's Page-Thorne constants,
//! for any spin a* (0 included): the one place they are computed, from the
//! closed forms of [`crate::physics::kerr`] (Bardeen, Press & Teukolsky
//! 1972; Page & Thorne 1974). Radii in units of the hole's rs (= 2M);
//! everything else of the crate asks here or through
//! [`super::Spacetime`].

use crate::physics::kerr;
pub use crate::physics::kerr::PageThorne;

/// The outer horizon r+ of a hole of size `rs` spinning at `spin`: rs at
/// spin 0, rs / 2 at |a*| = 1.
pub fn horizon(rs: f64, spin: f64) -> f64 {
    0.5 * rs * kerr::frame::r_horizon(spin)
}

/// The inner horizon r- (0 at spin 0).
pub fn inner_horizon(rs: f64, spin: f64) -> f64 {
    0.5 * rs * kerr::r_inner_horizon(spin)
}

/// The circular photon orbit in the equatorial plane turning with the hole
/// (`prograde`) or against it: 1.5 rs for both at spin 0.
pub fn photon_orbit(rs: f64, spin: f64, prograde: bool) -> f64 {
    0.5 * rs * kerr::r_photon_equatorial(spin.abs(), prograde)
}

/// The innermost stable circular orbit of a disk turning the way the scene's
/// disk does: prograde for spin > 0, retrograde for spin < 0 (3 rs at spin
/// 0, rs / 2 and 4.5 rs at |a*| = 1).
pub fn isco(rs: f64, spin: f64) -> f64 {
    0.5 * rs * kerr::r_isco(spin)
}

/// The shadow's outline of a hole spinning at `spin` seen from far away at
/// `inclination_deg` from its spin axis: 2 `n` points (alpha, beta) on the
/// sky in units of rs (impact parameters; an angle times the distance),
/// closed around the shadow, alpha across the projected spin axis
/// (Bardeen's sign: the side where light turns with the hole at alpha <
/// 0), beta along it. A circle of radius 3 sqrt(3) / 2 rs at spin 0.
pub fn shadow_outline(spin: f64, inclination_deg: f64, n: usize) -> Vec<(f64, f64)> {
    kerr::shadow::outline(spin, inclination_deg.to_radians(), n)
        .into_iter()
        .map(|(x, y)| (0.5 * x, 0.5 * y))
        .collect()
}

/// The equatorial photon constant lambda (in M) of the critical ray that
/// winds onto the photon orbit on the `prograde` side, signed as the spin:
/// -a + 6 cos(acos(-a) / 3) prograde, -a - 6 cos(acos(a) / 3) retrograde
/// (a = |a*|), which tends to +-3 sqrt(3) as the spin vanishes (the
/// spherical orbits' lambda(r) = -(r^3 - 3r^2 + a^2 r + a^2) / (a (r - 1))
/// is 0 / 0 there: at a* = 1e-16 it gave no paths at all).
pub fn critical_lambda(spin: f64, prograde: bool) -> f64 {
    let a = spin.abs();
    let lambda = if prograde {
        -a + 6.0 * ((-a).acos() / 3.0).cos()
    } else {
        -a - 6.0 * (a.acos() / 3.0).cos()
    };
    lambda * if spin < 0.0 { -1.0 } else { 1.0 }
}

/// The Page-Thorne flux's constants for the shader (x = sqrt(r / M)): the
/// ISCO's x0, the three roots of x^3 - 3x + 2a* and their log terms'
/// coefficients.
pub fn page_thorne(spin: f64) -> PageThorne {
    PageThorne::new(spin)
}

/// The Page-Thorne flux's shape f(r) (r in M; zero at and inside the ISCO).
pub fn page_thorne_flux(r: f64, spin: f64) -> f64 {
    if r <= kerr::r_isco(spin) {
        0.0
    } else {
        kerr::page_thorne_f(r, spin)
    }
}

/// The largest value of f(r) / r, the shader's normaliser of T^4 (r in M).
pub fn page_thorne_peak(spin: f64) -> f64 {
    kerr::page_thorne_peak(spin).1
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The textbook values: Schwarzschild's horizon, photon sphere and ISCO
    /// at spin 0; an extreme hole's prograde ISCO and photon orbit at M.
    #[test]
    fn the_radii_take_their_closed_form_limits() {
        assert_eq!(horizon(1.0, 0.0), 1.0);
        assert_eq!(inner_horizon(1.0, 0.0), 0.0);
        assert_eq!(isco(1.0, 0.0), 3.0);
        assert!((photon_orbit(1.0, 0.0, true) - 1.5).abs() < 1e-15);
        assert!((photon_orbit(1.0, 0.0, false) - 1.5).abs() < 1e-15);
        assert!((isco(2.0, 1.0) - 1.0).abs() < 1e-6);
        assert!((isco(2.0, -1.0) - 9.0).abs() < 1e-9);
        assert!((photon_orbit(2.0, 1.0, true) - 1.0).abs() < 1e-6);
        assert!((photon_orbit(2.0, 1.0, false) - 4.0).abs() < 1e-9);
        let a: f64 = 0.6;
        assert!((horizon(2.0, a) + inner_horizon(2.0, a) - 2.0).abs() < 1e-15);
        assert!((horizon(2.0, a) * inner_horizon(2.0, a) - a * a).abs() < 1e-15);
    }
}
