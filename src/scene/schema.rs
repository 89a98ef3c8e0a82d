//! The scene schema: every TOML section as a serde struct with the defaults
//! of the built-in scene (omitted keys take them).

use std::path::Path;

use glam::DVec3;

pub use crate::camera::{CameraFrame, Projection, Stereo};

/// The eyes' distance for ODS when `ipd` is omitted, rs: small beside the
/// hole, so the parallax shows near it and not on the distant sky.
pub const DEFAULT_IPD: f64 = 0.1;
use serde::Deserialize;

use super::animation::Animation;
use super::polarization::Polarization;
use crate::physics::observer::ObserverKind;

/// Camera (the binding convention of docs/physics.md): `position`, `look_at`, `up`, `vfov_deg`.
#[derive(Clone, Copy, Debug, PartialEq, Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields, default)]
pub struct Camera {
    pub position: [f64; 3],
    pub look_at: [f64; 3],
    pub up: [f64; 3],
    pub vfov_deg: f64,
    /// Who holds the camera: "static" (at rest), "orbiting", "falling" or
    /// "flat" (the pixel direction used as the coordinate direction).
    pub observer: ObserverKind,
    /// How pixels become directions: "pinhole", "equirect" (the whole
    /// sphere, 2:1) or "fisheye" (equidistant; `vfov_deg` across the circle).
    pub projection: Projection,
    /// "none" or "ods" (omni-directional stereo, with equirect: left eye on
    /// top, right eye below).
    pub stereo: Stereo,
    /// The distance between the eyes for ODS, rs.
    pub ipd: f64,
}

impl Default for Camera {
    fn default() -> Self {
        Camera {
            position: [0.0, 0.8, -15.0],
            look_at: [0.0; 3],
            up: [0.0, 1.0, 0.0],
            vfov_deg: 60.0,
            observer: ObserverKind::Static,
            projection: Projection::Pinhole,
            stereo: Stereo::None,
            ipd: DEFAULT_IPD,
        }
    }
}

impl Camera {
    /// The camera's frame (src/camera: the binding convention).
    pub fn frame(&self) -> CameraFrame {
        CameraFrame::new(
            DVec3::from(self.position),
            DVec3::from(self.look_at),
            DVec3::from(self.up),
            self.vfov_deg,
        )
        .with_projection(self.projection, self.stereo, self.ipd)
    }
}

/// One `[[black_hole]]`: its place, its size rs and its spin a* (0: a
/// non-rotating hole; a spinning one must be the scene's only hole).
#[derive(Clone, Debug, PartialEq, Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields, default)]
pub struct BlackHole {
    pub position: [f64; 3],
    /// Schwarzschild radius (= 2M in G = c = 1), the unit of every length.
    pub rs: f64,
    /// Mass in solar masses, for display only (r_s = 2.953 km per solar mass).
    pub mass_solar: Option<f64>,
    /// Spin a* = a / M, signed (|a*| <= 0.9999): positive turns the same
    /// way as the disk, about the disk's normal.
    pub spin: f64,
}

impl Default for BlackHole {
    fn default() -> Self {
        BlackHole {
            position: [0.0; 3],
            rs: 1.0,
            mass_solar: None,
            spin: 0.0,
        }
    }
}

/// What kind of disk surrounds the (first) hole.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum DiskKind {
    Thin,
    Volumetric,
    None,
}

/// The accretion disk, centred on the first hole.
#[derive(Clone, Debug, PartialEq, Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields, default)]
pub struct Disk {
    pub kind: DiskKind,
    pub normal: [f64; 3],
    /// A number (rs), or `"isco"`: the innermost stable circular orbit of
    /// the (first) hole's spin, prograde for a* >= 0 and retrograde below
    /// (3 rs at spin 0), resolved when the scene is read. Omitted in a scene
    /// file it is `"isco"`, as in the built-in default scene (`Disk::default`
    /// holds its value at spin 0).
    #[serde(default = "isco_mark", deserialize_with = "number_or_isco")]
    pub inner_radius: f64,
    pub outer_radius: f64,
    /// `"page-thorne"` (the default) or `"newtonian"`.
    pub temperature_profile: TemperatureProfile,
    /// Emission scale (luminance of the hottest ring, seen unshifted).
    pub brightness: f64,
    /// Temperature of the hottest ring, kelvin.
    pub temperature_k: f64,
    /// Thin disk: contrast of its filaments and clumps (0: smooth, the
    /// bare Novikov-Thorne disk; 1: fully structured). Each element turns
    /// with its own Keplerian orbit (`speed`, time from [animation]).
    pub structure: f64,
    /// Thin disk: opacity where the density is average (1: opaque there;
    /// thinner parts let the light behind through).
    pub opacity: f64,
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
    /// How fast the gas turns (x Keplerian; time from [animation]).
    pub speed: f64,
    /// Volumetric disk: emission scale.
    pub lit: f64,
    /// Volumetric disk colour: the blackbody of the physical disk (with its
    /// shifts), or a film-like colour map.
    pub color: VolumeColor,
}

