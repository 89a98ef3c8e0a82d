//! The ray march: one compute invocation per pixel follows the camera ray
//! and writes linear HDR radiance (or the geodesic AOV). Which path it takes
//! is a specialisation of the shader ([`Variant`]): one hole with gravity,
//! the closed-form light path (shaders/include/lightpath.glsl, the
//! conventions of docs/physics.md); gravity off, a straight line;
//! several holes, the spatial-orbit form x'' = -1.5 rs h^2 x / r^5 of the
//! null geodesic equation (from Binet's equation u'' + u = 1.5 rs u^2)
//! integrated in Cartesian coordinates with adaptive Dormand-Prince 5(4),
//! so the holes' pulls can be summed.
//!
//! Where it pays, the ray march is split into a trace pass over every
//! pixel and a deferred pass, dispatched indirectly over the pixels the
//! trace pass lists, for the rare, expensive paths: a non-rotating hole's
//! thin disk (`raymarch disk`), a spinning hole's uncommon radial and polar
//! motions (`raymarch rare`). [`crate::deferred`] says what is deferred and
//! decides when; this pass records the two dispatches and the list between
//! them. The spinning hole's trace pass takes the build with 32-bit roots
//! and defers the paths near the shadow's edge too; the second pass keeps
//! the device's. In the default view at a* = 0.9 it defers about 4 % of the
//! pixels (the disk in front of the shadow) and the frame falls from about
//! 4.5 to 5.3 times the non-rotating one's on lavapipe to 2.0 to 2.3.

use ash::vk;

pub mod baked;
pub mod params;

pub use baked::Baked;
pub use params::{FrameSpec, RaymarchParams};
use params::{disk_kind, sky_kind};

use std::sync::Arc;

use super::VariantCache;
use super::compute::{self, Binding, ComputePass};
use crate::Result;
use crate::deferred;
use crate::features::Features;
use crate::graph::{BufferHandle, Graph, ImageDesc, ImageHandle};
use crate::scene::{Scene, VolumeColor};
use crate::shaders::{self, RaymarchBuild};
use crate::spacetime::{GpuPath, Spacetime};
use crate::vk::{Access, Buffer, ComputePipeline, Gpu, Sampler};

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
    pub const STAGE_ALL: u32 = 0;
    pub const STAGE_TRACE: u32 = 1;
    pub const STAGE_DEFERRED: u32 = 2;
    pub const POL_OFF: u32 = 0;
    pub const POL_VIEW: u32 = 1;
    pub const POL_STOKES: u32 = 2;
    pub use crate::camera::{PROJ_EQUIRECT, PROJ_FISHEYE, PROJ_PINHOLE, STEREO_NONE, STEREO_ODS};
    /// Workgroups (of 64 listed pixels) in one row of the deferred pass's
    /// indirect dispatch.
    pub const DEFERRED_ROW: u32 = 256;
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
    /// The geodesic AOV (docs/physics.md).
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
    /// Split the ray march into a trace pass and a deferred pass if the
    /// device can ([`crate::deferred::pays`]).
    pub split: bool,
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
    /// The part of the split ray march, `glsl::STAGE_*` (`SPLIT_STAGE`)
    /// (constant 7).
    pub stage: u32,
    /// The observer moves through the static frame: aberration (constant 8).
    pub observer_moves: bool,
    /// The thin disk's temperature is Page and Thorne's (constant 9).
    pub page_thorne: bool,
    /// `camera::Projection` as a number (constant 10).
    pub projection: u32,
    /// A falling camera of one non-rotating hole: its pixels become rays
    /// by the rain form, outside, at and inside the horizon (constant 11).
    pub rain_form: bool,
    /// A falling camera between a spinning hole's horizons or just outside
    /// (`Spacetime::camera_inside_spinning`): its photons from the metric's
    /// falling frame, azimuth and time in ingoing form (constant 12; never
    /// split).
    pub kerr_inside: bool,
    /// The number of holes (at most MAX_HOLES; constant 13): the loops over
    /// them run to a constant (the static frame of a metric of several
    /// holes or none, the straight and summed paths' capture tests).
    pub holes: u32,
    /// The polarized thin disk, `glsl::POL_*` (constant 14): off, the
    /// polarized view, or the Stokes AOV.
    pub polarization: u32,
    /// The scene's static parameters compiled in ([`baked`]; constants 15
    /// on), or read from the parameter block.
    pub baked: Option<Baked>,
}

