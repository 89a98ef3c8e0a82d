//! What a hostile but realistic user does, each test named after the hazard:
//! wrong output with exit 0, work or data lost, memory or time without
//! bound, checks made too late, messages that point the wrong way. Every
//! refusal is one line, exit status 2, before any GPU work, and leaves no
//! file behind.

mod common;

use std::path::Path;
use std::process::Command;

use common::{assert_clean, blackhole, path_in, refused_early, render_scene, run, scratch};

fn files_in(dir: &Path) -> Vec<String> {
    let mut v: Vec<String> = std::fs::read_dir(dir)
        .expect("listing the scratch folder")
        .map(|e| e.expect("entry").file_name().to_string_lossy().into_owned())
        .collect();
    v.sort();
    v
}

// ---------------------------------------------------------------- wrong output

#[test]
fn a_sky_texel_past_half_float_or_infinite_leaves_every_pixel_finite_and_visible() {
    let dir = scratch();
    // A grey panorama with a sun of 7e4 (past the largest half float), an
    // infinite texel and a NaN one.
    let (w, h) = (64u32, 32u32);
    let mut sky = image::Rgba32FImage::from_pixel(w, h, image::Rgba([0.5, 0.5, 0.5, 1.0]));
    sky.put_pixel(10, 10, image::Rgba([7e4, 7e4, 7e4, 1.0]));
    sky.put_pixel(40, 12, image::Rgba([f32::INFINITY, 1.0, 1.0, 1.0]));
    sky.put_pixel(20, 20, image::Rgba([f32::NAN, 1.0, 1.0, 1.0]));
    // Ensure those texels are seen: fill a band with the sun.
    for x in 0..w {
        sky.put_pixel(x, 16, image::Rgba([7e4, 6e4, 5e4, 1.0]));
    }
    sky.save(path_in(&dir, "sky.exr")).expect("writing the sky");
    let toml = "[sky]\nkind = \"image\"\nimage = \"sky.exr\"\n[disk]\nkind = \"none\"\n";
    for (out, extra) in [
        ("f.png", None),
        ("f.exr", None),
        ("p.exr", Some("--exr-post")),
    ] {
        let path = path_in(&dir, out);
        let mut args = vec!["--out", path.to_str().expect("utf-8 path")];
        args.extend(extra);
        let (code, stdout, stderr) = run(render_scene(&dir, toml, &args));
        assert_clean(code, &stdout, &stderr);
        assert!(
            stderr.contains("sky.exr") && stderr.contains("NaN or infinite"),
            "the bad texels are reported: {stderr}"
        );
        let img = image::open(&path).expect("written").into_rgba32f();
        assert!(
            img.pixels().all(|p| p.0.iter().all(|v| v.is_finite())),
            "{out}: every value finite"
        );
        let mean: f32 = img.pixels().map(|p| p.0[1]).sum::<f32>() / (w * h) as f32;
        assert!(mean > 0.02, "{out}: not black (mean green {mean})");
    }
}

