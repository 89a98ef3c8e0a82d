//! Memory: every resource gets a named allocation from gpu-allocator (so a leak
//! report names it), freed by its owner's `Drop`.

use ash::vk;
use gpu_allocator::MemoryLocation;
use gpu_allocator::vulkan::{Allocation, AllocationCreateDesc, AllocationScheme};

use super::Gpu;
use crate::{Error, Result};

/// Allocates memory for a resource named `name`.
pub fn allocate(
    gpu: &Gpu,
    name: &str,
    requirements: vk::MemoryRequirements,
    location: MemoryLocation,
    linear: bool,
) -> Result<Allocation> {
    if super::fault::alloc_fault(gpu.settings.fault.as_ref(), name) {
        return Err(Error::Allocation {
            what: format!("allocating memory for `{name}` (BLACKHOLE_FAULT)"),
            source: gpu_allocator::AllocationError::OutOfMemory,
        });
    }
    gpu.allocator()
        .allocate(&AllocationCreateDesc {
            name,
            requirements,
            location,
            linear,
            allocation_scheme: AllocationScheme::GpuAllocatorManaged,
        })
        .map_err(|source| Error::Allocation {
            what: format!("allocating memory for `{name}`"),
            source,
        })
}

/// Returns an allocation to the allocator (errors only mean a double free,
/// which ownership rules out; they are logged).
pub fn free(gpu: &Gpu, allocation: Allocation) {
    if let Err(e) = gpu.allocator().free(allocation) {
        log::warn!("freeing GPU memory: {e}");
    }
}
