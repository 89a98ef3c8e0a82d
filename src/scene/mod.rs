//! Scenes: the TOML schema (DESIGN.md section 3), validation with messages that
//! name the key, the value and the line, and the built-in presets.

pub mod animation;
mod locate;

pub use animation::{Animation, CameraPath, Keyframe};

use std::path::Path;

use glam::DVec3;
use serde::Deserialize;

use crate::{Error, Result};

/// Camera (DESIGN.md section 2): `position`, `look_at`, `up`, `vfov_deg`.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Camera {
    pub position: [f64; 3],
    pub look_at: [f64; 3],
    pub up: [f64; 3],
    pub vfov_deg: f64,
}

impl Default for Camera {
    fn default() -> Self {
        Camera {
            position: [0.0, 0.8, -15.0],
            look_at: [0.0; 3],
            up: [0.0, 1.0, 0.0],
            vfov_deg: 60.0,
        }
    }
}

/// An orthonormal camera frame, by the binding convention.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraFrame {
    pub position: DVec3,
    pub forward: DVec3,
    pub right: DVec3,
    pub up: DVec3,
    /// tan(vfov / 2).
    pub tan_half_fov: f64,
}

impl Camera {
    /// `forward = normalize(look_at - position)`, `right = normalize(cross(up,
    /// forward))`, `cam_up = cross(forward, right)`.
    pub fn frame(&self) -> CameraFrame {
        let position = DVec3::from(self.position);
        let forward = (DVec3::from(self.look_at) - position).normalize();
        let right = DVec3::from(self.up).cross(forward).normalize();
        let up = forward.cross(right);
        CameraFrame {
            position,
            forward,
            right,
            up,
            tan_half_fov: (self.vfov_deg.to_radians() * 0.5).tan(),
        }
    }
}

impl CameraFrame {
    /// The unit direction of the ray through the centre of pixel (`col`, `row`)
    /// of a `width` x `height` image, row 0 at the top.
    pub fn ray_dir(&self, col: u32, row: u32, width: u32, height: u32) -> DVec3 {
        let aspect = f64::from(width) / f64::from(height);
        let sx =
            (2.0 * (f64::from(col) + 0.5) / f64::from(width) - 1.0) * self.tan_half_fov * aspect;
        let sy = (1.0 - 2.0 * (f64::from(row) + 0.5) / f64::from(height)) * self.tan_half_fov;
        (self.forward + sx * self.right + sy * self.up).normalize()
    }
}

/// One Schwarzschild hole.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct BlackHole {
    pub position: [f64; 3],
    /// Schwarzschild radius (= 2M in G = c = 1), the unit of every length.
    pub rs: f64,
    /// Mass in solar masses, for display only (r_s = 2.953 km per solar mass).
    pub mass_solar: Option<f64>,
}

impl Default for BlackHole {
    fn default() -> Self {
        BlackHole {
            position: [0.0; 3],
            rs: 1.0,
            mass_solar: None,
        }
    }
}

/// What kind of disk surrounds the (first) hole.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum DiskKind {
    Thin,
    Volumetric,
    None,
}

/// The accretion disk, centred on the first hole.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Disk {
    pub kind: DiskKind,
    pub normal: [f64; 3],
    pub inner_radius: f64,
    pub outer_radius: f64,
    /// Emission scale (luminance of the hottest ring, seen unshifted).
    pub brightness: f64,
    /// Temperature of the hottest ring, kelvin (Novikov-Thorne profile).
    pub temperature_k: f64,
    /// Volumetric disk: half-thickness.
    pub height: f64,
    /// Volumetric disk: exponent of the fall of density with height.
    pub density_v: f64,
    /// Volumetric disk: exponent of the fall of density with radius.
    pub density_h: f64,
    /// Volumetric disk: spatial frequency of the noise (per rs).
    pub noise_scale: f64,
    /// Volumetric disk: octaves of noise (1 to 8).
    pub noise_octaves: u32,
    /// Volumetric disk: how fast the gas turns (x Keplerian; time from [animation]).
    pub speed: f64,
    /// Volumetric disk: emission scale.
    pub lit: f64,
    /// Volumetric disk colour: the blackbody of the physical disk (with its
    /// shifts), or a film-like colour map.
    pub color: VolumeColor,
}

