//! The windowed demo under Xvfb (started here when no display is set), driven
//! with xdotool: open, render, resize, unmap and map, screenshot, exit; and a
//! synthetic drag that orbits the camera. Validation is required and silent.

mod common;

use std::process::{Child, Command, Stdio};
use std::sync::OnceLock;
use std::time::{Duration, Instant};

use common::{assert_clean, blackhole, path_in, scratch};

/// The tests share one display and find the window by its title: one at a time.
fn one_at_a_time() -> std::sync::MutexGuard<'static, ()> {
    static LOCK: std::sync::Mutex<()> = std::sync::Mutex::new(());
    LOCK.lock().unwrap_or_else(|p| p.into_inner())
}

/// The display to use: $DISPLAY, or an Xvfb this test process starts.
fn display() -> String {
    static DISPLAY: OnceLock<String> = OnceLock::new();
    DISPLAY
        .get_or_init(|| {
            if let Ok(d) = std::env::var("DISPLAY") {
                if !d.is_empty() {
                    return d;
                }
            }
            // Xvfb picks a free display and writes its number (-displayfd):
            // a fixed number once met another run's Xvfb, which then ended
            // under this one's tests ("X connection broken").
            // Under `timeout`: nothing ends it with the test process (it is
            // shared by the tests), so it ends itself well after the suite.
            let mut child = Command::new("timeout")
                .args([
                    "900",
                    "Xvfb",
                    "-displayfd",
                    "1",
                    "-screen",
                    "0",
                    "1280x1024x24",
                    "-nolisten",
                    "tcp",
                ])
                .stdout(Stdio::piped())
                .stderr(Stdio::null())
                .spawn()
                .expect("Xvfb runs (apt-get install xvfb)");
            let mut number = String::new();
            let out = child.stdout.take().expect("Xvfb's stdout");
            std::io::BufRead::read_line(&mut std::io::BufReader::new(out), &mut number)
                .expect("Xvfb says its display");
            assert!(!number.trim().is_empty(), "Xvfb did not start");
            let d = format!(":{}", number.trim());
            // Left running for the other tests.
            std::mem::forget(child);
            d
        })
        .clone()
}

fn xdotool(args: &[&str]) -> String {
    let out = Command::new("xdotool")
        .args(args)
        .env("DISPLAY", display())
        .output()
        .expect("xdotool runs (apt-get install xdotool)");
    String::from_utf8_lossy(&out.stdout).trim().to_owned()
}

/// Waits for the window of `child` to appear; returns its X id.
fn window_id(child: &mut Child) -> String {
    let start = Instant::now();
    loop {
        let id = xdotool(&["search", "--sync", "--onlyvisible", "--name", "^blackhole$"]);
        if let Some(first) = id.lines().next() {
            return first.to_owned();
        }
        assert!(
            child.try_wait().expect("polling the window").is_none(),
            "the window exited before it appeared"
        );
        assert!(
            start.elapsed() < Duration::from_secs(60),
            "no window after 60 s"
        );
        std::thread::sleep(Duration::from_millis(200));
    }
}

/// Opens the window (it runs until Esc, or 100,000 frames).
fn spawn_window(shot: &std::path::Path) -> Child {
    spawn_window_with(shot, &[])
}

/// The same, with extra arguments.
fn spawn_window_with(shot: &std::path::Path, extra: &[&std::ffi::OsStr]) -> Child {
    let mut c = blackhole();
    c.env("DISPLAY", display())
        .args([
            "window",
            "--width",
            "640",
            "--height",
            "360",
            "--render-scale",
            "0.5",
        ])
        .args(["--frames", "100000", "--screenshot"])
        .arg(shot)
        .args(extra)
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    c.spawn().expect("the blackhole binary runs")
}

/// Presses `key` in the window (focused first: synthetic events sent to a
/// window are ignored, real ones through XTEST go to the focus).
fn press(id: &str, key: &str) {
    xdotool(&["windowfocus", "--sync", id]);
    xdotool(&["key", key]);
}

/// Lets the window render for a while, presses Esc and collects the run;
/// checks it presented at least `min_frames`.
fn finish(child: Child, id: &str, min_frames: u64) -> (i32, String, String) {
    std::thread::sleep(Duration::from_millis(1500));
    press(id, "Escape");
    let out = child.wait_with_output().expect("waiting for the window");
    let err = String::from_utf8_lossy(&out.stderr);
    let presented: u64 = err
        .lines()
        .find_map(|l| {
            l.strip_prefix("presented ")?
                .split(' ')
                .next()?
                .parse()
                .ok()
        })
        .unwrap_or(0);
    assert!(
        presented >= min_frames,
        "presented {presented} frames:\n{err}"
    );
    (
        out.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&out.stdout).into_owned(),
        String::from_utf8_lossy(&out.stderr).into_owned(),
    )
}

