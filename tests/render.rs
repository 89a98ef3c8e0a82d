//! Offscreen renders on lavapipe with the validation layer required: every run
//! must finish with zero validation errors and warnings.

// (Its device-dependent test runs from tests/device.rs: helpers only it
// uses are unused in this target.)
#![cfg_attr(test, allow(dead_code))]

mod common;

use common::{
    SceneSrc, assert_clean, blackhole, path_in, render_command, render_png, run, scratch,
};

fn luma(p: &image::Rgb<u8>) -> f32 {
    0.2126 * f32::from(p[0]) + 0.7152 * f32::from(p[1]) + 0.0722 * f32::from(p[2])
}

#[test]
fn default_scene_renders_shadow_disk_and_sky_without_validation_messages() {
    let dir = scratch();
    let out = path_in(&dir, "bh.png");
    let mut c = blackhole();
    c.args(["render", "--width", "160", "--height", "90", "--out"])
        .arg(&out);
    let (code, stdout, stderr) = run(c);
    assert_clean(code, &stdout, &stderr);

    let img = image::open(&out).expect("PNG written").to_rgb8();
    assert_eq!(img.dimensions(), (160, 90));

    // The centre looks straight at the hole: the shadow is black.
    for (x, y) in [(79, 44), (80, 44), (79, 43), (80, 43)] {
        let p = img.get_pixel(x, y);
        assert!(
            p.0.iter().all(|&c| c <= 2),
            "shadow pixel ({x},{y}) = {p:?}"
        );
    }
    // Below the centre, the near side of the disk crosses in front of the
    // hole (radius ~5 to ~10 along the centre column): the warm colour of a
    // 6000 K blackbody seen redshifted, unlike either checker tone of the sky
    // (which are blue-grey).
    // Its filaments make single pixels dark or bright: the mean of the
    // stretch is taken.
    let mut mean = [0.0f32; 3];
    for y in 48..=58 {
        let p = img.get_pixel(80, y);
        for k in 0..3 {
            mean[k] += f32::from(p[k]) / 11.0;
        }
    }
    // (Red above blue by 20 levels: the Page-Thorne profile, the default
    // since the spinning hole, is hotter there than the Newtonian one was,
    // red - blue 24.5 against 31.9; the sky's tones have blue above red.)
    assert!(
        mean[0] > 70.0 && mean[0] > mean[2] + 20.0 && mean[0] >= mean[1] && mean[1] >= mean[2],
        "disk pixels (80, 48..=58), mean {mean:?}"
    );
    // Not uniform: the luminance spread is wide.
    let l: Vec<f32> = img.pixels().map(luma).collect();
    let mean = l.iter().sum::<f32>() / l.len() as f32;
    let var = l.iter().map(|v| (v - mean).powi(2)).sum::<f32>() / l.len() as f32;
    assert!(var.sqrt() > 20.0, "luminance std dev {}", var.sqrt());
    // The default sky is a star field: dark between the stars (the median of
    // each corner block), with some stars somewhere in the frame.
    for (x0, y0) in [(0, 0), (150, 0), (0, 80), (150, 80)] {
        let mut block: Vec<f32> = (0..10)
            .flat_map(|dy| (0..10).map(move |dx| (x0 + dx, y0 + dy)))
            .map(|(x, y)| luma(img.get_pixel(x, y)))
            .collect();
        block.sort_by(f32::total_cmp);
        assert!(
            block[50] < 25.0,
            "corner ({x0},{y0}) median luma {}",
            block[50]
        );
    }
    let stars = (0..30)
        .flat_map(|y| (0..160).map(move |x| (x, y)))
        .filter(|&(x, y)| luma(img.get_pixel(x, y)) > 60.0)
        .count();
    assert!(stars >= 3, "{stars} star pixels in the top rows");
}

