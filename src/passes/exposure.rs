//! Automatic exposure: one pass meters the HDR image (a histogram of the lit
//! pixels' log luminance, the mean of a band of its percentiles) into a
//! one-float buffer that the composite multiplies by
//! (`shaders/exposure.comp`). Each
//! frame is metered on its own, so a sequence's frames do not depend on one
//! another (sharding and `--resume` give the same frames).

use bytemuck::{Pod, Zeroable};

use std::sync::Arc;

use super::compute::{self, Binding, ComputePass};
use crate::Result;
use crate::graph::{BufferHandle, Graph, ImageHandle};
use crate::scene::Post;
use crate::vk::{Access, ComputePipeline, Gpu, Sampler};

/// The luminance the metered band's mean is brought to: the band is
/// weighted toward the bright pixels, so this sits above mid grey (0.18).
pub const KEY: f32 = 0.45;

/// Push constants of `shaders/exposure.comp`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct ExposurePush {
    pub size: [u32; 2],
    pub low: f32,
    pub high: f32,
    pub key: f32,
}

/// `shaders/exposure.comp`'s bindings: the HDR image, the metered result.
pub const BINDINGS: [Binding; 2] = [Binding::sampled("hdr"), Binding::storage_buffer("Result")];

/// The metering's pipeline and sampler, owned by this pass.
pub struct ExposurePipeline {
    pipeline: ComputePipeline,
    sampler: Sampler,
}

impl ExposurePipeline {
    pub fn new(gpu: &Arc<Gpu>) -> Result<Self> {
        Ok(ExposurePipeline {
            pipeline: ComputePipeline::new(
                gpu,
                "exposure",
                crate::shaders::EXPOSURE,
                &compute::kinds(&BINDINGS),
                std::mem::size_of::<ExposurePush>() as u32,
            )?,
            sampler: Sampler::linear_clamp(gpu)?,
        })
    }
}

/// Adds the metering of `hdr` when `post` asks for automatic exposure;
/// returns the buffer holding the exposure (one f32).
pub fn add_exposure<'a>(
    graph: &mut Graph<'a>,
    pipeline: &'a ExposurePipeline,
    hdr: &ImageHandle,
    post: &Post,
) -> Option<BufferHandle> {
    if !post.auto_exposure {
        return None;
    }
    let mut exposure = graph.create_buffer("exposure", 16);
    let push = ExposurePush {
        size: [hdr.desc.width, hdr.desc.height],
        low: post.meter_low as f32,
        high: post.meter_high as f32,
        key: KEY,
    };
    // One workgroup (256 invocations) meters the whole image.
    ComputePass::new(graph, "exposure", &BINDINGS)
        .sampled(hdr, pipeline.sampler.sampler)
        .buffer_write(&mut exposure, Access::ComputeStorageWrite)
        .dispatch(
            move || Ok(&pipeline.pipeline),
            bytemuck::bytes_of(&push).to_vec(),
            (1, 1),
        );
    Some(exposure)
}
