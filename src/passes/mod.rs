//! Effects, one per file. Each is a function that adds passes to a graph and
//! returns the images it produced; none writes a barrier.

pub mod accumulate;
pub mod bloom;
pub mod composite;
pub mod copy;
pub mod exposure;
pub mod present;
pub mod raymarch;

use std::sync::Arc;

use crate::Result;
use crate::shaders::{RAYMARCH, RAYMARCH_AOV, RAYMARCH_NO_QUAD, RAYMARCH_SPLIT};
use crate::vk::{BindingKind, ComputePipeline, Gpu, Sampler};

/// The parameter block is a read-only storage buffer, not a uniform buffer:
/// on Mesa's lavapipe (22.3) every dispatch that read a uniform buffer
/// leaked about 0.55 MB inside the driver until the device was destroyed
/// (1,000 frames at 160x90 took 640 MB; the same with a storage buffer, 120
/// MB) and cost twice the time. Found by skipping one pass's dispatch at a
/// time; the layout is the same (every member a vec4). Bindings 6 and 7 are
/// the split thin-disk ray march's work list and indirect dispatch.
const RAYMARCH_BINDINGS: [BindingKind; 8] = [
    BindingKind::StorageImage,
    BindingKind::StorageBuffer,
    BindingKind::SampledImage,
    BindingKind::SampledImage,
    BindingKind::SampledImage,
    BindingKind::SampledImage,
    BindingKind::StorageBuffer,
    BindingKind::StorageBuffer,
];

/// Pipelines and samplers the passes use, created once per renderer.
pub struct Pipelines {
    /// Ray-march pipelines by variant, built the first time a scene needs one.
    raymarch: VariantCache<raymarch::Variant>,
    gpu: Arc<Gpu>,
    /// What the renderer does on this device.
    features: crate::render::Features,
    /// Composite pipelines by variant, built on first use.
    composite: VariantCache<composite::Variant>,
    pub bloom_prefilter: ComputePipeline,
    pub bloom_down: ComputePipeline,
    pub bloom_up: ComputePipeline,
    pub accumulate: ComputePipeline,
    pub exposure: ComputePipeline,
    pub linear_clamp: Sampler,
    /// Bound where a pass's optional buffer is absent (a shader's
    /// specialisation then never reads it).
    pub placeholder_buffer: crate::vk::Buffer,
    pub sky_sampler: Sampler,
    pub repeat_sampler: Sampler,
}

impl Pipelines {
    /// Builds every pipeline from the embedded SPIR-V.
    pub fn new(gpu: &Arc<Gpu>, features: crate::render::Features) -> Result<Self> {
        Ok(Pipelines {
            raymarch: VariantCache::new(),
            gpu: gpu.clone(),
            features,
            composite: VariantCache::new(),
            bloom_prefilter: ComputePipeline::new(
                gpu,
                "bloom prefilter",
                crate::shaders::BLOOM_PREFILTER,
                &[BindingKind::SampledImage, BindingKind::StorageImage],
                std::mem::size_of::<bloom::BloomPrefilterPush>() as u32,
            )?,
            bloom_down: ComputePipeline::new(
                gpu,
                "bloom down",
                crate::shaders::BLOOM_DOWN,
                &[BindingKind::SampledImage, BindingKind::StorageImage],
                std::mem::size_of::<bloom::BloomDownPush>() as u32,
            )?,
            bloom_up: ComputePipeline::new(
                gpu,
                "bloom up",
                crate::shaders::BLOOM_UP,
                &[BindingKind::SampledImage, BindingKind::StorageImage],
                std::mem::size_of::<bloom::BloomUpPush>() as u32,
            )?,
            accumulate: ComputePipeline::new(
                gpu,
                "accumulate",
                crate::shaders::ACCUMULATE,
                &[BindingKind::StorageImage, BindingKind::StorageImage],
                std::mem::size_of::<accumulate::AccumulatePush>() as u32,
            )?,
            exposure: ComputePipeline::new(
                gpu,
                "exposure",
                crate::shaders::EXPOSURE,
                &[BindingKind::SampledImage, BindingKind::StorageBuffer],
                std::mem::size_of::<exposure::ExposurePush>() as u32,
            )?,
            linear_clamp: Sampler::linear_clamp(gpu)?,
            placeholder_buffer: crate::vk::Buffer::new(
                gpu,
                "placeholder",
                16,
                ash::vk::BufferUsageFlags::STORAGE_BUFFER,
                gpu_allocator::MemoryLocation::GpuOnly,
            )?,
            sky_sampler: Sampler::linear_repeat_u(gpu)?,
            repeat_sampler: Sampler::linear_repeat(gpu)?,
        })
    }
}

/// Pipelines of one shader by specialisation, built on first use and kept.
struct VariantCache<K>(std::sync::Mutex<std::collections::HashMap<K, Arc<ComputePipeline>>>);

impl<K: std::hash::Hash + Eq + Copy> VariantCache<K> {
    fn new() -> Self {
        VariantCache(std::sync::Mutex::new(std::collections::HashMap::new()))
    }

    fn get(
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

impl Pipelines {
    /// The ray march specialised for a scene's variant (the specialization
    /// constants of raymarch.comp), built on first use and kept. Code a scene
    /// does not use is compiled out, not just skipped: on a CPU driver such as
    /// lavapipe every branch runs under a mask for every pixel, so a branch
    /// not taken costs as much as one taken.
    pub fn raymarch(&self, variant: raymarch::Variant) -> Result<Arc<ComputePipeline>> {
        self.raymarch.get(variant, || {
            let spirv = if variant.aov {
                RAYMARCH_AOV
            } else if variant.disk_stage != raymarch::glsl::DISK_STAGE_ALL {
                RAYMARCH_SPLIT
            } else if self.features.ray_differentials {
                RAYMARCH
            } else {
                RAYMARCH_NO_QUAD
            };
            ComputePipeline::with_constants(
                &self.gpu,
                &variant.name(),
                spirv,
                &RAYMARCH_BINDINGS,
                0,
                &variant.constants(),
            )
        })
    }

    /// What the renderer does on this device.
    pub fn features(&self) -> crate::render::Features {
        self.features
    }

    /// The ray-march pipelines one frame of `variant` runs on this device
    /// ([`raymarch::Variant::stages`]), split if `split` and the device can.
    pub fn raymarch_stages(
        &self,
        variant: raymarch::Variant,
        split: bool,
    ) -> Vec<raymarch::Variant> {
        variant.stages(split && self.features.disk_split)
    }

    /// The composite specialised for its output, tone map, bloom and
    /// upscaling (composite.comp's constants), built on first use and kept.
    pub fn composite(&self, variant: composite::Variant) -> Result<Arc<ComputePipeline>> {
        self.composite.get(variant, || {
            let spirv = if variant.linear {
                crate::shaders::COMPOSITE_HDR
            } else {
                crate::shaders::COMPOSITE
            };
            let bindings = [
                BindingKind::SampledImage,
                BindingKind::StorageImage,
                BindingKind::SampledImage,
                BindingKind::StorageBuffer,
            ];
            ComputePipeline::with_constants(
                &self.gpu,
                &format!("{variant:?}"),
                spirv,
                &bindings,
                std::mem::size_of::<composite::CompositePush>() as u32,
                &variant.constants(),
            )
        })
    }
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
