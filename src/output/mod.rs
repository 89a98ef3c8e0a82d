//! Writing frames to disk: PNG (8-bit sRGB, tone-mapped) or EXR (linear HDR),
//! chosen by the extension, or a sequence as one video (video.rs, through
//! ffmpeg). Files are written to a temporary name beside the target and
//! renamed, so a failure never leaves a partial file.

pub mod video;

use std::path::{Path, PathBuf};

use crate::frame::{Frame, OutputKind, Pixels};
use crate::{Error, Result};

/// Output file formats.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum FileFormat {
    Png,
    Exr,
}

impl FileFormat {
    /// The format named by `path`'s extension.
    pub fn from_path(path: &Path) -> Result<Self> {
        let ext = extension(path);
        match ext.as_str() {
            "png" => Ok(FileFormat::Png),
            "exr" => Ok(FileFormat::Exr),
            _ => Err(Error::Usage(format!(
                "--out {}: unknown extension `{ext}`; use .png (8-bit sRGB) or .exr (linear HDR)",
                path.display()
            ))),
        }
    }

    /// What the renderer must produce for this format.
    pub fn output_kind(self) -> OutputKind {
        match self {
            FileFormat::Png => OutputKind::Ldr,
            FileFormat::Exr => OutputKind::Hdr,
        }
    }
}

/// The extension of `path`, lower case ("" if none).
pub fn extension(path: &Path) -> String {
    path.extension()
        .map(|e| e.to_string_lossy().to_lowercase())
        .unwrap_or_default()
}

fn temp_path(path: &Path) -> PathBuf {
    let name = path
        .file_name()
        .map(|n| n.to_string_lossy().into_owned())
        .unwrap_or_else(|| "frame".into());
    path.with_file_name(format!(".{name}.{}.tmp", std::process::id()))
}

/// Writes `frame` to `path` in `format`, atomically.
pub fn write_frame(frame: &Frame, path: &Path, format: FileFormat) -> Result<()> {
    let (w, h) = (frame.width, frame.height);
    let bad = || Error::Other(format!("frame buffer does not match {w}x{h}"));
    let img: image::DynamicImage = match (&frame.pixels, format) {
        (Pixels::Rgba8(p), FileFormat::Png) => {
            let rgba = image::RgbaImage::from_raw(w, h, p.clone()).ok_or_else(bad)?;
            // RGB, unless some pixel has no ray (a fisheye's corners): then
            // RGBA, transparent there.
            if p.chunks_exact(4).all(|px| px[3] == 255) {
                image::DynamicImage::ImageRgb8(image::DynamicImage::ImageRgba8(rgba).to_rgb8())
            } else {
                image::DynamicImage::ImageRgba8(rgba)
            }
        }
        // Alpha is written as rendered: 1 for beauty, the outcome for the AOV.
        (Pixels::Rgba32F(p), FileFormat::Exr) => image::DynamicImage::ImageRgba32F(
            image::Rgba32FImage::from_raw(w, h, p.clone()).ok_or_else(bad)?,
        ),
        _ => {
            return Err(Error::Other(format!(
                "cannot write these pixels as {format:?} (renderer produced the wrong kind)"
            )));
        }
    };
    write_atomically(path, |tmp| {
        let fmt = match format {
            FileFormat::Png => image::ImageFormat::Png,
            FileFormat::Exr => image::ImageFormat::OpenExr,
        };
        img.save_with_format(tmp, fmt)
            .map_err(|source| Error::Image {
                path: path.to_owned(),
                source,
            })
    })
}

/// Whether `path` holds a whole frame of `width` x `height` in `format`, as
/// [`write_frame`] writes it: a PNG whose header has that size and which
/// ends with its closing chunk, an EXR that decodes to that size. The reason
/// in words if not ("empty", "truncated", "3x2, not 64x36", ...).
pub fn check_complete(
    path: &Path,
    format: FileFormat,
    width: u32,
    height: u32,
) -> std::result::Result<(), String> {
    let len = std::fs::metadata(path).map_err(|e| e.to_string())?.len();
    if len == 0 {
        return Err("empty".into());
    }
    let reader = image::ImageReader::open(path)
        .map_err(|e| e.to_string())?
        .with_guessed_format()
        .map_err(|e| e.to_string())?;
    let (w, h) = match format {
        FileFormat::Png => {
            let (w, h) = reader
                .into_dimensions()
                .map_err(|_| "truncated or not a PNG".to_string())?;
            // Every PNG ends with the IEND chunk: length 0, type, CRC.
            const IEND: [u8; 12] = [0, 0, 0, 0, b'I', b'E', b'N', b'D', 0xAE, 0x42, 0x60, 0x82];
            use std::io::{Read, Seek, SeekFrom};
            let mut tail = [0u8; 12];
            let mut f = std::fs::File::open(path).map_err(|e| e.to_string())?;
            f.seek(SeekFrom::End(-12))
                .and_then(|_| f.read_exact(&mut tail))
                .map_err(|_| "truncated".to_string())?;
            if tail != IEND {
                return Err("truncated (no closing IEND chunk)".into());
            }
            (w, h)
        }
        FileFormat::Exr => {
            let img = reader
                .decode()
                .map_err(|_| "truncated or not an EXR".to_string())?;
            (img.width(), img.height())
        }
    };
    if (w, h) != (width, height) {
        return Err(format!("{w}x{h}, not {width}x{height}"));
    }
    Ok(())
}

