//! Compiling a graph: pure code, no Vulkan calls, unit-tested without a device.
//!
//! [`compile`] reads as a list of steps (after Granite's `bake()`):
//!
//! 1. Validate every declared use (range inside the image, access allowed on
//!    the resource kind, no subresource used twice in one pass), so a wrong
//!    declaration fails here, not as a driver crash.
//! 2. Cull: walk the passes backwards from what leaves the graph (imported
//!    resources with a final state); a pass lives if it writes a subresource a
//!    live pass (or the outside) reads. Culling is per mip level.
//! 3. Order: keep declaration order among the live passes. Passes can only read
//!    what earlier passes wrote, so declaration order is already a valid order.
//! 4. Derive usage flags of every image and buffer from their live accesses.
//! 5. Track the state of every subresource through the live passes and emit
//!    the minimal barrier before each use (a read of a transient nobody wrote
//!    is refused: its contents would be undefined): a layout change, a write after
//!    anything (WAW / WAR), or a read of a write not yet made visible to that
//!    stage and access (RAW). Reads of an already visible write add nothing.
//! 6. Merge adjacent mip levels whose barriers are identical into one range.
//! 7. Emit the final barriers that leave imported resources in their requested
//!    final state.
//! 8. Report the state each image is left in, so the owner of an image kept
//!    across frames imports it next time in the state it is really in.

use ash::vk;

use super::{Graph, ImageOrigin};
use crate::vk::Access;
use crate::{Error, Result};

/// One image memory barrier over a range of mips.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct ImageBarrier {
    pub image: usize,
    pub base_mip: u32,
    pub mip_count: u32,
    pub src_stage: vk::PipelineStageFlags2,
    pub src_access: vk::AccessFlags2,
    pub dst_stage: vk::PipelineStageFlags2,
    pub dst_access: vk::AccessFlags2,
    pub old_layout: vk::ImageLayout,
    pub new_layout: vk::ImageLayout,
}

/// One buffer memory barrier (whole buffer).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct BufferBarrier {
    pub buffer: usize,
    pub src_stage: vk::PipelineStageFlags2,
    pub src_access: vk::AccessFlags2,
    pub dst_stage: vk::PipelineStageFlags2,
    pub dst_access: vk::AccessFlags2,
}

/// Barriers recorded together before one pass (or after the last).
#[derive(Clone, Debug, Default, PartialEq, Eq)]
pub struct PassBarriers {
    pub images: Vec<ImageBarrier>,
    pub buffers: Vec<BufferBarrier>,
}

impl PassBarriers {
    /// True when nothing needs to be recorded.
    pub fn is_empty(&self) -> bool {
        self.images.is_empty() && self.buffers.is_empty()
    }
}

/// The result of [`compile`].
#[derive(Clone, Debug, Default)]
pub struct Compiled {
    /// Live passes, in execution order (indices into the graph's passes).
    pub order: Vec<usize>,
    /// Passes culled because nobody uses what they write.
    pub culled: Vec<usize>,
    /// Barriers before each pass of `order` (same length).
    pub before: Vec<PassBarriers>,
    /// Barriers after the last pass, leaving imports in their final state.
    pub after: PassBarriers,
    /// Usage flags of every image (index = image id).
    pub image_usage: Vec<vk::ImageUsageFlags>,
    /// Usage flags of every buffer (index = buffer id).
    pub buffer_usage: Vec<vk::BufferUsageFlags>,
    /// The state each image is left in after the frame (index = image id):
    /// an import's final access, else its last live use's; None for an
    /// image no live pass uses. An import's owner keeps it for the next
    /// frame's import ([`Compiled::left_in`]).
    pub images_left: Vec<Option<Access>>,
}

impl Compiled {
    /// The state the image named `name` is left in after the frame.
    pub fn left_in(&self, graph: &Graph<'_>, name: &str) -> Option<Access> {
        let id = graph.images.iter().position(|i| i.name == name)?;
        self.images_left.get(id).copied().flatten()
    }
}

/// Synchronization state of one subresource (one mip, or one buffer).
///
/// A write goes through three steps: it happens (`sync_stage`, `pending`),
/// a barrier makes it available (`pending` becomes empty, but later barriers
/// still chain from `sync_stage`), and barriers make it visible to each
/// (stage, access) that reads it (`visible_*`). A layout transition is a write
/// that the barrier performing it has already made available.
#[derive(Clone, Copy, Debug)]
struct SubState {
    layout: vk::ImageLayout,
    /// Stages a later access must wait for to come after the last write (or
    /// the last layout transition): the write's own stage, or the destination
    /// stage of the barrier that transitioned the layout.
    sync_stage: vk::PipelineStageFlags2,
    /// Access mask of the last write not yet made available (empty once a
    /// barrier has flushed it). Always supported by `sync_stage`.
    pending: vk::AccessFlags2,
    /// Whether the subresource holds written data (a transient starts without).
    written: bool,
    /// Stages and accesses the last write (or transition) is already visible to.
    visible_stage: vk::PipelineStageFlags2,
    visible_access: vk::AccessFlags2,
    /// Stages that read since the last write (a later write must wait for them).
    read_stage: vk::PipelineStageFlags2,
}

