//! Every file a command will write is checked here, before any GPU work: its
//! extension says the format written, it is not a folder, its folder exists
//! and takes a file, and it is not one of the run's inputs (the scene file,
//! its sky images), which writing would destroy.

use std::ops::Range;
use std::path::{Path, PathBuf};

use crate::{Error, Result};

/// One output a command writes.
pub struct Output<'a> {
    /// The option that names it, for messages (`--out`, `--json`, ...).
    pub flag: &'static str,
    pub path: &'a Path,
    /// Extensions (lower case, no dot) of the formats written there.
    pub extensions: &'static [&'static str],
    /// What is written there, for messages ("SVG", "PNG or EXR", ...).
    pub what: &'static str,
}

impl Output<'_> {
    fn refuse(&self, why: impl std::fmt::Display) -> Error {
        Error::Usage(format!("{} {}: {why}", self.flag, self.path.display()))
    }

    /// Checks the output (and, with `frames`, every numbered file of the
    /// sequence) against the rules above.
    pub fn check(&self, inputs: &[PathBuf], frames: Option<&Range<u64>>) -> Result<()> {
        let ext = crate::output::extension(self.path);
        if !self.extensions.contains(&ext.as_str()) {
            let list: Vec<String> = self.extensions.iter().map(|e| format!(".{e}")).collect();
            let shown = if ext.is_empty() {
                "no extension".to_string()
            } else {
                format!("the extension .{ext}")
            };
            return Err(self.refuse(format!(
                "has {shown}, but this writes {}: name a {} file",
                self.what,
                list.join(" or ")
            )));
        }
        if self.path.is_dir() {
            return Err(self.refuse("is a folder; name a file to write"));
        }
        check_folder(self)?;
        for input in inputs {
            let clash = match frames {
                None => same_file(self.path, input),
                Some(range) => numbered_clash(self.path, range, input),
            };
            if clash {
                return Err(self.refuse(format!(
                    "would overwrite {}, an input of this run; choose another name",
                    input.display()
                )));
            }
        }
        Ok(())
    }
}

