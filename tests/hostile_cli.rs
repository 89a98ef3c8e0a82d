//! Hostile command lines, round 3 (issue of Step 15): each refused up front
//! with one line naming the option and its rule, exit 2, before any GPU work.

mod common;

use common::{blackhole, refused_early, render_scene, scratch};

/// The one-line refusal of rendering the scene `toml` (with `extra`
/// arguments), checked to leave no output.
fn refused(dir: &tempfile::TempDir, toml: &str, extra: &[&str]) -> String {
    let out = dir.path().join("x.png");
    let mut c = render_scene(dir, toml, extra);
    c.arg("--out").arg(&out);
    let e = refused_early(c);
    assert!(!out.exists(), "{toml}: an output was written");
    e
}

/// A negative number given to a numeric option is that option's value,
/// refused by its own rule (once clap took `-0.5` for an unknown flag and
/// answered "unexpected argument '-0' found").
#[test]
fn negative_numbers_reach_their_options_rule() {
    let dir = scratch();
    let out = dir.path().join("x.png");
    let out = out.to_str().expect("a UTF-8 path");
    for (args, option) in [
        (
            vec!["render", "--shutter", "-0.5", "--out", out],
            "--shutter",
        ),
        (vec!["render", "--width", "-5", "--out", out], "--width"),
        (vec!["render", "--spp", "-2", "--out", out], "--spp"),
        (vec!["window", "--render-scale", "-1"], "--render-scale"),
        (vec!["profile", "--frames", "-3"], "--frames"),
    ] {
        let mut c = blackhole();
        c.args(&args);
        let e = refused_early(c);
        assert!(
            e.contains(option) && e.contains("invalid value") && !e.contains("unexpected argument"),
            "{args:?}: {e}"
        );
    }
    assert!(!dir.path().join("x.png").exists());
}

/// Two outputs of one run naming one file (directly, or through another
/// spelling of its folder) are refused before the GPU: once the trace
/// silently replaced the figures.
#[test]
fn two_outputs_of_one_run_on_one_file_are_refused() {
    let dir = scratch();
    let json = dir.path().join("p.json");
    let again = dir.path().join(".").join("p.json");
    let mut c = blackhole();
    c.args(["profile", "--frames", "1", "--json"])
        .arg(&json)
        .arg("--trace")
        .arg(&again);
    let e = refused_early(c);
    assert!(e.contains("--trace") && e.contains("--json's file"), "{e}");
    assert!(!json.exists());
}

/// `inner_radius = "isco"` resolves to a number the user never wrote: a
/// message quoting it says it is the ISCO of that spin.
#[test]
fn an_isco_inner_radius_is_quoted_as_the_isco() {
    let dir = scratch();
    let e = refused(
        &dir,
        "[[black_hole]]\nspin = -0.998\n[disk]\nouter_radius = 4.0\n",
        &[],
    );
    assert!(
        e.contains("disk.outer_radius = 4")
            && e.contains(
                "\"isco\": 4.4972, the ISCO of black_hole[0] with rs = 1 and spin = -0.998"
            ),
        "{e}"
    );
}

/// Frame rates no video holds (1e-6, 1e9) are refused with the range
/// before any frame is rendered (once every frame rendered, then ffmpeg
/// failed or wrote another rate than the one reported).
#[test]
fn frame_rates_no_video_holds_are_refused_up_front() {
    let dir = scratch();
    for fps in ["1e-6", "1e9", "0.0"] {
        let toml = format!("[animation]\nfps = {fps}\ncamera = \"orbit\"\n");
        let e = refused(&dir, &toml, &["--frames", "0..3"]);
        assert!(
            e.contains("animation.fps") && e.contains("from 0.01 to 1000"),
            "{fps}: {e}"
        );
    }
}

/// Every number of a scene is checked whether or not the chosen mode reads
/// it: `vfov_deg = nan` with the panorama (which ignores it) once passed.
#[test]
fn a_number_the_mode_ignores_is_checked_all_the_same() {
    let dir = scratch();
    let toml = "[camera]\nprojection = \"equirect\"\nvfov_deg = nan\n";
    let e = refused(&dir, toml, &[]);
    assert!(e.contains("camera.vfov_deg = NaN"), "{e}");
}