/// How the volumetric disk is coloured.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum VolumeColor {
    Blackbody,
    Colormap,
}

impl Default for Disk {
    fn default() -> Self {
        Disk {
            kind: DiskKind::Thin,
            normal: [0.0, 1.0, 0.0],
            inner_radius: 3.0,
            outer_radius: 12.0,
            brightness: 1.2,
            temperature_k: 6000.0,
            height: 0.5,
            density_v: 2.0,
            density_h: 1.5,
            noise_scale: 0.8,
            noise_octaves: 4,
            speed: 1.0,
            lit: 1.0,
            color: VolumeColor::Blackbody,
        }
    }
}

/// What kind of sky escaped rays see.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "lowercase")]
pub enum SkyKind {
    /// Procedural stars and a faint galaxy band.
    Stars,
    /// Checker squares on the celestial sphere (shows lensing clearly).
    Checker,
    /// An equirectangular panorama from `image`.
    Image,
    /// Six cube-map faces from `cubemap` (+x, -x, +y, -y, +z, -z).
    Cubemap,
    Black,
}

/// The sky (celestial sphere).
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Sky {
    pub kind: SkyKind,
    /// Checker squares around the equator.
    pub squares: u32,
    /// Chance that a star cell holds a star (0 to 1).
    pub star_density: f64,
    /// Brightness of the galaxy band (stars sky).
    pub galaxy: f64,
    pub brightness: f64,
    /// Panorama file (PNG, JPEG, HDR, EXR), relative to the scene file.
    pub image: Option<String>,
    /// Six face files, +x, -x, +y, -y, +z, -z, relative to the scene file.
    pub cubemap: Option<Vec<String>>,
}

impl Sky {
    /// The files an image or cube-map sky reads, resolved against `base`.
    pub fn files(&self, base: &Path) -> Vec<std::path::PathBuf> {
        match self.kind {
            SkyKind::Image => self.image.iter().map(|f| base.join(f)).collect(),
            SkyKind::Cubemap => self
                .cubemap
                .iter()
                .flatten()
                .map(|f| base.join(f))
                .collect(),
            _ => Vec::new(),
        }
    }
}

impl Default for Sky {
    fn default() -> Self {
        Sky {
            kind: SkyKind::Stars,
            squares: 24,
            star_density: 0.5,
            galaxy: 0.02,
            brightness: 1.0,
            image: None,
            cubemap: None,
        }
    }
}

/// The first seed's grid plane behind the hole.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct GridPlane {
    pub enabled: bool,
    /// A point on the plane (its centre).
    pub position: [f64; 3],
    /// Normal, facing the camera.
    pub normal: [f64; 3],
    /// Distance between grid lines.
    pub spacing: f64,
    /// Half the side of the square.
    pub size: f64,
}

impl Default for GridPlane {
    fn default() -> Self {
        GridPlane {
            enabled: false,
            position: [0.0, 0.0, 40.0],
            normal: [0.0, 0.0, -1.0],
            spacing: 2.0,
            size: 60.0,
        }
    }
}

/// Integration quality.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Quality {
    /// Step budget per ray.
    pub steps: u32,
    /// Local error tolerance of the adaptive integrator.
    pub tolerance: f64,
    /// Radius (from each hole) past which a ray has escaped; 0 = automatic.
    pub escape_radius: f64,
}

impl Default for Quality {
    fn default() -> Self {
        Quality {
            steps: 4000,
            tolerance: 1e-5,
            escape_radius: 0.0,
        }
    }
}

/// Physics switches: the film look (Doppler and redshift off) and the
/// physical look are one switch apart.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Physics {
    /// Bend light (off: straight rays; the horizon still absorbs).
    pub gravity: bool,
    /// Doppler shift and beaming of the orbiting disk.
    pub doppler: bool,
    /// Gravitational redshift of the disk's light.
    pub gravitational_redshift: bool,
}

impl Default for Physics {
    fn default() -> Self {
        Physics {
            gravity: true,
            doppler: true,
            gravitational_redshift: true,
        }
    }
}

