//! The renderer: owns the device, the pipelines, the resources kept across
//! frames and the frame slots; builds each frame with the one recipe
//! ([`recipe::add_frame`]) and runs it, offscreen (read back to the host:
//! `offscreen.rs`, one readback path) or onto a swapchain image (the window:
//! `window.rs`). What it does on the device is decided in
//! [`crate::features`].

pub mod noise;
mod offscreen;
pub mod pipelines;
pub mod recipe;
pub mod resources;
pub mod slots;
mod window;

use std::sync::Arc;

use ash::vk;

pub use crate::features::{Features, RendererOptions};
pub use offscreen::MAX_SPP;
pub use pipelines::Pipelines;
pub use recipe::{Accumulation, HdrSource, PostSettings, add_frame};
pub use slots::{FRAMES_IN_FLIGHT, FrameSlot};
pub use window::{Overlay, SwapchainTarget, ViewOptions};

use crate::frame::OutputKind;
use crate::graph::{Graph, ImageHandle};
use crate::passes::{self, raymarch};
use crate::scene::Scene;
use crate::spacetime::Spacetime;
use crate::vk::{Access, BufferBinding, Gpu, Image, ImageBinding, ImageDesc};
use crate::{Error, Result};
use resources::SceneResources;

/// The renderer. Fields drop in declaration order: frame slots and per-view
/// images, then the shared resources and pipelines, then (through the last
/// `Arc`) the device.
pub struct Renderer {
    slots: Vec<FrameSlot>,
    /// The slot the next windowed frame uses.
    next_slot: usize,
    /// The window's running mean for progressive refinement, with the state
    /// the last frame left it in.
    mean: Option<(Image, Access)>,
    /// The slot, size and format of the last captured swapchain frame.
    capture: Option<(usize, u32, u32, vk::Format)>,
    resources: SceneResources,
    pipelines: Pipelines,
    gpu: Arc<Gpu>,
    /// Raised (by a signal handler) to stop a many-sample image between its
    /// samples ([`Renderer::stop_when`]).
    stop: Option<&'static std::sync::atomic::AtomicBool>,
    /// The current scene's spacetime with what it was built from (the
    /// holes, gravity, the disk's axis): rebuilt only when those change.
    spacetime: Option<(crate::scene::SpacetimeKey, Arc<Spacetime>)>,
}

/// What one frame of a scene is drawn with, decided once at its start
/// ([`Renderer::start_frame`]): the scene's spacetime, held by the
/// renderer, and the ray march's variant, built from the one parameter
/// block the frame uploads.
pub(crate) struct FramePlan {
    pub spacetime: Arc<Spacetime>,
    pub variant: raymarch::Variant,
}

impl Renderer {
    /// Stops a many-sample render between samples once `flag` is raised:
    /// [`Renderer::render_samples_with`] then returns [`crate::Error::Interrupted`]
    /// (a still at --spp 1024 once finished every sample, ten seconds,
    /// before honouring SIGTERM).
    pub fn stop_when(&mut self, flag: &'static std::sync::atomic::AtomicBool) {
        self.stop = Some(flag);
    }

    /// Opens the device and builds the pipelines.
    pub fn new(options: RendererOptions) -> Result<Self> {
        crate::settings::init()?;
        let gpu = Gpu::new(options.validation, crate::settings::get().gpu())?;
        Self::with_gpu(gpu, options)
    }

    /// Builds the renderer on a device opened by the caller (the window opens
    /// it with a surface in mind).
    pub fn with_gpu(gpu: Arc<Gpu>, options: RendererOptions) -> Result<Self> {
        let features = Features::decide(&gpu.info, &options);
        log::debug!("features on {}: {features:?}", gpu.info.name);
        let pipelines = Pipelines::new(&gpu, features)?;
        let resources = SceneResources::new(&gpu)?;
        let slots = (0..FRAMES_IN_FLIGHT)
            .map(|i| FrameSlot::new(&gpu, i))
            .collect::<Result<Vec<_>>>()?;
        Ok(Renderer {
            slots,
            next_slot: 0,
            mean: None,
            capture: None,
            resources,
            pipelines,
            gpu,
            stop: None,
            spacetime: None,
        })
    }

