//! A camera falling through a non-rotating hole's horizon, on the GPU,
//! against the independent f64 reference: the light paths integrated step by
//! step in Painleve-Gullstrand coordinates from the metric alone
//! (physics/river.rs), ray by ray. Outcomes must agree away from edges;
//! escape direction, disk radius and g within 1e-5 rad, 2e-4 rs and 1e-5
//! (p99), over the rays that a 1e-7 rad nudge of the pixel direction (the
//! f32 pixel direction's own error) leaves in place, judged on the f64
//! closed form (which the reference meets to 1e-12: physics/river.rs).
//! Then the images through the crossing: no jump at the horizon.

mod common;

use blackhole::physics::closed_form::trace_closed;
use blackhole::physics::geodesic::{Disk, Hole, Outcome};
use blackhole::physics::observer::{Observer, ObserverKind};
use blackhole::physics::river::{RiverDisk, RiverOutcome, trace_rain_to};
use common::{refused_early, render_scene, scratch};
use glam::DVec3;

const DIR_TOL: f64 = 1e-5;
const RADIUS_TOL: f64 = 2e-4;
const G_TOL: f64 = 1e-5;
const W: u32 = 48;
const H: u32 = 27;
const INNER: f64 = 3.0;
const OUTER: f64 = 12.0;

fn p99(v: &mut [f64]) -> f64 {
    if v.is_empty() {
        return 0.0;
    }
    v.sort_by(f64::total_cmp);
    v[((0.99 * v.len() as f64).ceil() as usize).clamp(1, v.len()) - 1]
}

/// The reference's record of a ray as the AOV's four numbers.
fn aov_of(o: RiverOutcome) -> [f64; 4] {
    match o {
        RiverOutcome::Escaped(d) => [d.x, d.y, d.z, 0.0],
        RiverOutcome::Captured => [0.0, 0.0, 0.0, 1.0],
        RiverOutcome::Disk { r, phi, g } => [r, phi, g, 2.0],
        RiverOutcome::NoSteps => [0.0, 0.0, 0.0, 3.0],
        RiverOutcome::OtherUniverse => [0.0, 0.0, 0.0, 5.0],
    }
}

/// The f64 closed form's record through the observer's rain form (outcome
/// 5: the other universe; a disk hit's g is not needed here), for the
/// conditioning of a pixel.
fn closed_form(obs: &Observer, x0: DVec3, d: DVec3) -> [f64; 4] {
    if obs.energy(d) <= 0.0 {
        return [0.0, 0.0, 0.0, 5.0];
    }
    let hole = Hole {
        position: DVec3::ZERO,
        rs: 1.0,
    };
    let disk = Disk {
        normal: DVec3::Y,
        inner: INNER,
        outer: OUTER,
    };
    match trace_closed(&hole, Some(&disk), x0, obs.coordinate_direction(d)) {
        Outcome::Escaped { direction: e } => [e.x, e.y, e.z, 0.0],
        Outcome::Disk { position, .. } => [position.length(), 0.0, 0.0, 2.0],
        _ => [0.0, 0.0, 0.0, 1.0],
    }
}

/// How far two records are apart, in units of their tolerances (the escape
/// direction by its angle; a disk hit by its radius), or infinity where
/// the outcomes differ.
fn distance(a: [f64; 4], b: [f64; 4]) -> f64 {
    if a[3] != b[3] {
        return f64::INFINITY;
    }
    match a[3] as u32 {
        0 => angle(a, b) / DIR_TOL,
        2 => (a[0] - b[0]).abs() / RADIUS_TOL,
        _ => 0.0,
    }
}

fn angle(a: [f64; 4], b: [f64; 4]) -> f64 {
    let (x, y) = (DVec3::new(a[0], a[1], a[2]), DVec3::new(b[0], b[1], b[2]));
    2.0 * (0.5 * (x - y).length()).min(1.0).asin()
}

struct Figures {
    rays: usize,
    ill_conditioned: usize,
    /// escaped, captured, disk, other universe
    outcomes: [usize; 4],
    dir: Vec<f64>,
    radius: Vec<f64>,
    g: Vec<f64>,
}

