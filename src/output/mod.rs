//! Writing frames to disk: PNG (8-bit sRGB, tone-mapped) or EXR (linear HDR),
//! chosen by the extension. Files are written to a temporary name beside the
//! target and renamed, so a failure never leaves a partial file.

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
        let ext = path
            .extension()
            .map(|e| e.to_string_lossy().to_lowercase())
            .unwrap_or_default();
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
            image::DynamicImage::ImageRgb8(image::DynamicImage::ImageRgba8(rgba).to_rgb8())
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

/// Writes `path` through `write(tmp)` and a rename; removes `tmp` on failure.
pub fn write_atomically(path: &Path, write: impl FnOnce(&Path) -> Result<()>) -> Result<()> {
    let tmp = temp_path(path);
    let result = write(&tmp).and_then(|()| {
        std::fs::rename(&tmp, path).map_err(|source| Error::Io {
            path: path.to_owned(),
            source,
        })
    });
    if result.is_err() {
        let _ = std::fs::remove_file(&tmp);
    }
    result
}
