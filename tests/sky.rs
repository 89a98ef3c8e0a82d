//! Skies: an equirectangular panorama and a cube map, sampled where the
//! convention says, and clear errors for missing files; the catalogue sky's
//! stars where their published coordinates put them.

// (Its device-dependent test runs from tests/device.rs: helpers only it
// uses are unused in this target.)
#![cfg_attr(test, allow(dead_code))]

mod common;

use common::{SceneSrc, blackhole, path_in, render_png, run, scratch};

/// A scene with gravity off and the hole far away, camera at the origin
/// looking along `look`, so each pixel sees the sky in its own direction.
fn scene(sky: &str, look: [f64; 3]) -> String {
    format!(
        "[camera]\nposition = [0.0, 0.0, 0.0]\nlook_at = [{}, {}, {}]\nvfov_deg = 20.0\n\n\
         [[black_hole]]\nposition = [500.0, 500.0, 500.0]\nrs = 0.01\n\n\
         [disk]\nkind = \"none\"\n\n[physics]\ngravity = false\n\n[bloom]\nstrength = 0.0\n\n\
         [post]\nauto_exposure = false\ntonemap = \"linear\"\ndither = false\n\n[sky]\n{sky}",
        look[0], look[1], look[2]
    )
}

fn centre(dir: &tempfile::TempDir, name: &str, toml: &str) -> image::Rgb<u8> {
    *render_png(dir, name, SceneSrc::Toml(toml), 33, 33).get_pixel(16, 16)
}

fn dominant(p: image::Rgb<u8>) -> usize {
    (0..3).max_by_key(|&k| p[k]).unwrap_or(0)
}

#[test]
fn panorama_is_sampled_by_longitude_and_latitude() {
    let dir = scratch();
    // 64x32 panorama: u in [0.4, 0.6) red (looking along +x), u in [0.65, 0.85)
    // green (+z), the top rows blue (+y), the rest dark grey.
    let mut pano = image::RgbImage::from_pixel(64, 32, image::Rgb([20, 20, 20]));
    for y in 0..32 {
        for x in 0..64 {
            let u = (f64::from(x) + 0.5) / 64.0;
            let c = if y < 4 {
                [0, 0, 255]
            } else if (0.4..0.6).contains(&u) {
                [255, 0, 0]
            } else if (0.65..0.85).contains(&u) {
                [0, 255, 0]
            } else {
                continue;
            };
            pano.put_pixel(x, y, image::Rgb(c));
        }
    }
    pano.save(path_in(&dir, "pano.png")).unwrap();
    let sky = "kind = \"image\"\nimage = \"pano.png\"\n";
    assert_eq!(
        dominant(centre(&dir, "x", &scene(sky, [1.0, 0.0, 0.0]))),
        0,
        "+x is red"
    );
    assert_eq!(
        dominant(centre(&dir, "z", &scene(sky, [0.0, 0.0, 1.0]))),
        1,
        "+z is green"
    );
    let up = scene(sky, [0.0, 1.0, 0.0])
        .replace("vfov_deg = 20.0", "vfov_deg = 20.0\nup = [0.0, 0.0, 1.0]");
    assert_eq!(dominant(centre(&dir, "y", &up)), 2, "+y is blue");

    // The same panorama as linear float data in OpenEXR, and as JPEG.
    image::DynamicImage::ImageRgb8(pano.clone())
        .to_rgba32f()
        .save(path_in(&dir, "pano.exr"))
        .unwrap();
    let exr = "kind = \"image\"\nimage = \"pano.exr\"\n";
    assert_eq!(
        dominant(centre(&dir, "xe", &scene(exr, [1.0, 0.0, 0.0]))),
        0,
        "EXR: +x is red"
    );
    assert_eq!(
        dominant(centre(&dir, "ze", &scene(exr, [0.0, 0.0, 1.0]))),
        1,
        "EXR: +z is green"
    );
    pano.save(path_in(&dir, "pano.jpg")).unwrap();
    let jpg = "kind = \"image\"\nimage = \"pano.jpg\"\n";
    assert_eq!(
        dominant(centre(&dir, "xj", &scene(jpg, [1.0, 0.0, 0.0]))),
        0,
        "JPEG: +x is red"
    );
}

