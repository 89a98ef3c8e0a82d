//! A compute pass declared binding by binding: each call declares a graph
//! access *and* fills the shader's next descriptor binding, so a resource is
//! named once, where it is bound (after kajiya-rg's `SimpleRenderPass`,
//! `hl.rs`, and screen-13's `read_descriptor_as`).
//!
//! A shader's bindings are a table of [`Binding`]s, declared once per pass
//! beside its pipelines: the pipeline's layout takes its kinds from the
//! table ([`kinds`]), and a pass walks the same table in order. A
//! declaration of the wrong kind, or too few or too many, fails the pass's
//! recording with a message naming the binding, before anything reaches the
//! device.
//!
//! ```text
//! ComputePass::new(graph, "bloom down 1", &BLOOM_BINDINGS)
//!     .sampled_mip(&chain, 0, sampler)                       // binding 0
//!     .storage_image(&mut chain, Access::ComputeStorageWrite, 1)  // binding 1
//!     .dispatch(move || Ok(&pipelines.down), push, (w, h));
//! ```

use std::ops::Deref;

use ash::vk;

use super::{dispatch_2d, dispatch_indirect};
use crate::graph::{BufferHandle, BufferRef, Graph, ImageHandle, ImageRef, Mips, PassBuilder};
use crate::vk::{Access, BindingKind, ComputePipeline, Descriptor};
use crate::{Error, Result};

/// One descriptor binding of a compute shader: its name (the GLSL
/// variable, or the `#define` of its number) and its kind. Its number is
/// its place in the table.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Binding {
    pub name: &'static str,
    pub kind: BindingKind,
}

impl Binding {
    pub const fn storage_image(name: &'static str) -> Self {
        Binding {
            name,
            kind: BindingKind::StorageImage,
        }
    }

    pub const fn sampled(name: &'static str) -> Self {
        Binding {
            name,
            kind: BindingKind::SampledImage,
        }
    }

    pub const fn storage_buffer(name: &'static str) -> Self {
        Binding {
            name,
            kind: BindingKind::StorageBuffer,
        }
    }
}

/// The kinds of a table's bindings, in order: a pipeline layout's.
pub fn kinds(table: &[Binding]) -> Vec<BindingKind> {
    table.iter().map(|b| b.kind).collect()
}

/// What a declaration bound, resolved to a descriptor when the pass records.
enum Bound {
    StorageImage(ImageRef, u32),
    /// All mips (None) or one.
    Sampled(ImageRef, Option<u32>, vk::Sampler),
    Buffer(BufferRef),
    /// A buffer outside the graph (a placeholder a specialisation never
    /// reads).
    Absent(vk::Buffer),
}

impl Bound {
    fn kind(&self) -> BindingKind {
        match self {
            Bound::StorageImage(..) => BindingKind::StorageImage,
            Bound::Sampled(..) => BindingKind::SampledImage,
            Bound::Buffer(_) | Bound::Absent(_) => BindingKind::StorageBuffer,
        }
    }
}

/// A compute pass being declared (see the module's documentation).
pub struct ComputePass<'g, 'a> {
    pass: PassBuilder<'g, 'a>,
    name: String,
    table: &'static [Binding],
    bound: Vec<Bound>,
}

impl<'g, 'a> ComputePass<'g, 'a> {
    /// A pass named `name` of a shader whose bindings are `table`.
    pub fn new(graph: &'g mut Graph<'a>, name: &str, table: &'static [Binding]) -> Self {
        ComputePass {
            pass: graph.add_pass(name),
            name: name.to_owned(),
            table,
            bound: Vec::new(),
        }
    }

    /// The next binding: mip `mip` of `image` as a storage image, written
    /// (or read and written) with `access`.
    pub fn storage_image(mut self, image: &mut ImageHandle, access: Access, mip: u32) -> Self {
        let r = self.pass.write(image, access, Mips::one(mip));
        self.bound.push(Bound::StorageImage(r, mip));
        self
    }

    /// The next binding: mip `mip` of `image` as a storage image, only read.
    pub fn storage_image_read(mut self, image: &ImageHandle, mip: u32) -> Self {
        let r = self
            .pass
            .read(image, Access::ComputeStorageRead, Mips::one(mip));
        self.bound.push(Bound::StorageImage(r, mip));
        self
    }

    /// The next binding: every mip of `image`, sampled with `sampler`.
    pub fn sampled(self, image: &ImageHandle, sampler: vk::Sampler) -> Self {
        self.sample(image, None, sampler)
    }

    /// The next binding: mip `mip` of `image` alone, sampled with `sampler`.
    pub fn sampled_mip(self, image: &ImageHandle, mip: u32, sampler: vk::Sampler) -> Self {
        self.sample(image, Some(mip), sampler)
    }

