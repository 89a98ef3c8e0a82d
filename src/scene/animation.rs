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
    /// hole's centre in rs (None: for a falling camera [`FALL_END_DEFAULT`]
    /// for a non-rotating hole, [`FALL_END_INNER`] times the deepest
    /// Boyer-Lindquist r for a spinning one, just outside its inner horizon;
    /// otherwise [`FALL_END_SPINNING`] times the horizon's distance).
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

/// Where a fall into a non-rotating hole ends by default (rs): the closest
/// a falling camera may come to the singularity.
pub const FALL_END_DEFAULT: f64 = crate::spacetime::FALLING_MIN_R;

/// Where a fall stops outside a hole by default (an observer other than
/// `"falling"`, several holes, gravity off): this factor times the horizon's
/// distance from the centre (sqrt(r+^2 + a^2) for a spinning hole).
pub const FALL_END_SPINNING: f64 = 1.05;

/// Where a falling camera's fall into a spinning hole ends by default: this
/// factor times the deepest Boyer-Lindquist r it may reach
/// (`physics::kerr::falling_floor`: just outside the inner horizon r-, or
/// 0.05 rs for a slowly turning hole), on the line of the fall.
pub const FALL_END_INNER: f64 = 1.01;

/// The hole a fall heads for: its centre, its rs, its spin and axis, and
/// whether the camera may fall through its horizon (a falling observer
/// around one hole with gravity on; any other observer, several holes or
/// gravity off: the fall stops at [`FALL_END_SPINNING`] times the horizon's
/// distance, as it always did).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct FallTarget {
    pub centre: DVec3,
    pub rs: f64,
    pub spin: f64,
    /// The spin axis (the disk's normal), unit.
    pub axis: DVec3,
    pub interior: bool,
}

impl FallTarget {
    /// The distance from the centre (scene units) at which the fall's `line`
    /// (unit, from the centre) reaches Boyer-Lindquist r (rs): r^2 + a^2
    /// sin^2 theta, cos theta = y / r.
    pub fn distance_at(&self, r: f64, line: DVec3) -> f64 {
        let (a, ny) = (0.5 * self.spin, line.dot(self.axis));
        ((r * r + a * a) / (1.0 + a * a * ny * ny / (r * r))).sqrt() * self.rs
    }

    /// The Boyer-Lindquist r (rs) at `distance` (scene units) from the centre
    /// along `line`.
    pub fn radius_at(&self, distance: f64, line: DVec3) -> f64 {
        let (a, ny, rho) = (0.5 * self.spin, line.dot(self.axis), distance / self.rs);
        let w = rho * rho - a * a;
        (0.5 * (w + (w * w + 4.0 * a * a * rho * rho * ny * ny).sqrt())).sqrt()
    }

    /// The falling observers' proper time (scene units, c = 1) from
    /// `near` to `far` (distances from the centre) along `line`: dtau =
    /// Sigma dr / sqrt(2 r (r^2 + a^2)) (M = 1) in Boyer-Lindquist r, Sigma
    /// = r^2 + a^2 cos^2 theta where the line crosses each r, by Simpson's
    /// rule over 256 intervals (at spin 0 it is (2/3) (far^1.5 -
    /// near^1.5) / sqrt(rs), the law [`Animation::fall_radius`] inverts).
    pub fn fall_time(&self, near: f64, far: f64, line: DVec3) -> f64 {
        let (a, ny) = (self.spin, line.dot(self.axis));
        let (r0, r1) = (
            2.0 * self.radius_at(near, line),
            2.0 * self.radius_at(far, line),
        );
        let rate = |r: f64| {
            // cos theta = y / r, y = the line's height (M units).
            let y = 2.0 * self.distance_at(0.5 * r, line) / self.rs * ny;
            (r * r + a * a * (y / r).powi(2)) / (2.0 * r * (r * r + a * a)).sqrt()
        };
        let n = 256;
        let h = (r1 - r0) / f64::from(n);
        let inner: f64 = (1..n)
            .map(|i| f64::from(if i % 2 == 1 { 4 } else { 2 }) * rate(r0 + f64::from(i) * h))
            .sum();
        (rate(r0) + inner + rate(r1)) * h / 3.0 * (0.5 * self.rs)
    }

    /// The deepest Boyer-Lindquist r (rs) a falling camera may reach.
    pub fn floor(&self) -> f64 {
        if self.spin == 0.0 {
            FALL_END_DEFAULT
        } else {
            0.5 * crate::physics::kerr::falling_floor(self.spin.abs())
        }
    }
}

