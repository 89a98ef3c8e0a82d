//! The look on lavapipe, validation required: the tone map keeps each
//! pixel's hue and clips nothing, the `doppler` preset shows its colours
//! (figures stated in docs/physics.md), each physics switch changes the image,
//! and the automatic exposure meters the light, not the black.

use blackhole::scene::{Bloom, Post, Tonemap};
mod common;

use blackhole::{OutputKind, Pixels, Renderer, Scene};
use common::{renderer, rgba8};

fn rgba32(f: blackhole::Frame) -> Vec<f32> {
    match f.pixels {
        Pixels::Rgba32F(p) => p,
        Pixels::Rgba8(_) => panic!("expected float pixels"),
    }
}

/// Rec. 709 luma of 8-bit RGBA pixels, in levels of 255.
fn luma8(px: &[u8]) -> Vec<f64> {
    px.chunks(4)
        .map(|p| 0.2126 * f64::from(p[0]) + 0.7152 * f64::from(p[1]) + 0.0722 * f64::from(p[2]))
        .collect()
}

/// A preset with a fixed exposure and no dither, so two renders differ only
/// where the scene does.
fn steady(preset: &str) -> Scene {
    let mut scene = Scene::load(preset).unwrap();
    scene.post.auto_exposure = false;
    scene.post.dither = false;
    scene
}

