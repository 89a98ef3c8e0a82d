//! A scene's static parameters compiled into the ray march (an offscreen
//! render's default, shaders/include/baked.glsl) draw what the same
//! parameters read from the block draw (`BLACKHOLE_NO_BAKE=1`, the window's
//! way): every kind of path and disk, a grid plane, a hole off the origin
//! and a tilted disk (no value that folds to 0 or 1), the geodesic AOV, and
//! a panorama sky (its texel size baked from the loaded image: once it was
//! baked as 0, and every offscreen panorama took its finest mip, aliased).
//! Fails when a baked value lands in the wrong field (a swapped name, an id
//! off by one) or the driver folds them into something else.

mod common;

use common::{assert_clean, path_in, render_command, run, scratch};

/// Each scene rendered to EXR baked and not: a preset's name (its TOML
/// empty) or a name and its TOML, and whether the geodesic AOV is compared
/// instead of the image.
const SCENES: [(&str, &str, bool); 8] = [
    ("default", "", false),
    ("interstellar", "", false),
    ("gargantua", "", false),
    ("falling", "", false),
    (
        "tilted",
        "[[black_hole]]\nposition = [0.7, -0.4, 0.3]\nrs = 1.3\n\
         [disk]\nnormal = [0.2, 1.0, -0.3]\nouter_radius = 9.0\ntemperature_profile = \"newtonian\"\n\
         [sky]\nkind = \"checker\"\n\
         [grid_plane]\nenabled = true\n",
        false,
    ),
    ("binary", "", false),
    (
        "panorama",
        "[sky]\nkind = \"image\"\nimage = \"panorama.png\"\n",
        false,
    ),
    (
        "tilted-aov",
        "[[black_hole]]\nposition = [0.7, -0.4, 0.3]\nspin = 0.7\n[disk]\nnormal = [0.2, 1.0, -0.3]\n",
        true,
    ),
];

fn render(
    dir: &tempfile::TempDir,
    scene: &std::path::Path,
    name: &str,
    bake: bool,
    aov: bool,
) -> image::Rgba32FImage {
    let out = path_in(dir, &format!("{name}-{bake}.exr"));
    let mut c = render_command(scene, &out, 160, 90);
    if aov {
        c.args(["--aov", "geodesic"]);
    }
    if !bake {
        c.env("BLACKHOLE_NO_BAKE", "1");
    }
    let (code, stdout, stderr) = run(c);
    assert_clean(code, &stdout, &stderr);
    image::open(&out).expect("EXR written").to_rgba32f()
}

#[test]
fn baked_parameters_draw_what_the_parameter_block_draws() {
    let dir = scratch();
    // A panorama of 8-texel squares, fine enough that every pixel's
    // footprint takes a coarser mip.
    let panorama = image::RgbImage::from_fn(2048, 1024, |x, y| {
        let on = (x / 8 + y / 8) % 2 == 1;
        image::Rgb([if on { 230 } else { 30 }, (x / 8) as u8, 90])
    });
    panorama
        .save(path_in(&dir, "panorama.png"))
        .expect("the panorama written");
    for (name, toml, aov) in SCENES {
        let scene = if toml.is_empty() {
            std::path::PathBuf::from(name)
        } else {
            let p = path_in(&dir, &format!("{name}.toml"));
            std::fs::write(&p, toml).unwrap();
            p
        };
        let baked = render(&dir, &scene, name, true, aov);
        let block = render(&dir, &scene, name, false, aov);
        let lit = block
            .pixels()
            .filter(|p| p[0] != 0.0 || p[1] != 0.0)
            .count();
        assert!(
            lit > 160 * 90 / 4,
            "{name}: the view shows something ({lit} pixels)"
        );
        // Within a unit of the half-float image (the AOV: 1e-5 relative);
        // the driver may fold the constants into other roundings, and a
        // pixel at a discontinuity (a star's cell, the shadow's edge) may
        // fall on the other side of it.
        let unit = if aov { 1e-5 } else { 1.0 / 1024.0 };
        let differ = block
            .pixels()
            .zip(baked.pixels())
            .filter(|(b, k)| (0..4).any(|c| (b[c] - k[c]).abs() > unit * b[c].abs().max(1.0)))
            .count();
        assert!(
            differ <= 2,
            "{name}: {differ} pixels differ, baked against the block"
        );
    }
}