/// `trace` at a spin of 1e-16 draws the photon paths as at 1e-14 (once it
/// drew none: the critical constant's spherical-orbit form is 0 / 0 there).
#[test]
fn a_vanishing_spin_still_traces_its_photon_paths() {
    let dir = scratch();
    let count = |spin: &str| {
        let scene = dir.path().join("s.toml");
        std::fs::write(&scene, format!("[[black_hole]]\nspin = {spin}\n")).expect("scene");
        let out = dir.path().join(format!("t{spin}.svg"));
        let mut c = blackhole();
        c.args(["trace", "--scene"])
            .arg(&scene)
            .arg("--out")
            .arg(&out);
        let (code, _, stderr) = common::run(c);
        assert_eq!(code, 0, "{stderr}");
        let svg = std::fs::read_to_string(&out).expect("the SVG");
        svg.matches("<polyline").count() + svg.matches("<path").count()
    };
    let (tiny, small) = (count("1e-16"), count("1e-14"));
    assert!(
        tiny > 100 && tiny.abs_diff(small) <= small / 20,
        "{tiny} vs {small}"
    );
}

/// An `"orbiting"` camera on the disk's axis is refused at every spin (once
/// refused at 0 and accepted at 1e-9): one rule, continuous in the spin.
#[test]
fn an_orbit_on_the_axis_is_refused_at_every_spin() {
    let dir = scratch();
    for spin in ["0.0", "1e-9", "0.5", "-0.9"] {
        let toml = format!(
            "[[black_hole]]\nspin = {spin}\n[camera]\nposition = [0.0, 10.0, 0.0]\nup = [0.0, 0.0, 1.0]\nobserver = \"orbiting\"\n"
        );
        let e = refused(&dir, &toml, &[]);
        assert!(
            e.contains("camera.position") && e.contains("disk's axis"),
            "{spin}: {e}"
        );
    }
}

/// `light_travel_time = true` where it cannot act (several holes, whose
/// summed paths carry no clock; the volumetric gas) is refused naming the
/// key, instead of silently doing nothing.
#[test]
fn light_travel_time_where_it_cannot_act_is_refused() {
    let dir = scratch();
    for (toml, why) in [
        (
            "[[black_hole]]\nposition = [0.0, 0.0, 0.0]\n[[black_hole]]\nposition = [20.0, 0.0, 0.0]\n",
            "one hole",
        ),
        ("[disk]\nkind = \"volumetric\"\n", "volumetric"),
    ] {
        let toml = format!("{toml}[animation]\nlight_travel_time = true\n");
        let e = refused(&dir, &toml, &[]);
        assert!(
            e.contains("animation.light_travel_time = true") && e.contains(why),
            "{e}"
        );
    }
}

/// An ODS image's height must split into two equal eyes: odd heights and 1
/// are refused before the GPU, naming --height.
#[test]
fn ods_heights_that_do_not_split_into_two_eyes_are_refused() {
    let dir = scratch();
    let scene = dir.path().join("s.toml");
    std::fs::write(
        &scene,
        "[camera]\nprojection = \"equirect\"\nstereo = \"ods\"\nipd = 0.1\nposition = [0.0, 1.0, -15.0]\n",
    )
    .expect("writing the scene");
    for h in ["1", "7"] {
        let out = dir.path().join("x.png");
        let mut c = blackhole();
        c.args(["render", "--width", "16", "--height", h, "--scene"])
            .arg(&scene)
            .arg("--out")
            .arg(&out);
        let e = refused_early(c);
        assert!(
            e.contains(&format!("--height {h}")) && e.contains("two equal eyes"),
            "{e}"
        );
        assert!(!out.exists());
    }
}

/// Every instant a frame samples (the shutter open, --spp samples) obeys
/// the camera's rules, named by frame, sample and time: a static camera
/// whose later samples stood inside the ergoregion once rendered them as
/// another observer. A still samples frame 0's interval the same way.
#[test]
fn every_instant_a_frame_samples_obeys_the_camera_rules() {
    let dir = scratch();
    let toml = "[[black_hole]]\nspin = 0.9\n[camera]\nposition = [0.0, 0.0, -3.0]\nobserver = \"static\"\n[animation]\ncamera = \"fall\"\nfall_seconds = 1.0\nfps = 1.0\nshutter = 1.0\n";
    for frames in [
        &["--spp", "16", "--frames", "0..1"][..],
        &["--spp", "16"][..],
    ] {
        let e = refused(&dir, toml, frames);
        assert!(
            e.contains("frame 0 (t = 0.9575 s: sample 15 of 16, shutter 1)")
                && e.contains("ergoregion"),
            "{e}"
        );
    }
}

