//! `blackhole profile`: render N frames and summarise GPU time per pass.

use std::path::PathBuf;
use std::process::ExitCode;

use super::{View, finish, load_scene};
use crate::frame::{FrameTimings, OutputKind};
use crate::scene::Scene;
use crate::{Error, Renderer, RendererOptions, Result, output};

/// `blackhole profile`: times the frames and prints (and optionally writes) the report.
pub fn run_command(view: View, frames: u32, json: Option<PathBuf>) -> Result<ExitCode> {
    let scene = load_scene(view.scene.as_deref())?;
    let mut renderer = Renderer::new(RendererOptions::default())?;
    let report = run(&mut renderer, &scene, view.width, view.height, frames)?;
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

/// The whole report (the binding `--json` shape documented in the README).
#[derive(Clone, Debug, serde::Serialize)]
pub struct Report {
    pub device: String,
    pub width: u32,
    pub height: u32,
    pub frames: u32,
    pub frame: Stats,
    pub passes: Vec<PassReport>,
}

/// Renders one warm-up frame (shader compilation, allocation) and then
/// `frames` timed frames.
pub fn run(
    r: &mut Renderer,
    scene: &Scene,
    width: u32,
    height: u32,
    frames: u32,
) -> Result<Report> {
    r.render(scene, width, height, OutputKind::Ldr)?;
    let mut all: Vec<FrameTimings> = Vec::with_capacity(frames as usize);
    for _ in 0..frames {
        all.push(r.render(scene, width, height, OutputKind::Ldr)?.timings);
    }
    let Some(first) = all.first() else {
        return Err(Error::Usage("--frames must be at least 1".into()));
    };
    if first.passes.is_empty() {
        return Err(Error::Other(format!(
            "{} reports no GPU timestamps on its compute queue; nothing to profile",
            r.device_name()
        )));
    }
    let names: Vec<String> = first.passes.iter().map(|p| p.name.clone()).collect();
    let passes = names
        .iter()
        .enumerate()
        .map(|(i, name)| PassReport {
            name: name.clone(),
            stats: Stats::of(&all.iter().map(|t| t.passes[i].ms).collect::<Vec<_>>()),
        })
        .collect();
    Ok(Report {
        device: r.device_name().to_owned(),
        width,
        height,
        frames,
        frame: Stats::of(&all.iter().map(|t| t.frame_ms).collect::<Vec<_>>()),
        passes,
    })
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
            "{:<16} {:>10.3} {:>10.3} {:>6.1}%\n",
            "frame", self.frame.median_ms, self.frame.p95_ms, 100.0
        );
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
