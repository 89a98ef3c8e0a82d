//! The GPU's Stokes AOV against the independent f64 reference
//! (src/physics/kerr/transport.rs: the electric vector parallel-transported
//! step by step in Kerr-Schild coordinates, no Walker-Penrose constant),
//! ray by ray, for several spins, cameras and observers: the polarization
//! angle within 1e-4 rad and I (and so P = fraction I) within 2e-4
//! relative at the 99th percentile, wherever sin(theta_B) and |k_z| are
//! above 1e-2; no pixel NaN; I = Q = U = 0 off the disk.

// (Its device-dependent test runs from tests/device.rs.)
#![cfg_attr(test, allow(dead_code))]

mod common;

use blackhole::physics::kerr::{self, KerrDisk, KerrObserver};
use blackhole::physics::observer::{Observer, ObserverKind};
use blackhole::spacetime::Stokes;
use glam::DVec3;

const W: u32 = 40;
const H: u32 = 24;

fn p99(v: &mut [f64]) -> f64 {
    if v.is_empty() {
        return 0.0;
    }
    v.sort_by(f64::total_cmp);
    v[((0.99 * v.len() as f64).ceil() as usize).clamp(1, v.len()) - 1]
}

/// The angle between two electric vectors (headless), radians.
fn angle_between(a: &Stokes, b: &Stokes) -> f64 {
    let d = a.angle() - b.angle();
    (2.0 * d).sin().atan2((2.0 * d).cos()).abs() / 2.0
}

struct Figures {
    compared: usize,
    edges: usize,
    /// Volumetric: rays whose sum is depolarized (P / I below 0.99 of the
    /// fraction: light of two crossings, the thin slab being transparent).
    depolarized: usize,
    angle: Vec<f64>,
    intensity: Vec<f64>,
}

/// One camera's Stokes AOV (rendered with `env`) against the reference.
/// `volume`: the scene's disk is a thin volumetric slab, whose summed
/// samples are compared with the thin disk's angle (the intensity's model
/// differs: `intensity` holds |P / I - fraction| / fraction instead).
fn compare(scene_toml: &str, env: &[(&str, &str)], volume: bool) -> Figures {
    let (scene, gpu) = common::render_aov_named("stokes", scene_toml, W, H, env);
    let frame = scene.camera.frame();
    let spin = scene.black_holes[0].spin;
    let kind = match scene.camera.observer {
        ObserverKind::Zamo => KerrObserver::Zamo,
        ObserverKind::Falling => KerrObserver::Falling,
        ObserverKind::Orbiting => KerrObserver::Orbiting,
        _ => KerrObserver::Static,
    };
    let disk = KerrDisk {
        inner: scene.disk.inner_radius,
        outer: scene.disk.outer_radius,
    };
    let em = scene.emission();
    let mut at = frame.position;
    if at.x == 0.0 && at.z == 0.0 {
        at.x = 1e-6 * at.length();
    }
    // A falling camera between the horizons or just outside them: its own
    // frame, built from the metric (no velocity through any other).
    let falling = kind == KerrObserver::Falling && kerr::in_falling_band(2.0 * at, spin);
    // The observer's velocity through the ZAMO's frame; at a* = 0 the
    // non-rotating hole's own observers (an orbiting one on the great
    // circle through it, not around the disk's axis).
    let beta = if falling {
        DVec3::ZERO
    } else if spin == 0.0 {
        let holes = [blackhole::physics::Hole {
            position: DVec3::ZERO,
            rs: 1.0,
        }];
        Observer::new(scene.camera.observer, at, &holes, DVec3::Y, true).beta
    } else {
        kerr::observer_velocity(kind, 2.0 * at, spin).expect("placed")
    };
    let mut f = Figures {
        compared: 0,
        edges: 0,
        depolarized: 0,
        angle: Vec::new(),
        intensity: Vec::new(),
    };
    for y in 0..H {
        for x in 0..W {
            let p = gpu.get_pixel(x, y).0.map(f64::from);
            assert!(
                p.iter().all(|v| v.is_finite()),
                "{scene_toml}\npixel ({x}, {y}): GPU {p:?}"
            );
            // (Outside a fisheye's circle: no ray, no light.)
            let Some(d) = frame.ray_dir(x, y, W, H) else {
                assert_eq!(p[0], 0.0, "pixel ({x}, {y}) has no ray");
                continue;
            };
            let got = Stokes {
                i: p[0],
                q: p[1],
                u: p[2],
                v: p[3],
            };
            assert_eq!(got.v, 0.0, "pixel ({x}, {y}): no circular part");
            let twin =
                kerr::polarized::stokes(at, d, frame.up, spin, kind, disk, &em).expect("placed");
            if twin.stokes.i == 0.0 && got.i == 0.0 {
                continue;
            }
            let want = if falling {
                kerr::transport::stokes_transported_falling(at, d, frame.up, spin, disk, &em)
            } else {
                kerr::transport::stokes_transported_moving(at, d, frame.up, spin, beta, disk, &em)
            };
            if (want.stokes.i == 0.0) != (got.i == 0.0) {
                // On and off the disk: only at the annulus's edges and the
                // photon ring, where a 1e-7 rad turn of the ray decides.
                f.edges += 1;
                continue;
            }
            if !want.well_defined() {
                continue;
            }
            if volume {
                let m = got.polarized() / got.i / em.fraction;
                if m < 0.99 {
                    f.depolarized += 1;
                    continue;
                }
                f.intensity.push((m - 1.0).abs());
            } else {
                f.intensity
                    .push((got.i - want.stokes.i).abs() / want.stokes.i);
            }
            f.compared += 1;
            f.angle.push(angle_between(&got, &want.stokes));
        }
    }
    f
}

