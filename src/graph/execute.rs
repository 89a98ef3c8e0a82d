//! Executing a compiled graph: realize transient images and buffers, then
//! for each live pass record a debug label, a timestamp pair, the pass's
//! barriers and the pass's own commands; then the final barriers.

use std::sync::Arc;

use ash::vk;

use super::{
    BufferOrigin, BufferRef, Compiled, Graph, ImageDesc, ImageOrigin, ImageRef, PassBarriers,
};
use crate::vk::{Buffer, Gpu, Image, TimestampPool};
use crate::{Error, Result};

/// Graph-owned images and buffers, created on first use and reused by later
/// frames with the same description and usage (never re-created per frame).
pub struct TransientPool {
    gpu: Arc<Gpu>,
    images: Vec<(Image, bool)>,
    buffers: Vec<(Buffer, vk::BufferUsageFlags, bool)>,
}

impl TransientPool {
    /// An empty pool.
    pub fn new(gpu: &Arc<Gpu>) -> Self {
        TransientPool {
            gpu: gpu.clone(),
            images: Vec::new(),
            buffers: Vec::new(),
        }
    }

    fn begin_frame(&mut self) {
        for (_, used) in &mut self.images {
            *used = false;
        }
        for (_, _, used) in &mut self.buffers {
            *used = false;
        }
    }

    fn acquire(
        &mut self,
        name: &str,
        desc: ImageDesc,
        usage: vk::ImageUsageFlags,
    ) -> Result<usize> {
        if let Some(i) = self
            .images
            .iter()
            .position(|(img, used)| !used && img.desc == desc && img.usage == usage)
        {
            self.images[i].1 = true;
            return Ok(i);
        }
        let image = Image::new(&self.gpu, name, desc, usage)?;
        self.images.push((image, true));
        Ok(self.images.len() - 1)
    }

    fn acquire_buffer(
        &mut self,
        name: &str,
        size: u64,
        usage: vk::BufferUsageFlags,
    ) -> Result<vk::Buffer> {
        if let Some(i) = self
            .buffers
            .iter()
            .position(|(b, u, used)| !used && b.size == size && *u == usage)
        {
            self.buffers[i].2 = true;
            return Ok(self.buffers[i].0.buffer);
        }
        let buffer = Buffer::new(
            &self.gpu,
            name,
            size,
            usage,
            gpu_allocator::MemoryLocation::GpuOnly,
        )?;
        let handle = buffer.buffer;
        self.buffers.push((buffer, usage, true));
        Ok(handle)
    }

    /// Drops images and buffers no frame used since the last `begin_frame`
    /// (after a resize).
    pub fn trim_unused(&mut self) {
        self.images.retain(|(_, used)| *used);
        self.buffers.retain(|(_, _, used)| *used);
    }

    /// Number of images and buffers held.
    pub fn len(&self) -> usize {
        self.images.len() + self.buffers.len()
    }

    /// True when the pool holds nothing.
    pub fn is_empty(&self) -> bool {
        self.images.is_empty() && self.buffers.is_empty()
    }
}

#[derive(Clone)]
struct Resolved {
    image: vk::Image,
    mip_views: Vec<vk::ImageView>,
    full_view: vk::ImageView,
}

/// What a pass sees while recording: the command buffer and the Vulkan objects
/// behind its handles. Barriers are already in place.
pub struct PassContext<'r> {
    pub gpu: &'r Gpu,
    pub cmd: vk::CommandBuffer,
    /// The pass being recorded (its references are checked against it).
    pass: usize,
    images: &'r [Resolved],
    buffers: &'r [vk::Buffer],
}

impl PassContext<'_> {
    fn resolve(&self, r: &ImageRef) -> &Resolved {
        debug_assert_eq!(
            r.pass, self.pass,
            "an image reference used outside its pass"
        );
        &self.images[r.id]
    }

    /// The view of one mip level of an image the pass declared.
    pub fn view(&self, r: &ImageRef, mip: u32) -> vk::ImageView {
        self.resolve(r).mip_views[mip as usize]
    }

    /// A view of all mip levels.
    pub fn full_view(&self, r: &ImageRef) -> vk::ImageView {
        self.resolve(r).full_view
    }

    /// The image itself (for copies).
    pub fn image(&self, r: &ImageRef) -> vk::Image {
        self.resolve(r).image
    }

    /// A buffer the pass declared.
    pub fn buffer(&self, r: &BufferRef) -> vk::Buffer {
        debug_assert_eq!(
            r.pass, self.pass,
            "a buffer reference used outside its pass"
        );
        self.buffers[r.id]
    }
}

/// Timestamp slots used by `n` timed passes.
pub fn timestamp_count(n: usize) -> u32 {
    2 * n as u32
}

