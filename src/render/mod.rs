//! The renderer: owns the device, the pipelines, the resources kept across
//! frames and the frame slots; builds each frame with the one recipe
//! ([`recipe::add_frame`]) and runs it, offscreen (read back to the host) or
//! onto a swapchain image (the window).

pub mod features;
pub mod noise;
pub mod recipe;
pub mod resources;
pub mod slots;

use std::sync::Arc;

use ash::vk;
use gpu_allocator::MemoryLocation;

pub use features::Features;
pub use recipe::{Accumulation, HdrSource, PostSettings, add_frame};
pub use slots::{FRAMES_IN_FLIGHT, FrameSlot};

use crate::frame::{Frame, FrameTimings, OutputKind, Pixels};
use crate::graph::{Graph, ImageHandle};
use crate::passes::{self, Pipelines, copy, raymarch};
use crate::scene::{DiskKind, Scene, SkyKind};
use crate::vk::{Access, Buffer, BufferBinding, Gpu, Image, ImageBinding, ImageDesc, Validation};
use crate::{Error, Result};
use resources::SceneResources;

/// Options for creating a [`Renderer`]; the defaults come from the
/// environment ([`crate::settings`]).
#[derive(Clone, Copy, Debug)]
pub struct RendererOptions {
    pub validation: Validation,
    /// Use ray differentials where the device can (`BLACKHOLE_NO_QUAD=1`
    /// turns them off, for comparisons).
    pub ray_differentials: bool,
    /// Split the thin disk's ray march where the device and the frame
    /// gain by it (`BLACKHOLE_NO_SPLIT=1` keeps the one dispatch).
    pub disk_split: bool,
}

impl Default for RendererOptions {
    fn default() -> Self {
        let settings = crate::settings::get();
        RendererOptions {
            validation: Validation::from_env(),
            ray_differentials: !settings.no_quad,
            disk_split: !settings.no_split,
        }
    }
}

/// How the window wants one frame drawn.
#[derive(Clone, Copy, Debug)]
pub struct ViewOptions {
    /// Size of the ray march (the window's size times the render scale).
    pub render_size: (u32, u32),
    /// Sub-pixel jitter of the ray march, in pixels (0, 0 = pixel centres).
    pub jitter: (f32, f32),
    /// Which sample of an unchanged view this frame is; `None` turns the
    /// progressive accumulation off.
    pub sample: Option<u32>,
}

/// Something drawn over the frame on the swapchain image (the GUI panel).
pub trait Overlay {
    /// Adds the overlay's passes; `target` is the swapchain image, holding
    /// the frame already.
    fn add_passes<'a>(&'a mut self, graph: &mut Graph<'a>, target: &mut ImageHandle);
}

/// A swapchain image to draw onto, with its semaphores.
pub struct SwapchainTarget<'t> {
    pub desc: ImageDesc,
    pub binding: ImageBinding,
    /// Signalled by the acquire; waited at [`Access::Acquired`]'s stages.
    pub acquired: vk::Semaphore,
    /// Signalled when the frame is done; presentation waits on it.
    pub rendered: vk::Semaphore,
    pub overlay: Option<&'t mut dyn Overlay>,
    /// Also copy the finished image to the host ([`Renderer::take_capture`]).
    pub capture: bool,
}

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
}

