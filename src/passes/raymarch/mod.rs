//! The ray march: one compute invocation per pixel follows the camera ray
//! and writes linear HDR radiance (or the geodesic AOV). Which path it takes
//! is a specialisation of the shader ([`Variant`]): one hole with gravity,
//! the closed-form light path (shaders/include/lightpath.glsl, the
//! conventions in the README, "Physics"); gravity off, a straight line;
//! several holes, the spatial-orbit form x'' = -1.5 rs h^2 x / r^5 of the
//! null geodesic equation (from Binet's equation u'' + u = 1.5 rs u^2)
//! integrated in Cartesian coordinates with adaptive Dormand-Prince 5(4),
//! so the holes' pulls can be summed.
//!
//! One hole with a thin disk is split in two dispatches (on devices with
//! subgroup ballots): `raymarch` traces every pixel's path to the sky or the
//! horizon and lists the pixels whose path crosses the disk's annulus;
//! `raymarch disk`, dispatched indirectly over that list, adds the disk's
//! light in front of what `raymarch` wrote. On a CPU driver every branch of
//! a shader costs every pixel, taken or not, so in one dispatch the disk's
//! crossings cost the whole frame; split, they cost the pixels that cross it
//! (a quarter of the default view). Those pixels pay for their path twice,
//! so where the disk fills much of the view the one dispatch is cheaper:
//! [`split_pays`] estimates the disk's share of the frame on the CPU.
//!
//! A spinning hole splits by its paths instead (any disk): `raymarch`
//! carries the common ones (shaders/include/metric/kerr.glsl,
//! `KERR_COMMON_ONLY`: the radial case 2 whose turning point lies outside
//! the horizon, the polar motion that crosses the equator) with the code of
//! the others compiled out, and lists the 2x2 quads where a path needs the
//! rest; `raymarch rare` redoes those quads with the whole shader, ray
//! differentials and all. The trace pass takes the build with 32-bit roots
//! and defers the paths near the shadow's edge too; the second pass keeps
//! the device's. In the default view at a* = 0.9 it defers about 4 % of the
//! pixels (the disk in front of the shadow) and the frame falls from about
//! 4.5 to 5.3 times the non-rotating one's on lavapipe to 2.0 to 2.3.

use ash::vk;

pub mod params;

pub use params::{FrameSpec, RaymarchParams};
use params::{disk_kind, sky_kind};

use std::sync::Arc;

use super::{VariantCache, dispatch_2d, dispatch_indirect};
use crate::Result;
use crate::graph::{BufferHandle, Graph, ImageDesc, ImageHandle, Mips};
use crate::render::Features;
use crate::scene::{DiskKind, Scene, VolumeColor};
use crate::shaders::{self, RaymarchBuild};
use crate::spacetime::{GpuPath, Spacetime};
use crate::vk::{Access, BindingKind, Buffer, ComputePipeline, Descriptor, Gpu, Sampler};

/// Constants mirrored from `shaders/include/params.glsl` (tests/layout.rs
/// checks them against the GLSL source).
pub mod glsl {
    pub const MAX_HOLES: u32 = 8;
    pub const DISK_NONE: u32 = 0;
    pub const DISK_THIN: u32 = 1;
    pub const DISK_VOLUME: u32 = 2;
    pub const SKY_BLACK: u32 = 0;
    pub const SKY_CHECKER: u32 = 1;
    pub const SKY_STARS: u32 = 2;
    pub const SKY_IMAGE: u32 = 3;
    pub const SKY_CATALOGUE: u32 = 4;
    pub const DISK_STAGE_ALL: u32 = 0;
    pub const DISK_STAGE_TRACE: u32 = 1;
    pub const DISK_STAGE_DISK: u32 = 2;
    pub const PROJ_PINHOLE: u32 = 0;
    pub const PROJ_EQUIRECT: u32 = 1;
    pub const PROJ_FISHEYE: u32 = 2;
    pub const STEREO_NONE: u32 = 0;
    pub const STEREO_ODS: u32 = 1;
    /// Workgroups (of 64 listed pixels) in one row of the disk pass's
    /// indirect dispatch.
    pub const DISK_ROW: u32 = 256;
    pub const LUT_MIN_K: f64 = crate::physics::blackbody::LUT_MIN_K;
    pub const LUT_MAX_K: f64 = crate::physics::blackbody::LUT_MAX_K;
}

