//! The spinning hole's light paths in closed form, in f64: the reference
//! that the GPU's f32 twin is tested against. A pixel direction in the
//! ZAMO's frame gives the photon's constants (lambda, eta) and the signs of
//! its backward motion (frame.rs); the roots of the radial quartic pick one
//! of Gralla & Lupsasca's four cases and give r(tau) in Mino time
//! (radial.rs); theta(tau) crosses the equator at an arithmetic progression
//! of Mino times (angular.rs), so the disk's crossings need no stepping;
//! the azimuth and the escape direction come from Carlson's integrals
//! (elliptic.rs). `mino.rs` integrates the same ray step by step, for the
//! tests only.
//!
//! Conventions: lengths in r_s = 2M = 1 at the boundary, M = 1 inside; the
//! hole's frame has x = e1 (disk azimuth 0), y = the spin axis = the disk's
//! normal, z = e1 x n; spin a* signed (a* > 0 turns with the disk); Boyer-
//! Lindquist x = rho sin(th) cos(ph), y = r cos(th), z = -rho sin(th)
//! sin(ph). A disk hit's azimuth is atan2(z, x) of the hit point, which is
//! -phi_BL.

pub mod angular;
pub mod elliptic;
pub mod frame;
pub mod interior;
pub mod mino;
pub mod path;
pub mod polarized;
pub mod radial;
pub mod schild;
pub mod shadow;
pub mod transport;

use std::f64::consts::PI;

use glam::DVec3;

pub use frame::{
    Constants, FALLING_FRAME_BAND, KerrObserver, LocalFrame, PlacementError, boyer_lindquist_r,
    falling_floor, in_falling_band, observer_velocity, r_horizon, r_inner_horizon, to_zamo_frame,
};
use radial::Radial;

/// Where a backward ray ends.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum KerrOutcome {
    /// In the horizon (or a photon with E <= 0 inside the ergoregion).
    Captured,
    /// The first crossing of the thin disk's annulus: BL radius (r_s),
    /// azimuth atan2(z, x) of the hit point, the redshift g the camera's
    /// observer measures, and how many equatorial crossings outside the
    /// annulus came before.
    Disk {
        r: f64,
        phi: f64,
        g: f64,
        crossings_before: u32,
    },
    /// To infinity, leaving along this world direction (hole frame).
    Escaped(DVec3),
}

/// One traced ray: its outcome, GL's radial case (0 for E <= 0) and its
/// constants (M = 1).
#[derive(Clone, Copy, Debug)]
pub struct KerrRay {
    pub outcome: KerrOutcome,
    pub case: u8,
    pub lambda: f64,
    pub eta: f64,
}

/// The thin disk in the equatorial plane, radii in r_s.
#[derive(Clone, Copy, Debug)]
pub struct KerrDisk {
    pub inner: f64,
    pub outer: f64,
}

/// Equatorial crossings examined before a ray counts as escaped or captured.
pub const MAX_CROSSINGS: u32 = 8;

