//! The cameras beyond the pinhole: the equirectangular panorama, the
//! equidistant fisheye (a dome master) and omni-directional stereo. With
//! gravity off the geodesic AOV must reproduce the binding projection
//! formulas ray by ray (directions to 1e-5 rad; the ODS eyes' origins through
//! where their straight rays meet the disk); with gravity on the two ODS
//! eyes see the shadow displaced the way parallax says. The formulas are
//! written out here again from the convention, not taken from src/camera.

mod common;

use std::f64::consts::{FRAC_PI_2, PI};

use common::{SceneSrc, path_in, render_aov, render_png, scratch};
use glam::DVec3;

const DIR_TOL: f64 = 1e-5;

/// The camera frame by the binding convention.
struct Frame {
    pos: DVec3,
    fwd: DVec3,
    right: DVec3,
    up: DVec3,
}

fn frame(pos: [f64; 3], look_at: [f64; 3]) -> Frame {
    let pos = DVec3::from(pos);
    let fwd = (DVec3::from(look_at) - pos).normalize();
    let right = DVec3::Y.cross(fwd).normalize();
    Frame {
        pos,
        fwd,
        right,
        up: fwd.cross(right),
    }
}

/// Equirect pixel (c, r) of a W x H panorama (one eye's rows for ODS):
/// (origin offset factor along the viewing circle, direction).
fn equirect(f: &Frame, c: u32, r: u32, w: u32, h: u32) -> (DVec3, DVec3) {
    let lon = (2.0 * (f64::from(c) + 0.5) / f64::from(w) - 1.0) * PI;
    let lat = (1.0 - 2.0 * (f64::from(r) + 0.5) / f64::from(h)) * FRAC_PI_2;
    let dir = lat.cos() * lon.sin() * f.right + lat.sin() * f.up + lat.cos() * lon.cos() * f.fwd;
    let circle = lon.cos() * f.right - lon.sin() * f.fwd;
    (circle, dir)
}

/// Fisheye pixel (c, r): the direction, or None outside the image circle.
fn fisheye(f: &Frame, c: u32, r: u32, w: u32, h: u32, vfov_deg: f64) -> Option<DVec3> {
    let s = f64::from(w.min(h));
    let x = (2.0 * (f64::from(c) + 0.5) - f64::from(w)) / s;
    let y = (f64::from(h) - 2.0 * (f64::from(r) + 0.5)) / s;
    let rho = x.hypot(y);
    if rho > 1.0 {
        return None;
    }
    let theta = rho * vfov_deg.to_radians() / 2.0;
    Some(theta.cos() * f.fwd + theta.sin() * (x / rho * f.right + y / rho * f.up))
}

fn angle(a: DVec3, b: DVec3) -> f64 {
    2.0 * (0.5 * (a.normalize() - b.normalize()).length())
        .min(1.0)
        .asin()
}

/// Where a straight ray first passes within `rs` of the origin (the hole),
/// if it does: closest approach distance and whether it is ahead.
fn closest_approach(o: DVec3, d: DVec3) -> (f64, bool) {
    let t = -o.dot(d);
    ((o + t.max(0.0) * d).length(), t > 0.0)
}

/// Checks an AOV pixel against a straight ray from `o` along `d` (gravity
/// off: escaped along d unless it meets the unit horizon). Returns the
/// direction error, or None where the ray grazes the horizon.
fn check_straight(px: [f32; 4], o: DVec3, d: DVec3, at: (u32, u32)) -> Option<f64> {
    let (dist, ahead) = closest_approach(o, d);
    if (dist - 1.0).abs() < 1e-3 {
        return None;
    }
    let captured = ahead && dist < 1.0;
    let want = if captured { 1.0 } else { 0.0 };
    assert_eq!(f64::from(px[3]), want, "pixel {at:?}: outcome");
    if captured {
        return Some(0.0);
    }
    let got = DVec3::new(f64::from(px[0]), f64::from(px[1]), f64::from(px[2]));
    Some(angle(got, d))
}