/// HDR format written by the ray march.
pub const HDR_FORMAT: vk::Format = vk::Format::R16G16B16A16_SFLOAT;
/// Format of the geodesic AOV (full f32: directions to 1e-7).
pub const AOV_FORMAT: vk::Format = vk::Format::R32G32B32A32_SFLOAT;

/// What the ray march writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum RaymarchOutput {
    /// Linear HDR radiance.
    Beauty,
    /// The geodesic AOV in the README.
    Geodesic,
}

/// The images every ray march reads, kept across frames
/// (`render::resources`) and imported into each frame's graph.
pub struct SceneImages {
    pub disk_lut: ImageHandle,
    /// The thin disk's tileable noise (`render::noise::disk_noise`).
    pub disk_noise: ImageHandle,
    /// The volumetric disk's noise volume (`render::noise::volume_noise`;
    /// a 1x1x1 placeholder for other disks).
    pub volume_noise: ImageHandle,
    /// The image sky, when the sky is an image.
    pub sky: Option<ImageHandle>,
}

/// What the ray march reads: the host-written parameter block and the images.
pub struct RaymarchInputs<'h> {
    /// The [`RaymarchParams`] buffer, written by the host this frame.
    pub params: &'h BufferHandle,
    pub images: &'h SceneImages,
    pub output: RaymarchOutput,
    /// Size of the image it writes (the window may render at a fraction).
    pub size: (u32, u32),
    /// Which specialisation of the shader the scene needs.
    pub variant: Variant,
    /// Split the thin disk off into its own pass if the device can
    /// ([`split_pays`]).
    pub split: bool,
}

/// The largest share of the pixels crossing the thin disk at which the split
/// ray march pays. Measured on lavapipe at 1280x720 (frame ms, split against
/// one dispatch, by the share of disk pixels): falling 4 % 57 / 68, edge-on
/// 13 % 50 / 58, default 23 % 55 / 60, top-down 49 % 67 / 61, doppler 60 %
/// 80 / 62; the difference crosses zero near a third.
pub const SPLIT_MAX_DISK_SHARE: f64 = 0.3;

/// The largest share of the pixels whose paths the spinning hole's trace
/// pass defers at which its split ray march pays (the deferred 2x2 quads
/// cost the whole shader again, about twice the trace pass's per pixel).
pub const SPLIT_MAX_DEFERRED_SHARE: f64 = 0.3;

/// Whether splitting the ray march pays for this frame: the share of a 16 x
/// 9 grid of the frame's rays, traced in closed form on the CPU (about 0.1
/// ms), that cross the thin disk's annulus (one non-rotating hole) is below
/// [`SPLIT_MAX_DISK_SHARE`], or that the spinning hole's trace pass would
/// defer ([`crate::spacetime::SpinningHole::defers`]) is below
/// [`SPLIT_MAX_DEFERRED_SHARE`]. (Asked only through
/// [`crate::render::Features::splits`], where the device splits at all.)
pub fn split_pays(scene: &Scene, width: u32, height: u32) -> bool {
    let spacetime = Spacetime::of(scene);
    let disk = crate::physics::Disk {
        normal: glam::DVec3::from(scene.disk.normal),
        inner: scene.disk.inner_radius,
        outer: scene.disk.outer_radius,
    };
    let thin = (scene.disk.kind == DiskKind::Thin).then_some(&disk);
    let frame = scene.camera.frame();
    let observer = scene.observer();
    // The share of a grid's rays for which `counts` holds.
    let share = |counts: &dyn Fn(glam::DVec3, glam::DVec3) -> bool| {
        let (cols, rows) = (16u32, 9u32);
        let mut n = 0;
        for row in 0..rows {
            for col in 0..cols {
                // The pixel at the centre of each cell of the grid.
                let x = ((2 * col + 1) * width / (2 * cols)).min(width - 1);
                let y = ((2 * row + 1) * height / (2 * rows)).min(height - 1);
                let Some(ray) = frame.pixel_ray(x, y, width, height, (0.0, 0.0)) else {
                    continue;
                };
                if counts(ray.origin, observer.coordinate_direction(ray.dir)) {
                    n += 1;
                }
            }
        }
        f64::from(n) / f64::from(cols * rows)
    };
    match &spacetime {
        Spacetime::Kerr(hole) => {
            share(&|x0, d| hole.defers(thin, x0, d)) < SPLIT_MAX_DEFERRED_SHARE
        }
        Spacetime::Schwarzschild(_) if thin.is_some() => {
            let on_disk = |x0, d| {
                let outcome = spacetime.trace(thin, x0, d, &Default::default());
                matches!(outcome, crate::physics::Outcome::Disk { .. })
            };
            share(&on_disk) < SPLIT_MAX_DISK_SHARE
        }
        _ => false,
    }
}

