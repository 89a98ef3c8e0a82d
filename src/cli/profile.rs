//! `blackhole profile`: render N frames and summarise GPU time per pass.

use std::path::PathBuf;
use std::process::ExitCode;

use super::{View, finish, load_scene};
use crate::frame::{FrameTimings, OutputKind};
use crate::scene::Scene;
use crate::{Error, Renderer, RendererOptions, Result, output};

/// What `blackhole profile` was asked for.
pub struct Options {
    pub frames: u32,
    pub warmup: u32,
    pub json: Option<PathBuf>,
    pub trace: Option<PathBuf>,
}

/// `blackhole profile`: times the frames and prints (and optionally writes) the report.
pub fn run_command(view: View, opts: Options) -> Result<ExitCode> {
    let scene = load_scene(view.scene.as_deref())?;
    scene.check_image_size(view.width, view.height)?;
    let outs: Vec<super::outputs::Output<'_>> = [("--json", &opts.json), ("--trace", &opts.trace)]
        .into_iter()
        .filter_map(|(flag, path)| {
            path.as_deref().map(|path| super::outputs::Output {
                flag,
                path,
                extensions: &["json"],
                what: "JSON",
            })
        })
        .collect();
    super::outputs::check_all(&outs, &scene.input_files(), None)?;
    let mut renderer = Renderer::new(RendererOptions::default())?;
    let (report, frames) = run_frames(
        &mut renderer,
        &scene,
        view.width,
        view.height,
        opts.warmup,
        opts.frames,
    )?;
    print!("{}", report.table());
    if let Some(path) = opts.json {
        write_text(&path, &report.to_json())?;
    }
    if let Some(path) = opts.trace {
        write_text(&path, &trace_json(&report.device, &frames))?;
    }
    finish(renderer)
}

pub(super) fn write_text(path: &std::path::Path, text: &str) -> Result<()> {
    output::write_atomically(path, |tmp| {
        std::fs::write(tmp, text).map_err(|source| Error::Io {
            path: path.to_owned(),
            source,
        })
    })
}

/// Median and 95th percentile of one series, in milliseconds.
#[derive(Clone, Debug, PartialEq, serde::Serialize)]
pub struct Stats {
    pub median_ms: f64,
    pub p95_ms: f64,
}

impl Stats {
    /// Nearest-rank median and p95 of `samples` (which must not be empty).
    pub fn of(samples: &[f64]) -> Self {
        let mut s = samples.to_vec();
        s.sort_by(f64::total_cmp);
        let rank = |q: f64| {
            let i = ((q * s.len() as f64).ceil() as usize).clamp(1, s.len());
            s[i - 1]
        };
        Stats {
            median_ms: rank(0.5),
            p95_ms: rank(0.95),
        }
    }
}

/// One pass's figures.
#[derive(Clone, Debug, serde::Serialize)]
pub struct PassReport {
    pub name: String,
    #[serde(flatten)]
    pub stats: Stats,
}

/// The whole report (the binding `--json` shape documented in docs/commands.md,
/// with more fields).
#[derive(Clone, Debug, serde::Serialize)]
pub struct Report {
    pub device: String,
    pub width: u32,
    pub height: u32,
    pub frames: u32,
    pub warmup: u32,
    /// Whether the GPU times come from timestamps; without them `frame` is
    /// the wall time from submit to fence and `passes` is empty.
    pub timestamps: bool,
    pub frame: Stats,
    pub passes: Vec<PassReport>,
    /// CPU milliseconds per phase of a frame.
    pub cpu: Vec<PassReport>,
}

/// The most frames `profile` times, and warms up with.
pub const MAX_FRAMES: u32 = 100_000;
pub const MAX_WARMUP: u32 = 10_000;

/// Renders `warmup` untimed frames (pipeline builds, allocation) and then
/// `frames` timed ones; the report and each timed frame's timings.
pub fn run_frames(
    r: &mut Renderer,
    scene: &Scene,
    width: u32,
    height: u32,
    warmup: u32,
    frames: u32,
) -> Result<(Report, Vec<FrameTimings>)> {
    for _ in 0..warmup {
        r.render(scene, width, height, OutputKind::Ldr)?;
    }
    if !(1..=MAX_FRAMES).contains(&frames) || warmup > MAX_WARMUP {
        return Err(Error::Usage(format!(
            "profile frames = {frames}, warmup = {warmup}: frames must be 1 to {MAX_FRAMES}, warmup 0 to {MAX_WARMUP}"
        )));
    }
    let mut all: Vec<FrameTimings> = Vec::with_capacity(frames as usize);
    for _ in 0..frames {
        all.push(r.render(scene, width, height, OutputKind::Ldr)?.timings);
    }
    let Some(first) = all.first() else {
        return Err(Error::Usage("--frames must be at least 1".into()));
    };
    let timestamps = !first.passes.is_empty();
    if !timestamps {
        log::warn!(
            "{} reports no GPU timestamps on its compute queue: the frame time is the wall time from submit to fence, and there are no per-pass times",
            r.device_name()
        );
    }
    let names: Vec<String> = first.passes.iter().map(|p| p.name.clone()).collect();
    let passes = names
        .iter()
        .enumerate()
        .map(|(i, name)| PassReport {
            name: name.clone(),
            stats: Stats::of(
                &all.iter()
                    .map(|t| t.passes.get(i).map_or(0.0, |p| p.ms))
                    .collect::<Vec<_>>(),
            ),
        })
        .collect();
    let cpu = first
        .cpu
        .named()
        .iter()
        .enumerate()
        .map(|(i, (name, _))| PassReport {
            name: (*name).to_owned(),
            stats: Stats::of(&all.iter().map(|t| t.cpu.named()[i].1).collect::<Vec<_>>()),
        })
        .collect();
    let frame = if timestamps {
        Stats::of(&all.iter().map(|t| t.frame_ms).collect::<Vec<_>>())
    } else {
        Stats::of(&all.iter().map(|t| t.wall_ms).collect::<Vec<_>>())
    };
    let report = Report {
        device: r.device_name().to_owned(),
        width,
        height,
        frames,
        warmup,
        timestamps,
        frame,
        passes,
        cpu,
    };
    Ok((report, all))
}

