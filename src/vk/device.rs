//! Physical device choice, the logical device, its queue and the allocator.
//!
//! Teardown order, written down once: every resource (image, buffer, pipeline,
//! pool) holds an `Arc<Gpu>`, so they are all destroyed first; then `Gpu`'s
//! `Drop` waits for the device to be idle, drops the allocator (which reports
//! leaks) and destroys the device; then its `Instance` field destroys the debug
//! messenger and the instance.

use std::ffi::CStr;
use std::mem::ManuallyDrop;
use std::sync::{Arc, Mutex, MutexGuard};
use std::time::Duration;

use ash::{ext, khr, vk};
use gpu_allocator::vulkan::{Allocator, AllocatorCreateDesc};

use super::fault::Fault;
use super::instance::{Instance, Validation};
use crate::error::VkContext;
use crate::{Error, Result};

/// Facts about the chosen device that the renderer needs.
#[derive(Clone, Debug)]
pub struct DeviceInfo {
    pub name: String,
    pub kind: vk::PhysicalDeviceType,
    pub api_version: u32,
    /// Nanoseconds per timestamp tick.
    pub timestamp_period: f32,
    /// Valid bits of timestamps on the compute queue (0: no timestamps).
    pub timestamp_valid_bits: u32,
    pub max_push_constants: u32,
    /// Subgroup quad operations in compute shaders (the ray march's ray
    /// differentials need them).
    pub quad_compute: bool,
    /// Subgroup ballot operations in compute shaders (the split ray march
    /// lists the disk's pixels with them).
    pub ballot_compute: bool,
    /// 64-bit floats in shaders (shaderFloat64; enabled when present): the
    /// spinning hole's light paths need them.
    pub float64: bool,
}

/// The logical device and everything created with it once.
pub struct Gpu {
    pub device: ash::Device,
    pub physical: vk::PhysicalDevice,
    pub queue: vk::Queue,
    pub queue_family: u32,
    pub info: DeviceInfo,
    pub push_descriptor: khr::push_descriptor::Device,
    /// Labels and object names, when VK_EXT_debug_utils is there.
    pub debug_utils: Option<ext::debug_utils::Device>,
    /// VK_KHR_synchronization2 entry points on a 1.2 device; None on 1.3.
    sync2_khr: Option<khr::synchronization2::Device>,
    /// Shared with the GUI renderer, which allocates its own buffers; both
    /// are gone before the device (see the teardown order above).
    allocator: ManuallyDrop<Arc<Mutex<Allocator>>>,
    /// Whether the queue can present and the swapchain extension is on.
    pub presents: bool,
    /// What the caller asked of it (timeouts, injected faults).
    pub settings: GpuSettings,
    pub instance: Instance,
}

fn device_type_rank(t: vk::PhysicalDeviceType) -> u32 {
    match t {
        vk::PhysicalDeviceType::DISCRETE_GPU => 4,
        vk::PhysicalDeviceType::INTEGRATED_GPU => 3,
        vk::PhysicalDeviceType::VIRTUAL_GPU => 2,
        vk::PhysicalDeviceType::CPU => 1,
        _ => 0,
    }
}

struct Candidate {
    physical: vk::PhysicalDevice,
    name: String,
    kind: vk::PhysicalDeviceType,
    api_version: u32,
    queue_family: u32,
    timestamp_valid_bits: u32,
    props: vk::PhysicalDeviceProperties,
    quad_compute: bool,
    ballot_compute: bool,
    float64: bool,
    /// Why it cannot be used, if it cannot.
    unusable: Option<String>,
}

/// Asks whether queue `family` of a device can present to the window's surface.
pub type PresentCheck<'a> = &'a dyn Fn(&Instance, vk::PhysicalDevice, u32) -> bool;

/// The wait limit for one submission unless the caller sets another: a 4K
/// volumetric frame on a CPU driver takes seconds, not minutes.
pub const DEFAULT_GPU_TIMEOUT_S: f64 = 600.0;

