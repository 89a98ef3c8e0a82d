//! Round four of the hostile user, each test named after the hazard: a
//! contradictory fall, derived values quoted as if written, empty
//! environment variables, messages whose digits contradict them, and the
//! same refusal worded two ways. Every refusal is one line, exit status 2,
//! before any GPU work, and leaves no file behind.

mod common;

use common::{assert_clean, blackhole, path_in, refused_early, render_scene, run, scratch};

fn refused(toml: &str) -> String {
    let dir = scratch();
    let out = path_in(&dir, "x.png");
    let e = refused_early(render_scene(
        &dir,
        toml,
        &["--out", out.to_str().expect("utf-8")],
    ));
    assert!(!out.exists(), "no output after a refusal");
    e
}

#[test]
fn a_fall_that_ends_above_its_start_is_refused_naming_both_radii() {
    let e = refused(
        "[camera]\nposition = [0.0, 0.0, 4.0]\nobserver = \"falling\"\n\
         [animation]\ncamera = \"fall\"\nfall_end_radius = 6.0\n",
    );
    assert!(
        e.contains("fall_end_radius = 6") && e.contains("starts 4.000 rs") && e.contains(":6:"),
        "{e}"
    );
    // The same for the window's fall (F), whatever the animation's camera.
    let e = refused("[camera]\nposition = [0.0, 0.0, 4.0]\n[animation]\nfall_end_radius = 4.0\n");
    assert!(e.contains("inward"), "{e}");
}

#[test]
fn a_value_derived_from_another_key_names_the_key_that_made_it() {
    // rs = 1e9 (the top of its range): the default inner radius, the ISCO
    // (3e9), is no longer quoted as if the user had written it.
    let e = refused("[[black_hole]]\nrs = 1e8\n[camera]\nposition = [0.0, 0.0, 9e8]\n");
    assert!(
        e.contains("disk.outer_radius = 12 (the default")
            && e.contains("the ISCO of black_hole[0] with rs = 100000000"),
        "{e}"
    );
    let e = refused("[[black_hole]]\nrs = 1e9\n");
    assert!(
        e.contains("camera.position = [0, 0.8, -15] (the default"),
        "{e}"
    );
    // With no disk to draw the derived radius is not checked at all.
    let dir = scratch();
    let out = path_in(&dir, "x.png");
    let toml = "[[black_hole]]\nrs = 1e9\n[disk]\nkind = \"none\"\n\
                [camera]\nposition = [0.0, 0.0, 5e8]\nobserver = \"falling\"\n";
    let (code, stdout, stderr) = run(render_scene(
        &dir,
        toml,
        &["--out", out.to_str().expect("utf-8")],
    ));
    assert_clean(code, &stdout, &stderr);
    assert!(out.exists());
}

#[test]
fn an_empty_environment_variable_is_refused_like_any_bad_value() {
    for name in [
        "BLACKHOLE_NO_QUAD",
        "BLACKHOLE_NO_SPLIT",
        "BLACKHOLE_NO_F64",
        "BLACKHOLE_NO_BAKE",
        "BLACKHOLE_VALIDATION",
        "BLACKHOLE_GPU_TIMEOUT_S",
    ] {
        let dir = scratch();
        let mut c = blackhole();
        c.env(name, "")
            .args(["render", "--out"])
            .arg(path_in(&dir, "x.png"));
        let e = refused_early(c);
        assert!(e.contains(name) && e.contains("empty"), "{e}");
    }
    // (refused_early names a device of its own: this one by hand.)
    let mut c = blackhole();
    c.env("BLACKHOLE_DEVICE", "")
        .args(["render", "--out", "/nonexistent/x.png"]);
    let (code, _, stderr) = run(c);
    assert!(
        code == 2 && stderr.contains("BLACKHOLE_DEVICE is set but empty"),
        "{stderr}"
    );
}

#[test]
fn a_refusal_prints_enough_digits_to_show_why() {
    let e = refused("[camera]\nposition = [0.0, 0.0, 0.04999999]\nobserver = \"falling\"\n");
    assert!(
        e.contains("is 0.04999999 rs") && e.contains("r >= 0.05"),
        "{e}"
    );
    let e = refused("[camera]\nposition = [0.0, 0.0, 1.4999999]\nobserver = \"orbiting\"\n");
    assert!(e.contains("r = 1.4999999 <= 1.5 rs"), "{e}");
}

#[test]
fn an_observer_inside_any_horizon_is_refused_in_one_wording() {
    let plain = refused("[camera]\nposition = [0.0, 0.0, 0.5]\nobserver = \"static\"\n");
    let spinning = refused(
        "[[black_hole]]\nspin = 0.9\n[camera]\nposition = [0.0, 0.0, 0.5]\nobserver = \"zamo\"\n",
    );
    for e in [&plain, &spinning] {
        assert!(
            e.contains("camera.position = [0, 0, 0.5]")
                && e.contains("is inside the horizon of black_hole[0]")
                && e.contains("set observer = \"falling\""),
            "{e}"
        );
    }
    assert!(plain.contains("r+ = 1.000 rs") && spinning.contains("r+ = 0.7179 rs"));
}