#[test]
fn animated_cameras_obey_the_camera_rules_with_their_key_path() {
    let dir = scratch();
    let key = |body: &str| {
        format!(
            "[animation]\ncamera = \"keyframes\"\n[[animation.keyframe]]\ntime = 0.0\n\
             position = [0.0, 1.0, -15.0]\n[[animation.keyframe]]\ntime = 1.0\n{body}\n"
        )
    };
    for (body, says) in [
        (
            "position = [nan, 0.0, -15.0]",
            "animation.keyframe[1].position",
        ),
        (
            "position = [1e300, 0.0, -15.0]",
            "animation.keyframe[1].position",
        ),
        (
            "position = [0.0, 0.0, -9.0]\nlook_at = [0.0, 0.0, -9.0]",
            "animation.keyframe[1].look_at",
        ),
        (
            "position = [0.0, 1.0, -15.0]\nvfov_deg = 500.0",
            "animation.keyframe[1].vfov_deg",
        ),
        (
            "position = [0.0, 0.0, 0.5]",
            "animation.keyframe[1].position",
        ),
    ] {
        let out = path_in(&dir, "k.png");
        let mut c = render_scene(&dir, &key(body), &["--frames", "0..30", "--out"]);
        c.arg(&out);
        let e = refused_early(c);
        assert!(e.contains(says) && e.contains("scene.toml:"), "{body}: {e}");
    }
    // An orbit through the hole, and one whose radius is inside it.
    for anim in [
        "camera = \"orbit\"\norbit_radius = 0.5",
        "camera = \"orbit\"\ninclination_deg = 0.0\n[camera]\nposition = [0.0, 0.0, -15.0]\n\
         look_at = [0.0, 0.0, -7.5]",
    ] {
        let mut c = render_scene(
            &dir,
            &format!("[animation]\n{anim}\n"),
            &["--frames", "0..30"],
        );
        c.arg("--out").arg(path_in(&dir, "o.png"));
        let e = refused_early(c);
        assert!(e.contains("passes inside the horizon"), "{anim}: {e}");
    }
    // A fall whose line crosses a second hole: the first bad frame is named.
    let fall = "[camera]\nposition = [0.0, 0.0, -20.0]\nlook_at = [1.0, 0.0, 0.0]\n\
                [[black_hole]]\nrs = 1.0\n[[black_hole]]\nposition = [0.0, 0.0, -10.0]\nrs = 1.0\n\
                [animation]\ncamera = \"fall\"\nfps = 10.0\n";
    let mut c = render_scene(&dir, fall, &["--frames", "0..100", "--out"]);
    c.arg(path_in(&dir, "f.png"));
    let e = refused_early(c);
    assert!(
        e.contains("frame ") && e.contains("horizon of black_hole[1]"),
        "{e}"
    );
    assert!(
        files_in(dir.path()).iter().all(|n| !n.ends_with(".png")),
        "nothing written"
    );
}

#[test]
fn impossible_cameras_for_the_projections_are_refused_with_the_key() {
    let dir = scratch();
    for (toml, key, why) in [
        (
            "[camera]\nstereo = \"ods\"\n",
            "camera.stereo",
            "needs camera.projection = \"equirect\"",
        ),
        (
            "[camera]\nprojection = \"fisheye\"\nvfov_deg = 400.0\n",
            "camera.vfov_deg = 400",
            "(0, 360]",
        ),
        (
            "[camera]\nvfov_deg = 200.0\n",
            "camera.vfov_deg = 200",
            "(0, 180)",
        ),
        ("[camera]\nipd = -0.1\n", "camera.ipd = -0.1", ">= 0"),
        (
            "[camera]\nprojection = \"equirect\"\nstereo = \"ods\"\nipd = 0.0\n",
            "camera.ipd = 0",
            "> 0",
        ),
        (
            "[camera]\nposition = [0.0, 0.0, -2.0]\nprojection = \"equirect\"\nstereo = \"ods\"\nipd = 2.5\n",
            "camera.ipd = 2.5",
            "puts an eye within",
        ),
        (
            "[camera]\nprojection = \"cylinder\"\n",
            "projection = \"cylinder\"",
            "expected one of `pinhole`, `equirect`, `fisheye`",
        ),
    ] {
        let e = refused_early(render_scene(&dir, toml, &[]));
        assert!(e.contains(key) && e.contains(why), "{toml}: {e}");
        assert!(e.contains("scene.toml:"), "names the file and line: {e}");
    }
}

#[test]
fn a_volumetric_disk_inside_the_photon_sphere_is_refused() {
    let dir = scratch();
    let c = render_scene(
        &dir,
        "[disk]\nkind = \"volumetric\"\ninner_radius = 1.2\n",
        &[],
    );
    let e = refused_early(c);
    assert!(
        e.contains("disk.inner_radius = 1.2") && e.contains("photon sphere"),
        "{e}"
    );
}

// ---------------------------------------------------------------- work lost