/// Each ODS eye is the observer's own place and obeys its rules: an eye
/// inside the ergoregion of a static camera, or inside the photon sphere
/// of an orbiting one, is refused naming ipd (both once rendered).
#[test]
fn ods_eyes_obey_the_observers_rules() {
    let dir = scratch();
    for (toml, why) in [
        (
            "[[black_hole]]\nspin = 0.9\n[camera]\nposition = [0.0, 0.0, -1.12]\nlook_at = [5.0, 0.0, -1.12]\nobserver = \"static\"\n",
            "ergoregion",
        ),
        (
            "[camera]\nposition = [0.0, 0.3, -1.51]\nlook_at = [5.0, 0.3, -1.51]\nobserver = \"orbiting\"\n",
            "photon sphere",
        ),
    ] {
        let toml = format!("{toml}projection = \"equirect\"\nstereo = \"ods\"\nipd = 0.1\n");
        let e = refused(&dir, &toml, &[]);
        assert!(
            e.contains("camera.ipd = 0.1: puts an eye at") && e.contains(why),
            "{e}"
        );
    }
}

/// `--resume` removes only the temporaries whose writer is gone: one of a
/// run still alive (here this test's own pid: stopped or slow, it would
/// have failed when its file vanished) is left alone.
#[test]
fn resume_leaves_a_live_runs_temporary_alone() {
    let dir = scratch();
    let out = dir.path().join("f.png");
    let live = dir
        .path()
        .join(format!(".f_0001.png.{}.tmp", std::process::id()));
    let dead = dir.path().join(".f_0002.png.999999.tmp");
    std::fs::write(&live, b"half").expect("writes");
    std::fs::write(&dead, b"half").expect("writes");
    let mut c = blackhole();
    c.args([
        "render", "--width", "32", "--height", "18", "--frames", "0..3", "--resume",
    ])
    .arg("--out")
    .arg(&out);
    let (code, stdout, stderr) = common::run(c);
    common::assert_clean(code, &stdout, &stderr);
    assert!(live.exists(), "a live run's temporary was removed");
    assert!(!dead.exists(), "a dead run's temporary is still there");
    assert!(stderr.contains("removed 1 temporary"), "{stderr}");
}

/// SIGTERM during a long still (--spp 1024, most of a minute here) or a
/// many-sample sequence stops it between samples, not after all of them
/// (once about ten seconds later), with exit 130 and no incomplete file.
/// (The bound is loose: a sample takes tens of milliseconds; the full
/// render, tens of seconds.)
#[test]
fn sigterm_during_a_long_still_stops_between_samples() {
    for frames in [&[][..], &["--frames", "0..3"][..]] {
        let dir = scratch();
        let out = dir.path().join("long.png");
        let mut c = blackhole();
        c.args([
            "render", "--spp", "1024", "--width", "640", "--height", "360",
        ])
        .args(frames)
        .arg("--out")
        .arg(&out)
        .stdout(std::process::Stdio::null())
        .stderr(std::process::Stdio::piped());
        let mut child = c.spawn().expect("starts");
        std::thread::sleep(std::time::Duration::from_secs(4));
        let t0 = std::time::Instant::now();
        std::process::Command::new("kill")
            .args(["-TERM", &child.id().to_string()])
            .status()
            .expect("kill");
        let status = child.wait().expect("waits");
        let took = t0.elapsed().as_secs_f64();
        let mut stderr = String::new();
        if let Some(mut e) = child.stderr.take() {
            use std::io::Read;
            let _ = e.read_to_string(&mut stderr);
        }
        assert_eq!(status.code(), Some(130), "{frames:?}: {stderr}");
        assert!(
            took < 6.0,
            "{frames:?}: stopped {took:.1} s after the signal"
        );
        assert!(stderr.contains("interrupted"), "{stderr}");
        assert_eq!(
            std::fs::read_dir(dir.path()).expect("lists").count(),
            0,
            "{frames:?}"
        );
    }
}