#[test]
fn cube_map_faces_land_in_their_directions() {
    let dir = scratch();
    let colours = [
        [255, 0, 0],
        [0, 255, 255],
        [0, 255, 0],
        [255, 0, 255],
        [0, 0, 255],
        [255, 255, 0],
    ];
    let names = ["px", "nx", "py", "ny", "pz", "nz"];
    for (n, c) in names.iter().zip(colours) {
        image::RgbImage::from_pixel(16, 16, image::Rgb(c))
            .save(path_in(&dir, &format!("{n}.png")))
            .unwrap();
    }
    let sky = "kind = \"cubemap\"\ncubemap = [\"px.png\", \"nx.png\", \"py.png\", \"ny.png\", \"pz.png\", \"nz.png\"]\n";
    let p = centre(&dir, "cx", &scene(sky, [1.0, 0.0, 0.0]));
    assert!(p[0] > 200 && p[1] < 40 && p[2] < 40, "+x face red: {p:?}");
    let p = centre(&dir, "cz", &scene(sky, [0.0, 0.0, 1.0]));
    assert!(p[2] > 200 && p[0] < 40 && p[1] < 40, "+z face blue: {p:?}");
    let p = centre(&dir, "cnz", &scene(sky, [0.0, 0.0, -1.0]));
    assert!(
        p[0] > 200 && p[1] > 200 && p[2] < 40,
        "-z face yellow: {p:?}"
    );
}

#[test]
fn a_missing_sky_file_is_named() {
    let dir = scratch();
    let path = path_in(&dir, "bad.toml");
    std::fs::write(&path, "[sky]\nkind = \"image\"\nimage = \"nowhere.hdr\"\n").unwrap();
    let out = path_in(&dir, "bad.png");
    let mut c = blackhole();
    c.args(["render", "--scene"])
        .arg(&path)
        .arg("--out")
        .arg(&out);
    let (code, _, stderr) = run(c);
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("nowhere.hdr") && stderr.contains("bad.toml:3"),
        "{stderr}"
    );
    assert!(!out.exists());

    // A file that exists but is not an image: named, with the decoder's reason.
    std::fs::write(path_in(&dir, "junk.png"), b"not a png").unwrap();
    std::fs::write(&path, "[sky]\nkind = \"image\"\nimage = \"junk.png\"\n").unwrap();
    let mut c = blackhole();
    c.args(["render", "--scene"])
        .arg(&path)
        .arg("--out")
        .arg(&out);
    let (code, _, stderr) = run(c);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("junk.png"), "{stderr}");
    assert!(!out.exists());
}

/// World direction of galactic longitude `l` and latitude `b` (degrees) in
/// the catalogue sky's galactic frame, not turned (docs/scenes.md, "The real sky": the
/// galactic centre along +z, the north galactic pole along +y, longitude
/// growing to the left as seen from inside).
fn galactic_world(l: f64, b: f64) -> [f64; 3] {
    let (l, b) = (l.to_radians(), b.to_radians());
    [-b.cos() * l.sin(), b.sin(), b.cos() * l.cos()]
}

/// The brightest pixel of a linear HDR render of the catalogue sky from the
/// origin (gravity off) looking along `look`.
fn brightest(look: [f64; 3], vfov: f64, w: u32, h: u32) -> (u32, u32) {
    use blackhole::vk::Validation;
    use blackhole::{OutputKind, Pixels, Renderer, RendererOptions, Scene};
    let toml = format!(
        "[camera]\nposition = [0.0, 0.0, 0.0]\nlook_at = [{}, {}, {}]\nvfov_deg = {vfov}\n\n\
         [[black_hole]]\nposition = [500.0, 500.0, 500.0]\nrs = 0.01\n\n\
         [disk]\nkind = \"none\"\n\n[physics]\ngravity = false\n\n\
         [sky]\nkind = \"catalogue\"\nframe = \"galactic\"\nrotation_deg = 0.0\ntilt_deg = 0.0\ngalaxy = 0.0\n",
        look[0], look[1], look[2]
    );
    let scene = Scene::from_toml(&toml, "test scene").unwrap();
    let mut r = Renderer::new(RendererOptions {
        validation: Validation::Required,
        ..Default::default()
    })
    .unwrap();
    let f = r.render(&scene, w, h, OutputKind::Hdr).unwrap();
    let Pixels::Rgba32F(px) = f.pixels else {
        panic!("float pixels")
    };
    let mut best = (0, 0, 0.0f32);
    for y in 0..h {
        for x in 0..w {
            let i = (4 * (y * w + x)) as usize;
            let l = px[i] + px[i + 1] + px[i + 2];
            if l > best.2 {
                best = (x, y, l);
            }
        }
    }
    assert_eq!(r.validation_counts(), (0, 0));
    r.shutdown().unwrap();
    (best.0, best.1)
}

