//! The thin disk's temperature: the Novikov-Thorne profile (Novikov & Thorne
//! 1973; Page & Thorne 1974, Newtonian-limit form),
//! T⁴ ∝ r⁻³ (1 - sqrt(r_in / r)), which peaks at r = (49/36) r_in.

/// Radius of the temperature peak for inner radius `r_in`.
pub fn peak_radius(r_in: f64) -> f64 {
    49.0 / 36.0 * r_in
}

/// Temperature at `r` for a disk with inner radius `r_in` whose hottest ring
/// is at `t_peak` kelvin (0 inside r_in).
pub fn temperature(r: f64, r_in: f64, t_peak: f64) -> f64 {
    let f = |r: f64| (r.powi(-3) * (1.0 - (r_in / r).sqrt())).max(0.0);
    t_peak * (f(r) / f(peak_radius(r_in))).powf(0.25)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn peak_is_at_49_36_r_in_and_equals_t_peak() {
        let r_in = 3.0;
        let tp = temperature(peak_radius(r_in), r_in, 1e4);
        assert!((tp - 1e4).abs() < 1e-6);
        for dr in [-0.2, -0.01, 0.01, 0.2] {
            assert!(temperature(peak_radius(r_in) + dr, r_in, 1e4) < 1e4);
        }
        assert_eq!(temperature(r_in, r_in, 1e4), 0.0);
        // Far out, T ∝ r^(-3/4).
        let ratio = temperature(2e5, r_in, 1e4) / temperature(1e5, r_in, 1e4);
        assert!((ratio - 2f64.powf(-0.75)).abs() < 1e-3);
    }
}