impl Animation {
    /// Where a fall into `target` along `line` (unit, from its centre) ends,
    /// in the scene's units.
    pub fn fall_end(&self, target: &FallTarget, line: DVec3) -> f64 {
        if target.interior && target.spin != 0.0 && self.fall_end_radius.is_none() {
            return target.distance_at(FALL_END_INNER * target.floor(), line);
        }
        let default = if target.interior {
            FALL_END_DEFAULT
        } else if target.spin == 0.0 {
            FALL_END_SPINNING
        } else {
            let (r, a) = (
                crate::spacetime::radii::horizon(1.0, target.spin.abs()),
                0.5 * target.spin,
            );
            FALL_END_SPINNING * (r * r + a * a).sqrt()
        };
        self.fall_end_radius.unwrap_or(default) * target.rs
    }

    /// Time of frame `index`, seconds.
    pub fn time_of(&self, index: u64) -> f64 {
        index as f64 / self.fps
    }

    /// The radius (from `centre`) of a camera that started falling at `r0`
    /// from rest at infinity, `t` seconds into the animation, ending at
    /// `r_end`.
    pub fn fall_radius(&self, r0: f64, rs: f64, r_end: f64, t: f64) -> f64 {
        let r_end = r_end.min(r0);
        // Proper time from r0 to r_end, spread over fall_seconds.
        let tau_total = (2.0 / 3.0) * (r0.powf(1.5) - r_end.powf(1.5)) / rs.sqrt();
        let tau = (t / self.fall_seconds).clamp(0.0, 1.0) * tau_total;
        (r0.powf(1.5) - 1.5 * rs.sqrt() * tau)
            .max(r_end.powf(1.5))
            .powf(2.0 / 3.0)
    }

    /// The distance from `target`'s centre of a camera falling along `line`
    /// from `start`, `t` seconds into the animation, ending at `end`: for a
    /// falling camera of a spinning hole by its proper time
    /// ([`FallTarget::fall_time`], inverted by bisection), otherwise
    /// [`Animation::fall_radius`].
    pub fn fall_distance(
        &self,
        target: &FallTarget,
        line: DVec3,
        start: f64,
        end: f64,
        t: f64,
    ) -> f64 {
        if target.spin == 0.0 || !target.interior {
            return self.fall_radius(start, target.rs, end, t);
        }
        let end = end.min(start);
        let frac = (t / self.fall_seconds).clamp(0.0, 1.0);
        if frac >= 1.0 {
            return end;
        }
        let tau = frac * target.fall_time(end, start, line);
        let (mut lo, mut hi) = (end, start);
        for _ in 0..60 {
            let mid = 0.5 * (lo + hi);
            if target.fall_time(mid, start, line) > tau {
                lo = mid;
            } else {
                hi = mid;
            }
        }
        0.5 * (lo + hi)
    }

