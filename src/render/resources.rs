//! Resources kept across frames and shared by every frame slot: the blackbody
//! colour table and the scene's image sky, uploaded once through one-pass
//! graphs of their own.

use std::path::PathBuf;
use std::sync::Arc;

use ash::vk;
use gpu_allocator::MemoryLocation;

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

/// Texels of the noise volume along x, y (the disk's axis) and z.
pub const VOLUME_NOISE_SIZE: [u32; 3] = [128, 64, 128];

/// The noise volume's period in lattice units of its first octave. The ray
/// march reads it at 1.6 lattice units per noise unit (the shader's noise
/// coordinates: the disk frame scaled by `noise_scale`, height stretched
/// four times), so it repeats every 10 noise units across (12.5 rs at the
/// default scale; the Keplerian shear turns each radius by its own angle as
/// the disk turns) and every 5 along the axis (more than the whole slab at
/// the default height and scale).
pub const VOLUME_NOISE_PERIOD: [f64; 3] = [16.0, 8.0, 16.0];

/// The volumetric disk's noise: three octaves of periodic Perlin gradient
/// noise (lattice spacing 1, 1/2 and 1/4 noise units), one per channel
/// (r, g, b; a unused), each in [0, 1] around 0.5. The ray march reads the
/// volume with a repeating trilinear sampler and sums the channels it needs
/// (raymarch.comp, `volume_density`): one fetch for three octaves instead of
/// three evaluations of simplex noise per sample, and a second fetch at
/// eight times the frequency for octaves four to six.
pub fn volume_noise() -> Vec<u8> {
    let [w, h, d] = VOLUME_NOISE_SIZE.map(|v| v as usize);
    let hash = |x: u32, y: u32, z: u32, o: u32| -> u32 {
        let mut v = x
            .wrapping_mul(0x8da6_b343)
            .wrapping_add(y.wrapping_mul(0xd816_3841))
            .wrapping_add(z.wrapping_mul(0xcb1a_b31f))
            .wrapping_add(o.wrapping_mul(0x1656_67b1));
        v ^= v >> 15;
        v = v.wrapping_mul(0x2c1b_3c6d);
        v ^= v >> 12;
        v = v.wrapping_mul(0x297a_2d39);
        v ^= v >> 15;
        v
    };
    // Perlin's twelve edge gradients.
    const G: [[f64; 3]; 12] = [
        [1.0, 1.0, 0.0],
        [-1.0, 1.0, 0.0],
        [1.0, -1.0, 0.0],
        [-1.0, -1.0, 0.0],
        [1.0, 0.0, 1.0],
        [-1.0, 0.0, 1.0],
        [1.0, 0.0, -1.0],
        [-1.0, 0.0, -1.0],
        [0.0, 1.0, 1.0],
        [0.0, -1.0, 1.0],
        [0.0, 1.0, -1.0],
        [0.0, -1.0, -1.0],
    ];
    let fade = |t: f64| t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
    let lerp = |a: f64, b: f64, t: f64| a + t * (b - a);
    let mut out = vec![0u8; w * h * d * 4];
    for octave in 0..3u32 {
        let freq = f64::from(1u32 << octave);
        // Lattice cells along each axis in one period.
        let cells = VOLUME_NOISE_PERIOD.map(|p| (p * freq).round() as u32);
        for z in 0..d {
            for y in 0..h {
                for x in 0..w {
                    let p = [
                        x as f64 / w as f64 * f64::from(cells[0]),
                        y as f64 / h as f64 * f64::from(cells[1]),
                        z as f64 / d as f64 * f64::from(cells[2]),
                    ];
                    let i = p.map(|v| v.floor());
                    let f = [p[0] - i[0], p[1] - i[1], p[2] - i[2]];
                    let corner = |dx: u32, dy: u32, dz: u32| -> f64 {
                        let c = [
                            (i[0] as u32 + dx) % cells[0],
                            (i[1] as u32 + dy) % cells[1],
                            (i[2] as u32 + dz) % cells[2],
                        ];
                        let g = G[(hash(c[0], c[1], c[2], octave) % 12) as usize];
                        g[0] * (f[0] - f64::from(dx))
                            + g[1] * (f[1] - f64::from(dy))
                            + g[2] * (f[2] - f64::from(dz))
                    };
                    let (u, v, t) = (fade(f[0]), fade(f[1]), fade(f[2]));
                    let n = lerp(
                        lerp(
                            lerp(corner(0, 0, 0), corner(1, 0, 0), u),
                            lerp(corner(0, 1, 0), corner(1, 1, 0), u),
                            v,
                        ),
                        lerp(
                            lerp(corner(0, 0, 1), corner(1, 0, 1), u),
                            lerp(corner(0, 1, 1), corner(1, 1, 1), u),
                            v,
                        ),
                        t,
                    );
                    let texel = ((z * h + y) * w + x) * 4;
                    out[texel + octave as usize] =
                        ((n * 0.5 + 0.5).clamp(0.0, 1.0) * 255.0).round() as u8;
                }
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each octave of the noise volume is centred on 0.5 with the spread
    /// of simplex noise (the contrast curve in volume.glsl was tuned on
    /// simplex noise), and tiles: the last texel continues into the first.
    #[test]
    fn the_noise_volume_has_three_centred_octaves_that_tile() {
        let v = volume_noise();
        let [w, h, d] = VOLUME_NOISE_SIZE.map(|v| v as usize);
        assert_eq!(v.len(), w * h * d * 4);
        for octave in 0..3 {
            let vals: Vec<f64> = v
                .iter()
                .skip(octave)
                .step_by(4)
                .map(|&b| f64::from(b) / 255.0 * 2.0 - 1.0)
                .collect();
            let mean = vals.iter().sum::<f64>() / vals.len() as f64;
            let std =
                (vals.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / vals.len() as f64).sqrt();
            eprintln!("octave {octave}: mean {mean:.4}, std {std:.4}");
            assert!(mean.abs() < 0.02, "octave {octave}: mean {mean}");
            assert!((0.2..0.35).contains(&std), "octave {octave}: std {std}");
        }
        // Neighbouring texels across the wrap differ as little as inside.
        let at = |x: usize, y: usize, z: usize| f64::from(v[((z * h + y) * w + x) * 4]);
        let (mut across, mut inside) = (0.0, 0.0);
        for z in 0..d {
            for y in 0..h {
                across += (at(w - 1, y, z) - at(0, y, z)).abs();
                inside += (at(w / 2 - 1, y, z) - at(w / 2, y, z)).abs();
            }
        }
        assert!(
            across < 1.5 * inside,
            "across the wrap {across}, inside {inside}"
        );
    }
}