/// What the caller asks of the device from outside Vulkan (the program's
/// `BLACKHOLE_*` settings, [`crate::settings`], build it): vk/ reads no
/// environment and no global of its own.
#[derive(Clone, Debug, PartialEq)]
pub struct GpuSettings {
    /// Part of the name of the device to use (`BLACKHOLE_DEVICE`).
    pub device: Option<String>,
    /// The longest wait for one submission (`BLACKHOLE_GPU_TIMEOUT_S`).
    pub gpu_timeout: Duration,
    /// A failure injected for the tests (`BLACKHOLE_FAULT`).
    pub fault: Option<Fault>,
}

impl Default for GpuSettings {
    fn default() -> Self {
        GpuSettings {
            device: None,
            gpu_timeout: Duration::from_secs_f64(DEFAULT_GPU_TIMEOUT_S),
            fault: None,
        }
    }
}

impl GpuSettings {
    /// Longest wait before resources are freed: `gpu_timeout`, but at least
    /// ten seconds (a frame that timed out may still finish).
    pub fn drop_timeout(&self) -> Duration {
        self.gpu_timeout.max(Duration::from_secs(10))
    }
}

impl Gpu {
    /// Creates the instance and picks a device: discrete > integrated > virtual >
    /// CPU, or the first whose name contains `settings.device`.
    pub fn new(validation: Validation, settings: GpuSettings) -> Result<Arc<Self>> {
        Self::open(Instance::new(validation)?, None, settings)
    }

    /// Picks a device on `instance`. With `present`, the queue must also do
    /// graphics (blits, the GUI) and present to the surface `present` asks
    /// about, and the swapchain and dynamic rendering are enabled.
    /// The device to use: the first of the usable devices (the one
    /// `BLACKHOLE_DEVICE` names, if set) by kind, discrete first; why none
    /// is, if none is.
    fn choose(
        instance: &Instance,
        present: Option<PresentCheck<'_>>,
        wanted: Option<&str>,
    ) -> Result<Candidate> {
        let inst = &instance.instance;

        // SAFETY: valid instance.
        let physicals = match unsafe { inst.enumerate_physical_devices() } {
            Ok(p) => p,
            Err(vk::Result::ERROR_INITIALIZATION_FAILED) => Vec::new(),
            Err(result) => {
                return Err(super::instance::loader_failure("listing devices", result));
            }
        };
        if physicals.is_empty() {
            return Err(Error::NoDevice(String::new()));
        }
        let mut candidates: Vec<Candidate> = physicals
            .iter()
            .map(|&pd| Self::describe(instance, pd, present))
            .collect::<Result<_>>()?;

        let names: Vec<String> = candidates.iter().map(|c| c.name.clone()).collect();
        if let Some(w) = wanted {
            let lw = w.to_lowercase();
            candidates.retain(|c| c.name.to_lowercase().contains(&lw));
            if candidates.is_empty() {
                return Err(Error::NoDevice(format!(
                    " whose name contains BLACKHOLE_DEVICE=`{w}` (available: {})",
                    names.join(", ")
                )));
            }
        }
        let reasons: Vec<String> = candidates
            .iter()
            .filter_map(|c| c.unusable.as_ref().map(|r| format!("{}: {r}", c.name)))
            .collect();
        candidates.retain(|c| c.unusable.is_none());
        candidates.sort_by_key(|c| std::cmp::Reverse(device_type_rank(c.kind)));
        let Some(chosen) = candidates.into_iter().next() else {
            return Err(Error::NoDevice(format!(
                " that can run the renderer ({})",
                reasons.join("; ")
            )));
        };
        log::info!(
            "Vulkan device: {} ({:?}, API {}.{}.{})",
            chosen.name,
            chosen.kind,
            vk::api_version_major(chosen.api_version),
            vk::api_version_minor(chosen.api_version),
            vk::api_version_patch(chosen.api_version)
        );

        Ok(chosen)
    }