#[test]
fn exr_output_round_trips_with_finite_linear_values() {
    let dir = scratch();
    let out = path_in(&dir, "bh.exr");
    let mut c = blackhole();
    c.args(["render", "--width", "64", "--height", "36", "--out"])
        .arg(&out);
    let (code, stdout, stderr) = run(c);
    assert_clean(code, &stdout, &stderr);

    let img = image::open(&out).expect("EXR written").to_rgba32f();
    assert_eq!(img.dimensions(), (64, 36));
    assert!(
        img.pixels()
            .all(|p| p.0.iter().all(|v| v.is_finite() && *v >= 0.0))
    );
    // Linear HDR: the disk near the inner edge is brighter than 1 (not tone-mapped).
    let max = img.pixels().map(|p| p[0]).fold(0.0f32, f32::max);
    assert!(max > 1.0, "max red {max}: expected unclamped HDR values");
    // The centre is the shadow.
    let p = img.get_pixel(31, 17);
    assert!(p[0] == 0.0 && p[1] == 0.0 && p[2] == 0.0, "centre {p:?}");
}

#[test]
fn negative_rs_is_rejected_naming_the_key_and_writes_nothing() {
    let dir = scratch();
    let scene = path_in(&dir, "bad.toml");
    std::fs::write(
        &scene,
        "[camera]\nvfov_deg = 60.0\n\n[[black_hole]]\nrs = -1\n",
    )
    .unwrap();
    let out = path_in(&dir, "bad.png");
    let mut c = blackhole();
    c.args(["render", "--width", "32", "--height", "18", "--scene"])
        .arg(&scene)
        .arg("--out")
        .arg(&out);
    let (code, _, stderr) = run(c);
    assert_ne!(code, 0);
    assert!(stderr.contains("black_hole[0].rs = -1"), "{stderr}");
    assert!(stderr.contains("bad.toml:5"), "names the line: {stderr}");
    assert_eq!(stderr.trim().lines().count(), 1, "one line: {stderr}");
    assert!(!out.exists());
    assert_eq!(
        std::fs::read_dir(dir.path()).unwrap().count(),
        1,
        "no temporary files left"
    );
}

#[test]
fn unknown_output_extension_is_rejected_before_rendering() {
    let dir = scratch();
    let out = path_in(&dir, "frame.jpg");
    let mut c = blackhole();
    c.args(["render", "--out"]).arg(&out);
    let (code, _, stderr) = run(c);
    assert_eq!(code, 2);
    assert!(
        stderr.contains("extension .jpg") && stderr.contains(".png or .exr"),
        "{stderr}"
    );
    assert!(!out.exists());
}

#[test]
fn unknown_preset_lists_the_presets() {
    let mut c = blackhole();
    c.args(["render", "--scene", "no-such-scene", "--out", "x.png"]);
    let (code, _, stderr) = run(c);
    assert_eq!(code, 2);
    assert!(
        stderr.contains("no-such-scene") && stderr.contains("default"),
        "{stderr}"
    );
}

#[test]
fn no_vulkan_driver_is_one_sentence_naming_the_package() {
    let dir = scratch();
    let out = path_in(&dir, "x.png");
    let mut c = blackhole();
    c.env("BLACKHOLE_VALIDATION", "0")
        .env("VK_DRIVER_FILES", "/nonexistent/icd.json")
        .env("VK_ICD_FILENAMES", "/nonexistent/icd.json")
        .args(["render", "--out"])
        .arg(&out);
    let (code, _, stderr) = run(c);
    assert_eq!(code, 2, "{stderr}");
    let errors: Vec<&str> = stderr.lines().filter(|l| l.starts_with("error:")).collect();
    assert_eq!(errors.len(), 1, "{stderr}");
    assert!(
        errors[0].contains("no Vulkan device") && errors[0].contains("mesa-vulkan-drivers"),
        "{stderr}"
    );
    assert!(!stderr.contains("panicked"), "{stderr}");
    assert!(!out.exists());
}

fn render_small(dir: &tempfile::TempDir, name: &str, scene: &str) -> image::RgbImage {
    render_png(dir, name, SceneSrc::Toml(scene), 160, 90)
}

