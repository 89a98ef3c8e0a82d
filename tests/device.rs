//! The tests that need something of the device: a capability it may lack
//! (ray differentials, the split ray march, 64-bit floats) or, for the
//! golden images, the driver they were blessed on. Each is declared here
//! with what it needs (as wgpu's test parameters do); the harness
//! (libtest-mimic) asks the device once and lists a test it cannot run as
//! ignored, under its own name and with what it needs, so the summary never
//! counts it as passed. The tests themselves live beside their kin
//! (golden.rs, kerr_gpu.rs, render.rs, sky.rs), compiled here only.

// Each file included below brings its own `mod common`, as in its own
// target.
#![allow(clippy::duplicate_mod)]

use std::process::ExitCode;

use libtest_mimic::{Arguments, Trial};

mod common;
#[allow(unused_imports)]
#[path = "golden.rs"]
mod golden;
#[allow(unused_imports)]
#[path = "kerr_gpu.rs"]
mod kerr_gpu;
#[allow(unused_imports)]
#[path = "polarization_gpu.rs"]
mod polarization_gpu;
#[allow(unused_imports)]
#[path = "render.rs"]
mod render;
#[allow(unused_imports)]
#[path = "sky.rs"]
mod sky;

/// What a test needs of the device.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
enum Need {
    /// 2x2 subgroup quads: the lensed footprint of each pixel on the sky.
    RayDifferentials,
    /// The split ray march (a CPU device with quad and ballot operations,
    /// and neither BLACKHOLE_NO_SPLIT=1 nor BLACKHOLE_NO_QUAD=1).
    Split,
    /// 64-bit floats for a spinning hole's per-ray constants (not under
    /// BLACKHOLE_NO_F64=1).
    Float64,
    /// The driver the golden images were blessed on, with ray differentials.
    BlessedDevice,
}

/// Why the device cannot run a test needing `need`, if it cannot.
fn lacks(need: Need, features: &blackhole::features::Features) -> Option<String> {
    let why = match need {
        Need::RayDifferentials if !features.ray_differentials => {
            "ray differentials (subgroup quads; off with BLACKHOLE_NO_QUAD=1)".to_string()
        }
        Need::Split if !features.split => "the split ray march (a CPU device with subgroup \
             quads and ballots; off with BLACKHOLE_NO_SPLIT=1 or BLACKHOLE_NO_QUAD=1)"
            .to_string(),
        Need::Float64 if !features.kerr_f64 => {
            "64-bit floats in shaders (shaderFloat64; off with BLACKHOLE_NO_F64=1)".to_string()
        }
        Need::BlessedDevice => golden::blessed_device().err()?,
        _ => return None,
    };
    Some(why)
}

fn main() -> ExitCode {
    let args = Arguments::from_args();
    let features = common::renderer().features();
    let tests: [(&str, Need, fn()); 9] = [
        (
            "presets_match_their_golden_images",
            Need::BlessedDevice,
            golden::presets_match_their_golden_images,
        ),
        (
            "gpu_kerr_aov_matches_the_f64_closed_form",
            Need::Float64,
            kerr_gpu::gpu_kerr_aov_matches_the_f64_closed_form,
        ),
        (
            "gpu_kerr_inside_matches_the_f64_closed_form",
            Need::Float64,
            kerr_gpu::gpu_kerr_inside_matches_the_f64_closed_form,
        ),
        (
            "gpu_stokes_matches_the_transported_reference",
            Need::Float64,
            polarization_gpu::gpu_stokes_matches_the_transported_reference,
        ),
        (
            "gpu_stokes_of_a_thin_volumetric_slab_matches_the_transported_disk",
            Need::Float64,
            polarization_gpu::gpu_stokes_of_a_thin_volumetric_slab_matches_the_transported_disk,
        ),
        (
            "gpu_stokes_of_a_thick_volumetric_slab_lies_among_its_transported_planes",
            Need::Float64,
            polarization_gpu::gpu_stokes_of_a_thick_volumetric_slab_lies_among_its_transported_planes,
        ),
        (
            "the_spinning_holes_split_draws_what_the_single_dispatch_draws",
            Need::Split,
            render::the_spinning_holes_split_draws_what_the_single_dispatch_draws,
        ),
        (
            "the_split_disk_pass_draws_what_the_single_dispatch_draws",
            Need::Split,
            render::the_split_disk_pass_draws_what_the_single_dispatch_draws,
        ),
        (
            "a_lensed_star_brightens_by_the_point_lens_magnification",
            Need::RayDifferentials,
            sky::a_lensed_star_brightens_by_the_point_lens_magnification,
        ),
    ];
    let trials = tests
        .into_iter()
        .map(|(name, need, test)| {
            let lacking = lacks(need, &features);
            if let Some(why) = &lacking {
                println!("{name}: ignored on this device, which lacks what it needs: {why}");
            }
            Trial::test(name, move || {
                test();
                Ok(())
            })
            .with_ignored_flag(lacking.is_some())
        })
        .collect();
    libtest_mimic::run(&args, trials).exit_code()
}
