//! The command line: argument definitions (clap) and one module per command.
//! `main.rs` only parses and calls [`run`].

pub mod outputs;
pub mod profile;
pub mod render;
mod stokes;
pub mod trace;

use std::path::PathBuf;
use std::process::ExitCode;

use clap::{Parser, Subcommand};

use crate::{Error, Renderer, Scene};

/// `blackhole`: the whole command line.
#[derive(Parser)]
#[command(
    name = "blackhole",
    version,
    about = "A black-hole renderer on Vulkan: exact light paths around a non-rotating or spinning hole"
)]
pub struct Cli {
    #[command(subcommand)]
    pub command: Command,
}

#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Aov {
    /// The rendered image.
    Beauty,
    /// The geodesic AOV (docs/physics.md, "The geodesic AOV").
    Geodesic,
    /// The Stokes AOV of the polarized thin disk (docs/polarization.md).
    Stokes,
}

impl Aov {
    /// The name `--aov` takes.
    pub fn name(self) -> &'static str {
        match self {
            Aov::Beauty => "beauty",
            Aov::Geodesic => "geodesic",
            Aov::Stokes => "stokes",
        }
    }
}

/// What to render and at what size (shared by `render` and `profile`).
#[derive(clap::Args)]
pub struct View {
    /// Scene TOML file or built-in preset name (default: the built-in default scene).
    #[arg(long)]
    pub scene: Option<String>,
    /// Image width in pixels.
    #[arg(long, default_value_t = 1280, value_parser = clap::value_parser!(u32).range(1..=16384))]
    pub width: u32,
    /// Image height in pixels.
    #[arg(long, default_value_t = 720, value_parser = clap::value_parser!(u32).range(1..=16384))]
    pub height: u32,
}

/// The named scene or preset, or the built-in default.
pub fn load_scene(name: Option<&str>) -> Result<Scene, Error> {
    match name {
        Some(s) => Scene::load(s),
        None => Scene::builtin_default(),
    }
}

#[derive(Subcommand)]
pub enum Command {
    /// Open the real-time window: drag to orbit, wheel to zoom, a panel with
    /// every parameter and the GPU time of each pass.
    // (Every command reads a negative number as an option's value, refused
    // by that option's own rule, not as an unknown flag.)
    #[command(after_help = window_help(), allow_negative_numbers = true)]
    Window {
        #[command(flatten)]
        view: View,
        /// Fraction of the window's size the ray march runs at (upscaled in the
        /// composite), or `auto` to hold about 20 frames a second.
        #[arg(long, default_value = "auto", value_parser = parse_scale)]
        render_scale: RenderScale,
        /// How frames reach the display.
        #[arg(long, value_enum, default_value_t = Present::Fifo)]
        present: Present,
        /// Exit after N presented frames (for automated runs).
        #[arg(long, value_parser = clap::value_parser!(u64).range(1..))]
        frames: Option<u64>,
        /// Write the last presented frame (panel included) as PNG on exit.
        #[arg(long)]
        screenshot: Option<PathBuf>,
    },
    /// Render a still or a sequence offscreen to PNG (8-bit sRGB, tone-mapped), EXR (linear HDR) or video.
    #[command(after_help = presets_help(), allow_negative_numbers = true)]
    Render {
        #[command(flatten)]
        view: View,
        /// Output file; the extension chooses the format: .png or .exr, or
        /// with --frames a video through ffmpeg (.mp4 H.264, .webm VP9, .mov
        /// ProRes).
        #[arg(long, default_value = "blackhole.png")]
        out: PathBuf,
        /// What to write: the image, or per pixel where its ray went (EXR only;
        /// R,G,B,A = direction, or radius/azimuth/redshift, and the outcome).
        #[arg(long, value_enum, default_value_t = Aov::Beauty)]
        aov: Aov,
        /// Render frames A to B-1 of the scene's [animation] as a numbered
        /// sequence: --out out.png writes out_0000.png, out_0001.png, ...
        /// (--out film.mp4: one video). Frame i is at time i / fps, so ranges
        /// can be split across machines.
        #[arg(long, value_name = "A..B", value_parser = parse_range)]
        frames: Option<std::ops::Range<u64>>,
        /// With an .exr --out: apply bloom and exposure (still linear, no tone
        /// map). Without it an EXR is the ray march's radiance as it is.
        #[arg(long)]
        exr_post: bool,
        /// Jittered samples per pixel (the same sub-pixel offsets every frame,
        /// so sequences are deterministic), averaged before bloom and the tone
        /// map: anti-aliased stills and sequences at N times the ray march.
        #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(1..=i64::from(crate::render::MAX_SPP)))]
        spp: u32,
        /// The fraction of each frame's interval the shutter is open, in
        /// [0, 1] (overrides [animation] shutter): the --spp samples spread
        /// over it, so the disk's turning and the camera's motion blur.
        #[arg(long, value_name = "F", value_parser = parse_shutter)]
        shutter: Option<f64>,
        /// With --frames: render only the frames whose files are missing (each
        /// file is written whole and renamed into place, so one that exists is
        /// complete), e.g. after an interrupted run.
        #[arg(long, requires = "frames")]
        resume: bool,
        /// With --aov stokes (a still): also write the polarimetric numbers
        /// it prints (|m|_net, <|m|>, beta_2; through the beam and not) as JSON.
        #[arg(long)]
        json: Option<PathBuf>,
    },
    /// Plot photon paths in the hole's equatorial plane (SVG), with the horizon,
    /// the photon sphere and the ISCO.
    #[command(allow_negative_numbers = true)]
    Trace {
        /// Scene TOML file or preset (its first hole sets rs).
        #[arg(long)]
        scene: Option<String>,
        /// Output SVG file.
        #[arg(long, default_value = "paths.svg")]
        out: PathBuf,
    },
    /// Render N frames and print GPU time per pass (median, p95, share of frame).
    #[command(after_help = presets_help(), allow_negative_numbers = true)]
    Profile {
        #[command(flatten)]
        view: View,
        /// Frames to time (after the warm-up frames).
        #[arg(long, default_value_t = 20, value_parser = clap::value_parser!(u32).range(1..=i64::from(profile::MAX_FRAMES)))]
        frames: u32,
        /// Frames rendered first and not timed (pipeline builds, allocation, caches).
        #[arg(long, default_value_t = 1, value_parser = clap::value_parser!(u32).range(0..=i64::from(profile::MAX_WARMUP)))]
        warmup: u32,
        /// Also write the figures as JSON.
        #[arg(long)]
        json: Option<PathBuf>,
        /// Write Chrome trace-event JSON of the timed frames (open it in
        /// Perfetto or chrome://tracing): a track of GPU passes and one of CPU phases.
        #[arg(long)]
        trace: Option<PathBuf>,
    },
}

