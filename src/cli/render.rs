//! `blackhole render`: stills and numbered sequences, offscreen, to PNG or EXR.

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

use super::{Aov, View, finish, load_scene};
use crate::output::{self, FileFormat};
use crate::{Error, Renderer, RendererOptions};

/// What `render` writes besides the view and the file.
pub struct Options {
    pub aov: Aov,
    pub frames: Option<std::ops::Range<u64>>,
    pub exr_post: bool,
    /// Jittered samples per pixel.
    pub spp: u32,
}

/// Renders what the arguments ask; checks every argument before the GPU.
pub fn run(view: View, out: PathBuf, options: Options) -> Result<ExitCode, Error> {
    let Options {
        aov,
        frames,
        exr_post,
        spp,
    } = options;
    let View {
        scene,
        width,
        height,
    } = view;

    // Check everything the user gave before touching the GPU.
    let format = FileFormat::from_path(&out)?;
    check_out_dir(&out)?;
    if aov == Aov::Geodesic && format != FileFormat::Exr {
        return Err(Error::Usage(format!(
            "--aov geodesic writes float data: give an .exr --out, not {}",
            out.display()
        )));
    }
    if exr_post && (format != FileFormat::Exr || aov != Aov::Beauty) {
        return Err(Error::Usage(
            "--exr-post applies to the image (--aov beauty) written as .exr".into(),
        ));
    }
    let scene = load_scene(scene.as_deref())?;
    if aov == Aov::Geodesic && scene.disk.kind == crate::scene::DiskKind::Volumetric {
        return Err(Error::Usage(
            "--aov geodesic needs a thin disk (or none); this scene's disk is volumetric".into(),
        ));
    }
    let kind = match aov {
        Aov::Beauty if exr_post => crate::OutputKind::HdrPost,
        Aov::Beauty => format.output_kind(),
        Aov::Geodesic => crate::OutputKind::Geodesic,
    };
    let mut renderer = Renderer::new(RendererOptions::default())?;
    let start = Instant::now();
    if let Some(range) = frames {
        let bar = indicatif::ProgressBar::new(range.end - range.start);
        bar.set_style(
            indicatif::ProgressStyle::with_template(
                "{elapsed_precise} [{bar:40}] {pos}/{len} frames, ETA {eta} {msg}",
            )
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar())
            .progress_chars("=> "),
        );
        for i in range.clone() {
            let path = numbered(&out, i);
            let frame = renderer.render_samples(&scene.at_frame(i), width, height, kind, spp)?;
            output::write_frame(&frame, &path, format)?;
            bar.set_message(format!("{}", path.display()));
            bar.inc(1);
        }
        bar.finish_and_clear();
        println!(
            "wrote {} frames {}..{} ({width}x{height}) in {:.1} s on {}",
            range.end - range.start,
            numbered(&out, range.start).display(),
            numbered(&out, range.end - 1).display(),
            start.elapsed().as_secs_f64(),
            renderer.device_name()
        );
        return finish(renderer);
    }
    let frame = renderer.render_samples(&scene, width, height, kind, spp)?;
    output::write_frame(&frame, &out, format)?;
    log::info!("GPU: {}", frame.timings);
    println!(
        "wrote {} ({width}x{height}) in {:.0} ms on {}",
        out.display(),
        start.elapsed().as_secs_f64() * 1e3,
        renderer.device_name()
    );
    finish(renderer)
}

/// `out.png` and frame 7 -> `out_0007.png`.
fn numbered(out: &std::path::Path, index: u64) -> PathBuf {
    let stem = out
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let ext = out
        .extension()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    out.with_file_name(format!("{stem}_{index:04}.{ext}"))
}

/// The output's folder must exist before any rendering starts.
fn check_out_dir(out: &std::path::Path) -> Result<(), Error> {
    match out.parent() {
        Some(dir) if !dir.as_os_str().is_empty() && !dir.is_dir() => Err(Error::Usage(format!(
            "--out {}: the folder {} does not exist",
            out.display(),
            dir.display()
        ))),
        _ => Ok(()),
    }
}
