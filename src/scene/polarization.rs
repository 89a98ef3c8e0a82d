//! `[polarization]`: the thin disk as a synchrotron-like emitter whose
//! linear polarization is carried exactly to the camera, and how its picture
//! is drawn (Stokes I in a colour map with the polarization's ticks over it,
//! through a telescope's beam) and measured (docs/polarization.md).

use serde::Deserialize;

use super::locate::Seg::Key;
use super::rule::{Check, fail, vec3};
use super::validate::{InRange, direction, rule};
use super::{Camera, Scene};

/// The most field models drawn side by side (`fields`).
pub const MAX_FIELDS: usize = 4;
/// The most ticks across the picture's height.
pub const MAX_TICKS: u32 = 200;

/// G M_sun / c^2 in metres (IAU 2015 nominal solar mass parameter).
const SUN_GM_C2_M: f64 = 1_476.625_038;
/// One parsec in metres.
const PARSEC_M: f64 = 3.085_677_581_491_367e16;
/// Microarcseconds in a radian.
const UAS_PER_RAD: f64 = 180.0 / std::f64::consts::PI * 3600.0 * 1e6;

/// `[polarization]` (DESIGN: "Polarized light"; the picture's keys are this
/// renderer's own).
#[derive(Clone, Debug, PartialEq, Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields, default)]
pub struct Polarization {
    /// Draw the polarized picture (Stokes I and ticks) instead of the
    /// disk's light; `--aov stokes` implies it.
    pub enabled: bool,
    /// The field on the gas's frame (e_(r), e_(phi), e_(z)); any non-zero
    /// vector, used normalised.
    pub field: [f64; 3],
    /// alpha: I_nu proportional to nu^-alpha.
    pub spectral_index: f64,
    /// n: emissivity proportional to r^-n.
    pub emissivity_index: f64,
    /// The polarized share of the emitted light, 0 to 1.
    pub fraction: f64,
    /// What the colour map under the ticks shows.
    pub view: PolarizedView,
    /// The colour map of the picture.
    pub colormap: Colormap,
    /// How I (or P) is mapped onto the colour map, from the picture's
    /// brightest pixel down.
    pub brightness: Brightness,
    /// Ticks across the picture's height (0: none); each tick's length
    /// grows with the polarized intensity, its colour with the fraction.
    pub ticks: u32,
    /// No tick where the (blurred) Stokes I is below this share of the
    /// picture's brightest pixel.
    pub tick_cut: f64,
    /// The telescope's beam, full width at half maximum, microarcseconds
    /// (0: none): I, Q and U are blurred by it before the ticks are drawn.
    pub beam: f64,
    /// The hole's mass in solar masses and its distance in parsecs: with
    /// them the picture has an angular scale (GM/c^2 / distance).
    pub mass_msun: f64,
    pub distance_pc: f64,
    /// The ring annulus over which beta_2 is summed, [inner, outer] radii
    /// on the image plane in GM/c^2 around the image's centre.
    pub annulus: [f64; 2],
    /// Field models drawn side by side (up to four, each a picture of the
    /// whole view, left to right); empty: one picture with `field`.
    pub fields: Vec<[f64; 3]>,
}

impl Default for Polarization {
    fn default() -> Self {
        Polarization {
            enabled: false,
            field: [0.87, 0.5, 0.0],
            spectral_index: 1.0,
            emissivity_index: 2.0,
            fraction: 0.7,
            view: PolarizedView::Intensity,
            colormap: Colormap::Inferno,
            brightness: Brightness::Linear,
            ticks: 24,
            tick_cut: 0.1,
            beam: 0.0,
            mass_msun: 6.5e9,
            distance_pc: 16.8e6,
            annulus: [3.0, 12.0],
            fields: Vec::new(),
        }
    }
}

/// What the polarized picture's colour map shows.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum PolarizedView {
    /// Stokes I, as the EHT's figures show it.
    Intensity,
    /// The polarized intensity P = |Q + iU|.
    Polarized,
    /// The fraction m = P / I (0 to `fraction`).
    Fraction,
}

impl PolarizedView {
    pub const ALL: [PolarizedView; 3] = [
        PolarizedView::Intensity,
        PolarizedView::Polarized,
        PolarizedView::Fraction,
    ];

    pub fn name(self) -> &'static str {
        match self {
            PolarizedView::Intensity => "intensity",
            PolarizedView::Polarized => "polarized",
            PolarizedView::Fraction => "fraction",
        }
    }

    /// The code `shaders/pol_map.comp` reads.
    pub fn gpu_id(self) -> u32 {
        self as u32
    }
}

/// The polarized picture's colour map.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Colormap {
    /// Perceptually uniform, black through purple and orange to pale yellow
    /// (matplotlib's inferno).
    Inferno,
    /// Black through red and orange to white, as the EHT draws M87*
    /// (matplotlib's afmhot).
    Afmhot,
}

impl Colormap {
    pub const ALL: [Colormap; 2] = [Colormap::Inferno, Colormap::Afmhot];

    pub fn name(self) -> &'static str {
        match self {
            Colormap::Inferno => "inferno",
            Colormap::Afmhot => "afmhot",
        }
    }

    /// The code `shaders/pol_map.comp` reads.
    pub fn gpu_id(self) -> u32 {
        self as u32
    }
}

/// How the picture's brightness is mapped onto its colour map.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, serde::Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Brightness {
    /// In proportion (as the EHT's figures).
    Linear,
    /// Its square root: the fainter disk shows.
    Sqrt,
    /// Logarithmic over three decades below the brightest pixel.
    Log,
}