/// The tone curve of the 8-bit output.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize)]
#[serde(rename_all = "kebab-case")]
pub enum Tonemap {
    /// Stephen Hill's RRT+ODT fit of ACES (the fuller one).
    AcesHill,
    /// Krzysztof Narkowicz's one-line ACES fit.
    AcesNarkowicz,
    /// Clamp only (for checking values).
    Linear,
}

/// Post-processing.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Post {
    /// Exposure in EV stops (x 2^ev before tone mapping).
    pub exposure_ev: f64,
    pub tonemap: Tonemap,
    /// Triangular dither of +-1 step in the 8-bit output.
    pub dither: bool,
}

impl Default for Post {
    fn default() -> Self {
        Post {
            exposure_ev: 0.0,
            tonemap: Tonemap::AcesHill,
            dither: true,
        }
    }
}

/// The bloom mip chain.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Bloom {
    /// How much of the blurred bright light is added (0: no bloom, no passes).
    pub strength: f64,
    /// Brightest-channel value above which light blooms.
    pub threshold: f64,
    /// Width of the soft knee around the threshold.
    pub knee: f64,
    /// Mip levels of the chain, 1 to 8 (each halves the size).
    pub levels: u32,
    /// Tent radius of the upsample, in texels of the smaller level.
    pub radius: f64,
}

impl Default for Bloom {
    fn default() -> Self {
        Bloom {
            strength: 0.6,
            threshold: 1.0,
            knee: 0.5,
            levels: 6,
            radius: 1.0,
        }
    }
}

/// A whole scene. Every section is optional; omitted keys take the values of
/// the built-in default scene.
#[derive(Clone, Debug, PartialEq, Deserialize)]
#[serde(deny_unknown_fields, default)]
pub struct Scene {
    pub camera: Camera,
    #[serde(rename = "black_hole")]
    pub black_holes: Vec<BlackHole>,
    pub disk: Disk,
    pub sky: Sky,
    #[serde(rename = "grid_plane")]
    pub plane: GridPlane,
    pub quality: Quality,
    pub physics: Physics,
    pub bloom: Bloom,
    pub post: Post,
    pub animation: Animation,
    /// Seconds since the start of the animation (set per frame, not read from TOML).
    #[serde(skip)]
    pub time: f64,
    /// Folder that relative file names in the scene are resolved against.
    #[serde(skip)]
    pub base_dir: std::path::PathBuf,
}

impl Default for Scene {
    fn default() -> Self {
        Scene {
            camera: Camera::default(),
            black_holes: vec![BlackHole::default()],
            disk: Disk::default(),
            sky: Sky::default(),
            plane: GridPlane::default(),
            quality: Quality::default(),
            physics: Physics::default(),
            bloom: Bloom::default(),
            post: Post::default(),
            animation: Animation::default(),
            time: 0.0,
            base_dir: std::path::PathBuf::new(),
        }
    }
}

/// Most holes one scene may have (the shader's fixed array).
pub const MAX_HOLES: usize = 8;

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
];

/// Names of the built-in presets, for `--help`.
pub fn preset_names() -> Vec<&'static str> {
    PRESETS.iter().map(|p| p.0).collect()
}

impl Scene {
    /// The scene at frame `index` of its animation (the camera moved).
    pub fn at_frame(&self, index: u64) -> Scene {
        let t = self.animation.time_of(index);
        Scene {
            camera: self.animation.camera_at(&self.camera, t),
            time: t,
            ..self.clone()
        }
    }

    /// Parses and validates TOML; `origin` names the file in messages.
    pub fn from_toml(src: &str, origin: &str) -> Result<Self> {
        let scene: Scene = toml::from_str(src).map_err(|e| {
            let line = e.span().map(|s| locate::line_of(src, s.start));
            let msg = e.message().trim().replace('\n', " ");
            let context = e
                .span()
                .and_then(|s| locate::line_text(src, s.start))
                .map(|t| format!(" (in `{t}`)"))
                .unwrap_or_default();
            match line {
                Some(l) => Error::Scene(format!("{origin}:{l}: {msg}{context}")),
                None => Error::Scene(format!("{origin}: {msg}")),
            }
        })?;
        scene.validate().map_err(|(path, value, why)| {
            let line = locate::line_of_key(src, &path)
                .map(|l| format!(":{l}"))
                .unwrap_or_default();
            let key = locate::display_path(&path);
            Error::Scene(format!("{origin}{line}: {key} = {value}: {why}"))
        })?;
        Ok(scene)
    }

