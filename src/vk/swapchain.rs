//! The window's surface and swapchain: creation, recreation on resize or when
//! the driver says out-of-date or suboptimal, acquire and present, and one
//! "rendered" semaphore per swapchain image (a semaphore handed to present is
//! reused only once that image is acquired again).

use std::sync::Arc;

use ash::{khr, vk};

use super::{Gpu, ImageBinding, ImageDesc};
use crate::error::VkContext;
use crate::{Error, Result};

/// How frames are handed to the display.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum PresentMode {
    /// Vsync, never tears (always available).
    Fifo,
    /// Vsync without blocking the renderer (newest frame wins).
    Mailbox,
    /// No vsync (may tear).
    Immediate,
}

impl PresentMode {
    fn vk(self) -> vk::PresentModeKHR {
        match self {
            PresentMode::Fifo => vk::PresentModeKHR::FIFO,
            PresentMode::Mailbox => vk::PresentModeKHR::MAILBOX,
            PresentMode::Immediate => vk::PresentModeKHR::IMMEDIATE,
        }
    }
}

/// The surface (owned) and its current swapchain.
pub struct Swapchain {
    gpu: Arc<Gpu>,
    surface_fn: khr::surface::Instance,
    swapchain_fn: khr::swapchain::Device,
    pub surface: vk::SurfaceKHR,
    swapchain: vk::SwapchainKHR,
    images: Vec<vk::Image>,
    views: Vec<vk::ImageView>,
    /// Signalled when the frame drawn on image i is done (present waits on it).
    rendered: Vec<vk::Semaphore>,
    /// Acquire semaphores, one per frame slot, used round-robin.
    acquired: Vec<vk::Semaphore>,
    next_acquire: usize,
    pub format: vk::Format,
    pub extent: vk::Extent2D,
    pub mode: vk::PresentModeKHR,
    wanted: PresentMode,
}

/// An acquired image, ready to draw on.
pub struct Acquired {
    pub index: u32,
    pub desc: ImageDesc,
    pub binding: ImageBinding,
    pub acquired: vk::Semaphore,
    pub rendered: vk::Semaphore,
}

impl Swapchain {
    /// Takes ownership of `surface` and builds a swapchain of `size`.
    pub fn new(
        gpu: &Arc<Gpu>,
        surface: vk::SurfaceKHR,
        size: (u32, u32),
        wanted: PresentMode,
        frames_in_flight: usize,
    ) -> Result<Self> {
        let inst = &gpu.instance;
        let mut this = Swapchain {
            gpu: gpu.clone(),
            surface_fn: khr::surface::Instance::new(&inst.entry, &inst.instance),
            swapchain_fn: khr::swapchain::Device::new(&inst.instance, &gpu.device),
            surface,
            swapchain: vk::SwapchainKHR::null(),
            images: Vec::new(),
            views: Vec::new(),
            rendered: Vec::new(),
            acquired: Vec::new(),
            next_acquire: 0,
            format: vk::Format::UNDEFINED,
            extent: vk::Extent2D::default(),
            mode: vk::PresentModeKHR::FIFO,
            wanted,
        };
        for _ in 0..frames_in_flight {
            let s = this.semaphore()?;
            this.acquired.push(s);
        }
        this.recreate(size)?;
        Ok(this)
    }

    fn semaphore(&self) -> Result<vk::Semaphore> {
        // SAFETY: valid device.
        unsafe {
            self.gpu
                .device
                .create_semaphore(&vk::SemaphoreCreateInfo::default(), None)
        }
        .ctx(|| "creating a swapchain semaphore".into())
    }

