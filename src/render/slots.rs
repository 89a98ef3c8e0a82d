//! Frame slots: everything one frame in flight needs of its own, so the CPU
//! can record frame N + 1 while the GPU still runs frame N. A slot is reused
//! only after its fence has signalled, and only then are its transient images
//! and buffers, parameter buffer, timestamps and readback touched again.

use std::sync::Arc;
use std::time::Instant;

use ash::vk;
use gpu_allocator::MemoryLocation;

use crate::frame::{CpuPhases, FrameTimings, PassTiming};
use crate::graph::{self, Graph, TransientPool};
use crate::passes::raymarch::RaymarchParams;
use crate::vk::{Access, Buffer, CommandContext, Gpu, TimestampPool};
use crate::{Error, Result};

/// Frames in flight in the window.
pub const FRAMES_IN_FLIGHT: usize = 2;

/// Most passes a frame can time.
const MAX_TIMED_PASSES: u32 = 64;

/// One frame in flight's own resources.
/// The states a submitted frame leaves its imported images in, as the graph
/// reports them ([`crate::graph::Compiled::images_left`]): what an image
/// kept across frames is imported in next time.
#[derive(Clone, Debug, Default)]
pub struct ImportsLeft(Vec<(String, Access)>);

impl ImportsLeft {
    /// The state the import named `name` is left in.
    pub fn of(&self, name: &str) -> Option<Access> {
        self.0.iter().find(|(n, _)| n == name).map(|(_, a)| *a)
    }
}

pub struct FrameSlot {
    /// Graph-owned images and buffers of this slot's frames; never shared
    /// with the other slot, so one slot cannot overwrite what the other's
    /// frame still reads.
    pub transients: TransientPool,
    /// The host-written ray-march parameters of this slot's frame.
    pub params: Buffer,
    /// Where offscreen frames are copied for the host (grown on demand).
    pub readback: Option<Buffer>,
    pub timestamps: Option<TimestampPool>,
    /// Names of the passes the last submission timed (read after the fence).
    timed: Vec<String>,
    /// Whether a submission is in flight whose timings are not read yet.
    pending: bool,
    /// CPU phases of the last submission (compile, record, submit, wait).
    cpu: CpuPhases,
    /// When the last submission went to the queue.
    submitted: Option<Instant>,
    wall_ms: f64,
    pub commands: CommandContext,
}

impl FrameSlot {
    /// Creates slot `index`'s command buffer, fence, parameter buffer and
    /// timestamp pool (transients and readback come on first use).
    pub fn new(gpu: &Arc<Gpu>, index: usize) -> Result<Self> {
        Ok(FrameSlot {
            transients: TransientPool::new(gpu),
            params: Buffer::new(
                gpu,
                &format!("raymarch params (slot {index})"),
                std::mem::size_of::<RaymarchParams>() as u64,
                vk::BufferUsageFlags::STORAGE_BUFFER,
                MemoryLocation::CpuToGpu,
            )?,
            readback: None,
            timestamps: TimestampPool::new(gpu, 2 * MAX_TIMED_PASSES)?,
            timed: Vec::new(),
            pending: false,
            cpu: CpuPhases::default(),
            submitted: None,
            wall_ms: 0.0,
            commands: CommandContext::new(gpu)?,
        })
    }

    /// Waits for this slot's last frame and returns its GPU timings (None if
    /// nothing was submitted since the last call). After this the slot's
    /// resources are free to reuse.
    pub fn wait(&mut self) -> Result<Option<FrameTimings>> {
        let t = Instant::now();
        if self.pending
            && let Some(result) = crate::vk::fault::wait_fault(self.commands.fault())
        {
            // Injected (tests): fail while the frame is still running.
            let e = Error::Vulkan {
                what: "BLACKHOLE_FAULT".into(),
                result,
            };
            return Err(self.failed_in(e));
        }
        if let Err(e) = self.commands.wait() {
            return Err(self.failed_in(e));
        }
        self.cpu.wait_ms = ms_since(t);
        if let Some(s) = self.submitted.take() {
            self.wall_ms = ms_since(s);
        }
        if !self.pending {
            return Ok(None);
        }
        self.pending = false;
        let mut timings = self.read_timings()?;
        timings.cpu = self.cpu;
        timings.wall_ms = self.wall_ms;
        Ok(Some(timings))
    }

    /// Makes sure the readback buffer holds at least `needed` bytes (the slot
    /// must be idle).
    pub fn ensure_readback(&mut self, gpu: &Arc<Gpu>, needed: u64) -> Result<&Buffer> {
        if self.readback.as_ref().is_none_or(|b| b.size < needed) {
            self.readback = None;
            self.readback = Some(Buffer::new(
                gpu,
                "readback",
                needed,
                vk::BufferUsageFlags::TRANSFER_DST,
                MemoryLocation::GpuToCpu,
            )?);
        }
        self.readback
            .as_ref()
            .ok_or_else(|| Error::Other("readback buffer missing".into()))
    }