impl Renderer {
    /// Opens the device and builds the pipelines.
    pub fn new(options: RendererOptions) -> Result<Self> {
        crate::settings::init()?;
        let gpu = Gpu::new(options.validation)?;
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
        })
    }

    /// Destroys everything in the documented order and checks that nothing
    /// outlived it: every Vulkan object holds the device, so a device still
    /// referenced afterwards means a leaked object (and its memory).
    pub fn shutdown(mut self) -> Result<()> {
        self.wait_idle()?;
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
        if heap > 0 && need > heap / 10 * 8 {
            return Err(Error::Usage(format!(
                "image size {width}x{height} needs about {:.1} GB of GPU memory; {} has {:.1} GB (its largest heap)",
                need as f64 / 1e9,
                self.gpu.info.name,
                heap as f64 / 1e9
            )));
        }
        Ok(())
    }

    /// Uploads the scene's image sky if it changed (after every frame in
    /// flight is done with the old one). An unreadable sky is reported here,
    /// before any frame is built.
    pub fn prepare_scene(&mut self, scene: &Scene) -> Result<()> {
        if self.resources.sky_changes(scene) || self.resources.volume_changes(scene) {
            self.wait_idle()?;
            self.resources.ensure_sky(scene)?;
            self.resources.ensure_volume(scene)?;
        }
        // The ray march specialised for this scene, built now rather than
        // while a frame records (a new variant takes lavapipe a moment):
        // split and whole, as a moving camera may need either.
        let variant = raymarch::Variant::of(scene, false);
        for split in [true, false] {
            for stage in self.pipelines.raymarch_stages(variant, split) {
                self.pipelines.raymarch(stage)?;
            }
        }
        Ok(())
    }

    /// Writes slot `slot`'s parameter block for `scene` (the slot is idle).
    fn write_params(
        &mut self,
        slot: usize,
        scene: &Scene,
        size: (u32, u32),
        jitter: (f32, f32),
    ) -> Result<()> {
        let mut params = raymarch::RaymarchParams::new(scene, size.0, size.1);
        params.cam_up[3] = jitter.0;
        params.cam_fwd[3] = jitter.1;
        // An image sky's shader needs its panorama's width (the catalogue's
        // grid size is set by RaymarchParams::new).
        if let Some((_, sky)) = &self.resources.sky
            && matches!(scene.sky.kind, SkyKind::Image | SkyKind::Cubemap)
        {
            params.sky[1] = sky.desc.width as f32;
        }
        self.slots[slot]
            .params
            .mapped_mut()?
            .copy_from_slice(bytemuck::bytes_of(&params));
        Ok(())
    }

    /// Renders `scene` at `width` x `height` offscreen and reads the result
    /// back (waits for it).
    pub fn render(
        &mut self,
        scene: &Scene,
        width: u32,
        height: u32,
        kind: OutputKind,
    ) -> Result<Frame> {
        self.check_size(width, height)?;
        if kind == OutputKind::Geodesic && scene.disk.kind == DiskKind::Volumetric {
            return Err(Error::Usage(
                "--aov geodesic describes thin-disk hits; this scene's disk is volumetric".into(),
            ));
        }
        self.prepare_scene(scene)?;
        self.slots[OFFSCREEN_SLOT].wait()?;
        let build = std::time::Instant::now();
        self.write_params(OFFSCREEN_SLOT, scene, (width, height), (0.0, 0.0))?;
        self.offscreen(
            (width, height),
            kind,
            build,
            |g, pipelines, resources, params| {
                add_scene_frame(
                    g,
                    pipelines,
                    resources,
                    scene,
                    params,
                    (width, height),
                    kind,
                    None,
                )
            },
        )
    }

    /// Renders `scene` with `spp` jittered samples per pixel (Halton (2, 3)
    /// offsets, the same for every frame, so sequences are deterministic):
    /// each sample's ray march is folded into a running mean, and bloom,
    /// exposure and tone map run once on the mean. `spp` <= 1 is
    /// [`Renderer::render`]; the geodesic AOV takes one sample (it describes
    /// rays, not light).
    pub fn render_samples(
        &mut self,
        scene: &Scene,
        width: u32,
        height: u32,
        kind: OutputKind,
        spp: u32,
    ) -> Result<Frame> {
        if spp <= 1 || kind == OutputKind::Geodesic {
            return self.render(scene, width, height, kind);
        }
        self.check_size(width, height)?;
        self.prepare_scene(scene)?;
        // The plain EXR is the mean itself: the linear composite with
        // nothing applied turns it into the same half floats.
        let mut post_scene;
        let (scene, output) = if kind == OutputKind::Hdr {
            post_scene = scene.clone();
            post_scene.bloom.strength = 0.0;
            post_scene.post.auto_exposure = false;
            post_scene.post.exposure_ev = 0.0;
            post_scene.post.saturation = 1.0;
            (&post_scene, OutputKind::HdrPost)
        } else {
            (scene, kind)
        };
        self.ensure_mean((width, height))?;
        let mut timings = FrameTimings::default();
        for i in 0..spp {
            self.slots[OFFSCREEN_SLOT].wait()?;
            let build = std::time::Instant::now();
            let jitter = (
                (halton(i + 1, 2) - 0.5) as f32,
                (halton(i + 1, 3) - 0.5) as f32,
            );
            self.write_params(OFFSCREEN_SLOT, scene, (width, height), jitter)?;
            let mean = self
                .mean
                .as_ref()
                .map(|(img, state)| (img.desc, img.binding(), *state))
                .ok_or_else(|| Error::Other("accumulation image missing".into()))?;
            if let Some((_, state)) = self.mean.as_mut() {
                *state = Access::ComputeSampledRead;
            }
            if i + 1 < spp {
                let mut g = Graph::new(width, height);
                let params = self.slots[OFFSCREEN_SLOT].params.binding();
                let sample = Sample {
                    scene,
                    size: (width, height),
                    mean: mean.clone(),
                    index: i,
                };
                sample.add(
                    &mut g,
                    &self.pipelines,
                    &self.resources,
                    params,
                    OutputKind::Hdr,
                );
                self.slots[OFFSCREEN_SLOT].submit(&self.gpu, g, &[], &[])?;
                if let Some(t) = self.slots[OFFSCREEN_SLOT].wait()? {
                    timings.add(&t);
                }
                continue;
            }
            let mut frame = self.offscreen(
                (width, height),
                kind,
                build,
                |g, pipelines, resources, params| {
                    let sample = Sample {
                        scene,
                        size: (width, height),
                        mean,
                        index: i,
                    };
                    sample.add(g, pipelines, resources, params, output)
                },
            )?;
            timings.add(&frame.timings);
            timings.cpu = frame.timings.cpu;
            frame.timings = timings;
            return Ok(frame);
        }
        Err(Error::Other("no samples rendered".into()))
    }

    /// The one offscreen path: on the offscreen slot (idle, its parameters
    /// written), `build` adds a frame to a new graph and returns the image to
    /// read back; it is copied into the slot's readback buffer, submitted,
    /// waited for and decoded as `kind`.
    fn offscreen<F>(
        &mut self,
        (width, height): (u32, u32),
        kind: OutputKind,
        build_start: std::time::Instant,
        build: F,
    ) -> Result<Frame>
    where
        F: for<'a> FnOnce(
            &mut Graph<'a>,
            &'a Pipelines,
            &SceneResources,
            BufferBinding,
        ) -> ImageHandle,
    {
        let needed = u64::from(width) * u64::from(height) * kind.texel_bytes();
        let gpu = self.gpu.clone();
        let slot = &mut self.slots[OFFSCREEN_SLOT];
        let readback = slot.ensure_readback(&gpu, needed)?.binding();
        let params = slot.params.binding();
        let mut g = Graph::new(width, height);
        let mut out_buf = g.import_buffer(
            "readback",
            readback,
            Access::Nothing,
            Some(Access::HostRead),
        );
        let result = build(&mut g, &self.pipelines, &self.resources, params);
        copy::add_copy_to_buffer(&mut g, &result, &mut out_buf);
        let slot = &mut self.slots[OFFSCREEN_SLOT];
        let build_ms = slots::ms_since(build_start);
        slot.submit(&self.gpu, g, &[], &[])?;
        let mut timings = slot.wait()?.unwrap_or_default();
        timings.cpu.build_ms = build_ms;
        let readback_start = std::time::Instant::now();
        let readback = slot
            .readback
            .as_ref()
            .ok_or_else(|| Error::Other("readback buffer missing".into()))?;
        let pixels = Pixels::decode(kind, &readback.mapped()?[..needed as usize]);
        timings.cpu.readback_ms = slots::ms_since(readback_start);
        Ok(Frame {
            width,
            height,
            pixels,
            timings,
        })
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

    /// Runs the post-processing part of the recipe (bloom, exposure, tone
    /// map) on an HDR image given as RGBA f32 rows, row 0 at the top; returns
    /// the 8-bit frame.
    pub fn post_process(
        &mut self,
        hdr: &[f32],
        width: u32,
        height: u32,
        bloom: &crate::scene::Bloom,
        post: &crate::scene::Post,
    ) -> Result<Frame> {
        let texels = width as usize * height as usize;
        if width == 0 || height == 0 || hdr.len() != 4 * texels {
            return Err(Error::Usage(format!(
                "post_process: {} floats do not make a {width}x{height} RGBA image",
                hdr.len()
            )));
        }
        self.check_size(width, height)?;
        let bytes: &[u8] = bytemuck::cast_slice(hdr);
        let mut staging = Buffer::new(
            &self.gpu,
            "post input staging",
            bytes.len() as u64,
            vk::BufferUsageFlags::TRANSFER_SRC,
            MemoryLocation::CpuToGpu,
        )?;
        staging.mapped_mut()?.copy_from_slice(bytes);
        self.slots[OFFSCREEN_SLOT].wait()?;
        let build = std::time::Instant::now();
        let staged = staging.binding();
        let frame = self.offscreen(
            (width, height),
            OutputKind::Ldr,
            build,
            |g, pipelines, _, _| {
                let src = g.import_buffer("post input staging", staged, Access::HostWrite, None);
                let mut input =
                    g.create_relative("hdr input", vk::Format::R32G32B32A32_SFLOAT, 1, 1);
                copy::add_upload(g, &src, &mut input, 16);
                add_frame(
                    g,
                    pipelines,
                    HdrSource::Image(&input),
                    PostSettings { bloom, post },
                    OutputKind::Ldr,
                    None,
                )
            },
        );
        drop(staging);
        frame
    }

    /// Waits for the frame slot the next windowed frame will use (call it
    /// before acquiring a swapchain image, so the slot's acquire semaphore is
    /// free again); returns that slot's last frame's GPU timings.
    pub fn begin_window_frame(&mut self) -> Result<Option<FrameTimings>> {
        self.slots[self.next_slot].wait()
    }

    /// Draws `scene` onto a swapchain image (the window): the frame recipe at
    /// `view.render_size`, a blit onto the image, then the overlay, in the
    /// slot [`Renderer::begin_window_frame`] waited for. Does not wait for
    /// the GPU.
    pub fn draw_to_swapchain(
        &mut self,
        scene: &Scene,
        view: ViewOptions,
        target: SwapchainTarget<'_>,
    ) -> Result<()> {
        let (w, h) = view.render_size;
        self.check_size(w, h)?;
        self.check_size(target.desc.width, target.desc.height)?;
        self.prepare_scene(scene)?;
        let slot_index = self.next_slot;
        self.next_slot = (self.next_slot + 1) % self.slots.len();
        self.slots[slot_index].wait()?;
        self.write_params(slot_index, scene, view.render_size, view.jitter)?;

        // The running mean follows the render size; a new one starts over.
        let mut sample = view.sample;
        if let Some(s) = sample.as_mut()
            && self.ensure_mean((w, h))?
        {
            *s = 0;
        }

        let (out_w, out_h) = (target.desc.width, target.desc.height);
        let mut g = Graph::new(out_w, out_h);
        let mut mean_handle = match (sample, self.mean.as_ref()) {
            (Some(_), Some((img, state))) => {
                Some(import_mean(&mut g, (img.desc, img.binding(), *state)))
            }
            _ => None,
        };
        let accumulation = match (mean_handle.as_mut(), sample) {
            (Some(mean), Some(index)) => Some(Accumulation { mean, index }),
            _ => None,
        };
        let ldr = add_scene_frame(
            &mut g,
            &self.pipelines,
            &self.resources,
            scene,
            self.slots[slot_index].params.binding(),
            (w, h),
            OutputKind::Ldr,
            accumulation,
        );
        let mut swap = g.import_image(
            "swapchain",
            target.desc,
            target.binding,
            Access::Acquired,
            Some(Access::Present),
        );
        passes::present::add_blit_to(&mut g, &ldr, &mut swap);
        if let Some(o) = target.overlay {
            o.add_passes(&mut g, &mut swap);
        }
        if target.capture {
            let needed = u64::from(out_w) * u64::from(out_h) * 4;
            let gpu = self.gpu.clone();
            let readback = self.slots[slot_index]
                .ensure_readback(&gpu, needed)?
                .binding();
            let mut buf =
                g.import_buffer("capture", readback, Access::Nothing, Some(Access::HostRead));
            copy::add_copy_to_buffer(&mut g, &swap, &mut buf);
            self.capture = Some((slot_index, out_w, out_h, target.desc.format));
        }
        let waits = [(target.acquired, Access::Acquired.info().stage)];
        self.slots[slot_index].submit(&self.gpu, g, &waits, &[target.rendered])?;
        if let Some((_, state)) = self.mean.as_mut() {
            if sample.is_some() {
                *state = Access::ComputeSampledRead;
            }
        }
        Ok(())
    }
}