#[test]
fn doppler_brightens_the_approaching_side_and_the_film_look_is_symmetric() {
    let dir = scratch();
    // The disk turns counter-clockwise seen from +y, so its right (+x) side
    // comes toward the camera on -z.
    // A smooth disk, so mirrored pixels differ only by the shifts.
    let physical = render_small(&dir, "physical", "[disk]\nstructure = 0.0\n");
    let film = render_small(
        &dir,
        "film",
        "[disk]\nstructure = 0.0\n[physics]\ndoppler = false\nbeaming = false\ngravitational_redshift = false\n",
    );
    for (x, y) in [(20, 53), (40, 56), (60, 50)] {
        let (left, right) = (physical.get_pixel(x, y), physical.get_pixel(159 - x, y));
        assert!(
            luma(right) > 1.5 * luma(left),
            "physical ({x},{y}) {left:?} vs {right:?}"
        );
        // Blueshifted: relatively more blue on the approaching side.
        let bluer = f32::from(right[2]) / f32::from(right[0].max(1))
            > f32::from(left[2]) / f32::from(left[0].max(1));
        assert!(bluer, "physical ({x},{y}) {left:?} vs {right:?}");
        let (fl, fr) = (film.get_pixel(x, y), film.get_pixel(159 - x, y));
        for k in 0..3 {
            assert!(
                fl[k].abs_diff(fr[k]) <= 2,
                "film ({x},{y}) {fl:?} vs {fr:?}"
            );
        }
    }
}

#[test]
fn bad_aov_requests_are_rejected_before_rendering() {
    let dir = scratch();
    let png = path_in(&dir, "aov.png");
    let mut c = blackhole();
    c.args(["render", "--aov", "geodesic", "--out"]).arg(&png);
    let (code, _, stderr) = run(c);
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("--aov geodesic") && stderr.contains(".exr"),
        "{stderr}"
    );
    assert!(!png.exists());

    let exr = path_in(&dir, "aov.exr");
    let mut c = blackhole();
    c.args(["render", "--aov", "normals", "--out"]).arg(&exr);
    let (code, _, stderr) = run(c);
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("normals") && stderr.contains("geodesic"),
        "{stderr}"
    );
    assert!(!exr.exists());

    let scene = path_in(&dir, "volumetric.toml");
    std::fs::write(&scene, "[disk]\nkind = \"volumetric\"\n").unwrap();
    let mut c = blackhole();
    c.args(["render", "--aov", "geodesic", "--scene"])
        .arg(&scene)
        .arg("--out")
        .arg(&exr);
    let (code, _, stderr) = run(c);
    assert_eq!(code, 2, "{stderr}");
    assert!(
        stderr.contains("--aov geodesic") && stderr.contains("volumetric"),
        "{stderr}"
    );
    assert!(!exr.exists());
}

#[test]
fn trace_writes_an_svg_of_photon_paths() {
    let dir = scratch();
    let out = path_in(&dir, "paths.svg");
    let mut c = blackhole();
    c.args(["trace", "--out"]).arg(&out);
    let (code, _, stderr) = run(c);
    assert_eq!(code, 0, "{stderr}");
    let svg = std::fs::read_to_string(&out).expect("SVG written");
    assert!(svg.starts_with("<svg"));
    for label in [
        "horizon",
        "photon sphere, 1.5 rs",
        "ISCO, 3 rs",
        "x / rs",
        "y / rs",
    ] {
        assert!(svg.contains(label), "missing {label}");
    }
}

#[test]
fn every_preset_renders_validation_clean() {
    let dir = scratch();
    for (name, _, _) in blackhole::scene::PRESETS {
        let out = path_in(&dir, &format!("{name}.png"));
        let mut c = blackhole();
        c.args([
            "render", "--width", "64", "--height", "36", "--scene", name, "--out",
        ])
        .arg(&out);
        let (code, stdout, stderr) = run(c);
        assert_clean(code, &stdout, &stderr);
        let img = image::open(&out).expect("PNG written").to_rgb8();
        let l: Vec<f32> = img.pixels().map(luma).collect();
        let (lo, hi) = l
            .iter()
            .fold((f32::MAX, 0.0f32), |(a, b), &v| (a.min(v), b.max(v)));
        assert!(hi - lo > 50.0, "preset {name} looks uniform");
    }
}

#[test]
fn help_lists_every_preset() {
    let mut c = blackhole();
    c.args(["render", "--help"]);
    let (code, stdout, _) = run(c);
    assert_eq!(code, 0);
    for (name, _, _) in blackhole::scene::PRESETS {
        assert!(stdout.contains(name), "--help lacks {name}");
    }
}

