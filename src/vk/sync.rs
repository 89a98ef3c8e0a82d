//! The closed set of ways a pass can touch a resource, and the one table that
//! maps each to a pipeline stage, an access mask and an image layout.
//!
//! No other file spells synchronization flags: the frame graph asks this table
//! (after Tobias Hector's simple_vulkan_synchronization and vk-sync).

use ash::vk;

/// How a pass touches an image or a buffer. Closed on purpose: a new use is a
/// new variant here, with its row in [`Access::info`].
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum Access {
    /// No access: the state of a fresh resource whose contents do not matter.
    Nothing,
    /// Sampled (texture) read in a compute shader.
    ComputeSampledRead,
    /// Storage image / storage buffer read in a compute shader.
    ComputeStorageRead,
    /// Storage image / storage buffer write in a compute shader.
    ComputeStorageWrite,
    /// Storage read and write of the same subresource in one dispatch.
    ComputeStorageReadWrite,
    /// Dispatch arguments read by `vkCmdDispatchIndirect` (buffers only).
    IndirectRead,
    /// Source of a copy or blit.
    TransferRead,
    /// Destination of a copy, blit or clear.
    TransferWrite,
    /// Read by the host after a fence (readback).
    HostRead,
    /// Written by the host before submission (uploads).
    HostWrite,
    /// Colour attachment written by a graphics pass (the GUI overlay).
    ColorAttachmentWrite,
    /// Sampled read in a fragment shader.
    FragmentSampledRead,
    /// Handed to the presentation engine.
    Present,
    /// A swapchain image just acquired: contents undefined, and the acquire
    /// semaphore is waited at exactly these stages, so the first barrier
    /// chains to it (Khronos synchronization examples, "Swapchain Image
    /// Acquire and Present").
    Acquired,
}

/// What [`Access::info`] returns: everything a barrier needs about one side.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct AccessInfo {
    pub stage: vk::PipelineStageFlags2,
    pub access: vk::AccessFlags2,
    /// The layout an image must be in for this access (buffers ignore it).
    pub layout: vk::ImageLayout,
    /// Whether the access writes memory (and so must be made visible).
    pub writes: bool,
}

impl Access {
    /// Every access kind, for exhaustive tests.
    pub const ALL: [Access; 14] = [
        Access::Nothing,
        Access::ComputeSampledRead,
        Access::ComputeStorageRead,
        Access::ComputeStorageWrite,
        Access::ComputeStorageReadWrite,
        Access::IndirectRead,
        Access::TransferRead,
        Access::TransferWrite,
        Access::HostRead,
        Access::HostWrite,
        Access::ColorAttachmentWrite,
        Access::FragmentSampledRead,
        Access::Present,
        Access::Acquired,
    ];