/// Run by tests/device.rs (64-bit floats for the camera's side and the
/// constants).
pub fn gpu_stokes_matches_the_transported_reference() {
    let cameras = [
        // spin, position, observer, vfov, look-at
        (0.9, [2.0, 3.0, -14.0], "zamo", 50.0),
        (-0.5, [0.0, 1.5, -9.0], "static", 60.0),
        (0.5, [1.0, 1.0, -6.0], "falling", 80.0),
        (0.99, [0.8, 0.1, 0.2], "zamo", 90.0),
        (0.7, [0.0, 500.0, -850.0], "static", 1.8),
        // Far: 1e4 to 1e5 rs, the rays passing the hole at 1e-4 of that
        // (the spinning hole's 64-bit build forms them in f64).
        (0.7, [0.0, 6123.4, -19234.5], "static", 0.09),
        (0.9, [7012.3, 2345.6, -6987.6], "falling", 0.18),
        (-0.6, [0.0, 30123.4, -95234.5], "zamo", 0.018),
        (0.3, [0.0, 12.0, -0.5], "orbiting", 70.0),
        // The non-rotating hole (the AOV takes the spinning hole's 64-bit
        // form at a* = 0 where the device has 64-bit floats), near and far.
        (0.0, [1.0, 2.0, -15.0], "static", 50.0),
        (0.0, [0.0, 6123.4, -19234.5], "static", 0.09),
        (0.0, [8012.3, 2345.6, -5987.6], "falling", 0.18),
        (0.0, [0.5, 1.0, -5.0], "falling", 80.0),
        (0.0, [0.0, 9.0, -3.0], "orbiting", 70.0),
        // Falling through the horizon: between a spinning hole's horizons
        // (0.67 r+ of a* = 0.9), in the band just outside r+ (1.015 r+ of
        // a* = 0.7), inside the non-rotating hole (0.62 rs) and just
        // outside it (1.015 rs).
        (0.9, [0.1, 0.25, -0.55], "falling", 100.0),
        (0.7, [0.0, 0.3, -0.88], "falling", 100.0),
        (0.0, [0.3, 0.35, -0.42], "falling", 100.0),
        (0.0, [0.0, 0.1, -1.01], "falling", 100.0),
    ];
    check_cameras(&cameras, &[]);
    // A panorama and a fisheye from between the horizons (every pixel's own
    // north from the camera's up).
    let mut report = Vec::new();
    for projection in ["equirect", "fisheye"] {
        let toml = format!(
            "[[black_hole]]\nspin = 0.9\n[camera]\nposition = [0.1, 0.25, -0.55]\nlook_at = [0.3, 0.0, -1.6]\nprojection = \"{projection}\"\nvfov_deg = 180.0\nobserver = \"falling\"\nup = [0.1, 1.0, 0.0]\n[disk]\ninner_radius = {}\nouter_radius = 12.0\n[polarization]\nfield = [0.3, 0.6, 0.7]\n",
            kerr::r_isco(0.9) / 2.0
        );
        let mut f = compare(&toml, &[], false);
        let (angle, intensity) = (p99(&mut f.angle), p99(&mut f.intensity));
        report.push(format!(
            "{projection} from 0.67 r+ of a* = 0.9: {} rays, {} edges, angle p99 {angle:.2e} rad, I p99 {intensity:.2e}",
            f.compared, f.edges
        ));
        assert!(
            f.compared > 20 && f.edges * 20 <= f.compared,
            "{}",
            report.join("\n")
        );
        assert!(angle <= 1e-4 && intensity <= 2e-4, "{}", report.join("\n"));
    }
    println!("{}", report.join("\n"));
}

