//! Buffers: parameters written by the host, work lists, readback targets.

use std::sync::Arc;

use ash::vk;
use gpu_allocator::MemoryLocation;
use gpu_allocator::vulkan::Allocation;

use super::{Gpu, memory};
use crate::error::VkContext;
use crate::{Error, Result};

/// The Vulkan object behind an imported buffer.
#[derive(Clone, Copy, Debug)]
pub struct BufferBinding {
    pub buffer: vk::Buffer,
    pub size: u64,
}

/// A buffer with its own named allocation.
pub struct Buffer {
    gpu: Arc<Gpu>,
    pub buffer: vk::Buffer,
    pub size: u64,
    allocation: Option<Allocation>,
    pub name: String,
}

impl Buffer {
    /// Creates a buffer in `location` (host-visible ones stay mapped).
    pub fn new(
        gpu: &Arc<Gpu>,
        name: &str,
        size: u64,
        usage: vk::BufferUsageFlags,
        location: MemoryLocation,
    ) -> Result<Self> {
        let info = vk::BufferCreateInfo::default()
            .size(size.max(4))
            .usage(usage)
            .sharing_mode(vk::SharingMode::EXCLUSIVE);
        // SAFETY: valid device and create info.
        let buffer = unsafe { gpu.device.create_buffer(&info, None) }
            .ctx(|| format!("creating buffer `{name}` ({size} bytes)"))?;
        let mut this = Buffer {
            gpu: gpu.clone(),
            buffer,
            size,
            allocation: None,
            name: name.to_owned(),
        };
        gpu.set_name(buffer, name);
        // SAFETY: the buffer belongs to this device.
        let reqs = unsafe { gpu.device.get_buffer_memory_requirements(buffer) };
        let allocation = memory::allocate(gpu, name, reqs, location, true)?;
        // SAFETY: fresh allocation satisfying the buffer's requirements.
        unsafe {
            gpu.device
                .bind_buffer_memory(buffer, allocation.memory(), allocation.offset())
        }
        .ctx(|| format!("binding memory of buffer `{name}`"))?;
        this.allocation = Some(allocation);
        Ok(this)
    }

    /// The mapped bytes of a host-visible buffer.
    pub fn mapped(&self) -> Result<&[u8]> {
        self.allocation
            .as_ref()
            .and_then(|a| a.mapped_slice())
            .map(|s| &s[..self.size as usize])
            .ok_or_else(|| Error::Other(format!("buffer `{}` is not host-visible", self.name)))
    }

    /// The mapped bytes of a host-visible buffer, for writing.
    pub fn mapped_mut(&mut self) -> Result<&mut [u8]> {
        let size = self.size as usize;
        let name = &self.name;
        self.allocation
            .as_mut()
            .and_then(|a| a.mapped_slice_mut())
            .map(|s| &mut s[..size])
            .ok_or_else(|| Error::Other(format!("buffer `{name}` is not host-visible")))
    }

    /// The handle the frame graph imports.
    pub fn binding(&self) -> BufferBinding {
        BufferBinding {
            buffer: self.buffer,
            size: self.size,
        }
    }
}

impl Drop for Buffer {
    fn drop(&mut self) {
        // SAFETY: owners drop buffers only after the fences of frames using them.
        unsafe { self.gpu.device.destroy_buffer(self.buffer, None) };
        if let Some(a) = self.allocation.take() {
            memory::free(&self.gpu, a);
        }
    }
}
