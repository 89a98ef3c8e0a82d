//! `cargo bench`: wall time of whole offscreen frames (ray march, bloom,
//! composite, readback) for fixed scenes and sizes on the Vulkan device the
//! renderer picks (the default view with spin 0.9 beside the default rows),
//! and the cost of one f64 light path, closed form against the step-by-step
//! integrator and the spinning hole's closed form. GPU time per pass:
//! `blackhole profile`.

use std::hint::black_box;
use std::time::Duration;

use blackhole::frame::OutputKind;
use blackhole::physics::closed_form::trace_closed;
use blackhole::physics::geodesic::{Disk, Hole, TraceOptions, trace};
use blackhole::scene::Scene;
use blackhole::{Renderer, RendererOptions};
use criterion::{Criterion, criterion_group, criterion_main};
use glam::DVec3;

fn frames(c: &mut Criterion) {
    let mut renderer = match Renderer::new(RendererOptions::default()) {
        Ok(r) => r,
        Err(e) => {
            eprintln!("frame benchmarks skipped: {e}");
            return;
        }
    };
    let mut group = c.benchmark_group("frame");
    group
        .sample_size(10)
        .measurement_time(Duration::from_secs(5));
    let cases: [(&str, &[(u32, u32)]); 4] = [
        (
            "default",
            &[(320, 180), (640, 360), (1280, 720), (1920, 1080)],
        ),
        ("doppler", &[(1280, 720)]),
        ("interstellar", &[(320, 180), (640, 360)]),
        ("gargantua", &[(640, 360)]),
    ];
    for (name, sizes) in cases {
        let scene = match Scene::load(name) {
            Ok(s) => s,
            Err(e) => panic!("preset {name}: {e}"),
        };
        for &(w, h) in sizes {
            group.bench_function(format!("{name}/{w}x{h}"), |b| {
                b.iter(|| {
                    renderer
                        .render(&scene, w, h, OutputKind::Ldr)
                        .unwrap_or_else(|e| panic!("{name} {w}x{h}: {e}"))
                })
            });
        }
    }
    // The default view around a spinning hole, against the default rows.
    let mut spinning = Scene::default();
    spinning.black_holes[0].spin = 0.9;
    for (w, h) in [(640, 360), (1280, 720)] {
        group.bench_function(format!("default spin 0.9/{w}x{h}"), |b| {
            b.iter(|| {
                renderer
                    .render(&spinning, w, h, OutputKind::Ldr)
                    .unwrap_or_else(|e| panic!("spin 0.9 {w}x{h}: {e}"))
            })
        });
    }
    group.finish();
}

fn light_paths(c: &mut Criterion) {
    let hole = Hole {
        position: DVec3::ZERO,
        rs: 1.0,
    };
    let disk = Disk {
        normal: DVec3::Y,
        inner: 3.0,
        outer: 12.0,
    };
    let x0 = DVec3::new(0.0, 0.8, -15.0);
    // A fan of rays across the disk and past the hole.
    let dirs: Vec<DVec3> = (0..64)
        .map(|i| (DVec3::new(-0.4 + 0.0125 * f64::from(i), -0.02, 1.0)).normalize())
        .collect();
    let mut group = c.benchmark_group("light path (64 rays, f64)");
    group.bench_function("closed form", |b| {
        b.iter(|| {
            for d in &dirs {
                black_box(trace_closed(&hole, Some(&disk), x0, *d));
            }
        })
    });
    let opts = TraceOptions::default();
    group
        .sample_size(10)
        .bench_function("integrator (tolerance 1e-12)", |b| {
            b.iter(|| {
                for d in &dirs {
                    black_box(trace(&[hole], Some(&disk), x0, *d, &opts));
                }
            })
        });
    group.bench_function("spinning hole closed form (a* = 0.9)", |b| {
        b.iter(|| {
            for d in &dirs {
                black_box(blackhole::physics::kerr::trace_zamo(
                    x0,
                    *d,
                    0.9,
                    Some(blackhole::physics::kerr::KerrDisk {
                        inner: 3.0,
                        outer: 12.0,
                    }),
                ));
            }
        })
    });
    group.finish();
}

criterion_group!(benches, light_paths, frames);
criterion_main!(benches);
