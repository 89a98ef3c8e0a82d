//! Film: the shutter (the --spp samples spread over the open part of each
//! frame's interval, so motion blurs) and sequences written straight to
//! video through ffmpeg (installed by the README's package line).

mod common;

use std::process::{Command, Stdio};

use common::{SceneSrc, assert_clean, blackhole, path_in, render_png, run, scratch};

/// An orbiting camera (90 degrees a second: 3 degrees, about 8 pixels at
/// 160 wide, within a frame at 30 fps) over the checker sky, no disk.
const ORBIT: &str = "[disk]\nkind = \"none\"\n[sky]\nkind = \"checker\"\n[animation]\ncamera = \"orbit\"\norbit_speed_deg = 90.0\nshutter = SHUTTER\n";

/// The share of steep horizontal steps (more than 40 of 255 levels between
/// neighbours) in the outer thirds of the picture, where the sky turns
/// with the camera and the hole's lensing does not hide the motion.
fn steep_share(img: &image::RgbImage) -> f64 {
    let luma = |x: u32, y: u32| {
        let p = img.get_pixel(x, y);
        0.2126 * f64::from(p[0]) + 0.7152 * f64::from(p[1]) + 0.0722 * f64::from(p[2])
    };
    let (w, h) = img.dimensions();
    let (mut steep, mut all) = (0u32, 0u32);
    for y in 0..h {
        for x in (0..w / 3).chain(2 * w / 3..w - 1) {
            all += 1;
            if (luma(x + 1, y) - luma(x, y)).abs() > 40.0 {
                steep += 1;
            }
        }
    }
    f64::from(steep) / f64::from(all)
}

/// The temporaries in `dir`.
fn temporaries(dir: &tempfile::TempDir) -> Vec<std::path::PathBuf> {
    std::fs::read_dir(dir.path())
        .expect("lists")
        .filter_map(|e| e.ok())
        .map(|e| e.path())
        .filter(|p| p.to_string_lossy().ends_with(".tmp"))
        .collect()
}

/// Starts a 100,000-frame video to `out` (its output streams made by
/// `stdio`) and waits until frames are going in.
fn start_long_video(
    dir: &tempfile::TempDir,
    out: &std::path::Path,
    stdio: fn() -> Stdio,
) -> std::process::Child {
    let mut c = blackhole();
    c.args([
        "render",
        "--width",
        "320",
        "--height",
        "180",
        "--frames",
        "0..100000",
    ])
    .arg("--out")
    .arg(out)
    .stdout(stdio())
    .stderr(stdio());
    let child = c.spawn().expect("starts");
    wait_for_frames_going_in(dir);
    child
}

/// Waits for a video's temporary (ffmpeg started), then half a second more
/// (frames going in).
fn wait_for_frames_going_in(dir: &tempfile::TempDir) {
    let t0 = std::time::Instant::now();
    while temporaries(dir).is_empty() {
        assert!(
            t0.elapsed().as_secs() < 120,
            "no temporary after two minutes"
        );
        std::thread::sleep(std::time::Duration::from_millis(20));
    }
    std::thread::sleep(std::time::Duration::from_millis(500));
}

#[test]
fn an_open_shutter_blurs_an_orbiting_camera_and_stays_deterministic() {
    let dir = scratch();
    let frame = |name: &str, shutter: &str, extra: &[&str]| {
        let scene = path_in(&dir, &format!("{name}.toml"));
        std::fs::write(&scene, ORBIT.replace("SHUTTER", shutter)).expect("scene");
        let out = path_in(&dir, &format!("{name}.png"));
        let mut c = blackhole();
        c.args(["render", "--width", "160", "--height", "90", "--spp", "8"])
            .args(extra)
            .arg("--scene")
            .arg(&scene)
            .arg("--out")
            .arg(&out);
        let (code, stdout, stderr) = run(c);
        assert_clean(code, &stdout, &stderr);
        image::open(&out).expect("PNG").to_rgb8()
    };
    let sharp = frame("closed", "0.0", &[]);
    let blurred = frame("open", "1.0", &[]);
    let (s, b) = (steep_share(&sharp), steep_share(&blurred));
    println!("steep steps in the outer thirds: shutter 0 {s:.4}, shutter 1 {b:.4}");
    assert!(s > 0.02, "the closed shutter's checkers have edges: {s}");
    assert!(b < 0.75 * s, "shutter 1 is not softer: {b} against {s}");
    // The same frame again (and through --shutter, which overrides the
    // scene's key): identical, so sharded sequences match.
    let again = frame("open_again", "0.0", &["--shutter", "1"]);
    assert!(
        again.as_raw() == blurred.as_raw(),
        "the shutter's samples are not deterministic"
    );
}