#[test]
fn a_sequence_split_into_ranges_renders_the_same_frames() {
    let dir = scratch();
    let scene = path_in(&dir, "orbit.toml");
    std::fs::write(
        &scene,
        "[animation]\ncamera = \"orbit\"\norbit_speed_deg = 30.0\nfps = 4.0\n",
    )
    .unwrap();
    let render = |sub: &str, range: &str| {
        let folder = dir.path().join(sub);
        std::fs::create_dir(&folder).unwrap();
        let mut c = blackhole();
        c.args([
            "render", "--width", "48", "--height", "27", "--frames", range, "--scene",
        ])
        .arg(&scene)
        .arg("--out")
        .arg(folder.join("f.png"));
        let (code, stdout, stderr) = run(c);
        assert_clean(code, &stdout, &stderr);
        folder
    };
    let whole = render("whole", "0..3");
    let part = render("part", "1..3");
    let names = |d: &std::path::Path| {
        let mut v: Vec<String> = std::fs::read_dir(d)
            .unwrap()
            .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
            .collect();
        v.sort();
        v
    };
    assert_eq!(names(&whole), ["f_0000.png", "f_0001.png", "f_0002.png"]);
    assert_eq!(names(&part), ["f_0001.png", "f_0002.png"]);
    for f in ["f_0001.png", "f_0002.png"] {
        assert_eq!(
            std::fs::read(whole.join(f)).unwrap(),
            std::fs::read(part.join(f)).unwrap(),
            "{f}"
        );
    }
    // The camera moves: consecutive frames differ.
    assert_ne!(
        std::fs::read(whole.join("f_0000.png")).unwrap(),
        std::fs::read(whole.join("f_0001.png")).unwrap()
    );
}

#[test]
fn bad_frame_ranges_and_missing_folders_are_rejected() {
    for range in ["5..2", "3..3", "x..4", "7"] {
        let mut c = blackhole();
        c.args(["render", "--frames", range, "--out", "never.png"]);
        let (code, _, stderr) = run(c);
        assert_eq!(code, 2, "{range}: {stderr}");
        assert!(stderr.contains(range), "{range}: {stderr}");
    }
    let mut c = blackhole();
    c.args(["render", "--out", "/nonexistent-folder/x.png"]);
    let (code, _, stderr) = run(c);
    assert_eq!(code, 2);
    assert!(
        stderr.contains("/nonexistent-folder") && stderr.contains("does not exist"),
        "{stderr}"
    );
}

#[test]
fn exr_post_applies_exposure_and_bloom_but_stays_linear() {
    let dir = scratch();
    let render = |name: &str, scene: &str, post: bool| {
        let scene_path = path_in(&dir, &format!("{name}.toml"));
        std::fs::write(&scene_path, scene).unwrap();
        let out = path_in(&dir, &format!("{name}.exr"));
        let mut c = blackhole();
        c.args(["render", "--width", "64", "--height", "36", "--scene"])
            .arg(&scene_path)
            .arg("--out")
            .arg(&out);
        if post {
            c.arg("--exr-post");
        }
        let (code, stdout, stderr) = run(c);
        assert_clean(code, &stdout, &stderr);
        image::open(&out).unwrap().to_rgba32f()
    };
    let plain = render(
        "plain",
        "[post]\nexposure_ev = 1.0\nauto_exposure = false\n",
        false,
    );
    let exposed = render(
        "exposed",
        "[post]\nexposure_ev = 1.0\nauto_exposure = false\n[bloom]\nstrength = 0.0\n",
        true,
    );
    // One stop: twice the radiance (f16 storage: 1e-3 relative).
    for (a, b) in plain.pixels().zip(exposed.pixels()) {
        for k in 0..3 {
            assert!(
                (2.0 * a[k] - b[k]).abs() <= 2e-3 * b[k].max(1e-2),
                "{a:?} vs {b:?}"
            );
        }
    }
    // Not tone-mapped: values above 1 survive.
    assert!(exposed.pixels().any(|p| p[0] > 1.0));
    // Bloom adds light.
    let bloomed = render(
        "bloomed",
        "[post]\nexposure_ev = 1.0\nauto_exposure = false\n[bloom]\nstrength = 1.0\nthreshold = 0.5\n",
        true,
    );
    let sum = |img: &image::Rgba32FImage| {
        img.pixels()
            .map(|p| f64::from(p[0] + p[1] + p[2]))
            .sum::<f64>()
    };
    assert!(sum(&bloomed) > 1.01 * sum(&exposed));
    // And it is refused for PNG output.
    let mut c = blackhole();
    c.args(["render", "--exr-post", "--out"])
        .arg(path_in(&dir, "x.png"));
    let (code, _, stderr) = run(c);
    assert_eq!(code, 2);
    assert!(stderr.contains("--exr-post"), "{stderr}");
}