impl SubState {
    fn from_access(access: Access) -> Self {
        let i = access.info();
        let mut s = SubState {
            layout: i.layout,
            sync_stage: vk::PipelineStageFlags2::NONE,
            pending: vk::AccessFlags2::NONE,
            written: !matches!(access, Access::Nothing | Access::Acquired),
            visible_stage: vk::PipelineStageFlags2::NONE,
            visible_access: vk::AccessFlags2::NONE,
            read_stage: vk::PipelineStageFlags2::NONE,
        };
        if i.writes {
            s.sync_stage = i.stage;
            s.pending = i.access;
        } else {
            s.read_stage = i.stage;
        }
        s
    }
}

/// What one access needs on one subresource before it (a barrier's two
/// halves and the layouts), as [`transition`] derives it.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
struct Dep {
    src_stage: vk::PipelineStageFlags2,
    src_access: vk::AccessFlags2,
    dst_stage: vk::PipelineStageFlags2,
    dst_access: vk::AccessFlags2,
    old_layout: vk::ImageLayout,
    new_layout: vk::ImageLayout,
}

/// Whether the last write is already visible to this read's stage and access.
fn already_visible(s: &SubState, i: crate::vk::AccessInfo) -> bool {
    s.visible_stage.contains(i.stage) && s.visible_access.contains(i.access)
}

/// The barrier one access needs on one subresource, given its state; updates
/// the state. `None` when the access is already safe.
fn transition(s: &mut SubState, access: Access, track_layout: bool) -> Option<Dep> {
    let i = access.info();
    let new_layout = if track_layout {
        i.layout
    } else {
        vk::ImageLayout::UNDEFINED
    };
    let layout_change = track_layout && s.layout != new_layout;
    let has_write = !s.sync_stage.is_empty() || !s.pending.is_empty();
    let dep = if i.writes || layout_change {
        // A write (or a layout transition, which writes) must wait for the last
        // write and every read since, and a write not yet available is flushed.
        // The visible stages chain through an earlier barrier to that write.
        let src_stage = s.sync_stage | s.read_stage | s.visible_stage;
        let needed = !src_stage.is_empty() || layout_change;
        needed.then_some(Dep {
            src_stage,
            src_access: s.pending,
            dst_stage: i.stage,
            dst_access: i.access,
            old_layout: s.layout,
            new_layout,
        })
    } else if has_write && !already_visible(s, i) {
        // Read after a write not yet visible to this stage and access: chain
        // from the write (or the barrier that flushed it); flush it if needed.
        Some(Dep {
            src_stage: s.sync_stage | s.visible_stage,
            src_access: s.pending,
            dst_stage: i.stage,
            dst_access: i.access,
            old_layout: s.layout,
            new_layout: s.layout,
        })
    } else {
        None
    };

    // Update the state.
    if i.writes {
        s.sync_stage = i.stage;
        s.pending = i.access;
        s.written = true;
        s.visible_stage = vk::PipelineStageFlags2::NONE;
        s.visible_access = vk::AccessFlags2::NONE;
        s.read_stage = vk::PipelineStageFlags2::NONE;
    } else {
        if layout_change {
            // The transition is now the last "write": it completes before this
            // access's stage, is available, and is visible to this access only.
            s.sync_stage = i.stage;
            s.read_stage = vk::PipelineStageFlags2::NONE;
            s.visible_stage = i.stage;
            s.visible_access = i.access;
        } else if dep.is_some() {
            s.visible_stage |= i.stage;
            s.visible_access |= i.access;
        }
        // Whatever was pending is available after any barrier.
        if dep.is_some() {
            s.pending = vk::AccessFlags2::NONE;
        }
        s.read_stage |= i.stage;
    }
    s.layout = new_layout;
    dep
}

/// Compiles `graph`; see the module docs for the steps.
pub fn compile(graph: &Graph<'_>) -> Result<Compiled> {
    validate(graph)?;
    let live = cull(graph);
    let order: Vec<usize> = (0..graph.passes.len()).filter(|&p| live[p]).collect();
    let culled: Vec<usize> = (0..graph.passes.len()).filter(|&p| !live[p]).collect();
    let (image_usage, buffer_usage) = usage_flags(graph, &order);
    let mut states = States::initial(graph);
    let before = order
        .iter()
        .map(|&p| states.before_pass(graph, p))
        .collect::<Result<Vec<_>>>()?;
    let after = states.leave_imports(graph);
    let images_left = images_left(graph, &order);
    Ok(Compiled {
        order,
        culled,
        before,
        after,
        image_usage,
        buffer_usage,
        images_left,
    })
}

