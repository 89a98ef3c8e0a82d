//! The frames of a sequence: every frame's camera is checked by the rules of
//! `[camera]` before the first frame renders, so an animation that moves the
//! camera into a horizon (or onto its `look_at`) is refused with the first
//! bad frame named, instead of rendering black or NaN frames.

use std::ops::Range;

use super::locate::{Seg::Key, display_path};
use super::{Camera, CameraPath, Scene};
use crate::{Error, Result};

/// The most frames one `--frames` range may hold: ten million (3.9 days at
/// 30 frames a second). A longer range is refused with this figure named;
/// split it into several runs.
pub const MAX_SEQUENCE_FRAMES: u64 = 10_000_000;

impl Scene {
    /// The camera at frame `index` of the animation.
    pub fn camera_at_frame(&self, index: u64) -> Camera {
        self.camera_at_time(self.animation.time_of(index))
    }

    /// The camera at animation time `t`, seconds.
    pub fn camera_at_time(&self, t: f64) -> Camera {
        self.animation.camera_at(&self.camera, t, &self.spacetime())
    }

    /// Checks the camera of every frame in `range` and, with the shutter
    /// open, of every instant its `spp` samples take ([`Scene::at_sample`]:
    /// once a static camera's later samples stood inside the ergoregion and
    /// silently became another observer); those after the camera stops
    /// moving are the same and checked once. The first bad frame is named
    /// with the instant's time. Refuses a range longer than
    /// [`MAX_SEQUENCE_FRAMES`].
    pub fn check_frames(&self, range: &Range<u64>, spp: u32) -> Result<()> {
        let count = range.end.saturating_sub(range.start);
        if count > MAX_SEQUENCE_FRAMES {
            return Err(Error::Usage(format!(
                "--frames {}..{} asks for {count} frames; one run renders at most \
                 {MAX_SEQUENCE_FRAMES} (split the range into several runs)",
                range.start, range.end
            )));
        }
        let a = &self.animation;
        // The time after which the camera no longer moves, if it stops.
        let still_after = match a.camera {
            CameraPath::Static => return Ok(()),
            CameraPath::Fall => Some(a.fall_seconds),
            CameraPath::Keyframes => a.keyframes.last().map(|k| k.time),
            CameraPath::Orbit => None,
        };
        let end = still_after.map_or(range.end, |t| {
            // `as` saturates: a time past u64's frames keeps the whole range.
            let last = ((t * a.fps).ceil().max(0.0) as u64).saturating_add(1);
            range.end.min(last.max(range.start + 1))
        });
        let origin = self
            .source
            .as_ref()
            .map_or_else(|| "the scene".to_string(), |p| p.display().to_string());
        let spacetime = self.spacetime();
        let samples = if a.shutter > 0.0 { spp.max(1) } else { 1 };
        for i in range.start..end {
            for s in 0..samples {
                let at = self.at_sample(i, s, samples);
                if let Err((path, value, why)) =
                    self.check_camera_in(&spacetime, &at.camera, &[Key("camera")])
                {
                    let which = if samples > 1 {
                        format!(": sample {s} of {samples}, shutter {}", a.shutter)
                    } else {
                        String::new()
                    };
                    return Err(Error::Scene(format!(
                        "{origin}: frame {i} (t = {:.4} s{which}) of the animation (camera = \"{}\"): {} = {value}: {why}",
                        at.time,
                        a.camera.name(),
                        display_path(&path)
                    )));
                }
            }
        }
        Ok(())
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene(toml: &str) -> Scene {
        Scene::from_toml(toml, "t.toml").expect("scene parses")
    }

    #[test]
    fn a_fall_through_a_second_hole_names_the_first_bad_frame() {
        // Falling from -z toward the first hole, through a second one on the way.
        let s = scene(
            "[camera]\nposition = [0.0, 0.0, -20.0]\nlook_at = [1.0, 0.0, 0.0]\n\
             [[black_hole]]\nrs = 1.0\n[[black_hole]]\nposition = [0.0, 0.0, -10.0]\nrs = 1.0\n\
             [animation]\ncamera = \"fall\"\nfall_seconds = 10.0\nfps = 10.0\n",
        );
        let e = s.check_frames(&(0..100), 1).unwrap_err().to_string();
        assert!(e.contains("frame ") && e.contains("black_hole[1]"), "{e}");
        // Frames before the hole are fine.
        assert!(s.check_frames(&(0..10), 1).is_ok());
    }

    #[test]
    fn absurd_ranges_are_refused_and_long_still_ones_are_cheap() {
        let s = scene("[animation]\ncamera = \"fall\"\n");
        let e = s.check_frames(&(0..u64::MAX), 1).unwrap_err().to_string();
        assert!(e.contains("at most 10000000"), "{e}");
        // A fall stops moving at fall_seconds: only those frames are checked.
        let t = std::time::Instant::now();
        s.check_frames(&(0..MAX_SEQUENCE_FRAMES), 1)
            .expect("the default fall is fine");
        assert!(t.elapsed().as_secs_f64() < 5.0);
    }
}