impl Variant {
    /// The beauty variant a scene needs (its AOV's: [`Variant::for_aov`]),
    /// with its static parameters compiled in from `block`, the frame's
    /// parameter block, if `bake` ([`crate::features::Features::bake`]).
    pub fn of(scene: &Scene, spacetime: &Spacetime, block: &RaymarchParams, bake: bool) -> Variant {
        let viewer = scene.camera.viewer();
        let observer = spacetime.camera_observer(&viewer);
        Variant {
            aov: false,
            path: spacetime.gpu_path(),
            disk: disk_kind(scene),
            sky: sky_kind(scene),
            plane: scene.plane.enabled,
            light_delay: scene.animation.light_travel_time,
            structure: scene.disk.structure > 0.0,
            thin_crossings: if scene.disk.structure > 0.0 || scene.disk.opacity < 1.0 {
                2
            } else {
                1
            },
            volume_blackbody: scene.disk.color == VolumeColor::Blackbody,
            stage: glsl::STAGE_ALL,
            observer_moves: observer.beta != glam::DVec3::ZERO,
            page_thorne: scene.disk.temperature_profile
                == crate::scene::TemperatureProfile::PageThorne,
            projection: scene.camera.projection.gpu_id(),
            rain_form: observer.rain.is_some(),
            kerr_inside: spacetime.camera_inside_spinning(&viewer),
            holes: spacetime.holes().len().min(crate::scene::MAX_HOLES) as u32,
            polarization: if scene.polarization.enabled {
                glsl::POL_VIEW
            } else {
                glsl::POL_OFF
            },
            baked: bake.then(|| Baked::of(block)),
        }
    }

    /// The same variant writing the geodesic AOV (no light delay: the AOV
    /// records where each path goes, not when).
    pub fn for_aov(self) -> Variant {
        Variant {
            aov: true,
            light_delay: false,
            polarization: glsl::POL_OFF,
            ..self
        }
    }

    /// The same variant writing the polarized picture's Stokes parameters
    /// (`POL_VIEW`): the beauty build, split where the beauty frame is (so
    /// the picture costs what the frame does), with the first disk crossing
    /// as the Stokes AOV's, no light delay and no structure, and the sky
    /// dark.
    pub fn for_picture(self) -> Variant {
        Variant {
            aov: false,
            light_delay: false,
            structure: false,
            thin_crossings: 1,
            polarization: glsl::POL_VIEW,
            ..self
        }
    }

    /// The same variant writing the Stokes AOV.
    pub fn for_stokes(self) -> Variant {
        Variant {
            polarization: glsl::POL_STOKES,
            ..self.for_aov()
        }
    }

    /// The pipelines one frame of this variant runs, in order: the trace and
    /// deferred passes when `split` and the variant has a deferred pass
    /// ([`crate::deferred::applies`]), else itself.
    pub fn stages(self, split: bool) -> Vec<Variant> {
        if split
            && deferred::applies(self.path, self.disk == glsl::DISK_THIN)
            && !self.aov
            && !self.kerr_inside
        {
            [glsl::STAGE_TRACE, glsl::STAGE_DEFERRED]
                .map(|stage| Variant { stage, ..self })
                .to_vec()
        } else {
            vec![self]
        }
    }