/// The thin disk's temperature profile.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum TemperatureProfile {
    /// T^4 ~ r^-3 (1 - sqrt(r_in / r)), the Newtonian limit (peak at 49/36 r_in).
    Newtonian,
    /// Page & Thorne (1974): the relativistic Novikov-Thorne flux for the
    /// hole's spin, zero at its ISCO whatever inner_radius says (the
    /// default for every spin, 0 included).
    #[default]
    PageThorne,
}

/// How the volumetric disk is coloured.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, serde::Serialize)]
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
            temperature_profile: TemperatureProfile::PageThorne,
            brightness: 1.2,
            temperature_k: 6000.0,
            structure: 0.8,
            opacity: 1.0,
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
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, serde::Serialize)]
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
    /// The real stars (Hipparcos, to magnitude 7.5) at their places, with
    /// the Milky Way's band along the galactic plane (`galaxy`).
    Catalogue,
    Black,
}

/// What a camera inside a horizon sees where the light came from the other
/// universe of the eternal hole (E <= 0).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum OtherUniverse {
    /// Nothing: a hole formed by collapse has no other universe.
    #[default]
    Black,
    /// The eternal hole's second exterior, given a copy of this sky (its
    /// own is unknowable): the light paths there are exact, the sky a
    /// stand-in.
    Mirror,
}

/// The sky (celestial sphere).
#[derive(Clone, Debug, PartialEq, Deserialize, serde::Serialize)]
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
    /// Catalogue sky: which celestial frame the world's axes follow.
    pub frame: crate::stars::SkyFrame,
    /// Catalogue sky: turn of the sky about +y, degrees (counter-clockwise
    /// seen from above).
    pub rotation_deg: f64,
    /// Catalogue sky: then its tilt about +z, degrees.
    pub tilt_deg: f64,
    /// Inside a horizon: what the light from the other universe shows.
    pub other_universe: OtherUniverse,
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
            kind: SkyKind::Catalogue,
            squares: 24,
            star_density: 0.5,
            galaxy: 0.02,
            brightness: 1.0,
            image: None,
            cubemap: None,
            frame: crate::stars::SkyFrame::Galactic,
            rotation_deg: 20.0,
            tilt_deg: 35.0,
            other_universe: OtherUniverse::Black,
        }
    }
}

/// A grid of lines on a square plane behind the hole, to show the lensing.
#[derive(Clone, Debug, PartialEq, Deserialize, serde::Serialize)]
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
#[derive(Clone, Debug, PartialEq, Deserialize, serde::Serialize)]
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
#[derive(Clone, Debug, PartialEq, Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields, default)]
pub struct Physics {
    /// Bend light (off: straight rays; the horizon still absorbs).
    pub gravity: bool,
    /// Doppler shift of the orbiting disk's colour (its observed temperature).
    pub doppler: bool,
    /// Doppler beaming: the approaching side brighter by g^4, the receding
    /// side dimmer.
    pub beaming: bool,
    /// Gravitational redshift of the disk's light (colour and brightness).
    pub gravitational_redshift: bool,
    /// Shift the sky's light by the g the camera measures of light from
    /// rest at infinity (brightness by g^4, colour as 6500 K light's): the
    /// sky above a falling camera dims and reddens, below it brightens and
    /// blues. Off by default (the sky as the catalogue or image gives it);
    /// the presets that fall through the horizon turn it on.
    pub sky_shift: bool,
}

impl Default for Physics {
    fn default() -> Self {
        Physics {
            gravity: true,
            doppler: true,
            beaming: true,
            gravitational_redshift: true,
            sky_shift: false,
        }
    }
}

/// The tone curve of the 8-bit output.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Tonemap {
    /// The ACES tone curve (Hill's RRT+ODT fit) applied to each pixel's
    /// brightest channel and the pixel scaled by it: luminance is compressed,
    /// hue and saturation kept (the disk's colours stay those of the
    /// blackbody at its observed temperature), nothing clips.
    HuePreserving,
    /// Stephen Hill's RRT+ODT fit of ACES (the fuller one).
    AcesHill,
    /// Krzysztof Narkowicz's one-line ACES fit.
    AcesNarkowicz,
    /// Clamp only (for checking values).
    Linear,
}