/// The non-rotating hole's falling cameras through the horizon again in the
/// 32-bit build (`BLACKHOLE_NO_F64=1`, as on a device without 64-bit
/// floats: its own rain-frame closed form): the same goals. (A spinning
/// hole's falling frame needs 64-bit floats: refused by name.)
#[test]
fn gpu_stokes_through_the_horizon_in_32_bits_matches_the_transported_reference() {
    check_cameras(
        &[
            (0.0, [0.3, 0.35, -0.42], "falling", 100.0),
            (0.0, [0.0, 0.2, -0.49], "falling", 100.0),
            (0.0, [0.0, 0.1, -1.01], "falling", 100.0),
        ],
        &[("BLACKHOLE_NO_F64", "1")],
    );
}

/// Each camera (spin, position in rs, observer, vfov) against the
/// reference, with the goals.
fn check_cameras(cameras: &[(f64, [f64; 3], &str, f64)], env: &[(&str, &str)]) {
    let mut report = Vec::new();
    for &(spin, at, observer, vfov) in cameras {
        // (From inside the horizon our universe is outward: a falling
        // camera there, or just outside, looks along the disk's plane away
        // from the hole.)
        let inside = observer == "falling" && at[0] * at[0] + at[1] * at[1] + at[2] * at[2] < 1.1;
        let look = if inside {
            [3.0 * at[0], 0.0, 3.0 * at[2]]
        } else {
            [0.0; 3]
        };
        let toml = format!(
            "[[black_hole]]\nspin = {spin}\n[camera]\nposition = [{}, {}, {}]\nlook_at = [{}, {}, {}]\nvfov_deg = {vfov}\nobserver = \"{observer}\"\nup = [0.1, 1.0, 0.0]\n[disk]\ninner_radius = {}\nouter_radius = 12.0\n[polarization]\nfield = [0.3, 0.6, 0.7]\n",
            at[0],
            at[1],
            at[2],
            look[0],
            look[1],
            look[2],
            kerr::r_isco(spin) / 2.0
        );
        let mut f = compare(&toml, env, false);
        let (angle, intensity) = (p99(&mut f.angle), p99(&mut f.intensity));
        report.push(format!(
            "{env:?} spin {spin} {at:?} {observer}: {} rays, {} edges, angle p99 {angle:.2e} rad, I p99 {intensity:.2e}",
            f.compared, f.edges
        ));
        assert!(f.compared > 20, "{}", report.join("\n"));
        assert!(f.edges * 20 <= f.compared, "{}", report.join("\n"));
        assert!(angle <= 1e-4 && intensity <= 2e-4, "{}", report.join("\n"));
    }
    println!("{}", report.join("\n"));
}

/// The volumetric disk's summed samples (each its own Walker-Penrose
/// constant; src/physics/kerr/transport/tests.rs holds each sample off the
/// equator against the transport to 1e-6 rad): in a slab 0.004 rs thick
/// they draw the thin disk's electric vector, within 1e-4 rad of the
/// transported one at the 99th percentile, and P / I the fraction within
/// 1e-3. Run by tests/device.rs (the spinning hole's 64-bit build, a* = 0
/// on its form too).
pub fn gpu_stokes_of_a_thin_volumetric_slab_matches_the_transported_disk() {
    check_slab(
        &[
            (0.9, [2.0, 3.0, -14.0], "zamo", 50.0),
            (-0.5, [0.0, 1.5, -9.0], "static", 60.0),
            (0.5, [1.0, 1.0, -6.0], "falling", 80.0),
            (0.0, [1.0, 2.0, -15.0], "static", 50.0),
        ],
        &[],
    );
}