/// Checks every output of a run ([`Output::check`]), and that no two name the
/// same file: the second written would replace the first (`profile --json
/// p.json --trace p.json` once left only the trace). `frames`: the numbered
/// sequence of the first, if any.
pub fn check_all(
    outs: &[Output<'_>],
    inputs: &[PathBuf],
    frames: Option<&Range<u64>>,
) -> Result<()> {
    for (i, out) in outs.iter().enumerate() {
        out.check(inputs, if i == 0 { frames } else { None })?;
        if let Some(first) = outs[..i].iter().find(|o| same_place(o.path, out.path)) {
            return Err(out.refuse(format!(
                "is also {}'s file: two outputs of one run would overwrite each other; \
                 give each its own name",
                first.flag
            )));
        }
    }
    Ok(())
}

/// Whether two output paths name one file, existing or not (their folders
/// resolved, through links).
fn same_place(a: &Path, b: &Path) -> bool {
    let place = |p: &Path| {
        let dir = match p.parent() {
            Some(d) if !d.as_os_str().is_empty() => d,
            _ => Path::new("."),
        };
        dir.canonicalize()
            .ok()
            .zip(p.file_name().map(|n| n.to_owned()))
    };
    same_file(a, b) || matches!((place(a), place(b)), (Some(x), Some(y)) if x == y)
}

/// The folder the output goes to must exist and take a file (a probe file is
/// made and removed).
fn check_folder(out: &Output<'_>) -> Result<()> {
    let dir = match out.path.parent() {
        Some(d) if !d.as_os_str().is_empty() => d,
        _ => Path::new("."),
    };
    if !dir.is_dir() {
        return Err(out.refuse(format!("the folder {} does not exist", dir.display())));
    }
    let probe = dir.join(format!(".blackhole-probe-{}", std::process::id()));
    match std::fs::File::create(&probe) {
        Ok(_) => {
            let _ = std::fs::remove_file(&probe);
            Ok(())
        }
        Err(e) => Err(out.refuse(format!("cannot write in {}: {e}", dir.display()))),
    }
}

/// Whether `a` and `b` name the same existing file (through links too).
pub fn same_file(a: &Path, b: &Path) -> bool {
    let (Ok(ma), Ok(mb)) = (std::fs::metadata(a), std::fs::metadata(b)) else {
        return false;
    };
    #[cfg(unix)]
    {
        use std::os::unix::fs::MetadataExt;
        ma.dev() == mb.dev() && ma.ino() == mb.ino()
    }
    #[cfg(not(unix))]
    {
        let _ = (ma, mb);
        matches!((a.canonicalize(), b.canonicalize()), (Ok(x), Ok(y)) if x == y)
    }
}

/// `out.png` and frame 7 -> `out_0007.png`.
pub fn numbered(out: &Path, index: u64) -> PathBuf {
    let (stem, ext) = stem_and_ext(out);
    out.with_file_name(format!("{stem}_{index:04}.{ext}"))
}

fn stem_and_ext(out: &Path) -> (String, String) {
    let stem = out
        .file_stem()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    let ext = out
        .extension()
        .map(|s| s.to_string_lossy().into_owned())
        .unwrap_or_default();
    (stem, ext)
}

/// The frame index of `name` if it is one of `out`'s numbered files
/// (`out_0007.png` -> 7).
pub fn frame_index(out: &Path, name: &str) -> Option<u64> {
    let (stem, ext) = stem_and_ext(out);
    let digits = name
        .strip_prefix(stem.as_str())?
        .strip_prefix('_')?
        .strip_suffix(ext.as_str())?
        .strip_suffix('.')?;
    if digits.len() < 4 || !digits.bytes().all(|b| b.is_ascii_digit()) {
        return None;
    }
    let n: u64 = digits.parse().ok()?;
    // Only the spelling `numbered` writes (no extra leading zeros).
    (format!("{n:04}") == digits).then_some(n)
}

/// Whether `input` is one of the numbered files a sequence over `range`
/// would write.
fn numbered_clash(out: &Path, range: &Range<u64>, input: &Path) -> bool {
    let Some(name) = input.file_name().map(|n| n.to_string_lossy().into_owned()) else {
        return false;
    };
    frame_index(out, &name)
        .filter(|n| range.contains(n))
        .is_some_and(|n| same_file(&numbered(out, n), input))
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn numbered_names_round_trip() {
        let out = Path::new("dir/f.png");
        assert_eq!(numbered(out, 7), Path::new("dir/f_0007.png"));
        assert_eq!(frame_index(out, "f_0007.png"), Some(7));
        assert_eq!(frame_index(out, "f_123456.png"), Some(123456));
        assert_eq!(frame_index(out, "f_00007.png"), None);
        assert_eq!(frame_index(out, "f_0007.exr"), None);
        assert_eq!(frame_index(out, "g_0007.png"), None);
        assert_eq!(frame_index(out, ".f_0007.png.12.tmp"), None);
    }

    #[test]
    fn an_output_over_an_input_is_refused() {
        let dir = tempfile::tempdir().expect("temp dir");
        let scene = dir.path().join("scene.png");
        std::fs::write(&scene, "x").expect("write");
        let out = Output {
            flag: "--out",
            path: &scene,
            extensions: &["png"],
            what: "PNG",
        };
        let e = out.check(std::slice::from_ref(&scene), None).unwrap_err();
        assert!(e.to_string().contains("an input of this run"), "{e}");
        // A sequence whose numbered files would include it.
        let frame = dir.path().join("f_0003.png");
        std::fs::write(&frame, "x").expect("write");
        let seq = Output {
            path: &dir.path().join("f.png"),
            ..out
        };
        assert!(
            seq.check(std::slice::from_ref(&frame), Some(&(0..10)))
                .is_err()
        );
        assert!(
            seq.check(std::slice::from_ref(&frame), Some(&(4..10)))
                .is_ok()
        );
    }
}