impl Renderer {
    /// The last frame drawn with `capture`, as 8-bit RGBA (waits for it).
    pub fn take_capture(&mut self) -> Result<Frame> {
        let (slot, width, height, format) = self
            .capture
            .take()
            .ok_or_else(|| Error::Other("no frame was captured".into()))?;
        self.wait_idle()?;
        let readback = self.slots[slot]
            .readback
            .as_ref()
            .ok_or_else(|| Error::Other("capture buffer missing".into()))?;
        let needed = (u64::from(width) * u64::from(height) * 4) as usize;
        let mut bytes = readback.mapped()?[..needed].to_vec();
        if matches!(
            format,
            vk::Format::B8G8R8A8_UNORM | vk::Format::B8G8R8A8_SRGB
        ) {
            for px in bytes.chunks_exact_mut(4) {
                px.swap(0, 2);
            }
        }
        Ok(Frame {
            width,
            height,
            pixels: Pixels::Rgba8(bytes),
            timings: FrameTimings::default(),
        })
    }
}

/// One jittered sample of [`Renderer::render_samples`], folded into the
/// running mean.
struct Sample<'s> {
    scene: &'s Scene,
    size: (u32, u32),
    /// The accumulation image: description, binding, current state.
    mean: (ImageDesc, ImageBinding, Access),
    index: u32,
}

