//! The bloom chain on lavapipe, validation required: one timed pass per
//! level, no contribution when nothing passes the threshold, and symmetric
//! spread of a single bright spot.

use blackhole::scene::{Bloom, Post, Tonemap};
mod common;

use blackhole::{OutputKind, Scene};
use common::{renderer, rgba8};

#[test]
fn every_level_is_its_own_timed_pass() {
    let mut r = renderer();
    let mut scene = Scene::builtin_default().unwrap();
    scene.bloom.levels = 4;
    let f = r.render(&scene, 96, 54, OutputKind::Ldr).unwrap();
    let names: Vec<&str> = f.timings.passes.iter().map(|p| p.name.as_str()).collect();
    let ray_march = r.ray_march_passes(&scene, 96, 54);
    let post = [
        "bloom prefilter",
        "bloom down 1",
        "bloom down 2",
        "bloom down 3",
        "bloom up 2",
        "bloom up 1",
        "bloom up 0",
        "exposure",
        "composite",
        "readback",
    ];
    assert_eq!(names, [&ray_march[..], &post[..]].concat());
    assert_eq!(r.validation_counts(), (0, 0));
    r.shutdown().expect("nothing outlives the renderer");
}

#[test]
fn strength_zero_culls_the_chain_and_a_threshold_nothing_reaches_adds_nothing() {
    let mut r = renderer();
    let mut scene = Scene::builtin_default().unwrap();
    scene.bloom.strength = 0.0;
    let plain = r.render(&scene, 96, 54, OutputKind::Ldr).unwrap();
    assert!(
        plain
            .timings
            .passes
            .iter()
            .all(|p| !p.name.starts_with("bloom"))
    );
    scene.bloom.strength = 1.0;
    scene.bloom.threshold = 1e6;
    scene.bloom.knee = 0.0;
    let dark_bloom = r.render(&scene, 96, 54, OutputKind::Ldr).unwrap();
    assert!(
        dark_bloom
            .timings
            .passes
            .iter()
            .any(|p| p.name == "bloom up 0")
    );
    assert_eq!(rgba8(plain), rgba8(dark_bloom));
    // And a real bloom changes the image.
    scene.bloom.threshold = 0.5;
    let bloomed = r.render(&scene, 96, 54, OutputKind::Ldr).unwrap();
    scene.bloom.strength = 0.0;
    assert_ne!(
        rgba8(bloomed),
        rgba8(r.render(&scene, 96, 54, OutputKind::Ldr).unwrap())
    );
    assert_eq!(r.validation_counts(), (0, 0));
    r.shutdown().expect("nothing outlives the renderer");
}

/// At 128 x 128 the composite finishes 2x2 blocks that share four bloom
/// texels (composite.comp, BLOCKS): a wrong cell or fraction there shifts
/// the glow and breaks the mirror symmetry checked here.
#[test]
fn a_bright_spot_spreads_symmetrically_and_falls_off() {
    const N: u32 = 128;
    let mut hdr = vec![0.0f32; (4 * N * N) as usize];
    for y in 63..=64 {
        for x in 63..=64 {
            let i = (4 * (y * N + x)) as usize;
            hdr[i..i + 4].copy_from_slice(&[50.0, 50.0, 50.0, 1.0]);
        }
    }
    let post = Post {
        exposure_ev: 0.0,
        auto_exposure: false,
        tonemap: Tonemap::Linear,
        dither: false,
        ..Post::default()
    };
    let bloom = Bloom {
        strength: 1.0,
        threshold: 1.0,
        knee: 0.5,
        levels: 5,
        radius: 1.0,
    };
    let mut r = renderer();
    let out = rgba8(r.post_process(&hdr, N, N, &bloom, &post).unwrap());
    let at = |x: u32, y: u32| out[(4 * (y * N + x)) as usize];
    for y in 0..N {
        for x in 0..N {
            let v = at(x, y);
            for (mx, my) in [(N - 1 - x, y), (x, N - 1 - y), (y, x)] {
                assert!(
                    v.abs_diff(at(mx, my)) <= 1,
                    "({x},{y}) = {v} vs ({mx},{my}) = {}",
                    at(mx, my)
                );
            }
        }
    }
    // It spreads: well beyond the 2x2 spot the image is lit, and it falls off.
    assert!(at(64 + 10, 64) > 0, "no glow 10 px away");
    for x in 66..100 {
        assert!(
            at(x + 1, 64) <= at(x, 64),
            "not falling off at {x}: {} then {}",
            at(x, 64),
            at(x + 1, 64)
        );
    }
    let unbloomed = rgba8(
        r.post_process(
            &hdr,
            N,
            N,
            &Bloom {
                strength: 0.0,
                ..bloom
            },
            &post,
        )
        .unwrap(),
    );
    assert_eq!(
        unbloomed[(4 * (64 * N + 74)) as usize],
        0,
        "without bloom nothing is there"
    );
    assert_eq!(r.validation_counts(), (0, 0));
    r.shutdown().expect("nothing outlives the renderer");
}
