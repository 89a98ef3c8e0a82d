//! One command pool, one command buffer and its fence. A frame slot owns one:
//! it records a frame, submits it (optionally waiting on and signalling
//! semaphores, for a swapchain), and waits on the fence before reusing it.

use std::sync::Arc;

use ash::vk;

use super::Gpu;
use crate::Result;
use crate::error::VkContext;

/// A resettable command buffer with the fence that tells when it is done.
pub struct CommandContext {
    gpu: Arc<Gpu>,
    pool: vk::CommandPool,
    pub cmd: vk::CommandBuffer,
    fence: vk::Fence,
}

impl CommandContext {
    /// Creates the pool, buffer and (signalled) fence.
    pub fn new(gpu: &Arc<Gpu>) -> Result<Self> {
        let d = &gpu.device;
        let mut this = CommandContext {
            gpu: gpu.clone(),
            pool: vk::CommandPool::null(),
            cmd: vk::CommandBuffer::null(),
            fence: vk::Fence::null(),
        };
        // SAFETY: valid device; `this` owns each handle as soon as it exists.
        unsafe {
            this.pool = d
                .create_command_pool(
                    &vk::CommandPoolCreateInfo::default()
                        .queue_family_index(gpu.queue_family)
                        .flags(vk::CommandPoolCreateFlags::RESET_COMMAND_BUFFER),
                    None,
                )
                .ctx(|| "creating the command pool".into())?;
            this.cmd = d
                .allocate_command_buffers(
                    &vk::CommandBufferAllocateInfo::default()
                        .command_pool(this.pool)
                        .level(vk::CommandBufferLevel::PRIMARY)
                        .command_buffer_count(1),
                )
                .ctx(|| "allocating the command buffer".into())?
                .into_iter()
                .next()
                .unwrap_or_default();
            this.fence = d
                .create_fence(
                    &vk::FenceCreateInfo::default().flags(vk::FenceCreateFlags::SIGNALED),
                    None,
                )
                .ctx(|| "creating the frame fence".into())?;
        }
        Ok(this)
    }

    /// Waits for the previous submission, then begins recording.
    pub fn begin(&mut self) -> Result<vk::CommandBuffer> {
        let d = &self.gpu.device;
        // SAFETY: the fence and buffer belong to this context.
        unsafe {
            d.wait_for_fences(&[self.fence], true, u64::MAX)
                .ctx(|| "waiting for the previous frame".into())?;
            d.reset_command_buffer(self.cmd, vk::CommandBufferResetFlags::empty())
                .ctx(|| "resetting the command buffer".into())?;
            d.begin_command_buffer(
                self.cmd,
                &vk::CommandBufferBeginInfo::default()
                    .flags(vk::CommandBufferUsageFlags::ONE_TIME_SUBMIT),
            )
            .ctx(|| "beginning the command buffer".into())?;
        }
        Ok(self.cmd)
    }

    /// Ends recording and submits; `waits` are (semaphore, stages that wait
    /// on it), `signals` are signalled once every command has finished.
    pub fn submit(
        &mut self,
        waits: &[(vk::Semaphore, vk::PipelineStageFlags2)],
        signals: &[vk::Semaphore],
    ) -> Result<()> {
        let d = &self.gpu.device;
        // SAFETY: the buffer is recording; the fence is ours.
        unsafe {
            d.end_command_buffer(self.cmd)
                .ctx(|| "ending the command buffer".into())?;
            d.reset_fences(&[self.fence])
                .ctx(|| "resetting the frame fence".into())?;
        }
        let wait_infos: Vec<vk::SemaphoreSubmitInfo<'_>> = waits
            .iter()
            .map(|&(s, stage)| {
                vk::SemaphoreSubmitInfo::default()
                    .semaphore(s)
                    .stage_mask(stage)
            })
            .collect();
        let signal_infos: Vec<vk::SemaphoreSubmitInfo<'_>> = signals
            .iter()
            .map(|&s| {
                vk::SemaphoreSubmitInfo::default()
                    .semaphore(s)
                    .stage_mask(vk::PipelineStageFlags2::ALL_COMMANDS)
            })
            .collect();
        let cmd_infos = [vk::CommandBufferSubmitInfo::default().command_buffer(self.cmd)];
        let submit = [vk::SubmitInfo2::default()
            .wait_semaphore_infos(&wait_infos)
            .command_buffer_infos(&cmd_infos)
            .signal_semaphore_infos(&signal_infos)];
        self.gpu.queue_submit2(&submit, self.fence)
    }

    /// Waits until the last submission has finished, at most
    /// the device's `gpu_timeout` ([`super::GpuSettings`]): a frame that takes longer (a hung GPU) is an error
    /// (`vk::Result::TIMEOUT`), not a hang; so are a lost device and a
    /// device out of memory, which the fence reports.
    pub fn wait(&self) -> Result<()> {
        let timeout = self.gpu.settings.gpu_timeout;
        // SAFETY: the fence is ours.
        let r = unsafe {
            self.gpu
                .device
                .wait_for_fences(&[self.fence], true, timeout.as_nanos() as u64)
        };
        match r {
            Ok(()) => Ok(()),
            Err(vk::Result::TIMEOUT) => Err(crate::Error::Vulkan {
                what: format!(
                    "the GPU did not finish within {} s (BLACKHOLE_GPU_TIMEOUT_S)",
                    timeout.as_secs_f64()
                ),
                result: vk::Result::TIMEOUT,
            }),
            Err(result) => Err(crate::Error::Vulkan {
                what: "waiting for the GPU to finish".into(),
                result,
            }),
        }
    }

    /// Before the caller frees what the last submission used: waits for it,
    /// at most [`super::GpuSettings::drop_timeout`], ignoring failures (the frame's own error was
    /// reported already).
    pub fn settle(&self) {
        // SAFETY: the fence is ours.
        let _ = unsafe {
            self.gpu.device.wait_for_fences(
                &[self.fence],
                true,
                self.gpu.settings.drop_timeout().as_nanos() as u64,
            )
        };
    }

    /// The failure injected for the tests, if any.
    pub fn fault(&self) -> Option<&super::fault::Fault> {
        self.gpu.settings.fault.as_ref()
    }

    /// The longest [`Self::wait`] waits.
    pub fn timeout(&self) -> std::time::Duration {
        self.gpu.settings.gpu_timeout
    }

    /// Ends recording, submits, and waits for the GPU to finish.
    /// On a failed wait it still lets the GPU settle (see [`Self::settle`]),
    /// so the caller may free what the submission used.
    pub fn submit_and_wait(&mut self) -> Result<()> {
        self.submit(&[], &[])?;
        self.wait().inspect_err(|_| self.settle())
    }
}

impl Drop for CommandContext {
    fn drop(&mut self) {
        // SAFETY: wait so nothing in flight references the buffer, then destroy.
        unsafe {
            let d = &self.gpu.device;
            if self.fence != vk::Fence::null() {
                let _ = d.wait_for_fences(
                    &[self.fence],
                    true,
                    self.gpu.settings.drop_timeout().as_nanos() as u64,
                );
                d.destroy_fence(self.fence, None);
            }
            if self.pool != vk::CommandPool::null() {
                d.destroy_command_pool(self.pool, None);
            }
        }
    }
}