    /// The variant's specialisation constants as (GLSL name, value), in
    /// `constant_id` order from 0: the one list of them, which the
    /// pipeline's constants, its name and tests/layout.rs (against
    /// include/variant.glsl and every SPIR-V module) all read. A new
    /// constant is a field, its line in [`Variant::of`], a row here and its
    /// `constant_id` line in variant.glsl.
    pub fn named(&self) -> [(&'static str, u32); VARIANT_CONSTANTS] {
        [
            ("DISK_KIND", self.disk),
            ("SKY_KIND", self.sky),
            ("GRID_PLANE", u32::from(self.plane)),
            ("LIGHT_DELAY", u32::from(self.light_delay)),
            ("THIN_STRUCTURE", u32::from(self.structure)),
            ("THIN_CROSSINGS", self.thin_crossings),
            ("VOLUME_BLACKBODY", u32::from(self.volume_blackbody)),
            ("SPLIT_STAGE", self.stage),
            ("OBSERVER_MOVES", u32::from(self.observer_moves)),
            ("PAGE_THORNE", u32::from(self.page_thorne)),
            ("PROJECTION", self.projection),
            ("RAIN_FORM", u32::from(self.rain_form)),
            ("KERR_INSIDE", u32::from(self.kerr_inside)),
            ("HOLE_COUNT", self.holes),
            ("POLARIZATION", self.polarization),
        ]
    }

    /// The GLSL names of [`Variant::named`], in `constant_id` order.
    pub fn constant_names() -> [&'static str; VARIANT_CONSTANTS] {
        let any = Variant::of(
            &Scene::default(),
            &Scene::default().spacetime(),
            &RaymarchParams::default(),
            false,
        );
        any.named().map(|(name, _)| name)
    }

    /// Every constant in `constant_id` order: [`Variant::named`]'s values,
    /// then `BAKED` and the baked values ([`baked::BAKED_NAMES`]; zeros
    /// when not baked).
    pub fn constants(&self) -> Vec<u32> {
        let mut all: Vec<u32> = self.named().iter().map(|&(_, v)| v).collect();
        all.push(u32::from(self.baked.is_some()));
        all.extend(self.baked.map_or([0; baked::BAKED_COUNT], |b| b.0));
        all
    }

    /// The pipeline's name: its build, path and every constant's value.
    pub fn name(&self) -> String {
        let constants: Vec<String> = self
            .named()
            .iter()
            .map(|(name, v)| format!("{} {v}", name.to_lowercase().replace('_', " ")))
            .collect();
        format!(
            "raymarch{}{} ({:?}, {})",
            if self.aov { " aov" } else { "" },
            if self.baked.is_some() { " baked" } else { "" },
            self.path,
            constants.join(", ")
        )
    }
}

/// How many specialisation constants a [`Variant`] has (ids 0 to 14; the
/// baked values follow from [`baked::BAKED_FIRST_ID`]).
pub const VARIANT_CONSTANTS: usize = 15;

/// The parameter block is a read-only storage buffer, not a uniform buffer:
/// on Mesa's lavapipe (22.3) every dispatch that read a uniform buffer
/// leaked about 0.55 MB inside the driver until the device was destroyed
/// (1,000 frames at 160x90 took 640 MB; the same with a storage buffer, 120
/// MB) and cost twice the time. Found by skipping one pass's dispatch at a
/// time. Bindings 6 and 7 are the split ray march's work list and indirect
/// dispatch. The ray march's bindings, in order (the names and numbers of
/// shaders/include/bindings.glsl; tests/layout.rs checks them against it
/// and the SPIR-V).
pub const BINDINGS: [Binding; 8] = [
    Binding::storage_image("RM_OUT_IMAGE"),
    Binding::storage_buffer("RM_PARAMS"),
    Binding::sampled("RM_DISK_LUT"),
    Binding::sampled("RM_SKY"),
    Binding::sampled("RM_DISK_NOISE"),
    Binding::sampled("RM_VOLUME_NOISE"),
    Binding::storage_buffer("RM_DEFERRED_LIST"),
    Binding::storage_buffer("RM_DEFERRED_DISPATCH"),
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
        if variant.kerr_inside && !self.features.kerr_f64 {
            // (Its 32-bit build misses by 1e-3 rad at 0.8 r+ and by up to a
            // radian near r-: tests/kerr_gpu.rs's cameras.)
            return Err(crate::Error::Other(
                "a falling camera inside a spinning hole's horizon, or within 5% of it \
                 outside (the falling frame's band), needs 64-bit floats in shaders \
                 (shaderFloat64), which this device lacks or BLACKHOLE_NO_F64=1 turns off: its \
                 light paths are not drawn in 32-bit floats"
                    .into(),
            ));
        }
        self.cache.get(variant, || {
            let build = if variant.aov {
                RaymarchBuild::Aov
            } else if variant.stage != glsl::STAGE_ALL {
                RaymarchBuild::Split
            } else if self.features.ray_differentials {
                RaymarchBuild::Beauty
            } else {
                RaymarchBuild::NoQuad
            };
            // The spinning hole's split trace pass takes the 32-bit roots
            // (it defers the paths near the shadow's edge, where they lose
            // precision, to the second pass, which keeps the device's).
            let trace = variant.stage == glsl::STAGE_TRACE;
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
                &compute::kinds(&BINDINGS),
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
        variant.stages(split && self.features.split)
    }
}

/// The ray march's pass (the whole of it, or the split's trace pass).
pub const TRACE_PASS: &str = "raymarch";
/// The split's pass that empties the deferred list before the trace pass.
pub const LIST_CLEAR_PASS: &str = "deferred list clear";

/// The split's deferred pass on `path`: a non-rotating hole's thin disk, a
/// spinning hole's rare paths.
pub fn deferred_pass_name(path: GpuPath) -> &'static str {
    match path {
        GpuPath::Kerr => "raymarch rare",
        _ => "raymarch disk",
    }
}

/// The passes the ray march of `variant` adds, in order, split or not.
pub fn pass_names(variant: Variant, split: bool) -> Vec<&'static str> {
    if variant.stages(split).len() == 2 {
        vec![
            LIST_CLEAR_PASS,
            TRACE_PASS,
            deferred_pass_name(variant.path),
        ]
    } else {
        vec![TRACE_PASS]
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
    let [trace, deferred] = stages[..] else {
        stage(graph, &mut hdr, variant, Stage::Whole);
        return hdr;
    };

    // The deferred pass's work list (a count, then one packed pixel each; whole
    // 2x2 quads for a split by paths, so up to the size rounded up to even)
    // and its indirect dispatch, emptied first.
    let pixels = u64::from(width.next_multiple_of(2)) * u64::from(height.next_multiple_of(2));
    let mut work = DeferredWork {
        list: graph.create_buffer("deferred list", 4 + 4 * pixels),
        dispatch: graph.create_buffer("deferred dispatch", 16),
    };
    let mut pass = graph.add_pass(LIST_CLEAR_PASS);
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
                // groups_y grows from 0 with groups_x (rows of DEFERRED_ROW).
                bytemuck::bytes_of(&[0u32, 0, 1, 0]),
            );
        }
        Ok(())
    });
    stage(graph, &mut hdr, trace, Stage::Trace(&mut work));
    stage(graph, &mut hdr, deferred, Stage::Deferred(&work));
    hdr
}

