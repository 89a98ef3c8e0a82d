//! Copies between images and buffers: readback to the host, uploads from it.

use ash::vk;

use crate::graph::{BufferHandle, Graph, ImageHandle, Mips};
use crate::vk::Access;

/// Adds a transfer pass that copies mip 0 of `image` into `buffer`, tightly packed.
pub fn add_copy_to_buffer(graph: &mut Graph<'_>, image: &ImageHandle, buffer: &mut BufferHandle) {
    let mut pass = graph.add_pass("readback");
    let src = pass.read(image, Access::TransferRead, Mips::one(0));
    let dst = pass.write_buffer(buffer, Access::TransferWrite);
    pass.record(move |ctx| {
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

/// Adds a transfer pass that copies `buffer` into every mip level of `image`:
/// the levels tightly packed one after the other, level 0 first, with
/// `texel_bytes` per texel.
pub fn add_upload(
    graph: &mut Graph<'_>,
    buffer: &BufferHandle,
    image: &mut ImageHandle,
    texel_bytes: u64,
) {
    let mut pass = graph.add_pass("upload");
    let src = pass.read_buffer(buffer, Access::TransferRead);
    let dst = pass.write(image, Access::TransferWrite, Mips::ALL);
    pass.record(move |ctx| {
        let mut offset = 0u64;
        let regions: Vec<vk::BufferImageCopy> = (0..dst.desc.mip_levels)
            .map(|level| {
                let (w, h) = dst.desc.mip_extent(level);
                let region = vk::BufferImageCopy {
                    buffer_offset: offset,
                    buffer_row_length: 0,
                    buffer_image_height: 0,
                    image_subresource: vk::ImageSubresourceLayers {
                        aspect_mask: vk::ImageAspectFlags::COLOR,
                        mip_level: level,
                        base_array_layer: 0,
                        layer_count: 1,
                    },
                    image_offset: vk::Offset3D::default(),
                    image_extent: vk::Extent3D {
                        width: w,
                        height: h,
                        depth: dst.desc.depth,
                    },
                };
                offset += u64::from(w) * u64::from(h) * u64::from(dst.desc.depth) * texel_bytes;
                region
            })
            .collect();
        if offset > src.size {
            return Err(crate::Error::Other(format!(
                "upload needs {offset} bytes, the staging buffer has {}",
                src.size
            )));
        }
        // SAFETY: the graph put every level in TRANSFER_DST_OPTIMAL after
        // the host's writes to the buffer; the regions fit both (checked).
        unsafe {
            ctx.gpu.device.cmd_copy_buffer_to_image(
                ctx.cmd,
                ctx.buffer(&src),
                ctx.image(&dst),
                vk::ImageLayout::TRANSFER_DST_OPTIMAL,
                &regions,
            )
        };
        Ok(())
    });
}