/// The same of the non-rotating hole's own 32-bit form (static frame,
/// coordinate-free: `BLACKHOLE_NO_F64=1`, as on a device without 64-bit
/// floats).
#[test]
fn gpu_stokes_of_a_thin_volumetric_slab_in_32_bits_matches_the_transported_disk() {
    check_slab(
        &[
            (0.0, [1.0, 2.0, -15.0], "static", 50.0),
            (0.0, [0.5, 1.0, -5.0], "falling", 80.0),
        ],
        &[("BLACKHOLE_NO_F64", "1")],
    );
}

fn check_slab(cameras: &[(f64, [f64; 3], &str, f64)], env: &[(&str, &str)]) {
    let mut report = Vec::new();
    for &(spin, at, observer, vfov) in cameras {
        let toml = format!(
            "[[black_hole]]\nspin = {spin}\n[camera]\nposition = [{}, {}, {}]\nvfov_deg = {vfov}\nobserver = \"{observer}\"\nup = [0.1, 1.0, 0.0]\n[disk]\nkind = \"volumetric\"\nheight = 0.002\ninner_radius = {}\nouter_radius = 12.0\n[polarization]\nfield = [0.3, 0.6, 0.7]\n",
            at[0],
            at[1],
            at[2],
            kerr::r_isco(spin) / 2.0
        );
        let mut f = compare(&toml, env, true);
        let (angle, fraction) = (p99(&mut f.angle), p99(&mut f.intensity));
        report.push(format!(
            "{env:?} slab, spin {spin} {at:?} {observer}: {} rays, {} edges, {} depolarized, angle p99 {angle:.2e} rad, P / I p99 {fraction:.2e}",
            f.compared, f.edges, f.depolarized
        ));
        assert!(f.compared > 20, "{}", report.join("\n"));
        // (Two crossings' light: the rays near the shadow whose path
        // crosses the annulus again, a ring of the image.)
        assert!(
            f.edges * 20 <= f.compared && f.depolarized * 6 <= f.compared,
            "{}",
            report.join("\n")
        );
        assert!(angle <= 1e-4 && fraction <= 1e-3, "{}", report.join("\n"));
    }
    println!("{}", report.join("\n"));
}