#[test]
fn sirius_lands_where_its_coordinates_say() {
    // Sirius: galactic l = 227.230, b = -8.890 (from its ICRS place, not from
    // the embedded table). Centred in a 2-degree field of 65x65 pixels.
    let (x, y) = brightest(galactic_world(227.230, -8.890), 2.0, 65, 65);
    assert!(
        x.abs_diff(32) <= 1 && y.abs_diff(32) <= 1,
        "Sirius at ({x},{y})"
    );
}

#[test]
fn the_catalogue_sky_is_not_mirrored() {
    // A 30-degree field centred 14 degrees right of Sirius along the
    // galactic plane: Sirius, the brightest star in it, must sit where a
    // pinhole camera puts it, left of the centre (the sky seen from inside
    // has east on the left; a mirrored sky would put it right).
    let (w, h, vfov) = (161u32, 91u32, 30.0f64);
    let look = galactic_world(213.230, -8.890);
    let (x, y) = brightest(look, vfov, w, h);
    let sirius = galactic_world(227.230, -8.890);
    // The camera's frame (docs/physics.md, the binding camera convention): right = up x forward.
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let n = dot(look, look).sqrt();
    let fwd = look.map(|v| v / n);
    let up0 = [0.0, 1.0, 0.0];
    let right = [
        up0[1] * fwd[2] - up0[2] * fwd[1],
        up0[2] * fwd[0] - up0[0] * fwd[2],
        up0[0] * fwd[1] - up0[1] * fwd[0],
    ];
    let rn = dot(right, right).sqrt();
    let right = right.map(|v| v / rn);
    let up = [
        fwd[1] * right[2] - fwd[2] * right[1],
        fwd[2] * right[0] - fwd[0] * right[2],
        fwd[0] * right[1] - fwd[1] * right[0],
    ];
    let f = (f64::from(h) / 2.0) / (vfov.to_radians() / 2.0).tan();
    let z = dot(sirius, fwd);
    let want = (
        f64::from(w) / 2.0 + f * dot(sirius, right) / z,
        f64::from(h) / 2.0 - f * dot(sirius, up) / z,
    );
    assert!(
        want.0 < f64::from(w) / 2.0 - 20.0,
        "the prediction is left: {want:?}"
    );
    assert!(
        (f64::from(x) + 0.5 - want.0).abs() <= 2.0 && (f64::from(y) + 0.5 - want.1).abs() <= 2.0,
        "Sirius at ({x},{y}), expected near ({:.1},{:.1})",
        want.0,
        want.1
    );
}

/// Linear HDR render of the catalogue sky (no Milky Way) from the origin
/// looking at `look`, with one hole of rs = 1 at `hole` (gravity on) or
/// straight rays (gravity off).
fn render_hdr(look: [f64; 3], hole: [f64; 3], gravity: bool, vfov: f64, n: u32) -> Vec<f32> {
    use blackhole::vk::Validation;
    use blackhole::{OutputKind, Pixels, Renderer, RendererOptions, Scene};
    let toml = format!(
        "[camera]\nposition = [0.0, 0.0, 0.0]\nlook_at = [{}, {}, {}]\nvfov_deg = {vfov}\n\n\
         [[black_hole]]\nposition = [{}, {}, {}]\nrs = 1.0\n\n\
         [disk]\nkind = \"none\"\n\n[physics]\ngravity = {gravity}\n\n\
         [sky]\nkind = \"catalogue\"\nrotation_deg = 0.0\ntilt_deg = 0.0\ngalaxy = 0.0\n",
        look[0], look[1], look[2], hole[0], hole[1], hole[2]
    );
    let scene = Scene::from_toml(&toml, "test scene").unwrap();
    let mut r = Renderer::new(RendererOptions {
        validation: Validation::Required,
        ..Default::default()
    })
    .unwrap();
    let f = r.render(&scene, n, n, OutputKind::Hdr).unwrap();
    assert_eq!(r.validation_counts(), (0, 0));
    r.shutdown().unwrap();
    match f.pixels {
        Pixels::Rgba32F(p) => p,
        Pixels::Rgba8(_) => panic!("float pixels"),
    }
}