#[test]
fn resume_renders_truncated_and_empty_frames_again_and_removes_stale_temporaries() {
    let dir = scratch();
    let out = path_in(&dir, "f.png");
    let args = |c: &mut Command| {
        c.args([
            "render", "--width", "48", "--height", "27", "--frames", "0..4",
        ])
        .arg("--out")
        .arg(&out);
    };
    let mut c = blackhole();
    args(&mut c);
    let (code, stdout, stderr) = run(c);
    assert_clean(code, &stdout, &stderr);
    let frame = |i: u32| path_in(&dir, &format!("f_{i:04}.png"));
    let whole = std::fs::read(frame(1)).expect("frame 1");
    std::fs::write(frame(1), &whole[..whole.len() / 2]).expect("truncating");
    std::fs::write(frame(2), b"").expect("emptying");
    std::fs::write(path_in(&dir, ".f_0003.png.999999.tmp"), b"half").expect("stale temp");
    let before = std::fs::metadata(frame(0)).and_then(|m| m.modified()).ok();
    let mut c = blackhole();
    args(&mut c);
    c.arg("--resume");
    let (code, stdout, stderr) = run(c);
    assert_clean(code, &stdout, &stderr);
    assert!(
        stderr.contains("f_0001.png (truncated") && stderr.contains("f_0002.png (empty)"),
        "broken frames are reported: {stderr}"
    );
    assert!(stderr.contains("removed 1 temporary"), "{stderr}");
    assert!(
        stdout.contains("wrote 2 frames") && stdout.contains("2 already there"),
        "{stdout}"
    );
    for i in 0..4 {
        let img = image::open(frame(i)).unwrap_or_else(|e| panic!("frame {i}: {e}"));
        assert_eq!((img.width(), img.height()), (48, 27));
    }
    assert_eq!(
        std::fs::metadata(frame(0)).and_then(|m| m.modified()).ok(),
        before,
        "a complete frame is left alone"
    );
    assert!(
        files_in(dir.path()).iter().all(|n| !n.ends_with(".tmp")),
        "{:?}",
        files_in(dir.path())
    );
}

#[test]
fn an_output_naming_an_input_of_the_run_is_refused() {
    let dir = scratch();
    let sky = path_in(&dir, "sky.png");
    image::RgbImage::from_pixel(16, 8, image::Rgb([90, 90, 90]))
        .save(&sky)
        .expect("writing the sky");
    let before = std::fs::read(&sky).expect("sky bytes");
    let toml = "[sky]\nkind = \"image\"\nimage = \"sky.png\"\n";
    let mut c = render_scene(&dir, toml, &["--out"]);
    c.arg(&sky);
    let e = refused_early(c);
    assert!(e.contains("an input of this run"), "{e}");
    // The scene file itself, written by profile's JSON.
    let scene = path_in(&dir, "scene.json");
    std::fs::write(&scene, "[disk]\nkind = \"none\"\n").expect("scene");
    let mut c = blackhole();
    c.args(["profile", "--scene"])
        .arg(&scene)
        .arg("--json")
        .arg(&scene);
    let e = refused_early(c);
    assert!(e.contains("an input of this run"), "{e}");
    assert_eq!(std::fs::read(&sky).expect("sky bytes"), before);
}

#[test]
fn two_quick_signals_leave_no_temporary_and_say_what_was_written() {
    let dir = scratch();
    let out = path_in(&dir, "s.exr");
    let mut c = blackhole();
    c.args([
        "render", "--width", "640", "--height", "360", "--spp", "16", "--frames", "0..1000",
        "--out",
    ])
    .arg(&out)
    .stdout(std::process::Stdio::piped())
    .stderr(std::process::Stdio::piped());
    let child = c.spawn().expect("starts");
    let first = path_in(&dir, "s_0000.exr");
    let t0 = std::time::Instant::now();
    while !first.exists() {
        assert!(t0.elapsed().as_secs() < 120, "no frame after two minutes");
        std::thread::sleep(std::time::Duration::from_millis(5));
    }
    // What `timeout` does: the child, then its process group, in quick
    // succession (far enough apart that the first is handled, not merged
    // with the second by the kernel).
    let term = |pid: u32| {
        Command::new("kill")
            .args(["-TERM", &pid.to_string()])
            .status()
            .expect("kill");
    };
    let mut child = child;
    term(child.id());
    std::thread::sleep(std::time::Duration::from_millis(100));
    // A fast device may have finished the frame in hand and left already.
    let second = child.try_wait().expect("polls").is_none();
    if second {
        term(child.id());
    }
    let done = child.wait_with_output().expect("waits");
    let stderr = String::from_utf8_lossy(&done.stderr);
    assert_eq!(done.status.code(), Some(130), "{stderr}");
    // Before the fix a second signal ended the process without a word.
    assert!(stderr.contains("interrupted: wrote"), "{stderr}");
    if second && !stderr.contains("second signal") {
        println!("the process left after the first signal; the second was not exercised");
    }
    let names = files_in(dir.path());
    assert!(names.iter().all(|n| !n.ends_with(".tmp")), "{names:?}");
    for n in names.iter().filter(|n| n.ends_with(".exr")) {
        image::open(dir.path().join(n)).unwrap_or_else(|e| panic!("{n}: {e}"));
    }
}

