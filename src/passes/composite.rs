//! Composite: bloom added to the HDR image, exposure (EV stops), a filmic tone
//! map, sRGB encoding and a triangular dither into an 8-bit image. Tone curves:
//! Stephen Hill's RRT+ODT fit of ACES (default) and Narkowicz's one-line fit
//! ("ACES Filmic Tone Mapping Curve", 2016).

use ash::vk;
use bytemuck::{Pod, Zeroable};

use std::sync::Arc;

use super::VariantCache;
use super::compute::{self, Binding, ComputePass};
use crate::Result;
use crate::graph::{BufferHandle, Graph, ImageDesc, ImageHandle};
use crate::scene::{Bloom, Post, Tonemap};
use crate::vk::{Access, Buffer, ComputePipeline, Gpu, Sampler};

/// 8-bit output format (sRGB-encoded values in a UNORM image: storage images
/// cannot be SRGB).
pub const LDR_FORMAT: vk::Format = vk::Format::R8G8B8A8_UNORM;
/// Format of the linear composite (`--exr-post`).
pub const HDR_POST_FORMAT: vk::Format = vk::Format::R16G16B16A16_SFLOAT;

/// Tone-map codes mirrored from `shaders/composite.comp` (tests/layout.rs
/// checks them against the GLSL source).
pub mod glsl {
    pub const TONEMAP_ACES_HILL: u32 = 0;
    pub const TONEMAP_ACES_NARKOWICZ: u32 = 1;
    pub const TONEMAP_LINEAR: u32 = 2;
    pub const TONEMAP_HUE_PRESERVING: u32 = 3;
}

/// Push constants of `shaders/composite.comp`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct CompositePush {
    pub exposure: f32,
    pub width: u32,
    pub height: u32,
    pub bloom_strength: f32,
    pub dither: f32,
    pub saturation: f32,
}

/// A specialisation of composite.comp (its constants and the HDR build): on a
/// CPU driver every branch runs for every pixel, so the tone maps, bloom and
/// the upscale a frame does not use are compiled out.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Variant {
    /// Linear HDR out (`--exr-post`), no tone map.
    pub linear: bool,
    /// The ray march is smaller than the output: bilinear upscale (constant 0).
    pub upscale: bool,
    /// `glsl::TONEMAP_*` (constant 1).
    pub tonemap: u32,
    /// Bloom is added (constant 2).
    pub bloom: bool,
    /// The metered exposure multiplies (constant 3).
    pub auto_exposure: bool,
    /// The saturation is not 1 (constant 4).
    pub saturate: bool,
    /// 2x2 pixels an invocation, sharing four bloom texels: bloom on, the
    /// output the ray march's size and a multiple of 4 (constant 5).
    pub blocks: bool,
    /// Where the HDR image's alpha is 0 there is no ray: black, alpha 0
    /// (constant 6; else alpha 1 everywhere).
    pub mask: bool,
}

impl Variant {
    /// The GLSL names of [`Variant::constants`], in `constant_id` order
    /// (tests/layout.rs checks them against composite.comp).
    pub const CONSTANT_NAMES: [&'static str; 7] = [
        "UPSCALE",
        "TONEMAP",
        "BLOOM",
        "AUTO_EXPOSURE",
        "SATURATE",
        "BLOCKS",
        "MASK",
    ];

    pub fn constants(&self) -> [u32; 7] {
        [
            u32::from(self.upscale),
            self.tonemap,
            u32::from(self.bloom),
            u32::from(self.auto_exposure),
            u32::from(self.saturate),
            u32::from(self.blocks),
            u32::from(self.mask),
        ]
    }
}

/// What the composite makes: the 8-bit image the tone map ends in, or the
/// linear HDR image with bloom and exposure only (`--exr-post`: no tone
/// map, no dither).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum CompositeOutput {
    Ldr,
    LinearHdr,
}

/// How the composite makes it.
pub struct CompositeOptions<'s> {
    pub bloom: &'s Bloom,
    pub post: &'s Post,
    pub output: CompositeOutput,
    /// Pixels the ray march left transparent have no ray (a fisheye's
    /// corners): keep them black and transparent.
    pub mask_no_ray: bool,
}

/// `shaders/composite.comp`'s bindings (both builds).
pub const BINDINGS: [Binding; 4] = [
    Binding::sampled("hdr"),
    Binding::storage_image("ldr"),
    Binding::sampled("bloom"),
    Binding::storage_buffer("Metered"),
];

/// The composite's inputs besides the HDR image.
pub struct CompositeInputs<'h> {
    /// Level 0 of the bloom chain, if bloom is on.
    pub bloom: Option<&'h ImageHandle>,
    /// The metered exposure (one f32), if automatic.
    pub exposure: Option<&'h BufferHandle>,
}