fn luma(img: &image::RgbImage, x0: u32, y0: u32, w: u32, h: u32) -> f64 {
    let mut sum = 0.0;
    for y in y0..y0 + h {
        for x in x0..x0 + w {
            let p = img.get_pixel(x, y);
            sum += 0.2126 * f64::from(p[0]) + 0.7152 * f64::from(p[1]) + 0.0722 * f64::from(p[2]);
        }
    }
    sum / f64::from(w * h) / 255.0
}

#[test]
fn window_renders_resizes_survives_unmap_and_takes_a_screenshot() {
    let _one = one_at_a_time();
    let dir = scratch();
    let shot = path_in(&dir, "window.png");
    let mut child = spawn_window(&shot);
    let id = window_id(&mut child);
    std::thread::sleep(Duration::from_millis(1000));
    xdotool(&["windowsize", "--sync", &id, "800", "450"]);
    std::thread::sleep(Duration::from_millis(500));
    xdotool(&["windowunmap", "--sync", &id]);
    std::thread::sleep(Duration::from_millis(500));
    xdotool(&["windowmap", "--sync", &id]);
    // It kept presenting across the resize and the unmap (how many frames in
    // these 3.5 s depends on the machine: 29 seen on a slow two-core one).
    let (code, out, err) = finish(child, &id, 10);
    assert_clean(code, &out, &err);

    let img = image::open(&shot)
        .expect("the screenshot is a PNG")
        .to_rgb8();
    assert_eq!(
        img.dimensions(),
        (800, 450),
        "the screenshot follows the resize"
    );
    // The view right of the panel (folded to a bar: the window started
    // narrow): the hole's shadow sits just above the view's centre (the
    // disk's near side crosses the centre), with bright disk light and
    // stars around it.
    let (x0, w, h) = view_of(&err);
    assert!(
        x0 > 0 && x0 < 60 && w == 800 - x0 && h == 450,
        "view {x0} {w} {h}"
    );
    let cx = x0 + w / 2;
    let shadow = luma(&img, cx - 10, 180, 20, 16);
    let around = luma(&img, cx + 160, 200, 200, 50);
    assert!(shadow < 0.05, "the shadow is not dark: {shadow}");
    assert!(
        around > shadow + 0.05,
        "no structure around the hole: {around}"
    );
}

/// The view's first column, width and height, as the window said at exit.
fn view_of(err: &str) -> (u32, u32, u32) {
    let line = err
        .lines()
        .find_map(|l| l.strip_prefix("view at x "))
        .unwrap_or_else(|| panic!("no view line:\n{err}"));
    let n: Vec<u32> = line.split(' ').filter_map(|t| t.parse().ok()).collect();
    assert_eq!(n.len(), 3, "view line: {line}");
    (n[0], n[1], n[2])
}

#[test]
fn a_small_window_shows_the_hole_in_the_middle_of_its_free_view() {
    let _one = one_at_a_time();
    let dir = scratch();
    let shot = path_in(&dir, "small.png");
    let mut child = spawn_window(&shot);
    let id = window_id(&mut child);
    let (code, out, err) = finish(child, &id, 2);
    assert_clean(code, &out, &err);
    let img = image::open(&shot).expect("PNG").to_rgb8();
    assert_eq!(img.dimensions(), (640, 360));
    // At 640 pixels wide the panel starts folded to a thin bar at the left:
    // the view keeps more than nine tenths of the window.
    let (x0, w, h) = view_of(&err);
    assert!(
        x0 > 0 && w > 576 && x0 + w == 640 && h == 360,
        "view {x0} {w} {h}"
    );
    // The bar is the panel's grey, not the picture.
    let bar = luma(&img, 2, 100, x0 - 4, 160);
    assert!(bar > 0.05, "no panel bar at the left: {bar}");
    // The shadow at the centre of the free view (just above: the disk's
    // near side crosses the middle), bright disk light left and right of it
    // at the same height (the view is centred, not cut by the panel).
    let cx = x0 + w / 2;
    let shadow = luma(&img, cx - 8, 140, 16, 12);
    assert!(
        shadow < 0.05,
        "no shadow at the view's centre x {cx}: {shadow}"
    );
    let left = luma(&img, x0 + 10, 182, 40, 24);
    let right = luma(&img, 640 - 50, 182, 40, 24);
    assert!(
        left > 0.1 && right > 0.1,
        "the disk is not across the whole view: left {left}, right {right}"
    );
}

