//! Descriptors, pushed straight into the command buffer (VK_KHR_push_descriptor):
//! no pools, no per-frame sets to recycle.

use ash::vk;

use super::Gpu;
use super::pipeline::{BindingKind, ComputePipeline};
use crate::{Error, Result};

/// One resource bound to one binding, in binding order.
#[derive(Clone, Copy, Debug)]
pub enum Descriptor {
    StorageImage(vk::ImageView),
    SampledImage(vk::ImageView, vk::Sampler),
    StorageBuffer(vk::Buffer),
}

impl Descriptor {
    fn kind(&self) -> BindingKind {
        match self {
            Descriptor::StorageImage(_) => BindingKind::StorageImage,
            Descriptor::SampledImage(..) => BindingKind::SampledImage,
            Descriptor::StorageBuffer(_) => BindingKind::StorageBuffer,
        }
    }
}

/// Binds `pipeline` and pushes `descriptors` as its set 0.
pub fn bind_compute(
    gpu: &Gpu,
    cmd: vk::CommandBuffer,
    pipeline: &ComputePipeline,
    descriptors: &[Descriptor],
) -> Result<()> {
    let kinds: Vec<BindingKind> = descriptors.iter().map(Descriptor::kind).collect();
    if kinds != pipeline.bindings {
        return Err(Error::Other(format!(
            "pipeline `{}` expects bindings {:?}, got {:?}",
            pipeline.name, pipeline.bindings, kinds
        )));
    }
    let image_infos: Vec<[vk::DescriptorImageInfo; 1]> = descriptors
        .iter()
        .map(|d| match *d {
            Descriptor::StorageImage(view) => [vk::DescriptorImageInfo {
                sampler: vk::Sampler::null(),
                image_view: view,
                image_layout: vk::ImageLayout::GENERAL,
            }],
            Descriptor::SampledImage(view, sampler) => [vk::DescriptorImageInfo {
                sampler,
                image_view: view,
                image_layout: vk::ImageLayout::SHADER_READ_ONLY_OPTIMAL,
            }],
            _ => [vk::DescriptorImageInfo::default()],
        })
        .collect();
    let buffer_infos: Vec<[vk::DescriptorBufferInfo; 1]> = descriptors
        .iter()
        .map(|d| match *d {
            Descriptor::StorageBuffer(b) => [vk::DescriptorBufferInfo {
                buffer: b,
                offset: 0,
                range: vk::WHOLE_SIZE,
            }],
            _ => [vk::DescriptorBufferInfo::default()],
        })
        .collect();
    let writes: Vec<vk::WriteDescriptorSet<'_>> = descriptors
        .iter()
        .enumerate()
        .map(|(i, d)| {
            let w = vk::WriteDescriptorSet::default()
                .dst_binding(i as u32)
                .descriptor_type(d.kind().descriptor_type());
            match d {
                Descriptor::StorageImage(_) | Descriptor::SampledImage(..) => {
                    w.image_info(&image_infos[i])
                }
                Descriptor::StorageBuffer(_) => w.buffer_info(&buffer_infos[i]),
            }
        })
        .collect();
    // SAFETY: cmd is recording; the views and buffers outlive the frame.
    unsafe {
        gpu.device
            .cmd_bind_pipeline(cmd, vk::PipelineBindPoint::COMPUTE, pipeline.pipeline);
        gpu.push_descriptor.cmd_push_descriptor_set(
            cmd,
            vk::PipelineBindPoint::COMPUTE,
            pipeline.layout,
            0,
            &writes,
        );
    }
    Ok(())
}

/// Pushes constants to a compute pipeline.
pub fn push_constants(gpu: &Gpu, cmd: vk::CommandBuffer, pipeline: &ComputePipeline, bytes: &[u8]) {
    debug_assert!(bytes.len() as u32 <= pipeline.push_constant_size);
    // SAFETY: cmd is recording with this pipeline's layout bound.
    unsafe {
        gpu.device.cmd_push_constants(
            cmd,
            pipeline.layout,
            vk::ShaderStageFlags::COMPUTE,
            0,
            bytes,
        )
    };
}
