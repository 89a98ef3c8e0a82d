//! Frame-graph compilation, tested without a device. Each test is named after
//! the hazard it covers.

use ash::vk;
use blackhole::graph::{
    BufferBinding, BufferHandle, Graph, ImageBinding, ImageDesc, ImageHandle, Mips,
};
use blackhole::vk::Access;

use vk::AccessFlags2 as A;
use vk::ImageLayout as L;
use vk::PipelineStageFlags2 as S;

const FMT: vk::Format = vk::Format::R16G16B16A16_SFLOAT;

fn fake_image(levels: u32) -> ImageBinding {
    ImageBinding {
        image: vk::Image::null(),
        mip_views: vec![vk::ImageView::null(); levels as usize],
        full_view: vk::ImageView::null(),
    }
}

fn fake_buffer() -> BufferBinding {
    BufferBinding {
        buffer: vk::Buffer::null(),
        size: 1024,
    }
}

/// A buffer the graph must leave readable by the host: passes that write it
/// are never culled.
fn exported(g: &mut Graph<'_>) -> BufferHandle {
    g.import_buffer(
        "out",
        fake_buffer(),
        Access::Nothing,
        Some(Access::HostRead),
    )
}

/// A final pass that reads `img` (mips) and writes an exported buffer, so the
/// passes before it stay alive.
fn consume(g: &mut Graph<'_>, img: &ImageHandle, mips: Mips) {
    let mut out = exported(g);
    {
        let mut p = g.add_pass("consume");
        p.read(img, Access::ComputeSampledRead, mips);
        p.write_buffer(&mut out, Access::ComputeStorageWrite);
    }
}

#[test]
fn read_after_write_makes_the_storage_write_visible_and_changes_layout() {
    let mut g = Graph::new(64, 64);
    let mut img = g.create_image("a", ImageDesc::new_2d(FMT, 64, 64));
    {
        let mut p = g.add_pass("write");
        p.write(&mut img, Access::ComputeStorageWrite, Mips::ALL);
    }
    consume(&mut g, &img, Mips::ALL);
    let c = g.compile().unwrap();
    assert_eq!(c.order, vec![0, 1]);
    // First use: undefined -> general, nothing to wait for.
    let first = &c.before[0].images;
    assert_eq!(first.len(), 1);
    assert_eq!(
        (first[0].old_layout, first[0].new_layout),
        (L::UNDEFINED, L::GENERAL)
    );
    assert_eq!(first[0].src_stage, S::NONE);
    // Read after write.
    let b = &c.before[1].images;
    assert_eq!(b.len(), 1);
    assert_eq!(b[0].src_stage, S::COMPUTE_SHADER);
    assert_eq!(b[0].src_access, A::SHADER_STORAGE_WRITE);
    assert_eq!(b[0].dst_stage, S::COMPUTE_SHADER);
    assert_eq!(b[0].dst_access, A::SHADER_SAMPLED_READ);
    assert_eq!(
        (b[0].old_layout, b[0].new_layout),
        (L::GENERAL, L::SHADER_READ_ONLY_OPTIMAL)
    );
}

#[test]
fn write_after_read_waits_for_the_reader_without_a_memory_dependency() {
    let mut g = Graph::new(64, 64);
    let mut img = g.import_image(
        "a",
        ImageDesc::new_2d(FMT, 8, 8),
        fake_image(1),
        Access::ComputeStorageRead,
        Some(Access::ComputeStorageRead),
    );
    {
        let mut p = g.add_pass("write");
        p.write(&mut img, Access::ComputeStorageWrite, Mips::ALL);
    }
    let c = g.compile().unwrap();
    let b = &c.before[0].images;
    assert_eq!(b.len(), 1);
    assert_eq!(
        b[0].src_stage,
        S::COMPUTE_SHADER,
        "waits for the earlier read"
    );
    assert_eq!(
        b[0].src_access,
        A::NONE,
        "a read has nothing to make available"
    );
    assert_eq!(b[0].dst_access, A::SHADER_STORAGE_WRITE);
    assert_eq!((b[0].old_layout, b[0].new_layout), (L::GENERAL, L::GENERAL));
    // And the final state: readable again, made visible.
    let after = &c.after.images;
    assert_eq!(after.len(), 1);
    assert_eq!(after[0].src_access, A::SHADER_STORAGE_WRITE);
    assert_eq!(after[0].dst_access, A::SHADER_STORAGE_READ);
}

