//! Thin ash wrappers, one Vulkan concept per file. Each object has one owner
//! that destroys it in `Drop`; see [`device`] for the teardown order.

pub mod buffer;
pub mod commands;
pub mod descriptors;
pub mod device;
pub mod fault;
pub mod image;
pub mod instance;
pub mod memory;
pub mod pipeline;
pub mod swapchain;
pub mod sync;
pub mod timestamps;

pub use buffer::{Buffer, BufferBinding};
pub use commands::CommandContext;
pub use descriptors::{Descriptor, bind_compute, push_constants};
pub use device::{DEFAULT_GPU_TIMEOUT_S, DeviceInfo, Gpu, GpuSettings, PresentCheck};
pub use image::{Image, ImageBinding, ImageDesc, Sampler};
pub use instance::{Instance, Validation};
pub use pipeline::{BindingKind, ComputePipeline};
pub use swapchain::{PresentMode, Swapchain};
pub use sync::{Access, AccessInfo};
pub use timestamps::TimestampPool;