/// The split ray march's work list and its indirect dispatch.
struct DeferredWork {
    list: BufferHandle,
    dispatch: BufferHandle,
}

/// Which ray-march dispatch [`add_stage`] adds.
enum Stage<'w> {
    /// The whole ray march, every pixel.
    Whole,
    /// The trace pass: every pixel, appending to the work list.
    Trace(&'w mut DeferredWork),
    /// The deferred pass: dispatched indirectly over the list, reading back
    /// what the trace pass wrote.
    Deferred(&'w DeferredWork),
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
    let name = match stage {
        Stage::Deferred(_) => deferred_pass_name(variant.path),
        _ => TRACE_PASS,
    };
    let hdr_access = match stage {
        Stage::Deferred(_) => Access::ComputeStorageReadWrite,
        _ => Access::ComputeStorageWrite,
    };
    let repeat = pipelines.repeat_sampler.sampler;
    // Without an image sky the binding holds the colour table (never sampled).
    let pass = ComputePass::new(graph, name, &BINDINGS)
        .storage_image(hdr, hdr_access, 0)
        .buffer_read(params, Access::ComputeStorageRead)
        .sampled(&images.disk_lut, pipelines.linear_clamp.sampler)
        .sampled(
            images.sky.as_ref().unwrap_or(&images.disk_lut),
            pipelines.sky_sampler.sampler,
        )
        .sampled(&images.disk_noise, repeat)
        .sampled(&images.volume_noise, repeat);
    // Built on first use (Renderer::prepare_scene builds it ahead).
    let pipeline = move || pipelines.pipeline(variant);
    match stage {
        // Without the split its buffers are never read.
        Stage::Whole => {
            let placeholder = pipelines.placeholder.buffer;
            pass.absent_buffer(placeholder)
                .absent_buffer(placeholder)
                .dispatch(pipeline, Vec::new(), (width, height));
        }
        Stage::Trace(w) => pass
            .buffer_write(&mut w.list, Access::ComputeStorageReadWrite)
            .buffer_write(&mut w.dispatch, Access::ComputeStorageReadWrite)
            .dispatch(pipeline, Vec::new(), (width, height)),
        Stage::Deferred(w) => pass
            .buffer_read(&w.list, Access::ComputeStorageRead)
            .buffer_read(&w.dispatch, Access::IndirectRead)
            .dispatch_indirect(pipeline, "RM_DEFERRED_DISPATCH"),
    }
}
