//! Effects, one per file. Each is a function that adds passes to a graph and
//! returns the images it produced; none writes a barrier.

pub mod composite;
pub mod copy;
pub mod raymarch;

use std::sync::Arc;

use crate::Result;
use crate::vk::{BindingKind, ComputePipeline, Gpu, Sampler};

const RAYMARCH_BINDINGS: [BindingKind; 3] = [
    BindingKind::StorageImage,
    BindingKind::UniformBuffer,
    BindingKind::SampledImage,
];

/// Pipelines and samplers the passes use, created once per renderer.
pub struct Pipelines {
    pub raymarch: ComputePipeline,
    pub raymarch_aov: ComputePipeline,
    pub composite: ComputePipeline,
    pub linear_clamp: Sampler,
}

impl Pipelines {
    /// Builds every pipeline from the embedded SPIR-V.
    pub fn new(gpu: &Arc<Gpu>) -> Result<Self> {
        Ok(Pipelines {
            raymarch: ComputePipeline::new(
                gpu,
                "raymarch",
                crate::shaders::RAYMARCH,
                &RAYMARCH_BINDINGS,
                0,
            )?,
            raymarch_aov: ComputePipeline::new(
                gpu,
                "raymarch (geodesic AOV)",
                crate::shaders::RAYMARCH_AOV,
                &RAYMARCH_BINDINGS,
                0,
            )?,
            composite: ComputePipeline::new(
                gpu,
                "composite",
                crate::shaders::COMPOSITE,
                &[BindingKind::SampledImage, BindingKind::StorageImage],
                std::mem::size_of::<composite::CompositePush>() as u32,
            )?,
            linear_clamp: Sampler::linear_clamp(gpu)?,
        })
    }
}

/// Workgroups to cover `n` items with groups of `size`.
pub(crate) fn groups(n: u32, size: u32) -> u32 {
    n.div_ceil(size)
}