/// A build of raymarch.comp (its metric, and the AOV build) and its
/// specialisation constants.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Variant {
    /// The geodesic AOV build (`GEODESIC_AOV`).
    pub aov: bool,
    /// The metric compiled in (`shaders/include/metric.glsl`).
    pub path: GpuPath,
    /// The disk kind, `glsl::DISK_*` (constant 0).
    pub disk: u32,
    /// The sky kind, `glsl::SKY_*` (constant 1).
    pub sky: u32,
    /// The grid plane is on (constant 2).
    pub plane: bool,
    /// The disk is seen as it was when its light left (constant 3).
    pub light_delay: bool,
    /// The thin disk's filaments and clumps (constant 4).
    pub structure: bool,
    /// Thin-disk crossings a ray may see: 2 where light comes through it
    /// (constant 5).
    pub thin_crossings: u32,
    /// The volumetric disk glows as a blackbody (else the colour map)
    /// (constant 6).
    pub volume_blackbody: bool,
    /// The part of the split thin-disk ray march, `glsl::DISK_STAGE_*`
    /// (constant 7).
    pub disk_stage: u32,
    /// The observer moves through the static frame: aberration (constant 8).
    pub observer_moves: bool,
    /// The thin disk's temperature is Page and Thorne's (constant 9).
    pub page_thorne: bool,
    /// `camera::Projection` as a number (constant 10).
    pub projection: u32,
}

impl Variant {
    /// The variant a scene needs.
    pub fn of(scene: &Scene, aov: bool) -> Variant {
        Variant {
            aov,
            path: Spacetime::of(scene).gpu_path(),
            disk: disk_kind(scene),
            sky: sky_kind(scene),
            plane: scene.plane.enabled,
            light_delay: scene.animation.light_travel_time && !aov,
            structure: scene.disk.structure > 0.0,
            thin_crossings: if scene.disk.structure > 0.0 || scene.disk.opacity < 1.0 {
                2
            } else {
                1
            },
            volume_blackbody: scene.disk.color == VolumeColor::Blackbody,
            disk_stage: glsl::DISK_STAGE_ALL,
            observer_moves: scene.observer().beta != glam::DVec3::ZERO,
            page_thorne: scene.disk.temperature_profile
                == crate::scene::TemperatureProfile::PageThorne,
            projection: match scene.camera.projection {
                crate::camera::Projection::Pinhole => glsl::PROJ_PINHOLE,
                crate::camera::Projection::Equirect => glsl::PROJ_EQUIRECT,
                crate::camera::Projection::Fisheye => glsl::PROJ_FISHEYE,
            },
        }
    }

    /// The pipelines one frame of this variant runs, in order: the trace and
    /// disk passes for one hole with a thin disk when `split` (the device
    /// has subgroup ballots), else itself.
    pub fn stages(self, split: bool) -> Vec<Variant> {
        let splits = match self.path {
            GpuPath::ClosedForm => self.disk == glsl::DISK_THIN,
            GpuPath::Kerr => true,
            GpuPath::Straight | GpuPath::Integrated => false,
        };
        if split && splits && !self.aov {
            [glsl::DISK_STAGE_TRACE, glsl::DISK_STAGE_DISK]
                .map(|disk_stage| Variant { disk_stage, ..self })
                .to_vec()
        } else {
            vec![self]
        }
    }

    /// The GLSL names of [`Variant::constants`], in `constant_id` order
    /// (tests/layout.rs checks them against include/variant.glsl).
    pub const CONSTANT_NAMES: [&'static str; 11] = [
        "DISK_KIND",
        "SKY_KIND",
        "GRID_PLANE",
        "LIGHT_DELAY",
        "THIN_STRUCTURE",
        "THIN_CROSSINGS",
        "VOLUME_BLACKBODY",
        "DISK_STAGE",
        "OBSERVER_MOVES",
        "PAGE_THORNE",
        "PROJECTION",
    ];