#[test]
fn write_after_write_orders_the_two_writes() {
    let mut g = Graph::new(64, 64);
    let mut img = g.create_image("a", ImageDesc::new_2d(FMT, 8, 8));
    {
        let mut p = g.add_pass("first");
        p.write(&mut img, Access::ComputeStorageWrite, Mips::ALL);
    }
    {
        let mut p = g.add_pass("second");
        p.write(&mut img, Access::ComputeStorageReadWrite, Mips::ALL);
    }
    consume(&mut g, &img, Mips::ALL);
    let c = g.compile().unwrap();
    assert_eq!(c.order, vec![0, 1, 2]);
    let b = &c.before[1].images;
    assert_eq!(b.len(), 1);
    assert_eq!(b[0].src_stage, S::COMPUTE_SHADER);
    assert_eq!(b[0].src_access, A::SHADER_STORAGE_WRITE);
    assert_eq!(
        b[0].dst_access,
        A::SHADER_STORAGE_READ | A::SHADER_STORAGE_WRITE
    );
    assert_eq!((b[0].old_layout, b[0].new_layout), (L::GENERAL, L::GENERAL));
}

#[test]
fn second_read_of_a_visible_write_needs_no_barrier() {
    let mut g = Graph::new(64, 64);
    let mut img = g.create_image("a", ImageDesc::new_2d(FMT, 8, 8));
    let mut other = g.create_image("b", ImageDesc::new_2d(FMT, 8, 8));
    {
        let mut p = g.add_pass("write");
        p.write(&mut img, Access::ComputeStorageWrite, Mips::ALL);
    }
    {
        let mut p = g.add_pass("read1");
        p.read(&img, Access::ComputeSampledRead, Mips::ALL);
        p.write(&mut other, Access::ComputeStorageWrite, Mips::ALL);
    }
    let mut out = exported(&mut g);
    {
        let mut p = g.add_pass("read2");
        p.read(&img, Access::ComputeSampledRead, Mips::ALL);
        p.read(&other, Access::ComputeSampledRead, Mips::ALL);
        p.write_buffer(&mut out, Access::ComputeStorageWrite);
    }
    let c = g.compile().unwrap();
    assert_eq!(c.order, vec![0, 1, 2]);
    let img_barriers: Vec<_> = c.before[2].images.iter().filter(|b| b.image == 0).collect();
    assert!(img_barriers.is_empty(), "{img_barriers:?}");
}

#[test]
fn mip_chain_reading_n_writing_n_plus_1_gets_one_barrier_per_level() {
    const LEVELS: u32 = 6;
    let mut g = Graph::new(64, 64);
    let mut img = g.create_image("chain", ImageDesc::new_2d(FMT, 256, 256).with_mips(LEVELS));
    assert_eq!(img.desc.mip_levels, LEVELS);
    {
        let mut p = g.add_pass("mip0");
        p.write(&mut img, Access::ComputeStorageWrite, Mips::one(0));
    }
    for n in 0..LEVELS - 1 {
        {
            let mut p = g.add_pass(&format!("down{n}"));
            p.read(&img, Access::ComputeSampledRead, Mips::one(n));
            p.write(&mut img, Access::ComputeStorageWrite, Mips::one(n + 1));
        }
    }
    consume(&mut g, &img, Mips::one(LEVELS - 1));
    let c = g.compile().unwrap();
    assert_eq!(c.order.len(), LEVELS as usize + 1);

    // mip0 pass: only level 0 goes undefined -> general.
    let b0 = &c.before[0].images;
    assert_eq!(b0.len(), 1);
    assert_eq!((b0[0].base_mip, b0[0].mip_count), (0, 1));

    for n in 0..LEVELS - 1 {
        let b = &c.before[1 + n as usize].images;
        assert_eq!(b.len(), 2, "down{n}: {b:?}");
        for barrier in b {
            assert_eq!(barrier.mip_count, 1, "one level per barrier");
        }
        let read = b
            .iter()
            .find(|x| x.base_mip == n)
            .expect("barrier on the level read");
        assert_eq!(
            (read.old_layout, read.new_layout),
            (L::GENERAL, L::SHADER_READ_ONLY_OPTIMAL)
        );
        assert_eq!(read.src_access, A::SHADER_STORAGE_WRITE);
        assert_eq!(read.dst_access, A::SHADER_SAMPLED_READ);
        let write = b
            .iter()
            .find(|x| x.base_mip == n + 1)
            .expect("barrier on the level written");
        assert_eq!(
            (write.old_layout, write.new_layout),
            (L::UNDEFINED, L::GENERAL)
        );
        // No other level is touched.
        assert!(b.iter().all(|x| x.base_mip == n || x.base_mip == n + 1));
    }
    // The consumer reads the last level: only that one transitions.
    let last = &c.before[LEVELS as usize].images;
    assert_eq!(last.len(), 1);
    assert_eq!(last[0].base_mip, LEVELS - 1);
    assert_eq!(last[0].new_layout, L::SHADER_READ_ONLY_OPTIMAL);
}

