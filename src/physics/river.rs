//! Light paths of a non-rotating hole integrated step by step in
//! Painlevé-Gullstrand coordinates (the "river" model: flat space that
//! flows into the hole at `v = sqrt(rs / r)`), valid across the horizon:
//! an independent reference for the camera that falls through it. Nothing
//! here uses the closed form or the photon's constants: only the metric.
//!
//! In Cartesian PG coordinates, lapse 1 and shift `beta = v r_hat`, so
//! `ds^2 = -dt^2 + |dx + beta dt|^2` and a null geodesic is the flow of
//! `H = (|p|^2 - (p_t - beta . p)^2) / 2` (p_t = -E conserved):
//! `dx/dl = p + (p_t - beta . p) beta`, `dp/dl = -(p_t - beta . p)
//! grad(beta . p)`. The rain observer's frame is the flat coordinate frame
//! itself (see [`super::rain`]), so a pixel's unit direction `d` is the
//! photon's covector `p = -d` (per unit frequency), `E = 1 + beta . d`.

use glam::DVec3;

/// Where a backward ray from a rain observer ends.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RiverOutcome {
    /// Out to infinity: the backward ray's final unit direction (the
    /// direction on the sky the light came from).
    Escaped(DVec3),
    /// The thin disk (its plane through the hole, normal +y): the crossing's
    /// radius, its azimuth atan2(z, x) and the redshift g the rain observer
    /// measures of light from the disk's prograde Keplerian emitter there.
    Disk { r: f64, phi: f64, g: f64 },
    /// Back into the horizon from outside (the shadow).
    Captured,
    /// E <= 0: light from the other universe of an eternal hole.
    OtherUniverse,
    /// The step budget ran out.
    NoSteps,
}

/// The thin disk a backward ray may end at: the annulus [inner, outer] of
/// the plane y = 0 through the hole (normal +y, turning counter-clockwise
/// seen from +y).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct RiverDisk {
    pub inner: f64,
    pub outer: f64,
}

/// The backward ray of a rain observer at `x0` (the hole of size `rs` at the
/// origin) along the unit pixel direction `d` of its frame.
pub fn trace_rain(rs: f64, x0: DVec3, d: DVec3) -> RiverOutcome {
    trace_rain_to(rs, x0, d, None)
}

/// One RK4 step of length `h` of the backward flow `deriv`.
fn rk4(
    deriv: &impl Fn(DVec3, DVec3) -> (DVec3, DVec3),
    x: DVec3,
    p: DVec3,
    h: f64,
) -> (DVec3, DVec3) {
    let (k1x, k1p) = deriv(x, p);
    let (k2x, k2p) = deriv(x + 0.5 * h * k1x, p + 0.5 * h * k1p);
    let (k3x, k3p) = deriv(x + 0.5 * h * k2x, p + 0.5 * h * k2p);
    let (k4x, k4p) = deriv(x + h * k3x, p + h * k3p);
    (
        x + h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x),
        p + h / 6.0 * (k1p + 2.0 * k2p + 2.0 * k3p + k4p),
    )
}