    pub fn open(
        instance: Instance,
        present: Option<PresentCheck<'_>>,
        settings: GpuSettings,
    ) -> Result<Arc<Self>> {
        let chosen = Self::choose(&instance, present, settings.device.as_deref())?;
        let inst = &instance.instance;
        let is_13 = chosen.api_version >= vk::API_VERSION_1_3;
        let mut ext_names = vec![khr::push_descriptor::NAME.as_ptr()];
        if present.is_some() {
            ext_names.push(khr::swapchain::NAME.as_ptr());
        }
        if !is_13 {
            ext_names.push(khr::synchronization2::NAME.as_ptr());
        }
        let priorities = [1.0f32];
        let queue_info = [vk::DeviceQueueCreateInfo::default()
            .queue_family_index(chosen.queue_family)
            .queue_priorities(&priorities)];
        let mut f13 = vk::PhysicalDeviceVulkan13Features::default()
            .synchronization2(true)
            .dynamic_rendering(present.is_some());
        let mut sync2 =
            vk::PhysicalDeviceSynchronization2Features::default().synchronization2(true);
        let core = vk::PhysicalDeviceFeatures::default().shader_float64(chosen.float64);
        let mut create = vk::DeviceCreateInfo::default()
            .queue_create_infos(&queue_info)
            .enabled_extension_names(&ext_names)
            .enabled_features(&core);
        create = if is_13 {
            create.push_next(&mut f13)
        } else {
            create.push_next(&mut sync2)
        };
        // SAFETY: the physical device came from this instance; the create
        // info's pointers outlive the call.
        let device = unsafe { inst.create_device(chosen.physical, &create, None) }
            .ctx(|| format!("creating the logical device on {}", chosen.name))?;
        // SAFETY: the family was created with one queue.
        let queue = unsafe { device.get_device_queue(chosen.queue_family, 0) };

        let allocator = Allocator::new(&AllocatorCreateDesc {
            instance: inst.clone(),
            device: device.clone(),
            physical_device: chosen.physical,
            debug_settings: Default::default(),
            buffer_device_address: false,
            allocation_sizes: gpu_allocator::AllocationSizes::new(32 << 20, 16 << 20),
        });
        let allocator = match allocator {
            Ok(a) => a,
            Err(source) => {
                // SAFETY: nothing was created on the device yet.
                unsafe { device.destroy_device(None) };
                return Err(Error::Allocation {
                    what: "creating the memory allocator".into(),
                    source,
                });
            }
        };

        let push_descriptor = khr::push_descriptor::Device::new(inst, &device);
        let debug_utils = instance
            .debug_utils
            .as_ref()
            .map(|_| ext::debug_utils::Device::new(inst, &device));
        let sync2_khr = (!is_13).then(|| khr::synchronization2::Device::new(inst, &device));

        Ok(Arc::new(Gpu {
            device,
            physical: chosen.physical,
            queue,
            queue_family: chosen.queue_family,
            info: DeviceInfo {
                name: chosen.name,
                kind: chosen.kind,
                api_version: chosen.api_version,
                timestamp_period: chosen.props.limits.timestamp_period,
                timestamp_valid_bits: chosen.timestamp_valid_bits,
                max_push_constants: chosen.props.limits.max_push_constants_size,
                quad_compute: chosen.quad_compute,
                ballot_compute: chosen.ballot_compute,
                float64: chosen.float64,
            },
            push_descriptor,
            debug_utils,
            sync2_khr,
            allocator: ManuallyDrop::new(Arc::new(Mutex::new(allocator))),
            presents: present.is_some(),
            settings,
            instance,
        }))
    }

