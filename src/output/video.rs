//! Sequences straight to video: the frames' 8-bit sRGB pixels are piped to
//! `ffmpeg` (a separate program, found on PATH), which encodes them into a
//! temporary file beside the target; the file is renamed into place only
//! when every frame is in and ffmpeg has finished, so an interrupted or
//! failed run leaves no partial video.
//!
//! The containers and codecs: `.mp4` H.264 (libx264, CRF 18, yuv420p, the
//! index at the front for streaming), `.webm` VP9 (libvpx-vp9, CRF 30),
//! `.mov` ProRes 422 HQ (prores_ks, 10-bit 4:2:2, for editing). All tagged
//! BT.709.

use std::io::{Read, Write};
use std::path::{Path, PathBuf};
use std::process::{Child, ChildStdin, Command, Stdio};

use crate::frame::{Frame, Pixels};
use crate::{Error, Result};

/// A video container, chosen by the output's extension.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Container {
    Mp4,
    Webm,
    Mov,
}

/// The extensions written as video.
pub const VIDEO_EXTENSIONS: [&str; 3] = ["mp4", "webm", "mov"];

impl Container {
    /// The container `path`'s extension names, if it is a video.
    pub fn from_path(path: &Path) -> Option<Container> {
        match super::extension(path).as_str() {
            "mp4" => Some(Container::Mp4),
            "webm" => Some(Container::Webm),
            "mov" => Some(Container::Mov),
            _ => None,
        }
    }

    /// ffmpeg's name of the encoder, and what it is in words.
    fn encoder(self) -> (&'static str, &'static str) {
        match self {
            Container::Mp4 => ("libx264", "H.264"),
            Container::Webm => ("libvpx-vp9", "VP9"),
            Container::Mov => ("prores_ks", "ProRes"),
        }
    }

    /// ffmpeg's options for the codec (after `-c:v` and the encoder) and the
    /// container.
    fn args(self) -> &'static [&'static str] {
        match self {
            Container::Mp4 => &[
                "-preset",
                "medium",
                "-crf",
                "18",
                "-pix_fmt",
                "yuv420p",
                "-movflags",
                "+faststart",
                "-f",
                "mp4",
            ],
            Container::Webm => &[
                "-crf", "30", "-b:v", "0", "-row-mt", "1", "-pix_fmt", "yuv420p", "-f", "webm",
            ],
            Container::Mov => &["-profile:v", "3", "-pix_fmt", "yuv422p10le", "-f", "mov"],
        }
    }

    /// Checks, before any rendering, that a `width` x `height` video can be
    /// written: chroma subsampling needs even sizes (4:2:0 both, 4:2:2 the
    /// width), and ffmpeg must be installed with the encoder.
    pub fn check(self, width: u32, height: u32) -> Result<()> {
        let (encoder, name) = self.encoder();
        let odd = match self {
            Container::Mov => width % 2 != 0,
            _ => width % 2 != 0 || height % 2 != 0,
        };
        if odd {
            let needs = if self == Container::Mov {
                "an even width"
            } else {
                "an even width and height"
            };
            return Err(Error::Usage(format!(
                "--width {width} --height {height}: {name} video needs {needs}"
            )));
        }
        let listed = Command::new("ffmpeg")
            .args(["-hide_banner", "-loglevel", "error", "-encoders"])
            .stdin(Stdio::null())
            .stderr(Stdio::null())
            .output();
        let listed = match listed {
            Ok(out) if out.status.success() => String::from_utf8_lossy(&out.stdout).into_owned(),
            Ok(out) => {
                return Err(Error::Usage(format!(
                    "writing video runs ffmpeg, which failed to list its encoders ({})",
                    out.status
                )));
            }
            Err(e) if e.kind() == std::io::ErrorKind::NotFound => {
                return Err(Error::Usage(
                    "writing video needs ffmpeg, which is not installed (Debian/Ubuntu: \
                     apt-get install ffmpeg); or write PNG frames and join them later"
                        .into(),
                ));
            }
            Err(e) => {
                return Err(Error::Usage(format!(
                    "writing video runs ffmpeg, which could not start: {e}"
                )));
            }
        };
        if !listed.split_whitespace().any(|word| word == encoder) {
            return Err(Error::Usage(format!(
                "this ffmpeg has no {encoder} encoder for {name} video; install a full ffmpeg \
                 build (Debian/Ubuntu: apt-get install ffmpeg) or choose another of .mp4, \
                 .webm, .mov"
            )));
        }
        Ok(())
    }
}