    /// A sampled binding; an image the pass already samples the same way
    /// (one texture behind two bindings) is declared to the graph once.
    fn sample(mut self, image: &ImageHandle, mip: Option<u32>, sampler: vk::Sampler) -> Self {
        let earlier = self.bound.iter().find_map(|b| match b {
            Bound::Sampled(r, m, _) if r.id == image.id && *m == mip => Some(*r),
            _ => None,
        });
        let r = earlier.unwrap_or_else(|| {
            let mips = mip.map_or(Mips::ALL, Mips::one);
            self.pass.read(image, Access::ComputeSampledRead, mips)
        });
        self.bound.push(Bound::Sampled(r, mip, sampler));
        self
    }

    /// The next binding: `buffer` as a storage buffer, read with `access`
    /// (a storage read, or the indirect dispatch's arguments).
    pub fn buffer_read(mut self, buffer: &BufferHandle, access: Access) -> Self {
        let r = self.pass.read_buffer(buffer, access);
        self.bound.push(Bound::Buffer(r));
        self
    }

    /// The next binding: `buffer` as a storage buffer, written with `access`.
    pub fn buffer_write(mut self, buffer: &mut BufferHandle, access: Access) -> Self {
        let r = self.pass.write_buffer(buffer, access);
        self.bound.push(Bound::Buffer(r));
        self
    }

    /// The next binding: a buffer outside the graph that the shader's
    /// specialisation never reads (where an optional buffer is absent).
    pub fn absent_buffer(mut self, buffer: vk::Buffer) -> Self {
        self.bound.push(Bound::Absent(buffer));
        self
    }

    /// Records the pass: the pipeline (built on first use by `pipeline`),
    /// its descriptors, `push` constants and 8x8 workgroups over `size`.
    pub fn dispatch<P: Deref<Target = ComputePipeline>>(
        self,
        pipeline: impl FnOnce() -> Result<P> + 'a,
        push: Vec<u8>,
        size: (u32, u32),
    ) {
        self.record(pipeline, move |ctx, p, d, _| {
            dispatch_2d(ctx, p, d, &push, size.0, size.1)
        });
    }

    /// Records the pass dispatched indirectly: the workgroup counts are the
    /// first three u32 of the buffer bound at the binding named `args`.
    pub fn dispatch_indirect<P: Deref<Target = ComputePipeline>>(
        self,
        pipeline: impl FnOnce() -> Result<P> + 'a,
        args: &'static str,
    ) {
        let at = self.table.iter().position(|b| b.name == args);
        self.record(pipeline, move |ctx, p, d, buffers| {
            match at.and_then(|i| buffers.get(i)) {
                Some(Some(b)) => dispatch_indirect(ctx, p, d, *b),
                _ => Err(Error::Other(format!(
                    "binding `{args}` holds no buffer for the indirect dispatch"
                ))),
            }
        });
    }

    /// Checks the declarations against the table (a programming error
    /// reported as the pass's failure, not a panic).
    fn check(&self) -> Result<()> {
        let declared: Vec<BindingKind> = self.bound.iter().map(Bound::kind).collect();
        if declared.len() != self.table.len() {
            return Err(Error::Other(format!(
                "pass `{}` declares {} bindings; its shader has {}",
                self.name,
                declared.len(),
                self.table.len()
            )));
        }
        for (i, (b, kind)) in self.table.iter().zip(&declared).enumerate() {
            if b.kind != *kind {
                return Err(Error::Other(format!(
                    "pass `{}` binds a {kind:?} at binding {i} (`{}`), which is a {:?}",
                    self.name, b.name, b.kind
                )));
            }
        }
        Ok(())
    }

    fn record<P: Deref<Target = ComputePipeline>>(
        self,
        pipeline: impl FnOnce() -> Result<P> + 'a,
        run: impl FnOnce(
            &crate::graph::PassContext<'_>,
            &ComputePipeline,
            &[Descriptor],
            &[Option<vk::Buffer>],
        ) -> Result<()>
        + 'a,
    ) {
        let checked = self.check();
        let bound = self.bound;
        self.pass.record(move |ctx| {
            checked?;
            let pipeline = pipeline()?;
            let buffers: Vec<Option<vk::Buffer>> = bound
                .iter()
                .map(|b| match b {
                    Bound::Buffer(r) => Some(ctx.buffer(r)),
                    Bound::Absent(buffer) => Some(*buffer),
                    _ => None,
                })
                .collect();
            let descriptors: Vec<Descriptor> = bound
                .iter()
                .zip(&buffers)
                .map(|(b, buffer)| match b {
                    Bound::StorageImage(r, mip) => Descriptor::StorageImage(ctx.view(r, *mip)),
                    Bound::Sampled(r, None, s) => Descriptor::SampledImage(ctx.full_view(r), *s),
                    Bound::Sampled(r, Some(mip), s) => {
                        Descriptor::SampledImage(ctx.view(r, *mip), *s)
                    }
                    Bound::Buffer(_) | Bound::Absent(_) => {
                        Descriptor::StorageBuffer(buffer.unwrap_or_default())
                    }
                })
                .collect();
            run(ctx, &pipeline, &descriptors, &buffers)
        });
    }
}
