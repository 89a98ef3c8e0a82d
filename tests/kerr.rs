//! The spinning hole's closed-form light paths (src/physics/kerr) against
//! closed forms of the geometry, the reference rays of the specification
//! (made with an independent f64 reference and a 20-digit Taylor-series
//! integrator), an independent step-by-step Mino-time integrator on random
//! rays, the non-rotating closed form at spin 0, and the symmetries. Each
//! test is named after what it shows.

use blackhole::physics::closed_form::trace_closed;
use blackhole::physics::geodesic::{Disk, Hole, Outcome};
use blackhole::physics::kerr::{
    self, KerrDisk, KerrObserver, KerrOutcome, KerrRay, mino, r_horizon, r_isco,
    r_photon_equatorial,
};
use glam::DVec3;

/// A small deterministic generator (SplitMix64), so failures reproduce.
struct Rng(u64);

impl Rng {
    fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }

    fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }
}

/// The camera convention: up +y, looking at the hole; the ray of screen
/// offsets (sx, sy).
fn offsets_direction(camera: DVec3, sx: f64, sy: f64) -> DVec3 {
    let forward = (-camera).normalize();
    let right = DVec3::Y.cross(forward).normalize();
    let up = forward.cross(right);
    (forward + sx * right + sy * up).normalize()
}

/// The angle between two unit vectors, accurate when it is small (acos
/// of the dot product is not: 1e-16 apart reads as 1e-8).
fn angle(a: DVec3, b: DVec3) -> f64 {
    2.0 * (0.5 * (a - b).length()).min(1.0).asin()
}

/// The disk of the reference rays: the prograde ISCO to 12 rs.
fn isco_disk(astar: f64) -> KerrDisk {
    KerrDisk {
        inner: r_isco(astar) / 2.0,
        outer: 12.0,
    }
}

/// a*, camera (rs), screen offsets, case, r (rs), azimuth, g, crossings before.
type ReferenceRay = (f64, [f64; 3], (f64, f64), u8, f64, f64, f64, u32);

#[test]
fn the_reference_rays_of_the_specification_are_reproduced() {
    // a*, camera (rs), (sx, sy), case, r (rs), azimuth, g, crossings before;
    // rounded to 9 decimals.
    let rows: [ReferenceRay; 6] = [
        (
            0.7,
            [2.0, 3.0, -20.0],
            (0.05, -0.06),
            3,
            6.026526422,
            -1.343684173,
            0.938745352,
            0,
        ),
        (
            0.7,
            [2.0, 3.0, -20.0],
            (0.01, -0.03),
            3,
            3.494176074,
            -1.404658177,
            0.811934241,
            0,
        ),
        (
            0.7,
            [2.0, 3.0, -20.0],
            (-0.12, 0.09),
            2,
            1.911989286,
            2.119995076,
            0.372360356,
            0,
        ),
        (
            0.95,
            [-5.0, -1.0, 7.0],
            (0.02, 0.11),
            3,
            4.342041388,
            2.223520478,
            0.887316186,
            0,
        ),
        (
            0.95,
            [-5.0, -1.0, 7.0],
            (0.0, 0.17),
            3,
            5.278218713,
            2.197481599,
            0.908647834,
            0,
        ),
        (
            0.7,
            [2.0, 3.0, -20.0],
            (0.1, 0.0),
            2,
            5.494320903,
            -2.464250398,
            0.989583222,
            1,
        ),
    ];
    for (a, cam, (sx, sy), case, r0, phi0, g0, before0) in rows {
        let cam = DVec3::from(cam);
        let ray = kerr::trace_zamo(cam, offsets_direction(cam, sx, sy), a, Some(isco_disk(a)));
        let KerrOutcome::Disk {
            r,
            phi,
            g,
            crossings_before,
        } = ray.outcome
        else {
            panic!("a* {a} {cam} ({sx}, {sy}): {:?}, not the disk", ray.outcome);
        };
        assert_eq!(
            (ray.case, crossings_before),
            (case, before0),
            "a* {a} ({sx}, {sy})"
        );
        let err = (r - r0).abs().max((phi - phi0).abs()).max((g - g0).abs());
        assert!(
            err < 1.5e-9,
            "a* {a} ({sx}, {sy}): r {r} phi {phi} g {g}: off by {err:e}"
        );
    }
}

