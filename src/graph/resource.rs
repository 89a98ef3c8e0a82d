//! Graph resources: handles, descriptions and subresource ranges.

pub use crate::vk::{BufferBinding, ImageBinding, ImageDesc};

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