#[test]
fn with_gravity_off_the_aov_reproduces_the_panorama_and_the_dome_ray_by_ray() {
    // Equirect: the whole sphere, the hole ahead (its straight-line shadow
    // shows as captured rays).
    let (w, h) = (96, 48);
    let (_, aov) = render_aov(
        "[physics]\ngravity = false\n[disk]\nkind = \"none\"\n[camera]\nposition = [0.0, 0.8, -15.0]\nprojection = \"equirect\"\n",
        w,
        h,
    );
    let f = frame([0.0, 0.8, -15.0], [0.0; 3]);
    let mut worst: f64 = 0.0;
    let mut captured = 0;
    for r in 0..h {
        for c in 0..w {
            let (_, d) = equirect(&f, c, r, w, h);
            let px = aov.get_pixel(c, r).0;
            if let Some(e) = check_straight(px, f.pos, d, (c, r)) {
                worst = worst.max(e);
                captured += usize::from(px[3] == 1.0);
            }
        }
    }
    println!("equirect {w}x{h}: worst direction error {worst:.2e} rad, {captured} captured");
    assert!(worst < DIR_TOL, "equirect: {worst:.3e} rad");
    assert!(captured > 0, "the hole ahead is in the panorama");
    // The pixel behind the camera (the left and right edges) looks back.
    let back = aov.get_pixel(0, h / 2).0;
    assert!(
        f64::from(back[2]) < -0.99,
        "the left edge looks backward: {back:?}"
    );

    // Fisheye, 220 degrees across its circle, on a wider than tall image:
    // the circle is inscribed in the height, and outside it there is no ray
    // (outcome 4).
    let (w, h) = (64, 40);
    let (_, aov) = render_aov(
        "[physics]\ngravity = false\n[disk]\nkind = \"none\"\n[camera]\nposition = [0.0, -12.0, -3.0]\nprojection = \"fisheye\"\nvfov_deg = 220.0\n",
        w,
        h,
    );
    let f = frame([0.0, -12.0, -3.0], [0.0; 3]);
    let (mut worst, mut none, mut rays): (f64, usize, usize) = (0.0, 0, 0);
    for r in 0..h {
        for c in 0..w {
            let px = aov.get_pixel(c, r).0;
            match fisheye(&f, c, r, w, h, 220.0) {
                None => {
                    assert_eq!(px, [0.0, 0.0, 0.0, 4.0], "pixel ({c}, {r}) has no ray");
                    none += 1;
                }
                Some(d) => {
                    rays += 1;
                    if let Some(e) = check_straight(px, f.pos, d, (c, r)) {
                        worst = worst.max(e);
                    }
                }
            }
        }
    }
    println!("fisheye {w}x{h}: worst direction error {worst:.2e} rad, {rays} rays, {none} without");
    assert!(worst < DIR_TOL, "fisheye: {worst:.3e} rad");
    // The circle of radius 20 pixels: pi 20^2 = 1257 of the 2560 pixels.
    assert!(
        (1200..1320).contains(&rays) && none == 2560 - rays,
        "{rays} rays, {none} without"
    );
}

