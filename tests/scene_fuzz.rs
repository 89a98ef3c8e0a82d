//! Hostile scene files, without a device: random text, the default scene
//! with values replaced by extremes and wrong types, lines dropped,
//! duplicated and swapped, invalid UTF-8, and panel-style edits of the
//! scene in memory. Nothing may panic; a refusal is one short line that
//! names the file (and the line or key where there is one); an accepted
//! scene gives the GPU only finite numbers.

use std::mem::offset_of;

use blackhole::Scene;
use blackhole::passes::raymarch::FrameSpec;
use blackhole::passes::raymarch::params::{
    CameraParams, IntegratorParams, MetricParams, RaymarchParams,
};
use proptest::prelude::*;

const DEFAULT: &str = include_str!("../src/scene/presets/default.toml");

/// Every float of the parameter block an accepted scene gives the GPU is
/// finite (the image size, hole count and step budget are integers).
fn assert_finite_params(scene: &Scene) {
    let p = RaymarchParams::new(scene, &scene.spacetime(), &FrameSpec::new(64, 36));
    let integers = [
        offset_of!(RaymarchParams, camera) + offset_of!(CameraParams, size),
        offset_of!(RaymarchParams, camera) + offset_of!(CameraParams, size) + 4,
        offset_of!(RaymarchParams, camera) + offset_of!(CameraParams, _pad),
        offset_of!(RaymarchParams, camera) + offset_of!(CameraParams, _pad) + 4,
        offset_of!(RaymarchParams, metric) + offset_of!(MetricParams, hole_count),
        offset_of!(RaymarchParams, integrator) + offset_of!(IntegratorParams, steps),
    ];
    for (i, w) in bytemuck::bytes_of(&p).chunks_exact(4).enumerate() {
        if integers.contains(&(4 * i)) {
            continue;
        }
        let v = f32::from_le_bytes([w[0], w[1], w[2], w[3]]);
        assert!(v.is_finite(), "parameter word {i} is {v}");
    }
}

fn check(src: &str) {
    match Scene::from_toml(src, "fuzz.toml") {
        Ok(scene) => {
            scene.check().expect("a parsed scene passes its own checks");
            assert_finite_params(&scene);
            let again = scene.to_toml().expect("written back as TOML");
            Scene::from_toml(&again, "written").expect("and read again");
        }
        Err(e) => {
            let m = e.to_string();
            assert!(!m.contains('\n'), "not one line: {m}");
            assert!(m.starts_with("fuzz.toml"), "does not name the file: {m}");
            // Long enough for the list of the keys a table takes.
            assert!(m.len() < 600, "too long ({} bytes): {m}", m.len());
        }
    }
}

const VALUES: &[&str] = &[
    "nan",
    "inf",
    "-inf",
    "1e308",
    "-1e308",
    "1e-320",
    "0",
    "-0.0",
    "-1",
    "99999999999999999999999",
    "0x10",
    "\"text\"",
    "\"\"",
    "'unterminated",
    "[1, 2]",
    "[]",
    "[[[[[[[[1]]]]]]]]",
    "{ a = 1 }",
    "true",
    "1979-05-27",
    "[0.0, nan, 1.0]",
    "[1e308, 1e308, 1e308]",
    "[0.0, 0.0, 0.0]",
];

proptest! {
    // A fixed seed, so a run is the same on every machine (set
    // PROPTEST_CASES higher to search further), and no regression files.
    #![proptest_config(ProptestConfig {
        cases: 1500,
        failure_persistence: None,
        rng_seed: proptest::test_runner::RngSeed::Fixed(0x626c_6163_6b68),
        ..ProptestConfig::default()
    })]

    #[test]
    fn random_text_is_refused_cleanly(s in "\\PC{0,300}") {
        check(&s);
    }

    #[test]
    fn a_value_replaced_by_an_extreme_or_a_wrong_type(line in 0usize..120, v in 0usize..VALUES.len()) {
        let lines: Vec<&str> = DEFAULT.lines().collect();
        let i = line % lines.len();
        let mut out: Vec<String> = lines.iter().map(|l| l.to_string()).collect();
        if let Some((key, _)) = lines[i].split_once('=') {
            out[i] = format!("{key}= {}", VALUES[v]);
        }
        check(&out.join("\n"));
    }

    #[test]
    fn lines_dropped_duplicated_and_swapped(ops in proptest::collection::vec((0usize..120, 0u8..3), 1..8)) {
        let mut lines: Vec<String> = DEFAULT.lines().map(str::to_string).collect();
        for (at, op) in ops {
            let i = at % lines.len();
            match op {
                0 => { lines.remove(i); }
                1 => { let l = lines[i].clone(); lines.insert(i, l); }
                _ => { if i + 1 < lines.len() { lines.swap(i, i + 1); } }
            }
            if lines.is_empty() {
                break;
            }
        }
        check(&lines.join("\n"));
    }

    #[test]
    fn panel_edits_are_checked(field in 0usize..12, v in prop_oneof![
        Just(f64::NAN), Just(f64::INFINITY), Just(f64::NEG_INFINITY), Just(0.0), Just(-1.0),
        Just(1e300), Just(-1e300), Just(1e-300), -1e6f64..1e6f64,
    ]) {
        let mut s = Scene::default();
        match field {
            0 => s.camera.vfov_deg = v,
            1 => s.camera.position[1] = v,
            2 => s.black_holes[0].rs = v,
            3 => s.disk.inner_radius = v,
            4 => s.disk.outer_radius = v,
            5 => s.disk.temperature_k = v,
            6 => s.disk.structure = v,
            7 => s.post.exposure_ev = v,
            8 => s.post.saturation = v,
            9 => s.sky.rotation_deg = v,
            10 => s.bloom.radius = v,
            _ => s.quality.tolerance = v,
        }
        if s.check().is_ok() {
            assert_finite_params(&s);
        }
    }
}

#[test]
fn empty_and_deeply_nested_files() {
    check("");
    check(&format!(
        "a = {}{}",
        "[".repeat(100_000),
        "]".repeat(100_000)
    ));
    check(&format!(
        "[camera]\nposition = {}{}",
        "[".repeat(5_000),
        "]".repeat(5_000)
    ));
    check(&"[camera]\n".repeat(1_000));
    check(&"x".repeat(1_000_000));
}

#[test]
fn invalid_utf8_names_the_file() {
    let dir = tempfile::tempdir().unwrap();
    let path = dir.path().join("bad.toml");
    std::fs::write(&path, b"[camera]\nvfov_deg = 60.0 \xff\xfe\n").unwrap();
    let e = Scene::load(path.to_str().unwrap()).unwrap_err().to_string();
    assert!(e.contains("bad.toml") && e.contains("UTF-8"), "{e}");
    assert!(!e.contains('\n'), "{e}");
}