fn parse_shutter(s: &str) -> Result<f64, String> {
    match s.parse::<f64>() {
        Ok(v) if (0.0..=1.0).contains(&v) => Ok(v),
        _ => Err(format!(
            "{s:?} is not a shutter fraction: give a number from 0 (closed) to 1 (open the whole frame)"
        )),
    }
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

fn presets_help() -> String {
    let lines: Vec<String> = crate::scene::PRESETS
        .iter()
        .map(|(name, what, _)| format!("  {name:<12} {what}"))
        .collect();
    format!("Built-in presets (--scene NAME):\n{}", lines.join("\n"))
}

/// `--present`.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
pub enum Present {
    /// Vsync (always available).
    Fifo,
    /// Vsync without blocking (falls back to fifo).
    Mailbox,
    /// No vsync (falls back to fifo).
    Immediate,
}

/// `--render-scale`: a fraction in (0, 1], or automatic.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum RenderScale {
    Fixed(f64),
    Auto,
}

fn parse_scale(s: &str) -> Result<RenderScale, String> {
    if s == "auto" {
        return Ok(RenderScale::Auto);
    }
    match s.parse::<f64>() {
        Ok(v) if v > 0.0 && v <= 1.0 => Ok(RenderScale::Fixed(v)),
        _ => Err(format!("`{s}` is not `auto` or a number in (0, 1]")),
    }
}

fn window_help() -> String {
    format!(
        "Controls: left drag orbits, wheel zooms, right drag pans; 1/2/3 front, top and free \
         views; R resets; Space pauses; H hides the panel; F12 saves a PNG of the view; Esc quits.\n\n{}",
        presets_help()
    )
}

/// Runs a parsed command line; the exit code on success.
pub fn run(cli: Cli) -> Result<ExitCode, Error> {
    crate::settings::init()?;
    match cli.command {
        Command::Render {
            view,
            out,
            aov,
            frames,
            exr_post,
            spp,
            shutter,
            resume,
            json,
        } => render::run(
            view,
            out,
            render::Options {
                aov,
                frames,
                exr_post,
                spp,
                shutter,
                resume,
                json,
            },
        ),
        Command::Trace { scene, out } => trace::run(scene.as_deref(), &out),
        Command::Profile {
            view,
            frames,
            warmup,
            json,
            trace,
        } => profile::run_command(
            view,
            profile::Options {
                frames,
                warmup,
                json,
                trace,
            },
        ),
        Command::Window {
            view,
            render_scale,
            present,
            frames,
            screenshot,
        } => {
            let scene = load_scene(view.scene.as_deref())?;
            if let Some(path) = &screenshot {
                outputs::Output {
                    flag: "--screenshot",
                    path,
                    extensions: &["png"],
                    what: "PNG",
                }
                .check(&scene.input_files(), None)?;
            }
            crate::app::run(crate::app::WindowOptions {
                scene,
                width: view.width,
                height: view.height,
                render_scale: match render_scale {
                    RenderScale::Fixed(v) => Some(v),
                    RenderScale::Auto => None,
                },
                present: match present {
                    Present::Fifo => crate::vk::PresentMode::Fifo,
                    Present::Mailbox => crate::vk::PresentMode::Mailbox,
                    Present::Immediate => crate::vk::PresentMode::Immediate,
                },
                frames,
                screenshot,
            })
        }
    }
}

/// Shuts the renderer down (checking for leaks) and gives the exit code.
pub fn finish(renderer: Renderer) -> Result<ExitCode, Error> {
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