    /// Destroys everything in the documented order and checks that nothing
    /// outlived it: every Vulkan object holds the device, so a device still
    /// referenced afterwards means a leaked object (and its memory).
    pub fn shutdown(mut self) -> Result<()> {
        // A lost device has nothing left to finish: its objects are
        // destroyed all the same, and closing it is not an error.
        match self.wait_idle() {
            Err(Error::Vulkan {
                result: vk::Result::ERROR_DEVICE_LOST,
                ..
            }) => log::debug!("shutting down a lost device"),
            other => other?,
        }
        let device = Arc::downgrade(&self.gpu);
        drop(self);
        match device.upgrade() {
            None => Ok(()),
            Some(gpu) => Err(Error::Other(format!(
                "{} Vulkan objects still hold the device after shutdown (leaked)",
                Arc::strong_count(&gpu) - 1
            ))),
        }
    }

    /// What the renderer does on this device (ray differentials, the split
    /// ray march); tests expect their pass lists and images from it.
    pub fn features(&self) -> Features {
        self.pipelines.features()
    }

    /// The ray march's passes in a frame of `scene` at `width` x `height`
    /// on this device, in order: split into the deferred list's clear, the
    /// trace pass and the deferred pass where the device and the frame gain
    /// by it ([`crate::deferred`]), one dispatch otherwise.
    pub fn ray_march_passes(&self, scene: &Scene, width: u32, height: u32) -> Vec<&'static str> {
        let spacetime = scene.spacetime();
        let block = self.block(scene, &spacetime, raymarch::FrameSpec::new(width, height));
        let variant = raymarch::Variant::of(scene, &spacetime, &block, self.features().bake);
        raymarch::pass_names(
            variant,
            self.features().splits(scene, &spacetime, width, height),
        )
    }

    /// The device.
    pub fn gpu(&self) -> &Arc<Gpu> {
        &self.gpu
    }

    /// Images and buffers the frame slots' transient pools hold (the
    /// objects frames create; a long run must not grow it).
    pub fn transient_resources(&self) -> usize {
        self.slots.iter().map(|s| s.transients.len()).sum()
    }

    /// The device in use.
    pub fn device_name(&self) -> &str {
        &self.gpu.info.name
    }

    /// Validation errors and warnings reported so far (0, 0 when validation is off).
    pub fn validation_counts(&self) -> (u32, u32) {
        self.gpu.validation_counts()
    }

    /// Whether the validation layer is active.
    pub fn validation_enabled(&self) -> bool {
        self.gpu.instance.validation_enabled
    }

    /// Waits for every frame in flight (their timings are dropped).
    pub fn wait_idle(&mut self) -> Result<()> {
        for slot in &mut self.slots {
            slot.wait()?;
        }
        Ok(())
    }

    /// Drops transient images and buffers no frame of each slot used lately
    /// (after a resize). Waits for the frames in flight first.
    pub fn trim(&mut self) -> Result<()> {
        self.wait_idle()?;
        for slot in &mut self.slots {
            slot.transients.trim_unused();
        }
        Ok(())
    }

    /// Keeps the state a submitted frame left the accumulation image in, as
    /// the graph reports it, for its next import.
    fn keep_mean_state(&mut self, left: &slots::ImportsLeft) {
        if let (Some((_, state)), Some(a)) = (self.mean.as_mut(), left.of(MEAN)) {
            *state = a;
        }
    }

    fn check_size(&self, width: u32, height: u32) -> Result<()> {
        let max = self.gpu.max_image_dimension();
        if width == 0 || height == 0 || width > max || height > max {
            return Err(Error::Usage(format!(
                "image size {width}x{height} is outside 1..={max} per side on {}",
                self.gpu.info.name
            )));
        }
        // Memory: the frame's images and readback take about 64 bytes a
        // pixel at most (HDR, accumulated mean, bloom chain, 8-bit output,
        // a float readback); refuse what cannot fit in the largest heap.
        let need = u64::from(width) * u64::from(height) * 64;
        let heap = self.gpu.largest_device_heap();
        let ceiling = heap / 10 * 8;
        if heap > 0 && need > ceiling {
            return Err(Error::Usage(format!(
                "image size {width}x{height} needs about {:.1} GB of GPU memory (64 bytes a pixel), \
                 over the {:.1} GB a frame may take on {}: 80 % of its largest heap, {:.1} GB",
                need as f64 / 1e9,
                ceiling as f64 / 1e9,
                self.gpu.info.name,
                heap as f64 / 1e9
            )));
        }
        Ok(())
    }

    /// Uploads the scene's image sky and builds its volume if they changed
    /// (after every frame in flight is done with the old ones), and builds
    /// the ray march specialised for this scene now rather than while a
    /// frame records (a new variant takes lavapipe a moment): split and
    /// whole, as a moving camera may need either. An unreadable sky is
    /// reported here, before any frame is built. (The window calls it ahead
    /// of a fall's end; every frame's start does it for its own variant.)
    pub fn prepare_scene(&mut self, scene: &Scene) -> Result<()> {
        self.prepare_images(scene)?;
        let spacetime = scene.spacetime();
        let block = self.block(scene, &spacetime, raymarch::FrameSpec::new(1, 1));
        let variant = raymarch::Variant::of(scene, &spacetime, &block, self.features().bake);
        self.prepare_variant(variant)
    }

    /// The scene's image sky and volume, uploaded or built where they changed.
    fn prepare_images(&mut self, scene: &Scene) -> Result<()> {
        if self.resources.sky_changes(scene) || self.resources.volume_changes(scene) {
            self.wait_idle()?;
            self.resources.ensure_sky(scene)?;
            self.resources.ensure_volume(scene)?;
        }
        Ok(())
    }

    /// The pipelines of `variant`, split and whole, built where missing.
    fn prepare_variant(&mut self, variant: raymarch::Variant) -> Result<()> {
        for split in [true, false] {
            for stage in self.pipelines.raymarch.stages(variant, split) {
                self.pipelines.raymarch.pipeline(stage)?;
            }
        }
        Ok(())
    }

    /// The scene's spacetime, held across frames: rebuilt only when the
    /// holes, gravity or the disk's axis change.
    fn spacetime_of(&mut self, scene: &Scene) -> Arc<Spacetime> {
        let key = scene.spacetime_key();
        match &self.spacetime {
            Some((held, spacetime)) if *held == key => Arc::clone(spacetime),
            _ => {
                let spacetime = Arc::new(scene.spacetime());
                self.spacetime = Some((key, Arc::clone(&spacetime)));
                spacetime
            }
        }
    }

    /// The spacetime an AOV (`output`) of `scene` is traced in: one
    /// non-rotating hole in the spinning hole's form at a* = 0 where the
    /// device has 64-bit floats ([`Spacetime::spinning_form`]: its camera
    /// and roots in f64, exact for far cameras and deep inside the
    /// horizon), except for a `"flat"` camera (the comparison mapping).
    /// Every other frame keeps `spacetime`.
    fn aov_form(
        &self,
        scene: &Scene,
        spacetime: Arc<Spacetime>,
        output: OutputKind,
    ) -> Arc<Spacetime> {
        let viewer = scene.camera.viewer();
        if !output.is_aov()
            || !self.features().kerr_f64
            || viewer.observer == crate::physics::observer::ObserverKind::Flat
        {
            return spacetime;
        }
        match spacetime.spinning_form() {
            Some(form) => Arc::new(form),
            None => spacetime,
        }
    }

    /// The parameter block of `scene` for `frame` (its image sky's width
    /// filled in from the loaded sky).
    fn block(
        &self,
        scene: &Scene,
        spacetime: &Spacetime,
        frame: raymarch::FrameSpec,
    ) -> raymarch::RaymarchParams {
        let frame = raymarch::FrameSpec {
            image_sky_width: self.resources.sky.as_ref().map(|(_, sky)| sky.desc.width),
            ..frame
        };
        raymarch::RaymarchParams::new(scene, spacetime, &frame)
    }

    /// The start of every frame, offscreen or in the window: the scene's
    /// images ready, slot `slot` idle (its last frame waited for), the
    /// scene's spacetime held, one parameter block built and written to the
    /// slot, and the variant built from it once, its pipelines ready.
    fn start_frame(
        &mut self,
        slot: usize,
        scene: &Scene,
        size: (u32, u32),
        jitter: (f32, f32),
        output: OutputKind,
    ) -> Result<FramePlan> {
        self.prepare_images(scene)?;
        let spacetime = self.spacetime_of(scene);
        let spacetime = self.aov_form(scene, spacetime, output);
        let frame = raymarch::FrameSpec {
            jitter,
            ..raymarch::FrameSpec::new(size.0, size.1)
        };
        let block = self.block(scene, &spacetime, frame);
        let variant = raymarch::Variant::of(scene, &spacetime, &block, self.features().bake);
        self.prepare_variant(variant)?;
        self.slots[slot].wait()?;
        self.slots[slot]
            .params
            .mapped_mut()?
            .copy_from_slice(bytemuck::bytes_of(&block));
        Ok(FramePlan { spacetime, variant })
    }

    /// Makes sure the accumulation image matches `size` (a new one, after
    /// the GPU is idle, if not); true when it was made anew.
    fn ensure_mean(&mut self, (w, h): (u32, u32)) -> Result<bool> {
        let fits = self
            .mean
            .as_ref()
            .is_some_and(|(img, _)| (img.desc.width, img.desc.height) == (w, h));
        if fits {
            return Ok(false);
        }
        self.wait_idle()?;
        self.mean = None;
        self.mean = Some((
            Image::new(
                &self.gpu,
                "accumulated mean",
                ImageDesc::new_2d(passes::accumulate::MEAN_FORMAT, w, h),
                vk::ImageUsageFlags::STORAGE | vk::ImageUsageFlags::SAMPLED,
            )?,
            Access::Nothing,
        ));
        Ok(true)
    }
}