fn compare(position: [f64; 3], look_at: [f64; 3]) -> Figures {
    let (scene, gpu) = common::render_aov(
        &format!(
            "[camera]\nposition = {position:?}\nlook_at = {look_at:?}\nvfov_deg = 80.0\nobserver = \"falling\"\n[disk]\ninner_radius = {INNER}\nouter_radius = {OUTER}\n"
        ),
        W,
        H,
    );
    let frame = scene.camera.frame();
    let x0 = frame.position;
    let hole = Hole {
        position: DVec3::ZERO,
        rs: 1.0,
    };
    let obs = Observer::new(ObserverKind::Falling, x0, &[hole], DVec3::Y, true);
    let disk = Some(RiverDisk {
        inner: INNER,
        outer: OUTER,
    });
    let mut f = Figures {
        rays: 0,
        ill_conditioned: 0,
        outcomes: [0; 4],
        dir: Vec::new(),
        radius: Vec::new(),
        g: Vec::new(),
    };
    for y in 0..H {
        for x in 0..W {
            let d = frame.ray_dir(x, y, W, H).expect("a pinhole ray");
            let p = gpu.get_pixel(x, y).0.map(f64::from);
            f.rays += 1;
            assert!(
                p.iter().all(|v| v.is_finite()),
                "{position:?} pixel ({x}, {y}): GPU {p:?}"
            );
            // The ray's sensitivity to the f32 pixel direction's error.
            let here = closed_form(&obs, x0, d);
            let (u, v) = (frame.right, frame.up);
            let turns = [u, -u, v, -v];
            let turned = turns
                .iter()
                .map(|n| distance(here, closed_form(&obs, x0, (d + 1e-7 * *n).normalize())));
            // And to the f32 camera position's (near the horizon the view
            // changes fast with r).
            let scales = [1.0 - 1e-7, 1.0 + 1e-7];
            let moved = scales.iter().map(|s| {
                let at = x0 * *s;
                let o = Observer::new(ObserverKind::Falling, at, &[hole], DVec3::Y, true);
                distance(here, closed_form(&o, at, d))
            });
            let nudge = turned.chain(moved).fold(0.0, f64::max);
            if nudge > 0.25 {
                f.ill_conditioned += 1;
                continue;
            }
            let want = aov_of(trace_rain_to(1.0, x0, d, disk));
            assert_eq!(
                p[3], want[3],
                "{position:?} pixel ({x}, {y}): GPU {p:?} vs reference {want:?}"
            );
            f.outcomes[match want[3] as u32 {
                0 => 0,
                1 => 1,
                2 => 2,
                _ => 3,
            }] += 1;
            match want[3] as u32 {
                0 => f.dir.push(angle(p, want)),
                2 => {
                    f.radius.push((p[0] - want[0]).abs());
                    f.g.push((p[2] - want[2]).abs());
                }
                _ => {}
            }
        }
    }
    f
}

/// Cameras falling at and through the horizon down to the closest one may
/// come, each looking across the disk's plane at the sky, the shadow, the
/// disk's lensed ring and (inside) the other universe below.
#[test]
fn gpu_interior_aov_matches_the_integrated_reference() {
    let at = |r: f64| [0.0, 0.3 * r, -r * 0.91f64.sqrt()];
    for (r, look_at) in [
        (2.5, [0.0, 0.0, 0.0]),
        (1.02, [0.0, -0.5, 3.0]),
        (1.0 + 1e-3, [0.0, -0.5, 3.0]),
        (1.0 - 1e-3, [0.0, -0.5, 3.0]),
        (0.5, [0.0, -1.0, 4.0]),
        (0.5, [3.0, 0.2, 0.0]),
        (0.1, [3.0, 0.0, 0.0]),
        (0.05, [3.0, 0.0, 0.0]),
    ] {
        let mut f = compare(at(r), look_at);
        let (dir, radius, g) = (p99(&mut f.dir), p99(&mut f.radius), p99(&mut f.g));
        println!(
            "falling r {r:6} rs, looking at {look_at:?}: rays {} (ill-conditioned {}), escaped/captured/disk/other {:?}: escape dir p99 {dir:.2e} rad, disk radius p99 {radius:.2e} rs, g p99 {g:.2e}",
            f.rays, f.ill_conditioned, f.outcomes
        );
        assert!(
            dir <= DIR_TOL && radius <= RADIUS_TOL && g <= G_TOL,
            "r {r}: {dir:e} {radius:e} {g:e}"
        );
        assert!(
            f.outcomes[0] > 0 && f.outcomes[1] + f.outcomes[3] > 0,
            "r {r}: {:?}",
            f.outcomes
        );
        if r < 0.6 {
            assert!(f.outcomes[2] > 0, "r {r}: no disk seen: {:?}", f.outcomes);
        }
    }
}

