//! Effects, one per file. Each owns its pipelines (built from the embedded
//! SPIR-V, with its own samplers) and has a function that adds its passes to
//! a graph and returns the images it produced; none writes a barrier. This
//! module holds only what they share: the dispatch helpers and the cache of
//! specialised pipelines.

pub mod accumulate;
pub mod bloom;
pub mod composite;
pub mod compute;
pub mod copy;
pub mod exposure;
pub mod polarimetry;
pub mod present;
pub mod raymarch;

use std::sync::Arc;

use crate::Result;
use crate::vk::{ComputePipeline, Gpu};

/// Pipelines of one shader by specialisation, built on first use and kept.
pub(crate) struct VariantCache<K>(
    std::sync::Mutex<std::collections::HashMap<K, Arc<ComputePipeline>>>,
);

impl<K: std::hash::Hash + Eq + Copy> VariantCache<K> {
    pub(crate) fn new() -> Self {
        VariantCache(std::sync::Mutex::new(std::collections::HashMap::new()))
    }

    pub(crate) fn get(
        &self,
        key: K,
        build: impl FnOnce() -> Result<ComputePipeline>,
    ) -> Result<Arc<ComputePipeline>> {
        let mut cache = self
            .0
            .lock()
            .map_err(|_| crate::Error::Other("the pipeline cache lock was poisoned".into()))?;
        if let Some(p) = cache.get(&key) {
            return Ok(p.clone());
        }
        let p = Arc::new(build()?);
        cache.insert(key, p.clone());
        Ok(p)
    }
}

/// A 16-byte storage buffer bound where a pass's optional buffer is absent
/// (a shader's specialisation then never reads it).
pub(crate) fn placeholder_buffer(gpu: &Arc<Gpu>) -> Result<crate::vk::Buffer> {
    crate::vk::Buffer::new(
        gpu,
        "placeholder",
        16,
        ash::vk::BufferUsageFlags::STORAGE_BUFFER,
        gpu_allocator::MemoryLocation::GpuOnly,
    )
}

/// Binds `pipeline` with `descriptors`, pushes `push` (if any) and dispatches
/// 8x8 workgroups over `width` x `height`: what every compute pass records.
pub(crate) fn dispatch_2d(
    ctx: &crate::graph::PassContext<'_>,
    pipeline: &ComputePipeline,
    descriptors: &[crate::vk::Descriptor],
    push: &[u8],
    width: u32,
    height: u32,
) -> Result<()> {
    crate::vk::bind_compute(ctx.gpu, ctx.cmd, pipeline, descriptors)?;
    if !push.is_empty() {
        crate::vk::push_constants(ctx.gpu, ctx.cmd, pipeline, push);
    }
    // SAFETY: the pipeline and its descriptors are bound on a recording buffer.
    unsafe {
        ctx.gpu
            .device
            .cmd_dispatch(ctx.cmd, groups(width, 8), groups(height, 8), 1)
    };
    Ok(())
}

/// Binds `pipeline` with `descriptors` and dispatches the workgroup counts
/// the first three u32 of `args` hold (written on the device).
pub(crate) fn dispatch_indirect(
    ctx: &crate::graph::PassContext<'_>,
    pipeline: &ComputePipeline,
    descriptors: &[crate::vk::Descriptor],
    args: ash::vk::Buffer,
) -> Result<()> {
    crate::vk::bind_compute(ctx.gpu, ctx.cmd, pipeline, descriptors)?;
    // SAFETY: the pipeline and its descriptors are bound on a recording
    // buffer; `args` holds a VkDispatchIndirectCommand at offset 0.
    unsafe { ctx.gpu.device.cmd_dispatch_indirect(ctx.cmd, args, 0) };
    Ok(())
}

/// Workgroups to cover `n` items with groups of `size`.
pub(crate) fn groups(n: u32, size: u32) -> u32 {
    n.div_ceil(size)
}