#[test]
fn horizon_isco_photon_orbits_and_critical_lambda_match_their_closed_forms() {
    // a*, r+, ISCO pro, retro, photon orbit pro, retro, lambda_c pro, retro (M = 1).
    let rows = [
        (0.0, 2.0, 6.0, 6.0, 3.0, 3.0, 5.196152423, -5.196152423),
        (
            0.5,
            1.866025,
            4.233002530,
            7.554584715,
            2.347296355,
            3.532088886,
            4.096266659,
            -6.138155725,
        ),
        (
            0.7,
            1.714143,
            3.393128470,
            8.142965465,
            2.013334124,
            3.725345251,
            3.556760166,
            -6.490346039,
        ),
        (
            0.95,
            1.312250,
            1.937237878,
            8.859030068,
            1.386280528,
            3.955347318,
            2.582212445,
            -6.916416501,
        ),
        (
            0.99,
            1.141067,
            1.454497938,
            8.971861343,
            1.167641852,
            3.991102861,
            2.251724335,
            -6.983323431,
        ),
    ];
    for (a, rp, isco_p, isco_r, ph_p, ph_r, lam_p, lam_r) in rows {
        assert!((r_horizon(a) - rp).abs() < 1e-6, "a* {a}");
        assert!((r_isco(a) - isco_p).abs() < 1e-9, "a* {a}: {}", r_isco(a));
        assert!((r_isco(-a) - isco_r).abs() < 1e-9, "a* {a}: {}", r_isco(-a));
        let (p, r) = (r_photon_equatorial(a, true), r_photon_equatorial(a, false));
        assert!(
            (p - ph_p).abs() < 1e-9 && (r - ph_r).abs() < 1e-9,
            "a* {a}: {p} {r}"
        );
        // lambda_c = -a +- 6 cos(acos(-+a) / 3), and Bardeen's at the orbit.
        let closed = |s: f64| -a + s * 6.0 * ((-s * a).acos() / 3.0).cos();
        assert!((closed(1.0) - lam_p).abs() < 1e-9 && (closed(-1.0) - lam_r).abs() < 1e-9);
        if a != 0.0 {
            let (lp, ep) = kerr::critical_lambda_eta(p, a);
            let (lr, er) = kerr::critical_lambda_eta(r, a);
            assert!(
                (lp - lam_p).abs() < 1e-8 && (lr - lam_r).abs() < 1e-8,
                "a* {a}: {lp} {lr}"
            );
            // Equatorial orbits: eta_c = 0.
            assert!(ep.abs() < 1e-7 && er.abs() < 1e-7, "a* {a}: {ep} {er}");
        }
    }
}

/// The largest difference between two traced rays with the same outcome
/// (r, azimuth, g or the escape direction's angle), or None if the
/// outcomes differ.
fn difference(x: &KerrRay, y: &KerrRay) -> Option<f64> {
    match (x.outcome, y.outcome) {
        (KerrOutcome::Captured, KerrOutcome::Captured) => Some(0.0),
        (
            KerrOutcome::Disk {
                r,
                phi,
                g,
                crossings_before: n,
            },
            KerrOutcome::Disk {
                r: r2,
                phi: phi2,
                g: g2,
                crossings_before: n2,
            },
        ) if n == n2 => {
            let dphi = (phi - phi2 + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU)
                - std::f64::consts::PI;
            Some((r - r2).abs().max(dphi.abs()).max((g - g2).abs()))
        }
        (KerrOutcome::Escaped(d), KerrOutcome::Escaped(d2)) => Some(angle(d, d2)),
        _ => None,
    }
}