/// Chrome trace-event JSON (the format Perfetto and chrome://tracing open):
/// one track of CPU phases, laid end to end per frame as they ran, and one
/// of GPU passes from the timestamps, each frame's first pass placed when its
/// submit returned (the two clocks are not calibrated against each other).
pub fn trace_json(device: &str, frames: &[FrameTimings]) -> String {
    let mut events = vec![
        serde_json::json!({"name": "process_name", "ph": "M", "pid": 1, "args": {"name": format!("blackhole profile ({device})")}}),
        serde_json::json!({"name": "thread_name", "ph": "M", "pid": 1, "tid": 1, "args": {"name": "CPU phases"}}),
        serde_json::json!({"name": "thread_name", "ph": "M", "pid": 1, "tid": 2, "args": {"name": "GPU passes"}}),
    ];
    let mut t_us = 0.0f64;
    for (i, f) in frames.iter().enumerate() {
        let frame_start = t_us;
        let mut gpu_start = t_us;
        for (name, ms) in f.cpu.named() {
            events.push(serde_json::json!({
                "name": name, "cat": "cpu", "ph": "X", "pid": 1, "tid": 1,
                "ts": t_us, "dur": ms * 1e3, "args": {"frame": i}
            }));
            t_us += ms * 1e3;
            if name == "submit" {
                gpu_start = t_us;
            }
        }
        for p in &f.passes {
            events.push(serde_json::json!({
                "name": p.name, "cat": "gpu", "ph": "X", "pid": 1, "tid": 2,
                "ts": gpu_start + p.start_ms * 1e3, "dur": p.ms * 1e3, "args": {"frame": i}
            }));
        }
        // Keep frames apart even when a phase was too short to measure.
        t_us = t_us.max(frame_start + f.frame_ms * 1e3) + 1.0;
    }
    serde_json::to_string(&serde_json::json!({
        "traceEvents": events,
        "displayTimeUnit": "ms",
    }))
    .unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
}

impl Report {
    /// A plain-text table.
    pub fn table(&self) -> String {
        let mut s = format!(
            "{} at {}x{}, {} frames\n{:<16} {:>10} {:>10} {:>7}\n",
            self.device,
            self.width,
            self.height,
            self.frames,
            "pass",
            "median ms",
            "p95 ms",
            "share"
        );
        for p in &self.passes {
            let share = if self.frame.median_ms > 0.0 {
                100.0 * p.stats.median_ms / self.frame.median_ms
            } else {
                0.0
            };
            s += &format!(
                "{:<16} {:>10.3} {:>10.3} {:>6.1}%\n",
                p.name, p.stats.median_ms, p.stats.p95_ms, share
            );
        }
        s += &format!(
            "{:<16} {:>10.3} {:>10.3} {:>6.1}%{}\n",
            "frame",
            self.frame.median_ms,
            self.frame.p95_ms,
            100.0,
            if self.timestamps {
                ""
            } else {
                "  (wall time: no GPU timestamps)"
            }
        );
        s += &format!("{:<16} {:>10} {:>10}\n", "CPU phase", "median ms", "p95 ms");
        for p in &self.cpu {
            s += &format!(
                "{:<16} {:>10.3} {:>10.3}\n",
                p.name, p.stats.median_ms, p.stats.p95_ms
            );
        }
        s
    }

    /// The JSON form.
    pub fn to_json(&self) -> String {
        serde_json::to_string_pretty(self).unwrap_or_else(|e| format!("{{\"error\": \"{e}\"}}"))
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn nearest_rank_percentiles() {
        let s = Stats::of(&[5.0, 1.0, 4.0, 2.0, 3.0]);
        assert_eq!(s.median_ms, 3.0);
        assert_eq!(s.p95_ms, 5.0);
        let twenty: Vec<f64> = (1..=20).map(f64::from).collect();
        let s = Stats::of(&twenty);
        assert_eq!((s.median_ms, s.p95_ms), (10.0, 19.0));
    }
}