/// A video being written: ffmpeg reading raw RGBA frames on its standard
/// input into a temporary file. Dropped before [`VideoWriter::finish`], it
/// stops ffmpeg and removes the temporary.
pub struct VideoWriter {
    child: Option<Child>,
    stdin: Option<ChildStdin>,
    /// ffmpeg's messages, read on a thread (so a chatty ffmpeg cannot block
    /// on a full pipe while the frames wait on its input).
    messages: Option<std::thread::JoinHandle<String>>,
    tmp: PathBuf,
    target: PathBuf,
    size: (u32, u32),
    frames: u64,
}

impl VideoWriter {
    /// Starts ffmpeg writing a `width` x `height` video at `fps` frames a
    /// second for `target`. On Linux ffmpeg is killed when the thread that
    /// started it ends (PR_SET_PDEATHSIG): start it from the thread that
    /// outlives the video (the command line's main thread).
    pub fn start(
        target: &Path,
        container: Container,
        (width, height): (u32, u32),
        fps: f64,
    ) -> Result<Self> {
        // A dead run's temporaries of this video go first.
        super::remove_stale_temps(target);
        let tmp = super::temp_path(target);
        // ffmpeg reads `word:rest` as a URL (a folder named `10:30` gave
        // "Protocol not found"; `file:x/v.mp4` wrote elsewhere): the
        // temporary goes to it as `file:` and an absolute path, literally.
        let literal = literal_url(&tmp)?;
        let size = format!("{width}x{height}");
        let rate = format!("{fps}");
        let mut cmd = Command::new("ffmpeg");
        cmd.args(["-hide_banner", "-loglevel", "error", "-nostdin", "-y"])
            .args(["-f", "rawvideo", "-pix_fmt", "rgba", "-s", &size])
            .args(["-framerate", &rate, "-i", "pipe:0"])
            .args(["-vf", "scale=out_color_matrix=bt709:out_range=tv"])
            .args(["-colorspace", "bt709", "-color_primaries", "bt709"])
            .args(["-color_trc", "bt709"])
            .args(["-c:v", container.encoder().0])
            .args(container.args())
            .arg(&literal)
            .stdin(Stdio::piped())
            .stdout(Stdio::null())
            .stderr(Stdio::piped());
        // Its own process group: Ctrl-C in the terminal reaches the
        // renderer, which finishes or abandons the video in order, and not
        // ffmpeg behind its back.
        #[cfg(unix)]
        std::os::unix::process::CommandExt::process_group(&mut cmd, 0);
        // And it dies with the renderer: killed (SIGKILL), the renderer
        // once left ffmpeg finishing a hidden temporary on its own.
        #[cfg(target_os = "linux")]
        {
            let parent = std::process::id();
            // SAFETY: between fork and exec only async-signal-safe calls:
            // prctl, getppid and _exit.
            unsafe {
                std::os::unix::process::CommandExt::pre_exec(&mut cmd, move || {
                    if libc::prctl(libc::PR_SET_PDEATHSIG, libc::SIGKILL) != 0 {
                        return Err(std::io::Error::last_os_error());
                    }
                    // (The renderer already gone before the call above.)
                    if u32::try_from(libc::getppid()) != Ok(parent) {
                        libc::_exit(1);
                    }
                    Ok(())
                });
            }
        }
        let mut child = cmd.spawn().map_err(|e| Error::Io {
            path: PathBuf::from("ffmpeg"),
            source: e,
        })?;
        super::set_current_temp(Some(&tmp));
        let stdin = child.stdin.take();
        let messages = child.stderr.take().map(|mut err| {
            std::thread::spawn(move || {
                let mut s = String::new();
                let _ = err.read_to_string(&mut s);
                s
            })
        });
        Ok(VideoWriter {
            child: Some(child),
            stdin,
            messages,
            tmp,
            target: target.to_path_buf(),
            size: (width, height),
            frames: 0,
        })
    }

    /// Appends one frame (8-bit RGBA of the video's size).
    pub fn push(&mut self, frame: &Frame) -> Result<()> {
        let Pixels::Rgba8(bytes) = &frame.pixels else {
            return Err(Error::Other(
                "video frames must be 8-bit (the renderer produced floats)".into(),
            ));
        };
        if (frame.width, frame.height) != self.size {
            return Err(Error::Other(format!(
                "a {}x{} frame for a {}x{} video",
                frame.width, frame.height, self.size.0, self.size.1
            )));
        }
        let stdin = self
            .stdin
            .as_mut()
            .ok_or_else(|| Error::Other("the video is already closed".into()))?;
        if let Err(e) = stdin.write_all(bytes) {
            let why = self.stop_and_collect();
            return Err(Error::Other(format!(
                "ffmpeg stopped taking frames after {} ({e}){why}",
                self.frames
            )));
        }
        self.frames += 1;
        Ok(())
    }