#[test]
fn the_closed_form_agrees_with_a_step_by_step_integrator_on_random_rays() {
    let mut rng = Rng(0x6b65_7272);
    let (mut worst, mut count, mut near_edge) = (0.0f64, [0usize; 3], 0);
    for i in 0..240 {
        let a = if i % 4 == 3 {
            -rng.range(0.0, 0.9)
        } else {
            rng.range(0.0, 0.99)
        };
        let r = rng.range(2.5, 25.0);
        let th = rng.range(0.15, std::f64::consts::PI - 0.15);
        let ph = rng.range(-3.1, 3.1);
        let cam = r * DVec3::new(th.sin() * ph.cos(), th.cos(), -th.sin() * ph.sin());
        // Mostly toward the hole, some away from it.
        let spread = if i % 5 == 0 { 2.5 } else { 0.6 };
        let (sx, sy) = (rng.range(-spread, spread), rng.range(-spread, spread));
        let d = offsets_direction(cam, sx, sy);
        let disk = Some(KerrDisk {
            inner: r_isco(a) / 2.0,
            outer: 12.0,
        });
        let closed = kerr::trace_zamo(cam, d, a, disk);
        if closed.lambda.abs() < 1e-6 {
            continue; // the integrator is unreliable next to the axis
        }
        let stepped = mino::integrate(cam, d, a, disk, 1e-12);
        match difference(&closed, &stepped) {
            Some(e) => {
                worst = worst.max(e);
                count[match closed.outcome {
                    KerrOutcome::Captured => 0,
                    KerrOutcome::Disk { .. } => 1,
                    KerrOutcome::Escaped(_) => 2,
                }] += 1;
                assert!(
                    e < 3e-8,
                    "ray {i}: a* {a} cam {cam} d {d}: {closed:?} vs {stepped:?}"
                );
            }
            None => {
                // Only a ray on the shadow's edge may differ.
                let proxy = kerr::shadow_proxy(a, closed.lambda, closed.eta, 2.0 * r);
                assert!(
                    proxy.abs() < 1e-6,
                    "ray {i}: a* {a} cam {cam} d {d}: {closed:?} vs {stepped:?}"
                );
                near_edge += 1;
            }
        }
    }
    println!("captured/disk/escaped {count:?}, on the edge {near_edge}, worst {worst:.2e}");
    assert!(
        count.iter().all(|&c| c >= 20),
        "{count:?}: every outcome tested"
    );
}

#[test]
fn at_spin_zero_the_kerr_path_is_the_schwarzschild_closed_form() {
    let hole = Hole {
        position: DVec3::ZERO,
        rs: 1.0,
    };
    let disk = Disk {
        normal: DVec3::Y,
        inner: 3.0,
        outer: 12.0,
    };
    let kdisk = KerrDisk {
        inner: 3.0,
        outer: 12.0,
    };
    let mut rng = Rng(7);
    let mut seen = [0usize; 3];
    for _ in 0..300 {
        let cam = DVec3::new(
            rng.range(-1.0, 1.0),
            rng.range(-0.6, 0.6),
            rng.range(-1.0, 1.0),
        )
        .normalize()
            * rng.range(4.0, 30.0);
        let d = offsets_direction(cam, rng.range(-0.7, 0.7), rng.range(-0.7, 0.7));
        let k = kerr::trace(cam, d, 0.0, KerrObserver::Static, Some(kdisk))
            .expect("outside the horizon");
        // The same ray in the non-rotating closed form: the static
        // observer's direction as a coordinate direction.
        let observer = blackhole::physics::observer::Observer::new(
            blackhole::physics::observer::ObserverKind::Static,
            cam,
            &[hole],
            DVec3::Y,
            true,
        );
        let s = trace_closed(&hole, Some(&disk), cam, observer.coordinate_direction(d));
        match (k.outcome, s) {
            (KerrOutcome::Captured, Outcome::Captured { .. }) => seen[0] += 1,
            (KerrOutcome::Disk { r, phi, .. }, Outcome::Disk { position, .. }) => {
                assert!((r - position.length()).abs() < 1e-9, "{r} vs {position}");
                let az = position.z.atan2(position.x);
                assert!((phi - az).abs() < 1e-9, "{phi} vs {az}");
                seen[1] += 1;
            }
            (KerrOutcome::Escaped(a), Outcome::Escaped { direction }) => {
                assert!(angle(a, direction) < 1e-9, "{a} vs {direction}");
                seen[2] += 1;
            }
            (x, y) => {
                let m = kerr::shadow_proxy(0.0, k.lambda, k.eta, 2.0 * cam.length());
                assert!(m.abs() < 1e-9, "cam {cam} d {d}: {x:?} vs {y:?}");
            }
        }
    }
    assert!(seen.iter().all(|&c| c >= 20), "{seen:?}");
}