/// Post-processing.
#[derive(Clone, Debug, PartialEq, Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields, default)]
pub struct Post {
    /// Exposure in EV stops (x 2^ev before tone mapping); with
    /// `auto_exposure`, a compensation added to the metered exposure.
    pub exposure_ev: f64,
    /// Meter each frame: the mean log luminance of a band of the lit pixels'
    /// histogram is brought to mid grey.
    pub auto_exposure: bool,
    /// The metered band, as fractions of the lit pixels from the darkest.
    pub meter_low: f64,
    pub meter_high: f64,
    /// Colour saturation before the tone map (1: as rendered; above 1 the
    /// colours move away from grey at the same luminance and hue).
    pub saturation: f64,
    pub tonemap: Tonemap,
    /// Triangular dither of +-1 step in the 8-bit output.
    pub dither: bool,
}

impl Default for Post {
    fn default() -> Self {
        Post {
            exposure_ev: 0.0,
            auto_exposure: true,
            meter_low: 0.5,
            meter_high: 0.95,
            saturation: 1.0,
            tonemap: Tonemap::HuePreserving,
            dither: true,
        }
    }
}

/// The bloom mip chain.
#[derive(Clone, Debug, PartialEq, Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields, default)]
pub struct Bloom {
    /// How much of the blurred bright light is added (0: no bloom, no passes).
    pub strength: f64,
    /// Brightest-channel value above which light blooms.
    pub threshold: f64,
    /// Width of the soft knee around the threshold.
    pub knee: f64,
    /// Mip levels of the chain, 1 to 8: the first a quarter of the image
    /// size, each next one half the one before.
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
#[derive(Clone, Debug, PartialEq, Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields, default)]
pub struct Scene {
    pub camera: Camera,
    #[serde(rename = "black_hole")]
    pub black_holes: Vec<BlackHole>,
    #[serde(default = "disk_in_a_file")]
    pub disk: Disk,
    pub sky: Sky,
    #[serde(rename = "grid_plane")]
    pub plane: GridPlane,
    pub quality: Quality,
    pub physics: Physics,
    pub bloom: Bloom,
    pub post: Post,
    pub animation: Animation,
    pub polarization: Polarization,
    /// Seconds since the start of the animation (set per frame, not read from TOML).
    #[serde(skip)]
    pub time: f64,
    /// Folder that relative file names in the scene are resolved against.
    #[serde(skip)]
    pub base_dir: std::path::PathBuf,
    /// The file the scene was read from (none for a preset or an edit).
    #[serde(skip)]
    pub source: Option<std::path::PathBuf>,
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
            polarization: Polarization::default(),
            time: 0.0,
            base_dir: std::path::PathBuf::new(),
            source: None,
        }
    }
}

/// Most holes one scene may have (the shader's fixed array).
pub const MAX_HOLES: usize = 8;

/// What `[disk] inner_radius = "isco"` reads as until the scene resolves it
/// ([`crate::Scene::from_toml`]): a NaN whose payload no TOML number has (a
/// scene's `nan` is the canonical NaN), so it cannot be written by hand.
pub const ISCO_MARK: u64 = 0x7ff8_0000_1c0d_0001;

fn isco_mark() -> f64 {
    f64::from_bits(ISCO_MARK)
}

/// A scene file without `[disk]`: the default disk, its inner edge at the
/// spin's ISCO.
fn disk_in_a_file() -> Disk {
    Disk {
        inner_radius: isco_mark(),
        ..Disk::default()
    }
}

fn number_or_isco<'de, D: serde::Deserializer<'de>>(d: D) -> Result<f64, D::Error> {
    #[derive(Deserialize)]
    #[serde(untagged)]
    enum NumberOrName {
        Number(f64),
        Integer(i64),
        Name(String),
    }
    match NumberOrName::deserialize(d)? {
        NumberOrName::Number(x) => Ok(x),
        NumberOrName::Integer(i) => Ok(i as f64),
        NumberOrName::Name(n) if n == "isco" => Ok(f64::from_bits(ISCO_MARK)),
        NumberOrName::Name(n) => Err(serde::de::Error::custom(format!(
            "expected a radius or \"isco\", found \"{n}\""
        ))),
    }
}
