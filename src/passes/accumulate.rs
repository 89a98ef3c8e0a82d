//! Progressive refinement: the window re-renders an unchanged view with a new
//! sub-pixel jitter each frame and keeps the running mean of the samples, so
//! the still converges to an anti-aliased image (Monte Carlo pixel
//! integration with a box filter, as in any progressive path tracer). Any
//! change of the view restarts the mean at sample 0.

use bytemuck::{Pod, Zeroable};

use std::sync::Arc;

use super::compute::{self, Binding, ComputePass};
use crate::Result;
use crate::graph::{Graph, ImageHandle};
use crate::vk::{Access, ComputePipeline, Gpu};

/// Format of the running mean (f32: thousands of samples without drift).
pub const MEAN_FORMAT: ash::vk::Format = ash::vk::Format::R32G32B32A32_SFLOAT;

/// Push constants of `shaders/accumulate.comp`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct AccumulatePush {
    pub width: u32,
    pub height: u32,
    pub weight: f32,
}

/// `shaders/accumulate.comp`'s bindings: this frame's sample, the mean.
pub const BINDINGS: [Binding; 2] = [
    Binding::storage_image("sample_img"),
    Binding::storage_image("mean_img"),
];

/// The accumulation's pipeline, owned by this pass.
pub struct AccumulatePipeline(ComputePipeline);

impl AccumulatePipeline {
    pub fn new(gpu: &Arc<Gpu>) -> Result<Self> {
        Ok(AccumulatePipeline(ComputePipeline::new(
            gpu,
            "accumulate",
            crate::shaders::ACCUMULATE,
            &compute::kinds(&BINDINGS),
            std::mem::size_of::<AccumulatePush>() as u32,
        )?))
    }
}

/// Folds `sample` (the `index`-th sample of this view, 0-based) into `mean`,
/// an image kept across frames. Sample 0 overwrites the mean, so the mean is
/// only read (and must hold earlier samples) when `index > 0`.
pub fn add_accumulate<'a>(
    graph: &mut Graph<'a>,
    pipeline: &'a AccumulatePipeline,
    sample: &ImageHandle,
    mean: &mut ImageHandle,
    index: u32,
) {
    let (width, height) = (sample.desc.width, sample.desc.height);
    let access = if index == 0 {
        Access::ComputeStorageWrite
    } else {
        Access::ComputeStorageReadWrite
    };
    let push = AccumulatePush {
        width,
        height,
        weight: 1.0 / (index as f32 + 1.0),
    };
    ComputePass::new(graph, "accumulate", &BINDINGS)
        .storage_image_read(sample, 0)
        .storage_image(mean, access, 0)
        .dispatch(
            move || Ok(&pipeline.0),
            bytemuck::bytes_of(&push).to_vec(),
            (width, height),
        );
}
