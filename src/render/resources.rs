//! Resources kept across frames and shared by every frame slot: the blackbody
//! colour table and the scene's image sky, uploaded once through one-pass
//! graphs of their own.

use std::path::PathBuf;
use std::sync::Arc;

use ash::vk;
use gpu_allocator::MemoryLocation;

use super::noise::{NOISE_SIZE, VOLUME_NOISE_SIZE, disk_noise, volume_noise};
use crate::graph::{self, Graph, TransientPool};
use crate::passes::copy;
use crate::scene::{DiskKind, Scene, SkyKind};
use crate::vk::{Access, Buffer, CommandContext, Gpu, Image, ImageDesc};
use crate::{Error, Result};

/// The colour table and the image sky in use, with the command buffer and
/// pool their uploads use (separate from the frame slots').
pub struct SceneResources {
    pub disk_lut: Image,
    /// The thin disk's tileable noise ([`disk_noise`]).
    pub disk_noise: Image,
    /// The volumetric disk's tileable noise volume ([`volume_noise`]): a
    /// 1x1x1 placeholder until a scene with a volumetric disk needs it.
    pub volume_noise: Image,
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
        let volume_noise = upload_image(
            gpu,
            &mut commands,
            &mut transients,
            "volume noise",
            ImageDesc::new_3d(vk::Format::R8G8B8A8_UNORM, 1, 1, 1),
            &[128, 128, 128, 128],
            4,
        )?;
        Ok(SceneResources {
            disk_lut,
            disk_noise,
            volume_noise,
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

    /// Whether `scene` needs the noise volume and only the placeholder is
    /// held (the caller must then wait for every frame in flight before
    /// [`SceneResources::ensure_volume`] replaces it).
    pub fn volume_changes(&self, scene: &Scene) -> bool {
        scene.disk.kind == DiskKind::Volumetric && self.volume_noise.desc.depth == 1
    }

    /// Builds and uploads the noise volume if `scene` needs it and it is not
    /// held yet (about 0.1 s, once).
    pub fn ensure_volume(&mut self, scene: &Scene) -> Result<()> {
        if !self.volume_changes(scene) {
            return Ok(());
        }
        let [w, h, d] = VOLUME_NOISE_SIZE;
        let texels = volume_noise();
        self.volume_noise = upload_image(
            &self.gpu,
            &mut self.commands,
            &mut self.transients,
            "volume noise",
            ImageDesc::new_3d(vk::Format::R8G8B8A8_UNORM, w, h, d),
            &texels,
            4,
        )?;
        Ok(())
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
