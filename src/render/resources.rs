//! Resources kept across frames and shared by every frame slot: the blackbody
//! colour table and the scene's image sky, uploaded once through one-pass
//! graphs of their own.

use std::path::PathBuf;
use std::sync::Arc;

use ash::vk;
use gpu_allocator::MemoryLocation;

use crate::graph::{self, Graph, TransientPool};
use crate::passes::copy;
use crate::scene::{Scene, SkyKind};
use crate::vk::{Access, Buffer, CommandContext, Gpu, Image, ImageDesc};
use crate::{Error, Result};

/// The colour table and the image sky in use, with the command buffer and
/// pool their uploads use (separate from the frame slots').
pub struct SceneResources {
    pub disk_lut: Image,
    /// The thin disk's tileable noise ([`disk_noise`]).
    pub disk_noise: Image,
    /// The image sky in use, with the files it came from.
    pub sky: Option<(Vec<PathBuf>, Image)>,
    transients: TransientPool,
    commands: CommandContext,
    gpu: Arc<Gpu>,
}

impl SceneResources {
    /// Builds and uploads the colour table.
    pub fn new(gpu: &Arc<Gpu>) -> Result<Self> {
        let mut commands = CommandContext::new(gpu)?;
        let mut transients = TransientPool::new(gpu);
        let disk_lut = upload_disk_lut(gpu, &mut commands, &mut transients)?;
        let texels = disk_noise();
        let disk_noise = upload_image(
            gpu,
            &mut commands,
            &mut transients,
            "disk noise",
            ImageDesc::new_2d(vk::Format::R8_UNORM, NOISE_SIZE, NOISE_SIZE),
            &texels,
            1,
        )?;
        Ok(SceneResources {
            disk_lut,
            disk_noise,
            sky: None,
            transients,
            commands,
            gpu: gpu.clone(),
        })
    }

    /// Whether `scene` needs a different image sky from the one held (the
    /// caller must then wait for every frame in flight before
    /// [`SceneResources::ensure_sky`] replaces it).
    pub fn sky_changes(&self, scene: &Scene) -> bool {
        matches!(
            scene.sky.kind,
            SkyKind::Image | SkyKind::Cubemap | SkyKind::Catalogue
        ) && self
            .sky
            .as_ref()
            .is_none_or(|(held, _)| *held != sky_sources(scene))
    }

    /// Loads and uploads the scene's image sky if it differs from the one held.
    pub fn ensure_sky(&mut self, scene: &Scene) -> Result<()> {
        let files = sky_sources(scene);
        if !matches!(
            scene.sky.kind,
            SkyKind::Image | SkyKind::Cubemap | SkyKind::Catalogue
        ) {
            return Ok(());
        }
        if self.sky.as_ref().is_some_and(|(held, _)| *held == files) {
            return Ok(());
        }
        let texture = match scene.sky.kind {
            SkyKind::Cubemap => crate::sky::load_cubemap(&files)?,
            SkyKind::Catalogue => {
                let stars = crate::stars::parse(crate::stars::HIPPARCOS)?;
                let n = crate::stars::GRID;
                crate::sky::SkyTexture {
                    width: 6 * n,
                    height: n,
                    levels: crate::stars::star_grid(&stars),
                    full_precision: true,
                }
            }
            _ => crate::sky::load_equirect(
                files
                    .first()
                    .ok_or_else(|| Error::Scene("sky.kind = \"image\" needs sky.image".into()))?,
            )?,
        };
        let max = self.gpu.max_image_dimension();
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
}

/// What a scene's sky texture is made from: its image files, or for the
/// catalogue sky a name standing for the built-in table.
fn sky_sources(scene: &Scene) -> Vec<PathBuf> {
    match scene.sky.kind {
        SkyKind::Catalogue => vec![PathBuf::from("(the built-in Hipparcos table)")],
        _ => scene.sky.files(&scene.base_dir),
    }
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
    let compiled = g.compile()?;
    let cmd = commands.begin()?;
    graph::execute::execute(g, &compiled, gpu, cmd, transients, None)?;
    commands.submit_and_wait()?;
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
    let levels = &texture.levels[..];
    if texture.full_precision {
        let desc = ImageDesc::new_2d(
            vk::Format::R32G32B32A32_SFLOAT,
            texture.width,
            texture.height,
        )
        .with_mips(levels.len() as u32);
        let texels: Vec<[f32; 4]> = levels.iter().flatten().copied().collect();
        return upload_image(
            gpu,
            commands,
            transients,
            "sky",
            desc,
            bytemuck::cast_slice(&texels),
            16,
        );
    }
    let desc = ImageDesc::new_2d(
        vk::Format::R16G16B16A16_SFLOAT,
        texture.width,
        texture.height,
    )
    .with_mips(levels.len() as u32);
    let halves: Vec<half::f16> = levels
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

/// Side of the thin disk's noise texture, texels.
pub const NOISE_SIZE: u32 = 256;

/// The thin disk's structure: tileable value noise, four octaves of a
/// periodic lattice (8, 16, 32, 64 cells across) with quintic smoothing,
/// as 8-bit texels (mean about 0.5). The ray march reads it in the
/// co-moving angle and log radius (raymarch.comp, `thin_disk_density`):
/// one filtered fetch instead of octaves of procedural noise per pixel.
pub fn disk_noise() -> Vec<u8> {
    let n = NOISE_SIZE as usize;
    let hash = |x: u32, y: u32, o: u32| -> f32 {
        let mut v = x
            .wrapping_mul(0x8da6_b343)
            .wrapping_add(y.wrapping_mul(0xd816_3841))
            .wrapping_add(o.wrapping_mul(0xcb1a_b31f));
        v ^= v >> 15;
        v = v.wrapping_mul(0x2c1b_3c6d);
        v ^= v >> 12;
        v = v.wrapping_mul(0x297a_2d39);
        v ^= v >> 15;
        (v >> 8) as f32 / (1u32 << 24) as f32
    };
    let smooth = |t: f32| t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
    let mut field = vec![0.0f32; n * n];
    let mut amp = 1.0f32;
    let mut total = 0.0f32;
    for (octave, cells) in [8u32, 16, 32, 64].into_iter().enumerate() {
        let step = n as f32 / cells as f32;
        for y in 0..n {
            for x in 0..n {
                let (fx, fy) = (x as f32 / step, y as f32 / step);
                let (x0, y0) = (fx.floor() as u32, fy.floor() as u32);
                let (tx, ty) = (smooth(fx.fract()), smooth(fy.fract()));
                let o = octave as u32;
                let at = |i: u32, j: u32| hash(i % cells, j % cells, o);
                let top = at(x0, y0) + tx * (at(x0 + 1, y0) - at(x0, y0));
                let bottom = at(x0, y0 + 1) + tx * (at(x0 + 1, y0 + 1) - at(x0, y0 + 1));
                field[y * n + x] += amp * (top + ty * (bottom - top));
            }
        }
        total += amp;
        amp *= 0.55;
    }
    field
        .iter()
        .map(|v| ((v / total).clamp(0.0, 1.0) * 255.0).round() as u8)
        .collect()
}
