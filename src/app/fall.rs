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
        scene.black_holes.first()?;
        let position = DVec3::from(orbit.camera().position);
        let fall = scene
            .spacetime()
            .fall_from(position, ObserverKind::Falling, DVec3::NEG_Z);
        Some(WindowFall {
            before: *orbit,
            began: Instant::now(),
            r0: fall.start(),
            line: fall.line(),
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
        // The scene's spacetime now: the panel may change the hole mid-fall.
        let fall = scene
            .spacetime()
            .fall(self.r0, self.line, ObserverKind::Falling);
        let anim = &scene.animation;
        let end = fall.end(anim.fall_end_radius);
        let r = fall.distance_after(anim.fall_fraction(t), end);
        let camera = fall.centre() + r * self.line;
        let mut o = *orbit;
        o.distance = LOOK * fall.rs();
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
    if scene.black_holes.is_empty() {
        return "no hole".into();
    }
    let c = &scene.camera;
    let fall = scene
        .spacetime()
        .fall_from(DVec3::from(c.position), c.observer, DVec3::Y);
    let r = fall.start() / fall.rs();
    // Inside: Boyer-Lindquist r <= r+ on the camera's line.
    let inside = fall.inside_horizon(fall.start());
    let mut s = format!(
        "r = {r:.4} rs, {} the horizon",
        if inside { "inside" } else { "outside" }
    );
    if let Some(tau) = fall.time_to_singularity() {
        s += &format!("  |  {tau:.4} rs/c of proper time to the singularity");
    }
    s
}