    pub fn constants(&self) -> [u32; 11] {
        [
            self.disk,
            self.sky,
            u32::from(self.plane),
            u32::from(self.light_delay),
            u32::from(self.structure),
            self.thin_crossings,
            u32::from(self.volume_blackbody),
            self.disk_stage,
            u32::from(self.observer_moves),
            u32::from(self.page_thorne),
            self.projection,
        ]
    }

    pub fn name(&self) -> String {
        format!(
            "raymarch{} ({:?}, disk {}, sky {}, plane {}, light delay {}, structure {}, crossings {}, volume blackbody {}, disk stage {}, observer moves {}, page-thorne {}, projection {})",
            if self.aov { " aov" } else { "" },
            self.path,
            self.disk,
            self.sky,
            self.plane,
            self.light_delay,
            self.structure,
            self.thin_crossings,
            self.volume_blackbody,
            self.disk_stage,
            self.observer_moves,
            self.page_thorne,
            self.projection
        )
    }
}

/// The parameter block is a read-only storage buffer, not a uniform buffer:
/// on Mesa's lavapipe (22.3) every dispatch that read a uniform buffer
/// leaked about 0.55 MB inside the driver until the device was destroyed
/// (1,000 frames at 160x90 took 640 MB; the same with a storage buffer, 120
/// MB) and cost twice the time. Found by skipping one pass's dispatch at a
/// time. Bindings 6 and 7 are the split thin-disk ray march's work list and
/// indirect dispatch.
const RAYMARCH_BINDINGS: [BindingKind; 8] = [
    BindingKind::StorageImage,
    BindingKind::StorageBuffer,
    BindingKind::SampledImage,
    BindingKind::SampledImage,
    BindingKind::SampledImage,
    BindingKind::SampledImage,
    BindingKind::StorageBuffer,
    BindingKind::StorageBuffer,
];

/// The ray march's pipelines by variant (built the first time a scene needs
/// one), its samplers and the buffer bound where a stage's work list is
/// absent, owned by this pass; and what the renderer does on this device.
pub struct RaymarchPipelines {
    cache: VariantCache<Variant>,
    gpu: Arc<Gpu>,
    features: Features,
    linear_clamp: Sampler,
    sky_sampler: Sampler,
    repeat_sampler: Sampler,
    placeholder: Buffer,
}

impl RaymarchPipelines {
    pub fn new(gpu: &Arc<Gpu>, features: Features) -> Result<Self> {
        Ok(RaymarchPipelines {
            cache: VariantCache::new(),
            gpu: gpu.clone(),
            features,
            linear_clamp: Sampler::linear_clamp(gpu)?,
            sky_sampler: Sampler::linear_repeat_u(gpu)?,
            repeat_sampler: Sampler::linear_repeat(gpu)?,
            placeholder: super::placeholder_buffer(gpu)?,
        })
    }

    /// The ray march specialised for a scene's variant (the specialization
    /// constants of include/variant.glsl), built on first use and kept. Code
    /// a scene does not use is compiled out, not just skipped: on a CPU
    /// driver such as lavapipe every branch runs under a mask for every
    /// pixel, so a branch not taken costs as much as one taken.
    pub fn pipeline(&self, variant: Variant) -> Result<Arc<ComputePipeline>> {
        self.cache.get(variant, || {
            let build = if variant.aov {
                RaymarchBuild::Aov
            } else if variant.disk_stage != glsl::DISK_STAGE_ALL {
                RaymarchBuild::Split
            } else if self.features.ray_differentials {
                RaymarchBuild::Beauty
            } else {
                RaymarchBuild::NoQuad
            };
            // The spinning hole's split trace pass takes the 32-bit roots
            // (it defers the paths near the shadow's edge, where they lose
            // precision, to the second pass, which keeps the device's).
            let trace = variant.disk_stage == glsl::DISK_STAGE_TRACE;
            let kerr_f64 = self.features.kerr_f64 && !(variant.path == GpuPath::Kerr && trace);
            let spirv = shaders::raymarch(variant.path, build, kerr_f64).ok_or_else(|| {
                crate::Error::Other(format!(
                    "no {build:?} build of the ray march for {variant:?}"
                ))
            })?;
            ComputePipeline::with_constants(
                &self.gpu,
                &variant.name(),
                spirv,
                &RAYMARCH_BINDINGS,
                0,
                &variant.constants(),
            )
        })
    }

