//! What the renderer does on this device, decided once and only here: from
//! what the device reports ([`crate::vk::DeviceInfo`], capabilities only)
//! and the switches of [`RendererOptions`] (which the `BLACKHOLE_NO_QUAD`,
//! `BLACKHOLE_NO_SPLIT` and `BLACKHOLE_NO_F64` settings set by default).
//! The pipelines, the frame recipe and the tests all ask this.

use crate::deferred;
use crate::scene::Scene;
use crate::spacetime::Spacetime;
use crate::vk::{DeviceInfo, Validation};

/// Options for creating a [`crate::Renderer`]; the defaults come from the
/// environment ([`crate::settings`]).
#[derive(Clone, Copy, Debug)]
pub struct RendererOptions {
    pub validation: Validation,
    /// Use ray differentials where the device can (`BLACKHOLE_NO_QUAD=1`
    /// turns them off, for comparisons).
    pub ray_differentials: bool,
    /// Split the ray march into a trace pass and a deferred pass where the
    /// device and the frame gain by it ([`crate::deferred`];
    /// `BLACKHOLE_NO_SPLIT=1` keeps the one dispatch).
    pub split: bool,
    /// Compute a spinning hole's per-ray constants in 64-bit floats where
    /// the device has them (`BLACKHOLE_NO_F64=1` takes the 32-bit build).
    pub float64: bool,
    /// Compile a scene's static parameters into its ray march
    /// ([`crate::passes::raymarch::baked`]; `BLACKHOLE_NO_BAKE=1` reads them
    /// from the parameter block). The window turns it off: its panel
    /// changes them between frames, and each change would build a pipeline.
    /// Each scene with other static values builds (and keeps) pipelines of
    /// its own: a program that renders many different scenes with one
    /// `Renderer` may turn it off too.
    pub bake: bool,
}

impl Default for RendererOptions {
    fn default() -> Self {
        let settings = crate::settings::get();
        RendererOptions {
            validation: settings.validation_mode(),
            ray_differentials: !settings.no_quad,
            split: !settings.no_split,
            float64: !settings.no_f64,
            bake: !settings.no_bake,
        }
    }
}

/// The renderer's choices for one device.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub struct Features {
    /// The ray march runs its tiles as 2x2 subgroup quads and takes each
    /// pixel's lensed footprint on the sky from its neighbours (stars and
    /// image skies through it); without, the unlensed footprint.
    pub ray_differentials: bool,
    /// The ray march may be split into a trace pass and a deferred pass for
    /// the rare, expensive paths ([`crate::deferred`]): on a CPU device with
    /// quad and ballot operations. Whether one frame is split:
    /// [`Features::splits`].
    pub split: bool,
    /// The spinning hole's per-ray constants (the quartic's roots and the
    /// elliptic integrals' arguments) run in 64-bit floats, which the device
    /// has; without them the build with 32-bit roots, exact away from a thin
    /// band around the shadow's outline.
    pub kerr_f64: bool,
    /// The ray march has the scene's static parameters compiled in
    /// ([`RendererOptions::bake`]).
    pub bake: bool,
}

impl Features {
    /// The choices for a device with `info` under `options`.
    pub fn decide(info: &DeviceInfo, options: &RendererOptions) -> Self {
        let ray_differentials = info.quad_compute && options.ray_differentials;
        Features {
            ray_differentials,
            split: deferred::device_splits(info, ray_differentials) && options.split,
            kerr_f64: info.float64 && options.float64,
            bake: options.bake,
        }
    }

    /// Whether a frame of `scene` (in `spacetime`) at `width` x `height`
    /// runs the split ray march: where the device can split and a coarse
    /// grid of closed-form rays defers little of the frame
    /// ([`deferred::pays`]).
    pub fn splits(&self, scene: &Scene, spacetime: &Spacetime, width: u32, height: u32) -> bool {
        self.split && deferred::pays(scene, spacetime, width, height)
    }
}
