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

/// A handle to an image in one graph, held by whoever created or imported
/// it. Neither `Clone` nor `Copy`: a pass declares a read through `&handle`
/// and a write through `&mut handle`, so a second owner that could write
/// behind the graph's back cannot exist. What a pass's recording sees is
/// the [`ImageRef`] its declaration returned, never the handle.
///
/// ```
/// use blackhole::graph::{Graph, ImageDesc, Mips};
/// use blackhole::vk::Access;
/// let mut g = Graph::new(8, 8);
/// let desc = ImageDesc::new_2d(ash::vk::Format::R8G8B8A8_UNORM, 8, 8);
/// let mut image = g.create_image("a", desc);
/// let mut pass = g.add_pass("write");
/// let out = pass.write(&mut image, Access::ComputeStorageWrite, Mips::ALL);
/// pass.record(move |ctx| {
///     let _view = ctx.view(&out, 0);
///     Ok(())
/// });
/// ```
///
/// A second owner cannot be made:
///
/// ```compile_fail
/// use blackhole::graph::{Graph, ImageDesc};
/// let mut g = Graph::new(8, 8);
/// let desc = ImageDesc::new_2d(ash::vk::Format::R8G8B8A8_UNORM, 8, 8);
/// let image = g.create_image("a", desc);
/// let second = image.clone();
/// ```
#[derive(Debug, PartialEq, Eq)]
pub struct ImageHandle {
    pub(crate) id: usize,
    pub desc: ImageDesc,
}

/// A handle to a buffer in one graph (see [`ImageHandle`]).
#[derive(Debug, PartialEq, Eq)]
pub struct BufferHandle {
    pub(crate) id: usize,
    pub size: u64,
}

/// One pass's declared use of an image: returned by
/// [`crate::graph::PassBuilder::read`] and [`crate::graph::PassBuilder::write`]
/// and the only way its recording reaches the image
/// ([`crate::graph::PassContext::view`]). Valid in that pass only (checked
/// in debug builds).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ImageRef {
    pub(crate) id: usize,
    pub(crate) pass: usize,
    pub desc: ImageDesc,
}

/// One pass's declared use of a buffer (see [`ImageRef`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BufferRef {
    pub(crate) id: usize,
    pub(crate) pass: usize,
    pub size: u64,
}