    /// What the renderer does on this device.
    pub fn features(&self) -> Features {
        self.features
    }

    /// The ray-march pipelines one frame of `variant` runs on this device
    /// ([`Variant::stages`]), split if `split` and the device can.
    pub fn stages(&self, variant: Variant, split: bool) -> Vec<Variant> {
        variant.stages(split && self.features.disk_split)
    }
}

/// Adds the ray march; returns the HDR image (or the AOV) it writes.
pub fn add_raymarch<'a>(
    graph: &mut Graph<'a>,
    pipelines: &'a RaymarchPipelines,
    inputs: RaymarchInputs<'_>,
) -> ImageHandle {
    let RaymarchInputs {
        params,
        images,
        output,
        size: (width, height),
        variant,
        split,
    } = inputs;
    let (name, format) = match output {
        RaymarchOutput::Beauty => ("hdr", HDR_FORMAT),
        RaymarchOutput::Geodesic => ("geodesic aov", AOV_FORMAT),
    };
    let mut hdr = graph.create_image(name, ImageDesc::new_2d(format, width, height));
    // The dispatches share everything but the image, variant and stage.
    let stage = |graph: &mut Graph<'a>, hdr: &mut ImageHandle, variant, stage: Stage<'_>| {
        add_stage(graph, pipelines, params, images, hdr, variant, stage);
    };
    let stages = pipelines.stages(variant, split);
    let [trace, disk] = stages[..] else {
        stage(graph, &mut hdr, variant, Stage::Whole);
        return hdr;
    };

    // The disk pass's work list (a count, then one packed pixel each; whole
    // 2x2 quads for a split by paths, so up to the size rounded up to even)
    // and its indirect dispatch, emptied first.
    let pixels = u64::from(width.next_multiple_of(2)) * u64::from(height.next_multiple_of(2));
    let mut work = DiskWork {
        list: graph.create_buffer("disk list", 4 + 4 * pixels),
        dispatch: graph.create_buffer("disk dispatch", 16),
    };
    let mut pass = graph.add_pass("disk list clear");
    let list = pass.write_buffer(&mut work.list, Access::TransferWrite);
    let dispatch = pass.write_buffer(&mut work.dispatch, Access::TransferWrite);
    pass.record(move |ctx| {
        let (list, dispatch) = (ctx.buffer(&list), ctx.buffer(&dispatch));
        // SAFETY: recording; both ranges lie inside the buffers.
        unsafe {
            ctx.gpu.device.cmd_fill_buffer(ctx.cmd, list, 0, 4, 0);
            ctx.gpu.device.cmd_update_buffer(
                ctx.cmd,
                dispatch,
                0,
                // groups_y grows from 0 with groups_x (rows of DISK_ROW).
                bytemuck::bytes_of(&[0u32, 0, 1, 0]),
            );
        }
        Ok(())
    });
    stage(graph, &mut hdr, trace, Stage::Trace(&mut work));
    stage(graph, &mut hdr, disk, Stage::Disk(&work));
    hdr
}

/// The split ray march's work list and its indirect dispatch.
struct DiskWork {
    list: BufferHandle,
    dispatch: BufferHandle,
}

