//! Images, their views and samplers.

use std::sync::Arc;

use ash::vk;
use gpu_allocator::MemoryLocation;
use gpu_allocator::vulkan::Allocation;

use super::{Gpu, memory};
use crate::Result;
use crate::error::VkContext;

/// Format, size and mip count of a colour image: 2-D, or a 3-D volume
/// (sampled, one level).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ImageDesc {
    pub format: vk::Format,
    pub width: u32,
    pub height: u32,
    /// 1 for a 2-D image.
    pub depth: u32,
    /// A 3-D image (even one texel deep).
    pub volume: bool,
    pub mip_levels: u32,
}

impl ImageDesc {
    /// A single-level 2-D image.
    pub fn new_2d(format: vk::Format, width: u32, height: u32) -> Self {
        ImageDesc {
            format,
            width,
            height,
            depth: 1,
            volume: false,
            mip_levels: 1,
        }
    }

    /// A single-level 3-D image.
    pub fn new_3d(format: vk::Format, width: u32, height: u32, depth: u32) -> Self {
        ImageDesc {
            format,
            width,
            height,
            depth: depth.max(1),
            volume: true,
            mip_levels: 1,
        }
    }

    /// The same image with `levels` mip levels (clamped to what the size allows).
    pub fn with_mips(mut self, levels: u32) -> Self {
        let max = 32 - self.width.max(self.height).max(1).leading_zeros();
        self.mip_levels = levels.clamp(1, max);
        self
    }

    /// Width and height of mip `level`.
    pub fn mip_extent(&self, level: u32) -> (u32, u32) {
        ((self.width >> level).max(1), (self.height >> level).max(1))
    }
}

/// The Vulkan objects behind an imported image (a readback target, a
/// swapchain image). The importer owns them and keeps them alive until the
/// frame's fence has signalled.
#[derive(Clone, Debug)]
pub struct ImageBinding {
    pub image: vk::Image,
    /// One view per mip level, indexed by level.
    pub mip_views: Vec<vk::ImageView>,
    /// A view of all levels (for sampling with mips).
    pub full_view: vk::ImageView,
}

/// A 2-D colour image with one view per mip level and one of all levels.
pub struct Image {
    gpu: Arc<Gpu>,
    pub image: vk::Image,
    pub desc: ImageDesc,
    pub usage: vk::ImageUsageFlags,
    pub mip_views: Vec<vk::ImageView>,
    pub full_view: vk::ImageView,
    allocation: Option<Allocation>,
    pub name: String,
}

impl Image {
    /// Creates a device-local image.
    pub fn new(
        gpu: &Arc<Gpu>,
        name: &str,
        desc: ImageDesc,
        usage: vk::ImageUsageFlags,
    ) -> Result<Self> {
        let d = &gpu.device;
        let info = vk::ImageCreateInfo::default()
            .image_type(if desc.volume {
                vk::ImageType::TYPE_3D
            } else {
                vk::ImageType::TYPE_2D
            })
            .format(desc.format)
            .extent(vk::Extent3D {
                width: desc.width,
                height: desc.height,
                depth: desc.depth,
            })
            .mip_levels(desc.mip_levels)
            .array_layers(1)
            .samples(vk::SampleCountFlags::TYPE_1)
            .tiling(vk::ImageTiling::OPTIMAL)
            .usage(usage)
            .sharing_mode(vk::SharingMode::EXCLUSIVE)
            .initial_layout(vk::ImageLayout::UNDEFINED);
        // SAFETY: valid device and create info.
        let image = unsafe { d.create_image(&info, None) }
            .ctx(|| format!("creating image `{name}` ({}x{})", desc.width, desc.height))?;
        // From here on `this` owns every handle, so an early return cleans up.
        let mut this = Image {
            gpu: gpu.clone(),
            image,
            desc,
            usage,
            mip_views: Vec::new(),
            full_view: vk::ImageView::null(),
            allocation: None,
            name: name.to_owned(),
        };
        gpu.set_name(image, name);
        // SAFETY: image belongs to this device.
        let reqs = unsafe { d.get_image_memory_requirements(image) };
        let allocation = memory::allocate(gpu, name, reqs, MemoryLocation::GpuOnly, false)?;
        // SAFETY: fresh allocation satisfying the image's requirements.
        unsafe { d.bind_image_memory(image, allocation.memory(), allocation.offset()) }
            .ctx(|| format!("binding memory of image `{name}`"))?;
        this.allocation = Some(allocation);
        this.full_view = this.make_view(0, desc.mip_levels)?;
        for level in 0..desc.mip_levels {
            let v = this.make_view(level, 1)?;
            this.mip_views.push(v);
        }
        Ok(this)
    }