#[test]
fn a_left_drag_orbits_the_camera_around_the_hole() {
    let _one = one_at_a_time();
    let dir = scratch();
    let still = path_in(&dir, "still.png");
    let dragged = path_in(&dir, "dragged.png");
    let mut child = spawn_window(&still);
    let id = window_id(&mut child);
    // H hides the panel, so the whole view shows.
    press(&id, "h");
    let (code, out, err) = finish(child, &id, 2);
    assert_clean(code, &out, &err);

    let mut child = spawn_window(&dragged);
    let id = window_id(&mut child);
    press(&id, "h");
    std::thread::sleep(Duration::from_millis(1000));
    xdotool(&["mousemove", "--window", &id, "500", "80"]);
    xdotool(&["mousedown", "1"]);
    for step in 1..=10 {
        let x = (500 + 8 * step).to_string();
        xdotool(&["mousemove", "--window", &id, &x, "80"]);
        std::thread::sleep(Duration::from_millis(50));
    }
    xdotool(&["mouseup", "1"]);
    let (code, out, err) = finish(child, &id, 2);
    assert_clean(code, &out, &err);

    let a = image::open(&still).expect("PNG").to_rgb8();
    let b = image::open(&dragged).expect("PNG").to_rgb8();
    // An orbit keeps the hole at the centre (the camera still looks at it)...
    assert!(
        luma(&a, 312, 144, 16, 12) < 0.05,
        "no shadow at the centre before the drag"
    );
    assert!(
        luma(&b, 312, 144, 16, 12) < 0.05,
        "the hole left the centre"
    );
    // ...while the sky behind it turns: the picture changes.
    let (mut changed, mut total) = (0u32, 0u32);
    for y in (0..360).step_by(2) {
        for x in (0..640).step_by(2) {
            total += 1;
            let (p, q) = (a.get_pixel(x, y), b.get_pixel(x, y));
            if (0..3).any(|c| p[c].abs_diff(q[c]) > 24) {
                changed += 1;
            }
        }
    }
    assert!(
        f64::from(changed) > 0.05 * f64::from(total),
        "the drag changed only {changed} of {total} pixels"
    );
}

#[test]
fn a_scene_saved_from_the_panel_loads_back_unchanged() {
    let dir = scratch();
    let path = path_in(&dir, "saved.toml");
    let mut scene = blackhole::Scene::load("doppler").expect("preset");
    scene.camera.position = [3.0, 4.0, -12.0];
    scene.disk.temperature_k = 7321.0;
    scene.bloom.levels = 5;
    let p = path.to_str().expect("utf-8 path");
    blackhole::app::editors::save_scene(&scene, p).expect("saves");
    let mut back = blackhole::Scene::load(p).expect("loads");
    // Where it was read from is not part of the scene.
    assert_eq!(back.source.as_deref(), Some(path.as_path()));
    back.base_dir = scene.base_dir.clone();
    back.source = scene.source.clone();
    assert_eq!(back, scene);
}

#[test]
fn the_window_survives_200_random_resizes_and_a_minimise() {
    let _one = one_at_a_time();
    let dir = scratch();
    let shot = path_in(&dir, "resized.png");
    let mut child = spawn_window(&shot);
    let id = window_id(&mut child);
    std::thread::sleep(Duration::from_millis(500));
    // A fixed pseudo-random walk of sizes, tiny to large, some sent without
    // waiting so the swapchain goes out of date mid-frame.
    let mut state = 0x9e37_79b9u32;
    let mut next = |n: u32| {
        state ^= state << 13;
        state ^= state >> 17;
        state ^= state << 5;
        state % n
    };
    for i in 0..200 {
        let (w, h) = match i % 10 {
            0 => (1 + next(4), 1 + next(4)),
            _ => (16 + next(1200), 16 + next(700)),
        };
        let (w, h) = (w.to_string(), h.to_string());
        if i % 3 == 0 {
            xdotool(&["windowsize", "--sync", &id, &w, &h]);
        } else {
            xdotool(&["windowsize", &id, &w, &h]);
        }
        if i == 100 {
            xdotool(&["windowminimize", "--sync", &id]);
            std::thread::sleep(Duration::from_millis(300));
            xdotool(&["windowmap", "--sync", &id]);
        }
    }
    xdotool(&["windowsize", "--sync", &id, "640", "360"]);
    // It kept presenting through the walk (how many frames depends on how
    // busy the machine is: 24 seen on a loaded two-core machine, 60 idle).
    let (code, out, err) = finish(child, &id, 10);
    assert_clean(code, &out, &err);
    let img = image::open(&shot).expect("a screenshot").to_rgb8();
    assert_eq!(img.dimensions(), (640, 360));
}

