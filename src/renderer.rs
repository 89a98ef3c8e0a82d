//! The offscreen renderer: owns the device, the pipelines and the per-frame
//! resources, builds the frame graph for a request, runs it and reads it back.

use std::sync::Arc;

use ash::vk;
use gpu_allocator::MemoryLocation;

use crate::graph::ImageDesc;
use crate::graph::{self, Graph, TransientPool};
use crate::passes::{self, Pipelines, composite, copy, raymarch};
use crate::scene::Scene;
use crate::vk::{Access, Buffer, CommandContext, Gpu, Image, TimestampPool, Validation};
use crate::{Error, Result};

/// What a render produces.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OutputKind {
    /// Tone-mapped, sRGB-encoded 8-bit RGBA.
    Ldr,
    /// Linear HDR RGBA, before tone mapping.
    Hdr,
    /// The geodesic AOV (DESIGN.md section 4), RGBA32F.
    Geodesic,
    /// Linear HDR after bloom and exposure, before the tone map (`--exr-post`).
    HdrPost,
}

/// Pixels read back from the GPU, row 0 at the top.
#[derive(Clone, Debug)]
pub enum Pixels {
    Rgba8(Vec<u8>),
    Rgba32F(Vec<f32>),
}

/// One rendered frame.
#[derive(Clone, Debug)]
pub struct Frame {
    pub width: u32,
    pub height: u32,
    pub pixels: Pixels,
    pub timings: FrameTimings,
}

/// GPU time of one pass.
#[derive(Clone, Debug, PartialEq)]
pub struct PassTiming {
    pub name: String,
    pub ms: f64,
}

/// GPU time per pass of one frame (empty when the device has no timestamps).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FrameTimings {
    pub passes: Vec<PassTiming>,
    /// From the first pass's start to the last pass's end.
    pub frame_ms: f64,
}

impl std::fmt::Display for FrameTimings {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let parts: Vec<String> = self
            .passes
            .iter()
            .map(|p| format!("{} {:.2} ms", p.name, p.ms))
            .collect();
        write!(f, "{} (frame {:.2} ms)", parts.join(", "), self.frame_ms)
    }
}

/// Options for creating a [`Renderer`].
#[derive(Clone, Copy, Debug)]
pub struct RendererOptions {
    pub validation: Validation,
}

impl Default for RendererOptions {
    fn default() -> Self {
        RendererOptions {
            validation: Validation::from_env(),
        }
    }
}

/// Most passes a frame can time.
const MAX_TIMED_PASSES: u32 = 64;

/// The offscreen renderer. Fields drop in declaration order: per-frame
/// resources, then pipelines, then (through the last `Arc`) the device.
pub struct Renderer {
    transients: TransientPool,
    disk_lut: Image,
    /// The image sky in use, with the files it came from.
    sky: Option<(Vec<std::path::PathBuf>, Image)>,
    readback: Option<Buffer>,
    params: Buffer,
    timestamps: Option<TimestampPool>,
    commands: CommandContext,
    pipelines: Pipelines,
    gpu: Arc<Gpu>,
}

impl Renderer {
    /// Opens the device and builds the pipelines.
    pub fn new(options: RendererOptions) -> Result<Self> {
        let gpu = Gpu::new(options.validation)?;
        let pipelines = Pipelines::new(&gpu)?;
        let commands = CommandContext::new(&gpu)?;
        let timestamps = TimestampPool::new(&gpu, 2 * MAX_TIMED_PASSES)?;
        let params = Buffer::new(
            &gpu,
            "raymarch params",
            std::mem::size_of::<raymarch::RaymarchParams>() as u64,
            vk::BufferUsageFlags::UNIFORM_BUFFER,
            MemoryLocation::CpuToGpu,
        )?;
        let mut transients = TransientPool::new(&gpu);
        let mut commands = commands;
        let disk_lut = upload_disk_lut(&gpu, &mut commands, &mut transients)?;
        Ok(Renderer {
            transients,
            disk_lut,
            sky: None,
            readback: None,
            params,
            timestamps,
            commands,
            pipelines,
            gpu,
        })
    }

