//! What the renderer does on this device, decided once and only here: from
//! what the device reports ([`crate::vk::DeviceInfo`], capabilities only)
//! and the switches of [`RendererOptions`] (which the `BLACKHOLE_NO_QUAD` and
//! `BLACKHOLE_NO_SPLIT` settings set by default). The pipelines, the frame
//! recipe and the tests all ask this.

use ash::vk;

use super::RendererOptions;
use crate::passes::raymarch;
use crate::scene::Scene;
use crate::vk::DeviceInfo;

/// The renderer's choices for one device.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Features {
    /// The ray march runs its tiles as 2x2 subgroup quads and takes each
    /// pixel's lensed footprint on the sky from its neighbours (stars and
    /// image skies through it); without, the unlensed footprint.
    pub ray_differentials: bool,
    /// The thin disk's ray march may be split into a trace pass that lists
    /// the disk's pixels and an indirect disk pass over them: on a CPU
    /// device with quad and ballot operations, which runs every branch for
    /// every pixel (a GPU already skips the disk's code in the SIMD groups
    /// that miss it). Whether one frame is split: [`Features::splits`].
    pub disk_split: bool,
    /// The spinning hole's per-ray constants (the quartic's roots and the
    /// elliptic integrals' arguments) run in 64-bit floats, which the device
    /// has; without them the build with 32-bit roots, exact away from a thin
    /// band around the shadow's outline.
    pub kerr_f64: bool,
}

impl Features {
    /// The choices for a device with `info` under `options`.
    pub fn decide(info: &DeviceInfo, options: &RendererOptions) -> Self {
        let ray_differentials = info.quad_compute && options.ray_differentials;
        Features {
            ray_differentials,
            disk_split: ray_differentials
                && info.ballot_compute
                && info.kind == vk::PhysicalDeviceType::CPU
                && options.disk_split,
            kerr_f64: info.float64 && options.float64,
        }
    }

    /// Whether a frame of `scene` at `width` x `height` runs the split ray
    /// march: where the device can split and a coarse grid of closed-form
    /// rays puts little of the frame on the disk ([`raymarch::split_pays`]).
    pub fn splits(&self, scene: &Scene, width: u32, height: u32) -> bool {
        self.disk_split && raymarch::split_pays(scene, width, height)
    }
}