#[test]
fn adjacent_levels_with_identical_barriers_merge_into_one_range() {
    let mut g = Graph::new(64, 64);
    let mut img = g.create_image("m", ImageDesc::new_2d(FMT, 64, 64).with_mips(6));
    {
        let mut p = g.add_pass("all");
        p.write(&mut img, Access::ComputeStorageWrite, Mips::ALL);
    }
    consume(&mut g, &img, Mips::ALL);
    let c = g.compile().unwrap();
    assert_eq!(c.before[0].images.len(), 1);
    assert_eq!(
        (
            c.before[0].images[0].base_mip,
            c.before[0].images[0].mip_count
        ),
        (0, 6)
    );
    assert_eq!(c.before[1].images.len(), 1);
    assert_eq!(c.before[1].images[0].mip_count, 6);
}

#[test]
fn pass_whose_output_nobody_reads_is_culled() {
    let mut g = Graph::new(64, 64);
    let mut used = g.create_image("used", ImageDesc::new_2d(FMT, 8, 8));
    let mut unused = g.create_image("unused", ImageDesc::new_2d(FMT, 8, 8));
    {
        let mut p = g.add_pass("useful");
        p.write(&mut used, Access::ComputeStorageWrite, Mips::ALL);
    }
    {
        let mut p = g.add_pass("wasted");
        p.write(&mut unused, Access::ComputeStorageWrite, Mips::ALL);
    }
    consume(&mut g, &used, Mips::ALL);
    let c = g.compile().unwrap();
    assert_eq!(c.order, vec![0, 2]);
    assert_eq!(c.culled, vec![1]);
    assert_eq!(c.before.len(), 2);
    // The culled pass's image gets no usage, so it is never created.
    assert!(c.image_usage[1].is_empty());
}

#[test]
fn culling_is_per_mip_level() {
    let mut g = Graph::new(64, 64);
    let mut img = g.create_image("m", ImageDesc::new_2d(FMT, 64, 64).with_mips(2));
    {
        let mut p = g.add_pass("level0");
        p.write(&mut img, Access::ComputeStorageWrite, Mips::one(0));
    }
    {
        let mut p = g.add_pass("level1");
        p.write(&mut img, Access::ComputeStorageWrite, Mips::one(1));
    }
    consume(&mut g, &img, Mips::one(0));
    let c = g.compile().unwrap();
    assert_eq!(c.order, vec![0, 2]);
    assert_eq!(c.culled, vec![1]);
}

#[test]
fn imported_image_is_left_in_its_requested_final_layout() {
    let mut g = Graph::new(64, 64);
    let mut target = g.import_image(
        "swapchain",
        ImageDesc::new_2d(vk::Format::R8G8B8A8_UNORM, 32, 32),
        fake_image(1),
        Access::Nothing,
        Some(Access::Present),
    );
    {
        let mut p = g.add_pass("draw");
        p.write(&mut target, Access::ComputeStorageWrite, Mips::ALL);
    }
    let c = g.compile().unwrap();
    assert_eq!(c.order, vec![0], "a pass writing an exported image is kept");
    let after = &c.after.images;
    assert_eq!(after.len(), 1);
    assert_eq!(
        (after[0].old_layout, after[0].new_layout),
        (L::GENERAL, L::PRESENT_SRC_KHR)
    );
    assert_eq!(after[0].src_access, A::SHADER_STORAGE_WRITE);
}

