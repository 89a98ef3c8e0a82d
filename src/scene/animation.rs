//! `[animation]`: how a scene changes with time, for sequences. Frame `i` is
//! at time `i / fps` seconds, whatever range a job renders, so any split of a
//! sequence into ranges renders the same frames.

use glam::DVec3;
use serde::Deserialize;

use super::Camera;
use crate::spacetime::Spacetime;

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

impl Keyframe {
    /// The camera this keyframe sets (`up` and the observer from `base`).
    pub fn camera(&self, base: &Camera) -> Camera {
        Camera {
            position: self.position,
            look_at: self.look_at,
            vfov_deg: self.vfov_deg.unwrap_or(base.vfov_deg),
            ..*base
        }
    }
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
    /// Falling radially from rest at infinity into the first hole, along the
    /// line from its centre through the camera, by the free-fall law
    /// r^(3/2) = r0^(3/2) - (3/2) √rs τ (τ: the faller's proper time),
    /// through the horizon of a non-rotating hole to `fall_end_radius`;
    /// `fall_seconds` of animation take it there, the film's seconds in
    /// proportion to the faller's proper time. Pair it with
    /// `observer = "falling"`.
    Fall,
}

impl CameraPath {
    /// The name a scene file uses.
    pub fn name(self) -> &'static str {
        match self {
            CameraPath::Static => "static",
            CameraPath::Orbit => "orbit",
            CameraPath::Keyframes => "keyframes",
            CameraPath::Fall => "fall",
        }
    }
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
    /// `camera = "fall"`: seconds of animation from the start to the end
    /// radius (film time in proportion to the faller's proper time).
    pub fall_seconds: f64,
    /// `camera = "fall"`: where the fall ends, its distance from the first
    /// hole's centre in rs (None: the default of [`crate::spacetime::Fall::end`]:
    /// for a falling camera 0.05 rs for a non-rotating hole, just outside
    /// the inner horizon for a spinning one; otherwise just outside the
    /// horizon).
    pub fall_end_radius: Option<f64>,
    /// Show the disk as it was when its light left it (one hole): each
    /// point's time is the frame's time less the light's travel time along
    /// its path (one second of animation is one rs/c x `speed`).
    pub light_travel_time: bool,
    /// The fraction of a frame's interval the shutter is open, in [0, 1]:
    /// with `--spp N` the N samples spread over it, so the disk's turning
    /// and the camera's motion blur as on film (0: every sample at the
    /// frame's instant).
    pub shutter: f64,
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
            fall_seconds: 10.0,
            fall_end_radius: None,
            light_travel_time: false,
            shutter: 0.0,
        }
    }
}

impl Animation {
    /// Time of frame `index`, seconds.
    pub fn time_of(&self, index: u64) -> f64 {
        index as f64 / self.fps
    }

    /// The fraction of a fall's proper time gone `t` seconds into the
    /// animation: the film's seconds in proportion to the faller's clock.
    pub fn fall_fraction(&self, t: f64) -> f64 {
        (t / self.fall_seconds).clamp(0.0, 1.0)
    }

    /// The camera at time `t` in `spacetime` (a fall heads for its first
    /// hole, [`Spacetime::fall_from`]).
    pub fn camera_at(&self, base: &Camera, t: f64, spacetime: &Spacetime) -> Camera {
        match self.camera {
            CameraPath::Static => *base,
            CameraPath::Fall => {
                let position = DVec3::from(base.position);
                let fall = spacetime.fall_from(position, base.observer, DVec3::ZERO);
                let end = fall.end(self.fall_end_radius);
                let r = fall.distance_after(self.fall_fraction(t), end);
                Camera {
                    position: fall.point(r).to_array(),
                    ..*base
                }
            }
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
                    ..*base
                }
            }
            CameraPath::Keyframes => {
                let k = &self.keyframes;
                if k.is_empty() {
                    return *base;
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
                    vfov_deg: fov(a) + (fov(b) - fov(a)) * s,
                    ..*base
                }
            }
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    use crate::physics::Hole;
    use crate::physics::observer::ObserverKind;
    use crate::spacetime::Body;

    /// A hole of rs 1 at the origin spinning at `spin`.
    fn hole(spin: f64) -> Spacetime {
        let hole = Hole {
            position: DVec3::ZERO,
            rs: 1.0,
        };
        Spacetime::new(&[Body { hole, spin }], true, DVec3::Y)
    }

