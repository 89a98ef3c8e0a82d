//! Copy an image (mip 0) into a buffer, for readback to the host.

use ash::vk;

use crate::graph::{BufferHandle, Graph, ImageHandle, Mips};
use crate::vk::Access;

/// Adds a transfer pass that copies mip 0 of `image` into `buffer`, tightly packed.
pub fn add_copy_to_buffer(graph: &mut Graph<'_>, image: &ImageHandle, buffer: &mut BufferHandle) {
    let (src, dst) = (image.clone(), buffer.clone());
    graph
        .add_pass("readback")
        .read(image, Access::TransferRead, Mips::one(0))
        .write_buffer(buffer, Access::TransferWrite)
        .record(move |ctx| {
            let region = vk::BufferImageCopy {
                buffer_offset: 0,
                buffer_row_length: 0,
                buffer_image_height: 0,
                image_subresource: vk::ImageSubresourceLayers {
                    aspect_mask: vk::ImageAspectFlags::COLOR,
                    mip_level: 0,
                    base_array_layer: 0,
                    layer_count: 1,
                },
                image_offset: vk::Offset3D::default(),
                image_extent: vk::Extent3D {
                    width: src.desc.width,
                    height: src.desc.height,
                    depth: 1,
                },
            };
            // SAFETY: the graph put the image in TRANSFER_SRC_OPTIMAL and made
            // the buffer writable; the region fits both.
            unsafe {
                ctx.gpu.device.cmd_copy_image_to_buffer(
                    ctx.cmd,
                    ctx.image(&src),
                    vk::ImageLayout::TRANSFER_SRC_OPTIMAL,
                    ctx.buffer(&dst),
                    &[region],
                )
            };
            Ok(())
        });
}