#[test]
fn readback_buffer_is_made_visible_to_the_host() {
    let mut g = Graph::new(64, 64);
    let mut img = g.create_image("a", ImageDesc::new_2d(FMT, 8, 8));
    let mut buf = g.import_buffer("rb", fake_buffer(), Access::Nothing, Some(Access::HostRead));
    {
        let mut p = g.add_pass("write");
        p.write(&mut img, Access::ComputeStorageWrite, Mips::ALL);
    }
    {
        let mut p = g.add_pass("copy");
        p.read(&img, Access::TransferRead, Mips::one(0));
        p.write_buffer(&mut buf, Access::TransferWrite);
    }
    let c = g.compile().unwrap();
    assert_eq!(c.before[1].images[0].new_layout, L::TRANSFER_SRC_OPTIMAL);
    assert_eq!(c.after.buffers.len(), 1);
    let b = c.after.buffers[0];
    assert_eq!(
        (b.src_stage, b.src_access),
        (S::ALL_TRANSFER, A::TRANSFER_WRITE)
    );
    assert_eq!((b.dst_stage, b.dst_access), (S::HOST, A::HOST_READ));
}

#[test]
fn usage_flags_are_derived_from_declared_accesses() {
    let mut g = Graph::new(64, 64);
    let mut img = g.create_image("a", ImageDesc::new_2d(FMT, 8, 8));
    let mut buf = g.import_buffer("rb", fake_buffer(), Access::Nothing, Some(Access::HostRead));
    {
        let mut p = g.add_pass("write");
        p.write(&mut img, Access::ComputeStorageWrite, Mips::ALL);
    }
    let mut other = g.create_image("b", ImageDesc::new_2d(FMT, 8, 8));
    {
        let mut p = g.add_pass("sample");
        p.read(&img, Access::ComputeSampledRead, Mips::ALL);
        p.write(&mut other, Access::ComputeStorageWrite, Mips::ALL);
    }
    {
        let mut p = g.add_pass("copy");
        p.read(&other, Access::TransferRead, Mips::ALL);
        p.write_buffer(&mut buf, Access::TransferWrite);
    }
    let c = g.compile().unwrap();
    use vk::ImageUsageFlags as U;
    assert_eq!(c.image_usage[0], U::STORAGE | U::SAMPLED);
    assert_eq!(c.image_usage[1], U::STORAGE | U::TRANSFER_SRC);
    assert_eq!(c.buffer_usage[0], vk::BufferUsageFlags::TRANSFER_DST);
}

#[test]
fn a_mip_outside_the_image_is_a_build_error() {
    let mut g = Graph::new(64, 64);
    let mut img = g.create_image("a", ImageDesc::new_2d(FMT, 8, 8).with_mips(2));
    {
        let mut p = g.add_pass("bad");
        p.write(&mut img, Access::ComputeStorageWrite, Mips::one(5));
    }
    consume(&mut g, &img, Mips::ALL);
    let e = g.compile().unwrap_err().to_string();
    assert!(e.contains("bad") && e.contains("outside"), "{e}");
}

#[test]
fn the_same_mip_declared_twice_in_one_pass_is_a_build_error() {
    let mut g = Graph::new(64, 64);
    let mut img = g.create_image("a", ImageDesc::new_2d(FMT, 8, 8));
    {
        let mut p = g.add_pass("twice");
        p.read(&img, Access::ComputeSampledRead, Mips::ALL);
        p.write(&mut img, Access::ComputeStorageWrite, Mips::ALL);
    }
    consume(&mut g, &img, Mips::ALL);
    assert!(g.compile().is_err());
}

#[test]
fn relative_images_follow_the_output_size() {
    let mut g = Graph::new(1280, 720);
    let full = g.create_relative("full", FMT, 1, 1);
    let half = g.create_relative("half", FMT, 2, 5);
    assert_eq!((full.desc.width, full.desc.height), (1280, 720));
    assert_eq!(
        (half.desc.width, half.desc.height, half.desc.mip_levels),
        (640, 360, 5)
    );
    assert_eq!(half.desc.mip_extent(4), (40, 22));
    let tiny = g.create_relative("tiny", FMT, 4096, 20);
    assert_eq!(
        (tiny.desc.width, tiny.desc.height, tiny.desc.mip_levels),
        (1, 1, 1)
    );
}