#[test]
fn with_gravity_off_each_ods_eye_starts_on_its_viewing_circle() {
    // Both eyes over a thin disk, no gravity: each downward ray meets the
    // disk's plane where a straight line from its eye's place meets it, so
    // the AOV's radius and azimuth there pin the origin (the direction alone
    // would not tell the eyes apart).
    let (w, h) = (64, 64);
    let ipd = 0.6;
    let toml = format!(
        "[physics]\ngravity = false\n[disk]\ninner_radius = 2.0\nouter_radius = 30.0\n[camera]\nposition = [1.0, 3.0, -6.0]\nlook_at = [1.0, 3.0, 0.0]\nprojection = \"equirect\"\nstereo = \"ods\"\nipd = {ipd}\n"
    );
    let (_, aov) = render_aov(&toml, w, h);
    let f = frame([1.0, 3.0, -6.0], [1.0, 3.0, 0.0]);
    let eye_h = h / 2;
    let (mut worst_dir, mut worst_r, mut worst_phi): (f64, f64, f64) = (0.0, 0.0, 0.0);
    let mut hits = [0usize; 2];
    let mut shift: f64 = 0.0;
    for r in 0..h {
        let (eye, er) = if r < eye_h {
            (-1.0, r)
        } else {
            (1.0, r - eye_h)
        };
        for c in 0..w {
            let (circle, d) = equirect(&f, c, er, w, eye_h);
            let o = f.pos + eye * 0.5 * ipd * circle;
            let px = aov.get_pixel(c, r).0;
            // Where the straight line meets the plane y = 0.
            let t = -o.y / d.y;
            let p = o + t * d;
            let radius = p.length();
            let on_disk = d.y < -0.05 && radius > 2.2 && radius < 28.0;
            if on_disk && closest_approach(o, d).0 > 1.001 {
                assert_eq!(px[3], 2.0, "eye {eye} pixel ({c}, {er}) hits the disk");
                hits[usize::from(eye > 0.0)] += 1;
                worst_r = worst_r.max((f64::from(px[0]) - radius).abs() / radius);
                let dphi = f64::from(px[1]) - p.z.atan2(p.x);
                worst_phi = worst_phi.max(((dphi + PI).rem_euclid(2.0 * PI) - PI).abs());
                // The other eye's hit, for the size of the parallax.
                let other = f.pos - eye * 0.5 * ipd * circle;
                shift = shift.max((other + (-other.y / d.y) * d - p).length());
            } else if d.y > 0.05 && closest_approach(o, d).0 > 1.001 {
                let got = DVec3::new(f64::from(px[0]), f64::from(px[1]), f64::from(px[2]));
                assert_eq!(px[3], 0.0, "eye {eye} pixel ({c}, {er}) escapes");
                worst_dir = worst_dir.max(angle(got, d));
            }
        }
    }
    println!(
        "ODS {w}x{h}: disk hits {hits:?}, radius error {worst_r:.2e} (relative), azimuth {worst_phi:.2e} rad, direction {worst_dir:.2e} rad; the eyes' hits up to {shift:.3} rs apart"
    );
    assert!(hits[0] > 50 && hits[1] > 50, "{hits:?}");
    assert!(worst_dir < DIR_TOL, "{worst_dir:.3e} rad");
    // The eyes' hit points differ by up to `shift`; an origin off by a
    // tenth of the eye's offset would move them by far more than this.
    assert!(shift > 0.3, "the test cannot tell the eyes apart: {shift}");
    assert!(
        worst_r < 2e-5 && worst_phi < 2e-5,
        "{worst_r:.3e} {worst_phi:.3e}"
    );
}

#[test]
fn the_ods_eyes_see_the_shadow_with_parallax_of_the_right_sign() {
    // A hole straight ahead at 6 rs with gravity on: the left eye (top
    // half) sits ipd / 2 to the left, so the hole appears to its right, and
    // to the right eye's left. The shift is about atan(ipd / 2 / r) each.
    let (w, h) = (512, 256);
    let ipd: f64 = 0.4;
    let r: f64 = 6.0;
    let (_, aov) = render_aov(
        &format!(
            "[disk]\nkind = \"none\"\n[camera]\nposition = [0.0, 0.0, -{r}]\nprojection = \"equirect\"\nstereo = \"ods\"\nipd = {ipd}\n"
        ),
        w,
        h,
    );
    let eye_h = h / 2;
    let centroid = |rows: std::ops::Range<u32>| {
        let (mut sum, mut n) = (0.0, 0.0);
        for y in rows {
            for x in 0..w {
                if aov.get_pixel(x, y).0[3] == 1.0 {
                    sum += f64::from(x) + 0.5;
                    n += 1.0;
                }
            }
        }
        assert!(n > 100.0, "a shadow in each eye: {n} pixels");
        sum / n
    };
    let left = centroid(0..eye_h);
    let right = centroid(eye_h..h);
    let per_px = 2.0 * PI / f64::from(w);
    let expected = 2.0 * (0.5 * ipd / r).atan() / per_px;
    println!(
        "ODS parallax at {r} rs, ipd {ipd}: shadow centroid column left eye {left:.2}, right eye {right:.2} (difference {:.2} px, straight-line estimate {expected:.2})",
        left - right
    );
    assert!(
        left > f64::from(w) / 2.0 && right < f64::from(w) / 2.0,
        "{left} {right}"
    );
    let diff = left - right;
    assert!(
        diff > 0.5 * expected && diff < 2.0 * expected,
        "parallax {diff:.2} px against about {expected:.2}"
    );
}