impl Sample<'_> {
    fn add<'a>(
        self,
        g: &mut Graph<'a>,
        pipelines: &'a Pipelines,
        resources: &SceneResources,
        params: BufferBinding,
        output: OutputKind,
    ) -> ImageHandle {
        let mut mean = import_mean(g, self.mean);
        add_scene_frame(
            g,
            pipelines,
            resources,
            self.scene,
            params,
            self.size,
            output,
            Some(Accumulation {
                mean: &mut mean,
                index: self.index,
            }),
        )
    }
}

/// Offscreen frames are synchronous: always this slot, once it is idle.
const OFFSCREEN_SLOT: usize = 0;

/// Imports the accumulation image (its description, binding and current
/// state); the graph leaves it ready to be sampled.
fn import_mean(
    g: &mut Graph<'_>,
    (desc, binding, state): (ImageDesc, ImageBinding, Access),
) -> ImageHandle {
    g.import_image(
        "accumulated mean",
        desc,
        binding,
        state,
        Some(Access::ComputeSampledRead),
    )
}

/// Imports a slot's parameter block (written by the host) and the shared
/// images, then adds the recipe for `scene`'s ray march at `size`.
fn add_scene_frame<'a>(
    g: &mut Graph<'a>,
    pipelines: &'a Pipelines,
    resources: &SceneResources,
    scene: &Scene,
    params: BufferBinding,
    size: (u32, u32),
    output: OutputKind,
    accumulation: Option<Accumulation<'_>>,
) -> ImageHandle {
    let params = g.import_buffer("raymarch params", params, Access::HostWrite, None);
    let images = import_scene_images(g, resources);
    add_frame(
        g,
        pipelines,
        HdrSource::RayMarch {
            scene,
            params: &params,
            images: &images,
            size,
        },
        PostSettings {
            bloom: &scene.bloom,
            post: &scene.post,
        },
        output,
        accumulation,
    )
}

/// Imports the colour table, the noise textures and the sky (the table again
/// when the sky is not an image: the binding must hold something).
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
    let sky = match &res.sky {
        Some((_, image)) => import("sky", image),
        None => disk_lut.clone(),
    };
    raymarch::SceneImages {
        disk_lut,
        disk_noise,
        volume_noise,
        sky,
    }
}

/// The radical inverse of `i` in `base` (Halton sequence), in [0, 1): the
/// sub-pixel offsets of accumulated samples (window and `--spp`).
pub fn halton(mut i: u32, base: u32) -> f64 {
    let mut f = 1.0;
    let mut r = 0.0;
    while i > 0 {
        f /= f64::from(base);
        r += f * f64::from(i % base);
        i /= base;
    }
    r
}
