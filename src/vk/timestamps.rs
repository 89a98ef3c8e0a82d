//! Timestamp queries: a begin/end pair per pass, read after the frame's fence.

use std::sync::Arc;

use ash::vk;

use super::Gpu;
use crate::Result;
use crate::error::VkContext;

/// A query pool of `capacity` timestamps.
pub struct TimestampPool {
    gpu: Arc<Gpu>,
    pub pool: vk::QueryPool,
    pub capacity: u32,
}

impl TimestampPool {
    /// Creates the pool; `None` when the queue has no timestamp support.
    pub fn new(gpu: &Arc<Gpu>, capacity: u32) -> Result<Option<Self>> {
        if gpu.info.timestamp_valid_bits == 0 {
            return Ok(None);
        }
        let info = vk::QueryPoolCreateInfo::default()
            .query_type(vk::QueryType::TIMESTAMP)
            .query_count(capacity);
        // SAFETY: valid device.
        let pool = unsafe { gpu.device.create_query_pool(&info, None) }
            .ctx(|| "creating the timestamp query pool".into())?;
        Ok(Some(TimestampPool {
            gpu: gpu.clone(),
            pool,
            capacity,
        }))
    }

    /// Resets the first `count` queries (recorded at the start of a frame).
    pub fn cmd_reset(&self, cmd: vk::CommandBuffer, count: u32) {
        // SAFETY: cmd is recording, outside any render pass.
        unsafe {
            self.gpu
                .device
                .cmd_reset_query_pool(cmd, self.pool, 0, count.min(self.capacity))
        };
    }

    /// Which of the first `count` timestamps the GPU has written so far, for
    /// naming the pass a failed frame was in; None on a CPU driver, where
    /// lavapipe answers only once the queue is idle (measured: the call took
    /// the rest of the frame), so asking could hang on a hung frame and
    /// would only ever say that every pass ended.
    pub fn written_early(&self, count: u32) -> Result<Option<Vec<bool>>> {
        if self.gpu.info.kind == vk::PhysicalDeviceType::CPU {
            return Ok(None);
        }
        self.written(count).map(Some)
    }

    /// Which of the first `count` timestamps the GPU has written so far (no
    /// wait is asked for).
    fn written(&self, count: u32) -> Result<Vec<bool>> {
        let mut words = vec![[0u64; 2]; count.min(self.capacity) as usize];
        if words.is_empty() {
            return Ok(Vec::new());
        }
        // SAFETY: the pool holds `count` queries; no wait is asked for.
        let r = unsafe {
            self.gpu.device.get_query_pool_results(
                self.pool,
                0,
                &mut words,
                vk::QueryResultFlags::TYPE_64 | vk::QueryResultFlags::WITH_AVAILABILITY,
            )
        };
        match r {
            Ok(()) | Err(vk::Result::NOT_READY) => Ok(words.iter().map(|w| w[1] != 0).collect()),
            Err(e) => Err(e).ctx(|| "reading GPU timestamps".into()),
        }
    }

    /// Reads `count` timestamps (after the fence) as nanoseconds since the first.
    pub fn read_ns(&self, count: u32) -> Result<Vec<f64>> {
        if count == 0 {
            return Ok(Vec::new());
        }
        let mut ticks = vec![0u64; count as usize];
        // SAFETY: the queries were written by a finished submission.
        unsafe {
            self.gpu.device.get_query_pool_results(
                self.pool,
                0,
                &mut ticks,
                vk::QueryResultFlags::TYPE_64 | vk::QueryResultFlags::WAIT,
            )
        }
        .ctx(|| "reading GPU timestamps".into())?;
        let bits = self.gpu.info.timestamp_valid_bits;
        let mask = if bits >= 64 {
            u64::MAX
        } else {
            (1u64 << bits) - 1
        };
        let period = f64::from(self.gpu.info.timestamp_period);
        let first = ticks[0] & mask;
        Ok(ticks
            .iter()
            .map(|&t| ((t & mask).wrapping_sub(first) & mask) as f64 * period)
            .collect())
    }
}

impl Drop for TimestampPool {
    fn drop(&mut self) {
        // SAFETY: dropped after the frames that wrote it finished.
        unsafe { self.gpu.device.destroy_query_pool(self.pool, None) };
    }
}
