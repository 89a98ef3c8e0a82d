//! The rain observer of a non-rotating hole (falling radially from rest at
//! infinity), valid outside the horizon, on it and inside it: the f64
//! reference the camera that falls through the horizon stands on (Step 13).
//!
//! Painlevé-Gullstrand coordinates make this simple: with `v = sqrt(rs / r)`
//! (c = 1), `ds^2 = -dt^2 + (dr + v dt)^2 + r^2 dOmega^2`. Every slice of
//! constant t is flat space, the rain observer's four-velocity is
//! `u = d_t - v d_r`, and its orthonormal spatial frame is `e_r = d_r`,
//! `e_theta = d_theta / r`, `e_phi = d_phi / (r sin theta)` at every r > 0,
//! nothing singular at r = rs. A pixel's unit direction `d` in that frame
//! (the backward ray goes along `d`) is the photon `k = omega (u - d)` that
//! arrives; its conserved energy and angular momentum per unit omega are
//!
//! ```text
//! E / omega = -k . d_t / omega = 1 + v d_r      (d_r = d . r_hat, outward)
//! L / omega = r |d_t|                           (d_t: d's part across r_hat)
//! b = L / E = r |d_t| / (1 + v d_r)
//! ```
//!
//! Outside, this is the static frame's Synge formula after aberration by the
//! inward speed v; at r = rs, a pixel at angle alpha from straight down has
//! `b = rs cot(alpha / 2)`; inside, `E <= 0` for pixels looking down within
//! `cos alpha >= 1 / v`: light that cannot have come from our universe.
//! The spatial shape of each path is still Binet's `u(phi)` (u = rs / r),
//! which the closed form ([`crate::physics::closed_form`]) follows through
//! u = 1 without change.

/// The rain observer's inward speed relative to the static frame, `sqrt(rs /
/// r)` (c = 1): 1 at the horizon, above 1 inside (where no static frame
/// exists; the PG coordinates' "river" speed).
pub fn fall_speed(r: f64, rs: f64) -> f64 {
    (rs / r).sqrt()
}

/// The photon a rain observer at radius `r` sees along a pixel direction
/// whose outward radial part is `d_r` and whose part across the radius has
/// length `d_t` (d_r^2 + d_t^2 = 1): its energy at infinity and its
/// angular momentum, both per unit of the frequency the observer measures.
/// `E <= 0` (possible inside the horizon only) is light from the other
/// universe of an eternal hole.
pub fn photon_constants(r: f64, rs: f64, d_r: f64, d_t: f64) -> (f64, f64) {
    (1.0 + fall_speed(r, rs) * d_r, r * d_t.abs())
}

/// The impact parameter `b = L / E` of that photon (infinite where E = 0).
pub fn impact_parameter(r: f64, rs: f64, d_r: f64, d_t: f64) -> f64 {
    let (e, l) = photon_constants(r, rs, d_r, d_t);
    l / e
}

/// The rain observer's proper time from radius `r0` to `r1 < r0`:
/// `dr / dtau = -sqrt(rs / r)`, so `tau = (2/3) (r0^(3/2) - r1^(3/2)) /
/// sqrt(rs)`; from the horizon to r = 0, `(2/3) rs` (c = 1).
pub fn proper_time(r0: f64, r1: f64, rs: f64) -> f64 {
    2.0 / 3.0 * (r0.powf(1.5) - r1.powf(1.5)) / rs.sqrt()
}

#[cfg(test)]
mod tests {
    use super::*;

    const RS: f64 = 1.0;

    /// The critical impact parameter, (3 sqrt 3 / 2) rs.
    fn b_c() -> f64 {
        1.5 * 3f64.sqrt() * RS
    }

    /// A pixel at angle `alpha` from straight down (the inward radial).
    fn down(alpha: f64) -> (f64, f64) {
        (-alpha.cos(), alpha.sin())
    }

    /// At the crossing, b = rs cot(alpha / 2): the shadow (b < b_c, the
    /// backward ray falls back in) is centred straight down with an angular
    /// radius of 2 atan(rs / b_c) = 42.10 degrees.
    #[test]
    fn at_the_horizon_the_shadow_is_42_10_degrees_around_straight_down() {
        for k in 1..180 {
            let alpha = f64::from(k).to_radians();
            let (d_r, d_t) = down(alpha);
            let b = impact_parameter(RS, RS, d_r, d_t);
            let cot = 1.0 / (0.5 * alpha).tan();
            assert!((b - RS * cot).abs() < 1e-12 * (1.0 + b), "alpha {k}: {b}");
        }
        let edge = 2.0 * (RS / b_c()).atan();
        assert!(
            (edge.to_degrees() - 42.10).abs() < 0.005,
            "{}",
            edge.to_degrees()
        );
        let (d_r, d_t) = down(edge);
        assert!((impact_parameter(RS, RS, d_r, d_t) - b_c()).abs() < 1e-12);
    }