/// The same, ending at the thin `disk` where the ray first crosses its
/// plane inside the annulus. The crossing is found by bisecting the step
/// that crosses the plane (each trial an RK4 step from the step's start);
/// its g is sqrt(1 - 1.5 rs / r) / (E - Omega L), with E = -p_t and
/// L = p . (y x x) the photon's conserved energy and angular momentum
/// about the disk's axis (per unit of the frequency the camera sees).
pub fn trace_rain_to(rs: f64, x0: DVec3, d: DVec3, disk: Option<RiverDisk>) -> RiverOutcome {
    let beta = |x: DVec3| rs.sqrt() * x.length().powf(-1.5) * x;
    let d = d.normalize();
    let e = 1.0 + beta(x0).dot(d);
    if e <= 0.0 {
        return RiverOutcome::OtherUniverse;
    }
    let p_t = -e;
    // The backward flow: minus Hamilton's equations.
    let deriv = |x: DVec3, p: DVec3| {
        let r = x.length();
        let b = beta(x);
        let w = p_t - b.dot(p);
        let grad = rs.sqrt() * (r.powf(-1.5) * p - 1.5 * r.powf(-3.5) * x.dot(p) * x);
        (-(p + w * b), w * grad)
    };
    let (mut x, mut p) = (x0, -d);
    let mut was_outside = x0.length() > rs;
    // Far enough that what bending and flow are left turn the direction by
    // under 1e-9 rad (rs b / (2 r^2) and the flow's v (b / r)).
    let r_escape = 1e7 * rs;
    for _ in 0..2_000_000 {
        let r = x.length();
        if r > r_escape {
            return RiverOutcome::Escaped(deriv(x, p).0.normalize());
        }
        // Outside the horizon and moving inward inside the photon sphere
        // (1.5 rs), a light path has no turning point left: it ends in the
        // horizon (at the past horizon, for a ray traced backward, where
        // these coordinates end).
        was_outside |= r > rs;
        if was_outside && r < 1.5 * rs && deriv(x, p).0.dot(x) < 0.0 {
            return RiverOutcome::Captured;
        }
        // A step a small fraction of r along the path (RK4).
        let speed = deriv(x, p).0.length().max(1e-300);
        let h = 2e-3 * r / speed;
        let (nx, np) = rk4(&deriv, x, p, h);
        if let Some(disk) = disk
            && x.y != 0.0
            && (x.y > 0.0) != (nx.y > 0.0)
        {
            let (mut lo, mut hi) = (0.0, h);
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                if (rk4(&deriv, x, p, mid).0.y > 0.0) == (x.y > 0.0) {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            let (cx, cp) = rk4(&deriv, x, p, 0.5 * (lo + hi));
            let rc = DVec3::new(cx.x, 0.0, cx.z).length();
            if rc >= disk.inner && rc <= disk.outer {
                let l = cp.dot(DVec3::Y.cross(cx));
                let omega = (rs / (2.0 * rc * rc * rc)).sqrt();
                let g = (1.0 - 1.5 * rs / rc).sqrt() / (e - omega * l);
                return RiverOutcome::Disk {
                    r: rc,
                    phi: cx.z.atan2(cx.x),
                    g,
                };
            }
        }
        (x, p) = (nx, np);
    }
    RiverOutcome::NoSteps
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::physics::rain;

    /// The rain frame's photon constants (E, b = L / E, physics/rain.rs)
    /// decide where a backward ray goes: E <= 0 the other universe; at and
    /// inside the horizon (every backward ray starts outward), b below the
    /// critical (3 sqrt 3 / 2) rs out to the sky, above it back into the
    /// horizon; outside, the same with the ray's heading and the photon
    /// sphere. The integrated paths, which know only the metric, agree for
    /// cameras outside, at and inside the horizon, for every pixel away
    /// from the critical b.
    #[test]
    fn integrated_paths_end_where_the_rain_frames_constants_say() {
        let rs = 1.0;
        let b_c = 1.5 * 3f64.sqrt() * rs;
        for r in [2.5, 1.0 + 1e-3, 1.0 - 1e-3, 0.5, 0.1] {
            let x0 = DVec3::new(0.0, r, 0.0);
            let mut seen = [0; 3];
            for k in 1..90 {
                let alpha = f64::from(2 * k).to_radians();
                // Angle alpha from straight down, in the x-y plane.
                let d = DVec3::new(alpha.sin(), -alpha.cos(), 0.0);
                let (e, l) = rain::photon_constants(r, rs, d.y, d.x);
                if e > 0.0 && ((l / e) / b_c - 1.0).abs() < 1e-3 {
                    continue;
                }
                let got = trace_rain(rs, x0, d);
                // The backward ray starts outward where d_r + v > 0 (always
                // at and inside the horizon when E > 0). Outside the photon
                // sphere it escapes unless it heads in below b_c; inside
                // it, only heading out below b_c.
                let outward = d.y + rain::fall_speed(r, rs) > 0.0;
                let below = l / e < b_c;
                let escapes = if r > 1.5 * rs {
                    outward || !below
                } else {
                    outward && below
                };
                let want = if e <= 0.0 {
                    2
                } else if escapes {
                    0
                } else {
                    1
                };
                let kind = match got {
                    RiverOutcome::Escaped(_) | RiverOutcome::Disk { .. } => 0,
                    RiverOutcome::Captured => 1,
                    RiverOutcome::OtherUniverse => 2,
                    RiverOutcome::NoSteps => 3,
                };
                assert_eq!(kind, want, "r {r}, alpha {}: {got:?}, b {}", 2 * k, l / e);
                seen[want] += 1;
            }
            // Every camera sees sky; the ones at and inside the horizon
            // see the shadow below them, the deepest the other universe.
            assert!(seen[0] > 0, "r {r}: {seen:?}");
            if r < 1.01 {
                assert!(seen[1] > 0, "r {r}: {seen:?}");
            }
            if r <= 0.5 {
                assert!(seen[2] > 0, "r {r}: {seen:?}");
            }
        }
    }

    /// The integrated paths (the metric alone) and the closed form fed by
    /// the falling observer's rain form (physics/observer.rs) agree on the
    /// sky's direction and the disk's radius and azimuth to 1e-7, for
    /// cameras outside, at, and inside the horizon: the rain form and
    /// Binet's u(phi) through r = rs are one light path. Pixels near the
    /// critical b or a disk edge (where 1e-9 of direction decides) are
    /// left out.
    #[test]
    fn integrated_paths_meet_the_closed_form_through_the_horizon() {
        use crate::physics::closed_form::trace_closed;
        use crate::physics::geodesic::{Disk, Hole, Outcome};
        use crate::physics::observer::{Observer, ObserverKind};
        let rs = 1.0;
        let hole = Hole {
            position: DVec3::ZERO,
            rs,
        };
        let disk = Disk {
            normal: DVec3::Y,
            inner: 3.0,
            outer: 12.0,
        };
        let river_disk = Some(RiverDisk {
            inner: 3.0,
            outer: 12.0,
        });
        let mut compared = [0usize; 2];
        for r in [2.5, 1.0 + 1e-3, 1.0, 0.5, 0.1] {
            let x0 = DVec3::new(0.0, 0.3 * r, -r * 0.91f64.sqrt());
            let obs = Observer::new(ObserverKind::Falling, x0, &[hole], DVec3::Y, true);
            for k in 0..400 {
                let d = crate::physics::sphere_direction(k, 400);
                let got = trace_rain_to(rs, x0, d, river_disk);
                if obs.energy(d) <= 0.0 {
                    assert_eq!(got, RiverOutcome::OtherUniverse, "r {r}, d {d}");
                    continue;
                }
                let v = obs.coordinate_direction(d);
                let want = trace_closed(&hole, Some(&disk), x0, v);
                // Well conditioned: a 1e-6 turn of d keeps the outcome.
                let near = trace_closed(
                    &hole,
                    Some(&disk),
                    x0,
                    obs.coordinate_direction((d + 1e-6 * DVec3::X).normalize()),
                );
                if std::mem::discriminant(&near) != std::mem::discriminant(&want) {
                    continue;
                }
                match (got, want) {
                    (RiverOutcome::Escaped(a), Outcome::Escaped { direction }) => {
                        assert!(
                            (a - direction).length() < 1e-7,
                            "r {r}, d {d}: {a} vs {direction}"
                        );
                        compared[0] += 1;
                    }
                    (RiverOutcome::Disk { r: rc, phi, .. }, Outcome::Disk { position, .. }) => {
                        let (rw, pw) = (position.length(), position.z.atan2(position.x));
                        assert!(
                            (rc - rw).abs() < 1e-7 && (phi - pw).abs() < 1e-7,
                            "r {r}, d {d}: {rc} {phi} vs {rw} {pw}"
                        );
                        compared[1] += 1;
                    }
                    (RiverOutcome::Captured, Outcome::Captured { .. }) => {}
                    (a, b) => panic!("r {r}, d {d}: integrated {a:?}, closed form {b:?}"),
                }
            }
        }
        assert!(compared[0] > 1000 && compared[1] > 50, "{compared:?}");
    }

    /// Far out, the river is still and the integrated path is the exterior
    /// light path: a ray from a distant camera bends by the weak-field
    /// angle 2 rs / b + (15 pi / 16) (rs / b)^2 to within its next order.
    #[test]
    fn far_out_the_integrated_path_bends_by_the_weak_field_angle() {
        let rs = 1.0;
        let r0 = 5e3;
        for b in [40.0, 80.0] {
            // The pixel that sees the sky at impact parameter b, looking
            // nearly at the hole: sin(psi) = b / r0 (the fall there is slow,
            // and its aberration is taken out by the constants).
            let x0 = DVec3::new(0.0, 0.0, -r0);
            let (mut lo, mut hi) = (0.0f64, 0.1f64);
            for _ in 0..60 {
                let mid = 0.5 * (lo + hi);
                let (e, l) = rain::photon_constants(r0, rs, -mid.cos(), mid.sin());
                if l / e < b {
                    lo = mid;
                } else {
                    hi = mid;
                }
            }
            let psi = 0.5 * (lo + hi);
            let d = DVec3::new(psi.sin(), 0.0, psi.cos());
            let RiverOutcome::Escaped(dir) = trace_rain(rs, x0, d) else {
                panic!("b {b}: did not escape");
            };
            // The backward ray left along d and ends along `dir`, turned
            // toward the hole (-x) by the deflection.
            let bend = psi - dir.x.atan2(dir.z);
            let weak = 2.0 * rs / b + 15.0 * std::f64::consts::PI / 16.0 * (rs / b).powi(2);
            // The camera and the escape sphere are at finite distance: each
            // leaves about rs / r0 + b / r of the angle unbent.
            assert!(
                (bend - weak).abs() < 0.1 * weak,
                "b {b}: {bend} against {weak}"
            );
        }
    }
}