#[test]
fn mirror_images_through_the_disk_plane_and_reversed_spin_are_the_same_paths() {
    let mut rng = Rng(99);
    for _ in 0..200 {
        let a = rng.range(0.05, 0.99);
        let cam = DVec3::new(
            rng.range(-10.0, 10.0),
            rng.range(-8.0, 8.0),
            rng.range(-20.0, -5.0),
        );
        let d = offsets_direction(cam, rng.range(-0.5, 0.5), rng.range(-0.5, 0.5));
        let disk = Some(KerrDisk {
            inner: 2.0,
            outer: 12.0,
        });
        let ray = kerr::trace_zamo(cam, d, a, disk);
        // Through the disk plane: y -> -y.
        let flip_y = DVec3::new(1.0, -1.0, 1.0);
        let mirrored = kerr::trace_zamo(cam * flip_y, d * flip_y, a, disk);
        // Spin reversed with x -> -x.
        let flip_x = DVec3::new(-1.0, 1.0, 1.0);
        let reversed = kerr::trace_zamo(cam * flip_x, d * flip_x, -a, disk);
        match (ray.outcome, mirrored.outcome, reversed.outcome) {
            (KerrOutcome::Captured, KerrOutcome::Captured, KerrOutcome::Captured) => {}
            (
                KerrOutcome::Disk { r, phi, g, .. },
                KerrOutcome::Disk {
                    r: r2,
                    phi: phi2,
                    g: g2,
                    ..
                },
                KerrOutcome::Disk {
                    r: r3, phi: phi3, ..
                },
            ) => {
                assert!(
                    (r - r2).abs() < 1e-9 && (phi - phi2).abs() < 1e-9 && (g - g2).abs() < 1e-9
                );
                let back = std::f64::consts::PI - phi3;
                let dphi = (phi - back + std::f64::consts::PI).rem_euclid(std::f64::consts::TAU)
                    - std::f64::consts::PI;
                assert!(
                    (r - r3).abs() < 1e-9 && dphi.abs() < 1e-9,
                    "{r} {phi} vs {r3} {phi3}"
                );
            }
            (KerrOutcome::Escaped(e), KerrOutcome::Escaped(e2), KerrOutcome::Escaped(e3)) => {
                assert!(angle(e, e2 * flip_y) < 1e-9, "{e} vs {e2}");
                assert!(angle(e, e3 * flip_x) < 1e-9, "{e} vs {e3}");
            }
            (x, y, z) => {
                let m = kerr::shadow_proxy(a, ray.lambda, ray.eta, 2.0 * cam.length());
                assert!(m.abs() < 1e-9, "a* {a} cam {cam}: {x:?} / {y:?} / {z:?}");
            }
        }
    }
}

#[test]
fn the_shadow_proxy_and_the_case_split_agree_on_inward_rays() {
    let mut rng = Rng(3);
    let mut both = [0usize; 2];
    for _ in 0..2000 {
        let a = rng.range(-0.6, 0.99);
        let cam = DVec3::new(
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
            rng.range(-1.0, 1.0),
        )
        .normalize()
            * rng.range(2.5, 30.0);
        let d = offsets_direction(cam, rng.range(-0.4, 0.4), rng.range(-0.4, 0.4));
        let ray = kerr::trace_zamo(cam, d, a, None);
        let cc = kerr::Constants::of(2.0 * cam, d, a);
        if cc.s_r > 0.0 || ray.case == 1 {
            continue;
        }
        let escapes = kerr::shadow_proxy(a, ray.lambda, ray.eta, cc.frame.r) < 0.0;
        assert_eq!(
            escapes,
            matches!(ray.outcome, KerrOutcome::Escaped(_)),
            "a* {a} cam {cam} d {d}"
        );
        both[usize::from(escapes)] += 1;
    }
    assert!(both.iter().all(|&c| c > 100), "{both:?}");
}

#[test]
fn page_thorne_flux_vanishes_at_the_isco_and_is_positive_outside() {
    for a in [-0.9, -0.5, 0.01, 0.5, 0.9, 0.998] {
        let isco = r_isco(a);
        assert!(
            kerr::page_thorne_f(isco * (1.0 + 1e-12), a).abs() < 1e-8,
            "a* {a}"
        );
        for k in 1..50 {
            let r = isco * (1.0 + 0.2 * f64::from(k));
            assert!(kerr::page_thorne_f(r, a) > 0.0, "a* {a} r {r}");
        }
    }
}
