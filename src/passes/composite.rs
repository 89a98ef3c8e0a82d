//! Composite: exposure (EV stops), a filmic tone map and sRGB encoding into an
//! 8-bit image. The tone curve is Narkowicz's fit of the ACES RRT+ODT
//! ("ACES Filmic Tone Mapping Curve", 2016).

use ash::vk;
use bytemuck::{Pod, Zeroable};

use super::{Pipelines, groups};
use crate::graph::{Graph, ImageDesc, ImageHandle, Mips};
use crate::vk::{Access, Descriptor, bind_compute, push_constants};

/// 8-bit output format (sRGB-encoded values in a UNORM image: storage images
/// cannot be SRGB).
pub const LDR_FORMAT: vk::Format = vk::Format::R8G8B8A8_UNORM;

/// Push constants of `shaders/composite.comp`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Pod, Zeroable)]
pub struct CompositePush {
    pub exposure: f32,
    pub width: u32,
    pub height: u32,
}

/// Adds the composite; returns the 8-bit image.
pub fn add_composite<'a>(
    graph: &mut Graph<'a>,
    pipelines: &'a Pipelines,
    hdr: &ImageHandle,
    exposure_ev: f32,
) -> ImageHandle {
    let (width, height) = (hdr.desc.width, hdr.desc.height);
    let mut ldr = graph.create_image("ldr", ImageDesc::new_2d(LDR_FORMAT, width, height));
    debug_assert_eq!((width, height), graph.output_size());
    let (input, output) = (hdr.clone(), ldr.clone());
    graph
        .add_pass("composite")
        .read(hdr, Access::ComputeSampledRead, Mips::ALL)
        .write(&mut ldr, Access::ComputeStorageWrite, Mips::ALL)
        .record(move |ctx| {
            bind_compute(
                ctx.gpu,
                ctx.cmd,
                &pipelines.composite,
                &[
                    Descriptor::SampledImage(ctx.full_view(&input), pipelines.linear_clamp.sampler),
                    Descriptor::StorageImage(ctx.view(&output, 0)),
                ],
            )?;
            let push = CompositePush {
                exposure: exposure_ev.exp2(),
                width,
                height,
            };
            push_constants(
                ctx.gpu,
                ctx.cmd,
                &pipelines.composite,
                bytemuck::bytes_of(&push),
            );
            // SAFETY: pipeline and descriptors bound on a recording buffer.
            unsafe {
                ctx.gpu
                    .device
                    .cmd_dispatch(ctx.cmd, groups(width, 8), groups(height, 8), 1)
            };
            Ok(())
        });
    ldr
}