/// A long run (`cargo test --release --test window -- --ignored
/// --nocapture`): 1,000 windowed frames under Xvfb with validation on,
/// resident memory sampled through the run.
#[test]
#[ignore = "long run: about a minute under Xvfb"]
fn a_thousand_window_frames_hold_memory_flat() {
    let _one = one_at_a_time();
    let mut c = blackhole();
    c.env("DISPLAY", display())
        .args([
            "window", "--width", "320", "--height", "180", "--frames", "1000",
        ])
        .stdout(Stdio::piped())
        .stderr(Stdio::piped());
    let child = c.spawn().expect("the blackhole binary runs");
    let pid = child.id();
    let mut samples = Vec::new();
    let t = std::time::Instant::now();
    while t.elapsed().as_secs() < 600 {
        let rss = common::rss_mb(pid);
        if rss == 0.0 {
            break;
        }
        samples.push(rss);
        std::thread::sleep(Duration::from_millis(500));
    }
    let out = child.wait_with_output().unwrap();
    let err = String::from_utf8_lossy(&out.stderr).into_owned();
    assert_clean(
        out.status.code().unwrap_or(-1),
        &String::from_utf8_lossy(&out.stdout),
        &err,
    );
    assert!(err.contains("presented 1000"), "{err}");
    // From a tenth of the run (after start-up) to its last sample.
    let start = samples[samples.len() / 10];
    let end = samples[samples.len().saturating_sub(2)];
    println!(
        "1,000 window frames in {:.0} s: resident {start:.1} MB early, {end:.1} MB late ({} samples)",
        t.elapsed().as_secs_f64(),
        samples.len()
    );
    assert!(
        end - start < 20.0,
        "resident memory grew by {:.1} MB",
        end - start
    );
}

/// F drops the camera from the view into the hole (a one-second fall here)
/// through the horizon: the view down the fall is black across its middle
/// (the region whose light came from the other universe, and the shadow
/// around it), where the view from outside shows the disk; F again returns.
/// The same into a spinning hole (a* = 0.9), whose fall ends just outside
/// its inner horizon.
#[test]
fn f_falls_through_the_horizon_and_f_again_returns() {
    let _one = one_at_a_time();
    for spin in ["0.0", "0.9"] {
        let dir = scratch();
        let scene = path_in(&dir, "scene.toml");
        let toml = format!("[[black_hole]]\nspin = {spin}\n[animation]\nfall_seconds = 1.0\n");
        std::fs::write(&scene, toml).expect("writing the scene");
        let shot = |name: &str, presses: &[&str]| {
            let out = path_in(&dir, name);
            let args = [std::ffi::OsStr::new("--scene"), scene.as_os_str()];
            let mut child = spawn_window_with(&out, &args);
            let id = window_id(&mut child);
            press(&id, "h");
            // Time for the first frames: with a cold pipeline cache the
            // spinning hole's ray march alone took lavapipe 2.5 s to build
            // here (the test once failed with one frame presented).
            std::thread::sleep(Duration::from_millis(3000));
            for p in presses {
                press(&id, p);
                std::thread::sleep(Duration::from_millis(2500));
            }
            let (code, stdout, stderr) = finish(child, &id, 2);
            assert_clean(code, &stdout, &stderr);
            image::open(&out).expect("PNG").to_rgb8()
        };
        let middle = |img: &image::RgbImage| luma(img, 220, 110, 200, 140);
        let outside = shot("outside.png", &[]);
        let inside = shot("inside.png", &["f"]);
        let back = shot("back.png", &["f", "f"]);
        assert!(
            middle(&outside) > 0.05,
            "spin {spin}: the disk is not in the middle outside"
        );
        // Spinning, the bright ring of blueshifted light runs off-centre,
        // across the middle: there, most of the view is black.
        let dark = if spin == "0.0" {
            middle(&inside) < 0.01
        } else {
            let n = inside
                .pixels()
                .filter(|p| p.0.iter().all(|&c| c < 32))
                .count();
            n as f64 > 0.8 * f64::from(inside.width() * inside.height())
        };
        assert!(
            dark,
            "spin {spin}: the view down the fall is not black after it: {}",
            middle(&inside)
        );
        assert!(middle(&back) > 0.05, "spin {spin}: F again did not return");
    }
}