/// How far apart two AOVs of the same view are: the mean angle between the
/// escape directions of the pixels that escape in both, and the fraction of
/// pixels whose outcome differs.
fn aov_change(a: &image::Rgba32FImage, b: &image::Rgba32FImage) -> (f64, f64) {
    let (mut sum, mut both, mut differ) = (0.0, 0usize, 0usize);
    for (p, q) in a.pixels().zip(b.pixels()) {
        let (p, q) = (p.0.map(f64::from), q.0.map(f64::from));
        if p[3] != q[3] {
            differ += 1;
        } else if p[3] == 0.0 {
            sum += angle(p, q);
            both += 1;
        }
    }
    (
        sum / both.max(1) as f64,
        differ as f64 / a.pixels().len() as f64,
    )
}

/// The image is continuous through the crossing: frames at rs (1 + 1e-3)
/// and rs (1 - 1e-3) differ no more than two frames 2e-3 rs apart just
/// outside do (printed beside a pair at 1.1 rs for scale): the same closed
/// form on both sides, nothing special at r = rs.
#[test]
fn frames_through_the_crossing_change_as_frames_outside_do() {
    let aov = |r: f64| {
        let at = [0.0, 0.3 * r, -r * 0.91f64.sqrt()];
        common::render_aov(
            &format!(
                "[camera]\nposition = {at:?}\nlook_at = [3.0, 0.0, 0.0]\nvfov_deg = 90.0\nobserver = \"falling\"\n"
            ),
            96,
            54,
        )
        .1
    };
    let farther = aov_change(&aov(1.101), &aov(1.099));
    println!("at 1.1 rs {farther:?}");
    assert_continuous(&aov);
}

/// Frames of `aov` (a view at a fraction of the horizon's radius) at 1 +-
/// 1e-3 differ no more than frames at 1.005 and 1.003 do (mean escape
/// direction, and outcomes but for two pixels).
fn assert_continuous(aov: &dyn Fn(f64) -> image::Rgba32FImage) {
    let across = aov_change(&aov(1.0 + 1e-3), &aov(1.0 - 1e-3));
    let outside = aov_change(&aov(1.005), &aov(1.003));
    println!(
        "mean escape-direction change and outcome changes: across the horizon {across:?}, \
         just outside {outside:?}"
    );
    assert!(across.0 > 0.0, "the frames did not change at all");
    assert!(
        across.0 <= 1.5 * outside.0 && across.1 <= 1.5 * outside.1 + 2.0 / (96.0 * 54.0),
        "across {across:?} against outside {outside:?}"
    );
}

/// The same through a spinning hole's outer horizon (a* = 0.9): frames at
/// r+ (1 +- 1e-3) differ no more than two frames 2e-3 r+ apart just
/// outside; a hair (1e-8 r+) to either side every pixel a number. And where
/// the camera's frame changes hands, at 1.05 r+ (outside it the ZAMO's
/// aberrated by the fall, inside it the falling frame built from the metric,
/// the azimuth in ingoing form), frames 2e-4 r+ apart across it differ no
/// more than two such frames beside it.
#[test]
fn frames_through_a_spinning_horizon_change_as_frames_outside_do() {
    let (spin, a) = (0.9f64, 0.45f64);
    let r_plus = 0.5 * (1.0 + (1.0 - spin * spin).sqrt());
    let n = DVec3::new(0.0, 0.3, -0.91f64.sqrt());
    let aov = |f: f64| {
        // Boyer-Lindquist r = f r+ on the line n: rho^2 = r^2 + a^2 sin^2.
        let r = f * r_plus;
        let rho = ((r * r + a * a) / (1.0 + a * a * n.y * n.y / (r * r))).sqrt();
        let at = (rho * n).to_array();
        common::render_aov(
            &format!(
                "[[black_hole]]\nspin = {spin}\n[camera]\nposition = {at:?}\nlook_at = [3.0, 0.0, 0.0]\nvfov_deg = 90.0\nobserver = \"falling\"\n"
            ),
            96,
            54,
        )
        .1
    };
    assert_continuous(&aov);
    // A hair from r+ on either side (1e-8, where the ZAMO's frame once gave
    // every pixel NaN): every pixel a number, and the two frames alike.
    let (outer, inner) = (aov(1.0 + 1e-8), aov(1.0 - 1e-8));
    for (hair, side) in [(&outer, "outside"), (&inner, "inside")] {
        assert!(
            hair.pixels().all(|p| p.0.iter().all(|v| v.is_finite())),
            "1e-8 r+ {side}: a pixel is not a number"
        );
    }
    let hair = aov_change(&outer, &inner);
    assert!(hair.0 < 1e-4 && hair.1 <= 2.0 / (96.0 * 54.0), "{hair:?}");
    let band = 1.0 + blackhole::physics::kerr::FALLING_FRAME_BAND;
    let across = aov_change(&aov(band - 1e-4), &aov(band + 1e-4));
    let beside = aov_change(&aov(band + 3e-4), &aov(band + 5e-4));
    println!("across the band's edge {across:?}, beside it {beside:?}");
    assert!(
        across.0 <= 1.5 * beside.0 + 1e-5 && across.1 <= 1.5 * beside.1 + 2.0 / (96.0 * 54.0),
        "across {across:?} against beside {beside:?}"
    );
}