/// Traces the backward ray from a ZAMO camera at `position` (r_s, hole
/// frame) along the unit direction `d` (the ZAMO's frame, world axes through
/// the flat triad), spin `spin`.
pub fn trace_zamo(position: DVec3, d: DVec3, spin: f64, disk: Option<KerrDisk>) -> KerrRay {
    let a = spin;
    let cc = Constants::of(2.0 * position, d, a);
    if cc.energy == 0.0 {
        // lambda and eta unbounded: the edge between the signs (a null set).
        return KerrRay {
            outcome: KerrOutcome::Captured,
            case: 0,
            lambda: f64::NAN,
            eta: f64::NAN,
        };
    }
    let (lambda, eta, f) = (cc.lambda, cc.eta, cc.frame);
    // A photon with E < 0 (inside the ergoregion) runs the same r and theta
    // motion in Mino time per unit |E|, but its azimuth turns the other way
    // along the backward ray: phi = phi_o + I_phi + lambda G_phi. It cannot
    // have come from infinity.
    let turn = cc.energy.signum();
    let rad = Radial::new(a, lambda, eta, f.r, cc.s_r);
    let ray = |outcome| KerrRay {
        outcome,
        case: rad.case,
        lambda,
        eta,
    };
    let ordinary = (eta > 0.0).then(|| {
        angular::Ordinary::new(a, lambda, eta, f.cos_theta, cc.theta_potential, cc.s_theta)
    });
    if let Some((n, tc, rc)) = ordinary
        .as_ref()
        .and_then(|ang| first_disk_crossing(&rad, ang, disk))
    {
        let ang = ordinary
            .as_ref()
            .expect("crossings need the ordinary motion");
        let phi_bl = f.phi - turn * (rad.i_phi(tc) + ang.lambda_g_phi(lambda, tc));
        return ray(KerrOutcome::Disk {
            r: rc / 2.0,
            phi: (-phi_bl.sin()).atan2(phi_bl.cos()),
            g: disk_g(rc, a, lambda, f.alpha, f.omega),
            crossings_before: n,
        });
    }
    if rad.captured || turn < 0.0 {
        return ray(KerrOutcome::Captured);
    }
    let t = rad.tau_end;
    let i_phi = if rad.case == 4 {
        radial::outward_u_quadrature(a, lambda, eta, f.r).1
    } else {
        rad.i_phi(t)
    };
    let (cos_th, phi) = if let Some(ang) = ordinary {
        (
            ang.cos_theta_at(t),
            f.phi - i_phi - ang.lambda_g_phi(lambda, t),
        )
    } else if eta < 0.0 {
        let v = angular::Vortical::new(a, lambda, eta, f.cos_theta, cc.s_theta);
        (v.cos_theta_at(t), f.phi - i_phi - v.lambda_g_phi(lambda, t))
    } else if f.cos_theta == 0.0 {
        // eta = 0 in the equatorial plane: an equatorial ray.
        (0.0, f.phi - i_phi - lambda * t)
    } else {
        (f64::NAN, f64::NAN)
    };
    let sin_th = (1.0 - cos_th * cos_th).max(0.0).sqrt();
    ray(KerrOutcome::Escaped(DVec3::new(
        sin_th * phi.cos(),
        cos_th,
        -sin_th * phi.sin(),
    )))
}

/// The first equatorial crossing of the backward ray inside the thin disk's
/// annulus, before the path ends: which crossing (n), its Mino time and its
/// Boyer-Lindquist radius (M).
pub fn first_disk_crossing(
    rad: &Radial,
    ang: &angular::Ordinary,
    disk: Option<KerrDisk>,
) -> Option<(u32, f64, f64)> {
    let disk = disk?;
    let (r_in, r_out) = (2.0 * disk.inner, 2.0 * disk.outer);
    for n in 0..MAX_CROSSINGS {
        let tc = ang.crossing_tau(n);
        if tc >= rad.tau_end {
            break;
        }
        let rc = rad.r_at(tc);
        if rc > 2e4 {
            break;
        }
        if (r_in..=r_out).contains(&rc) {
            return Some((n, tc, rc));
        }
    }
    None
}

/// Checks that two outcomes agree to 1e-6 (the sky's direction; a disk's
/// radius, azimuth and g) and says which they are: 0 escaped, 1 disk, 2
/// captured (tests of the references against each other).
#[cfg(test)]
pub(crate) fn same_outcome(a: KerrOutcome, b: KerrOutcome, what: &str) -> usize {
    match (a, b) {
        (KerrOutcome::Escaped(x), KerrOutcome::Escaped(y)) => {
            assert!((x - y).length() < 1e-6, "{what}: {x} vs {y}");
            0
        }
        (
            KerrOutcome::Disk { r, phi, g, .. },
            KerrOutcome::Disk {
                r: r2,
                phi: p2,
                g: g2,
                ..
            },
        ) => {
            let err = (r - r2).abs().max((phi - p2).abs()).max((g - g2).abs());
            assert!(err < 1e-6, "{what}: {r} {phi} {g} vs {r2} {p2} {g2}");
            1
        }
        (KerrOutcome::Captured, KerrOutcome::Captured) => 2,
        (x, y) => panic!("{what}: {x:?} vs {y:?}"),
    }
}

