//! Graph resources: handles, descriptions and subresource ranges.

use ash::vk;

/// A range of mip levels: `base .. base + count`.
///
/// Subresource indexing, explained once: an image with `m` mip levels (one
/// array layer, colour aspect) has subresources `0 .. m`, and subresource `i`
/// is mip level `i`. Every per-subresource array in the graph (state, liveness)
/// is indexed this way.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Mips {
    pub base: u32,
    pub count: u32,
}

impl Mips {
    /// One mip level.
    pub const fn one(level: u32) -> Self {
        Mips {
            base: level,
            count: 1,
        }
    }

    /// Levels `base .. base + count`.
    pub const fn range(base: u32, count: u32) -> Self {
        Mips { base, count }
    }

    /// Every level, resolved against the image's level count at build time.
    pub const ALL: Mips = Mips {
        base: 0,
        count: u32::MAX,
    };

    /// Iterates the levels, clamped to an image of `levels` mips.
    pub(crate) fn levels(self, levels: u32) -> std::ops::Range<u32> {
        let end = self.base.saturating_add(self.count).min(levels);
        self.base.min(end)..end
    }
}

/// Size of a graph-owned image.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct ImageDesc {
    pub format: vk::Format,
    pub width: u32,
    pub height: u32,
    pub mip_levels: u32,
}

impl ImageDesc {
    /// A single-level 2-D image.
    pub fn new_2d(format: vk::Format, width: u32, height: u32) -> Self {
        ImageDesc {
            format,
            width,
            height,
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

/// A handle to an image in one graph. Not `Copy`: passes read through `&handle`
/// and write through `&mut handle`, so intent shows in the types.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct ImageHandle {
    pub(crate) id: usize,
    pub desc: ImageDesc,
}

/// A handle to a buffer in one graph.
#[derive(Clone, Debug, PartialEq, Eq)]
pub struct BufferHandle {
    pub(crate) id: usize,
    pub size: u64,
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

/// The Vulkan object behind an imported buffer.
#[derive(Clone, Copy, Debug)]
pub struct BufferBinding {
    pub buffer: vk::Buffer,
    pub size: u64,
}