/// Whether every bit of `access` can be performed by some stage in `stage`
/// (the rule behind VUID-VkImageMemoryBarrier2-srcAccessMask-03914 and its
/// siblings): a source access mask must name accesses its stages perform.
fn access_supported_by(stage: vk::PipelineStageFlags2, access: vk::AccessFlags2) -> bool {
    let pairs: [(A, S); 9] = [
        (
            A::TRANSFER_READ | A::TRANSFER_WRITE,
            S::ALL_TRANSFER | S::COPY | S::BLIT,
        ),
        (
            A::SHADER_STORAGE_WRITE | A::SHADER_STORAGE_READ | A::SHADER_SAMPLED_READ,
            S::COMPUTE_SHADER | S::FRAGMENT_SHADER,
        ),
        (A::UNIFORM_READ, S::COMPUTE_SHADER | S::FRAGMENT_SHADER),
        (
            A::COLOR_ATTACHMENT_WRITE | A::COLOR_ATTACHMENT_READ,
            S::COLOR_ATTACHMENT_OUTPUT,
        ),
        (A::HOST_READ | A::HOST_WRITE, S::HOST),
        (A::INDIRECT_COMMAND_READ, S::DRAW_INDIRECT),
        (A::NONE, S::NONE),
        (A::NONE, S::NONE),
        (A::NONE, S::NONE),
    ];
    let mut left = access;
    for (a, s) in pairs {
        if stage.intersects(s) {
            left &= !a;
        }
    }
    left.is_empty()
}

fn assert_sources_valid(c: &blackhole::graph::Compiled) {
    for (i, b) in c.before.iter().chain(std::iter::once(&c.after)).enumerate() {
        for ib in &b.images {
            assert!(
                access_supported_by(ib.src_stage, ib.src_access),
                "barrier {i}: src access {:?} not performed by src stage {:?}",
                ib.src_access,
                ib.src_stage
            );
        }
        for bb in &b.buffers {
            assert!(
                access_supported_by(bb.src_stage, bb.src_access),
                "barrier {i}: src access {:?} not performed by src stage {:?}",
                bb.src_access,
                bb.src_stage
            );
        }
    }
}

/// Writes `img` with `first`, reads it in compute (a layout change), then in
/// a fragment shader; returns the compiled graph.
fn write_then_compute_then_fragment(first: Access) -> blackhole::graph::Compiled {
    let mut g = Graph::new(64, 64);
    let mut img = g.create_image("a", ImageDesc::new_2d(FMT, 64, 64));
    let mut out = exported(&mut g);
    let mut out2 = g.import_image(
        "target",
        ImageDesc::new_2d(FMT, 64, 64),
        fake_image(1),
        Access::Nothing,
        Some(Access::TransferRead),
    );
    {
        let mut p = g.add_pass("write");
        p.write(&mut img, first, Mips::ALL);
    }
    {
        let mut p = g.add_pass("compute read");
        p.read(&img, Access::ComputeSampledRead, Mips::ALL);
        p.write_buffer(&mut out, Access::ComputeStorageWrite);
    }
    {
        let mut p = g.add_pass("fragment read");
        p.read(&img, Access::FragmentSampledRead, Mips::ALL);
        p.write(&mut out2, Access::ColorAttachmentWrite, Mips::ALL);
    }
    g.compile().unwrap()
}

fn check_fragment_read_after_layout_changing_compute_read(first: Access) {
    let c = write_then_compute_then_fragment(first);
    assert_eq!(c.order, vec![0, 1, 2]);
    assert_sources_valid(&c);
    let w = first.info();
    // The compute read flushes the write and changes the layout.
    let b = &c.before[1].images;
    assert_eq!(b.len(), 1);
    assert_eq!((b[0].src_stage, b[0].src_access), (w.stage, w.access));
    assert_eq!(b[0].new_layout, L::SHADER_READ_ONLY_OPTIMAL);
    // The fragment read chains from the compute stage (which the transition
    // came before) and only needs visibility: the write is already available.
    let f: Vec<_> = c.before[2].images.iter().filter(|b| b.image == 0).collect();
    assert_eq!(f.len(), 1);
    assert!(f[0].src_stage.contains(S::COMPUTE_SHADER));
    assert_eq!(f[0].src_access, A::NONE);
    assert_eq!(
        (f[0].dst_stage, f[0].dst_access),
        (S::FRAGMENT_SHADER, A::SHADER_SAMPLED_READ)
    );
    assert_eq!(f[0].old_layout, f[0].new_layout);
}