// ---------------------------------------------------------------- unbounded

#[test]
fn absurd_frame_ranges_are_refused_at_once() {
    for range in ["0..18446744073709551615", "0..100000000"] {
        let dir = scratch();
        let mut c = blackhole();
        c.args(["render", "--resume", "--frames", range, "--out"])
            .arg(path_in(&dir, "f.png"));
        let t = std::time::Instant::now();
        let e = refused_early(c);
        assert!(e.contains("at most 10000000"), "{e}");
        assert!(t.elapsed().as_secs() < 10, "{range}: {:?}", t.elapsed());
    }
}

#[test]
fn scene_paths_that_are_not_regular_files_are_refused_without_reading_them() {
    let dir = scratch();
    let fifo = path_in(&dir, "pipe.toml");
    let made = Command::new("mkfifo").arg(&fifo).status();
    let big = path_in(&dir, "big.toml");
    std::fs::File::create(&big)
        .and_then(|f| f.set_len(65 << 20))
        .expect("a sparse 65 MB file");
    let mut cases = vec![
        ("/dev/zero".to_string(), "is a device"),
        (dir.path().display().to_string(), "is a folder"),
        (big.display().to_string(), "larger than 64 MB"),
    ];
    if made.is_ok_and(|s| s.success()) {
        cases.push((fifo.display().to_string(), "is a FIFO"));
    }
    for (scene, says) in cases {
        let mut c = blackhole();
        c.args(["render", "--scene", &scene, "--out"])
            .arg(path_in(&dir, "x.png"));
        let e = refused_early(c);
        assert!(e.contains(says), "{scene}: {e}");
    }
    // A sky image that is a folder says so (not "no such file").
    std::fs::create_dir(path_in(&dir, "skydir")).expect("folder");
    let c = render_scene(&dir, "[sky]\nkind = \"image\"\nimage = \"skydir\"\n", &[]);
    let e = refused_early(c);
    assert!(e.contains("sky.image") && e.contains("is a folder"), "{e}");
}

// ---------------------------------------------------------------- too late

#[test]
fn outputs_are_checked_before_any_gpu_work() {
    let dir = scratch();
    std::fs::create_dir(path_in(&dir, "taken.png")).expect("folder");
    let missing = path_in(&dir, "missing/x.json");
    let cases: Vec<(Vec<String>, &str)> = vec![
        (
            vec![
                "render".into(),
                "--out".into(),
                path_in(&dir, "taken.png").display().to_string(),
            ],
            "is a folder",
        ),
        (
            vec![
                "profile".into(),
                "--json".into(),
                missing.display().to_string(),
            ],
            "does not exist",
        ),
        (
            vec![
                "profile".into(),
                "--trace".into(),
                missing.display().to_string(),
            ],
            "does not exist",
        ),
        (
            vec![
                "profile".into(),
                "--json".into(),
                path_in(&dir, "p.csv").display().to_string(),
            ],
            ".json",
        ),
        (
            vec![
                "trace".into(),
                "--out".into(),
                path_in(&dir, "paths.png").display().to_string(),
            ],
            ".svg",
        ),
        (
            vec![
                "window".into(),
                "--screenshot".into(),
                path_in(&dir, "shot.jpg").display().to_string(),
            ],
            ".png",
        ),
        (
            vec![
                "window".into(),
                "--screenshot".into(),
                path_in(&dir, "missing/shot.png").display().to_string(),
            ],
            "does not exist",
        ),
    ];
    for (args, says) in cases {
        let mut c = blackhole();
        c.args(&args);
        let e = refused_early(c);
        assert!(e.contains(says), "{args:?}: {e}");
    }
    assert!(!path_in(&dir, "paths.png").exists());
}