    /// Ends the input, waits for ffmpeg and renames the video into place;
    /// returns the number of frames written.
    pub fn finish(mut self) -> Result<u64> {
        drop(self.stdin.take());
        let status = match self.child.take() {
            Some(mut c) => c.wait().map_err(|e| Error::Io {
                path: PathBuf::from("ffmpeg"),
                source: e,
            })?,
            None => return Err(Error::Other("ffmpeg is gone".into())),
        };
        let messages = self
            .messages
            .take()
            .and_then(|h| h.join().ok())
            .unwrap_or_default();
        if !status.success() {
            return Err(Error::Other(format!(
                "ffmpeg failed ({status}) encoding {}: {}",
                self.target.display(),
                last_line(&messages)
            )));
        }
        let io = |source| Error::Io {
            path: self.target.clone(),
            source,
        };
        std::fs::File::open(&self.tmp)
            .and_then(|f| f.sync_all())
            .map_err(io)?;
        // ffmpeg can exit 0 over a file it could not finish (a full disk:
        // an MP4 without its index, a WebM cut short): the video is read
        // back, and only one holding every frame takes the final name.
        let readable = readable_frames(&self.tmp)?;
        if readable != Some(self.frames) {
            let _ = std::fs::remove_file(&self.tmp);
            super::set_current_temp(None);
            let held = readable.map_or_else(
                || format!("unreadable after {} frames", self.frames),
                |n| format!("{n} of {} frames readable", self.frames),
            );
            return Err(Error::Other(format!(
                "ffmpeg left an incomplete video ({held}; is the disk full?): {} not written",
                self.target.display()
            )));
        }
        std::fs::rename(&self.tmp, &self.target).map_err(io)?;
        super::set_current_temp(None);
        Ok(self.frames)
    }

    /// Kills ffmpeg (if running) and returns its last message, as ": ..."
    /// (empty if none).
    fn stop_and_collect(&mut self) -> String {
        drop(self.stdin.take());
        if let Some(mut c) = self.child.take() {
            let _ = c.kill();
            let _ = c.wait();
        }
        let messages = self
            .messages
            .take()
            .and_then(|h| h.join().ok())
            .unwrap_or_default();
        let line = last_line(&messages);
        if line.is_empty() {
            String::new()
        } else {
            format!(": {line}")
        }
    }
}

impl Drop for VideoWriter {
    fn drop(&mut self) {
        if self.child.is_some() || self.tmp.exists() {
            let _ = self.stop_and_collect();
            let _ = std::fs::remove_file(&self.tmp);
            super::set_current_temp(None);
        }
    }
}

/// `path` as ffmpeg must be given it: `file:` and the absolute path,
/// literally (a bare `word:rest` is read as a URL: a folder named `10:30`
/// gave "Protocol not found"; `file:x/v.mp4` wrote elsewhere).
fn literal_url(path: &Path) -> Result<std::ffi::OsString> {
    let abs = std::path::absolute(path).map_err(|source| Error::Io {
        path: path.to_path_buf(),
        source,
    })?;
    let mut s = std::ffi::OsString::from("file:");
    s.push(abs.as_os_str());
    Ok(s)
}

/// How many video frames ffprobe reads back from `path` (its packets: no
/// decoding); None where it cannot read the file at all.
fn readable_frames(path: &Path) -> Result<Option<u64>> {
    let out = Command::new("ffprobe")
        .args(["-v", "error", "-select_streams", "v:0", "-count_packets"])
        .args(["-show_entries", "stream=nb_read_packets", "-of", "csv=p=0"])
        .arg(literal_url(path)?)
        .stdin(Stdio::null())
        .output()
        .map_err(|source| Error::Io {
            path: PathBuf::from("ffprobe"),
            source,
        })?;
    let text = String::from_utf8_lossy(&out.stdout);
    Ok(out
        .status
        .success()
        .then(|| text.trim().parse().ok())
        .flatten())
}

fn last_line(s: &str) -> String {
    s.lines()
        .rev()
        .find(|l| !l.trim().is_empty())
        .unwrap_or("")
        .trim()
        .to_string()
}
