//! The polarized picture (docs/polarization.md, "The picture"): the ray
//! march's Stokes image (`--aov stokes`'s, the same rays) blurred by the
//! telescope's beam (`pol_beam.comp`, one axis a pass, onto a coarser grid
//! when the beam is wide), its scale found (`pol_peak.comp`), and drawn as
//! the EHT draws its figures: a colour map with the polarization's ticks
//! over it (`pol_map.comp`), into the 8-bit image the composite would write.

use bytemuck::{Pod, Zeroable};

use std::sync::Arc;

use super::compute::{self, Binding, ComputePass};
use crate::Result;
use crate::graph::{Graph, ImageDesc, ImageHandle};
use crate::scene::Scene;
use crate::vk::{Access, ComputePipeline, Gpu, Sampler};

/// The Stokes images' format (the AOV's: f32, since I spans many decades).
pub const STOKES_FORMAT: ash::vk::Format = crate::passes::raymarch::AOV_FORMAT;
/// The beam's Gaussian is cut at this many sigma each side.
const BEAM_SIGMAS: f32 = 3.5;
/// The blurred grid's step is at most sigma / this (ray-march pixels).
const GRID_PER_SIGMA: f32 = 2.0;

/// `pol_beam.comp`'s push constants.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct BeamPush {
    pub src_size: [u32; 2],
    pub dst_size: [u32; 2],
    pub axis: u32,
    pub step: u32,
    pub tiles: u32,
    pub tile_texels: u32,
    pub sigma: f32,
    pub radius: i32,
}

/// `pol_map.comp`'s push constants.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct MapPush {
    pub out_size: [u32; 2],
    pub src_size: [u32; 2],
    pub tiles: u32,
    pub step: u32,
    pub tile_texels: u32,
    pub view: u32,
    pub map: u32,
    pub brightness: u32,
    pub cells: u32,
    pub spacing: f32,
    pub cut: f32,
    pub fraction: f32,
    pub beam: f32,
}

pub const BEAM_BINDINGS: [Binding; 2] = [Binding::sampled("src"), Binding::storage_image("dst")];
pub const PEAK_BINDINGS: [Binding; 2] =
    [Binding::sampled("stokes"), Binding::storage_buffer("Peak")];
pub const TICK_BINDINGS: [Binding; 3] = [
    Binding::sampled("stokes"),
    Binding::storage_image("tick_img"),
    Binding::storage_buffer("Peak"),
];
pub const MAP_BINDINGS: [Binding; 4] = [
    Binding::sampled("stokes"),
    Binding::storage_image("ldr"),
    Binding::storage_buffer("Peak"),
    Binding::storage_image("tick_img"),
];

/// The picture's pipelines and sampler, owned by this pass.
pub struct PolarimetryPipelines {
    beam: ComputePipeline,
    peak: ComputePipeline,
    ticks: ComputePipeline,
    map: ComputePipeline,
    sampler: Sampler,
}

impl PolarimetryPipelines {
    pub fn new(gpu: &Arc<Gpu>) -> Result<Self> {
        let build = |name, spv, table: &[Binding], push| {
            ComputePipeline::new(gpu, name, spv, &compute::kinds(table), push as u32)
        };
        Ok(PolarimetryPipelines {
            beam: build(
                "pol beam",
                crate::shaders::POL_BEAM,
                &BEAM_BINDINGS,
                std::mem::size_of::<BeamPush>(),
            )?,
            peak: build("pol peak", crate::shaders::POL_PEAK, &PEAK_BINDINGS, 8)?,
            ticks: build(
                "pol ticks",
                crate::shaders::POL_TICKS,
                &TICK_BINDINGS,
                std::mem::size_of::<MapPush>(),
            )?,
            map: build(
                "pol map",
                crate::shaders::POL_MAP,
                &MAP_BINDINGS,
                std::mem::size_of::<MapPush>(),
            )?,
            sampler: Sampler::linear_clamp(gpu)?,
        })
    }
}

/// How one frame's polarized picture is drawn, from the scene's
/// `[polarization]` keys and the sizes.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Picture {
    /// Pictures side by side (the field models).
    pub tiles: u32,
    /// The beam's sigma in ray-march pixels (0: no beam).
    pub sigma: f32,
    /// The beam's FWHM in output pixels (0: none).
    pub beam_out: f32,
    pub view: u32,
    pub map: u32,
    pub brightness: u32,
    /// Tick spacing in output pixels (0: no ticks).
    pub spacing: f32,
    pub cut: f32,
    pub fraction: f32,
}

impl Picture {
    /// The picture of `scene` ray-marched at `src` and drawn at `out`.
    pub fn of(scene: &Scene, src: (u32, u32), out: (u32, u32)) -> Self {
        let p = &scene.polarization;
        let tiles = p.models().len() as u32;
        let tile_width = (src.0 / tiles).max(1);
        let sigma = scene.beam_sigma_pixels(tile_width, src.1) as f32;
        let fwhm = sigma * (8.0 * std::f32::consts::LN_2).sqrt();
        let out_per_src = out.1 as f32 / src.1.max(1) as f32;
        Picture {
            tiles,
            sigma: if sigma.is_finite() { sigma } else { 0.0 },
            beam_out: (fwhm * out_per_src).min(out.1 as f32),
            view: p.view.gpu_id(),
            map: p.colormap.gpu_id(),
            brightness: p.brightness.gpu_id(),
            spacing: if p.ticks == 0 {
                0.0
            } else {
                out.1 as f32 / p.ticks as f32
            },
            cut: p.tick_cut as f32,
            fraction: p.fraction as f32,
        }
    }

