//! Loading scenes: TOML files, built-in presets, messages that name the file,
//! the line, the key and the value.

use std::path::Path;

use glam::DVec3;

use super::locate;
use super::{Scene, SkyKind};
use crate::{Error, Result};

/// Built-in presets: name, one-line description, TOML source.
pub const PRESETS: &[(&str, &str, &str)] = &[
    (
        "default",
        "one hole, physical thin disk seen from just above its plane, stars",
        include_str!("presets/default.toml"),
    ),
    (
        "interstellar",
        "the film look: volumetric disk, colour map, no Doppler or redshift",
        include_str!("presets/interstellar.toml"),
    ),
    (
        "doppler",
        "the thin disk from higher up: Doppler and gravitational shifts on",
        include_str!("presets/doppler.toml"),
    ),
    (
        "grid",
        "no disk, a checker sky: lensing made plain",
        include_str!("presets/grid.toml"),
    ),
    (
        "binary",
        "two holes, accelerations summed (an approximation), checker sky",
        include_str!("presets/binary.toml"),
    ),
    (
        "edge-on",
        "the camera a hair above the disk's plane",
        include_str!("presets/edge-on.toml"),
    ),
    (
        "no-gravity",
        "the default scene with straight rays",
        include_str!("presets/no-gravity.toml"),
    ),
    (
        "top-down",
        "looking down the disk's axis",
        include_str!("presets/top-down.toml"),
    ),
    (
        "falling",
        "falling from rest at infinity through the horizon to 0.05 rs (fisheye down the fall)",
        include_str!("presets/falling.toml"),
    ),
    (
        "plunge",
        "falling into the gargantua hole (a* = 0.998), through its horizon",
        include_str!("presets/plunge.toml"),
    ),
    (
        "gargantua",
        "a hole spinning at a* = 0.998, its disk to the ISCO, nearly edge-on, shifts off",
        include_str!("presets/gargantua.toml"),
    ),
    (
        "kerr-doppler",
        "the same spinning hole from higher up with the shifts on: the asymmetry",
        include_str!("presets/kerr-doppler.toml"),
    ),
    (
        "m87",
        "M87* polarized as the EHT sees it: 163 degrees, a 20 microarcsecond beam, ticks",
        include_str!("presets/m87.toml"),
    ),
    (
        "fields",
        "the polarized disk's field models side by side: radial, toroidal, vertical, spiral",
        include_str!("presets/fields.toml"),
    ),
];

/// Names of the built-in presets, for `--help`.
pub fn preset_names() -> Vec<&'static str> {
    PRESETS.iter().map(|p| p.0).collect()
}

/// Every table and key name a scene file may use (from the default scene
/// written out), for hints about look-alike names.
fn known_names() -> Vec<String> {
    fn walk(t: &toml::Table, out: &mut Vec<String>) {
        for (k, v) in t {
            out.push(k.clone());
            match v {
                toml::Value::Table(t) => walk(t, out),
                toml::Value::Array(a) => a.iter().for_each(|v| {
                    if let toml::Value::Table(t) = v {
                        walk(t, out);
                    }
                }),
                _ => {}
            }
        }
    }
    let mut out = Vec::new();
    if let Some(t) = Scene::default()
        .to_toml()
        .ok()
        .and_then(|s| s.parse::<toml::Table>().ok())
    {
        walk(&t, &mut out);
    }
    out
}

impl Scene {
    /// The scene at frame `index` of its animation (the camera moved).
    pub fn at_frame(&self, index: u64) -> Scene {
        self.at_time(self.animation.time_of(index))
    }

    /// The scene at animation time `t` (seconds): its camera on the
    /// animation's path, the disk turned to `t`.
    pub fn at_time(&self, t: f64) -> Scene {
        Scene {
            camera: self.camera_at_time(t),
            time: t,
            ..self.clone()
        }
    }

    /// Sample `sample` of `spp` of frame `index` under `[animation]
    /// shutter`: the shutter opens at the frame's time and stays open for
    /// `shutter` of the frame's interval; the samples take stratified
    /// times across it (sample i in the i-th of spp equal slices, at a
    /// fixed Halton offset within it), so every frame is deterministic and
    /// sharded sequences match. With the shutter closed (0) every sample is
    /// the frame's instant.
    pub fn at_sample(&self, index: u64, sample: u32, spp: u32) -> Scene {
        let a = &self.animation;
        if a.shutter <= 0.0 || spp <= 1 {
            return self.at_frame(index);
        }
        let slice = (f64::from(sample) + crate::camera::halton(sample + 1, 5)) / f64::from(spp);
        self.at_time(a.time_of(index) + a.shutter * slice / a.fps)
    }

    /// Parses and validates TOML; `origin` names the file in messages.
    pub fn from_toml(src: &str, origin: &str) -> Result<Self> {
        let mut scene: Scene = toml::from_str(src).map_err(|e| {
            let line = e.span().map(|s| locate::line_of(src, s.start));
            let mut msg = locate::compact_numbers(&e.message().trim().replace('\n', " "));
            let text = e.span().and_then(|s| locate::line_text(src, s.start));
            if let Some(hint) = locate::odd_name_hint(&msg, text.as_deref(), &known_names()) {
                msg.push_str(&hint);
            }
            let context = text.map(|t| format!(" (in `{t}`)")).unwrap_or_default();
            match line {
                Some(l) => Error::Scene(format!("{origin}:{l}: {msg}{context}")),
                None => Error::Scene(format!("{origin}: {msg}")),
            }
        })?;
        scene.resolve_isco();
        scene.validate().map_err(|(path, value, why)| {
            let key = locate::display_path(&path);
            // A key the file does not set is its default: said so, since
            // it has no line to point at.
            match locate::line_of_key(src, &path) {
                Some(l) => Error::Scene(format!("{origin}:{l}: {key} = {value}: {why}")),
                None => Error::Scene(format!(
                    "{origin}: {key} = {value} (the default: the file does not set it): {why}"
                )),
            }
        })?;
        Ok(scene)
    }