/// The temporary file being written now, if any: a second interrupt removes
/// it before the process ends ([`remove_current_temp`]).
static CURRENT_TEMP: std::sync::Mutex<Option<PathBuf>> = std::sync::Mutex::new(None);

fn set_current_temp(tmp: Option<&Path>) {
    if let Ok(mut current) = CURRENT_TEMP.lock() {
        *current = tmp.map(Path::to_path_buf);
    }
}

/// Removes the temporary file being written, if any (for a process that is
/// about to end in the middle of a write).
pub fn remove_current_temp() {
    if let Ok(mut current) = CURRENT_TEMP.lock()
        && let Some(tmp) = current.take()
    {
        let _ = std::fs::remove_file(tmp);
    }
}

/// Whether `name` is a temporary file of this module's for the file `target`
/// (`.target.<pid>.tmp`), left by a process that was killed mid-write.
pub fn is_temp_of(name: &str, target: &str) -> bool {
    temp_writer(name, target).is_some()
}

/// The pid of the run writing the temporary `name` of `target`.
fn temp_writer(name: &str, target: &str) -> Option<u32> {
    name.strip_prefix('.')
        .and_then(|n| n.strip_prefix(target))
        .and_then(|n| n.strip_prefix('.'))
        .and_then(|n| n.strip_suffix(".tmp"))
        .filter(|pid| !pid.is_empty() && pid.bytes().all(|b| b.is_ascii_digit()))
        .and_then(|pid| pid.parse().ok())
}

/// Whether `name` is a temporary of `target` left by a run that is gone:
/// its writer's pid no longer runs (a live run's, stopped or slow, is its
/// own: `--resume` once deleted one, which then failed).
pub fn is_stale_temp_of(name: &str, target: &str) -> bool {
    temp_writer(name, target).is_some_and(|pid| pid != std::process::id() && !running(pid))
}

#[cfg(unix)]
fn running(pid: u32) -> bool {
    let Ok(pid) = libc::pid_t::try_from(pid) else {
        return false;
    };
    // SAFETY: kill with signal 0 sends nothing; it only asks whether the
    // process exists (EPERM: it does, under another user).
    let alive = unsafe { libc::kill(pid, 0) } == 0;
    alive || std::io::Error::last_os_error().raw_os_error() == Some(libc::EPERM)
}

#[cfg(not(unix))]
fn running(_pid: u32) -> bool {
    true
}

/// Removes the temporaries a dead run left of `out` (a still or a video:
/// its own name) in one listing of its folder; returns how many.
pub fn remove_stale_temps(out: &Path) -> usize {
    let Some(target) = out.file_name().map(|n| n.to_string_lossy().into_owned()) else {
        return 0;
    };
    let dir = match out.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    let Ok(entries) = std::fs::read_dir(dir) else {
        return 0;
    };
    entries
        .flatten()
        .filter(|e| is_stale_temp_of(&e.file_name().to_string_lossy(), &target))
        .filter(|e| std::fs::remove_file(e.path()).is_ok())
        .count()
}

/// Writes `path` through `write(tmp)`, flushes the file to the disk and
/// renames it into place (then flushes the folder), so a crash or a power
/// cut leaves the old file or the whole new one; removes `tmp` on failure.
pub fn write_atomically(path: &Path, write: impl FnOnce(&Path) -> Result<()>) -> Result<()> {
    let tmp = temp_path(path);
    set_current_temp(Some(&tmp));
    let io = |source| Error::Io {
        path: path.to_owned(),
        source,
    };
    let result = write(&tmp)
        .and_then(|()| {
            std::fs::File::open(&tmp)
                .and_then(|f| f.sync_all())
                .map_err(io)
        })
        .and_then(|()| std::fs::rename(&tmp, path).map_err(io));
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    } else if let Some(dir) = path.parent() {
        let dir = if dir.as_os_str().is_empty() {
            Path::new(".")
        } else {
            dir
        };
        // The rename itself reaches the disk with the folder.
        let _ = std::fs::File::open(dir).and_then(|d| d.sync_all());
    }
    set_current_temp(None);
    result
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_second_signal_during_a_write_removes_the_temporary() {
        let dir = tempfile::tempdir().expect("temp dir");
        let path = dir.path().join("f.png");
        let mut seen = None;
        // What the signal handler does while the file is being written.
        let result = write_atomically(&path, |tmp| {
            std::fs::write(tmp, b"half a frame").expect("writing");
            seen = Some(tmp.to_path_buf());
            remove_current_temp();
            Ok(())
        });
        assert!(result.is_err(), "the vanished temporary is not renamed");
        assert!(!seen.expect("a temporary was used").exists());
        assert!(!path.exists());
    }

    #[test]
    fn temporaries_are_recognised_by_name() {
        assert!(is_temp_of(".f_0003.png.4242.tmp", "f_0003.png"));
        assert!(!is_temp_of(".f_0003.png.tmp", "f_0003.png"));
        assert!(!is_temp_of(".f_0003.png.42x.tmp", "f_0003.png"));
        assert!(!is_temp_of("f_0003.png", "f_0003.png"));
    }
}