#[test]
fn an_interrupted_sequence_leaves_complete_frames_and_resume_renders_the_rest() {
    let dir = scratch();
    let out = path_in(&dir, "seq.png");
    let args = |c: &mut std::process::Command| {
        c.args([
            "render", "--width", "240", "--height", "135", "--spp", "2", "--frames", "0..24",
            "--out",
        ])
        .arg(&out);
    };
    let frame = |i: u32| path_in(&dir, &format!("seq_{i:04}.png"));
    let mut c = blackhole();
    args(&mut c);
    let mut child = c
        .stdout(std::process::Stdio::piped())
        .stderr(std::process::Stdio::piped())
        .spawn()
        .unwrap();
    // SIGTERM (as a batch system sends) once two frames are there.
    let t0 = std::time::Instant::now();
    while !frame(1).exists() {
        assert!(t0.elapsed().as_secs() < 120, "no frames after two minutes");
        std::thread::sleep(std::time::Duration::from_millis(10));
    }
    std::process::Command::new("sh")
        .arg("-c")
        .arg(format!("kill -TERM {}", child.id()))
        .status()
        .unwrap();
    let status = child.wait().unwrap();
    let mut stderr = String::new();
    std::io::Read::read_to_string(child.stderr.as_mut().unwrap(), &mut stderr).unwrap();
    assert_eq!(status.code(), Some(130), "{stderr}");
    assert!(
        stderr.contains("interrupted") && stderr.contains("--resume"),
        "{stderr}"
    );
    // Only whole frames: every file there decodes, no temporary files.
    let names: Vec<String> = std::fs::read_dir(dir.path())
        .unwrap()
        .map(|e| e.unwrap().file_name().to_string_lossy().into_owned())
        .filter(|n| n.starts_with("seq") || n.contains(".tmp"))
        .collect();
    assert!(names.iter().all(|n| !n.contains(".tmp")), "{names:?}");
    let done = names.len();
    assert!((2..24).contains(&done), "{done} frames before the signal");
    for n in &names {
        image::open(dir.path().join(n)).unwrap_or_else(|e| panic!("{n}: {e}"));
    }
    // --resume renders just the missing ones.
    let mut c = blackhole();
    args(&mut c);
    c.arg("--resume");
    let (code, stdout, stderr) = run(c);
    assert_clean(code, &stdout, &stderr);
    assert!(
        stdout.contains(&format!("wrote {} frames", 24 - done))
            && stdout.contains(&format!("{done} already there")),
        "{stdout}"
    );
    for i in 0..24 {
        assert!(frame(i).is_file(), "frame {i}");
    }
}

#[test]
fn an_unwritable_output_folder_is_refused_before_rendering() {
    let mut c = blackhole();
    c.args(["render", "--out", "/proc/blackhole.png"]);
    let (code, _, stderr) = run(c);
    assert_eq!(code, 2, "{stderr}");
    assert!(stderr.contains("cannot write in /proc"), "{stderr}");
    assert!(
        !stderr.contains("Vulkan device"),
        "checked before the GPU: {stderr}"
    );
}

