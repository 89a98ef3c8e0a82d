//! Compute pipelines with a push-descriptor set layout.

use std::sync::Arc;

use ash::vk;

use super::Gpu;
use crate::error::VkContext;
use crate::{Error, Result};

/// The kind of each binding of a compute shader's set 0, in binding order.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum BindingKind {
    StorageImage,
    SampledImage,
    StorageBuffer,
}

impl BindingKind {
    pub(crate) fn descriptor_type(self) -> vk::DescriptorType {
        match self {
            BindingKind::StorageImage => vk::DescriptorType::STORAGE_IMAGE,
            BindingKind::SampledImage => vk::DescriptorType::COMBINED_IMAGE_SAMPLER,
            BindingKind::StorageBuffer => vk::DescriptorType::STORAGE_BUFFER,
        }
    }
}

/// A compute pipeline, its layout and its push-descriptor set layout.
pub struct ComputePipeline {
    gpu: Arc<Gpu>,
    pub pipeline: vk::Pipeline,
    pub layout: vk::PipelineLayout,
    pub set_layout: vk::DescriptorSetLayout,
    pub bindings: Vec<BindingKind>,
    pub push_constant_size: u32,
    pub name: String,
}

impl ComputePipeline {
    /// Builds a pipeline from embedded SPIR-V bytes.
    pub fn new(
        gpu: &Arc<Gpu>,
        name: &str,
        spirv: &[u8],
        bindings: &[BindingKind],
        push_constant_size: u32,
    ) -> Result<Self> {
        Self::with_constants(gpu, name, spirv, bindings, push_constant_size, &[])
    }

    /// Builds a pipeline, setting specialization constant `i` to `constants[i]`
    /// (32-bit values; a GLSL `bool` takes 0 or 1). The driver folds them, so a
    /// branch on one costs nothing at run time.
    pub fn with_constants(
        gpu: &Arc<Gpu>,
        name: &str,
        spirv: &[u8],
        bindings: &[BindingKind],
        push_constant_size: u32,
        constants: &[u32],
    ) -> Result<Self> {
        let d = &gpu.device;
        let words = ash::util::read_spv(&mut std::io::Cursor::new(spirv))
            .map_err(|e| Error::Other(format!("reading SPIR-V of `{name}`: {e}")))?;
        let set_bindings: Vec<vk::DescriptorSetLayoutBinding<'_>> = bindings
            .iter()
            .enumerate()
            .map(|(i, k)| {
                vk::DescriptorSetLayoutBinding::default()
                    .binding(i as u32)
                    .descriptor_type(k.descriptor_type())
                    .descriptor_count(1)
                    .stage_flags(vk::ShaderStageFlags::COMPUTE)
            })
            .collect();
        let set_info = vk::DescriptorSetLayoutCreateInfo::default()
            .flags(vk::DescriptorSetLayoutCreateFlags::PUSH_DESCRIPTOR_KHR)
            .bindings(&set_bindings);
        let mut this = ComputePipeline {
            gpu: gpu.clone(),
            pipeline: vk::Pipeline::null(),
            layout: vk::PipelineLayout::null(),
            set_layout: vk::DescriptorSetLayout::null(),
            bindings: bindings.to_vec(),
            push_constant_size,
            name: name.to_owned(),
        };
        // SAFETY: valid device; handles are owned by `this` as soon as created.
        unsafe {
            this.set_layout = d
                .create_descriptor_set_layout(&set_info, None)
                .ctx(|| format!("creating the descriptor set layout of `{name}`"))?;
            let ranges = [vk::PushConstantRange {
                stage_flags: vk::ShaderStageFlags::COMPUTE,
                offset: 0,
                size: push_constant_size,
            }];
            let set_layouts = [this.set_layout];
            let mut layout_info = vk::PipelineLayoutCreateInfo::default().set_layouts(&set_layouts);
            if push_constant_size > 0 {
                layout_info = layout_info.push_constant_ranges(&ranges);
            }
            this.layout = d
                .create_pipeline_layout(&layout_info, None)
                .ctx(|| format!("creating the pipeline layout of `{name}`"))?;
            let module = d
                .create_shader_module(&vk::ShaderModuleCreateInfo::default().code(&words), None)
                .ctx(|| format!("creating the shader module of `{name}`"))?;
            let entries: Vec<vk::SpecializationMapEntry> = (0..constants.len() as u32)
                .map(|i| vk::SpecializationMapEntry {
                    constant_id: i,
                    offset: 4 * i,
                    size: 4,
                })
                .collect();
            let data: &[u8] = bytemuck::cast_slice(constants);
            let spec = vk::SpecializationInfo::default()
                .map_entries(&entries)
                .data(data);
            let mut stage = vk::PipelineShaderStageCreateInfo::default()
                .stage(vk::ShaderStageFlags::COMPUTE)
                .module(module)
                .name(c"main");
            if !constants.is_empty() {
                stage = stage.specialization_info(&spec);
            }
            let info = [vk::ComputePipelineCreateInfo::default()
                .stage(stage)
                .layout(this.layout)];
            let result = d.create_compute_pipelines(vk::PipelineCache::null(), &info, None);
            d.destroy_shader_module(module, None);
            this.pipeline = result
                .map_err(|(_, r)| r)
                .ctx(|| format!("creating compute pipeline `{name}`"))?
                .into_iter()
                .next()
                .unwrap_or_default();
        }
        gpu.set_name(this.pipeline, name);
        Ok(this)
    }
}

impl Drop for ComputePipeline {
    fn drop(&mut self) {
        // SAFETY: pipelines are dropped after the last frame using them finished.
        unsafe {
            let d = &self.gpu.device;
            if self.pipeline != vk::Pipeline::null() {
                d.destroy_pipeline(self.pipeline, None);
            }
            if self.layout != vk::PipelineLayout::null() {
                d.destroy_pipeline_layout(self.layout, None);
            }
            if self.set_layout != vk::DescriptorSetLayout::null() {
                d.destroy_descriptor_set_layout(self.set_layout, None);
            }
        }
    }
}