    /// The camera of a fall follows the free-fall law through the horizon
    /// (the law itself: spacetime/fall.rs), on its line, to its end.
    #[test]
    fn fall_follows_the_free_fall_law_through_the_horizon() {
        let anim = Animation {
            camera: CameraPath::Fall,
            fall_seconds: 10.0,
            ..Animation::default()
        };
        let base = Camera {
            position: [0.0, 0.0, -20.0],
            observer: ObserverKind::Falling,
            ..Camera::default()
        };
        let hole0 = hole(0.0);
        let r = |t: f64| DVec3::from(anim.camera_at(&base, t, &hole0).position).length();
        assert!((r(0.0) - 20.0).abs() < 1e-12);
        assert!((r(10.0) - 0.05).abs() < 1e-12 && (r(99.0) - 0.05).abs() < 1e-12);
        // Film time goes with proper time: the horizon (2/3 rs from the
        // centre in proper time) is crossed where the closed form says,
        // (20^1.5 - 1) / (20^1.5 - 0.05^1.5) of the way.
        let frac = (20f64.powf(1.5) - 1.0) / (20f64.powf(1.5) - 0.05f64.powf(1.5));
        assert!((r(10.0 * frac) - 1.0).abs() < 1e-9, "{}", r(10.0 * frac));
        // Toward a spinning hole, a fall that may not go in stops just
        // outside its horizon: at a* = 0.9, r+ = (1 + sqrt(1 - 0.81)) / 2
        // rs, a = 0.45 rs.
        let spinning = hole(0.9);
        let static_base = Camera {
            observer: ObserverKind::Static,
            ..base
        };
        let p = anim.camera_at(&static_base, 99.0, &spinning).position;
        let r_plus: f64 = 0.5 * (1.0 + 0.19f64.sqrt());
        let end = 1.05 * (r_plus * r_plus + 0.45 * 0.45).sqrt();
        assert!((DVec3::from(p).length() - end).abs() < 1e-12);
        // A falling camera goes in, to 1.01 x (1 + 1e-3) r- (Boyer-
        // Lindquist, r- = 0.81 / (2 r+ / rs) rs): on the equator at
        // rho = sqrt(r^2 + a^2), on the axis at rho = r.
        let r_end = 1.01 * 1.001 * 0.5 * 0.81 / (2.0 * r_plus);
        for (start, rho) in [
            ([0.0, 0.0, -20.0], (r_end * r_end + 0.45 * 0.45).sqrt()),
            ([0.0, 20.0, 0.0], r_end),
        ] {
            let base = Camera {
                position: start,
                ..base
            };
            let p = DVec3::from(anim.camera_at(&base, 99.0, &spinning).position);
            assert!((p.length() - rho).abs() < 1e-12, "{start:?}: {p}");
            let fall = spinning.fall_from(p, ObserverKind::Falling, DVec3::Y);
            assert!((fall.radius_at(p.length()) - r_end).abs() < 1e-12);
        }
        // dr/dτ = -√(rs/r): the speed grows as it falls.
        let (a, b, c) = (r(2.0), r(5.0), r(8.0));
        assert!(a > b && b > c && (a - b) < (b - c), "{a} {b} {c}");
        // r^(3/2) falls linearly in time.
        let lin = |t: f64| r(t).powf(1.5);
        assert!(((lin(2.0) - lin(4.0)) - (lin(6.0) - lin(8.0))).abs() < 1e-9);
        // It stays on the line from the hole through the start.
        let p = anim.camera_at(&base, 5.0, &hole0).position;
        assert!(p[0] == 0.0 && p[1] == 0.0 && p[2] < 0.0);
    }

    #[test]
    fn orbit_starts_at_the_camera_and_keeps_its_distance() {
        let base = Camera::default();
        let anim = Animation {
            camera: CameraPath::Orbit,
            inclination_deg: (0.8f64 / 15.0).atan().to_degrees(),
            ..Animation::default()
        };
        let c0 = anim.camera_at(&base, 0.0, &hole(0.0));
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
            let c = anim.camera_at(&base, t, &hole(0.0));
            assert!((DVec3::from(c.position).length() - r0).abs() < 1e-9);
        }
        // A quarter turn after 9 s at 10 deg/s: from -z to +x (counter-clockwise from +y).
        let q = anim.camera_at(&base, 9.0, &hole(0.0));
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
        assert_eq!(anim.camera_at(&base, 0.0, &hole(0.0)).position[0], 0.0);
        assert!((anim.camera_at(&base, 1.0, &hole(0.0)).position[0] - 2.0).abs() < 1e-12);
        assert_eq!(anim.camera_at(&base, 5.0, &hole(0.0)).position[0], 4.0);
    }
}