    /// Rebuilds the swapchain for `size` (the window's inner size). The
    /// caller must have waited for every frame in flight.
    pub fn recreate(&mut self, size: (u32, u32)) -> Result<()> {
        // Fences cover the frames' submissions but not the presentation
        // engine's waits on the "rendered" semaphores destroyed below: only
        // an idle queue guarantees those are done.
        // SAFETY: valid device.
        unsafe { self.gpu.device.device_wait_idle() }
            .ctx(|| "waiting for the GPU before recreating the swapchain".into())?;
        let pd = self.gpu.physical;
        // SAFETY: the surface and physical device are alive.
        let caps = unsafe {
            self.surface_fn
                .get_physical_device_surface_capabilities(pd, self.surface)
        }
        .ctx(|| "reading the surface's capabilities".into())?;
        // SAFETY: as above.
        let formats = unsafe {
            self.surface_fn
                .get_physical_device_surface_formats(pd, self.surface)
        }
        .ctx(|| "listing the surface's formats".into())?;
        // SAFETY: as above.
        let modes = unsafe {
            self.surface_fn
                .get_physical_device_surface_present_modes(pd, self.surface)
        }
        .ctx(|| "listing the surface's present modes".into())?;
        let format = unorm_format(&formats)?;
        let mode = if modes.contains(&self.wanted.vk()) {
            self.wanted.vk()
        } else {
            log::warn!(
                "present mode {:?} is not available; using fifo",
                self.wanted
            );
            vk::PresentModeKHR::FIFO
        };
        let extent = extent_for(&caps, size);
        let mut count = caps.min_image_count + 1;
        if caps.max_image_count > 0 {
            count = count.min(caps.max_image_count);
        }
        let old = self.swapchain;
        let info = vk::SwapchainCreateInfoKHR::default()
            .surface(self.surface)
            .min_image_count(count)
            .image_format(format.format)
            .image_color_space(format.color_space)
            .image_extent(extent)
            .image_array_layers(1)
            .image_usage(
                vk::ImageUsageFlags::TRANSFER_DST
                    | vk::ImageUsageFlags::TRANSFER_SRC
                    | vk::ImageUsageFlags::COLOR_ATTACHMENT,
            )
            .image_sharing_mode(vk::SharingMode::EXCLUSIVE)
            .pre_transform(caps.current_transform)
            .composite_alpha(vk::CompositeAlphaFlagsKHR::OPAQUE)
            .present_mode(mode)
            .clipped(true)
            .old_swapchain(old);
        // SAFETY: valid device and surface; the old swapchain is retired here.
        let swapchain = unsafe { self.swapchain_fn.create_swapchain(&info, None) }.ctx(|| {
            format!(
                "creating the swapchain ({}x{})",
                extent.width, extent.height
            )
        })?;
        self.destroy_images();
        if old != vk::SwapchainKHR::null() {
            // SAFETY: every frame that used it has finished (caller waited).
            unsafe { self.swapchain_fn.destroy_swapchain(old, None) };
        }
        self.swapchain = swapchain;
        // SAFETY: the swapchain was just created.
        self.images = unsafe { self.swapchain_fn.get_swapchain_images(swapchain) }
            .ctx(|| "listing the swapchain's images".into())?;
        for (i, &image) in self.images.iter().enumerate() {
            let view_info = vk::ImageViewCreateInfo::default()
                .image(image)
                .view_type(vk::ImageViewType::TYPE_2D)
                .format(format.format)
                .subresource_range(vk::ImageSubresourceRange {
                    aspect_mask: vk::ImageAspectFlags::COLOR,
                    base_mip_level: 0,
                    level_count: 1,
                    base_array_layer: 0,
                    layer_count: 1,
                });
            // SAFETY: the image belongs to the swapchain.
            let view = unsafe { self.gpu.device.create_image_view(&view_info, None) }
                .ctx(|| format!("creating the view of swapchain image {i}"))?;
            self.views.push(view);
            let s = self.semaphore()?;
            self.rendered.push(s);
        }
        self.format = format.format;
        self.extent = extent;
        self.mode = mode;
        Ok(())
    }

    fn destroy_images(&mut self) {
        // SAFETY: the caller waited for every frame that used them.
        unsafe {
            for v in self.views.drain(..) {
                self.gpu.device.destroy_image_view(v, None);
            }
            for s in self.rendered.drain(..) {
                self.gpu.device.destroy_semaphore(s, None);
            }
        }
        self.images.clear();
    }