    /// Starlight from straight overhead (the backward ray straight up, so
    /// d_r = 1) reaches a rain observer at the horizon at half its frequency
    /// at infinity (E = omega (1 + v) = 2 omega), and anywhere at the
    /// fraction 1 / (1 + sqrt(rs / r)) of it: redshifted above the camera.
    #[test]
    fn starlight_from_overhead_arrives_at_half_its_frequency_at_the_horizon() {
        let (e, l) = photon_constants(RS, RS, 1.0, 0.0);
        assert!((1.0 / e - 0.5).abs() < 1e-15 && l == 0.0);
        for r in [0.05, 0.5, 2.0, 10.0] {
            let (e, _) = photon_constants(r, RS, 1.0, 0.0);
            assert!((1.0 / e - 1.0 / (1.0 + (RS / r).sqrt())).abs() < 1e-15);
        }
        // Straight down from outside: blueshifted, 1 / (1 - v).
        let (e, _) = photon_constants(4.0, RS, -1.0, 0.0);
        assert!((1.0 / e - 2.0).abs() < 1e-15);
    }

    #[test]
    fn the_fall_from_the_horizon_to_the_centre_takes_two_thirds_of_rs() {
        assert!((proper_time(RS, 0.0, RS) - 2.0 / 3.0 * RS).abs() < 1e-15);
        // The same by a midpoint sum of dtau = dr / sqrt(rs / r).
        let n = 200_000;
        let sum: f64 = (0..n)
            .map(|i| {
                let r = (f64::from(i) + 0.5) / f64::from(n) * RS;
                (RS / f64::from(n)) / fall_speed(r, RS)
            })
            .sum();
        assert!((sum - 2.0 / 3.0).abs() < 1e-9, "{sum}");
    }

    /// Outside, the rain frame is the static frame after aberration by the
    /// inward speed v: its b equals Synge's r sin(psi) / sqrt(1 - rs / r) at
    /// the static frame's angle psi of the same photon.
    #[test]
    fn outside_it_is_the_static_frame_aberrated_by_the_fall() {
        let r = 3.7;
        let v = fall_speed(r, RS);
        let gamma = 1.0 / (1.0 - v * v).sqrt();
        for k in 0..=36 {
            let alpha = f64::from(k) * 5f64.to_radians();
            let (d_r, d_t) = down(alpha);
            // The photon travels along -d in the rain frame; the static
            // frame moves outward at v relative to it.
            let (n_r, n_t) = (-d_r, -d_t);
            let n_r_static = (n_r - v) / (1.0 - v * n_r);
            let n_t_static = n_t / (gamma * (1.0 - v * n_r));
            let sin_psi = n_t_static.abs() / n_r_static.hypot(n_t_static);
            let synge = r * sin_psi / (1.0 - RS / r).sqrt();
            let b = impact_parameter(r, RS, d_r, d_t);
            assert!(
                (b - synge).abs() < 1e-12 * (1.0 + b),
                "alpha {}: {b} {synge}",
                5 * k
            );
        }
    }

    /// Inside, a photon looking down within cos(alpha) > 1 / v has E < 0:
    /// it cannot have come from our universe. Just inside the horizon only
    /// straight down; at 0.25 rs a cone of 60 degrees.
    #[test]
    fn inside_the_horizon_light_from_below_can_be_from_the_other_universe() {
        let r = 0.25 * RS;
        let v = fall_speed(r, RS);
        let cone = (1.0 / v).acos();
        assert!((cone.to_degrees() - 60.0).abs() < 1e-9);
        for (alpha, sign) in [(cone - 1e-6, -1.0), (cone + 1e-6, 1.0)] {
            let (d_r, d_t) = down(alpha);
            let (e, _) = photon_constants(r, RS, d_r, d_t);
            assert_eq!(e.signum(), sign, "alpha {}", alpha.to_degrees());
        }
        let (e, _) = photon_constants(RS * (1.0 - 1e-9), RS, -1.0, 0.0);
        assert!(e < 0.0 && e > -1e-9);
    }
}