/// Which ray-march dispatch [`add_stage`] adds.
enum Stage<'w> {
    /// The whole ray march, every pixel.
    Whole,
    /// The trace pass: every pixel, appending to the work list.
    Trace(&'w mut DiskWork),
    /// The disk pass: dispatched indirectly over the list, reading back
    /// what the trace pass wrote.
    Disk(&'w DiskWork),
}

/// Adds one ray-march dispatch of `variant` writing `hdr`.
fn add_stage<'a>(
    graph: &mut Graph<'a>,
    pipelines: &'a RaymarchPipelines,
    params: &BufferHandle,
    images: &SceneImages,
    hdr: &mut ImageHandle,
    variant: Variant,
    stage: Stage<'_>,
) {
    let (width, height) = (hdr.desc.width, hdr.desc.height);
    let indirect = matches!(stage, Stage::Disk(_));
    let mut pass = graph.add_pass(match (indirect, variant.path) {
        (false, _) => "raymarch",
        (true, GpuPath::Kerr) => "raymarch rare",
        (true, _) => "raymarch disk",
    });
    let sampled = Access::ComputeSampledRead;
    let block = pass.read_buffer(params, Access::ComputeStorageRead);
    let lut = pass.read(&images.disk_lut, sampled, Mips::ALL);
    let noise = pass.read(&images.disk_noise, sampled, Mips::ALL);
    let volume = pass.read(&images.volume_noise, sampled, Mips::ALL);
    // Without an image sky the binding holds the colour table (never sampled).
    let sky = match &images.sky {
        Some(sky) => pass.read(sky, sampled, Mips::ALL),
        None => lut,
    };
    let (work, hdr_access) = match stage {
        Stage::Whole => (None, Access::ComputeStorageWrite),
        Stage::Trace(w) => (
            Some((
                pass.write_buffer(&mut w.list, Access::ComputeStorageReadWrite),
                pass.write_buffer(&mut w.dispatch, Access::ComputeStorageReadWrite),
            )),
            Access::ComputeStorageWrite,
        ),
        Stage::Disk(w) => (
            Some((
                pass.read_buffer(&w.list, Access::ComputeStorageRead),
                pass.read_buffer(&w.dispatch, Access::IndirectRead),
            )),
            Access::ComputeStorageReadWrite,
        ),
    };
    let out = pass.write(hdr, hdr_access, Mips::ALL);
    pass.record(move |ctx| {
        // Built on first use (Renderer::prepare_scene builds it ahead).
        let pipeline = pipelines.pipeline(variant)?;
        let repeat = pipelines.repeat_sampler.sampler;
        // Without the split its buffers are never read.
        let (list, dispatch) = match &work {
            Some((l, d)) => (ctx.buffer(l), ctx.buffer(d)),
            None => {
                let placeholder = pipelines.placeholder.buffer;
                (placeholder, placeholder)
            }
        };
        let descriptors = [
            Descriptor::StorageImage(ctx.view(&out, 0)),
            Descriptor::StorageBuffer(ctx.buffer(&block)),
            Descriptor::SampledImage(ctx.full_view(&lut), pipelines.linear_clamp.sampler),
            Descriptor::SampledImage(ctx.full_view(&sky), pipelines.sky_sampler.sampler),
            Descriptor::SampledImage(ctx.full_view(&noise), repeat),
            Descriptor::SampledImage(ctx.full_view(&volume), repeat),
            Descriptor::StorageBuffer(list),
            Descriptor::StorageBuffer(dispatch),
        ];
        if indirect {
            dispatch_indirect(ctx, &pipeline, &descriptors, dispatch)
        } else {
            dispatch_2d(ctx, &pipeline, &descriptors, &[], width, height)
        }
    });
}

#[cfg(test)]
mod tests {
    use super::*;

    /// The presets' shares of disk pixels at 1280x720 (the geodesic AOV):
    /// falling 4 %, edge-on 13 %, default 23 %, top-down 49 %, doppler 60 %.
    #[test]
    fn the_split_is_taken_where_the_disk_fills_little_of_the_view() {
        let pays = |name: &str| split_pays(&Scene::load(name).unwrap(), 1280, 720);
        for name in ["falling", "edge-on", "default"] {
            assert!(pays(name), "{name}");
        }
        for name in [
            "top-down",
            "doppler",
            "interstellar",
            "no-gravity",
            "binary",
        ] {
            assert!(!pays(name), "{name}");
        }
    }

    /// The spinning hole splits where its trace pass defers few paths (the
    /// presets, the default view spun up), not where the shadow fills the
    /// view (measured at 1280x720 on lavapipe: deferred share 0.33, split
    /// 582 to 651 ms a frame against 613 to 617 in one dispatch; 0.27, 518
    /// to 527 against 664 to 669; the default view at a* = 0.9, 0.02).
    #[test]
    fn the_spinning_hole_splits_where_few_paths_are_deferred() {
        let spun = |toml: &str| Scene::from_toml(toml, "test.toml").unwrap();
        for name in ["gargantua", "kerr-doppler"] {
            assert!(split_pays(&Scene::load(name).unwrap(), 1280, 720), "{name}");
        }
        assert!(split_pays(&spun("[[black_hole]]\nspin = 0.9\n"), 1280, 720));
        let close = "[[black_hole]]\nspin = 0.9\n[camera]\nposition = [0.0, 0.4, -3.0]\n";
        assert!(!split_pays(&spun(close), 1280, 720));
    }
}