/// Step 8: the state each image is left in (an import's final access, else
/// its last live use's), for the owner of an import to keep.
fn images_left(graph: &Graph<'_>, order: &[usize]) -> Vec<Option<Access>> {
    let mut left: Vec<Option<Access>> = vec![None; graph.images.len()];
    for &p in order {
        for u in &graph.passes[p].images {
            left[u.image] = Some(u.access);
        }
    }
    for (id, img) in graph.images.iter().enumerate() {
        if let ImageOrigin::Imported {
            final_access: Some(fin),
            ..
        } = img.origin
        {
            left[id] = Some(fin);
        }
    }
    left
}

/// Step 1: every declared use is possible.
fn validate(graph: &Graph<'_>) -> Result<()> {
    for pass in &graph.passes {
        let mut seen: Vec<(usize, u32)> = Vec::new();
        for u in &pass.images {
            let node = graph.images.get(u.image).ok_or_else(|| {
                Error::Other(format!(
                    "pass `{}` uses an image of another graph",
                    pass.name
                ))
            })?;
            if !u.access.valid_for_image() || matches!(u.access, Access::Nothing | Access::Acquired)
            {
                return Err(Error::Other(format!(
                    "pass `{}`: {:?} is not an image access",
                    pass.name, u.access
                )));
            }
            let levels = u.mips.levels(node.desc.mip_levels);
            if levels.is_empty()
                || (u.mips.count != u32::MAX && levels.len() != u.mips.count as usize)
            {
                return Err(Error::Other(format!(
                    "pass `{}`: mips {}..{} of `{}` are outside its {} levels",
                    pass.name,
                    u.mips.base,
                    u.mips.base.saturating_add(u.mips.count),
                    node.name,
                    node.desc.mip_levels
                )));
            }
            for m in levels {
                if seen.contains(&(u.image, m)) {
                    return Err(Error::Other(format!(
                        "pass `{}` declares mip {m} of `{}` twice; use one read-write access",
                        pass.name, node.name
                    )));
                }
                seen.push((u.image, m));
            }
        }
        for u in &pass.buffers {
            let node = graph.buffers.get(u.buffer).ok_or_else(|| {
                Error::Other(format!(
                    "pass `{}` uses a buffer of another graph",
                    pass.name
                ))
            })?;
            if !u.access.valid_for_buffer() || u.access == Access::Nothing {
                return Err(Error::Other(format!(
                    "pass `{}`: {:?} is not a buffer access (buffer `{}`)",
                    pass.name, u.access, node.name
                )));
            }
        }
    }
    Ok(())
}

/// Whether an access reads what is there (a read-write does too).
fn reads(access: Access) -> bool {
    !access.info().writes || access == Access::ComputeStorageReadWrite
}

/// Step 2: which passes live, per mip backwards from what leaves the graph.
fn cull(graph: &Graph<'_>) -> Vec<bool> {
    let mut image_needed: Vec<Vec<bool>> = graph
        .images
        .iter()
        .map(|img| {
            let exported = matches!(
                img.origin,
                ImageOrigin::Imported {
                    final_access: Some(_),
                    ..
                }
            );
            vec![exported; img.desc.mip_levels as usize]
        })
        .collect();
    let mut buffer_needed: Vec<bool> = graph
        .buffers
        .iter()
        .map(|b| b.final_access().is_some())
        .collect();
    let mut live = vec![false; graph.passes.len()];
    for (p, pass) in graph.passes.iter().enumerate().rev() {
        let writes_needed = pass.images.iter().any(|u| {
            u.access.info().writes
                && u.mips
                    .levels(graph.images[u.image].desc.mip_levels)
                    .any(|m| image_needed[u.image][m as usize])
        }) || pass
            .buffers
            .iter()
            .any(|u| u.access.info().writes && buffer_needed[u.buffer]);
        if !writes_needed {
            continue;
        }
        live[p] = true;
        for u in pass.images.iter().filter(|u| reads(u.access)) {
            for m in u.mips.levels(graph.images[u.image].desc.mip_levels) {
                image_needed[u.image][m as usize] = true;
            }
        }
        for u in pass.buffers.iter().filter(|u| reads(u.access)) {
            buffer_needed[u.buffer] = true;
        }
    }
    live
}

