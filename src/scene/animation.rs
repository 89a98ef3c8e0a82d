//! `[animation]`: how a scene changes with time, for sequences. Frame `i` is
//! at time `i / fps` seconds, whatever range a job renders, so any split of a
//! sequence into ranges renders the same frames.

use glam::DVec3;
use serde::Deserialize;

use super::Camera;

/// A camera keyframe.
#[derive(Clone, Debug, PartialEq, Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields)]
pub struct Keyframe {
    /// Seconds.
    pub time: f64,
    pub position: [f64; 3],
    #[serde(default)]
    pub look_at: [f64; 3],
    #[serde(default)]
    pub vfov_deg: Option<f64>,
}

/// How the camera moves.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Deserialize, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum CameraPath {
    /// The `[camera]` as given, every frame.
    Static,
    /// A circle around the first hole (or `look_at`), in a plane tilted by
    /// `inclination_deg` from the disk's plane.
    Orbit,
    /// Straight-line interpolation between `[[animation.keyframe]]`s.
    Keyframes,
}

/// The `[animation]` section.
#[derive(Clone, Debug, PartialEq, Deserialize, serde::Serialize)]
#[serde(deny_unknown_fields, default)]
pub struct Animation {
    pub fps: f64,
    pub camera: CameraPath,
    /// Orbit radius (0: the camera's distance from `look_at`).
    pub orbit_radius: f64,
    /// Degrees per second, counter-clockwise seen from +y.
    pub orbit_speed_deg: f64,
    /// Height of the orbit above the disk plane, in degrees.
    pub inclination_deg: f64,
    #[serde(rename = "keyframe")]
    pub keyframes: Vec<Keyframe>,
}

impl Default for Animation {
    fn default() -> Self {
        Animation {
            fps: 30.0,
            camera: CameraPath::Static,
            orbit_radius: 0.0,
            orbit_speed_deg: 10.0,
            inclination_deg: 3.0,
            keyframes: Vec::new(),
        }
    }
}

impl Animation {
    /// Time of frame `index`, seconds.
    pub fn time_of(&self, index: u64) -> f64 {
        index as f64 / self.fps
    }

    /// The camera at time `t`.
    pub fn camera_at(&self, base: &Camera, t: f64) -> Camera {
        match self.camera {
            CameraPath::Static => base.clone(),
            CameraPath::Orbit => {
                let target = DVec3::from(base.look_at);
                let start = DVec3::from(base.position) - target;
                let radius = if self.orbit_radius > 0.0 {
                    self.orbit_radius
                } else {
                    start.length()
                };
                // Start where the camera is (its azimuth), then turn.
                let az0 = start.x.atan2(-start.z);
                let az = az0 + (self.orbit_speed_deg * t).to_radians();
                let inc = self.inclination_deg.to_radians();
                let offset = DVec3::new(
                    radius * inc.cos() * az.sin(),
                    radius * inc.sin(),
                    -radius * inc.cos() * az.cos(),
                );
                Camera {
                    position: (target + offset).to_array(),
                    ..base.clone()
                }
            }
            CameraPath::Keyframes => {
                let k = &self.keyframes;
                if k.is_empty() {
                    return base.clone();
                }
                let i = k.iter().rposition(|f| f.time <= t).unwrap_or(0);
                let a = &k[i];
                let b = k.get(i + 1).unwrap_or(a);
                // Before the first key and after the last, hold still.
                let s = if b.time > a.time && t > a.time {
                    ((t - a.time) / (b.time - a.time)).clamp(0.0, 1.0)
                } else {
                    0.0
                };
                // Smoothstep easing so the camera does not jerk at keys.
                let s = s * s * (3.0 - 2.0 * s);
                let lerp3 =
                    |p: [f64; 3], q: [f64; 3]| (DVec3::from(p).lerp(DVec3::from(q), s)).to_array();
                let fov = |f: &Keyframe| f.vfov_deg.unwrap_or(base.vfov_deg);
                Camera {
                    position: lerp3(a.position, b.position),
                    look_at: lerp3(a.look_at, b.look_at),
                    up: base.up,
                    vfov_deg: fov(a) + (fov(b) - fov(a)) * s,
                    observer: base.observer,
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn orbit_starts_at_the_camera_and_keeps_its_distance() {
        let base = Camera::default();
        let anim = Animation {
            camera: CameraPath::Orbit,
            inclination_deg: (0.8f64 / 15.0).atan().to_degrees(),
            ..Animation::default()
        };
        let c0 = anim.camera_at(&base, 0.0);
        for (a, b) in c0.position.iter().zip(base.position) {
            assert!(
                (a - b).abs() < 1e-9,
                "{:?} vs {:?}",
                c0.position,
                base.position
            );
        }
        let r0 = DVec3::from(base.position).length();
        for t in [1.0, 4.5, 36.0] {
            let c = anim.camera_at(&base, t);
            assert!((DVec3::from(c.position).length() - r0).abs() < 1e-9);
        }
        // A quarter turn after 9 s at 10 deg/s: from -z to +x (counter-clockwise from +y).
        let q = anim.camera_at(&base, 9.0);
        assert!(
            q.position[0] > 14.0 && q.position[2].abs() < 1e-6,
            "{:?}",
            q.position
        );
    }

    #[test]
    fn keyframes_interpolate_and_hold_at_the_ends() {
        let base = Camera::default();
        let k = |t: f64, x: f64| Keyframe {
            time: t,
            position: [x, 0.0, -10.0],
            look_at: [0.0; 3],
            vfov_deg: None,
        };
        let anim = Animation {
            camera: CameraPath::Keyframes,
            keyframes: vec![k(0.0, 0.0), k(2.0, 4.0)],
            ..Animation::default()
        };
        assert_eq!(anim.camera_at(&base, 0.0).position[0], 0.0);
        assert!((anim.camera_at(&base, 1.0).position[0] - 2.0).abs() < 1e-12);
        assert_eq!(anim.camera_at(&base, 5.0).position[0], 4.0);
    }
}