impl Brightness {
    pub const ALL: [Brightness; 3] = [Brightness::Linear, Brightness::Sqrt, Brightness::Log];

    pub fn name(self) -> &'static str {
        match self {
            Brightness::Linear => "linear",
            Brightness::Sqrt => "sqrt",
            Brightness::Log => "log",
        }
    }

    /// The code `shaders/pol_map.comp` reads.
    pub fn gpu_id(self) -> u32 {
        self as u32
    }
}

impl Polarization {
    /// GM/c^2 of the hole as an angle on the sky, microarcseconds.
    pub fn gravitational_angle_uas(&self) -> f64 {
        self.mass_msun * SUN_GM_C2_M / (self.distance_pc * PARSEC_M) * UAS_PER_RAD
    }

    /// The field models of the picture, left to right (`fields`, or the one
    /// `field`), as written.
    pub fn models(&self) -> Vec<[f64; 3]> {
        if self.fields.is_empty() {
            vec![self.field]
        } else {
            self.fields.clone()
        }
    }
}

impl Scene {
    /// The image plane's scale for the polarized picture and its numbers:
    /// GM/c^2 per pixel at the image's centre, for an image (one field
    /// model's tile) `height` pixels high. The camera at distance d from the
    /// hole sees a ray of impact parameter b at the angle b / d, so a
    /// pixel's angle times d is its size on the image plane (to within
    /// rs / d: a tenth of a per cent at 1000 rs).
    pub fn image_plane_scale(&self, camera: &Camera, width: u32, height: u32) -> f64 {
        let hole = self
            .black_holes
            .first()
            .map_or(glam::DVec3::ZERO, |h| glam::DVec3::from(h.position));
        let rs = self.black_holes.first().map_or(1.0, |h| h.rs);
        let d = (glam::DVec3::from(camera.position) - hole).length() / rs;
        // rs = 2 GM/c^2.
        2.0 * d * camera.frame().pixel_angle(width, height)
    }

    /// The beam's standard deviation in pixels of a picture (one field
    /// model's) `width` x `height` pixels: 0 without a beam.
    pub fn beam_sigma_pixels(&self, width: u32, height: u32) -> f64 {
        let p = &self.polarization;
        let per_pixel =
            self.image_plane_scale(&self.camera, width, height) * p.gravitational_angle_uas();
        let sigma = p.beam / per_pixel / (8.0 * std::f64::consts::LN_2).sqrt();
        if per_pixel > 0.0 && sigma.is_finite() {
            sigma
        } else {
            0.0
        }
    }

    /// The columns of each field model's picture in an image `width` pixels
    /// wide, left to right (as shaders/include/polarization.glsl's pol_tile).
    pub fn picture_columns(&self, width: u32) -> Vec<(u32, u32)> {
        let n = self.polarization.models().len() as u32;
        (0..n)
            .map(|t| (t * width / n, (t + 1) * width / n))
            .collect()
    }

    pub(super) fn validate_polarization(&self) -> Check {
        let p = &self.polarization;
        let key = |k| [Key("polarization"), Key(k)];
        direction(&key("field"), &p.field)?;
        if p.enabled {
            if let Some(why) = self.spacetime().polarization_refusal() {
                return fail(
                    &key("enabled"),
                    true,
                    format!("the polarized picture {why}"),
                );
            }
        }
        let within = |k, v: f64, lo: f64, hi: f64| {
            rule(
                v.in_range() && (lo..=hi).contains(&v),
                &key(k),
                v,
                format!("must be in [{lo}, {hi}]"),
            )
        };
        within("spectral_index", p.spectral_index, -1.0, 5.0)?;
        within("emissivity_index", p.emissivity_index, -10.0, 10.0)?;
        within("fraction", p.fraction, 0.0, 1.0)?;
        within("tick_cut", p.tick_cut, 0.0, 1.0)?;
        within("beam", p.beam, 0.0, 1e6)?;
        rule(
            p.ticks <= MAX_TICKS,
            &key("ticks"),
            p.ticks,
            format!("must be 0 to {MAX_TICKS}"),
        )?;
        // Masses from a star's to a quasar's, distances from a parsec to
        // beyond the observable universe (both above the 1e9 of other keys).
        let astronomical = |k, v: f64, lo: f64, hi: f64| {
            rule(
                v.is_finite() && (lo..=hi).contains(&v),
                &key(k),
                v,
                format!("must be a number from {lo:e} to {hi:e}"),
            )
        };
        astronomical("mass_msun", p.mass_msun, 1e-3, 1e12)?;
        astronomical("distance_pc", p.distance_pc, 1e-6, 1e11)?;
        let [inner, outer] = p.annulus;
        rule(
            inner.in_range() && outer.in_range() && 0.0 <= inner && inner < outer,
            &key("annulus"),
            format!("[{inner}, {outer}]"),
            "must be [inner, outer] radii in GM/c^2 with 0 <= inner < outer",
        )?;
        rule(
            p.fields.len() <= MAX_FIELDS,
            &key("fields"),
            format!("{} entries", p.fields.len()),
            format!("at most {MAX_FIELDS} field models are drawn side by side"),
        )?;
        for (i, f) in p.fields.iter().enumerate() {
            let at = [
                Key("polarization"),
                Key("fields"),
                super::locate::Seg::Idx(i),
            ];
            rule(
                f.iter().all(|x| x.in_range()) && glam::DVec3::from(*f).length() >= 1e-9,
                &at,
                vec3(f),
                "must be a finite, non-zero vector (sizes at most 1e9)",
            )?;
        }
        Ok(())
    }
}
