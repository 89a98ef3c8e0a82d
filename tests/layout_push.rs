//! The post passes' push constants (composite, accumulation, bloom,
//! exposure, the polarized picture): the Rust side's field offsets must equal
//! the offsets the shader compiler assigned, read from the SPIR-V itself (the
//! ray march's structs and constants: tests/layout.rs).

use std::mem::{offset_of, size_of};

// (The shared SPIR-V reader; this file uses only its block offsets.)
#[allow(dead_code)]
#[path = "common/spirv.rs"]
mod spirv;

use spirv::member_offsets;

#[test]
fn polarized_picture_push_constants_match_the_glsl_blocks() {
    use blackhole::passes::polarimetry::{BeamPush, MapPush};
    let beam: Vec<u32> = [
        offset_of!(BeamPush, src_size),
        offset_of!(BeamPush, dst_size),
        offset_of!(BeamPush, axis),
        offset_of!(BeamPush, step),
        offset_of!(BeamPush, tiles),
        offset_of!(BeamPush, tile_texels),
        offset_of!(BeamPush, sigma),
        offset_of!(BeamPush, radius),
    ]
    .iter()
    .map(|&o| o as u32)
    .collect();
    assert_eq!(member_offsets(blackhole::shaders::POL_BEAM, "Push"), beam);
    let map: Vec<u32> = [
        offset_of!(MapPush, out_size),
        offset_of!(MapPush, src_size),
        offset_of!(MapPush, tiles),
        offset_of!(MapPush, step),
        offset_of!(MapPush, tile_texels),
        offset_of!(MapPush, view),
        offset_of!(MapPush, map),
        offset_of!(MapPush, brightness),
        offset_of!(MapPush, cells),
        offset_of!(MapPush, spacing),
        offset_of!(MapPush, cut),
        offset_of!(MapPush, fraction),
        offset_of!(MapPush, beam),
    ]
    .iter()
    .map(|&o| o as u32)
    .collect();
    // The ticks and the map share one block (pol_picture.glsl).
    assert_eq!(member_offsets(blackhole::shaders::POL_MAP, "Push"), map);
    assert_eq!(member_offsets(blackhole::shaders::POL_TICKS, "Push"), map);
}

#[test]
fn composite_push_constants_match_the_glsl_block() {
    use blackhole::passes::composite::CompositePush;
    let glsl = member_offsets(blackhole::shaders::COMPOSITE, "Push");
    let rust: Vec<u32> = [
        offset_of!(CompositePush, exposure),
        offset_of!(CompositePush, width),
        offset_of!(CompositePush, height),
        offset_of!(CompositePush, bloom_strength),
        offset_of!(CompositePush, dither),
        offset_of!(CompositePush, saturation),
    ]
    .iter()
    .map(|&o| o as u32)
    .collect();
    assert_eq!(glsl, rust);
}

#[test]
fn accumulate_push_constants_match_the_glsl_block() {
    use blackhole::passes::accumulate::AccumulatePush;
    let glsl = member_offsets(blackhole::shaders::ACCUMULATE, "Push");
    let rust: Vec<u32> = [
        offset_of!(AccumulatePush, width),
        offset_of!(AccumulatePush, height),
        offset_of!(AccumulatePush, weight),
    ]
    .iter()
    .map(|&o| o as u32)
    .collect();
    assert_eq!(glsl, rust);
    assert_eq!(size_of::<AccumulatePush>(), 12);
}

/// Offsets of a push-constant block in `spirv` against the Rust struct's.
fn push_matches(spirv: &[u8], rust: &[usize]) {
    let glsl = member_offsets(spirv, "Push");
    let rust: Vec<u32> = rust.iter().map(|&o| o as u32).collect();
    assert_eq!(glsl, rust);
}

#[test]
fn bloom_and_exposure_push_constants_match_the_glsl_blocks() {
    use blackhole::passes::bloom::{BloomDownPush, BloomPrefilterPush, BloomUpPush};
    use blackhole::passes::exposure::ExposurePush;
    push_matches(
        blackhole::shaders::BLOOM_PREFILTER,
        &[
            offset_of!(BloomPrefilterPush, src_texel),
            offset_of!(BloomPrefilterPush, dst_size),
            offset_of!(BloomPrefilterPush, threshold),
            offset_of!(BloomPrefilterPush, knee),
        ],
    );
    push_matches(
        blackhole::shaders::BLOOM_DOWN,
        &[
            offset_of!(BloomDownPush, src_texel),
            offset_of!(BloomDownPush, dst_size),
        ],
    );
    push_matches(
        blackhole::shaders::BLOOM_UP,
        &[
            offset_of!(BloomUpPush, src_texel),
            offset_of!(BloomUpPush, dst_size),
            offset_of!(BloomUpPush, radius),
        ],
    );
    push_matches(
        blackhole::shaders::EXPOSURE,
        &[
            offset_of!(ExposurePush, size),
            offset_of!(ExposurePush, low),
            offset_of!(ExposurePush, high),
            offset_of!(ExposurePush, key),
        ],
    );
}

/// The integer after `#define NAME` in a GLSL source.
fn glsl_define(src: &str, name: &str) -> u32 {
    src.lines()
        .find_map(|l| {
            let mut w = l.split_whitespace();
            (w.next() == Some("#define") && w.next() == Some(name))
                .then(|| w.next().and_then(|v| v.parse().ok()))
                .flatten()
        })
        .unwrap_or_else(|| panic!("#define {name} not found"))
}

#[test]
fn the_picture_codes_in_rust_match_the_glsl_source() {
    use blackhole::scene::{Brightness, Colormap, PolarizedView};
    let picture = include_str!("../shaders/include/pol_picture.glsl");
    let maps = include_str!("../shaders/include/colormap.glsl");
    for v in PolarizedView::ALL {
        let name = format!("VIEW_{}", v.name().to_uppercase());
        assert_eq!(glsl_define(picture, &name), v.gpu_id(), "{name}");
    }
    for b in Brightness::ALL {
        let name = format!("SCALE_{}", b.name().to_uppercase());
        assert_eq!(glsl_define(picture, &name), b.gpu_id(), "{name}");
    }
    for m in Colormap::ALL {
        let name = format!("CMAP_{}", m.name().to_uppercase());
        assert_eq!(glsl_define(maps, &name), m.gpu_id(), "{name}");
    }
}