/// Light from the other universe is black by default; `[sky] other_universe
/// = "mirror"` follows its path on to that universe's infinity (the same
/// closed form: the orbit's shape knows only b) and shows a copy of the sky
/// there, ringed by the black of paths from its white hole. The AOV stays
/// outcome 5 either way.
#[test]
fn the_other_universe_is_black_or_a_mirror_sky() {
    let dir = scratch();
    let toml = |other: &str| {
        format!(
            "[camera]\nposition = [0.0, 0.0, -0.5]\nlook_at = [0.0, 0.0, 0.0]\nobserver = \"falling\"\nprojection = \"fisheye\"\nvfov_deg = 200.0\n[disk]\nkind = \"none\"\n[sky]\nkind = \"checker\"\nother_universe = \"{other}\"\n"
        )
    };
    let middle = |img: &image::RgbImage| {
        let p = img.get_pixel(32, 32);
        f64::from(p[0].max(p[1]).max(p[2])) / 255.0
    };
    let black = common::render_png(
        &dir,
        "black",
        common::SceneSrc::Toml(&toml("black")),
        64,
        64,
    );
    let mirror = common::render_png(
        &dir,
        "mirror",
        common::SceneSrc::Toml(&toml("mirror")),
        64,
        64,
    );
    assert!(middle(&black) < 0.01, "{}", middle(&black));
    assert!(middle(&mirror) > 0.2, "{}", middle(&mirror));
    for other in ["black", "mirror"] {
        let (_, aov) = common::render_aov(&toml(other), 16, 16);
        assert_eq!(aov.get_pixel(8, 8).0, [0.0, 0.0, 0.0, 5.0], "{other}");
    }
}

// ---------------------------------------------------------------- placement

#[test]
fn a_falling_camera_a_hair_from_the_horizon_draws_and_one_at_the_centre_is_refused() {
    // On either side of the horizon, 1e-8 rs from it: every pixel a
    // number (the rain form has no Lorentz factor to blow up).
    for z in ["-1.00000001", "-0.99999999", "-1.0"] {
        let (_, aov) = common::render_aov(
            &format!("[camera]\nobserver = \"falling\"\nposition = [0.0, 0.0, {z}]\n"),
            32,
            18,
        );
        assert!(
            aov.pixels().all(|p| p.0.iter().all(|v| v.is_finite())),
            "z {z}: a pixel is not a number"
        );
    }
    let dir = scratch();
    let c = render_scene(
        &dir,
        "[camera]\nobserver = \"falling\"\nposition = [0.0, 0.0, -0.01]\n",
        &[],
    );
    let e = refused_early(c);
    assert!(
        e.contains("camera.position") && e.contains("0.05 rs") && e.contains("singularity"),
        "{e}"
    );
}

#[test]
fn inside_a_horizon_only_a_falling_camera_of_one_hole_is_let_in() {
    let dir = scratch();
    for (toml, words) in [
        (
            "[camera]\nposition = [0.0, 0.0, -0.5]\n",
            &["camera.position", "horizon", "\"falling\""][..],
        ),
        (
            "[camera]\nobserver = \"zamo\"\nposition = [0.0, 0.3, -0.5]\n",
            &["camera.position", "\"falling\""][..],
        ),
        (
            "[camera]\nobserver = \"falling\"\nposition = [0.0, 0.0, -0.5]\n[[black_hole]]\nposition = [0.0, 0.0, 0.0]\n[[black_hole]]\nposition = [30.0, 0.0, 0.0]\n",
            &["camera.position", "black_hole[0]", "several holes"][..],
        ),
        (
            "[camera]\nobserver = \"falling\"\nposition = [0.0, 0.0, -0.5]\n[physics]\ngravity = false\n",
            &["camera.position", "gravity off"][..],
        ),
    ] {
        let e = refused_early(render_scene(&dir, toml, &[]));
        assert!(words.iter().all(|w| e.contains(w)), "{toml}: {e}");
    }
    assert!(std::fs::read_dir(dir.path()).expect("listing").count() == 1);
}