    /// Compiles `g`, records it into this slot's command buffer (waiting for
    /// the slot's previous frame first) and submits it with the given
    /// semaphores. Does not wait for it.
    pub fn submit(
        &mut self,
        gpu: &Gpu,
        g: Graph<'_>,
        waits: &[(vk::Semaphore, vk::PipelineStageFlags2)],
        signals: &[vk::Semaphore],
    ) -> Result<ImportsLeft> {
        let t = Instant::now();
        let compiled = g.compile()?;
        self.cpu.compile_ms = ms_since(t);
        let left = ImportsLeft(
            g.images
                .iter()
                .zip(&compiled.images_left)
                .filter(|(i, _)| matches!(i.origin, graph::ImageOrigin::Imported { .. }))
                .filter_map(|(i, left)| Some((i.name.clone(), (*left)?)))
                .collect(),
        );
        let t = Instant::now();
        let cmd = self.commands.begin()?;
        self.timed = graph::execute::execute(
            g,
            &compiled,
            gpu,
            cmd,
            &mut self.transients,
            self.timestamps.as_ref(),
        )?;
        self.cpu.record_ms = ms_since(t);
        let t = Instant::now();
        self.commands.submit(waits, signals)?;
        self.cpu.submit_ms = ms_since(t);
        self.submitted = Some(Instant::now());
        self.pending = true;
        Ok(left)
    }

    /// `e` (a fence that timed out, a lost device, no memory) with the pass
    /// the frame was in: the first timed pass whose end the GPU had not
    /// written.
    fn failed_in(&self, e: Error) -> Error {
        let Error::Vulkan { result, .. } = e else {
            return e;
        };
        let why = match result {
            vk::Result::TIMEOUT => format!(
                "the GPU did not finish the frame within {} s (BLACKHOLE_GPU_TIMEOUT_S)",
                self.commands.timeout().as_secs_f64()
            ),
            vk::Result::ERROR_DEVICE_LOST => {
                "the GPU device was lost (it stays lost: start again with a new renderer)"
                    .to_string()
            }
            vk::Result::ERROR_OUT_OF_DEVICE_MEMORY | vk::Result::ERROR_OUT_OF_HOST_MEMORY => {
                "the GPU ran out of memory".to_string()
            }
            other => format!("the frame failed ({other})"),
        };
        let count = graph::execute::timestamp_count(self.timed.len());
        let done = self
            .timestamps
            .as_ref()
            .and_then(|ts| ts.written_early(count).ok().flatten());
        let running = done.and_then(|d| running_pass(&self.timed, &d));
        let what = match running {
            Some(pass) => format!("{why}, in pass `{pass}`"),
            None => why,
        };
        Error::Vulkan { what, result }
    }

    fn read_timings(&self) -> Result<FrameTimings> {
        let Some(ts) = &self.timestamps else {
            return Ok(FrameTimings::default());
        };
        let count = graph::execute::timestamp_count(self.timed.len());
        if count > ts.capacity {
            return Ok(FrameTimings::default());
        }
        let ns = ts.read_ns(count)?;
        let passes = self
            .timed
            .iter()
            .enumerate()
            .map(|(i, n)| PassTiming {
                name: n.clone(),
                ms: (ns[2 * i + 1] - ns[2 * i]) * 1e-6,
                start_ms: ns[2 * i] * 1e-6,
            })
            .collect();
        let frame_ms = ns.last().copied().unwrap_or(0.0) * 1e-6;
        Ok(FrameTimings {
            passes,
            frame_ms,
            ..FrameTimings::default()
        })
    }
}

impl Drop for FrameSlot {
    fn drop(&mut self) {
        // The readback, timestamps and transients go first (field order):
        // the GPU must be done with them.
        self.commands.settle();
    }
}

/// Milliseconds since `t`.
pub fn ms_since(t: Instant) -> f64 {
    t.elapsed().as_secs_f64() * 1e3
}

/// The pass a failed frame was in: the first of `timed` (the frame's timed
/// passes in order) whose end timestamp `done` (availability of each pass's
/// begin and end query) does not show as written. None when every pass ended
/// (the failure came after them) or when `done` does not cover the passes.
fn running_pass<'a>(timed: &'a [String], done: &[bool]) -> Option<&'a str> {
    if done.len() < 2 * timed.len() {
        return None;
    }
    timed
        .iter()
        .enumerate()
        .find(|(i, _)| !done[2 * i + 1])
        .map(|(_, n)| n.as_str())
}

#[cfg(test)]
mod tests {
    use super::running_pass;

    #[test]
    fn the_failed_pass_is_the_first_whose_end_was_not_written() {
        let timed: Vec<String> = ["raymarch", "bloom", "composite"]
            .iter()
            .map(|s| s.to_string())
            .collect();
        // raymarch ended, bloom began but did not end.
        let done = [true, true, true, false, false, false];
        assert_eq!(running_pass(&timed, &done), Some("bloom"));
        assert_eq!(running_pass(&timed, &[false; 6]), Some("raymarch"));
        assert_eq!(running_pass(&timed, &[true; 6]), None);
        // Nothing known: no pass is named rather than a wrong one.
        assert_eq!(running_pass(&timed, &[]), None);
    }
}
