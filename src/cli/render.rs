//! `blackhole render`: stills, numbered sequences (PNG, EXR) and videos (through ffmpeg), offscreen.

use std::collections::HashSet;
use std::ops::Range;
use std::path::{Path, PathBuf};
use std::process::ExitCode;
use std::sync::atomic::{AtomicBool, AtomicU64, Ordering};
use std::time::Instant;

use super::outputs::{self, Output, numbered};
use super::{Aov, View, finish, load_scene};
use crate::output::video::{Container, VideoWriter};
use crate::output::{self, FileFormat};
use crate::{Error, Renderer, RendererOptions, Scene};

/// What `render` writes besides the view and the file.
pub struct Options {
    pub aov: Aov,
    pub frames: Option<std::ops::Range<u64>>,
    pub exr_post: bool,
    /// Jittered samples per pixel.
    pub spp: u32,
    /// Overrides `[animation] shutter`.
    pub shutter: Option<f64>,
    /// Skip the frames of a sequence whose files exist.
    pub resume: bool,
    /// The Stokes numbers as JSON (`--json`).
    pub json: Option<PathBuf>,
}

/// Set by Ctrl-C or SIGTERM: the render stops after the frame in hand (whose
/// file is written whole or not at all), so only complete frames remain. A
/// second signal ends the process at once, removing the file being written
/// and printing what was written.
static STOP: AtomicBool = AtomicBool::new(false);
/// Frames written so far and frames this run renders (0 for a still).
static WRITTEN: AtomicU64 = AtomicU64::new(0);
static TODO: AtomicU64 = AtomicU64::new(0);

/// Exit status of a render stopped by a signal (128 + SIGINT, as shells do).
const INTERRUPTED: u8 = 130;

/// The one line printed when a run is interrupted.
fn interrupted_summary(out: &Path) -> String {
    let todo = TODO.load(Ordering::SeqCst);
    if todo == 0 {
        return format!("interrupted: {} not written", out.display());
    }
    format!(
        "interrupted: wrote {} of {todo} frames; every file written is complete, and the same \
         command with --resume renders the rest",
        WRITTEN.load(Ordering::SeqCst)
    )
}

fn catch_signals(out: &Path) {
    let out = out.to_path_buf();
    let installed = ctrlc::set_handler(move || {
        if STOP.swap(true, Ordering::SeqCst) {
            output::remove_current_temp();
            eprintln!(
                "{} (stopped at once by a second signal)",
                interrupted_summary(&out)
            );
            // Not exit(): its atexit handlers would tear the driver down
            // under the main thread's frame in flight (seen as a crash
            // instead of status 130). The file being written is gone, and
            // nothing else is half-done on disk.
            // SAFETY: _exit ends the process at once; no Rust state is used after.
            unsafe { libc::_exit(i32::from(INTERRUPTED)) }
        }
    });
    if let Err(e) = installed {
        log::warn!("Ctrl-C and SIGTERM will end the render abruptly: {e}");
    }
}

fn stopped() -> bool {
    STOP.load(Ordering::SeqCst)
}