#[test]
fn a_twelve_frame_mp4_has_twelve_frames() {
    let dir = scratch();
    let out = path_in(&dir, "film.mp4");
    let mut c = blackhole();
    c.args([
        "render", "--width", "96", "--height", "54", "--frames", "0..12",
    ])
    .args(["--scene", "doppler", "--out"])
    .arg(&out);
    let (code, stdout, stderr) = run(c);
    assert_clean(code, &stdout, &stderr);
    assert!(stdout.contains("12 frames"), "{stdout}");
    let probe = Command::new("ffprobe")
        .args(["-v", "error", "-count_frames", "-select_streams", "v:0"])
        .args([
            "-show_entries",
            "stream=nb_read_frames,codec_name,width,height,r_frame_rate",
        ])
        .args(["-of", "default=noprint_wrappers=1"])
        .arg(&out)
        .output()
        .expect("ffprobe runs (the README's packages include ffmpeg)");
    let info = String::from_utf8_lossy(&probe.stdout);
    println!("{info}");
    for want in [
        "codec_name=h264",
        "width=96",
        "height=54",
        "r_frame_rate=30/1",
        "nb_read_frames=12",
    ] {
        assert!(info.lines().any(|l| l == want), "{want} in:\n{info}");
    }
    // Nothing else left beside it (the temporary was renamed).
    let names: Vec<_> = std::fs::read_dir(dir.path())
        .expect("lists")
        .map(|e| e.expect("entry").file_name())
        .collect();
    assert_eq!(names.len(), 1, "{names:?}");
}

#[test]
fn video_without_ffmpeg_is_refused_in_one_line_naming_the_package() {
    let dir = scratch();
    let out = path_in(&dir, "film.webm");
    let empty = path_in(&dir, "bin");
    std::fs::create_dir(&empty).expect("mkdir");
    let mut c = blackhole();
    c.env("PATH", &empty)
        .args([
            "render", "--width", "64", "--height", "36", "--frames", "0..3", "--out",
        ])
        .arg(&out);
    let (code, _, stderr) = run(c);
    assert_eq!(code, 2, "{stderr}");
    let errors: Vec<&str> = stderr.lines().filter(|l| l.starts_with("error:")).collect();
    assert_eq!(errors.len(), 1, "{stderr}");
    assert!(
        errors[0].contains("ffmpeg") && errors[0].contains("apt-get install ffmpeg"),
        "{stderr}"
    );
    assert!(!out.exists());
}

#[test]
fn an_interrupted_video_leaves_no_file() {
    let dir = scratch();
    let out = path_in(&dir, "film.mp4");
    let mut child = start_long_video(&dir, &out, Stdio::piped);
    Command::new("kill")
        .args(["-INT", &child.id().to_string()])
        .status()
        .expect("kill");
    let status = child.wait().expect("waits");
    let mut stderr = String::new();
    if let Some(mut e) = child.stderr.take() {
        use std::io::Read;
        let _ = e.read_to_string(&mut stderr);
    }
    assert_eq!(status.code(), Some(130), "{stderr}");
    assert!(stderr.contains("film.mp4 not written"), "{stderr}");
    let names: Vec<_> = std::fs::read_dir(dir.path())
        .expect("lists")
        .map(|e| e.expect("entry").file_name())
        .collect();
    assert!(names.is_empty(), "left behind: {names:?}");
}

#[test]
fn a_dome_frame_goes_to_video_black_outside_its_circle() {
    // The fisheye's corners have no ray: black in the video as in the PNG.
    let dir = scratch();
    let toml = "[camera]\nprojection = \"fisheye\"\nvfov_deg = 180.0\n";
    let png = render_png(&dir, "dome", SceneSrc::Toml(toml), 64, 64);
    assert_eq!(png.get_pixel(0, 0).0, [0, 0, 0]);
    let scene = path_in(&dir, "dome.toml");
    let out = path_in(&dir, "dome.mov");
    let mut c = blackhole();
    c.args([
        "render", "--width", "64", "--height", "64", "--frames", "0..2", "--scene",
    ])
    .arg(&scene)
    .arg("--out")
    .arg(&out);
    let (code, stdout, stderr) = run(c);
    assert_clean(code, &stdout, &stderr);
    // The first frame back as 8-bit RGB: the corner is black.
    let raw = Command::new("ffmpeg")
        .args(["-v", "error", "-i"])
        .arg(&out)
        .args([
            "-frames:v",
            "1",
            "-f",
            "rawvideo",
            "-pix_fmt",
            "rgb24",
            "pipe:1",
        ])
        .output()
        .expect("ffmpeg decodes");
    assert_eq!(
        raw.stdout.len(),
        64 * 64 * 3,
        "{}",
        String::from_utf8_lossy(&raw.stderr)
    );
    assert!(
        raw.stdout[..3].iter().all(|&v| v < 8),
        "{:?}",
        &raw.stdout[..3]
    );
    // Inside the circle the disk shows.
    let brightest = raw.stdout.iter().copied().max().unwrap_or(0);
    assert!(brightest > 60, "nothing bright in the dome: {brightest}");
}