    /// The blurred grid's step in ray-march pixels (1: no coarser grid).
    pub fn step(&self) -> u32 {
        ((self.sigma / GRID_PER_SIGMA).floor() as u32).max(1)
    }
}

/// Adds the picture of `stokes` (the ray march's Stokes image) at `out`;
/// returns the 8-bit image.
pub fn add_picture<'a>(
    graph: &mut Graph<'a>,
    pipelines: &'a PolarimetryPipelines,
    stokes: ImageHandle,
    picture: Picture,
    out: (u32, u32),
) -> ImageHandle {
    let src = (stokes.desc.width, stokes.desc.height);
    let step = picture.step();
    let tiles = picture.tiles.max(1);
    let (scaled, tile_texels) = if picture.sigma > 0.25 {
        add_beam(graph, pipelines, &stokes, picture.sigma, step, tiles)
    } else {
        (stokes, 0)
    };
    let mut peak = graph.create_buffer("pol peak", 16);
    let size = [scaled.desc.width, scaled.desc.height];
    ComputePass::new(graph, "pol peak", &PEAK_BINDINGS)
        .sampled(&scaled, pipelines.sampler.sampler)
        .buffer_write(&mut peak, Access::ComputeStorageWrite)
        .dispatch(
            move || Ok(&pipelines.peak),
            bytemuck::bytes_of(&size).to_vec(),
            (1, 1),
        );
    // The tick grid: `cells` a picture across, from its left edge.
    let spacing = picture.spacing;
    let grid = |n: u32| {
        if spacing > 0.0 {
            ((n as f32 / spacing).ceil() as u32).max(1)
        } else {
            1
        }
    };
    let cells = grid(out.0.div_ceil(tiles) + 1);
    let rows = grid(out.1);
    let push = MapPush {
        out_size: [out.0, out.1],
        src_size: [src.0, src.1],
        tiles,
        step: if tile_texels == 0 { 1 } else { step },
        tile_texels,
        view: picture.view,
        map: picture.map,
        brightness: picture.brightness,
        cells,
        spacing,
        cut: picture.cut,
        fraction: picture.fraction,
        beam: picture.beam_out,
    };
    let push = bytemuck::bytes_of(&push).to_vec();
    let mut ticks = graph.create_image(
        "pol ticks",
        ImageDesc::new_2d(STOKES_FORMAT, tiles * cells, rows),
    );
    ComputePass::new(graph, "pol ticks", &TICK_BINDINGS)
        .sampled(&scaled, pipelines.sampler.sampler)
        .storage_image(&mut ticks, Access::ComputeStorageWrite, 0)
        .buffer_read(&peak, Access::ComputeStorageRead)
        .dispatch(
            move || Ok(&pipelines.ticks),
            push.clone(),
            (tiles * cells, rows),
        );
    let mut ldr = graph.create_image(
        "pol picture",
        ImageDesc::new_2d(super::composite::LDR_FORMAT, out.0, out.1),
    );
    ComputePass::new(graph, "pol map", &MAP_BINDINGS)
        .sampled(&scaled, pipelines.sampler.sampler)
        .storage_image(&mut ldr, Access::ComputeStorageWrite, 0)
        .buffer_read(&peak, Access::ComputeStorageRead)
        .storage_image_read(&ticks, 0)
        .dispatch(move || Ok(&pipelines.map), push, out);
    ldr
}

/// The beam's two passes (along x onto `step` times fewer texels a tile,
/// then along y); returns the blurred image and its texels a tile along x.
fn add_beam<'a>(
    graph: &mut Graph<'a>,
    pipelines: &'a PolarimetryPipelines,
    stokes: &ImageHandle,
    sigma: f32,
    step: u32,
    tiles: u32,
) -> (ImageHandle, u32) {
    let (w, h) = (stokes.desc.width, stokes.desc.height);
    let tile_texels = w.div_ceil(tiles).div_ceil(step);
    let across = (tiles * tile_texels, h);
    let blurred = (across.0, h.div_ceil(step));
    let radius = (BEAM_SIGMAS * sigma).ceil() as i32;
    let mut x = graph.create_image(
        "pol beam x",
        ImageDesc::new_2d(STOKES_FORMAT, across.0, across.1),
    );
    let mut y = graph.create_image(
        "pol beam",
        ImageDesc::new_2d(STOKES_FORMAT, blurred.0, blurred.1),
    );
    let passes = [
        ("pol beam x", 0, (w, h), across),
        ("pol beam y", 1, across, blurred),
    ];
    for (name, axis, src, dst) in passes {
        let push = BeamPush {
            src_size: [src.0, src.1],
            dst_size: [dst.0, dst.1],
            axis,
            step,
            tiles,
            tile_texels,
            sigma,
            radius,
        };
        let pass = ComputePass::new(graph, name, &BEAM_BINDINGS);
        let pass = if axis == 0 {
            pass.sampled(stokes, pipelines.sampler.sampler)
                .storage_image(&mut x, Access::ComputeStorageWrite, 0)
        } else {
            pass.sampled(&x, pipelines.sampler.sampler).storage_image(
                &mut y,
                Access::ComputeStorageWrite,
                0,
            )
        };
        pass.dispatch(
            move || Ok(&pipelines.beam),
            bytemuck::bytes_of(&push).to_vec(),
            dst,
        );
    }
    (y, tile_texels)
}
