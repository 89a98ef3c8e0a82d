//! The one frame recipe: the ray march (or a given HDR image), the optional
//! progressive accumulation, the bloom mip chain and the composite, added to a
//! graph. Offscreen stills, sequences, the profiler, the post-processing API
//! and the window all build their frames with [`add_frame`]; what happens to
//! the result (a readback, a blit to the swapchain, a GUI on top) is added
//! after it by the caller.

use super::Pipelines;
use crate::frame::OutputKind;
use crate::graph::{BufferHandle, Graph, ImageHandle};
use crate::passes::{self, composite, polarimetry, raymarch};
use crate::scene::{Bloom, Post, Scene};
use crate::spacetime::Spacetime;

/// Where the frame's linear HDR radiance comes from.
pub enum HdrSource<'h> {
    /// The ray march of `scene`, at `size` (the graph's output size, or a
    /// fraction of it in the window).
    RayMarch {
        scene: &'h Scene,
        /// The scene's spacetime, held by the renderer.
        spacetime: &'h Spacetime,
        /// The ray march's variant for the frame, built once at its start
        /// (the AOV's is made from it here).
        variant: &'h raymarch::Variant,
        params: &'h BufferHandle,
        images: &'h raymarch::SceneImages,
        size: (u32, u32),
    },
    /// An image already in the graph (the post-processing API's upload).
    Image(ImageHandle),
}

/// The progressive accumulation of a still view (window only).
pub struct Accumulation {
    /// The running mean, kept across frames by the caller and imported.
    pub mean: ImageHandle,
    /// Which sample of the unchanged view this frame is (0 restarts).
    pub index: u32,
}

/// Post-processing settings of a frame.
pub struct PostSettings<'s> {
    pub bloom: &'s Bloom,
    pub post: &'s Post,
    /// Pixels the ray march left transparent have no ray (a fisheye's
    /// corners): the composite keeps them black and transparent.
    pub mask: bool,
}

/// Adds the whole frame to `graph`; returns the image it ends in (at the
/// graph's output size, except `Hdr` and `Geodesic`, which keep the ray
/// march's size; `Hdr` with accumulation returns the running mean).
pub fn add_frame<'a>(
    graph: &mut Graph<'a>,
    pipelines: &'a Pipelines,
    source: HdrSource<'_>,
    settings: PostSettings<'_>,
    output: OutputKind,
    accumulation: Option<Accumulation>,
) -> ImageHandle {
    // The polarized picture draws the ray march's Stokes image (the AOV's
    // rays and values, from the beauty build: split where its frame is) in
    // place of its light.
    let picture = match &source {
        HdrSource::RayMarch { scene, size, .. }
            if scene.polarization.enabled && !output.is_aov() =>
        {
            let out = picture_size(graph.output_size(), *size);
            Some(polarimetry::Picture::of(scene, *size, out))
        }
        _ => None,
    };
    let stokes = output == OutputKind::Stokes;
    let source_size = match &source {
        HdrSource::RayMarch { size, .. } => Some(*size),
        HdrSource::Image(_) => None,
    };
    let hdr = match source {
        HdrSource::RayMarch {
            scene,
            spacetime,
            variant,
            params,
            images,
            size,
        } => raymarch::add_raymarch(
            graph,
            &pipelines.raymarch,
            raymarch::RaymarchInputs {
                params,
                images,
                output: if output.is_aov() || stokes {
                    raymarch::RaymarchOutput::Geodesic
                } else {
                    raymarch::RaymarchOutput::Beauty
                },
                size,
                variant: if stokes {
                    variant.for_stokes()
                } else if picture.is_some() {
                    variant.for_picture()
                } else if output == OutputKind::Geodesic {
                    variant.for_aov()
                } else {
                    *variant
                },
                split: pipelines
                    .features()
                    .splits(scene, spacetime, size.0, size.1),
            },
        ),
        HdrSource::Image(image) => image,
    };
    if output.is_aov() {
        return hdr;
    }
    if let Some(picture) = picture {
        let out = match &source_size {
            Some(size) => picture_size(graph.output_size(), *size),
            None => graph.output_size(),
        };
        return polarimetry::add_picture(graph, &pipelines.polarimetry, hdr, picture, out);
    }
    let hdr = match accumulation {
        Some(Accumulation { mut mean, index }) => {
            passes::accumulate::add_accumulate(
                graph,
                &pipelines.accumulate,
                &hdr,
                &mut mean,
                index,
            );
            mean
        }
        None => hdr,
    };
    if output == OutputKind::Hdr {
        // The ray march's radiance, or with accumulation the running mean.
        return hdr;
    }
    let bloom = passes::bloom::add_bloom(graph, &pipelines.bloom, &hdr, settings.bloom);
    let exposure = passes::exposure::add_exposure(graph, &pipelines.exposure, &hdr, settings.post);
    composite::add_composite(
        graph,
        &pipelines.composite,
        &hdr,
        composite::CompositeInputs {
            bloom: bloom.as_ref(),
            exposure: exposure.as_ref(),
        },
        composite::CompositeOptions {
            bloom: settings.bloom,
            post: settings.post,
            output: if output == OutputKind::HdrPost {
                composite::CompositeOutput::LinearHdr
            } else {
                composite::CompositeOutput::Ldr
            },
            mask_no_ray: settings.mask,
        },
    )
}

/// The polarized picture's size: the output's height at the ray march's
/// aspect (the window's output is the whole swapchain, of which the blit
/// fills the view's part; a picture squeezed into it would turn its ticks).
fn picture_size(output: (u32, u32), ray_march: (u32, u32)) -> (u32, u32) {
    let (w, h) = ray_march;
    let width = (f64::from(output.1) * f64::from(w) / f64::from(h.max(1))).round() as u32;
    (width.clamp(1, output.0.max(1)), output.1)
}