    /// `[disk] inner_radius = "isco"`: the first hole's ISCO for its spin
    /// (3 rs without spin or gravity's spin), in rs.
    fn resolve_isco(&mut self) {
        if self.disk.inner_radius.to_bits() == super::schema::ISCO_MARK {
            let (rs, spin) = self.first_hole();
            self.disk.inner_radius = crate::spacetime::radii::isco(rs, spin.clamp(-1.0, 1.0));
        }
    }

    /// Whether an offscreen image of `width` x `height` can hold this
    /// scene's view: ODS stereo stacks two equal eyes, so its height is
    /// even and at least 2 (an odd one once gave the eyes unequal halves).
    pub fn check_image_size(&self, width: u32, height: u32) -> Result<()> {
        if self.camera.stereo == super::Stereo::Ods && (height < 2 || height % 2 == 1) {
            return Err(Error::Usage(format!(
                "--height {height}: camera.stereo = \"ods\" stacks two equal eyes (the left \
                 on top), so the height must be even and at least 2 ({width}x{height} asked)"
            )));
        }
        Ok(())
    }

    /// Checks every value as a scene file's would be (for scenes edited in the
    /// window's panel): `key = value: why` on failure.
    pub fn check(&self) -> Result<()> {
        self.validate().map_err(|(path, value, why)| {
            Error::Scene(format!("{} = {value}: {why}", locate::display_path(&path)))
        })
    }

    /// The scene as TOML (every key written), which [`Scene::from_toml`]
    /// reads back to the same scene.
    pub fn to_toml(&self) -> Result<String> {
        toml::to_string(self).map_err(|e| Error::Scene(format!("writing the scene as TOML: {e}")))
    }

    /// Loads a scene file, or a built-in preset by name. A path is read only
    /// if it is a regular file of at most [`crate::input::MAX_SCENE_BYTES`];
    /// a folder named like a preset does not hide the preset.
    pub fn load(name_or_path: &str) -> Result<Self> {
        let path = Path::new(name_or_path);
        let preset = PRESETS.iter().find(|p| p.0 == name_or_path);
        let from_preset =
            |(name, _, src): &(&str, &str, &str)| Self::from_toml(src, &format!("preset `{name}`"));
        match std::fs::metadata(path) {
            Ok(meta) if meta.is_dir() => {
                if let Some(p) = preset {
                    log::warn!(
                        "`{name_or_path}` is a folder here, not a scene file: using the built-in \
                         preset `{name_or_path}` (name a file inside the folder to use one)"
                    );
                    return from_preset(p);
                }
                Err(Error::Scene(format!(
                    "--scene {name_or_path}: is a folder, not a scene file (or a preset: {})",
                    preset_names().join(", ")
                )))
            }
            Ok(_) => {
                let src = crate::input::read_text(path, crate::input::MAX_SCENE_BYTES)
                    .map_err(|why| Error::Scene(format!("--scene {name_or_path}: {why}")))?;
                let mut scene = Self::from_toml(&src, name_or_path)?;
                scene.base_dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
                scene.source = Some(path.to_path_buf());
                scene.check_files(&src, name_or_path)?;
                Ok(scene)
            }
            Err(e) => match preset {
                Some(p) => from_preset(p),
                None if e.kind() != std::io::ErrorKind::NotFound => Err(Error::Scene(format!(
                    "--scene {name_or_path}: cannot read it: {e}"
                ))),
                None => Err(Error::Scene(format!(
                    "no scene file or preset named `{name_or_path}` (presets: {})",
                    preset_names().join(", ")
                ))),
            },
        }
    }

    /// Checks that the files the scene names are regular files (decoding
    /// comes later).
    fn check_files(&self, src: &str, origin: &str) -> Result<()> {
        use locate::Seg::Key;
        let key = if self.sky.kind == SkyKind::Image {
            "image"
        } else {
            "cubemap"
        };
        for f in self.sky.files(&self.base_dir) {
            if let Err(why) = crate::input::check_regular(&f) {
                let line = locate::line_of_key(src, &[Key("sky"), Key(key)])
                    .map(|l| format!(":{l}"))
                    .unwrap_or_default();
                return Err(Error::Scene(format!(
                    "{origin}{line}: sky.{key}: cannot read {}: {why}",
                    f.display()
                )));
            }
        }
        Ok(())
    }

    /// Every file the scene reads: the scene file itself and its sky images
    /// (a run must not write over them).
    pub fn input_files(&self) -> Vec<std::path::PathBuf> {
        self.source
            .iter()
            .cloned()
            .chain(self.sky.files(&self.base_dir))
            .collect()
    }

    /// The built-in default scene.
    pub fn builtin_default() -> Result<Self> {
        Self::load("default")
    }

    /// The radius past which rays count as escaped: beyond the camera and the
    /// disk by a wide margin, unless the scene sets one.
    pub fn escape_radius(&self) -> f64 {
        if self.quality.escape_radius > 0.0 {
            return self.quality.escape_radius;
        }
        let cam = DVec3::from(self.camera.position);
        let far = self
            .black_holes
            .iter()
            .map(|h| (cam - DVec3::from(h.position)).length() / h.rs)
            .fold(0.0, f64::max);
        let max_rs = self.black_holes.iter().map(|h| h.rs).fold(0.0, f64::max);
        (2.0 * far.max(self.disk.outer_radius / max_rs)).max(100.0) * max_rs
    }
}
