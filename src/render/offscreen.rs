//! Offscreen frames: a still, a still of `spp` jittered samples folded into
//! a running mean, and the post-processing chain alone on an uploaded HDR
//! image. All three go through [`Renderer::offscreen`], the one readback
//! sequence: build a graph, copy its result into the offscreen slot's
//! readback buffer, submit, wait, decode.

use ash::vk;
use gpu_allocator::MemoryLocation;

use super::Pipelines;
use super::resources::SceneResources;
use super::{
    Accumulation, FramePlan, HdrSource, PostSettings, Renderer, SceneFrame, add_frame,
    add_scene_frame, import_mean, slots,
};
use crate::frame::{Frame, FrameTimings, OutputKind, Pixels};
use crate::graph::{Graph, ImageHandle};
use crate::passes::copy;
use crate::scene::{DiskKind, Scene};
use crate::vk::{Access, Buffer, BufferBinding, ImageBinding, ImageDesc};
use crate::{Error, Result};

/// The most jittered samples a pixel (`--spp`, the Python `spp=`).
pub const MAX_SPP: u32 = 1024;

impl Renderer {
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
        scene.check_image_size(width, height)?;
        if kind.is_aov() && kind != OutputKind::Stokes && scene.disk.kind == DiskKind::Volumetric {
            return Err(Error::Usage(
                "--aov geodesic describes thin-disk hits; this scene's disk is volumetric".into(),
            ));
        }
        if scene.polarization.enabled && matches!(kind, OutputKind::Hdr | OutputKind::HdrPost) {
            return Err(Error::Usage(
                "the polarized picture ([polarization] enabled = true) is drawn in 8 bits (.png or video); `--aov stokes --out F.exr` writes its Stokes parameters".into(),
            ));
        }
        if kind == OutputKind::Stokes
            && let Some(why) = scene.spacetime().polarization_refusal()
        {
            return Err(Error::Usage(format!("--aov stokes {why}")));
        }
        let build = std::time::Instant::now();
        let plan = self.start_frame(OFFSCREEN_SLOT, scene, (width, height), (0.0, 0.0), kind)?;
        self.offscreen(
            (width, height),
            kind,
            build,
            |g, pipelines, resources, params| {
                let frame = SceneFrame {
                    scene,
                    plan: &plan,
                    params,
                    size: (width, height),
                    output: kind,
                    accumulation: None,
                };
                add_scene_frame(g, pipelines, resources, frame)
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
        self.render_samples_with(&|_| scene.clone(), width, height, kind, spp)
    }

    /// As [`Renderer::render_samples`], each sample drawing its own scene:
    /// `sample_scene(i)` for sample i (the same scene but for its time and
    /// camera, so a shutter open over part of the frame blurs motion: see
    /// [`Scene::at_sample`]). Everything but the time and the camera comes
    /// from sample 0's scene.
    pub fn render_samples_with(
        &mut self,
        sample_scene: &dyn Fn(u32) -> Scene,
        width: u32,
        height: u32,
        kind: OutputKind,
        spp: u32,
    ) -> Result<Frame> {
        if spp == 0 || spp > MAX_SPP {
            return Err(Error::Usage(format!(
                "spp = {spp}: must be 1 to {MAX_SPP} samples a pixel"
            )));
        }
        // The AOVs and the polarized picture describe the rays through the
        // pixel centres: one sample.
        if spp <= 1 || kind.is_aov() || sample_scene(0).polarization.enabled {
            return self.render(&sample_scene(0), width, height, kind);
        }
        self.check_size(width, height)?;
        self.prepare_scene(&sample_scene(0))?;
        // The plain EXR is the mean itself: the linear composite with
        // nothing applied turns it into the same half floats.
        let output = if kind == OutputKind::Hdr {
            OutputKind::HdrPost
        } else {
            kind
        };
        let for_output = |mut s: Scene| {
            if kind == OutputKind::Hdr {
                s.bloom.strength = 0.0;
                s.post.auto_exposure = false;
                s.post.exposure_ev = 0.0;
                s.post.saturation = 1.0;
            }
            s
        };
        self.ensure_mean((width, height))?;
        let mut timings = FrameTimings::default();
        for i in 0..spp {
            if self
                .stop
                .is_some_and(|f| f.load(std::sync::atomic::Ordering::SeqCst))
            {
                return Err(Error::Interrupted);
            }
            let owned = for_output(sample_scene(i));
            let scene = &owned;
            let build = std::time::Instant::now();
            let (jx, jy) = crate::camera::jitter(i + 1);
            let jitter = (jx as f32, jy as f32);
            let plan = self.start_frame(OFFSCREEN_SLOT, scene, (width, height), jitter, output)?;
            let mean = self
                .mean
                .as_ref()
                .map(|(img, state)| (img.desc, img.binding(), *state))
                .ok_or_else(|| Error::Other("accumulation image missing".into()))?;
            if i + 1 < spp {
                let mut g = Graph::new(width, height);
                let params = self.slots[OFFSCREEN_SLOT].params.binding();
                let sample = Sample {
                    scene,
                    plan: &plan,
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
                let left = self.slots[OFFSCREEN_SLOT].submit(&self.gpu, g, &[], &[])?;
                self.keep_mean_state(&left);
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
                        plan: &plan,
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
        let left = slot.submit(&self.gpu, g, &[], &[])?;
        let mut timings = slot.wait()?.unwrap_or_default();
        self.keep_mean_state(&left);
        let slot = &mut self.slots[OFFSCREEN_SLOT];
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
                    HdrSource::Image(input),
                    PostSettings {
                        bloom,
                        post,
                        mask: false,
                    },
                    OutputKind::Ldr,
                    None,
                )
            },
        );
        drop(staging);
        frame
    }
}

/// One jittered sample of [`Renderer::render_samples`], folded into the
/// running mean.
struct Sample<'s> {
    scene: &'s Scene,
    plan: &'s FramePlan,
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
        let mean = import_mean(g, self.mean);
        let frame = SceneFrame {
            scene: self.scene,
            plan: self.plan,
            params,
            size: self.size,
            output,
            accumulation: Some(Accumulation {
                mean,
                index: self.index,
            }),
        };
        add_scene_frame(g, pipelines, resources, frame)
    }
}

/// Offscreen frames are synchronous: always this slot, once it is idle.
const OFFSCREEN_SLOT: usize = 0;