#[test]
fn transfer_write_then_compute_read_then_fragment_read_chains_without_a_stale_source_access() {
    check_fragment_read_after_layout_changing_compute_read(Access::TransferWrite);
}

#[test]
fn colour_attachment_write_then_compute_read_then_fragment_read_chains_without_a_stale_source_access()
 {
    check_fragment_read_after_layout_changing_compute_read(Access::ColorAttachmentWrite);
}

#[test]
fn compute_write_of_a_buffer_then_storage_read_makes_the_write_visible_to_the_read() {
    let mut g = Graph::new(8, 8);
    let mut buf = g.import_buffer("params", fake_buffer(), Access::Nothing, None);
    let mut out = exported(&mut g);
    {
        let mut p = g.add_pass("write");
        p.write_buffer(&mut buf, Access::ComputeStorageWrite);
    }
    {
        let mut p = g.add_pass("read");
        p.read_buffer(&buf, Access::ComputeStorageRead);
        p.write_buffer(&mut out, Access::ComputeStorageWrite);
    }
    let c = g.compile().unwrap();
    assert_eq!(c.order, vec![0, 1]);
    assert_sources_valid(&c);
    let b: Vec<_> = c.before[1]
        .buffers
        .iter()
        .filter(|b| b.buffer == 0)
        .collect();
    assert_eq!(b.len(), 1);
    assert_eq!(
        (b[0].src_stage, b[0].src_access),
        (S::COMPUTE_SHADER, A::SHADER_STORAGE_WRITE)
    );
    assert_eq!(
        (b[0].dst_stage, b[0].dst_access),
        (S::COMPUTE_SHADER, A::SHADER_STORAGE_READ)
    );
}

#[test]
fn host_written_parameters_are_made_visible_to_the_storage_read() {
    let mut g = Graph::new(8, 8);
    let params = g.import_buffer("params", fake_buffer(), Access::HostWrite, None);
    let mut out = exported(&mut g);
    {
        let mut p = g.add_pass("read");
        p.read_buffer(&params, Access::ComputeStorageRead);
        p.write_buffer(&mut out, Access::ComputeStorageWrite);
    }
    let c = g.compile().unwrap();
    assert_sources_valid(&c);
    let b: Vec<_> = c.before[0]
        .buffers
        .iter()
        .filter(|b| b.buffer == 0)
        .collect();
    assert_eq!(b.len(), 1);
    assert_eq!((b[0].src_stage, b[0].src_access), (S::HOST, A::HOST_WRITE));
    assert_eq!(b[0].dst_access, A::SHADER_STORAGE_READ);
}

#[test]
fn reading_a_transient_before_anything_wrote_it_is_refused() {
    let mut g = Graph::new(8, 8);
    let img = g.create_image("never written", ImageDesc::new_2d(FMT, 8, 8));
    consume(&mut g, &img, Mips::ALL);
    let e = g.compile().unwrap_err().to_string();
    assert!(
        e.contains("never written") && e.contains("before any pass wrote it"),
        "{e}"
    );
}

#[test]
fn read_write_of_an_unwritten_transient_is_refused_too() {
    let mut g = Graph::new(8, 8);
    let mut img = g.create_image("acc", ImageDesc::new_2d(FMT, 8, 8));
    let mut out = exported(&mut g);
    {
        let mut p = g.add_pass("accumulate");
        p.write(&mut img, Access::ComputeStorageReadWrite, Mips::ALL);
        p.write_buffer(&mut out, Access::ComputeStorageWrite);
    }
    assert!(g.compile().is_err());
}