/// Run by tests/device.rs, which lists it as ignored where the device
/// cannot run it (so not a `#[test]` of this file).
pub fn a_lensed_star_brightens_by_the_point_lens_magnification() {
    // Sirius behind a hole 10^4 rs away, offset from it by one Einstein
    // radius (theta_E^2 = 2 rs / D for a source at infinity): a weak-field
    // point lens with u = 1 shows two images, at 1.618 and 0.618 theta_E on
    // either side, whose fluxes add to (u^2 + 2) / (u sqrt(u^2 + 4)) = 1.342
    // times the star's (strong-field corrections here are about 1 %). Every
    // image is drawn from the ray differentials of its pixels: nothing in
    // the renderer knows the formula.
    let dot = |a: [f64; 3], b: [f64; 3]| a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
    let cross = |a: [f64; 3], b: [f64; 3]| {
        [
            a[1] * b[2] - a[2] * b[1],
            a[2] * b[0] - a[0] * b[2],
            a[0] * b[1] - a[1] * b[0],
        ]
    };
    let unit = |a: [f64; 3]| {
        let n = dot(a, a).sqrt();
        a.map(|v| v / n)
    };
    let d: f64 = 1.0e4;
    let theta_e = (2.0 / d).sqrt();
    let s = galactic_world(227.230, -8.890);
    let k = unit(cross(s, [0.0, 1.0, 0.0]));
    let h = unit([0, 1, 2].map(|i| theta_e.cos() * s[i] + theta_e.sin() * k[i]));
    let hole = h.map(|v| v * d);
    let (n, vfov) = (300u32, 4.0f64);
    // Where a pinhole camera looking along h puts a direction.
    let right = unit(cross([0.0, 1.0, 0.0], h));
    let up = cross(h, right);
    let f = (f64::from(n) / 2.0) / (vfov.to_radians() / 2.0).tan();
    let pixel = |v: [f64; 3]| {
        let z = dot(v, h);
        (
            f64::from(n) / 2.0 + f * dot(v, right) / z,
            f64::from(n) / 2.0 - f * dot(v, up) / z,
        )
    };
    // Light within 5 pixels of a point.
    let aperture = |img: &[f32], (cx, cy): (f64, f64)| {
        let mut sum = 0.0;
        for y in 0..n {
            for x in 0..n {
                let (dx, dy) = (f64::from(x) + 0.5 - cx, f64::from(y) + 0.5 - cy);
                if dx * dx + dy * dy <= 25.0 {
                    let i = (4 * (y * n + x)) as usize;
                    sum += f64::from(img[i] + img[i + 1] + img[i + 2]);
                }
            }
        }
        sum
    };
    let plain = render_hdr(h, hole, false, vfov, n);
    let unlensed = aperture(&plain, pixel(s));
    assert!(unlensed > 0.0, "Sirius is in the unlensed view");
    let lensed_img = render_hdr(h, hole, true, vfov, n);
    let at = |theta: f64| {
        pixel(unit(
            [0, 1, 2].map(|i| theta.cos() * h[i] + theta.sin() * k[i]),
        ))
    };
    let phi = 1.618_034 * theta_e;
    let (primary, secondary) = (
        aperture(&lensed_img, at(-phi)),
        aperture(&lensed_img, at(0.618_034 * theta_e)),
    );
    let mu = (primary + secondary) / unlensed;
    println!(
        "lensed Sirius: images {:.4} + {:.4} of the unlensed flux, total {mu:.4} (point lens: 1.1708 + 0.1708 = 1.3416)",
        primary / unlensed,
        secondary / unlensed
    );
    assert!((mu / 1.3416 - 1.0).abs() < 0.05, "total magnification {mu}");
    assert!(
        (secondary / unlensed / 0.1708 - 1.0).abs() < 0.15,
        "secondary image"
    );
}

#[test]
fn a_star_keeps_its_flux_as_the_camera_moves_by_fractions_of_a_pixel() {
    // Sirius in a 2-degree field, the camera turned by eighths of a pixel:
    // the light it puts in the image stays the same (no blinking as a
    // sequence pans), to well under a per cent.
    let n = 65u32;
    let pixel = 2f64.to_radians() / f64::from(n);
    let s = galactic_world(227.230, -8.890);
    let right = {
        let r = [-s[2], 0.0, s[0]];
        let l = (r[0] * r[0] + r[2] * r[2]).sqrt();
        r.map(|v| v / l)
    };
    let mut fluxes = Vec::new();
    for i in 0..8 {
        let a = pixel * f64::from(i) / 8.0;
        let look = [0, 1, 2].map(|k| s[k] + a * right[k]);
        let img = render_hdr(look, [500.0, 500.0, 500.0], false, 2.0, n);
        fluxes.push(img.iter().map(|&v| f64::from(v)).sum::<f64>());
    }
    let mean = fluxes.iter().sum::<f64>() / fluxes.len() as f64;
    let spread = fluxes
        .iter()
        .map(|f| (f / mean - 1.0).abs())
        .fold(0.0, f64::max);
    println!("flux over eighth-pixel turns: {fluxes:.5?}, spread {spread:.2e}");
    assert!(spread < 0.005, "the star's light changes by {spread:.4}");
}

