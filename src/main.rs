//! The `blackhole` command line: `render` (offscreen stills).

use std::path::PathBuf;
use std::process::ExitCode;
use std::time::Instant;

use blackhole::output::{self, FileFormat};
use blackhole::{Error, Renderer, RendererOptions, Scene};
use clap::{Parser, Subcommand};

#[derive(Parser)]
#[command(
    name = "blackhole",
    version,
    about = "A Schwarzschild black-hole renderer on Vulkan"
)]
struct Cli {
    #[command(subcommand)]
    command: Command,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
enum Aov {
    /// The rendered image.
    Beauty,
    /// The geodesic AOV (DESIGN.md section 4).
    Geodesic,
}

/// What to render and at what size (shared by `render` and `profile`).
#[derive(clap::Args)]
struct View {
    /// Scene TOML file or built-in preset name (default: the built-in default scene).
    #[arg(long)]
    scene: Option<String>,
    /// Image width in pixels.
    #[arg(long, default_value_t = 1280, value_parser = clap::value_parser!(u32).range(1..=16384))]
    width: u32,
    /// Image height in pixels.
    #[arg(long, default_value_t = 720, value_parser = clap::value_parser!(u32).range(1..=16384))]
    height: u32,
}

/// The named scene or preset, or the built-in default.
fn load_scene(name: Option<&str>) -> Result<Scene, Error> {
    match name {
        Some(s) => Scene::load(s),
        None => Scene::builtin_default(),
    }
}

#[derive(Subcommand)]
enum Command {
    /// Render a still or a sequence offscreen to PNG (8-bit sRGB, tone-mapped) or EXR (linear HDR).
    #[command(after_help = presets_help())]
    Render {
        #[command(flatten)]
        view: View,
        /// Output file; the extension chooses the format (.png or .exr).
        #[arg(long, default_value = "blackhole.png")]
        out: PathBuf,
        /// What to write: the image, or per pixel where its ray went (EXR only;
        /// R,G,B,A = direction, or radius/azimuth/redshift, and the outcome).
        #[arg(long, value_enum, default_value_t = Aov::Beauty)]
        aov: Aov,
        /// Render frames A to B-1 of the scene's [animation] as a numbered
        /// sequence: --out out.png writes out_0000.png, out_0001.png, ...
        /// Frame i is at time i / fps, so ranges can be split across machines.
        #[arg(long, value_name = "A..B", value_parser = parse_range)]
        frames: Option<std::ops::Range<u64>>,
        /// With an .exr --out: apply bloom and exposure (still linear, no tone
        /// map). Without it an EXR is the ray march's radiance as it is.
        #[arg(long)]
        exr_post: bool,
    },
    /// Plot photon paths in the hole's equatorial plane (SVG), with the horizon,
    /// the photon sphere and the ISCO.
    Trace {
        /// Scene TOML file or preset (its first hole sets rs).
        #[arg(long)]
        scene: Option<String>,
        /// Output SVG file.
        #[arg(long, default_value = "paths.svg")]
        out: PathBuf,
    },
    /// Render N frames and print GPU time per pass (median, p95, share of frame).
    #[command(after_help = presets_help())]
    Profile {
        #[command(flatten)]
        view: View,
        /// Frames to time (after one warm-up frame).
        #[arg(long, default_value_t = 20, value_parser = clap::value_parser!(u32).range(1..=100000))]
        frames: u32,
        /// Also write the figures as JSON.
        #[arg(long)]
        json: Option<PathBuf>,
    },
}

fn parse_range(s: &str) -> Result<std::ops::Range<u64>, String> {
    let (a, b) = s
        .split_once("..")
        .ok_or_else(|| format!("`{s}` is not a range A..B (for example 0..120)"))?;
    let a: u64 = a
        .trim()
        .parse()
        .map_err(|_| format!("`{a}` in `{s}` is not a frame number"))?;
    let b: u64 = b
        .trim()
        .parse()
        .map_err(|_| format!("`{b}` in `{s}` is not a frame number"))?;
    if b <= a {
        return Err(format!(
            "`{s}` is empty: the end is exclusive and must be greater than the start"
        ));
    }
    Ok(a..b)
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

fn presets_help() -> String {
    let lines: Vec<String> = blackhole::scene::PRESETS
        .iter()
        .map(|(name, what, _)| format!("  {name:<12} {what}"))
        .collect();
    format!("Built-in presets (--scene NAME):\n{}", lines.join("\n"))
}

fn main() -> ExitCode {
    env_logger::Builder::from_env(env_logger::Env::default().default_filter_or("blackhole=info"))
        .format_timestamp(None)
        .init();
    let cli = Cli::parse();
    match run(cli) {
        Ok(code) => code,
        Err(e) => {
            eprintln!("error: {e}");
            ExitCode::from(e.exit_code() as u8)
        }
    }
}

fn run(cli: Cli) -> Result<ExitCode, Error> {
    match cli.command {
        Command::Render {
            view:
                View {
                    scene,
                    width,
                    height,
                },
            out,
            aov,
            frames,
            exr_post,
        } => {
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
            if aov == Aov::Geodesic && scene.disk.kind == blackhole::scene::DiskKind::Volumetric {
                return Err(Error::Usage(
                    "--aov geodesic needs a thin disk (or none); this scene's disk is volumetric"
                        .into(),
                ));
            }
            let kind = match aov {
                Aov::Beauty if exr_post => blackhole::OutputKind::HdrPost,
                Aov::Beauty => format.output_kind(),
                Aov::Geodesic => blackhole::OutputKind::Geodesic,
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
                    let frame = renderer.render(&scene.at_frame(i), width, height, kind)?;
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
            let frame = renderer.render(&scene, width, height, kind)?;
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
        Command::Trace { scene, out } => {
            let scene = load_scene(scene.as_deref())?;
            blackhole::trace_plot::write_svg(&scene, &out)?;
            println!("wrote {}", out.display());
            Ok(ExitCode::SUCCESS)
        }
        Command::Profile {
            view:
                View {
                    scene,
                    width,
                    height,
                },
            frames,
            json,
        } => {
            let scene = load_scene(scene.as_deref())?;
            let mut renderer = Renderer::new(RendererOptions::default())?;
            let report = blackhole::profile::run(&mut renderer, &scene, width, height, frames)?;
            print!("{}", report.table());
            if let Some(path) = json {
                output::write_atomically(&path, |tmp| {
                    std::fs::write(tmp, report.to_json()).map_err(|source| Error::Io {
                        path: path.clone(),
                        source,
                    })
                })?;
            }
            finish(renderer)
        }
    }
}

/// Shuts the renderer down (checking for leaks) and gives the exit code.
fn finish(renderer: Renderer) -> Result<ExitCode, Error> {
    let code = validation_verdict(&renderer);
    renderer.shutdown()?;
    Ok(code)
}

/// With validation on, any error or warning fails the run (exit 3).
fn validation_verdict(renderer: &Renderer) -> ExitCode {
    let (errors, warnings) = renderer.validation_counts();
    if renderer.validation_enabled() {
        eprintln!("validation: {errors} errors, {warnings} warnings");
    }
    if errors + warnings > 0 {
        ExitCode::from(3)
    } else {
        ExitCode::SUCCESS
    }
}