/// The volumetric disk off the equator, on the GPU: in a slab 0.5 rs
/// thick each ray's summed electric vector lies among those the transport
/// finds where its path crosses seven planes through the slab (from -H to
/// H), within 2e-4 rad, for all but 1 % of the rays whose light is of one
/// crossing (one sample's own
/// exactness off the equator is src/physics/kerr/transport/tests.rs's, to
/// 1e-6 rad).
fn check_thick_slab(cameras: &[(f64, [f64; 3], &str, f64)], env: &[(&str, &str)]) {
    const SW: u32 = 24;
    const SH: u32 = 14;
    let half = 0.25;
    let mut report = Vec::new();
    for &(spin, at, observer, vfov) in cameras {
        let toml = format!(
            "[[black_hole]]\nspin = {spin}\n[camera]\nposition = [{}, {}, {}]\nvfov_deg = {vfov}\nobserver = \"{observer}\"\nup = [0.1, 1.0, 0.0]\n[disk]\nkind = \"volumetric\"\nheight = {half}\ninner_radius = {}\nouter_radius = 12.0\n[polarization]\nfield = [0.3, 0.6, 0.7]\n",
            at[0],
            at[1],
            at[2],
            kerr::r_isco(spin) / 2.0
        );
        let (scene, gpu) = common::render_aov_named("stokes", &toml, SW, SH, env);
        let frame = scene.camera.frame();
        let kind = match observer {
            "zamo" => KerrObserver::Zamo,
            _ => KerrObserver::Static,
        };
        let beta = if spin == 0.0 {
            let holes = [blackhole::physics::Hole {
                position: DVec3::ZERO,
                rs: 1.0,
            }];
            Observer::new(
                scene.camera.observer,
                frame.position,
                &holes,
                DVec3::Y,
                true,
            )
            .beta
        } else {
            kerr::observer_velocity(kind, 2.0 * frame.position, spin).expect("placed")
        };
        let disk = KerrDisk {
            inner: scene.disk.inner_radius,
            outer: scene.disk.outer_radius,
        };
        let em = scene.emission();
        let (mut compared, mut outside, mut other, mut worst) = (0, 0, 0, 0.0f64);
        let mut widths = Vec::new();
        for y in 0..SH {
            for x in 0..SW {
                let p = gpu.get_pixel(x, y).0.map(f64::from);
                let got = Stokes {
                    i: p[0],
                    q: p[1],
                    u: p[2],
                    v: p[3],
                };
                let Some(d) = frame.ray_dir(x, y, SW, SH) else {
                    continue;
                };
                if got.i <= 0.0 {
                    continue;
                }
                let planes: Option<Vec<Stokes>> = (0..7)
                    .map(|k| {
                        let z = 2.0 * half * (f64::from(k) / 3.0 - 1.0);
                        kerr::transport::volume_sample_transported(
                            frame.position,
                            d,
                            frame.up,
                            spin,
                            beta,
                            z,
                            disk,
                            &em,
                        )
                        .map(|s| s.stokes)
                    })
                    .collect();
                let Some(planes) = planes else {
                    continue; // a path that does not cross the whole slab
                };
                let mid = planes[3].angle();
                let turn = |chi: f64| {
                    let t = 2.0 * (chi - mid);
                    t.sin().atan2(t.cos()) / 2.0
                };
                let (lo, hi) = planes
                    .iter()
                    .map(|s| turn(s.angle()))
                    .fold((0.0f64, 0.0f64), |(lo, hi), t| (lo.min(t), hi.max(t)));
                // Light whose angles all lie within hi - lo of each other
                // keeps P / I >= fraction cos(hi - lo); below that some of
                // it comes from elsewhere: another crossing's window (the
                // rays over the shadow pass the slab in front of the hole
                // and again behind it, under it: the gas is transparent),
                // counted, not compared; at most a quarter.
                if got.polarized() < em.fraction * (hi - lo).cos() * (1.0 - 1e-4) * got.i {
                    other += 1;
                    continue;
                }
                let g = turn(got.angle());
                widths.push(hi - lo);
                let excess = (lo - g).max(g - hi).max(0.0);
                worst = worst.max(excess);
                compared += 1;
                if excess > 2e-4 {
                    outside += 1;
                }
            }
        }
        widths.sort_by(f64::total_cmp);
        let width = widths.get(widths.len() / 2).copied().unwrap_or(0.0);
        report.push(format!(
            "{env:?} thick slab, spin {spin} {at:?} {observer}: {compared} rays ({other} with other light), the planes' angles {width:.2e} rad apart (median), {outside} outside them by over 2e-4 rad (worst {worst:.2e})"
        ));
        assert!(compared > 40, "{}", report.join("\n"));
        assert!(
            outside * 100 <= compared && other * 4 <= compared,
            "{}",
            report.join("\n")
        );
    }
    println!("{}", report.join("\n"));
}

/// Run by tests/device.rs (the spinning hole's 64-bit build).
pub fn gpu_stokes_of_a_thick_volumetric_slab_lies_among_its_transported_planes() {
    check_thick_slab(
        &[
            (0.9, [2.0, 3.0, -14.0], "zamo", 50.0),
            (0.0, [1.0, 2.0, -15.0], "static", 50.0),
        ],
        &[],
    );
}

/// The non-rotating hole's own 32-bit form (`BLACKHOLE_NO_F64=1`).
#[test]
fn gpu_stokes_of_a_thick_volumetric_slab_in_32_bits_lies_among_its_transported_planes() {
    check_thick_slab(
        &[(0.0, [1.0, 2.0, -15.0], "static", 50.0)],
        &[("BLACKHOLE_NO_F64", "1")],
    );
}
