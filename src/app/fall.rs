//! The window's fall: from the current view, the camera drops from rest
//! straight into the first hole along the line from its centre through the
//! camera, as `[animation] camera = "fall"` moves it (the free-fall law, its
//! own clock mapped to `fall_seconds` of the wall clock, to the scene's end
//! radius: through the horizon of a non-rotating hole), held by a
//! `"falling"` observer; "return" puts the view back. While it falls, a
//! drag turns the view around the camera (it starts looking down the fall)
//! instead of orbiting. And the panel's line about where the camera is.

use std::time::Instant;

use glam::DVec3;

use super::camera::Orbit;
use crate::physics::observer::ObserverKind;
use crate::scene::Scene;
use crate::spacetime::radii;

/// A fall in progress.
#[derive(Clone, Copy, Debug)]
pub struct WindowFall {
    /// The view it started from (and returns to).
    pub before: Orbit,
    began: Instant,
    /// Distance from the hole at the start.
    r0: f64,
    /// Unit direction from the hole to the start: the line of the fall.
    line: DVec3,
}

/// The orbit's distance while it turns the view around the falling camera
/// (in rs): the camera sits this far from the point it looks at.
const LOOK: f64 = 1e-3;

impl WindowFall {
    /// A fall from `orbit`'s camera into the scene's first hole; None
    /// without a hole.
    pub fn start(orbit: &Orbit, scene: &Scene) -> Option<WindowFall> {
        let target = scene.fall_target_as(ObserverKind::Falling);
        scene.black_holes.first()?;
        let rel = DVec3::from(orbit.camera().position) - target.centre;
        Some(WindowFall {
            before: *orbit,
            began: Instant::now(),
            r0: rel.length(),
            line: rel.normalize_or(DVec3::NEG_Z),
        })
    }

    /// The orbit `now`: the camera on the line of the fall at the fall's
    /// radius, held by a falling observer, looking the way `orbit`'s angles
    /// say (an orbit of [`LOOK`] rs around the point it looks at: at the
    /// start, the hole).
    pub fn orbit_at(&self, orbit: &Orbit, scene: &Scene, now: Instant) -> Orbit {
        self.orbit_after(orbit, scene, now.duration_since(self.began).as_secs_f64())
    }

    /// The same `t` seconds into the fall (past `fall_seconds`: its end).
    pub fn orbit_after(&self, orbit: &Orbit, scene: &Scene, t: f64) -> Orbit {
        let target = scene.fall_target_as(ObserverKind::Falling);
        let anim = &scene.animation;
        let end = anim.fall_end(&target, self.line);
        let r = anim.fall_distance(&target, self.line, self.r0, end, t);
        let camera = target.centre + r * self.line;
        let mut o = *orbit;
        o.distance = LOOK * target.rs;
        o.target = DVec3::ZERO;
        let offset = DVec3::from(o.camera().position);
        o.target = camera - offset;
        o.lens.observer = ObserverKind::Falling;
        o
    }
}

/// Where the camera is, for the panel: its distance from the first hole,
/// whether it is inside the horizon and, for a falling camera of a
/// non-rotating hole, the proper time it has left before the singularity,
/// (2/3) (r / rs)^(3/2) rs / c.
pub fn camera_status(scene: &Scene) -> String {
    let target = scene.fall_target();
    if scene.black_holes.is_empty() {
        return "no hole".into();
    }
    let rel = DVec3::from(scene.camera.position) - target.centre;
    let r = rel.length() / target.rs;
    // Inside: Boyer-Lindquist r <= r+ on the camera's line.
    let horizon = radii::horizon(1.0, target.spin.abs());
    let inside = target.radius_at(rel.length(), rel.normalize_or(DVec3::Y)) <= horizon;
    let mut s = format!(
        "r = {r:.4} rs, {} the horizon",
        if inside { "inside" } else { "outside" }
    );
    if target.interior && target.spin == 0.0 && scene.camera.observer == ObserverKind::Falling {
        s += &format!(
            "  |  {:.4} rs/c of proper time to the singularity",
            2.0 / 3.0 * r.powf(1.5)
        );
    }
    s
}