    fn describe(
        instance: &Instance,
        pd: vk::PhysicalDevice,
        present: Option<PresentCheck<'_>>,
    ) -> Result<Candidate> {
        let inst = &instance.instance;
        // SAFETY: `pd` was enumerated from this instance.
        let props = unsafe { inst.get_physical_device_properties(pd) };
        let name = props
            .device_name_as_c_str()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_else(|_| "(unnamed device)".into());
        // SAFETY: as above.
        let families = unsafe { inst.get_physical_device_queue_family_properties(pd) };
        // SAFETY: as above.
        let exts = unsafe { inst.enumerate_device_extension_properties(pd) }
            .ctx(|| format!("listing extensions of {name}"))?;
        let has = |n: &CStr| {
            exts.iter()
                .any(|e| e.extension_name_as_c_str().is_ok_and(|x| x == n))
        };
        let queue = families
            .iter()
            .enumerate()
            .position(|(i, f)| match present {
                None => f.queue_flags.contains(vk::QueueFlags::COMPUTE),
                Some(can_present) => {
                    f.queue_flags
                        .contains(vk::QueueFlags::COMPUTE | vk::QueueFlags::GRAPHICS)
                        && can_present(instance, pd, i as u32)
                }
            });
        let api = props.api_version;
        let mut subgroup = vk::PhysicalDeviceSubgroupProperties::default();
        {
            let mut props2 = vk::PhysicalDeviceProperties2::default().push_next(&mut subgroup);
            // SAFETY: as above; Vulkan 1.1 core (devices below 1.2 are refused).
            unsafe { inst.get_physical_device_properties2(pd, &mut props2) };
        }
        // What the device can do; what the renderer makes of it is decided
        // in render::features.
        let compute_ops = |op| {
            api >= vk::API_VERSION_1_1
                && subgroup
                    .supported_stages
                    .contains(vk::ShaderStageFlags::COMPUTE)
                && subgroup.supported_operations.contains(op)
        };
        let quad_compute = compute_ops(vk::SubgroupFeatureFlags::QUAD);
        let ballot_compute = compute_ops(vk::SubgroupFeatureFlags::BALLOT);
        // SAFETY: as above.
        let float64 = unsafe { inst.get_physical_device_features(pd) }.shader_float64 == vk::TRUE;
        let unusable = if api < vk::API_VERSION_1_2 {
            Some("Vulkan 1.2 or newer is needed".to_string())
        } else if api < vk::API_VERSION_1_3 && !has(khr::synchronization2::NAME) {
            Some("VK_KHR_synchronization2 is missing".to_string())
        } else if !has(khr::push_descriptor::NAME) {
            Some("VK_KHR_push_descriptor is missing".to_string())
        } else if present.is_some() && api < vk::API_VERSION_1_3 {
            Some("the window needs Vulkan 1.3 (dynamic rendering)".to_string())
        } else if present.is_some() && !has(khr::swapchain::NAME) {
            Some("VK_KHR_swapchain is missing".to_string())
        } else if queue.is_none() && present.is_some() {
            Some("no queue that does graphics, compute and presents to the window".to_string())
        } else if queue.is_none() {
            Some("no compute queue".to_string())
        } else {
            None
        };
        let queue_family = queue.unwrap_or(0);
        Ok(Candidate {
            physical: pd,
            name,
            kind: props.device_type,
            api_version: api,
            queue_family: queue_family as u32,
            timestamp_valid_bits: families
                .get(queue_family)
                .map_or(0, |f| f.timestamp_valid_bits),
            props,
            quad_compute,
            ballot_compute,
            float64,
            unusable,
        })
    }

    /// Size of the device's largest device-local memory heap, bytes.
    pub fn largest_device_heap(&self) -> u64 {
        // SAFETY: the physical device belongs to the live instance.
        let mem = unsafe {
            self.instance
                .instance
                .get_physical_device_memory_properties(self.physical)
        };
        mem.memory_heaps[..mem.memory_heap_count as usize]
            .iter()
            .filter(|h| h.flags.contains(vk::MemoryHeapFlags::DEVICE_LOCAL))
            .map(|h| h.size)
            .max()
            .unwrap_or(0)
    }

    /// Largest width or height of a 2-D image on this device.
    pub fn max_image_dimension(&self) -> u32 {
        // SAFETY: the physical device belongs to the live instance.
        unsafe {
            self.instance
                .instance
                .get_physical_device_properties(self.physical)
        }
        .limits
        .max_image_dimension2_d
    }

