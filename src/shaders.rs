//! SPIR-V compiled by build.rs from `shaders/*.comp`, embedded in the binary.

use crate::spacetime::GpuPath;

/// Which build of the ray march (`shaders/raymarch.comp`) for a metric.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum RaymarchBuild {
    /// Linear HDR, star footprints from subgroup quads.
    Beauty,
    /// Without subgroup quads (unlensed star footprints), for devices that
    /// lack quad operations in compute shaders (`NO_QUAD`).
    NoQuad,
    /// The geodesic AOV (`GEODESIC_AOV`).
    Aov,
    /// The split stages (`SPLIT_PASSES`: the trace pass that lists pixels and
    /// the indirect pass over them): the thin disk around a non-rotating
    /// hole, the rarer paths around a spinning one.
    Split,
}

macro_rules! spv {
    ($stem:literal) => {
        include_bytes!(concat!(env!("OUT_DIR"), "/", $stem, ".comp.spv"))
    };
}

/// The ray march compiled for one metric (`shaders/include/metric.glsl`,
/// the define build.rs sets) and one build; `None` for the split stages of
/// a metric with no closed form. The spinning hole has two: its
/// per-ray constants in 64-bit floats (`kerr_f64`, where the device has
/// them) or in 32-bit ones (`KERR_F32_ROOTS`).
pub fn raymarch(path: GpuPath, build: RaymarchBuild, kerr_f64: bool) -> Option<&'static [u8]> {
    use GpuPath::*;
    use RaymarchBuild::*;
    Some(match (path, build) {
        (Kerr, Beauty) if !kerr_f64 => spv!("raymarch_kerr_f32"),
        (Kerr, NoQuad) if !kerr_f64 => spv!("raymarch_kerr_f32_no_quad"),
        (Kerr, Aov) if !kerr_f64 => spv!("raymarch_kerr_f32_aov"),
        (Kerr, Split) if !kerr_f64 => spv!("raymarch_kerr_f32_split"),
        (ClosedForm, Beauty) => spv!("raymarch_schwarzschild"),
        (ClosedForm, NoQuad) => spv!("raymarch_schwarzschild_no_quad"),
        (ClosedForm, Aov) => spv!("raymarch_schwarzschild_aov"),
        (ClosedForm, Split) => spv!("raymarch_schwarzschild_split"),
        (Straight, Beauty) => spv!("raymarch_flat"),
        (Straight, NoQuad) => spv!("raymarch_flat_no_quad"),
        (Straight, Aov) => spv!("raymarch_flat_aov"),
        (Integrated, Beauty) => spv!("raymarch_summed"),
        (Integrated, NoQuad) => spv!("raymarch_summed_no_quad"),
        (Integrated, Aov) => spv!("raymarch_summed_aov"),
        (Kerr, Beauty) => spv!("raymarch_kerr"),
        (Kerr, NoQuad) => spv!("raymarch_kerr_no_quad"),
        (Kerr, Aov) => spv!("raymarch_kerr_aov"),
        (Kerr, Split) => spv!("raymarch_kerr_split"),
        (Straight | Integrated, Split) => return None,
    })
}

/// The composite (`shaders/composite.comp`).
pub const COMPOSITE: &[u8] = include_bytes!(concat!(env!("OUT_DIR"), "/composite.comp.spv"));
/// Bloom bright pass to a quarter of the size (`shaders/bloom_prefilter.comp`).
pub const BLOOM_PREFILTER: &[u8] =
    include_bytes!(concat!(env!("OUT_DIR"), "/bloom_prefilter.comp.spv"));
/// Bloom downsample (`shaders/bloom_down.comp`).
pub const BLOOM_DOWN: &[u8] = include_bytes!(concat!(env!("OUT_DIR"), "/bloom_down.comp.spv"));
/// Bloom upsample (`shaders/bloom_up.comp`).
pub const BLOOM_UP: &[u8] = include_bytes!(concat!(env!("OUT_DIR"), "/bloom_up.comp.spv"));
/// The composite writing linear HDR (`composite.comp` with `HDR_OUTPUT`).
pub const COMPOSITE_HDR: &[u8] =
    include_bytes!(concat!(env!("OUT_DIR"), "/composite_hdr.comp.spv"));
/// Progressive accumulation of jittered frames (`shaders/accumulate.comp`).
pub const ACCUMULATE: &[u8] = include_bytes!(concat!(env!("OUT_DIR"), "/accumulate.comp.spv"));
/// Automatic exposure metering (`shaders/exposure.comp`).
pub const EXPOSURE: &[u8] = include_bytes!(concat!(env!("OUT_DIR"), "/exposure.comp.spv"));
/// The telescope's beam over the Stokes image (`shaders/pol_beam.comp`).
pub const POL_BEAM: &[u8] = include_bytes!(concat!(env!("OUT_DIR"), "/pol_beam.comp.spv"));
/// The polarized picture's scale (`shaders/pol_peak.comp`).
pub const POL_PEAK: &[u8] = include_bytes!(concat!(env!("OUT_DIR"), "/pol_peak.comp.spv"));
/// The polarized picture's ticks (`shaders/pol_ticks.comp`).
pub const POL_TICKS: &[u8] = include_bytes!(concat!(env!("OUT_DIR"), "/pol_ticks.comp.spv"));
/// The polarized picture: colour map and ticks (`shaders/pol_map.comp`).
pub const POL_MAP: &[u8] = include_bytes!(concat!(env!("OUT_DIR"), "/pol_map.comp.spv"));
