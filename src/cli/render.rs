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
    /// Skip the frames of a sequence whose files exist.
    pub resume: bool,
}

/// Set by Ctrl-C or SIGTERM: the render stops after the frame in hand (whose
/// file is written whole or not at all), so only complete frames remain. A
/// second signal ends the process at once.
static STOP: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);

/// Exit status of a render stopped by a signal (128 + SIGINT, as shells do).
const INTERRUPTED: u8 = 130;

fn catch_signals() {
    use std::sync::atomic::Ordering;
    let installed = ctrlc::set_handler(|| {
        if STOP.swap(true, Ordering::SeqCst) {
            std::process::exit(i32::from(INTERRUPTED));
        }
    });
    if let Err(e) = installed {
        log::warn!("Ctrl-C and SIGTERM will end the render abruptly: {e}");
    }
}

fn stopped() -> bool {
    STOP.load(std::sync::atomic::Ordering::SeqCst)
}

/// Renders what the arguments ask; checks every argument before the GPU.
pub fn run(view: View, out: PathBuf, options: Options) -> Result<ExitCode, Error> {
    let Options {
        aov,
        frames,
        exr_post,
        spp,
        resume,
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
    catch_signals();
    let mut renderer = Renderer::new(RendererOptions::default())?;
    let start = Instant::now();
    if let Some(range) = frames {
        let todo: Vec<u64> = range
            .clone()
            .filter(|&i| !(resume && numbered(&out, i).is_file()))
            .collect();
        let skipped = (range.end - range.start) - todo.len() as u64;
        let bar = indicatif::ProgressBar::new(todo.len() as u64);
        bar.set_style(
            indicatif::ProgressStyle::with_template(
                "{elapsed_precise} [{bar:40}] {pos}/{len} frames, ETA {eta} {msg}",
            )
            .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar())
            .progress_chars("=> "),
        );
        let mut written = 0u64;
        for &i in &todo {
            if stopped() {
                break;
            }
            let path = numbered(&out, i);
            let frame = renderer.render_samples(&scene.at_frame(i), width, height, kind, spp)?;
            output::write_frame(&frame, &path, format)?;
            written += 1;
            bar.set_message(format!("{}", path.display()));
            bar.inc(1);
        }
        bar.finish_and_clear();
        let skip_note = if skipped > 0 {
            format!(", {skipped} already there")
        } else {
            String::new()
        };
        if stopped() {
            eprintln!(
                "interrupted: wrote {written} of {} frames{skip_note}; every file written is complete, \
                 and the same command with --resume renders the rest",
                todo.len()
            );
            finish(renderer)?;
            return Ok(ExitCode::from(INTERRUPTED));
        }
        println!(
            "wrote {written} frames of {}..{} ({width}x{height}){skip_note} in {:.1} s on {}",
            numbered(&out, range.start).display(),
            numbered(&out, range.end - 1).display(),
            start.elapsed().as_secs_f64(),
            renderer.device_name()
        );
        return finish(renderer);
    }
    let frame = renderer.render_samples(&scene, width, height, kind, spp)?;
    if stopped() {
        eprintln!("interrupted: {} not written", out.display());
        finish(renderer)?;
        return Ok(ExitCode::from(INTERRUPTED));
    }
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

/// The output's folder must exist and take a file before any rendering
/// starts (a probe file is made and removed).
fn check_out_dir(out: &std::path::Path) -> Result<(), Error> {
    let dir = match out.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => std::path::Path::new("."),
    };
    if !dir.is_dir() {
        return Err(Error::Usage(format!(
            "--out {}: the folder {} does not exist",
            out.display(),
            dir.display()
        )));
    }
    let probe = dir.join(format!(".blackhole-probe-{}", std::process::id()));
    match std::fs::File::create(&probe) {
        Ok(_) => {
            let _ = std::fs::remove_file(&probe);
            Ok(())
        }
        Err(e) => Err(Error::Usage(format!(
            "--out {}: cannot write in {}: {e}",
            out.display(),
            dir.display()
        ))),
    }
}
