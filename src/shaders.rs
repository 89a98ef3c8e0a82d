//! SPIR-V compiled by build.rs from `shaders/*.comp`, embedded in the binary.

/// The ray march (`shaders/raymarch.comp`).
pub const RAYMARCH: &[u8] = include_bytes!(concat!(env!("OUT_DIR"), "/raymarch.comp.spv"));
/// The composite (`shaders/composite.comp`).
pub const COMPOSITE: &[u8] = include_bytes!(concat!(env!("OUT_DIR"), "/composite.comp.spv"));
/// The ray march without subgroup quads (unlensed star footprints), for
/// devices that lack quad operations in compute shaders.
pub const RAYMARCH_NO_QUAD: &[u8] =
    include_bytes!(concat!(env!("OUT_DIR"), "/raymarch_no_quad.comp.spv"));
/// The ray march writing the geodesic AOV (`raymarch.comp` with `GEODESIC_AOV`).
pub const RAYMARCH_AOV: &[u8] = include_bytes!(concat!(env!("OUT_DIR"), "/raymarch_aov.comp.spv"));
/// The ray march's split thin-disk stages (`DISK_SPLIT`: the trace pass
/// that lists disk pixels and the indirect disk pass).
pub const RAYMARCH_SPLIT: &[u8] =
    include_bytes!(concat!(env!("OUT_DIR"), "/raymarch_split.comp.spv"));
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