    /// The allocator, locked. Poisoning only follows a panic elsewhere.
    pub fn allocator(&self) -> MutexGuard<'_, Allocator> {
        self.allocator.lock().unwrap_or_else(|p| p.into_inner())
    }

    /// The allocator itself, for a library that allocates on its own (the
    /// GUI renderer); it must be dropped before this `Gpu`.
    pub fn shared_allocator(&self) -> Arc<Mutex<Allocator>> {
        Arc::clone(&self.allocator)
    }

    /// Validation errors and warnings so far.
    pub fn validation_counts(&self) -> (u32, u32) {
        self.instance.validation_counts()
    }

    /// `vkCmdPipelineBarrier2` on 1.3, or its KHR alias on 1.2.
    pub fn cmd_pipeline_barrier2(&self, cmd: vk::CommandBuffer, dep: &vk::DependencyInfo<'_>) {
        // SAFETY: the caller records into a command buffer of this device.
        unsafe {
            match &self.sync2_khr {
                Some(k) => k.cmd_pipeline_barrier2(cmd, dep),
                None => self.device.cmd_pipeline_barrier2(cmd, dep),
            }
        }
    }

    /// `vkCmdWriteTimestamp2` (or the KHR alias).
    pub fn cmd_write_timestamp2(
        &self,
        cmd: vk::CommandBuffer,
        stage: vk::PipelineStageFlags2,
        pool: vk::QueryPool,
        query: u32,
    ) {
        // SAFETY: as above.
        unsafe {
            match &self.sync2_khr {
                Some(k) => k.cmd_write_timestamp2(cmd, stage, pool, query),
                None => self.device.cmd_write_timestamp2(cmd, stage, pool, query),
            }
        }
    }

    /// `vkQueueSubmit2` (or the KHR alias).
    pub fn queue_submit2(&self, submits: &[vk::SubmitInfo2<'_>], fence: vk::Fence) -> Result<()> {
        // SAFETY: the submit infos reference objects of this device.
        unsafe {
            match &self.sync2_khr {
                Some(k) => k.queue_submit2(self.queue, submits, fence),
                None => self.device.queue_submit2(self.queue, submits, fence),
            }
        }
        .ctx(|| "submitting the frame's commands".into())
    }

    /// Names a Vulkan object for validation messages and captures.
    pub fn set_name<H: vk::Handle>(&self, handle: H, name: &str) {
        if let Some(du) = &self.debug_utils {
            if let Ok(cname) = std::ffi::CString::new(name) {
                let info = vk::DebugUtilsObjectNameInfoEXT::default()
                    .object_handle(handle)
                    .object_name(&cname);
                // SAFETY: the handle belongs to this device. Naming is best-effort.
                let _ = unsafe { du.set_debug_utils_object_name(&info) };
            }
        }
    }

    /// Opens a debug label on a command buffer.
    pub fn begin_label(&self, cmd: vk::CommandBuffer, name: &str) {
        if let Some(du) = &self.debug_utils {
            if let Ok(cname) = std::ffi::CString::new(name) {
                let label = vk::DebugUtilsLabelEXT::default().label_name(&cname);
                // SAFETY: cmd is recording.
                unsafe { du.cmd_begin_debug_utils_label(cmd, &label) };
            }
        }
    }

    /// Closes the innermost debug label.
    pub fn end_label(&self, cmd: vk::CommandBuffer) {
        if let Some(du) = &self.debug_utils {
            // SAFETY: paired with begin_label on the same command buffer.
            unsafe { du.cmd_end_debug_utils_label(cmd) };
        }
    }
}

impl Drop for Gpu {
    fn drop(&mut self) {
        // SAFETY: every object made from the device holds an Arc<Gpu>, so none
        // is alive now. Allocator (leak report) before device before instance.
        unsafe {
            let _ = self.device.device_wait_idle();
            let allocator = ManuallyDrop::take(&mut self.allocator);
            if Arc::strong_count(&allocator) > 1 {
                log::warn!("the memory allocator is still shared at shutdown");
            }
            let leaks = allocator
                .lock()
                .map(|a| a.generate_report().allocations.len())
                .unwrap_or(0);
            if leaks > 0 {
                log::warn!("{leaks} GPU allocations were still alive at shutdown");
            }
            drop(allocator);
            self.device.destroy_device(None);
        }
    }
}
