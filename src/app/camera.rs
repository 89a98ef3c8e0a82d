//! The window's camera controller: an orbit around `look_at` in spherical
//! coordinates (distance, azimuth, elevation) about the scene camera's own
//! up (its pole: +y in most scenes; the sky's north in `m87`, whose
//! picture keeps north up as it turns), panned by moving `look_at` in the
//! view plane. It writes the scene's `[camera]` keys, so a saved scene
//! renders offscreen exactly what the window showed.

use glam::DVec3;

use crate::scene::Camera;
use crate::spacetime::Spacetime;

/// Closest the wheel brings the camera to the hole: just outside the photon
/// sphere (1.5 rs), unless the user asks to go further in. For a spinning
/// hole the same margin outside its outer (retrograde) circular photon orbit.
pub const MIN_DISTANCE_RS: f64 = 1.6;

/// The wheel's nearest distance (units of rs) to the spacetime's first
/// hole: 1.6/1.5 of the outer photon orbit's distance from the centre in
/// the disk's plane ([`Spacetime::equatorial_distance`]); inside allowed,
/// 1.01 of the horizon's.
pub fn min_distance_rs(spacetime: &Spacetime, allow_inside: bool) -> f64 {
    let Some(hole) = spacetime.holes().first() else {
        return MIN_DISTANCE_RS;
    };
    let d = |r: f64| spacetime.equatorial_distance(r) / hole.rs;
    if allow_inside {
        1.01 * d(spacetime.horizon_radius(hole))
    } else {
        // (Gravity off: no photon orbit; the wheel stops where it would be.)
        MIN_DISTANCE_RS / 1.5 * d(spacetime.outer_photon_orbit(hole).unwrap_or(1.5 * hole.rs))
    }
}

/// Highest elevation of the orbit (radians, just short of the pole): a
/// camera exactly on the pole would have no defined right.
const MAX_ELEVATION: f64 = 1.55;

/// An orbit camera.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Orbit {
    pub target: DVec3,
    pub distance: f64,
    /// Radians, around the pole, 0 on the side of -z (for the pole +y:
    /// looking from -z toward +z).
    pub azimuth: f64,
    /// Radians above the plane at right angles to the pole.
    pub elevation: f64,
    /// The orbit's axis and the camera's up (unit).
    pub pole: DVec3,
    /// The scene's camera, for what the orbit keeps as it is: the field of
    /// view, the observer, the projection, stereo and eye distance (its
    /// position, look_at and up are the orbit's).
    pub lens: Camera,
    /// Whether the wheel may take the camera inside the photon sphere.
    pub allow_inside: bool,
}

impl Orbit {
    /// The orbit that reproduces `camera` about its up (a camera on the
    /// pole is tilted to the highest elevation the orbit allows).
    pub fn from_camera(camera: &Camera) -> Self {
        let target = DVec3::from(camera.look_at);
        let d = DVec3::from(camera.position) - target;
        let distance = d.length().max(1e-6);
        let pole = DVec3::from(camera.up).try_normalize().unwrap_or(DVec3::Y);
        let (a, b) = azimuth_axes(pole);
        Orbit {
            target,
            distance,
            azimuth: d.dot(b).atan2(d.dot(a)),
            elevation: (d.dot(pole) / distance)
                .clamp(-1.0, 1.0)
                .asin()
                .clamp(-MAX_ELEVATION, MAX_ELEVATION),
            pole,
            lens: *camera,
            allow_inside: false,
        }
    }

    /// The scene camera of this orbit.
    pub fn camera(&self) -> Camera {
        let (se, ce) = self.elevation.sin_cos();
        let (sa, ca) = self.azimuth.sin_cos();
        let (a, b) = azimuth_axes(self.pole);
        let offset = (ce * (ca * a + sa * b) + se * self.pole) * self.distance;
        Camera {
            position: (self.target + offset).to_array(),
            look_at: self.target.to_array(),
            up: self.pole.to_array(),
            ..self.lens
        }
    }

    /// Left drag: `dx`, `dy` in pixels of a window `height` pixels tall
    /// (dragging right turns the scene right: the camera moves left).
    pub fn rotate(&mut self, dx: f64, dy: f64, height: f64) {
        let per_pixel = std::f64::consts::PI / height.max(1.0);
        self.azimuth -= dx * per_pixel;
        self.elevation = (self.elevation + dy * per_pixel).clamp(-MAX_ELEVATION, MAX_ELEVATION);
    }

    /// Wheel: `steps` notches, positive zooms in; never closer than
    /// [`min_distance_rs`] times the first hole's rs to the target.
    pub fn zoom(&mut self, steps: f64, spacetime: &Spacetime) {
        let rs = spacetime.holes().first().map_or(1.0, |h| h.rs);
        let min = min_distance_rs(spacetime, self.allow_inside) * rs;
        self.distance = (self.distance * 0.9f64.powf(steps)).clamp(min, 1e5 * rs);
    }

    /// Right drag: moves the target in the view plane, `dx`, `dy` in pixels.
    pub fn pan(&mut self, dx: f64, dy: f64, height: f64) {
        let cam = self.camera();
        let f = cam.frame();
        let h = height.max(1.0) as u32;
        let scale = self.distance * f.pixel_angle(h, h);
        self.target += (-dx * f.right + dy * f.up) * scale;
    }
}