#[test]
fn a_dome_master_is_black_and_transparent_outside_its_circle() {
    let dir = scratch();
    let toml =
        "[camera]\nposition = [0.0, -12.0, -3.0]\nprojection = \"fisheye\"\nvfov_deg = 180.0\n";
    let _ = render_png(&dir, "dome", SceneSrc::Toml(toml), 96, 64);
    let img = image::open(path_in(&dir, "dome.png"))
        .expect("PNG")
        .to_rgba8();
    // Corners: no ray, transparent black; the centre: opaque.
    for (x, y) in [(0, 0), (95, 0), (0, 63), (95, 63), (5, 32), (90, 32)] {
        assert_eq!(img.get_pixel(x, y).0, [0, 0, 0, 0], "({x}, {y})");
    }
    assert_eq!(img.get_pixel(48, 32).0[3], 255);
    // Inside the circle the disk, seen from below, is bright somewhere.
    let bright = (16..80)
        .flat_map(|x| (0..64).map(move |y| (x, y)))
        .filter(|&(x, y)| img.get_pixel(x, y).0[0] > 100)
        .count();
    assert!(
        bright > 50,
        "the disk shows inside the dome: {bright} bright pixels"
    );
}

/// The sky's light (radiance times each pixel's solid angle) summed over a
/// cone around `axis`, with a smooth edge (full weight inside 14 degrees,
/// none beyond 20) so stars astride the edge count alike in every image.
fn flux_in_cone(
    img: &image::Rgba32FImage,
    dir_and_solid_angle: impl Fn(u32, u32) -> Option<(DVec3, f64)>,
    axis: DVec3,
) -> f64 {
    let (inner, outer) = (14f64.to_radians(), 20f64.to_radians());
    let mut sum = 0.0;
    for (x, y, p) in img.enumerate_pixels() {
        let Some((d, omega)) = dir_and_solid_angle(x, y) else {
            continue;
        };
        let a = angle(d, axis);
        let w = if a <= inner {
            1.0
        } else if a >= outer {
            0.0
        } else {
            0.5 + 0.5 * (PI * (a - inner) / (outer - inner)).cos()
        };
        let l = 0.2126 * f64::from(p[0]) + 0.7152 * f64::from(p[1]) + 0.0722 * f64::from(p[2]);
        sum += w * l * omega;
    }
    sum
}