/// The work-list pattern of the ray march's disk pass: a transfer clears a
/// graph-owned counter, a compute pass appends to it, and a later dispatch
/// reads it as its indirect arguments.
#[test]
fn a_cleared_then_appended_transient_buffer_is_visible_to_the_indirect_dispatch_that_reads_it() {
    let mut g = Graph::new(8, 8);
    let mut args = g.create_buffer("args", 16);
    let mut list = g.create_buffer("list", 256);
    let mut out = exported(&mut g);
    {
        let mut p = g.add_pass("clear");
        p.write_buffer(&mut args, Access::TransferWrite);
        p.write_buffer(&mut list, Access::TransferWrite);
    }
    {
        let mut p = g.add_pass("append");
        p.write_buffer(&mut args, Access::ComputeStorageReadWrite);
        p.write_buffer(&mut list, Access::ComputeStorageReadWrite);
    }
    {
        let mut p = g.add_pass("indirect");
        p.read_buffer(&args, Access::IndirectRead);
        p.read_buffer(&list, Access::ComputeStorageRead);
        p.write_buffer(&mut out, Access::ComputeStorageWrite);
    }
    let c = g.compile().unwrap();
    assert_eq!(c.order, vec![0, 1, 2]);
    assert_sources_valid(&c);
    assert_eq!(
        c.buffer_usage[0],
        vk::BufferUsageFlags::TRANSFER_DST
            | vk::BufferUsageFlags::STORAGE_BUFFER
            | vk::BufferUsageFlags::INDIRECT_BUFFER
    );
    let barrier = |pass: usize, buffer: usize| {
        let b: Vec<_> = c.before[pass]
            .buffers
            .iter()
            .filter(|b| b.buffer == buffer)
            .copied()
            .collect();
        assert_eq!(b.len(), 1, "pass {pass}, buffer {buffer}");
        (
            b[0].src_stage,
            b[0].src_access,
            b[0].dst_stage,
            b[0].dst_access,
        )
    };
    let storage = A::SHADER_STORAGE_READ | A::SHADER_STORAGE_WRITE;
    for buffer in [0, 1] {
        assert_eq!(
            barrier(1, buffer),
            (
                S::ALL_TRANSFER,
                A::TRANSFER_WRITE,
                S::COMPUTE_SHADER,
                storage
            )
        );
    }
    assert_eq!(
        barrier(2, 0),
        (
            S::COMPUTE_SHADER,
            storage,
            S::DRAW_INDIRECT,
            A::INDIRECT_COMMAND_READ
        )
    );
    assert_eq!(
        barrier(2, 1),
        (
            S::COMPUTE_SHADER,
            storage,
            S::COMPUTE_SHADER,
            A::SHADER_STORAGE_READ
        )
    );
}

#[test]
fn reading_a_transient_buffer_before_anything_wrote_it_is_refused() {
    let mut g = Graph::new(8, 8);
    let args = g.create_buffer("never filled", 16);
    let mut out = exported(&mut g);
    {
        let mut p = g.add_pass("indirect");
        p.read_buffer(&args, Access::IndirectRead);
        p.write_buffer(&mut out, Access::ComputeStorageWrite);
    }
    let e = g.compile().unwrap_err().to_string();
    assert!(
        e.contains("never filled") && e.contains("before any pass wrote it"),
        "{e}"
    );
}

#[test]
fn indirect_arguments_are_a_buffer_access_only() {
    let mut g = Graph::new(8, 8);
    let img = g.create_image("a", ImageDesc::new_2d(FMT, 8, 8));
    let mut out = exported(&mut g);
    {
        let mut p = g.add_pass("bad");
        p.read(&img, Access::IndirectRead, Mips::ALL);
        p.write_buffer(&mut out, Access::ComputeStorageWrite);
    }
    assert!(g.compile().is_err());
}