#[test]
fn every_polarization_key_is_checked_whether_or_not_the_picture_is_on() {
    // The picture off (the default), in a volumetric scene, and in scenes
    // it cannot draw: two holes, gravity off. A bad value is refused by
    // its key in each (it would be drawn once the picture is turned on,
    // or read by --aov stokes).
    let scenes = [
        "",
        "[disk]\nkind = \"volumetric\"\ninner_radius = 3.0\n",
        "[[black_hole]]\nposition = [-3.0, 0.0, 0.0]\n[[black_hole]]\nposition = [3.0, 0.0, 0.0]\n",
        "[physics]\ngravity = false\n",
    ];
    let bad = [
        ("field", "[0.0, 0.0, 0.0]"),
        ("field", "[nan, 0.0, 1.0]"),
        ("field", "[1e10, 0.0, 0.0]"),
        ("spectral_index", "nan"),
        ("spectral_index", "9.0"),
        ("emissivity_index", "-11.0"),
        ("fraction", "1.5"),
        ("fraction", "-0.1"),
        ("tick_cut", "2.0"),
        ("beam", "-1.0"),
        ("beam", "inf"),
        ("beam", "1e7"),
        ("mass_msun", "0.0"),
        ("mass_msun", "1e13"),
        ("distance_pc", "-5.0"),
        ("distance_pc", "nan"),
        ("annulus", "[5.0, 2.0]"),
        ("annulus", "[-1.0, 2.0]"),
        ("fields", "[[0.0, 0.0, 0.0]]"),
        ("ticks", "100000"),
    ];
    for base in scenes {
        for (key, value) in bad {
            let e = refused(&format!("{base}[polarization]\n{key} = {value}\n"));
            assert!(
                e.contains(&format!("polarization.{key}")),
                "{base}{key} = {value}: {e}"
            );
        }
    }
}

#[test]
fn a_stokes_aov_the_scene_cannot_have_is_refused_before_the_gpu() {
    for (toml, words) in [
        (
            "[[black_hole]]\nposition = [-3.0, 0.0, 0.0]\n[[black_hole]]\nposition = [3.0, 0.0, 0.0]\n",
            "one hole",
        ),
        ("[physics]\ngravity = false\n", "gravity on"),
    ] {
        let dir = scratch();
        let out = path_in(&dir, "s.exr");
        let args = ["--aov", "stokes", "--out", out.to_str().expect("utf-8")];
        let e = refused_early(render_scene(&dir, toml, &args));
        assert!(
            e.contains("--aov stokes") && e.contains(words),
            "{toml}: {e}"
        );
        assert!(!out.exists());
    }
}

#[test]
fn a_volumetric_disk_gets_the_stokes_aov_and_its_numbers_but_not_the_geodesic_one() {
    // Once refused by name (the thin disk only): each sample of the gas
    // carries its own polarization, for a non-rotating and a spinning hole.
    for toml in [
        "[disk]\nkind = \"volumetric\"\ninner_radius = 3.0\n",
        "[[black_hole]]\nspin = 0.9\n[disk]\nkind = \"volumetric\"\ninner_radius = 2.0\n",
    ] {
        let (dir, out) = stokes_with_numbers(toml);
        let aov = image::open(&out).expect("EXR").to_rgba32f();
        let lit = aov.pixels().filter(|p| p.0[0] > 0.0).count();
        assert!(lit > 100, "{toml}: {lit} pixels with light");
        assert!(
            aov.pixels().all(|p| p.0.iter().all(|v| v.is_finite())
                && p.0[3] == 0.0
                && p.0[1].hypot(p.0[2]) <= 0.7001 * p.0[0]),
            "{toml}: P <= fraction I, V = 0"
        );
        let geodesic = path_in(&dir, "g.exr");
        let args = [
            "--aov",
            "geodesic",
            "--out",
            geodesic.to_str().expect("utf-8"),
        ];
        let e = refused_early(render_scene(&dir, toml, &args));
        assert!(
            e.contains("--aov geodesic") && e.contains("volumetric"),
            "{e}"
        );
        assert!(!geodesic.exists());
    }
}

#[test]
fn a_falling_camera_inside_the_horizon_gets_the_stokes_aov_and_its_numbers() {
    // Once refused by name (no frame at rest inside): now carried on the
    // falling frame, for a non-rotating and a spinning hole.
    for toml in [
        "[camera]\nposition = [0.0, 0.1, 0.5]\nobserver = \"falling\"\n",
        "[[black_hole]]\nspin = 0.9\n[camera]\nposition = [0.0, 0.2, -0.55]\nobserver = \"falling\"\n",
    ] {
        stokes_with_numbers(toml);
    }
}

/// `render --aov stokes --json` of the scene `toml`: clean, the EXR and
/// the JSON written, beta_2 printed; the scratch folder and the EXR.
fn stokes_with_numbers(toml: &str) -> (tempfile::TempDir, std::path::PathBuf) {
    let dir = scratch();
    let (out, json) = (path_in(&dir, "s.exr"), path_in(&dir, "s.json"));
    let args = [
        "--aov",
        "stokes",
        "--out",
        out.to_str().expect("utf-8"),
        "--json",
        json.to_str().expect("utf-8"),
    ];
    let (code, stdout, stderr) = run(render_scene(&dir, toml, &args));
    assert_clean(code, &stdout, &stderr);
    assert!(out.exists() && json.exists(), "{toml}: {stdout}{stderr}");
    assert!(stdout.contains("beta_2"), "{toml}: {stdout}");
    (dir, out)
}