/// Renders what the arguments ask; checks every argument before the GPU.
pub fn run(view: View, out: PathBuf, options: Options) -> Result<ExitCode, Error> {
    let Options {
        aov,
        frames,
        exr_post,
        spp,
        shutter,
        resume,
        json,
    } = options;
    let View {
        scene,
        width,
        height,
    } = view;

    // Check everything the user gave before touching the GPU.
    let mut scene = load_scene(scene.as_deref())?;
    scene.check_image_size(width, height)?;
    if let Some(s) = shutter {
        scene.animation.shutter = s;
    }
    let video = Container::from_path(&out);
    Output {
        flag: "--out",
        path: &out,
        extensions: &["png", "exr", "mp4", "webm", "mov"],
        what: "PNG (8-bit sRGB), EXR (linear HDR) or video (MP4, WebM, MOV)",
    }
    // A video is one file, not numbered ones.
    .check(
        &scene.input_files(),
        frames.as_ref().filter(|_| video.is_none()),
    )?;
    if let Some(container) = video {
        let Some(range) = frames else {
            return Err(Error::Usage(format!(
                "--out {}: a video is a sequence; give --frames A..B (or a .png or .exr --out for a still)",
                out.display()
            )));
        };
        if resume {
            return Err(Error::Usage(
                "--resume continues a sequence of numbered images; a video is written whole (render PNG frames to resume, then join them with ffmpeg)".into(),
            ));
        }
        if aov != Aov::Beauty || exr_post {
            return Err(Error::Usage(format!(
                "--out {}: video holds the 8-bit image; the geodesic AOV and --exr-post need an .exr --out",
                out.display()
            )));
        }
        container.check(width, height)?;
        scene.check_frames(&range, spp)?;
        catch_signals(&out);
        let job = Job {
            scene: &scene,
            out: &out,
            format: FileFormat::Png,
            kind: crate::OutputKind::Ldr,
            width,
            height,
            spp,
            json: None,
        };
        return job.video(range, container);
    }
    let format = FileFormat::from_path(&out)?;
    let request = ImageRequest {
        aov,
        exr_post,
        json: &json,
        frames: &frames,
    };
    check_image_request(&scene, &request, format, &out)?;
    // (A still with the shutter open samples frame 0's interval.)
    scene.check_frames(frames.as_ref().unwrap_or(&(0..1)), spp)?;
    let kind = match aov {
        Aov::Beauty if exr_post => crate::OutputKind::HdrPost,
        Aov::Beauty => format.output_kind(),
        Aov::Geodesic => crate::OutputKind::Geodesic,
        Aov::Stokes => crate::OutputKind::Stokes,
    };
    catch_signals(&out);
    let job = Job {
        scene: &scene,
        out: &out,
        format,
        kind,
        width,
        height,
        spp,
        json: json.as_deref(),
    };
    match frames {
        Some(range) => job.sequence(range, resume),
        None => job.still(),
    }
}

/// The progress bar of a sequence of `len` frames.
fn progress_bar(len: u64) -> indicatif::ProgressBar {
    let bar = indicatif::ProgressBar::new(len);
    bar.set_style(
        indicatif::ProgressStyle::with_template(
            "{elapsed_precise} [{bar:40}] {pos}/{len} frames, ETA {eta} {msg}",
        )
        .unwrap_or_else(|_| indicatif::ProgressStyle::default_bar())
        .progress_chars("=> "),
    );
    bar
}

/// What one `render` run makes.
struct Job<'a> {
    scene: &'a Scene,
    out: &'a Path,
    format: FileFormat,
    kind: crate::OutputKind,
    width: u32,
    height: u32,
    spp: u32,
    /// Where the Stokes numbers go as JSON.
    json: Option<&'a Path>,
}