    /// Loads a scene file, or a built-in preset by name.
    pub fn load(name_or_path: &str) -> Result<Self> {
        let path = Path::new(name_or_path);
        if path.exists() {
            let src = std::fs::read_to_string(path).map_err(|source| Error::Io {
                path: path.to_owned(),
                source,
            })?;
            let mut scene = Self::from_toml(&src, name_or_path)?;
            scene.base_dir = path.parent().map(Path::to_path_buf).unwrap_or_default();
            scene.check_files(&src, name_or_path)?;
            return Ok(scene);
        }
        if let Some((name, _, src)) = PRESETS.iter().find(|p| p.0 == name_or_path) {
            return Self::from_toml(src, &format!("preset `{name}`"));
        }
        Err(Error::Scene(format!(
            "no scene file or preset named `{name_or_path}` (presets: {})",
            preset_names().join(", ")
        )))
    }

    /// Checks that the files the scene names exist (decoding comes later).
    fn check_files(&self, src: &str, origin: &str) -> Result<()> {
        use locate::Seg::Key;
        let key = if self.sky.kind == SkyKind::Image {
            "image"
        } else {
            "cubemap"
        };
        for f in self.sky.files(&self.base_dir) {
            if !f.is_file() {
                let line = locate::line_of_key(src, &[Key("sky"), Key(key)])
                    .map(|l| format!(":{l}"))
                    .unwrap_or_default();
                return Err(Error::Scene(format!(
                    "{origin}{line}: sky.{key}: cannot read {}: no such file",
                    f.display()
                )));
            }
        }
        Ok(())
    }

    /// The built-in default scene.
    pub fn builtin_default() -> Result<Self> {
        Self::load("default")
    }