#[test]
fn the_catalogue_stars_keep_their_flux_in_every_projection() {
    // No gravity, no disk: the same piece of the real sky through a pinhole
    // (60 degrees), a dome (180 degrees) and a panorama, each pixel weighted
    // by its own solid angle. The stars are drawn with footprints from their
    // neighbours' directions, so each star's light must come out the same
    // whatever the projection makes of its pixels.
    let dir = scratch();
    let base = "[physics]\ngravity = false\n[disk]\nkind = \"none\"\n[sky]\nkind = \"catalogue\"\ngalaxy = 0.0\n[camera]\nposition = [0.0, 0.0, -40.0]\nlook_at = [-30.0, 25.0, 0.0]\n";
    let render = |name: &str, extra: &str, w: u32, h: u32| {
        let scene = path_in(&dir, &format!("{name}.toml"));
        std::fs::write(&scene, format!("{base}{extra}")).expect("scene");
        let out = path_in(&dir, &format!("{name}.exr"));
        let (code, stdout, stderr) = common::run(common::render_command(&scene, &out, w, h));
        common::assert_clean(code, &stdout, &stderr);
        image::open(&out).expect("EXR").to_rgba32f()
    };
    let f = frame([0.0, 0.0, -40.0], [-30.0, 25.0, 0.0]);
    let axis = f.fwd;

    let (pw, ph) = (320, 320);
    let tan_half = 30f64.to_radians().tan();
    let pin = render("pinhole", "vfov_deg = 60.0\n", pw, ph);
    let pin_flux = flux_in_cone(
        &pin,
        |c, r| {
            let sx = (2.0 * (f64::from(c) + 0.5) / f64::from(pw) - 1.0) * tan_half;
            let sy = (1.0 - 2.0 * (f64::from(r) + 0.5) / f64::from(ph)) * tan_half;
            let d = f.fwd + sx * f.right + sy * f.up;
            let step = 2.0 * tan_half / f64::from(ph);
            Some((d.normalize(), step * step / d.length().powi(3)))
        },
        axis,
    );

    let s = 640;
    let dome = render("dome", "projection = \"fisheye\"\nvfov_deg = 180.0\n", s, s);
    let half = FRAC_PI_2;
    let dome_flux = flux_in_cone(
        &dome,
        |c, r| {
            let d = fisheye(&f, c, r, s, s, 180.0)?;
            let theta = angle(d, f.fwd).max(1e-9);
            let step = 2.0 * half / f64::from(s);
            Some((d, step * step * theta.sin() / theta))
        },
        axis,
    );

    let (ew, eh) = (1024, 512);
    let pano = render("pano", "projection = \"equirect\"\n", ew, eh);
    let pano_flux = flux_in_cone(
        &pano,
        |c, r| {
            let (_, d) = equirect(&f, c, r, ew, eh);
            let lat = (1.0 - 2.0 * (f64::from(r) + 0.5) / f64::from(eh)) * FRAC_PI_2;
            Some((
                d,
                (2.0 * PI / f64::from(ew)) * (PI / f64::from(eh)) * lat.cos(),
            ))
        },
        axis,
    );
    println!(
        "sky flux in a 14-20 degree cone: pinhole {pin_flux:.5e}, dome {dome_flux:.5e} ({:+.2} %), panorama {pano_flux:.5e} ({:+.2} %)",
        100.0 * (dome_flux / pin_flux - 1.0),
        100.0 * (pano_flux / pin_flux - 1.0)
    );
    assert!(pin_flux > 0.0);
    for (name, v) in [("dome", dome_flux), ("panorama", pano_flux)] {
        assert!(
            (v / pin_flux - 1.0).abs() < 0.05,
            "{name}: {v:.5e} against the pinhole's {pin_flux:.5e}"
        );
    }
}

#[test]
fn every_projection_draws_every_kind_of_scene() {
    // Each projection over the presets that between them hold every disk
    // (thin, volumetric), sky, the grid plane, several holes, a spinning
    // hole and the moving observers: a clean frame (validation silent) with
    // light in it, the fisheye's corners transparent, the rest opaque.
    use blackhole::camera::{Projection, Stereo};
    use blackhole::{OutputKind, Pixels, Scene};
    let mut r = common::renderer();
    let (w, h) = (64, 64);
    let mut drawn = 0;
    for preset in [
        "default",
        "interstellar",
        "binary",
        "grid",
        "gargantua",
        "falling",
        "edge-on",
    ] {
        for (projection, stereo) in [
            (Projection::Equirect, Stereo::None),
            (Projection::Fisheye, Stereo::None),
            (Projection::Equirect, Stereo::Ods),
        ] {
            let mut scene = Scene::load(preset).expect("preset");
            scene.camera.projection = projection;
            scene.camera.stereo = stereo;
            if projection == Projection::Fisheye {
                scene.camera.vfov_deg = 180.0;
            }
            scene
                .check()
                .unwrap_or_else(|e| panic!("{preset} {projection:?} {stereo:?}: {e}"));
            let frame = r
                .render(&scene, w, h, OutputKind::Ldr)
                .unwrap_or_else(|e| panic!("{preset} {projection:?} {stereo:?}: {e}"));
            let Pixels::Rgba8(px) = frame.pixels else {
                panic!("8-bit frame expected");
            };
            let what = format!("{preset} {projection:?} {stereo:?}");
            let lit = px
                .chunks_exact(4)
                .filter(|p| p[..3].iter().any(|&v| v > 40))
                .count();
            assert!(lit > 10, "{what}: only {lit} lit pixels");
            let corner = &px[..4];
            if projection == Projection::Fisheye {
                assert_eq!(corner, [0, 0, 0, 0], "{what}: corner");
            } else {
                assert!(px.chunks_exact(4).all(|p| p[3] == 255), "{what}: opaque");
            }
            drawn += 1;
        }
    }
    assert_eq!(drawn, 21);
    assert_eq!(r.validation_counts(), (0, 0));
    r.shutdown().expect("nothing outlives the renderer");
}