/// Output paths reach ffmpeg literally, never as URLs: a folder named
/// `10:30` (once "Protocol not found" after every frame) and one named
/// `file:x` (once written elsewhere) each get their video, and nothing else
/// is left beside it.
#[test]
fn video_paths_that_look_like_urls_are_written_where_they_say() {
    let dir = scratch();
    for folder in ["10:30", "file:x"] {
        let sub = dir.path().join(folder);
        std::fs::create_dir(&sub).expect("a folder");
        let out = sub.join("v.mp4");
        let mut c = blackhole();
        c.args([
            "render", "--width", "64", "--height", "36", "--frames", "0..3",
        ])
        .args(["--scene", "doppler", "--out"])
        .arg(&out);
        let (code, stdout, stderr) = run(c);
        assert_clean(code, &stdout, &stderr);
        assert!(out.is_file(), "{folder}: no video");
        assert_eq!(
            std::fs::read_dir(&sub).expect("lists").count(),
            1,
            "{folder}"
        );
    }
    // Nothing written beside the folders (file:x's ffmpeg once wrote to x/).
    assert_eq!(std::fs::read_dir(dir.path()).expect("lists").count(), 2);
}

/// A disk that fills while ffmpeg encodes (here a file-size limit, whose
/// writes then fail as on a full disk): ffmpeg may still exit 0 over a
/// video without its index (MP4) or cut short (WebM); the run reads the
/// video back, fails (exit 1) and leaves nothing under the final name.
#[test]
fn a_disk_full_while_encoding_fails_the_run_and_leaves_no_file() {
    let dir = scratch();
    for ext in ["mp4", "webm"] {
        let out = dir.path().join(format!("v.{ext}"));
        let mut c = Command::new("bash");
        c.arg("-c")
            .arg(format!(
                "ulimit -f 8; trap '' XFSZ; exec \"{}\" render --scene doppler --width 320 --height 180 --frames 0..60 --out \"{}\"",
                env!("CARGO_BIN_EXE_blackhole"),
                out.display()
            ));
        // (The renderer's environment for tests: validation on, the cache.)
        for (k, v) in blackhole().get_envs() {
            if let Some(v) = v {
                c.env(k, v);
            }
        }
        let (code, _, stderr) = run(c);
        assert_eq!(code, 1, "{ext}: {stderr}");
        assert!(
            stderr.contains("incomplete video") && stderr.contains("not written"),
            "{stderr}"
        );
        let left: Vec<_> = std::fs::read_dir(dir.path())
            .expect("lists")
            .map(|e| e.expect("entry").file_name())
            .collect();
        assert!(left.is_empty(), "{ext}: left {left:?}");
    }
}

/// Killed outright (SIGKILL), the renderer takes ffmpeg with it (once the
/// encoder went on finishing a hidden temporary); the next run of the same
/// output removes what the dead run left, and a live run's temporary is
/// never touched.
#[test]
fn a_killed_video_run_takes_its_encoder_and_the_next_run_cleans_up() {
    let dir = scratch();
    let out = path_in(&dir, "film.mp4");
    let mut child = start_long_video(&dir, &out, Stdio::null);
    child.kill().expect("SIGKILL");
    child.wait().expect("waits");
    // The encoder went with it: the temporary stops growing at once.
    std::thread::sleep(std::time::Duration::from_millis(500));
    let left = temporaries(&dir);
    assert_eq!(left.len(), 1, "{left:?}");
    let size = |p: &std::path::Path| std::fs::metadata(p).map(|m| m.len()).unwrap_or(0);
    let before = size(&left[0]);
    std::thread::sleep(std::time::Duration::from_millis(1500));
    assert_eq!(size(&left[0]), before, "ffmpeg outlived the renderer");
    // A live run's temporary of the same name pattern is not touched.
    let live = dir
        .path()
        .join(format!(".film.mp4.{}.tmp", std::process::id()));
    std::fs::write(&live, b"a live run's").expect("writes");
    let mut c = blackhole();
    c.args([
        "render", "--width", "64", "--height", "36", "--frames", "0..2",
    ])
    .arg("--out")
    .arg(&out);
    let (code, stdout, stderr) = run(c);
    assert_clean(code, &stdout, &stderr);
    assert!(out.is_file());
    assert!(!left[0].exists(), "the dead run's temporary is still there");
    assert!(live.exists(), "a live run's temporary was removed");
}
