//! Automatic exposure: one pass meters the HDR image (a histogram of the lit
//! pixels' log luminance, the mean of a band of its percentiles) into a
//! one-float buffer that the composite multiplies by
//! (`shaders/exposure.comp`). Each
//! frame is metered on its own, so a sequence's frames do not depend on one
//! another (sharding and `--resume` give the same frames).

use bytemuck::{Pod, Zeroable};

use super::{Pipelines, dispatch_2d};
use crate::graph::{BufferHandle, Graph, ImageHandle, Mips};
use crate::scene::Post;
use crate::vk::{Access, Descriptor};

/// The luminance the metered band's mean is brought to: the band is
/// weighted toward the bright pixels, so this sits above mid grey (0.18).
pub const KEY: f32 = 0.45;

/// Push constants of `shaders/exposure.comp`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct ExposurePush {
    pub size: [u32; 2],
    pub low: f32,
    pub high: f32,
    pub key: f32,
}

/// Adds the metering of `hdr` when `post` asks for automatic exposure;
/// returns the buffer holding the exposure (one f32).
pub fn add_exposure<'a>(
    graph: &mut Graph<'a>,
    pipelines: &'a Pipelines,
    hdr: &ImageHandle,
    post: &Post,
) -> Option<BufferHandle> {
    if !post.auto_exposure {
        return None;
    }
    let mut exposure = graph.create_buffer("exposure", 16);
    let (input, output) = (hdr.clone(), exposure.clone());
    let push = ExposurePush {
        size: [hdr.desc.width, hdr.desc.height],
        low: post.meter_low as f32,
        high: post.meter_high as f32,
        key: KEY,
    };
    graph
        .add_pass("exposure")
        .read(hdr, Access::ComputeSampledRead, Mips::ALL)
        .write_buffer(&mut exposure, Access::ComputeStorageWrite)
        .record(move |ctx| {
            // One workgroup (256 invocations) meters the whole image.
            dispatch_2d(
                ctx,
                &pipelines.exposure,
                &[
                    Descriptor::SampledImage(ctx.full_view(&input), pipelines.linear_clamp.sampler),
                    Descriptor::StorageBuffer(ctx.buffer(&output)),
                ],
                bytemuck::bytes_of(&push),
                1,
                1,
            )
        });
    Some(exposure)
}