fn srgb_decode(v: u8) -> f64 {
    let c = f64::from(v) / 255.0;
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

const NO_BLOOM: Bloom = Bloom {
    strength: 0.0,
    threshold: 1.0,
    knee: 0.5,
    levels: 4,
    radius: 1.0,
};

#[test]
fn the_hue_preserving_tone_map_keeps_channel_ratios_and_never_turns_white() {
    // Blackbody-like colours from dim to 10^4 times too bright.
    const N: u32 = 64;
    let base = [[1.0f32, 0.55, 0.22], [0.75, 0.85, 1.0], [1.0, 0.9, 0.8]];
    let mut hdr = vec![0.0f32; (4 * N * N) as usize];
    for y in 0..N {
        for x in 0..N {
            let scale = 10f32.powf(-1.0 + 5.0 * x as f32 / (N - 1) as f32);
            let c = base[(y % 3) as usize];
            let i = (4 * (y * N + x)) as usize;
            hdr[i..i + 4].copy_from_slice(&[c[0] * scale, c[1] * scale, c[2] * scale, 1.0]);
        }
    }
    let post = Post {
        auto_exposure: false,
        dither: false,
        tonemap: Tonemap::HuePreserving,
        ..Post::default()
    };
    let mut r = renderer();
    let out = rgba8(r.post_process(&hdr, N, N, &NO_BLOOM, &post).unwrap());
    let mut brightest = 0u8;
    for y in 0..N {
        for x in 0..N {
            let i = (4 * (y * N + x)) as usize;
            let px = &out[i..i + 3];
            // However bright, a coloured pixel never turns white.
            assert!(px.iter().any(|&v| v < 240), "({x},{y}) went white: {px:?}");
            brightest = brightest.max(px[0].max(px[1]).max(px[2]));
            // Ratios of the decoded channels to the brightest one equal the
            // input's, to 8-bit precision, wherever the pixel is not dark.
            let m = px.iter().copied().max().unwrap();
            if m < 64 {
                continue;
            }
            let c = base[(y % 3) as usize];
            let cm = c[0].max(c[1]).max(c[2]);
            for k in 0..3 {
                let want = f64::from(c[k] / cm);
                let got = srgb_decode(px[k]) / srgb_decode(m);
                assert!(
                    (got - want).abs() < 0.03,
                    "({x},{y}) channel {k}: ratio {got:.3}, input {want:.3}"
                );
            }
        }
    }
    assert!(
        brightest > 240,
        "the brightest pixels reach near white: {brightest}"
    );
    // ACES Hill on the same input clips the bright end to white.
    let aces = rgba8(
        r.post_process(
            &hdr,
            N,
            N,
            &NO_BLOOM,
            &Post {
                tonemap: Tonemap::AcesHill,
                ..post.clone()
            },
        )
        .unwrap(),
    );
    assert!(aces.chunks(4).any(|p| p[..3] == [255, 255, 255]));
    assert_eq!(r.validation_counts(), (0, 0));
    r.shutdown().expect("nothing outlives the renderer");
}

#[test]
fn automatic_exposure_meters_the_lit_pixels() {
    // A dark frame with a lit patch: the patch is brought to the key value
    // whatever its level, and the black around it does not count.
    const N: u32 = 64;
    let mut r = renderer();
    let post = Post {
        dither: false,
        tonemap: Tonemap::Linear,
        ..Post::default()
    };
    for level in [0.01f32, 1.0, 300.0] {
        let mut hdr = vec![0.0f32; (4 * N * N) as usize];
        for y in 16..48 {
            for x in 16..48 {
                let i = (4 * (y * N + x)) as usize;
                hdr[i..i + 4].copy_from_slice(&[level, level, level, 1.0]);
            }
        }
        let out = rgba8(r.post_process(&hdr, N, N, &NO_BLOOM, &post).unwrap());
        let v = srgb_decode(out[(4 * (32 * N + 32)) as usize]);
        // The key to within the histogram's bin (a third of a stop).
        let key = f64::from(blackhole::passes::exposure::KEY);
        assert!((v / key - 1.0).abs() < 0.15, "level {level}: {v}");
        assert_eq!(out[0], 0, "black stays black");
    }
    assert_eq!(r.validation_counts(), (0, 0));
    r.shutdown().expect("nothing outlives the renderer");
}

/// Disk pixels of a frame (from the geodesic AOV) and the figures the
/// docs/physics.md states for the `doppler` preset: the share of disk pixels at 255
/// in any channel, and the mean blue share B / (R + G + B) of the right
/// (approaching) and left halves.
fn doppler_figures(r: &mut Renderer, scene: &Scene, w: u32, h: u32) -> (f64, f64, f64) {
    let ldr = rgba8(r.render(scene, w, h, OutputKind::Ldr).unwrap());
    let aov = rgba32(r.render(scene, w, h, OutputKind::Geodesic).unwrap());
    let (mut disk, mut at_255) = (0usize, 0usize);
    let mut share = [(0.0f64, 0usize); 2];
    for y in 0..h {
        for x in 0..w {
            let i = (4 * (y * w + x)) as usize;
            if (aov[i + 3] - 2.0).abs() > 0.5 {
                continue;
            }
            disk += 1;
            let px = &ldr[i..i + 3];
            if px.contains(&255) {
                at_255 += 1;
            }
            let sum: f64 = px.iter().map(|&v| f64::from(v)).sum();
            let half = usize::from(x >= w / 2);
            if sum > 0.0 {
                share[half].0 += f64::from(px[2]) / sum;
            }
            share[half].1 += 1;
        }
    }
    assert!(disk > 1000, "the disk is in view: {disk} pixels");
    let mean = |(s, n): (f64, usize)| s / n.max(1) as f64;
    (at_255 as f64 / disk as f64, mean(share[1]), mean(share[0]))
}

#[test]
fn the_doppler_preset_shows_blue_white_approaching_and_orange_receding() {
    let mut r = renderer();
    let scene = Scene::load("doppler").unwrap();
    let (clipped, right, left) = doppler_figures(&mut r, &scene, 640, 360);
    println!(
        "doppler 640x360: disk pixels at 255 {:.2} %, blue share approaching (right) {right:.3}, receding (left) {left:.3}, difference {:.3}",
        100.0 * clipped,
        right - left
    );
    assert!(
        clipped < 0.02,
        "{:.2} % of disk pixels clip",
        100.0 * clipped
    );
    assert!(right - left >= 0.12, "blue share {right:.3} vs {left:.3}");
    assert_eq!(r.validation_counts(), (0, 0));
    r.shutdown().expect("nothing outlives the renderer");
}

#[test]
fn each_physics_switch_changes_the_disk() {
    let mut r = renderer();
    let mut scene = steady("doppler");
    scene.bloom.strength = 0.0;
    let (w, h) = (160, 90);
    let mut with = |doppler, beaming, redshift| {
        scene.physics.doppler = doppler;
        scene.physics.beaming = beaming;
        scene.physics.gravitational_redshift = redshift;
        rgba8(r.render(&scene, w, h, OutputKind::Ldr).unwrap())
    };
    let none = with(false, false, false);
    let mean_abs_diff = |a: &[u8], b: &[u8]| {
        a.iter()
            .zip(b)
            .map(|(&x, &y)| f64::from(x.abs_diff(y)))
            .sum::<f64>()
            / a.len() as f64
    };
    for (name, img) in [
        ("doppler", with(true, false, false)),
        ("beaming", with(false, true, false)),
        ("gravitational redshift", with(false, false, true)),
    ] {
        let d = mean_abs_diff(&img, &none);
        println!("{name} alone: mean change {d:.2} of 255");
        assert!(d > 2.0, "{name} alone changes the image by only {d:.2}");
    }
    assert_eq!(r.validation_counts(), (0, 0));
    r.shutdown().expect("nothing outlives the renderer");
}

#[test]
fn light_travel_time_shows_the_disk_as_it_was() {
    // An animated frame with the disk turning: seeing each point as it was
    // when its light left changes the picture; with the disk at rest it
    // changes nothing. With gravity off too (straight paths at c: once the
    // key did nothing there).
    let mut r = renderer();
    for gravity in [true, false] {
        let mut scene = steady("default");
        scene.time = 40.0;
        scene.physics.gravity = gravity;
        let (w, h) = (160, 90);
        let mut frame = |delay: bool, speed: f64| {
            scene.animation.light_travel_time = delay;
            scene.disk.speed = speed;
            rgba8(r.render(&scene, w, h, OutputKind::Ldr).unwrap())
        };
        let (now, delayed) = (frame(false, 1.0), frame(true, 1.0));
        let changed = now
            .chunks(4)
            .zip(delayed.chunks(4))
            .filter(|(a, b)| a[..3].iter().zip(&b[..3]).any(|(x, y)| x.abs_diff(*y) > 8))
            .count();
        println!(
            "gravity {gravity}: light-travel time changes {changed} of {} pixels",
            w * h
        );
        assert!(
            changed > 200,
            "gravity {gravity}: only {changed} pixels changed"
        );
        assert_eq!(
            frame(false, 0.0),
            frame(true, 0.0),
            "a disk at rest looks the same"
        );
    }
    assert_eq!(r.validation_counts(), (0, 0));
    r.shutdown().expect("nothing outlives the renderer");
}

#[test]
fn a_spinning_holes_disk_is_delayed_as_the_non_rotating_one() {
    // At a* = 1e-4 the spinning hole's light paths (Mino time, its own
    // travel-time integral) are the non-rotating ones: what the delay
    // changes in the picture must be the same change (correlation 0.98,
    // mean change 6.28 against 6.24 of 255).
    let mut r = renderer();
    let mut scene = steady("default");
    scene.time = 40.0;
    let (w, h) = (160, 90);
    let mut luma = |spin: f64, delay: bool| -> Vec<f64> {
        scene.black_holes[0].spin = spin;
        scene.animation.light_travel_time = delay;
        luma8(&rgba8(r.render(&scene, w, h, OutputKind::Ldr).unwrap()))
    };
    let change =
        |a: &[f64], b: &[f64]| -> Vec<f64> { a.iter().zip(b).map(|(x, y)| x - y).collect() };
    let ds = change(&luma(0.0, true), &luma(0.0, false));
    let dk = change(&luma(1e-4, true), &luma(1e-4, false));
    let n = ds.len() as f64;
    let mean = |v: &[f64]| v.iter().sum::<f64>() / n;
    let (ms, mk) = (mean(&ds), mean(&dk));
    let cov: f64 = ds.iter().zip(&dk).map(|(a, b)| (a - ms) * (b - mk)).sum();
    let var = |v: &[f64], m: f64| v.iter().map(|a| (a - m) * (a - m)).sum::<f64>();
    let corr = cov / (var(&ds, ms) * var(&dk, mk)).sqrt();
    let size = |v: &[f64]| v.iter().map(|a| a.abs()).sum::<f64>() / n;
    println!(
        "the delay's change: a* = 0 mean |d| {:.2}, a* = 1e-4 {:.2}, correlation {corr:.3}",
        size(&ds),
        size(&dk)
    );
    assert!(
        size(&dk) > 1.0,
        "the delay changes nothing around a spinning hole"
    );
    assert!(corr > 0.8, "the changes differ: correlation {corr:.3}");
    let ratio = size(&dk) / size(&ds);
    assert!(
        (0.5..1.5).contains(&ratio),
        "the changes' sizes differ: {ratio:.2}"
    );
    // And at a* = 0.9 it changes the picture too.
    let d9 = change(&luma(0.9, true), &luma(0.9, false));
    assert!(size(&d9) > 1.0, "no delay at a* = 0.9: {:.2}", size(&d9));
    assert_eq!(r.validation_counts(), (0, 0));
    r.shutdown().expect("nothing outlives the renderer");
}

#[test]
fn at_a_tiny_spin_the_thin_disk_looks_as_around_a_still_hole() {
    // The default scene (a thin disk with structure: light comes through
    // its thin parts from the next crossing) at a* = 1e-4, along the
    // spinning hole's closed form, against a* = 0 along the non-rotating
    // one: the same picture, the light through the disk included (before
    // the spinning path let it through, the two differed by 3.5 levels of
    // 255 on average at 320x180, and 4,184 pixels by more than 16; now
    // 0.1 and 123, on the shadow's and the photon ring's edges).
    let mut r = renderer();
    let mut scene = steady("default");
    let (w, h) = (320, 180);
    let mut luma = |spin: f64| -> Vec<f64> {
        scene.black_holes[0].spin = spin;
        luma8(&rgba8(r.render(&scene, w, h, OutputKind::Ldr).unwrap()))
    };
    let (still, spinning) = (luma(0.0), luma(1e-4));
    let n = still.len() as f64;
    let mean = still
        .iter()
        .zip(&spinning)
        .map(|(a, b)| (a - b).abs())
        .sum::<f64>()
        / n;
    let worse = still
        .iter()
        .zip(&spinning)
        .filter(|(a, b)| (*a - *b).abs() > 16.0)
        .count();
    println!(
        "a* = 1e-4 against 0: mean |difference| {mean:.3} of 255, {worse} pixels off by more than 16"
    );
    assert!(mean < 0.5, "mean |difference| {mean:.3}");
    assert!(worse < 400, "{worse} pixels off by more than 16");
    assert_eq!(r.validation_counts(), (0, 0));
    r.shutdown().expect("nothing outlives the renderer");
}
