//! Helpers for tests that run the `blackhole` binary on lavapipe with the
//! validation layer required.

#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The binary under test, with validation required and caches kept in target/.
pub fn blackhole() -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_blackhole"));
    let cache = Path::new(env!("CARGO_TARGET_TMPDIR")).join("xdg-cache");
    c.env("BLACKHOLE_VALIDATION", "1")
        .env("XDG_CACHE_HOME", cache)
        .env("LP_NUM_THREADS", "4")
        .env("RUST_LOG", "blackhole=info");
    c
}

/// Runs a command; returns (exit code, stdout, stderr).
pub fn run(mut c: Command) -> (i32, String, String) {
    let Output {
        status,
        stdout,
        stderr,
    } = c.output().expect("the blackhole binary runs");
    (
        status.code().unwrap_or(-1),
        String::from_utf8_lossy(&stdout).into_owned(),
        String::from_utf8_lossy(&stderr).into_owned(),
    )
}

/// Asserts a run succeeded with the validation layer on and silent.
pub fn assert_clean(code: i32, stdout: &str, stderr: &str) {
    assert_eq!(code, 0, "exit code\nstdout:\n{stdout}\nstderr:\n{stderr}");
    assert!(
        stderr.contains("validation: 0 errors, 0 warnings"),
        "validation must be on and clean:\n{stderr}"
    );
    assert!(
        !stderr.contains("still alive at shutdown"),
        "GPU memory leaked:\n{stderr}"
    );
}

/// A fresh scratch directory for one test.
pub fn scratch() -> tempfile::TempDir {
    tempfile::Builder::new()
        .prefix("blackhole-test-")
        .tempdir_in(env!("CARGO_TARGET_TMPDIR"))
        .expect("creating a scratch directory")
}

/// Path of `name` inside `dir`.
pub fn path_in(dir: &tempfile::TempDir, name: &str) -> PathBuf {
    dir.path().join(name)
}