    /// Checks values serde cannot: returns (key path, value, reason).
    fn validate(&self) -> std::result::Result<(), (Vec<locate::Seg>, String, String)> {
        use locate::Seg::{Idx, Key};
        let err =
            |path: Vec<locate::Seg>, value: String, why: &str| Err((path, value, why.to_string()));
        let vec3 = |v: &[f64; 3]| format!("[{}, {}, {}]", v[0], v[1], v[2]);
        let finite3 = |v: &[f64; 3]| v.iter().all(|x| x.is_finite());

        let c = &self.camera;
        for (name, v) in [
            ("position", &c.position),
            ("look_at", &c.look_at),
            ("up", &c.up),
        ] {
            if !finite3(v) {
                return err(
                    vec![Key("camera"), Key(name)],
                    vec3(v),
                    "must be finite numbers",
                );
            }
        }
        if !(c.vfov_deg > 0.0 && c.vfov_deg < 180.0) {
            return err(
                vec![Key("camera"), Key("vfov_deg")],
                c.vfov_deg.to_string(),
                "must be in (0, 180) degrees",
            );
        }
        let fwd = DVec3::from(c.look_at) - DVec3::from(c.position);
        if fwd.length() < 1e-9 {
            return err(
                vec![Key("camera"), Key("look_at")],
                vec3(&c.look_at),
                "must differ from camera.position",
            );
        }
        if DVec3::from(c.up).cross(fwd.normalize()).length() < 1e-6 {
            return err(
                vec![Key("camera"), Key("up")],
                vec3(&c.up),
                "must not be zero or parallel to the view direction",
            );
        }

        if self.black_holes.is_empty() {
            return err(
                vec![Key("black_hole")],
                "[]".into(),
                "at least one black hole is needed",
            );
        }
        if self.black_holes.len() > MAX_HOLES {
            return err(
                vec![Key("black_hole")],
                format!("{} entries", self.black_holes.len()),
                &format!("at most {MAX_HOLES} black holes are supported"),
            );
        }
        for (i, h) in self.black_holes.iter().enumerate() {
            if !finite3(&h.position) {
                return err(
                    vec![Key("black_hole"), Idx(i), Key("position")],
                    vec3(&h.position),
                    "must be finite numbers",
                );
            }
            if !(h.rs.is_finite() && h.rs > 0.0) {
                return err(
                    vec![Key("black_hole"), Idx(i), Key("rs")],
                    h.rs.to_string(),
                    "must be a finite number > 0",
                );
            }
            if let Some(m) = h.mass_solar {
                if !(m.is_finite() && m > 0.0) {
                    return err(
                        vec![Key("black_hole"), Idx(i), Key("mass_solar")],
                        m.to_string(),
                        "must be a finite number > 0",
                    );
                }
            }
            if (DVec3::from(c.position) - DVec3::from(h.position)).length() <= h.rs {
                return err(
                    vec![Key("camera"), Key("position")],
                    vec3(&c.position),
                    &format!("is inside the horizon of black_hole[{i}]"),
                );
            }
        }

        let d = &self.disk;
        if !finite3(&d.normal) || DVec3::from(d.normal).length() < 1e-9 {
            return err(
                vec![Key("disk"), Key("normal")],
                vec3(&d.normal),
                "must be a finite, non-zero vector",
            );
        }
        if !(d.inner_radius.is_finite() && d.inner_radius >= 0.0) {
            return err(
                vec![Key("disk"), Key("inner_radius")],
                d.inner_radius.to_string(),
                "must be a finite number >= 0",
            );
        }
        if !(d.outer_radius.is_finite() && d.outer_radius > d.inner_radius) {
            return err(
                vec![Key("disk"), Key("outer_radius")],
                d.outer_radius.to_string(),
                &format!(
                    "must be finite and greater than inner_radius ({})",
                    d.inner_radius
                ),
            );
        }
        if !(d.brightness.is_finite() && d.brightness >= 0.0) {
            return err(
                vec![Key("disk"), Key("brightness")],
                d.brightness.to_string(),
                "must be a finite number >= 0",
            );
        }
        if !(d.temperature_k.is_finite() && d.temperature_k > 0.0) {
            return err(
                vec![Key("disk"), Key("temperature_k")],
                d.temperature_k.to_string(),
                "must be a finite temperature > 0 kelvin",
            );
        }
        for (name, v) in [("height", d.height), ("noise_scale", d.noise_scale)] {
            if !(v.is_finite() && v > 0.0) {
                return err(
                    vec![Key("disk"), Key(name)],
                    v.to_string(),
                    "must be a finite number > 0",
                );
            }
        }
        for (name, v) in [
            ("density_v", d.density_v),
            ("density_h", d.density_h),
            ("lit", d.lit),
        ] {
            if !(v.is_finite() && v >= 0.0) {
                return err(
                    vec![Key("disk"), Key(name)],
                    v.to_string(),
                    "must be a finite number >= 0",
                );
            }
        }
        if !d.speed.is_finite() {
            return err(
                vec![Key("disk"), Key("speed")],
                d.speed.to_string(),
                "must be a finite number",
            );
        }
        if !(1..=8).contains(&d.noise_octaves) {
            return err(
                vec![Key("disk"), Key("noise_octaves")],
                d.noise_octaves.to_string(),
                "must be 1 to 8",
            );
        }
        if d.kind == DiskKind::Volumetric && d.inner_radius <= 0.0 {
            return err(
                vec![Key("disk"), Key("inner_radius")],
                d.inner_radius.to_string(),
                "must be > 0 for a volumetric disk",
            );
        }

        let s = &self.sky;
        if s.kind == SkyKind::Image && s.image.is_none() {
            return err(
                vec![Key("sky"), Key("kind")],
                "\"image\"".into(),
                "needs sky.image = \"panorama file\"",
            );
        }
        if s.kind == SkyKind::Cubemap && s.cubemap.as_ref().is_none_or(|c| c.len() != 6) {
            return err(
                vec![Key("sky"), Key("kind")],
                "\"cubemap\"".into(),
                "needs sky.cubemap = [six files: +x, -x, +y, -y, +z, -z]",
            );
        }
        if !(s.star_density.is_finite() && (0.0..=1.0).contains(&s.star_density)) {
            return err(
                vec![Key("sky"), Key("star_density")],
                s.star_density.to_string(),
                "must be in [0, 1]",
            );
        }
        if !(s.galaxy.is_finite() && s.galaxy >= 0.0) {
            return err(
                vec![Key("sky"), Key("galaxy")],
                s.galaxy.to_string(),
                "must be a finite number >= 0",
            );
        }
        if s.squares == 0 {
            return err(
                vec![Key("sky"), Key("squares")],
                "0".into(),
                "must be at least 1",
            );
        }
        if !(s.brightness.is_finite() && s.brightness >= 0.0) {
            return err(
                vec![Key("sky"), Key("brightness")],
                s.brightness.to_string(),
                "must be a finite number >= 0",
            );
        }

        let q = &self.quality;
        if q.steps == 0 {
            return err(
                vec![Key("quality"), Key("steps")],
                "0".into(),
                "must be at least 1",
            );
        }
        if !(q.tolerance.is_finite() && q.tolerance > 0.0 && q.tolerance < 1.0) {
            return err(
                vec![Key("quality"), Key("tolerance")],
                q.tolerance.to_string(),
                "must be in (0, 1)",
            );
        }
        if !(q.escape_radius.is_finite() && q.escape_radius >= 0.0) {
            return err(
                vec![Key("quality"), Key("escape_radius")],
                q.escape_radius.to_string(),
                "must be a finite number >= 0 (0 = automatic)",
            );
        }
        let gp = &self.plane;
        if !finite3(&gp.position) {
            return err(
                vec![Key("grid_plane"), Key("position")],
                vec3(&gp.position),
                "must be finite numbers",
            );
        }
        if !finite3(&gp.normal) || DVec3::from(gp.normal).length() < 1e-9 {
            return err(
                vec![Key("grid_plane"), Key("normal")],
                vec3(&gp.normal),
                "must be a finite, non-zero vector",
            );
        }
        for (name, v) in [("spacing", gp.spacing), ("size", gp.size)] {
            if !(v.is_finite() && v > 0.0) {
                return err(
                    vec![Key("grid_plane"), Key(name)],
                    v.to_string(),
                    "must be a finite number > 0",
                );
            }
        }
        let b = &self.bloom;
        for (name, v) in [
            ("strength", b.strength),
            ("threshold", b.threshold),
            ("knee", b.knee),
        ] {
            if !(v.is_finite() && v >= 0.0) {
                return err(
                    vec![Key("bloom"), Key(name)],
                    v.to_string(),
                    "must be a finite number >= 0",
                );
            }
        }
        if !(1..=8).contains(&b.levels) {
            return err(
                vec![Key("bloom"), Key("levels")],
                b.levels.to_string(),
                "must be 1 to 8",
            );
        }
        if !(b.radius.is_finite() && b.radius > 0.0) {
            return err(
                vec![Key("bloom"), Key("radius")],
                b.radius.to_string(),
                "must be a finite number > 0",
            );
        }
        let a = &self.animation;
        if !(a.fps.is_finite() && a.fps > 0.0) {
            return err(
                vec![Key("animation"), Key("fps")],
                a.fps.to_string(),
                "must be a finite number > 0",
            );
        }
        for (name, v) in [
            ("orbit_radius", a.orbit_radius),
            ("orbit_speed_deg", a.orbit_speed_deg),
            ("inclination_deg", a.inclination_deg),
        ] {
            if !v.is_finite() || (name == "orbit_radius" && v < 0.0) {
                return err(
                    vec![Key("animation"), Key(name)],
                    v.to_string(),
                    "must be a finite number (radius >= 0)",
                );
            }
        }
        if a.inclination_deg.abs() >= 90.0 {
            return err(
                vec![Key("animation"), Key("inclination_deg")],
                a.inclination_deg.to_string(),
                "must be between -90 and 90 (the camera's up is +y)",
            );
        }
        if a.camera == CameraPath::Keyframes && a.keyframes.is_empty() {
            return err(
                vec![Key("animation"), Key("camera")],
                "\"keyframes\"".into(),
                "needs at least one [[animation.keyframe]]",
            );
        }
        for (i, k) in a.keyframes.iter().enumerate() {
            if !k.time.is_finite() || (i > 0 && k.time <= a.keyframes[i - 1].time) {
                return err(
                    vec![Key("animation"), Key("keyframe"), Idx(i), Key("time")],
                    k.time.to_string(),
                    "keyframe times must be finite and increasing",
                );
            }
        }
        if !self.post.exposure_ev.is_finite() {
            return err(
                vec![Key("post"), Key("exposure_ev")],
                self.post.exposure_ev.to_string(),
                "must be a finite number",
            );
        }
        Ok(())
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

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_preset_equals_the_defaults_of_omitted_keys() {
        let parsed = Scene::builtin_default().expect("default preset parses");
        assert_eq!(parsed, Scene::default());
        assert_eq!(
            Scene::from_toml("", "empty").expect("empty parses"),
            Scene::default()
        );
    }

    #[test]
    fn negative_rs_names_key_value_and_line() {
        let src =
            "[camera]\nvfov_deg = 50.0\n\n[[black_hole]]\nposition = [0.0, 0.0, 0.0]\nrs = -1.0\n";
        let e = Scene::from_toml(src, "s.toml").unwrap_err().to_string();
        assert_eq!(
            e,
            "s.toml:6: black_hole[0].rs = -1: must be a finite number > 0"
        );
    }

    #[test]
    fn second_hole_error_points_at_its_own_line() {
        let src =
            "[[black_hole]]\nrs = 1.0\n[[black_hole]]\nposition = [5.0, 0.0, 0.0]\nrs = 0.0\n";
        let e = Scene::from_toml(src, "s.toml").unwrap_err().to_string();
        assert!(e.starts_with("s.toml:5: black_hole[1].rs = 0"), "{e}");
    }

    #[test]
    fn unknown_key_is_rejected_with_its_line() {
        let src = "[disk]\ninner_radius = 3.0\nouter_radus = 12.0\n";
        let e = Scene::from_toml(src, "s.toml").unwrap_err().to_string();
        assert!(
            e.starts_with("s.toml:3: unknown field `outer_radus`"),
            "{e}"
        );
        assert!(!e.contains('\n'), "one line: {e}");
    }

    #[test]
    fn wrong_type_names_the_line_and_text() {
        let src = "[camera]\nvfov_deg = \"wide\"\n";
        let e = Scene::from_toml(src, "s.toml").unwrap_err().to_string();
        assert!(e.starts_with("s.toml:2: "), "{e}");
        assert!(e.contains("vfov_deg = \"wide\""), "{e}");
    }

    #[test]
    fn impossible_values_are_rejected() {
        let cases = [
            (
                "[disk]\ninner_radius = 12.0\nouter_radius = 3.0\n",
                "disk.outer_radius",
            ),
            ("[disk]\nnormal = [0.0, 0.0, 0.0]\n", "disk.normal"),
            ("[camera]\nvfov_deg = 180.0\n", "camera.vfov_deg"),
            ("[camera]\nvfov_deg = nan\n", "camera.vfov_deg"),
            ("[quality]\nsteps = 0\n", "quality.steps"),
            ("[camera]\nposition = [0.0, 0.0, 0.5]\n", "camera.position"),
            (
                "[camera]\nup = [0.0, 0.0, 1.0]\nposition = [0.0, 0.0, -10.0]\n",
                "camera.up",
            ),
            ("[[black_hole]]\nrs = inf\n", "black_hole[0].rs"),
        ];
        for (src, key) in cases {
            let e = Scene::from_toml(src, "s.toml").unwrap_err().to_string();
            assert!(e.contains(key), "{src:?} -> {e}");
            assert!(e.starts_with("s.toml:"), "{e}");
        }
    }

    #[test]
    fn camera_convention_matches_design() {
        let f = Camera::default().frame();
        // Looking toward +z from -z with +y up: +x is to the screen's right.
        assert!(f.right.x > 0.99);
        assert!(f.forward.z > 0.99);
        assert!(f.up.y > 0.99);
        // Top-left pixel points up and left, the centre straight ahead.
        let d = f.ray_dir(0, 0, 4, 2);
        assert!(d.x < 0.0 && d.y > f.forward.y);
        let c = f.ray_dir(1, 0, 3, 1);
        assert!((c - f.forward).length() < 1e-12);
    }
}