    /// The table: stage, access mask, layout, and whether it writes.
    pub fn info(self) -> AccessInfo {
        use vk::AccessFlags2 as A;
        use vk::ImageLayout as L;
        use vk::PipelineStageFlags2 as S;
        let (stage, access, layout, writes) = match self {
            Access::Nothing => (S::NONE, A::NONE, L::UNDEFINED, false),
            Access::ComputeSampledRead => (
                S::COMPUTE_SHADER,
                A::SHADER_SAMPLED_READ,
                L::SHADER_READ_ONLY_OPTIMAL,
                false,
            ),
            Access::ComputeStorageRead => {
                (S::COMPUTE_SHADER, A::SHADER_STORAGE_READ, L::GENERAL, false)
            }
            Access::ComputeStorageWrite => {
                (S::COMPUTE_SHADER, A::SHADER_STORAGE_WRITE, L::GENERAL, true)
            }
            Access::ComputeStorageReadWrite => (
                S::COMPUTE_SHADER,
                A::SHADER_STORAGE_READ | A::SHADER_STORAGE_WRITE,
                L::GENERAL,
                true,
            ),
            Access::IndirectRead => (
                S::DRAW_INDIRECT,
                A::INDIRECT_COMMAND_READ,
                L::UNDEFINED,
                false,
            ),
            // Every transfer command (copy, blit, clear): the present pass blits.
            Access::TransferRead => (
                S::ALL_TRANSFER,
                A::TRANSFER_READ,
                L::TRANSFER_SRC_OPTIMAL,
                false,
            ),
            Access::TransferWrite => (
                S::ALL_TRANSFER,
                A::TRANSFER_WRITE,
                L::TRANSFER_DST_OPTIMAL,
                true,
            ),
            Access::HostRead => (S::HOST, A::HOST_READ, L::GENERAL, false),
            Access::HostWrite => (S::HOST, A::HOST_WRITE, L::GENERAL, true),
            Access::ColorAttachmentWrite => (
                S::COLOR_ATTACHMENT_OUTPUT,
                A::COLOR_ATTACHMENT_READ | A::COLOR_ATTACHMENT_WRITE,
                L::COLOR_ATTACHMENT_OPTIMAL,
                true,
            ),
            Access::FragmentSampledRead => (
                S::FRAGMENT_SHADER,
                A::SHADER_SAMPLED_READ,
                L::SHADER_READ_ONLY_OPTIMAL,
                false,
            ),
            // Presentation needs no stage or access: the semaphore orders it.
            Access::Present => (S::NONE, A::NONE, L::PRESENT_SRC_KHR, false),
            // Only an execution dependency on the semaphore wait; the first
            // use discards the contents (old layout UNDEFINED).
            Access::Acquired => (
                S::ALL_TRANSFER | S::COLOR_ATTACHMENT_OUTPUT,
                A::NONE,
                L::UNDEFINED,
                false,
            ),
        };
        AccessInfo {
            stage,
            access,
            layout,
            writes,
        }
    }

    /// The image usage this access requires of the image it touches.
    pub fn image_usage(self) -> vk::ImageUsageFlags {
        use vk::ImageUsageFlags as U;
        match self {
            Access::ComputeSampledRead | Access::FragmentSampledRead => U::SAMPLED,
            Access::ComputeStorageRead
            | Access::ComputeStorageWrite
            | Access::ComputeStorageReadWrite => U::STORAGE,
            Access::TransferRead => U::TRANSFER_SRC,
            Access::TransferWrite => U::TRANSFER_DST,
            Access::ColorAttachmentWrite => U::COLOR_ATTACHMENT,
            Access::Nothing
            | Access::IndirectRead
            | Access::HostRead
            | Access::HostWrite
            | Access::Present
            | Access::Acquired => U::empty(),
        }
    }

    /// The buffer usage this access requires of the buffer it touches.
    pub fn buffer_usage(self) -> vk::BufferUsageFlags {
        use vk::BufferUsageFlags as U;
        match self {
            Access::ComputeStorageRead
            | Access::ComputeStorageWrite
            | Access::ComputeStorageReadWrite => U::STORAGE_BUFFER,
            Access::IndirectRead => U::INDIRECT_BUFFER,
            Access::TransferRead => U::TRANSFER_SRC,
            Access::TransferWrite => U::TRANSFER_DST,
            _ => U::empty(),
        }
    }

    /// Whether this access is allowed on an image.
    pub fn valid_for_image(self) -> bool {
        !matches!(self, Access::IndirectRead)
    }

    /// Whether this access is allowed on a buffer.
    pub fn valid_for_buffer(self) -> bool {
        !matches!(
            self,
            Access::ComputeSampledRead
                | Access::FragmentSampledRead
                | Access::ColorAttachmentWrite
                | Access::Present
                | Access::Acquired
        )
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn writes_have_write_access_bits_and_reads_do_not() {
        let write_bits = vk::AccessFlags2::SHADER_STORAGE_WRITE
            | vk::AccessFlags2::TRANSFER_WRITE
            | vk::AccessFlags2::HOST_WRITE
            | vk::AccessFlags2::COLOR_ATTACHMENT_WRITE;
        for a in Access::ALL {
            let i = a.info();
            assert_eq!(i.writes, i.access.intersects(write_bits), "{a:?}");
        }
    }

    #[test]
    fn every_image_access_but_nothing_names_a_defined_layout() {
        for a in Access::ALL {
            if a.valid_for_image() && a != Access::Nothing && a != Access::Acquired {
                assert_ne!(a.info().layout, vk::ImageLayout::UNDEFINED, "{a:?}");
            }
        }
    }
}