    fn make_view(&self, base: u32, count: u32) -> Result<vk::ImageView> {
        let info = vk::ImageViewCreateInfo::default()
            .image(self.image)
            .view_type(if self.desc.volume {
                vk::ImageViewType::TYPE_3D
            } else {
                vk::ImageViewType::TYPE_2D
            })
            .format(self.desc.format)
            .subresource_range(vk::ImageSubresourceRange {
                aspect_mask: vk::ImageAspectFlags::COLOR,
                base_mip_level: base,
                level_count: count,
                base_array_layer: 0,
                layer_count: 1,
            });
        // SAFETY: the image is alive and bound.
        unsafe { self.gpu.device.create_image_view(&info, None) }
            .ctx(|| format!("creating image `{}` mip {base} view", self.name))
    }

    /// The handles the frame graph needs to import this image.
    pub fn binding(&self) -> ImageBinding {
        ImageBinding {
            image: self.image,
            mip_views: self.mip_views.clone(),
            full_view: self.full_view,
        }
    }
}

impl Drop for Image {
    fn drop(&mut self) {
        // SAFETY: owners drop images only after the fences of frames using them.
        unsafe {
            for v in self.mip_views.drain(..) {
                self.gpu.device.destroy_image_view(v, None);
            }
            if self.full_view != vk::ImageView::null() {
                self.gpu.device.destroy_image_view(self.full_view, None);
            }
            self.gpu.device.destroy_image(self.image, None);
        }
        if let Some(a) = self.allocation.take() {
            memory::free(&self.gpu, a);
        }
    }
}

/// A sampler, destroyed with its owner.
pub struct Sampler {
    gpu: Arc<Gpu>,
    pub sampler: vk::Sampler,
}

impl Sampler {
    /// Linear filtering with mips, clamped at every edge.
    pub fn linear_clamp(gpu: &Arc<Gpu>) -> Result<Self> {
        Self::linear(
            gpu,
            "the linear sampler",
            vk::SamplerAddressMode::CLAMP_TO_EDGE,
        )
    }

    /// Linear filtering with mips, repeating in u (longitude), clamped in v.
    pub fn linear_repeat_u(gpu: &Arc<Gpu>) -> Result<Self> {
        Self::linear(gpu, "the sky sampler", vk::SamplerAddressMode::REPEAT)
    }

    /// Linear, repeating in every direction (tileable textures and volumes).
    pub fn linear_repeat(gpu: &Arc<Gpu>) -> Result<Self> {
        Self::linear_modes(
            gpu,
            "the repeating sampler",
            vk::SamplerAddressMode::REPEAT,
            vk::SamplerAddressMode::REPEAT,
            vk::SamplerAddressMode::REPEAT,
        )
    }

    fn linear(gpu: &Arc<Gpu>, what: &str, address_u: vk::SamplerAddressMode) -> Result<Self> {
        let clamp = vk::SamplerAddressMode::CLAMP_TO_EDGE;
        Self::linear_modes(gpu, what, address_u, clamp, clamp)
    }

    fn linear_modes(
        gpu: &Arc<Gpu>,
        what: &str,
        address_u: vk::SamplerAddressMode,
        address_v: vk::SamplerAddressMode,
        address_w: vk::SamplerAddressMode,
    ) -> Result<Self> {
        let info = vk::SamplerCreateInfo::default()
            .mag_filter(vk::Filter::LINEAR)
            .min_filter(vk::Filter::LINEAR)
            .mipmap_mode(vk::SamplerMipmapMode::LINEAR)
            .address_mode_u(address_u)
            .address_mode_v(address_v)
            .address_mode_w(address_w)
            .max_lod(vk::LOD_CLAMP_NONE);
        // SAFETY: valid device.
        let sampler =
            unsafe { gpu.device.create_sampler(&info, None) }.ctx(|| format!("creating {what}"))?;
        Ok(Sampler {
            gpu: gpu.clone(),
            sampler,
        })
    }
}

impl Drop for Sampler {
    fn drop(&mut self) {
        // SAFETY: owners outlive every frame that uses the sampler.
        unsafe { self.gpu.device.destroy_sampler(self.sampler, None) };
    }
}