    /// Destroys everything in the documented order and checks that nothing
    /// outlived it: every Vulkan object holds the device, so a device still
    /// referenced afterwards means a leaked object (and its memory).
    pub fn shutdown(self) -> Result<()> {
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

    /// Renders `scene` at `width` x `height` and reads the result back.
    pub fn render(
        &mut self,
        scene: &Scene,
        width: u32,
        height: u32,
        kind: OutputKind,
    ) -> Result<Frame> {
        let max = self.gpu_max_dimension();
        if width == 0 || height == 0 || width > max || height > max {
            return Err(Error::Usage(format!(
                "image size {width}x{height} is outside 1..={max} per side on {}",
                self.gpu.info.name
            )));
        }
        self.ensure_sky(scene)?;
        let mut params = raymarch::RaymarchParams::new(scene, width, height);
        if let Some((_, sky)) = &self.sky {
            params.sky[1] = sky.desc.width as f32;
        }
        self.params
            .mapped_mut()?
            .copy_from_slice(bytemuck::bytes_of(&params));

        if kind == OutputKind::Geodesic && scene.disk.kind == crate::scene::DiskKind::Volumetric {
            return Err(Error::Usage(
                "--aov geodesic describes thin-disk hits; this scene's disk is volumetric".into(),
            ));
        }
        let texel_bytes: u64 = match kind {
            OutputKind::Ldr => 4,
            OutputKind::Hdr | OutputKind::HdrPost => 8,
            OutputKind::Geodesic => 16,
        };
        let needed = u64::from(width) * u64::from(height) * texel_bytes;
        self.ensure_readback(needed)?;
        let readback = self
            .readback
            .as_ref()
            .ok_or_else(|| Error::Other("readback buffer missing".into()))?;

        // Build the frame graph.
        let pipelines = &self.pipelines;
        let mut g = Graph::new(width, height);
        let mut out_buf = g.import_buffer(
            "readback",
            readback.binding(),
            Access::Nothing,
            Some(Access::HostRead),
        );
        let mode = match kind {
            OutputKind::Geodesic => raymarch::RaymarchOutput::Geodesic,
            OutputKind::Ldr | OutputKind::Hdr | OutputKind::HdrPost => {
                raymarch::RaymarchOutput::Beauty
            }
        };
        let lut = g.import_image(
            "disk lut",
            self.disk_lut.desc,
            self.disk_lut.binding(),
            Access::ComputeSampledRead,
            Some(Access::ComputeSampledRead),
        );
        let sky = match &self.sky {
            Some((_, image)) => g.import_image(
                "sky",
                image.desc,
                image.binding(),
                Access::ComputeSampledRead,
                Some(Access::ComputeSampledRead),
            ),
            None => lut.clone(),
        };
        let hdr = passes::raymarch::add_raymarch(
            &mut g,
            pipelines,
            self.params.buffer,
            &lut,
            &sky,
            mode,
            scene.black_holes.len() == 1 && scene.physics.gravity,
            scene.disk.kind == crate::scene::DiskKind::Volumetric,
        );
        let result = match kind {
            OutputKind::Ldr | OutputKind::HdrPost => {
                let bloom = passes::bloom::add_bloom(&mut g, pipelines, &hdr, &scene.bloom);
                composite::add_composite(
                    &mut g,
                    pipelines,
                    &hdr,
                    bloom.as_ref(),
                    &scene.bloom,
                    &scene.post,
                    kind == OutputKind::HdrPost,
                )
            }
            OutputKind::Hdr | OutputKind::Geodesic => hdr,
        };
        copy::add_copy_to_buffer(&mut g, &result, &mut out_buf);
        let names = run_graph(
            g,
            &self.gpu,
            &mut self.commands,
            &mut self.transients,
            self.timestamps.as_ref(),
        )?;

        let timings = self.read_timings(&names)?;
        let bytes = &readback.mapped()?[..needed as usize];
        let pixels = match kind {
            OutputKind::Ldr => Pixels::Rgba8(bytes.to_vec()),
            OutputKind::Hdr | OutputKind::HdrPost => Pixels::Rgba32F(
                bytes
                    .chunks_exact(2)
                    .map(|c| half::f16::from_le_bytes([c[0], c[1]]).to_f32())
                    .collect(),
            ),
            OutputKind::Geodesic => Pixels::Rgba32F(
                bytes
                    .chunks_exact(4)
                    .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]))
                    .collect(),
            ),
        };
        Ok(Frame {
            width,
            height,
            pixels,
            timings,
        })
    }

    /// Runs the post-processing chain (bloom, exposure, tone map) on an HDR
    /// image given as RGBA f32 rows, row 0 at the top; returns the 8-bit frame.
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
        let bytes: &[u8] = bytemuck::cast_slice(hdr);
        let mut staging = Buffer::new(
            &self.gpu,
            "post input staging",
            bytes.len() as u64,
            vk::BufferUsageFlags::TRANSFER_SRC,
            MemoryLocation::CpuToGpu,
        )?;
        staging.mapped_mut()?.copy_from_slice(bytes);
        let needed = 4 * texels as u64;
        self.ensure_readback(needed)?;
        let readback = self
            .readback
            .as_ref()
            .ok_or_else(|| Error::Other("readback buffer missing".into()))?;

        let pipelines = &self.pipelines;
        let mut g = Graph::new(width, height);
        let src = g.import_buffer(
            "post input staging",
            staging.binding(),
            Access::HostWrite,
            None,
        );
        let mut out_buf = g.import_buffer(
            "readback",
            readback.binding(),
            Access::Nothing,
            Some(Access::HostRead),
        );
        let mut input = g.create_relative("hdr input", vk::Format::R32G32B32A32_SFLOAT, 1, 1);
        copy::add_upload(&mut g, &src, &mut input, 16);
        let blur = passes::bloom::add_bloom(&mut g, pipelines, &input, bloom);
        let ldr =
            composite::add_composite(&mut g, pipelines, &input, blur.as_ref(), bloom, post, false);
        copy::add_copy_to_buffer(&mut g, &ldr, &mut out_buf);
        let names = run_graph(
            g,
            &self.gpu,
            &mut self.commands,
            &mut self.transients,
            self.timestamps.as_ref(),
        )?;
        let timings = self.read_timings(&names)?;
        let pixels = Pixels::Rgba8(readback.mapped()?[..needed as usize].to_vec());
        Ok(Frame {
            width,
            height,
            pixels,
            timings,
        })
    }

    /// Makes sure the readback buffer holds at least `needed` bytes.
    fn ensure_readback(&mut self, needed: u64) -> Result<()> {
        if self.readback.as_ref().is_none_or(|b| b.size < needed) {
            self.readback = None;
            self.readback = Some(Buffer::new(
                &self.gpu,
                "readback",
                needed,
                vk::BufferUsageFlags::TRANSFER_DST,
                MemoryLocation::GpuToCpu,
            )?);
        }
        Ok(())
    }

    /// Loads and uploads the scene's image sky if it differs from the one held.
    fn ensure_sky(&mut self, scene: &Scene) -> Result<()> {
        use crate::scene::SkyKind;
        let files = scene.sky.files(&scene.base_dir);
        if !matches!(scene.sky.kind, SkyKind::Image | SkyKind::Cubemap) {
            return Ok(());
        }
        if self.sky.as_ref().is_some_and(|(held, _)| *held == files) {
            return Ok(());
        }
        let texture = match scene.sky.kind {
            SkyKind::Cubemap => crate::sky::load_cubemap(&files)?,
            _ => crate::sky::load_equirect(
                files
                    .first()
                    .ok_or_else(|| Error::Scene("sky.kind = \"image\" needs sky.image".into()))?,
            )?,
        };
        let max = self.gpu_max_dimension();
        if texture.width > max || texture.height > max {
            return Err(Error::Scene(format!(
                "sky image {}x{} is larger than this device allows ({max} per side)",
                texture.width, texture.height
            )));
        }
        self.sky = None;
        let image = upload_sky(
            &self.gpu,
            &mut self.commands,
            &mut self.transients,
            &texture,
        )?;
        self.sky = Some((files, image));
        Ok(())
    }

    fn read_timings(&self, names: &[String]) -> Result<FrameTimings> {
        let Some(ts) = &self.timestamps else {
            return Ok(FrameTimings::default());
        };
        if graph::execute::timestamp_count(names.len()) > ts.capacity {
            return Ok(FrameTimings::default());
        }
        let ns = ts.read_ns(graph::execute::timestamp_count(names.len()))?;
        let passes = names
            .iter()
            .enumerate()
            .map(|(i, n)| PassTiming {
                name: n.clone(),
                ms: (ns[2 * i + 1] - ns[2 * i]) * 1e-6,
            })
            .collect();
        let frame_ms = ns.last().copied().unwrap_or(0.0) * 1e-6;
        Ok(FrameTimings { passes, frame_ms })
    }

    fn gpu_max_dimension(&self) -> u32 {
        // SAFETY: the physical device belongs to the live instance.
        unsafe {
            self.gpu
                .instance
                .instance
                .get_physical_device_properties(self.gpu.physical)
        }
        .limits
        .max_image_dimension2_d
    }
}