#[test]
fn a_frame_past_the_gpu_timeout_is_an_error_not_a_hang() {
    let dir = scratch();
    let out = path_in(&dir, "slow.png");
    let mut c = blackhole();
    c.env("BLACKHOLE_GPU_TIMEOUT_S", "0.001")
        .args(["render", "--scene", "interstellar", "--out"])
        .arg(&out);
    let t = std::time::Instant::now();
    let (code, _, stderr) = run(c);
    assert!(t.elapsed().as_secs() < 60, "took {:?}", t.elapsed());
    assert_gpu_failure("timeout", code, &stderr, "BLACKHOLE_GPU_TIMEOUT_S", &out);
}

/// A run (`what`) the GPU failed: exit 1, exactly one `error` line and it
/// `says` what happened, no panic, no validation message, no output file.
fn assert_gpu_failure(what: &str, code: i32, stderr: &str, says: &str, out: &std::path::Path) {
    assert_eq!(code, 1, "{what}: {stderr}");
    let errors: Vec<&str> = stderr.lines().filter(|l| l.starts_with("error")).collect();
    assert_eq!(errors.len(), 1, "{what}: {stderr}");
    assert!(errors[0].contains(says), "{what}: {stderr}");
    assert!(
        !stderr.contains("panicked") && !stderr.contains("VALIDATION"),
        "{what}: {stderr}"
    );
    assert!(!out.exists(), "{what}: {} was written", out.display());
}

/// The failures a real GPU can produce and lavapipe never does, injected
/// (`BLACKHOLE_FAULT`, src/vk/fault.rs): a device lost or out of memory while
/// the first frame is still running, and an allocation refused. Each ends the
/// run with one error line saying what happened, exit 1, no panic, no
/// validation message from the teardown under a frame in flight, and no
/// output file.
#[test]
fn a_lost_device_or_exhausted_memory_is_one_error_line_not_a_crash() {
    let dir = scratch();
    for (fault, says) in [
        ("device-lost", "the GPU device was lost"),
        ("out-of-device-memory", "the GPU ran out of memory"),
        ("alloc:bloom", "allocating memory for `bloom"),
        (
            "alloc:raymarch params",
            "allocating memory for `raymarch params",
        ),
    ] {
        let out = path_in(&dir, "lost.png");
        let mut c = blackhole();
        c.env("BLACKHOLE_FAULT", fault)
            .args(["render", "--width", "320", "--height", "180", "--out"])
            .arg(&out);
        let (code, _, stderr) = run(c);
        assert_gpu_failure(fault, code, &stderr, says, &out);
    }
}

/// A scene rendered to EXR split and in one dispatch
/// (`BLACKHOLE_NO_SPLIT=1`), checking that the split's second pass (`pass`)
/// runs in the first only.
fn split_and_single(
    dir: &tempfile::TempDir,
    name: &str,
    toml: &str,
    (w, h): (u32, u32),
    pass: &str,
) -> [image::Rgba32FImage; 2] {
    let scene = path_in(dir, &format!("{name}.toml"));
    std::fs::write(&scene, toml).unwrap();
    [true, false].map(|split| {
        let out = path_in(dir, &format!("{name}-{split}.exr"));
        let mut c = render_command(&scene, &out, w, h);
        if !split {
            c.env("BLACKHOLE_NO_SPLIT", "1");
        }
        let (code, stdout, stderr) = run(c);
        assert_clean(code, &stdout, &stderr);
        assert_eq!(
            stderr.contains(pass),
            split,
            "{name}: `{pass}` runs only when split:\n{stderr}"
        );
        image::open(&out).expect("EXR written").to_rgba32f()
    })
}