/// Records `graph` into `cmd`. Returns the names of the live passes in order;
/// pass `i` wrote timestamps `2i` and `2i + 1` when `timestamps` is given.
pub fn execute(
    graph: Graph<'_>,
    compiled: &Compiled,
    gpu: &Gpu,
    cmd: vk::CommandBuffer,
    pool: &mut TransientPool,
    timestamps: Option<&TimestampPool>,
) -> Result<Vec<String>> {
    let Graph {
        images,
        buffers,
        mut passes,
        ..
    } = graph;

    // Realize images: imports as given, transients from the pool.
    pool.begin_frame();
    let used: Vec<bool> = (0..images.len())
        .map(|id| {
            compiled
                .order
                .iter()
                .any(|&p| passes[p].images.iter().any(|u| u.image == id))
        })
        .collect();
    let mut resolved = Vec::with_capacity(images.len());
    for (id, node) in images.iter().enumerate() {
        let r = match &node.origin {
            ImageOrigin::Imported { binding, .. } => Resolved {
                image: binding.image,
                mip_views: binding.mip_views.clone(),
                full_view: binding.full_view,
            },
            ImageOrigin::Transient if used[id] => {
                let i = pool.acquire(&node.name, node.desc, compiled.image_usage[id])?;
                let img = &pool.images[i].0;
                Resolved {
                    image: img.image,
                    mip_views: img.mip_views.clone(),
                    full_view: img.full_view,
                }
            }
            ImageOrigin::Transient => Resolved {
                image: vk::Image::null(),
                mip_views: Vec::new(),
                full_view: vk::ImageView::null(),
            },
        };
        resolved.push(r);
    }
    let mut buffer_handles = Vec::with_capacity(buffers.len());
    for (id, node) in buffers.iter().enumerate() {
        let used = compiled
            .order
            .iter()
            .any(|&p| passes[p].buffers.iter().any(|u| u.buffer == id));
        buffer_handles.push(match &node.origin {
            BufferOrigin::Imported { binding, .. } => binding.buffer,
            BufferOrigin::Transient if used => {
                pool.acquire_buffer(&node.name, node.size, compiled.buffer_usage[id])?
            }
            BufferOrigin::Transient => vk::Buffer::null(),
        });
    }

    let timed = timestamps.filter(|t| timestamp_count(compiled.order.len()) <= t.capacity);
    if timestamps.is_some() && timed.is_none() {
        log::warn!(
            "{} passes exceed the timestamp pool; this frame is not timed",
            compiled.order.len()
        );
    }
    if let Some(t) = timed {
        t.cmd_reset(cmd, timestamp_count(compiled.order.len()));
    }

    let mut names = Vec::with_capacity(compiled.order.len());
    for (i, &p) in compiled.order.iter().enumerate() {
        let pass = &mut passes[p];
        gpu.begin_label(cmd, &pass.name);
        if let Some(t) = timed {
            gpu.cmd_write_timestamp2(
                cmd,
                vk::PipelineStageFlags2::ALL_COMMANDS,
                t.pool,
                2 * i as u32,
            );
        }
        record_barriers(gpu, cmd, &compiled.before[i], &resolved, &buffer_handles);
        if let Some(f) = pass.record.take() {
            let mut ctx = PassContext {
                gpu,
                cmd,
                pass: p,
                images: &resolved,
                buffers: &buffer_handles,
            };
            f(&mut ctx).map_err(|e| match e {
                Error::Other(m) => Error::Other(format!("recording pass `{}`: {m}", pass.name)),
                other => other,
            })?;
        }
        if let Some(t) = timed {
            gpu.cmd_write_timestamp2(
                cmd,
                vk::PipelineStageFlags2::ALL_COMMANDS,
                t.pool,
                2 * i as u32 + 1,
            );
        }
        gpu.end_label(cmd);
        names.push(pass.name.clone());
    }
    record_barriers(gpu, cmd, &compiled.after, &resolved, &buffer_handles);
    Ok(names)
}

/// The dependency every barrier of the graph carries, from a compiled
/// barrier's four masks (the queue family never changes).
macro_rules! dependency {
    ($barrier:expr, $b:expr) => {
        $barrier
            .src_stage_mask($b.src_stage)
            .src_access_mask($b.src_access)
            .dst_stage_mask($b.dst_stage)
            .dst_access_mask($b.dst_access)
            .src_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
            .dst_queue_family_index(vk::QUEUE_FAMILY_IGNORED)
    };
}

fn record_barriers(
    gpu: &Gpu,
    cmd: vk::CommandBuffer,
    b: &PassBarriers,
    images: &[Resolved],
    buffers: &[vk::Buffer],
) {
    if b.is_empty() {
        return;
    }
    let image_barriers: Vec<vk::ImageMemoryBarrier2<'_>> = b
        .images
        .iter()
        .map(|ib| {
            dependency!(vk::ImageMemoryBarrier2::default(), ib)
                .old_layout(ib.old_layout)
                .new_layout(ib.new_layout)
                .image(images[ib.image].image)
                .subresource_range(vk::ImageSubresourceRange {
                    aspect_mask: vk::ImageAspectFlags::COLOR,
                    base_mip_level: ib.base_mip,
                    level_count: ib.mip_count,
                    base_array_layer: 0,
                    layer_count: 1,
                })
        })
        .collect();
    let buffer_barriers: Vec<vk::BufferMemoryBarrier2<'_>> = b
        .buffers
        .iter()
        .map(|bb| {
            dependency!(vk::BufferMemoryBarrier2::default(), bb)
                .buffer(buffers[bb.buffer])
                .offset(0)
                .size(vk::WHOLE_SIZE)
        })
        .collect();
    let dep = vk::DependencyInfo::default()
        .image_memory_barriers(&image_barriers)
        .buffer_memory_barriers(&buffer_barriers);
    gpu.cmd_pipeline_barrier2(cmd, &dep);
}