/// The redshift g of light from the prograde Keplerian emitter at BL radius
/// `r` (equatorial, M units), seen by the ZAMO whose lapse and frame-drag
/// are `alpha`, `omega`: ((1 - omega lambda) / alpha) / (u^t (1 - Omega lambda)).
pub fn disk_g(r: f64, a: f64, lambda: f64, alpha: f64, omega: f64) -> f64 {
    let om = 1.0 / (r.powf(1.5) + a);
    let gtt = -(1.0 - 2.0 / r);
    let gtp = -2.0 * a / r;
    let gpp = ((r * r + a * a).powi(2) - a * a * (r * r - 2.0 * r + a * a)) / (r * r);
    let ut = 1.0 / (-(gtt + 2.0 * gtp * om + gpp * om * om)).sqrt();
    ((1.0 - omega * lambda) / alpha) / (ut * (1.0 - om * lambda))
}

/// The same redshift from the photon's energy and angular momentum (per
/// unit of the frequency the camera sees), any sign: 1 / (u^t (E - Omega
/// L)) for the prograde Keplerian emitter at r (M = 1).
pub fn disk_g_of_constants(r: f64, a: f64, energy: f64, l: f64) -> f64 {
    let om = 1.0 / (r.powf(1.5) + a);
    let gtt = -(1.0 - 2.0 / r);
    let gtp = -2.0 * a / r;
    let gpp = ((r * r + a * a).powi(2) - a * a * (r * r - 2.0 * r + a * a)) / (r * r);
    let ut = 1.0 / (-(gtt + 2.0 * gtp * om + gpp * om * om)).sqrt();
    1.0 / (ut * (energy - om * l))
}

/// Traces the pixel direction `d` (unit, the observer's frame, hole-frame
/// axes) of a camera of `observer` at `position` (r_s): aberrated into the
/// ZAMO's frame, and a disk's g multiplied by the observer's Doppler factor.
/// A falling camera between the horizons has no ZAMO there: refused here as
/// InsideHorizon (its paths: [`interior::trace_falling_inside`]).
pub fn trace(
    position: DVec3,
    d: DVec3,
    spin: f64,
    observer: KerrObserver,
    disk: Option<KerrDisk>,
) -> Result<KerrRay, PlacementError> {
    let beta = observer_velocity(observer, 2.0 * position, spin)?;
    if LocalFrame::at(2.0 * position, spin).r <= r_horizon(spin) {
        // A falling camera between the horizons: interior::trace_falling_inside.
        return Err(PlacementError::InsideHorizon(
            LocalFrame::at(2.0 * position, spin).r,
        ));
    }
    let (dz, doppler) = to_zamo_frame(d, beta);
    let mut ray = trace_zamo(position, dz, spin, disk);
    if let KerrOutcome::Disk { g, .. } = &mut ray.outcome {
        *g *= doppler;
    }
    Ok(ray)
}

/// The ISCO (M = 1; Bardeen, Press & Teukolsky 1972): prograde for
/// a* >= 0, retrograde for a* < 0 (the disk always turns toward +phi).
pub fn r_isco(spin: f64) -> f64 {
    let b = spin.abs();
    let z1 = 1.0 + (1.0 - b * b).cbrt() * ((1.0 + b).cbrt() + (1.0 - b).cbrt());
    let z2 = (3.0 * b * b + z1 * z1).sqrt();
    3.0 + z2 - 1f64.copysign(spin) * ((3.0 - z1) * (3.0 + z1 + 2.0 * z2)).sqrt()
}

/// The equatorial circular photon orbit 2M [1 + cos((2/3) acos(-+a*))]
/// (M = 1), prograde or retrograde, a* >= 0.
pub fn r_photon_equatorial(spin: f64, prograde: bool) -> f64 {
    let x = if prograde { -spin } else { spin };
    2.0 * (1.0 + (2.0 / 3.0 * x.acos()).cos())
}

/// The constants (lambda_c, eta_c) of the spherical photon orbit of radius
/// r (Bardeen 1973), a* != 0.
pub fn critical_lambda_eta(r: f64, a: f64) -> (f64, f64) {
    let lambda = -(r.powi(3) - 3.0 * r * r + a * a * r + a * a) / (a * (r - 1.0));
    let eta = r.powi(3) * (4.0 * a * a - r * (r - 3.0).powi(2)) / (a * a * (r - 1.0).powi(2));
    (lambda, eta)
}