    /// The camera at time `t`; `hole` is the first hole, which the fall
    /// heads for.
    pub fn camera_at(&self, base: &Camera, t: f64, hole: &FallTarget) -> Camera {
        match self.camera {
            CameraPath::Static => *base,
            CameraPath::Fall => {
                let centre = hole.centre;
                let rel = DVec3::from(base.position) - centre;
                let line = rel.normalize_or_zero();
                let end = self.fall_end(hole, line);
                let r = self.fall_distance(hole, line, rel.length(), end, t);
                Camera {
                    position: (centre + rel.normalize_or_zero() * r).to_array(),
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

    const HOLE: &FallTarget = &FallTarget {
        centre: DVec3::ZERO,
        rs: 1.0,
        spin: 0.0,
        axis: DVec3::Y,
        interior: true,
    };

    #[test]
    fn fall_follows_the_free_fall_law_through_the_horizon() {
        let anim = Animation {
            camera: CameraPath::Fall,
            fall_seconds: 10.0,
            ..Animation::default()
        };
        let base = Camera {
            position: [0.0, 0.0, -20.0],
            ..Camera::default()
        };
        let r = |t: f64| DVec3::from(anim.camera_at(&base, t, HOLE).position).length();
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
        let spinning = FallTarget {
            spin: 0.9,
            interior: false,
            ..*HOLE
        };
        let p = anim.camera_at(&base, 99.0, &spinning).position;
        let r_plus: f64 = 0.5 * (1.0 + 0.19f64.sqrt());
        let end = 1.05 * (r_plus * r_plus + 0.45 * 0.45).sqrt();
        assert!((DVec3::from(p).length() - end).abs() < 1e-12);
        // A falling camera goes in, to 1.01 x (1 + 1e-3) r- (Boyer-
        // Lindquist, r- = 0.81 / (2 r+ / rs) rs): on the equator at
        // rho = sqrt(r^2 + a^2), on the axis at rho = r.
        let inside = FallTarget { spin: 0.9, ..*HOLE };
        let r_end = 1.01 * 1.001 * 0.5 * 0.81 / (2.0 * r_plus);
        for (start, rho) in [
            ([0.0, 0.0, -20.0], (r_end * r_end + 0.45 * 0.45).sqrt()),
            ([0.0, 20.0, 0.0], r_end),
        ] {
            let base = Camera {
                position: start,
                ..Camera::default()
            };
            let p = DVec3::from(anim.camera_at(&base, 99.0, &inside).position);
            assert!((p.length() - rho).abs() < 1e-12, "{start:?}: {p}");
            assert!((inside.radius_at(p.length(), p.normalize()) - r_end).abs() < 1e-12);
        }
        // dr/dτ = -√(rs/r): the speed grows as it falls.
        let (a, b, c) = (r(2.0), r(5.0), r(8.0));
        assert!(a > b && b > c && (a - b) < (b - c), "{a} {b} {c}");
        // r^(3/2) falls linearly in time.
        let lin = |t: f64| r(t).powf(1.5);
        assert!(((lin(2.0) - lin(4.0)) - (lin(6.0) - lin(8.0))).abs() < 1e-9);
        // It stays on the line from the hole through the start.
        let p = anim.camera_at(&base, 5.0, HOLE).position;
        assert!(p[0] == 0.0 && p[1] == 0.0 && p[2] < 0.0);
    }

    /// Into a spinning hole the film follows the falling observers' proper
    /// time: on the axis (Sigma = r^2 + a^2) dtau = sqrt((r^2 + a^2) / (2
    /// r)) dr, on the equator r^2 / sqrt(2 r (r^2 + a^2)) dr, integrated
    /// here independently (a 4096-step midpoint sum); at a tiny spin it is
    /// the non-rotating law.
    #[test]
    fn a_spinning_fall_follows_its_proper_time() {
        let target = |spin: f64| FallTarget { spin, ..*HOLE };
        let midpoint = |f: &dyn Fn(f64) -> f64, r0: f64, r1: f64| {
            let n = 4096;
            let h = (r1 - r0) / f64::from(n);
            (0..n)
                .map(|i| f(r0 + (f64::from(i) + 0.5) * h))
                .sum::<f64>()
                * h
        };
        let a = 0.9;
        // On the axis the distance is r (rs); from 4 rs to 0.3 rs, M = 1/2.
        let axis = target(a).fall_time(0.3, 4.0, DVec3::Y);
        let want = 0.5 * midpoint(&|r| ((r * r + a * a) / (2.0 * r)).sqrt(), 0.6, 8.0);
        assert!((axis - want).abs() < 1e-8 * want, "{axis} vs {want}");
        // On the equator the distance is sqrt(r^2 + a^2) (rs, a = 0.45 rs).
        let (d0, d1) = (
            (0.3f64.powi(2) + 0.45f64.powi(2)).sqrt(),
            (16.0f64 + 0.2025).sqrt(),
        );
        let eq = target(a).fall_time(d0, d1, DVec3::Z);
        let want = 0.5 * midpoint(&|r| r * r / (2.0 * r * (r * r + a * a)).sqrt(), 0.6, 8.0);
        assert!((eq - want).abs() < 1e-8 * want, "{eq} vs {want}");
        let tiny = target(1e-9).fall_time(0.3, 4.0, DVec3::new(0.6, 0.0, 0.8));
        let law = 2.0 / 3.0 * (4f64.powf(1.5) - 0.3f64.powf(1.5));
        assert!((tiny - law).abs() < 1e-9 * law, "{tiny} vs {law}");
        // The fall's film time inverts it: half the film, half the time.
        let anim = Animation {
            camera: CameraPath::Fall,
            fall_seconds: 10.0,
            ..Animation::default()
        };
        let d = anim.fall_distance(&target(a), DVec3::Y, 4.0, 0.3, 5.0);
        let half = target(a).fall_time(d, 4.0, DVec3::Y);
        assert!(
            (half - 0.5 * axis).abs() < 1e-9 * axis,
            "{half} vs {}",
            0.5 * axis
        );
        assert_eq!(
            anim.fall_distance(&target(a), DVec3::Y, 4.0, 0.3, 10.0),
            0.3
        );
    }

    #[test]
    fn orbit_starts_at_the_camera_and_keeps_its_distance() {
        let base = Camera::default();
        let anim = Animation {
            camera: CameraPath::Orbit,
            inclination_deg: (0.8f64 / 15.0).atan().to_degrees(),
            ..Animation::default()
        };
        let c0 = anim.camera_at(&base, 0.0, HOLE);
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
            let c = anim.camera_at(&base, t, HOLE);
            assert!((DVec3::from(c.position).length() - r0).abs() < 1e-9);
        }
        // A quarter turn after 9 s at 10 deg/s: from -z to +x (counter-clockwise from +y).
        let q = anim.camera_at(&base, 9.0, HOLE);
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
        assert_eq!(anim.camera_at(&base, 0.0, HOLE).position[0], 0.0);
        assert!((anim.camera_at(&base, 1.0, HOLE).position[0] - 2.0).abs() < 1e-12);
        assert_eq!(anim.camera_at(&base, 5.0, HOLE).position[0], 4.0);
    }
}
