//! Present: the composite's 8-bit result reaches the swapchain image through
//! the graph, as a blit (which also converts RGBA to the swapchain's BGRA
//! order and scales if the sizes differ). The composite already wrote
//! sRGB-encoded values, so the swapchain is a UNORM format and the blit copies
//! them unchanged; an sRGB swapchain would encode them twice.

use ash::vk;

use crate::graph::{Graph, ImageHandle, Mips};
use crate::vk::Access;

/// Adds a blit of `ldr` (mip 0) onto `target` (the acquired swapchain image),
/// filling its columns from `x0` to its right edge (the window's panel covers
/// the columns left of `x0`).
pub fn add_blit_to(graph: &mut Graph<'_>, ldr: &ImageHandle, target: &mut ImageHandle, x0: u32) {
    let mut pass = graph.add_pass("present blit");
    let src = pass.read(ldr, Access::TransferRead, Mips::one(0));
    let dst = pass.write(target, Access::TransferWrite, Mips::one(0));
    pass.record(move |ctx| {
        let corner = |w: u32, h: u32| vk::Offset3D {
            x: w as i32,
            y: h as i32,
            z: 1,
        };
        let layers = vk::ImageSubresourceLayers {
            aspect_mask: vk::ImageAspectFlags::COLOR,
            mip_level: 0,
            base_array_layer: 0,
            layer_count: 1,
        };
        let region = vk::ImageBlit {
            src_subresource: layers,
            src_offsets: [
                vk::Offset3D::default(),
                corner(src.desc.width, src.desc.height),
            ],
            dst_subresource: layers,
            dst_offsets: [
                vk::Offset3D {
                    x: x0.min(dst.desc.width.saturating_sub(1)) as i32,
                    y: 0,
                    z: 0,
                },
                corner(dst.desc.width, dst.desc.height),
            ],
        };
        // SAFETY: the graph put both images in their transfer layouts.
        unsafe {
            ctx.gpu.device.cmd_blit_image(
                ctx.cmd,
                ctx.image(&src),
                vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
                ctx.image(&dst),
                vk::ImageLayout::TRANSFER_DST_OPTIMAL,
                &[region],
                vk::Filter::LINEAR,
            )
        };
        Ok(())
    });
}