/// The accumulation image's name in a graph.
const MEAN: &str = "accumulated mean";

/// Imports the accumulation image (its description, binding and current
/// state); the graph leaves it ready to be sampled.
fn import_mean(
    g: &mut Graph<'_>,
    (desc, binding, state): (ImageDesc, ImageBinding, Access),
) -> ImageHandle {
    g.import_image(MEAN, desc, binding, state, Some(Access::ComputeSampledRead))
}

/// One frame of a scene as the renderer's three paths (a still, a sample of
/// `--spp`, the window) hand it to the recipe.
struct SceneFrame<'s> {
    scene: &'s Scene,
    /// The frame's spacetime and variant, decided once at its start.
    plan: &'s FramePlan,
    /// The slot's parameter block, written by the host.
    params: BufferBinding,
    /// The ray march's size.
    size: (u32, u32),
    output: OutputKind,
    accumulation: Option<Accumulation>,
}

/// Imports a slot's parameter block (written by the host) and the shared
/// images, then adds the recipe for the frame's ray march.
fn add_scene_frame<'a>(
    g: &mut Graph<'a>,
    pipelines: &'a Pipelines,
    resources: &SceneResources,
    frame: SceneFrame<'_>,
) -> ImageHandle {
    let SceneFrame {
        scene,
        plan,
        params,
        size,
        output,
        accumulation,
    } = frame;
    let params = g.import_buffer("raymarch params", params, Access::HostWrite, None);
    let images = import_scene_images(g, resources);
    add_frame(
        g,
        pipelines,
        HdrSource::RayMarch {
            scene,
            spacetime: &plan.spacetime,
            variant: &plan.variant,
            params: &params,
            images: &images,
            size,
        },
        PostSettings {
            bloom: &scene.bloom,
            post: &scene.post,
            mask: !scene.camera.projection.every_pixel_has_a_ray(),
        },
        output,
        accumulation,
    )
}

/// Imports the colour table, the noise textures and the sky image if any.
fn import_scene_images(g: &mut Graph<'_>, res: &SceneResources) -> raymarch::SceneImages {
    let mut import = |name: &str, image: &crate::vk::Image| {
        g.import_image(
            name,
            image.desc,
            image.binding(),
            Access::ComputeSampledRead,
            Some(Access::ComputeSampledRead),
        )
    };
    let disk_lut = import("disk lut", &res.disk_lut);
    let disk_noise = import("disk noise", &res.disk_noise);
    let volume_noise = import("volume noise", &res.volume_noise);
    let sky = res.sky.as_ref().map(|(_, image)| import("sky", image));
    raymarch::SceneImages {
        disk_lut,
        disk_noise,
        volume_noise,
        sky,
    }
}