    /// Acquires the next image; `Ok(None)` when the swapchain is out of date
    /// (recreate it and try again).
    pub fn acquire(&mut self) -> Result<Option<Acquired>> {
        let semaphore = self.acquired[self.next_acquire];
        // SAFETY: the semaphore is unsignalled: its last acquire was waited on
        // by a frame whose slot (same index) has finished.
        let result = unsafe {
            self.swapchain_fn.acquire_next_image(
                self.swapchain,
                u64::MAX,
                semaphore,
                vk::Fence::null(),
            )
        };
        let index = match result {
            Ok((index, _suboptimal)) => index,
            Err(vk::Result::ERROR_OUT_OF_DATE_KHR) => return Ok(None),
            Err(result) => {
                return Err(Error::Vulkan {
                    what: "acquiring a swapchain image".into(),
                    result,
                });
            }
        };
        self.next_acquire = (self.next_acquire + 1) % self.acquired.len();
        let i = index as usize;
        Ok(Some(Acquired {
            index,
            desc: ImageDesc::new_2d(self.format, self.extent.width, self.extent.height),
            binding: ImageBinding {
                image: self.images[i],
                mip_views: vec![self.views[i]],
                full_view: self.views[i],
            },
            acquired: semaphore,
            rendered: self.rendered[i],
        }))
    }

    /// Presents image `index` once `rendered` is signalled; `Ok(false)` when
    /// the swapchain is out of date or suboptimal (recreate it).
    pub fn present(&self, index: u32, rendered: vk::Semaphore) -> Result<bool> {
        let waits = [rendered];
        let swapchains = [self.swapchain];
        let indices = [index];
        let info = vk::PresentInfoKHR::default()
            .wait_semaphores(&waits)
            .swapchains(&swapchains)
            .image_indices(&indices);
        // SAFETY: the image was acquired and its frame submitted.
        match unsafe { self.swapchain_fn.queue_present(self.gpu.queue, &info) } {
            Ok(false) => Ok(true),
            Ok(true) | Err(vk::Result::ERROR_OUT_OF_DATE_KHR) => Ok(false),
            Err(result) => Err(Error::Vulkan {
                what: "presenting a frame".into(),
                result,
            }),
        }
    }
}

impl Drop for Swapchain {
    fn drop(&mut self) {
        // SAFETY: wait for the queue (present included), then destroy in
        // reverse creation order; the surface last.
        unsafe {
            let _ = self.gpu.device.device_wait_idle();
            self.destroy_images();
            for s in self.acquired.drain(..) {
                self.gpu.device.destroy_semaphore(s, None);
            }
            if self.swapchain != vk::SwapchainKHR::null() {
                self.swapchain_fn.destroy_swapchain(self.swapchain, None);
            }
            self.surface_fn.destroy_surface(self.surface, None);
        }
    }
}

/// The composite writes sRGB-encoded values: a UNORM swapchain shows them as
/// they are.
fn unorm_format(formats: &[vk::SurfaceFormatKHR]) -> Result<vk::SurfaceFormatKHR> {
    [vk::Format::B8G8R8A8_UNORM, vk::Format::R8G8B8A8_UNORM]
        .into_iter()
        .find_map(|f| formats.iter().find(|s| s.format == f).copied())
        .ok_or_else(|| {
            Error::Other(format!(
                "the window's surface offers no 8-bit UNORM format (it offers {:?})",
                formats.iter().map(|f| f.format).collect::<Vec<_>>()
            ))
        })
}

/// The surface's own size, or the window's clamped to what it allows.
fn extent_for(caps: &vk::SurfaceCapabilitiesKHR, size: (u32, u32)) -> vk::Extent2D {
    if caps.current_extent.width != u32::MAX {
        return caps.current_extent;
    }
    vk::Extent2D {
        width: size.0.clamp(
            caps.min_image_extent.width,
            caps.max_image_extent.width.max(1),
        ),
        height: size.1.clamp(
            caps.min_image_extent.height,
            caps.max_image_extent.height.max(1),
        ),
    }
}