/// Compiles `g`, records it, submits and waits; returns the timed passes' names.
fn run_graph(
    g: Graph<'_>,
    gpu: &Gpu,
    commands: &mut CommandContext,
    transients: &mut TransientPool,
    timestamps: Option<&TimestampPool>,
) -> Result<Vec<String>> {
    let compiled = g.compile()?;
    let cmd = commands.begin()?;
    let names = graph::execute::execute(g, &compiled, gpu, cmd, transients, timestamps)?;
    commands.submit_and_wait()?;
    Ok(names)
}

/// Creates a sampled image and fills every mip level from `bytes` (levels
/// packed one after the other) through a one-pass graph; the image is left
/// ready for sampling in compute shaders.
fn upload_image(
    gpu: &Arc<Gpu>,
    commands: &mut CommandContext,
    transients: &mut TransientPool,
    name: &str,
    desc: ImageDesc,
    bytes: &[u8],
    texel_bytes: u64,
) -> Result<Image> {
    let image = Image::new(
        gpu,
        name,
        desc,
        vk::ImageUsageFlags::SAMPLED | vk::ImageUsageFlags::TRANSFER_DST,
    )?;
    let staging_name = format!("{name} staging");
    let mut staging = Buffer::new(
        gpu,
        &staging_name,
        bytes.len() as u64,
        vk::BufferUsageFlags::TRANSFER_SRC,
        MemoryLocation::CpuToGpu,
    )?;
    staging.mapped_mut()?.copy_from_slice(bytes);
    let mut g = Graph::new(desc.width, desc.height);
    let src = g.import_buffer(&staging_name, staging.binding(), Access::HostWrite, None);
    let mut dst = g.import_image(
        name,
        desc,
        image.binding(),
        Access::Nothing,
        Some(Access::ComputeSampledRead),
    );
    copy::add_upload(&mut g, &src, &mut dst, texel_bytes);
    run_graph(g, gpu, commands, transients, None)?;
    Ok(image)
}