impl Job<'_> {
    fn still(&self) -> Result<ExitCode, Error> {
        let (width, height) = (self.width, self.height);
        // A dead run's temporaries of this image go first.
        output::remove_stale_temps(self.out);
        let mut renderer = Renderer::new(RendererOptions::default())?;
        let start = Instant::now();
        // A still is frame 0; with the shutter open its samples spread over
        // frame 0's interval (closed, the scene exactly as written).
        // A signal stops it between samples (within one sample's time).
        renderer.stop_when(&STOP);
        let rendered = if self.scene.animation.shutter > 0.0 {
            let at = |s| self.scene.at_sample(0, s, self.spp);
            renderer.render_samples_with(&at, width, height, self.kind, self.spp)
        } else {
            renderer.render_samples(self.scene, width, height, self.kind, self.spp)
        };
        let frame = match rendered {
            Err(Error::Interrupted) => None,
            other => Some(other?),
        };
        let Some(frame) = frame.filter(|_| !stopped()) else {
            eprintln!("{}", interrupted_summary(self.out));
            finish(renderer)?;
            return Ok(ExitCode::from(INTERRUPTED));
        };
        output::write_frame(&frame, self.out, self.format)?;
        if self.kind == crate::OutputKind::Stokes {
            super::stokes::report(self.scene, &frame, self.json)?;
        }
        log::info!("GPU: {}", frame.timings);
        println!(
            "wrote {} ({width}x{height}) in {:.0} ms on {}",
            self.out.display(),
            start.elapsed().as_secs_f64() * 1e3,
            renderer.device_name()
        );
        finish(renderer)
    }

    /// Frames `range` as one video through ffmpeg, with the progress bar of
    /// a sequence; written to a temporary name and renamed when complete.
    fn video(&self, range: Range<u64>, container: Container) -> Result<ExitCode, Error> {
        let (width, height) = (self.width, self.height);
        let total = range.end - range.start;
        let mut renderer = Renderer::new(RendererOptions::default())?;
        // A signal stops it between samples (within one sample's time).
        renderer.stop_when(&STOP);
        let start = Instant::now();
        let fps = self.scene.animation.fps;
        let mut writer = VideoWriter::start(self.out, container, (width, height), fps)?;
        let bar = progress_bar(total);
        for i in range.clone() {
            if stopped() {
                break;
            }
            let at = |s| self.scene.at_sample(i, s, self.spp);
            let frame = match renderer.render_samples_with(&at, width, height, self.kind, self.spp)
            {
                Err(Error::Interrupted) => break,
                other => other?,
            };
            writer.push(&frame)?;
            bar.inc(1);
        }
        bar.finish_and_clear();
        if stopped() {
            drop(writer);
            eprintln!("interrupted: {} not written", self.out.display());
            finish(renderer)?;
            return Ok(ExitCode::from(INTERRUPTED));
        }
        let frames = writer.finish()?;
        println!(
            "wrote {} ({frames} frames, {width}x{height} at {fps} fps) in {:.1} s on {}",
            self.out.display(),
            start.elapsed().as_secs_f64(),
            renderer.device_name()
        );
        finish(renderer)
    }

    /// Frames `range` as numbered files, lazily (constant memory whatever
    /// the range); with `resume`, those already complete are skipped.
    fn sequence(&self, range: Range<u64>, resume: bool) -> Result<ExitCode, Error> {
        let (width, height) = (self.width, self.height);
        let done = if resume {
            self.scan_done(&range)?
        } else {
            HashSet::new()
        };
        let total = range.end - range.start;
        let todo = total - done.len() as u64;
        TODO.store(todo, Ordering::SeqCst);
        let mut renderer = Renderer::new(RendererOptions::default())?;
        // A signal stops it between samples (within one sample's time).
        renderer.stop_when(&STOP);
        let start = Instant::now();
        let bar = progress_bar(todo);
        for i in range.clone().filter(|i| !done.contains(i)) {
            if stopped() {
                break;
            }
            let path = numbered(self.out, i);
            let at = |s| self.scene.at_sample(i, s, self.spp);
            let frame = match renderer.render_samples_with(&at, width, height, self.kind, self.spp)
            {
                Err(Error::Interrupted) => break,
                other => other?,
            };
            output::write_frame(&frame, &path, self.format)?;
            WRITTEN.fetch_add(1, Ordering::SeqCst);
            bar.set_message(format!("{}", path.display()));
            bar.inc(1);
        }
        bar.finish_and_clear();
        if stopped() {
            eprintln!("{}", interrupted_summary(self.out));
            finish(renderer)?;
            return Ok(ExitCode::from(INTERRUPTED));
        }
        let skip_note = if done.is_empty() {
            String::new()
        } else {
            format!(", {} already there", done.len())
        };
        println!(
            "wrote {} frames of {}..{} ({width}x{height}){skip_note} in {:.1} s on {}",
            WRITTEN.load(Ordering::SeqCst),
            numbered(self.out, range.start).display(),
            numbered(self.out, range.end - 1).display(),
            start.elapsed().as_secs_f64(),
            renderer.device_name()
        );
        finish(renderer)
    }

    /// `--resume`: lists the output folder once and returns the frames of
    /// `range` whose files are complete. Incomplete ones (empty, truncated,
    /// another size) are reported and rendered again; temporary files of
    /// this range left by a killed run are removed.
    fn scan_done(&self, range: &Range<u64>) -> Result<HashSet<u64>, Error> {
        let dir = match self.out.parent() {
            Some(d) if !d.as_os_str().is_empty() => d,
            _ => Path::new("."),
        };
        let io = |source| Error::Io {
            path: dir.to_owned(),
            source,
        };
        let mut done = HashSet::new();
        let (mut broken, mut stale) = (Vec::new(), 0usize);
        for entry in std::fs::read_dir(dir).map_err(io)? {
            if stopped() {
                break;
            }
            let entry = entry.map_err(io)?;
            let name = entry.file_name().to_string_lossy().into_owned();
            if let Some(target) = name
                .strip_prefix('.')
                .and_then(|n| n.rsplitn(3, '.').nth(2))
            {
                let ours =
                    outputs::frame_index(self.out, target).is_some_and(|i| range.contains(&i));
                if ours && output::is_stale_temp_of(&name, target) {
                    stale += usize::from(std::fs::remove_file(entry.path()).is_ok());
                }
                continue;
            }
            let Some(i) = outputs::frame_index(self.out, &name).filter(|i| range.contains(i))
            else {
                continue;
            };
            match output::check_complete(&entry.path(), self.format, self.width, self.height) {
                Ok(()) => {
                    done.insert(i);
                }
                Err(why) => broken.push(format!("{name} ({why})")),
            }
        }
        if stale > 0 {
            eprintln!("resume: removed {stale} temporary file(s) left by an interrupted run");
        }
        if !broken.is_empty() {
            broken.sort();
            let shown = broken
                .iter()
                .take(5)
                .cloned()
                .collect::<Vec<_>>()
                .join(", ");
            let more = broken.len().saturating_sub(5);
            let more = if more > 0 {
                format!(" and {more} more")
            } else {
                String::new()
            };
            eprintln!(
                "resume: {} incomplete frame(s) will be rendered again: {shown}{more}",
                broken.len()
            );
        }
        Ok(done)
    }
}

