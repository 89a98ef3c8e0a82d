//! The frame graph: passes declare what they read and write; the graph orders
//! them, culls the unused ones, derives usage flags and every barrier, and
//! records them.
//!
//! Three layers that never leak into each other (after kajiya-rg): `vk` wraps
//! Vulkan, this module schedules, `passes` add effects. A pass never writes a
//! barrier, never sets a usage flag and never opens a debug label or a
//! timestamp: [`compile`] and [`execute`] do that from the declarations.
//!
//! ```text
//! let mut g = Graph::new(w, h);
//! let mut hdr = g.create_image("hdr", ImageDesc::new_2d(format, w, h));
//! let mut pass = g.add_pass("raymarch");
//! let out = pass.write(&mut hdr, Access::ComputeStorageWrite, Mips::ALL);
//! pass.record(move |ctx| { /* bind ctx.view(&out, 0), dispatch */ });
//! let compiled = g.compile()?;
//! ```

pub mod compile;
pub mod execute;
pub mod resource;

pub use compile::{BufferBarrier, Compiled, ImageBarrier, PassBarriers, compile};
pub use execute::{PassContext, TransientPool};
pub use resource::{
    BufferBinding, BufferHandle, BufferRef, ImageBinding, ImageDesc, ImageHandle, ImageRef, Mips,
};

use crate::vk::Access;

/// Where an image comes from.
#[derive(Clone, Debug)]
pub(crate) enum ImageOrigin {
    /// Created (or reused) by the graph; contents start undefined each frame.
    Transient,
    /// Owned outside; starts in `initial` and must end in `final_access`.
    Imported {
        binding: ImageBinding,
        initial: Access,
        final_access: Option<Access>,
    },
}

#[derive(Clone, Debug)]
pub(crate) struct ImageNode {
    pub name: String,
    pub desc: ImageDesc,
    pub origin: ImageOrigin,
}

/// Where a buffer comes from.
#[derive(Clone, Debug)]
pub(crate) enum BufferOrigin {
    /// Created (or reused) by the graph; contents start undefined each frame.
    Transient,
    /// Owned outside; starts in `initial` and must end in `final_access`.
    Imported {
        binding: BufferBinding,
        initial: Access,
        final_access: Option<Access>,
    },
}

#[derive(Clone, Debug)]
pub(crate) struct BufferNode {
    pub name: String,
    pub size: u64,
    pub origin: BufferOrigin,
}

impl BufferNode {
    /// The state the buffer enters the graph in.
    pub(crate) fn initial(&self) -> Access {
        match self.origin {
            BufferOrigin::Transient => Access::Nothing,
            BufferOrigin::Imported { initial, .. } => initial,
        }
    }

    /// The state the graph must leave an imported buffer in, if any.
    pub(crate) fn final_access(&self) -> Option<Access> {
        match self.origin {
            BufferOrigin::Transient => None,
            BufferOrigin::Imported { final_access, .. } => final_access,
        }
    }
}

/// One declared image use of a pass.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ImageUse {
    pub image: usize,
    pub access: Access,
    pub mips: Mips,
}

/// One declared buffer use of a pass.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BufferUse {
    pub buffer: usize,
    pub access: Access,
}

/// What a pass records once its barriers are in place.
pub type RecordFn<'a> = Box<dyn FnOnce(&mut PassContext<'_>) -> crate::Result<()> + 'a>;

pub(crate) struct PassNode<'a> {
    pub name: String,
    pub images: Vec<ImageUse>,
    pub buffers: Vec<BufferUse>,
    pub record: Option<RecordFn<'a>>,
}

/// A frame's worth of passes and resources. Built each frame (cheap), compiled,
/// executed, dropped.
#[derive(Default)]
pub struct Graph<'a> {
    /// Size of the frame's output, which graph-owned images are sized against.
    output: (u32, u32),
    pub(crate) images: Vec<ImageNode>,
    pub(crate) buffers: Vec<BufferNode>,
    pub(crate) passes: Vec<PassNode<'a>>,
}

impl<'a> Graph<'a> {
    /// An empty graph for a `width` x `height` output.
    pub fn new(width: u32, height: u32) -> Self {
        Graph {
            output: (width, height),
            ..Self::default()
        }
    }

    /// The output size given to [`Graph::new`].
    pub fn output_size(&self) -> (u32, u32) {
        self.output
    }

    /// A graph-owned image sized relative to the output: `1 / divisor` of it
    /// per side (at least one texel), with `mips` levels (clamped to what the
    /// size allows).
    pub fn create_relative(
        &mut self,
        name: &str,
        format: ash::vk::Format,
        divisor: u32,
        mips: u32,
    ) -> ImageHandle {
        let d = divisor.max(1);
        let desc = ImageDesc::new_2d(
            format,
            (self.output.0 / d).max(1),
            (self.output.1 / d).max(1),
        )
        .with_mips(mips);
        self.create_image(name, desc)
    }

    /// A graph-owned image, created once and reused across frames.
    pub fn create_image(&mut self, name: &str, desc: ImageDesc) -> ImageHandle {
        self.images.push(ImageNode {
            name: name.to_owned(),
            desc,
            origin: ImageOrigin::Transient,
        });
        ImageHandle {
            id: self.images.len() - 1,
            desc,
        }
    }