/// CRC-32 (the PNG chunk checksum), to forge a header.
fn crc32(bytes: &[u8]) -> u32 {
    let mut c = 0xffff_ffffu32;
    for &b in bytes {
        c ^= u32::from(b);
        for _ in 0..8 {
            c = if c & 1 == 1 {
                0xedb8_8320 ^ (c >> 1)
            } else {
                c >> 1
            };
        }
    }
    !c
}

/// A PNG whose header says `w` x `h` and whose pixel data is empty.
fn png_header_only(w: u32, h: u32) -> Vec<u8> {
    let mut png = b"\x89PNG\r\n\x1a\n".to_vec();
    let mut chunk = |kind: &[u8], data: &[u8]| {
        let mut body = kind.to_vec();
        body.extend_from_slice(data);
        png.extend_from_slice(&(data.len() as u32).to_be_bytes());
        png.extend_from_slice(&body);
        png.extend_from_slice(&crc32(&body).to_be_bytes());
    };
    let mut ihdr = w.to_be_bytes().to_vec();
    ihdr.extend_from_slice(&h.to_be_bytes());
    ihdr.extend_from_slice(&[8, 6, 0, 0, 0]); // 8-bit RGBA
    chunk(b"IHDR", &ihdr);
    chunk(b"IDAT", &[]);
    chunk(b"IEND", &[]);
    png
}

#[test]
fn hostile_sky_images_are_refused_with_the_file_named() {
    let dir = scratch();
    let scene = path_in(&dir, "sky.toml");
    let out = path_in(&dir, "out.png");
    let render = |file: &str| {
        std::fs::write(
            &scene,
            format!("[sky]\nkind = \"image\"\nimage = \"{file}\"\n"),
        )
        .unwrap();
        let mut c = blackhole();
        c.args(["render", "--width", "32", "--height", "18", "--scene"])
            .arg(&scene)
            .arg("--out")
            .arg(&out);
        run(c)
    };
    // A real image, truncated half-way.
    let good = path_in(&dir, "good.png");
    image::RgbImage::from_fn(64, 32, |x, y| {
        image::Rgb([(x * 4) as u8, (y * 8) as u8, 90])
    })
    .save(&good)
    .unwrap();
    let bytes = std::fs::read(&good).unwrap();
    std::fs::write(path_in(&dir, "truncated.png"), &bytes[..bytes.len() / 2]).unwrap();
    std::fs::write(path_in(&dir, "empty.png"), b"").unwrap();
    std::fs::write(path_in(&dir, "huge.png"), png_header_only(100_000, 100_000)).unwrap();
    std::fs::write(path_in(&dir, "zero.png"), png_header_only(0, 16)).unwrap();
    std::fs::write(path_in(&dir, "wide.png"), png_header_only(u32::MAX / 2, 1)).unwrap();
    for (file, says) in [
        ("truncated.png", ""),
        ("empty.png", ""),
        ("huge.png", "larger than the limit"),
        ("zero.png", ""),
        ("wide.png", ""),
    ] {
        let (code, _, stderr) = render(file);
        assert_eq!(code, 2, "{file}: {stderr}");
        let errors: Vec<&str> = stderr.lines().filter(|l| l.starts_with("error")).collect();
        assert_eq!(errors.len(), 1, "{file}: one error line: {stderr}");
        assert!(
            errors[0].contains(file) && errors[0].contains(says),
            "{file}: {stderr}"
        );
        assert!(!stderr.contains("panicked"), "{file}: {stderr}");
        assert!(!out.exists(), "{file}: no output");
    }
    // Other channel counts are fine: grey and grey with alpha.
    image::GrayImage::from_pixel(64, 32, image::Luma([128]))
        .save(path_in(&dir, "grey.png"))
        .unwrap();
    image::GrayAlphaImage::from_pixel(64, 32, image::LumaA([128, 255]))
        .save(path_in(&dir, "grey_alpha.png"))
        .unwrap();
    for file in ["grey.png", "grey_alpha.png"] {
        let (code, stdout, stderr) = render(file);
        common::assert_clean(code, &stdout, &stderr);
        std::fs::remove_file(&out).unwrap();
    }
}