/// The composite's pipelines by variant (built on first use), its sampler
/// and the buffer bound where there is no metered exposure, owned by this
/// pass.
pub struct CompositePipelines {
    cache: VariantCache<Variant>,
    gpu: Arc<Gpu>,
    sampler: Sampler,
    placeholder: Buffer,
}

impl CompositePipelines {
    pub fn new(gpu: &Arc<Gpu>) -> Result<Self> {
        Ok(CompositePipelines {
            cache: VariantCache::new(),
            gpu: gpu.clone(),
            sampler: Sampler::linear_clamp(gpu)?,
            placeholder: super::placeholder_buffer(gpu)?,
        })
    }

    /// The composite specialised for its output, tone map, bloom and
    /// upscaling (composite.comp's constants), built on first use and kept.
    pub fn pipeline(&self, variant: Variant) -> Result<Arc<ComputePipeline>> {
        self.cache.get(variant, || {
            let spirv = if variant.linear {
                crate::shaders::COMPOSITE_HDR
            } else {
                crate::shaders::COMPOSITE
            };
            ComputePipeline::with_constants(
                &self.gpu,
                &format!("{variant:?}"),
                spirv,
                &compute::kinds(&BINDINGS),
                std::mem::size_of::<CompositePush>() as u32,
                &variant.constants(),
            )
        })
    }
}

/// Adds the composite of `hdr` (plus `bloom`, level 0, if given) at the
/// graph's output size (upscaling `hdr` bilinearly if it is smaller); returns
/// the image `options.output` asks for.
pub fn add_composite<'a>(
    graph: &mut Graph<'a>,
    pipelines: &'a CompositePipelines,
    hdr: &ImageHandle,
    inputs: CompositeInputs<'_>,
    options: CompositeOptions<'_>,
) -> ImageHandle {
    let (width, height) = graph.output_size();
    let CompositeInputs { bloom, exposure } = inputs;
    let CompositeOptions {
        bloom: bloom_settings,
        post,
        output,
        mask_no_ray: mask,
    } = options;
    let linear = output == CompositeOutput::LinearHdr;
    let (name, format) = if linear {
        ("post hdr", HDR_POST_FORMAT)
    } else {
        ("ldr", LDR_FORMAT)
    };
    let upscale = (hdr.desc.width, hdr.desc.height) != (width, height);
    let variant = Variant {
        linear,
        upscale,
        tonemap: match post.tonemap {
            Tonemap::AcesHill => glsl::TONEMAP_ACES_HILL,
            Tonemap::AcesNarkowicz => glsl::TONEMAP_ACES_NARKOWICZ,
            Tonemap::Linear => glsl::TONEMAP_LINEAR,
            Tonemap::HuePreserving => glsl::TONEMAP_HUE_PRESERVING,
        },
        bloom: bloom.is_some(),
        auto_exposure: exposure.is_some(),
        saturate: post.saturation != 1.0,
        blocks: !upscale
            && width % 4 == 0
            && height % 4 == 0
            && bloom.is_some_and(|b| (4 * b.desc.width, 4 * b.desc.height) == (width, height)),
        mask,
    };
    // Invocations: one per pixel, or per 2x2 block.
    let (groups_w, groups_h) = if variant.blocks {
        (width / 2, height / 2)
    } else {
        (width, height)
    };
    let mut ldr = graph.create_image(name, ImageDesc::new_2d(format, width, height));
    // The up chain sums every level into level 0: divide by their count so
    // `strength` means the same for any number of levels.
    let bloom_strength = match bloom {
        Some(b) => (bloom_settings.strength / f64::from(b.desc.mip_levels)) as f32,
        None => 0.0,
    };
    let push = CompositePush {
        exposure: post.exposure_ev.exp2() as f32,
        width,
        height,
        bloom_strength,
        dither: if post.dither { 1.0 } else { 0.0 },
        saturation: post.saturation as f32,
    };
    let sampler = pipelines.sampler.sampler;
    // Without bloom the binding still needs an image (the HDR input; the
    // shader skips it); without automatic exposure the shader never reads
    // its buffer.
    let pass = ComputePass::new(graph, "composite", &BINDINGS)
        .sampled(hdr, sampler)
        .storage_image(&mut ldr, Access::ComputeStorageWrite, 0);
    let pass = match bloom {
        Some(b) => pass.sampled_mip(b, 0, sampler),
        None => pass.sampled(hdr, sampler),
    };
    let pass = match exposure {
        Some(e) => pass.buffer_read(e, Access::ComputeStorageRead),
        None => pass.absent_buffer(pipelines.placeholder.buffer),
    };
    pass.dispatch(
        move || pipelines.pipeline(variant),
        bytemuck::bytes_of(&push).to_vec(),
        (groups_w, groups_h),
    );
    ldr
}
