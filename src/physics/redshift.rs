//! Frequency shift of light from a thin Keplerian disk (the conventions of docs/physics.md).

/// Angular velocity of a circular Keplerian orbit at radius `r`: Ω = sqrt(M / r³),
/// with M = rs / 2.
pub fn kepler_omega(r: f64, rs: f64) -> f64 {
    (0.5 * rs / (r * r * r)).sqrt()
}

/// g = ν_obs / ν_emit = sqrt(1 - 1.5 rs / r) / (1 - Ω λ) for an emitter on a
/// circular orbit at `r` and a photon of angular momentum per energy `lambda`
/// about the disk axis (positive when co-rotating), seen from rest at infinity.
pub fn disk_redshift(r: f64, rs: f64, lambda: f64) -> f64 {
    (1.0 - 1.5 * rs / r).sqrt() / (1.0 - kepler_omega(r, rs) * lambda)
}

/// The largest |λ| a photon can have at radius `r` (moving purely
/// tangentially as seen by a static observer): r / sqrt(1 - rs / r).
pub fn max_photon_lambda(r: f64, rs: f64) -> f64 {
    r / (1.0 - rs / r).sqrt()
}