/// What a still or a numbered sequence asks to write besides the image.
struct ImageRequest<'a> {
    aov: Aov,
    exr_post: bool,
    json: &'a Option<PathBuf>,
    frames: &'a Option<Range<u64>>,
}

/// The image outputs' rules (an AOV's file, the polarized picture,
/// --exr-post, --aov stokes's camera, --json), checked before the GPU starts.
fn check_image_request(
    scene: &Scene,
    request: &ImageRequest<'_>,
    format: FileFormat,
    out: &Path,
) -> Result<(), Error> {
    let ImageRequest {
        aov,
        exr_post,
        json,
        frames,
    } = *request;
    if aov != Aov::Beauty && format != FileFormat::Exr {
        return Err(Error::Usage(format!(
            "--aov {} writes float data: give an .exr --out, not {}",
            aov.name(),
            out.display()
        )));
    }
    if scene.polarization.enabled && aov == Aov::Beauty && format == FileFormat::Exr {
        return Err(Error::Usage(format!(
            "--out {}: the polarized picture ([polarization] enabled = true) is drawn in 8 bits (.png or video); `--aov stokes` writes its Stokes parameters as EXR",
            out.display()
        )));
    }
    if exr_post && (format != FileFormat::Exr || aov != Aov::Beauty) {
        return Err(Error::Usage(
            "--exr-post applies to the image (--aov beauty) written as .exr".into(),
        ));
    }
    if aov == Aov::Geodesic && scene.disk.kind == crate::scene::DiskKind::Volumetric {
        return Err(Error::Usage(format!(
            "--aov {} needs a thin disk (or none); this scene's disk is volumetric",
            aov.name()
        )));
    }
    if aov == Aov::Stokes
        && let Some(why) = scene.spacetime().polarization_refusal()
    {
        return Err(Error::Usage(format!("--aov stokes {why}")));
    }
    if let Some(path) = &json {
        if aov != Aov::Stokes || frames.is_some() {
            return Err(Error::Usage(
            "--json writes the numbers of a still's --aov stokes (give --aov stokes and no --frames)".into(),
        ));
        }
        Output {
            flag: "--json",
            path,
            extensions: &["json"],
            what: "JSON",
        }
        .check(&scene.input_files(), None)?;
        if outputs::same_file(path, out) {
            return Err(Error::Usage(format!(
                "--json {} and --out name the same file",
                path.display()
            )));
        }
    }
    Ok(())
}