#[test]
fn acquired_swapchain_image_chains_to_the_acquire_wait_and_leaves_for_present() {
    let mut g = Graph::new(8, 8);
    let ldr = {
        let mut i = g.create_image("ldr", ImageDesc::new_2d(FMT, 8, 8));
        {
            let mut p = g.add_pass("composite");
            p.write(&mut i, Access::ComputeStorageWrite, Mips::ALL);
        }
        i
    };
    let mut sc = g.import_image(
        "swapchain",
        ImageDesc::new_2d(vk::Format::B8G8R8A8_UNORM, 8, 8),
        fake_image(1),
        Access::Acquired,
        Some(Access::Present),
    );
    {
        let mut p = g.add_pass("present blit");
        p.read(&ldr, Access::TransferRead, Mips::ALL);
        p.write(&mut sc, Access::TransferWrite, Mips::ALL);
    }
    {
        let mut p = g.add_pass("gui");
        p.write(&mut sc, Access::ColorAttachmentWrite, Mips::ALL);
    }
    let c = g.compile().unwrap();
    assert_eq!(c.order, vec![0, 1, 2]);
    assert_sources_valid(&c);
    let acq = Access::Acquired.info().stage;
    let first: Vec<_> = c.before[1].images.iter().filter(|b| b.image == 1).collect();
    assert_eq!(first.len(), 1);
    // Khronos: srcStage = the semaphore's wait stage, srcAccess = 0, from UNDEFINED.
    assert_eq!(first[0].src_stage, acq);
    assert_eq!(first[0].src_access, A::NONE);
    assert_eq!(first[0].old_layout, L::UNDEFINED);
    assert_eq!(first[0].new_layout, L::TRANSFER_DST_OPTIMAL);
    // Leaves in PRESENT_SRC after the colour writes are flushed.
    let last: Vec<_> = c.after.images.iter().filter(|b| b.image == 1).collect();
    assert_eq!(last.len(), 1);
    assert_eq!(last[0].new_layout, L::PRESENT_SRC_KHR);
    assert_eq!(
        (last[0].src_stage, last[0].src_access),
        (
            S::COLOR_ATTACHMENT_OUTPUT,
            A::COLOR_ATTACHMENT_READ | A::COLOR_ATTACHMENT_WRITE
        )
    );
}

#[test]
fn no_barrier_of_a_long_mixed_chain_names_an_access_its_stage_cannot_perform() {
    // Every ordered pair of accesses on one image, followed by a third read.
    let image_accesses: Vec<Access> = Access::ALL
        .into_iter()
        .filter(|a| {
            a.valid_for_image()
                && !matches!(a, Access::Nothing | Access::Acquired | Access::Present)
                && !matches!(a, Access::HostRead | Access::HostWrite)
        })
        .collect();
    // The first write must not read (the image starts undefined).
    for &w in image_accesses
        .iter()
        .filter(|a| a.info().writes && **a != Access::ComputeStorageReadWrite)
    {
        for &r1 in &image_accesses {
            for &r2 in &image_accesses {
                let mut g = Graph::new(8, 8);
                let mut img = g.import_image(
                    "a",
                    ImageDesc::new_2d(FMT, 8, 8),
                    fake_image(1),
                    Access::Nothing,
                    Some(Access::ComputeSampledRead),
                );
                let mut out = exported(&mut g);
                {
                    let mut p = g.add_pass("w");
                    p.write(&mut img, w, Mips::ALL);
                }
                for (n, a) in [("1", r1), ("2", r2)] {
                    // Readers also write an exported buffer, so none is culled.
                    let mut p = g.add_pass(n);
                    p.write_buffer(&mut out, Access::ComputeStorageWrite);
                    if a.info().writes {
                        p.write(&mut img, a, Mips::ALL);
                    } else {
                        p.read(&img, a, Mips::ALL);
                    }
                }
                let c = g.compile().unwrap();
                assert_eq!(c.order.len(), 3);
                assert_sources_valid(&c);
            }
        }
    }
}

/// An image kept across frames must be imported next time in the state the
/// last frame left it in: the graph reports it (an import's final access,
/// else its last live use's), so its owner never guesses.
#[test]
fn the_state_an_image_is_left_in_is_reported_for_the_next_import() {
    let desc = ImageDesc::new_2d(FMT, 8, 8);
    let mut g = Graph::new(8, 8);
    let mut kept = g.import_image(
        "kept",
        desc,
        fake_image(1),
        Access::Nothing,
        Some(Access::ComputeSampledRead),
    );
    let mut loose = g.import_image("loose", desc, fake_image(1), Access::Nothing, None);
    let unused = g.import_image("unused", desc, fake_image(1), Access::Nothing, None);
    let mut out = exported(&mut g);
    let mut pass = g.add_pass("write both");
    pass.write(&mut kept, Access::ComputeStorageWrite, Mips::ALL);
    pass.write(&mut loose, Access::ComputeStorageWrite, Mips::ALL);
    pass.write_buffer(&mut out, Access::ComputeStorageWrite);
    pass.record(|_| Ok(()));
    let _ = &unused;
    let c = g.compile().expect("compiles");
    assert_eq!(c.left_in(&g, "kept"), Some(Access::ComputeSampledRead));
    assert_eq!(c.left_in(&g, "loose"), Some(Access::ComputeStorageWrite));
    assert_eq!(c.left_in(&g, "unused"), None);
}