/// The closed-form shadow proxy: the least f(u) = R / (E^2 r^4) over
/// u in [1/r_o, 1/r+]. An inward ray from outside the photon region escapes
/// iff it is negative.
pub fn shadow_proxy(a: f64, lambda: f64, eta: f64, r_o: f64) -> f64 {
    let h = eta + lambda * lambda - a * a;
    let b = eta + (lambda - a).powi(2);
    let c = a * a * eta;
    let f = |u: f64| 1.0 - h * u * u + 2.0 * b * u.powi(3) - c * u.powi(4);
    let (u0, u1) = (1.0 / r_o, 1.0 / r_horizon(a));
    let mut candidates = vec![u0, u1];
    if c != 0.0 {
        let disc = 36.0 * b * b - 32.0 * c * h;
        if disc >= 0.0 {
            let sq = disc.sqrt();
            candidates.extend([(6.0 * b - sq) / (8.0 * c), (6.0 * b + sq) / (8.0 * c)]);
        }
    } else if b != 0.0 {
        candidates.push(h / (3.0 * b));
    }
    candidates
        .into_iter()
        .filter(|u| (u0..=u1).contains(u))
        .map(f)
        .fold(f64::INFINITY, f64::min)
}

/// Page & Thorne (1974) eq. (15n), M = 1: the flux F = Mdot f / (4 pi r),
/// so T^4 is proportional to f / r; 0 at the ISCO. Signed spin.
pub fn page_thorne_f(r: f64, a: f64) -> f64 {
    let x = r.sqrt();
    let pt = PageThorne::new(a);
    let log_terms: f64 = (0..3)
        .map(|i| pt.coef[i] * ((x - pt.roots[i]) / (pt.x0 - pt.roots[i])).ln())
        .sum();
    let br = x - pt.x0 - 1.5 * a * (x / pt.x0).ln() - log_terms;
    1.5 / (x * x * (x.powi(3) - 3.0 * x + 2.0 * a)) * br
}

/// The constants of the Page-Thorne flux for spin a (M = 1): sqrt of the
/// ISCO, the roots x1, x2, x3 of x^3 - 3x + 2a = 0 and each root's
/// coefficient 3 (x_i - a)^2 / (x_i (x_i - x_j)(x_i - x_k)) (0 for a root
/// at 0, its limit at a = 0).
#[derive(Clone, Copy, Debug)]
pub struct PageThorne {
    pub x0: f64,
    pub roots: [f64; 3],
    pub coef: [f64; 3],
}

impl PageThorne {
    pub fn new(a: f64) -> Self {
        let t = a.acos() / 3.0;
        let roots = [
            2.0 * (t - PI / 3.0).cos(),
            2.0 * (t + PI / 3.0).cos(),
            -2.0 * t.cos(),
        ];
        let coef = std::array::from_fn(|i| {
            let (xi, xj, xk) = (roots[i], roots[(i + 1) % 3], roots[(i + 2) % 3]);
            if xi.abs() < 1e-12 {
                0.0
            } else {
                3.0 * (xi - a).powi(2) / (xi * (xi - xj) * (xi - xk))
            }
        });
        PageThorne {
            x0: r_isco(a).sqrt(),
            roots,
            coef,
        }
    }
}

/// Where T^4 (proportional to f / r) peaks around a hole of spin a, and its
/// value there (M = 1): golden-section search over (ISCO, 4 ISCO).
pub fn page_thorne_peak(a: f64) -> (f64, f64) {
    let isco = r_isco(a);
    let t4 = |r: f64| page_thorne_f(r, a) / r;
    let (mut lo, mut hi) = (isco * (1.0 + 1e-9), 4.0 * isco);
    let phi = 0.5 * (5f64.sqrt() - 1.0);
    for _ in 0..200 {
        let (m1, m2) = (hi - phi * (hi - lo), lo + phi * (hi - lo));
        if t4(m1) < t4(m2) {
            lo = m1;
        } else {
            hi = m2;
        }
    }
    let r = 0.5 * (lo + hi);
    (r, t4(r))
}