#[test]
fn a_folder_named_like_a_preset_does_not_hide_the_preset() {
    let dir = scratch();
    std::fs::create_dir(path_in(&dir, "grid")).expect("folder");
    let mut c = blackhole();
    c.current_dir(dir.path()).args([
        "render", "--scene", "grid", "--width", "32", "--height", "18", "--out", "g.png",
    ]);
    let (code, stdout, stderr) = run(c);
    assert_clean(code, &stdout, &stderr);
    assert!(
        stderr.contains("is a folder here") && stderr.contains("preset `grid`"),
        "{stderr}"
    );
    // A folder that is no preset is refused, exit 2.
    let mut c = blackhole();
    c.current_dir(dir.path())
        .args(["render", "--scene", ".", "--out", "x.png"]);
    let e = refused_early(c);
    assert!(e.contains("is a folder, not a scene file"), "{e}");
}

#[test]
fn a_look_alike_key_is_pointed_at() {
    let dir = scratch();
    let c = render_scene(&dir, "[c\u{430}mera]\nvfov_deg = 40.0\n", &[]);
    let e = refused_early(c);
    assert!(
        e.contains("scene.toml:1") && e.contains("U+0430") && e.contains("did you mean `camera`"),
        "{e}"
    );
}

#[test]
fn bad_environment_settings_are_errors_naming_them() {
    for (name, value) in [
        ("BLACKHOLE_GPU_TIMEOUT_S", "1ms"),
        ("BLACKHOLE_VALIDATION", "perhaps"),
        ("BLACKHOLE_NO_SPLIT", "please"),
    ] {
        let dir = scratch();
        let mut c = blackhole();
        c.env(name, value)
            .args(["render", "--out"])
            .arg(path_in(&dir, "x.png"));
        let e = refused_early(c);
        assert!(e.contains(name) && e.contains(value), "{e}");
        assert!(!path_in(&dir, "x.png").exists());
    }
}

#[test]
fn a_broken_driver_manifest_is_named_as_such() {
    let dir = scratch();
    let missing_library = path_in(&dir, "missing_lib.json");
    std::fs::write(
        &missing_library,
        r#"{"file_format_version": "1.0.0", "ICD": {"library_path": "/nonexistent/libvulkan_x.so", "api_version": "1.3.0"}}"#,
    )
    .expect("manifest");
    let garbage = path_in(&dir, "garbage.json");
    std::fs::write(&garbage, "{ not json").expect("manifest");
    for manifest in [missing_library, garbage] {
        let mut c = blackhole();
        c.env("VK_ICD_FILENAMES", &manifest)
            .env("VK_DRIVER_FILES", &manifest)
            .args(["render", "--out"])
            .arg(path_in(&dir, "x.png"));
        let (code, _, stderr) = run(c);
        assert_eq!(code, 2, "{stderr}");
        assert!(
            stderr.contains("no Vulkan device")
                && stderr.contains(&manifest.display().to_string())
                && !stderr.contains("host memory"),
            "{stderr}"
        );
    }
}

#[test]
fn a_window_without_a_display_says_how_to_get_one() {
    let mut c = blackhole();
    c.env_remove("DISPLAY")
        .env_remove("WAYLAND_DISPLAY")
        .args(["window", "--frames", "1"]);
    let e = refused_early(c);
    assert!(
        e.contains("no display: set DISPLAY (X11) or WAYLAND_DISPLAY, or run under Xvfb"),
        "{e}"
    );
    assert!(!e.contains(".cargo"), "{e}");
}