/// The spinning hole's split ray march (a trace pass that carries the common
/// paths and lists the 2x2 quads where a path needs the rest, then an
/// indirect pass that redoes those quads with the whole shader) draws what
/// the single dispatch draws (`BLACKHOLE_NO_SPLIT=1`): the default view at
/// a* = 0.9 (the disk in front of the shadow: paths into the horizon that
/// meet the disk first) and a view from above the pole (polar motions that
/// never cross the equator). A black sky and a smooth disk, so that what
/// is compared is the paths (to a unit of the half-float image: the trace
/// pass runs the 32-bit roots). Fails when the second pass misses quads (a
/// dropped entry, a short dispatch, a quad split across lanes) or the trace
/// pass keeps a path it cannot carry.
/// Run by tests/device.rs, which lists it as ignored where the device
/// cannot run it (so not a `#[test]` of this file).
pub fn the_spinning_holes_split_draws_what_the_single_dispatch_draws() {
    let dir = scratch();
    let scenes = [
        (
            "front",
            "[[black_hole]]\nspin = 0.9\n[sky]\nkind = \"black\"\n[disk]\nstructure = 0.0\n",
        ),
        (
            "pole",
            "[[black_hole]]\nspin = 0.9\n[sky]\nkind = \"black\"\n[disk]\nstructure = 0.0\n\
             [camera]\nposition = [0.0, 8.0, -0.5]\nlook_at = [0.0, 0.0, 0.0]\n",
        ),
    ];
    // Odd sizes: quads past the image's edge are listed and store nothing.
    for ((name, toml), (w, h)) in scenes.into_iter().zip([(321u32, 181u32), (160, 90)]) {
        let [split, single] = &split_and_single(&dir, name, toml, (w, h), "raymarch rare");
        let lit = single.pixels().filter(|p| p[0] > 0.0).count();
        assert!(
            lit > (w * h / 10) as usize,
            "{name}: the disk fills the view ({lit} pixels)"
        );
        let mut differ = 0;
        for (x, y, s) in single.enumerate_pixels() {
            let t = split.get_pixel(x, y);
            // Within a unit of the half-float image: the trace pass takes
            // the 32-bit roots (exact away from the shadow's edge, where it
            // defers), the one dispatch the device's 64-bit ones.
            let unit = 1.0 / 1024.0;
            if (0..3).any(|k| (t[k] - s[k]).abs() > unit * s[k].abs().max(1.0)) {
                differ += 1;
            }
        }
        assert_eq!(
            differ, 0,
            "{name}: {differ} pixels differ, split against single"
        );
    }
}

/// The thin disk's split ray march (a trace pass that lists the pixels whose
/// path crosses the annulus, then an indirect disk pass over that list)
/// draws what the single dispatch draws (`BLACKHOLE_NO_SPLIT=1`): the
/// structured disk seen with light-travel delay, and a translucent one seen
/// by a falling observer. A black sky, so that the one intended difference
/// cannot show: the split traces the rays an opaque disk stops on to the sky
/// too, so a star next to the disk takes its footprint from both neighbours.
/// Fails when the disk pass misses pixels (a dropped list entry, a short
/// dispatch), shades one twice, or composes the disk over the wrong light.
/// Run by tests/device.rs, which lists it as ignored where the device
/// cannot run it (so not a `#[test]` of this file).
pub fn the_split_disk_pass_draws_what_the_single_dispatch_draws() {
    use blackhole::passes::raymarch::glsl::DEFERRED_ROW;
    let dir = scratch();
    let scenes = [
        (
            "delayed",
            "[sky]\nkind = \"black\"\n[animation]\nlight_travel_time = true\n",
        ),
        (
            "translucent",
            "[sky]\nkind = \"black\"\n[disk]\nstructure = 0.0\nopacity = 0.6\n[camera]\nobserver = \"falling\"\n",
        ),
    ];
    // The larger size lists more pixels than one row of the disk pass's
    // indirect dispatch holds (DEFERRED_ROW workgroups of 64).
    for ((name, toml), (w, h)) in scenes.into_iter().zip([(640u32, 360u32), (160, 90)]) {
        let [split, single] = &split_and_single(&dir, name, toml, (w, h), "raymarch disk");
        let lit = single.pixels().filter(|p| p[0] > 0.0).count();
        assert!(
            lit > (w * h / 10) as usize,
            "{name}: the disk fills the view ({lit} pixels)"
        );
        if w > 160 {
            assert!(
                lit > 2 * DEFERRED_ROW as usize * 64,
                "{name}: more than one row of the dispatch ({lit} pixels)"
            );
        }
        for (x, y, s) in single.enumerate_pixels() {
            let t = split.get_pixel(x, y);
            for k in 0..3 {
                assert!(
                    (t[k] - s[k]).abs() <= 1e-5 * s[k].abs().max(1.0),
                    "{name}: pixel ({x}, {y}) channel {k}: split {} single {}",
                    t[k],
                    s[k]
                );
            }
        }
    }
}