    /// An image owned outside the graph, currently in state `initial`; if
    /// `final_access` is given, the graph leaves it in that state and keeps
    /// every pass that writes it.
    pub fn import_image(
        &mut self,
        name: &str,
        desc: ImageDesc,
        binding: ImageBinding,
        initial: Access,
        final_access: Option<Access>,
    ) -> ImageHandle {
        self.images.push(ImageNode {
            name: name.to_owned(),
            desc,
            origin: ImageOrigin::Imported {
                binding,
                initial,
                final_access,
            },
        });
        ImageHandle {
            id: self.images.len() - 1,
            desc,
        }
    }

    /// A graph-owned buffer of `size` bytes in device memory, created once
    /// and reused across frames (its usage comes from the passes that use
    /// it). Its contents start undefined each frame: a pass must write it
    /// (a shader, or a transfer such as a fill) before any pass reads it.
    pub fn create_buffer(&mut self, name: &str, size: u64) -> BufferHandle {
        self.buffers.push(BufferNode {
            name: name.to_owned(),
            size,
            origin: BufferOrigin::Transient,
        });
        BufferHandle {
            id: self.buffers.len() - 1,
            size,
        }
    }

    /// A buffer owned outside the graph (see [`Graph::import_image`]).
    pub fn import_buffer(
        &mut self,
        name: &str,
        binding: BufferBinding,
        initial: Access,
        final_access: Option<Access>,
    ) -> BufferHandle {
        self.buffers.push(BufferNode {
            name: name.to_owned(),
            size: binding.size,
            origin: BufferOrigin::Imported {
                binding,
                initial,
                final_access,
            },
        });
        BufferHandle {
            id: self.buffers.len() - 1,
            size: binding.size,
        }
    }

    /// Starts a pass; declare its uses on the builder, then `record`.
    pub fn add_pass<'g>(&'g mut self, name: &str) -> PassBuilder<'g, 'a> {
        self.passes.push(PassNode {
            name: name.to_owned(),
            images: Vec::new(),
            buffers: Vec::new(),
            record: None,
        });
        PassBuilder { graph: self }
    }

    /// Names of the passes in declaration order.
    pub fn pass_names(&self) -> Vec<&str> {
        self.passes.iter().map(|p| p.name.as_str()).collect()
    }

    /// Name of image `id` (for messages and labels).
    pub fn image_name(&self, h: &ImageHandle) -> &str {
        &self.images[h.id].name
    }

    /// Orders, culls and synchronizes the graph (pure; no Vulkan calls).
    pub fn compile(&self) -> crate::Result<Compiled> {
        compile::compile(self)
    }
}

/// Declares one pass's uses; each declaration returns the reference the
/// pass's recording reads the resource through, so a resource the pass did
/// not declare cannot be bound. Dropping the builder without `record` leaves
/// a pass that records nothing (still scheduled, still synchronized).
pub struct PassBuilder<'g, 'a> {
    graph: &'g mut Graph<'a>,
}

impl<'a> PassBuilder<'_, 'a> {
    fn index(&self) -> usize {
        // add_pass pushed the node this builder describes.
        self.graph.passes.len() - 1
    }

    fn pass(&mut self) -> &mut PassNode<'a> {
        let last = self.index();
        &mut self.graph.passes[last]
    }

    fn use_image(&mut self, image: &ImageHandle, access: Access, mips: Mips) -> ImageRef {
        self.pass().images.push(ImageUse {
            image: image.id,
            access,
            mips,
        });
        ImageRef {
            id: image.id,
            pass: self.index(),
            desc: image.desc,
        }
    }

    fn use_buffer(&mut self, buffer: &BufferHandle, access: Access) -> BufferRef {
        self.pass().buffers.push(BufferUse {
            buffer: buffer.id,
            access,
        });
        BufferRef {
            id: buffer.id,
            pass: self.index(),
            size: buffer.size,
        }
    }

    /// Declares a read of `mips` of `image`.
    pub fn read(&mut self, image: &ImageHandle, access: Access, mips: Mips) -> ImageRef {
        debug_assert!(!access.info().writes, "{access:?} is a write; use write()");
        self.use_image(image, access, mips)
    }

    /// Declares a write (or read-write) of `mips` of `image`.
    pub fn write(&mut self, image: &mut ImageHandle, access: Access, mips: Mips) -> ImageRef {
        debug_assert!(access.info().writes, "{access:?} is a read; use read()");
        self.use_image(image, access, mips)
    }

    /// Declares a read of `buffer`.
    pub fn read_buffer(&mut self, buffer: &BufferHandle, access: Access) -> BufferRef {
        debug_assert!(!access.info().writes, "{access:?} is a write");
        self.use_buffer(buffer, access)
    }

    /// Declares a write of `buffer`.
    pub fn write_buffer(&mut self, buffer: &mut BufferHandle, access: Access) -> BufferRef {
        debug_assert!(access.info().writes, "{access:?} is a read");
        self.use_buffer(buffer, access)
    }

    /// Sets what the pass records; called once the graph's barriers are in place.
    pub fn record(mut self, f: impl FnOnce(&mut PassContext<'_>) -> crate::Result<()> + 'a) {
        self.pass().record = Some(Box::new(f));
    }
}