/// Where a test's scene comes from.
pub enum SceneSrc<'a> {
    /// A built-in preset, by name.
    Preset(&'a str),
    /// TOML text, written to `NAME.toml` in the scratch folder.
    Toml(&'a str),
}

/// Renders `scene` at `width` x `height` to `NAME.png` in `dir`, requiring a
/// clean, validation-silent run; returns the image.
pub fn render_png(
    dir: &tempfile::TempDir,
    name: &str,
    scene: SceneSrc<'_>,
    width: u32,
    height: u32,
) -> image::RgbImage {
    let scene_arg = match scene {
        SceneSrc::Preset(p) => p.to_string(),
        SceneSrc::Toml(text) => {
            let path = path_in(dir, &format!("{name}.toml"));
            std::fs::write(&path, text).expect("writing the test scene");
            path.display().to_string()
        }
    };
    let out = path_in(dir, &format!("{name}.png"));
    let (code, stdout, stderr) = run(render_command(&scene_arg, &out, width, height));
    assert_clean(code, &stdout, &stderr);
    image::open(&out).expect("PNG written").to_rgb8()
}

/// `blackhole render --width W --height H --scene SCENE --out OUT`, not yet
/// run (a test may add flags or settings).
pub fn render_command(
    scene: impl AsRef<std::ffi::OsStr>,
    out: &Path,
    width: u32,
    height: u32,
) -> Command {
    let mut c = blackhole();
    c.args([
        "render",
        "--width",
        &width.to_string(),
        "--height",
        &height.to_string(),
    ])
    .arg("--scene")
    .arg(scene)
    .arg("--out")
    .arg(out);
    c
}

/// A renderer on the default device with the validation layer required.
pub fn renderer() -> blackhole::Renderer {
    blackhole::Renderer::new(blackhole::RendererOptions {
        validation: blackhole::vk::Validation::Required,
        ..Default::default()
    })
    .expect("a Vulkan device with the validation layer (install mesa-vulkan-drivers and vulkan-validationlayers)")
}

/// The 8-bit pixels of a frame (panics on a float frame).
pub fn rgba8(f: blackhole::Frame) -> Vec<u8> {
    match f.pixels {
        blackhole::Pixels::Rgba8(p) => p,
        blackhole::Pixels::Rgba32F(_) => panic!("expected 8-bit pixels"),
    }
}

/// Resident memory of process `pid`, MB (Linux; 0 when it is gone).
pub fn rss_mb(pid: u32) -> f64 {
    std::fs::read_to_string(format!("/proc/{pid}/status"))
        .unwrap_or_default()
        .lines()
        .find_map(|l| l.strip_prefix("VmRSS:"))
        .and_then(|v| v.trim().trim_end_matches("kB").trim().parse::<f64>().ok())
        .map_or(0.0, |kb| kb / 1024.0)
}

/// A small deterministic generator (SplitMix64), so failures reproduce.
pub struct Rng(pub u64);

impl Rng {
    /// Uniform in [0, 1).
    pub fn next(&mut self) -> f64 {
        self.0 = self.0.wrapping_add(0x9E37_79B9_7F4A_7C15);
        let mut z = self.0;
        z = (z ^ (z >> 30)).wrapping_mul(0xBF58_476D_1CE4_E5B9);
        z = (z ^ (z >> 27)).wrapping_mul(0x94D0_49BB_1331_11EB);
        ((z ^ (z >> 31)) >> 11) as f64 / (1u64 << 53) as f64
    }

    /// Uniform in [lo, hi).
    pub fn range(&mut self, lo: f64, hi: f64) -> f64 {
        lo + (hi - lo) * self.next()
    }

    /// A random unit vector.
    pub fn unit(&mut self) -> glam::DVec3 {
        loop {
            let v = glam::DVec3::new(self.next(), self.next(), self.next()) * 2.0 - 1.0;
            let l = v.length();
            if l > 0.1 && l < 1.0 {
                return v / l;
            }
        }
    }
}

/// Renders the geodesic AOV (`width` x `height`) of the scene `toml`;
/// returns the scene as the renderer read it and the AOV.
pub fn render_aov(toml: &str, width: u32, height: u32) -> (blackhole::Scene, image::Rgba32FImage) {
    render_aov_with(toml, width, height, &[])
}

/// [`render_aov`] with extra environment variables for the renderer.
pub fn render_aov_with(
    toml: &str,
    width: u32,
    height: u32,
    env: &[(&str, &str)],
) -> (blackhole::Scene, image::Rgba32FImage) {
    render_aov_named("geodesic", toml, width, height, env)
}

/// The AOV `aov` (`geodesic`, `stokes`) of a scene, through the CLI.
pub fn render_aov_named(
    aov: &str,
    toml: &str,
    width: u32,
    height: u32,
    env: &[(&str, &str)],
) -> (blackhole::Scene, image::Rgba32FImage) {
    let dir = scratch();
    let scene_path = path_in(&dir, "scene.toml");
    std::fs::write(&scene_path, toml).unwrap();
    let out = path_in(&dir, "aov.exr");
    let mut c = blackhole();
    c.args(["render", "--aov", aov, "--width", &width.to_string()])
        .args(["--height", &height.to_string(), "--scene"])
        .arg(&scene_path)
        .arg("--out")
        .arg(&out)
        .envs(env.iter().copied());
    let (code, stdout, stderr) = run(c);
    assert_clean(code, &stdout, &stderr);
    let gpu = image::open(&out).expect("AOV EXR").to_rgba32f();
    assert_eq!(gpu.dimensions(), (width, height));
    (blackhole::Scene::from_toml(toml, "scene").unwrap(), gpu)
}

/// A command that must be refused before the GPU starts: a device name no
/// device has makes any GPU work fail with a different message.
pub fn refused_early(mut c: Command) -> String {
    c.env("BLACKHOLE_DEVICE", "no-such-device-here");
    let (code, stdout, stderr) = run(c);
    assert_eq!(code, 2, "exit code\nstdout:\n{stdout}\nstderr:\n{stderr}");
    assert!(
        !stderr.contains("no-such-device-here"),
        "refused only after looking for a GPU:\n{stderr}"
    );
    let errors: Vec<&str> = stderr.lines().filter(|l| l.starts_with("error:")).collect();
    assert_eq!(errors.len(), 1, "one error line:\n{stderr}");
    errors[0].to_string()
}

pub fn render_scene(dir: &tempfile::TempDir, toml: &str, extra: &[&str]) -> Command {
    let scene = path_in(dir, "scene.toml");
    std::fs::write(&scene, toml).expect("writing the scene");
    let mut c = blackhole();
    c.args(["render", "--width", "64", "--height", "36", "--scene"])
        .arg(&scene)
        .args(extra);
    c
}