/// Builds the blackbody colour table on the CPU and uploads it.
fn upload_disk_lut(
    gpu: &Arc<Gpu>,
    commands: &mut CommandContext,
    transients: &mut TransientPool,
) -> Result<Image> {
    use crate::physics::blackbody;
    let texels = blackbody::lut_rgba();
    let desc = ImageDesc::new_2d(
        vk::Format::R32G32B32A32_SFLOAT,
        blackbody::LUT_SIZE as u32,
        1,
    );
    upload_image(
        gpu,
        commands,
        transients,
        "disk lut",
        desc,
        bytemuck::cast_slice(&texels),
        16,
    )
}

/// Uploads a sky panorama with its mips as RGBA16F.
fn upload_sky(
    gpu: &Arc<Gpu>,
    commands: &mut CommandContext,
    transients: &mut TransientPool,
    texture: &crate::sky::SkyTexture,
) -> Result<Image> {
    let desc = ImageDesc::new_2d(
        vk::Format::R16G16B16A16_SFLOAT,
        texture.width,
        texture.height,
    )
    .with_mips(texture.levels.len() as u32);
    let halves: Vec<half::f16> = texture.levels[..desc.mip_levels as usize]
        .iter()
        .flatten()
        .flat_map(|t| t.map(half::f16::from_f32))
        .collect();
    upload_image(
        gpu,
        commands,
        transients,
        "sky",
        desc,
        bytemuck::cast_slice(&halves),
        8,
    )
}