/// Step 4: usage flags from the live accesses.
fn usage_flags(
    graph: &Graph<'_>,
    order: &[usize],
) -> (Vec<vk::ImageUsageFlags>, Vec<vk::BufferUsageFlags>) {
    let mut image_usage = vec![vk::ImageUsageFlags::empty(); graph.images.len()];
    let mut buffer_usage = vec![vk::BufferUsageFlags::empty(); graph.buffers.len()];
    for &p in order {
        for u in &graph.passes[p].images {
            image_usage[u.image] |= u.access.image_usage();
        }
        for u in &graph.passes[p].buffers {
            buffer_usage[u.buffer] |= u.access.buffer_usage();
        }
    }
    (image_usage, buffer_usage)
}

/// The state of every subresource while steps 5 to 7 walk the live passes.
struct States {
    images: Vec<Vec<SubState>>,
    buffers: Vec<SubState>,
}

impl States {
    fn initial(graph: &Graph<'_>) -> Self {
        States {
            images: graph
                .images
                .iter()
                .map(|img| {
                    let initial = match &img.origin {
                        ImageOrigin::Transient => Access::Nothing,
                        ImageOrigin::Imported { initial, .. } => *initial,
                    };
                    vec![SubState::from_access(initial); img.desc.mip_levels as usize]
                })
                .collect(),
            buffers: graph
                .buffers
                .iter()
                .map(|b| SubState::from_access(b.initial()))
                .collect(),
        }
    }

    /// Steps 5 and 6: the barriers before pass `p`, adjacent mips merged.
    fn before_pass(&mut self, graph: &Graph<'_>, p: usize) -> Result<PassBarriers> {
        let pass = &graph.passes[p];
        let mut barriers = PassBarriers::default();
        for u in &pass.images {
            let levels = u.mips.levels(graph.images[u.image].desc.mip_levels);
            let mut deps: Vec<(u32, Option<Dep>)> = Vec::with_capacity(levels.len());
            for m in levels {
                let state = &mut self.images[u.image][m as usize];
                if reads(u.access) && !state.written {
                    return Err(Error::Other(format!(
                        "pass `{}` reads mip {m} of `{}` before any pass wrote it",
                        pass.name, graph.images[u.image].name
                    )));
                }
                deps.push((m, transition(state, u.access, true)));
            }
            merge_levels(u.image, &deps, &mut barriers.images);
        }
        for u in &pass.buffers {
            let state = &mut self.buffers[u.buffer];
            if reads(u.access) && !state.written {
                return Err(Error::Other(format!(
                    "pass `{}` reads buffer `{}` before any pass wrote it",
                    pass.name, graph.buffers[u.buffer].name
                )));
            }
            if let Some(d) = transition(state, u.access, false) {
                barriers.buffers.push(buffer_barrier(u.buffer, d));
            }
        }
        Ok(barriers)
    }

    /// Step 7: the barriers that leave imports in their final state.
    fn leave_imports(&mut self, graph: &Graph<'_>) -> PassBarriers {
        let mut after = PassBarriers::default();
        for (id, img) in graph.images.iter().enumerate() {
            if let ImageOrigin::Imported {
                final_access: Some(fin),
                ..
            } = img.origin
            {
                let deps: Vec<(u32, Option<Dep>)> = (0..img.desc.mip_levels)
                    .map(|m| (m, transition(&mut self.images[id][m as usize], fin, true)))
                    .collect();
                merge_levels(id, &deps, &mut after.images);
            }
        }
        for (id, b) in graph.buffers.iter().enumerate() {
            if let Some(fin) = b.final_access()
                && let Some(d) = transition(&mut self.buffers[id], fin, false)
            {
                after.buffers.push(buffer_barrier(id, d));
            }
        }
        after
    }
}

fn buffer_barrier(buffer: usize, d: Dep) -> BufferBarrier {
    BufferBarrier {
        buffer,
        src_stage: d.src_stage,
        src_access: d.src_access,
        dst_stage: d.dst_stage,
        dst_access: d.dst_access,
    }
}

fn merge_levels(image: usize, deps: &[(u32, Option<Dep>)], out: &mut Vec<ImageBarrier>) {
    let mut current: Option<ImageBarrier> = None;
    for &(m, dep) in deps {
        let Some(d) = dep else {
            out.extend(current.take());
            continue;
        };
        let b = ImageBarrier {
            image,
            base_mip: m,
            mip_count: 1,
            src_stage: d.src_stage,
            src_access: d.src_access,
            dst_stage: d.dst_stage,
            dst_access: d.dst_access,
            old_layout: d.old_layout,
            new_layout: d.new_layout,
        };
        match current.as_mut() {
            Some(c)
                if c.base_mip + c.mip_count == m
                    && ImageBarrier {
                        base_mip: c.base_mip,
                        mip_count: c.mip_count,
                        ..b
                    } == *c =>
            {
                c.mip_count += 1;
            }
            _ => {
                out.extend(current.take());
                current = Some(b);
            }
        }
    }
    out.extend(current);
}