/// The directions of azimuth 0 and 90 degrees about `pole`: -z and +x for
/// the pole +y (-z made perpendicular to the pole, or +x where the pole
/// is along z).
fn azimuth_axes(pole: DVec3) -> (DVec3, DVec3) {
    let a = (DVec3::NEG_Z - pole * -pole.z)
        .try_normalize()
        .unwrap_or_else(|| (DVec3::X - pole * pole.x).normalize());
    (a, a.cross(pole))
}

/// The three preset views about +y (the disk's usual axis): front (just
/// above the disk), top (down the axis) and a free three-quarter view, at
/// the current distance.
pub fn preset_view(which: u8, current: &Orbit) -> Orbit {
    let (azimuth, elevation) = match which {
        1 => (0.0, 3f64.to_radians()),
        2 => (0.0, 89f64.to_radians()),
        _ => (35f64.to_radians(), 25f64.to_radians()),
    };
    Orbit {
        azimuth,
        elevation,
        target: DVec3::ZERO,
        pole: DVec3::Y,
        ..*current
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn orbit_round_trips_the_default_camera() {
        let cam = Camera::default();
        let back = Orbit::from_camera(&cam).camera();
        for i in 0..3 {
            assert!((back.position[i] - cam.position[i]).abs() < 1e-9);
        }
    }

    /// The m87 preset's picture keeps the sky's north up as it turns: the
    /// orbit reproduces its camera, up and all, and a drag turns the camera
    /// about that up.
    #[test]
    fn the_orbit_turns_about_the_cameras_own_up() {
        let m87 = crate::scene::Scene::load("m87").expect("preset");
        let o = Orbit::from_camera(&m87.camera);
        let back = o.camera();
        for i in 0..3 {
            assert!((back.position[i] - m87.camera.position[i]).abs() < 1e-6 * o.distance);
            assert!((back.up[i] - DVec3::from(m87.camera.up).normalize()[i]).abs() < 1e-12);
        }
        let mut turned = o;
        turned.rotate(120.0, 0.0, 360.0);
        let cam = turned.camera();
        let up = DVec3::from(m87.camera.up).normalize();
        let d0 = DVec3::from(m87.camera.position);
        let d1 = DVec3::from(cam.position);
        assert!(
            (d1.dot(up) - d0.dot(up)).abs() < 1e-6 * o.distance,
            "about the up"
        );
        assert!(d1.distance(d0) > 0.5 * o.distance, "turned");
        assert_eq!(cam.up, up.to_array());
        let mut scene = m87.clone();
        scene.camera = cam;
        scene.check().expect("the turned camera passes validation");
    }

    #[test]
    fn a_camera_on_the_axis_becomes_a_valid_orbit_camera() {
        let top = crate::scene::Scene::load("top-down").expect("preset");
        let mut scene = top.clone();
        scene.camera = Orbit::from_camera(&top.camera).camera();
        scene.check().expect("the orbit's camera passes validation");
        let f = scene.camera.frame();
        assert!(f.right.is_finite() && f.up.is_finite());
        assert!(f.forward.dot(DVec3::NEG_Y) > 0.999, "still looks down");
    }

    #[test]
    fn dragging_right_moves_the_camera_toward_minus_x_and_keeps_the_distance() {
        let mut o = Orbit::from_camera(&Camera::default());
        let d0 = o.distance;
        o.rotate(100.0, 0.0, 360.0);
        let p = o.camera().position;
        assert!(p[0] < 0.0, "{p:?}");
        assert!((DVec3::from(p).length() - d0).abs() < 1e-9);
    }

    /// A hole of rs 1 at the origin spinning at `spin`.
    fn hole(spin: f64) -> Spacetime {
        let hole = crate::physics::Hole {
            position: DVec3::ZERO,
            rs: 1.0,
        };
        let body = crate::spacetime::Body { hole, spin };
        Spacetime::new(&[body], true, DVec3::Y)
    }

    #[test]
    fn the_wheel_stops_outside_the_photon_sphere() {
        let mut o = Orbit::from_camera(&Camera::default());
        o.zoom(500.0, &hole(0.0));
        assert!((o.distance - MIN_DISTANCE_RS).abs() < 1e-12);
        o.allow_inside = true;
        o.zoom(500.0, &hole(0.0));
        assert!(o.distance < 1.5 && o.distance > 1.0);
    }

    #[test]
    fn the_wheel_follows_the_spins_photon_orbits_and_horizon() {
        // a* = 0.998 (Bardeen 1972): retrograde photon orbit r = 3.9982 M,
        // horizon 1.0632 M; distances sqrt(r^2 + a^2) / 2 in rs.
        let mut o = Orbit::from_camera(&Camera::default());
        o.zoom(500.0, &hole(0.998));
        let outer = 0.5 * (3.9982f64.powi(2) + 0.998f64.powi(2)).sqrt();
        assert!(
            (o.distance - 1.6 / 1.5 * outer).abs() < 1e-3,
            "{}",
            o.distance
        );
        o.allow_inside = true;
        o.zoom(500.0, &hole(-0.998));
        let horizon = 0.5 * (1.0632f64.powi(2) + 0.998f64.powi(2)).sqrt();
        assert!((o.distance - 1.01 * horizon).abs() < 1e-3, "{}", o.distance);
    }
}
