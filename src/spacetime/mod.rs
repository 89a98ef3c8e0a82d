//! The spacetime seam: what a scene's holes do to light, as one closed enum.
//! Each variant gives, in f64, the light path from an origin along a
//! direction ([`Spacetime::trace`]: closed form, integrated or straight),
//! the observer's frame at any origin ([`Spacetime::observer`]), the
//! redshift of a Keplerian emitter ([`Spacetime::emitter_g`]), the horizon,
//! the photon orbit and the ISCO, and which path the GPU takes
//! ([`Spacetime::gpu_path`]). The physics behind each lives in
//! [`crate::physics`]; the GLSL twins are `shaders/include/metric/*.glsl`.
//!
//! The spinning (Kerr) hole is [`Spacetime::Kerr`]: `spacetime/kerr.rs`
//! maps the scene's frame to the hole's around the closed form of
//! [`crate::physics::kerr`]; `shaders/include/metric/kerr.glsl` is its GPU
//! twin (the same function set as `schwarzschild.glsl`).

pub mod kerr;
pub mod placement;
pub mod radii;

use glam::DVec3;

pub use kerr::SpinningHole;
pub use placement::{FALLING_MIN_R, Refusal};

use crate::physics::observer::{Observer, ObserverKind};
use crate::physics::{Disk, Hole, Outcome, TraceOptions, closed_form, geodesic, redshift};
use crate::scene::Scene;

/// What the holes of a scene do to light.
#[derive(Clone, Debug, PartialEq)]
pub enum Spacetime {
    /// Gravity off: straight lines (the holes still absorb).
    Flat(Vec<Hole>),
    /// One non-rotating hole: exact light paths in closed form.
    Schwarzschild(Hole),
    /// Several holes: their pulls summed (an approximation, exact for one
    /// hole only) and integrated step by step.
    Summed(Vec<Hole>),
    /// One spinning hole: exact light paths in closed form (Mino time).
    Kerr(SpinningHole),
}

/// Which metric the ray march is built with (one file of
/// `shaders/include/metric/` each, chosen by a define in build.rs; each
/// defines `metric_trace`; [`crate::shaders::raymarch`] picks the module).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub enum GpuPath {
    /// `metric/flat.glsl` (`METRIC_FLAT`): straight lines.
    Straight,
    /// `metric/schwarzschild.glsl` (`METRIC_SCHWARZSCHILD`): the closed form.
    ClosedForm,
    /// `metric/summed.glsl` (`METRIC_SUMMED`): integrated step by step.
    Integrated,
    /// `metric/kerr.glsl` (`METRIC_KERR`): the spinning hole's closed form.
    Kerr,
}

impl Spacetime {
    /// The scene's spacetime.
    pub fn of(scene: &Scene) -> Self {
        let holes = scene.physics_holes();
        match holes.as_slice() {
            _ if !scene.physics.gravity => Spacetime::Flat(holes),
            [one] if scene.black_holes[0].spin != 0.0 => Spacetime::Kerr(SpinningHole {
                hole: *one,
                spin: scene.black_holes[0].spin,
                axis: DVec3::from(scene.disk.normal).normalize(),
            }),
            [one] => Spacetime::Schwarzschild(*one),
            _ => Spacetime::Summed(holes),
        }
    }

    /// The spin a* of the spacetime's hole: a spinning hole's, else 0 (with
    /// gravity off too: then no hole spins, and the disk is a non-rotating
    /// hole's). The GPU block carries it once, in its metric part.
    pub fn spin(&self) -> f64 {
        match self {
            Spacetime::Kerr(k) => k.spin,
            _ => 0.0,
        }
    }

    /// The holes.
    pub fn holes(&self) -> &[Hole] {
        match self {
            Spacetime::Flat(h) | Spacetime::Summed(h) => h,
            Spacetime::Schwarzschild(h) => std::slice::from_ref(h),
            Spacetime::Kerr(k) => std::slice::from_ref(&k.hole),
        }
    }

    /// The hole whose frame an observer at `position` uses: the nearest.
    pub fn reference_hole(&self, position: DVec3) -> Option<&Hole> {
        crate::physics::observer::reference_hole(self.holes(), position)
    }

    /// The path the ray march takes.
    pub fn gpu_path(&self) -> GpuPath {
        match self {
            Spacetime::Flat(_) => GpuPath::Straight,
            Spacetime::Schwarzschild(_) => GpuPath::ClosedForm,
            Spacetime::Summed(_) => GpuPath::Integrated,
            Spacetime::Kerr(_) => GpuPath::Kerr,
        }
    }

    /// Where a ray from `x0` along `v0` (a coordinate direction; for a
    /// spinning hole, the direction in the ZAMO's frame at `x0`) ends: the
    /// sky (with its final direction), a horizon, or the thin `disk`.
    pub fn trace(&self, disk: Option<&Disk>, x0: DVec3, v0: DVec3, opt: &TraceOptions) -> Outcome {
        match self {
            Spacetime::Schwarzschild(hole) => closed_form::trace_closed(hole, disk, x0, v0),
            Spacetime::Summed(holes) => geodesic::trace(holes, disk, x0, v0, opt).outcome,
            Spacetime::Flat(holes) => trace_straight(holes, disk, x0, v0),
            Spacetime::Kerr(k) => k.trace(disk, x0, v0),
        }
    }

    /// The observer of `kind` at `position` (any origin): the frame its
    /// pixel directions are measured in. `disk_normal` sets an orbit's sense.
    /// Around a spinning hole the frame is the ZAMO's, and the observer's
    /// velocity is relative to it (zero where it cannot stand: validation
    /// refuses such cameras).
    pub fn observer(&self, kind: ObserverKind, position: DVec3, disk_normal: DVec3) -> Observer {
        if let Spacetime::Kerr(k) = self {
            return Observer {
                kind,
                rhat: DVec3::Y,
                lapse: 1.0,
                beta: k.observer_velocity(kind, position).unwrap_or(DVec3::ZERO),
                rain: None,
            };
        }
        let gravity = !matches!(self, Spacetime::Flat(_));
        Observer::new(kind, position, self.holes(), disk_normal, gravity)
    }

    /// Whether the scene's camera is a falling camera between a spinning
    /// hole's horizons, or just outside the outer one (within
    /// [`crate::physics::kerr::FALLING_FRAME_BAND`] of r+): the ray march's
    /// `KERR_INSIDE` path, its photons from the metric's falling frame.
    pub fn camera_inside_spinning(&self, scene: &Scene) -> bool {
        self.camera_inside_radius(scene).is_some()
    }

    /// The Boyer-Lindquist r (M) of such a camera; None for every other.
    pub fn camera_inside_radius(&self, scene: &Scene) -> Option<f64> {
        let Spacetime::Kerr(k) = self else {
            return None;
        };
        let r = k.radius_of(DVec3::from(scene.camera.position));
        let band = (1.0 + crate::physics::kerr::FALLING_FRAME_BAND) * k.r_plus_m();
        // (ODS eyes each stand at their own r: outside r+ they keep the
        // exterior's frames; inside, validation refuses them.)
        let ods = scene.camera.stereo == crate::scene::Stereo::Ods && r > k.r_plus_m();
        (scene.camera.observer == ObserverKind::Falling && r < band && !ods).then_some(r)
    }

    /// The observer holding the scene's camera (`[camera] observer` at its
    /// position, an orbit's sense from the disk's normal).
    pub fn camera_observer(&self, scene: &Scene) -> Observer {
        self.observer(
            scene.camera.observer,
            DVec3::from(scene.camera.position),
            DVec3::from(scene.disk.normal),
        )
    }

    /// The redshift g = nu_obs / nu_emit, seen from far away, of light from
    /// an emitter on a circular Keplerian orbit at `r` around the first hole,
    /// for a photon of angular momentum `lambda` about the disk's axis (per
    /// unit energy). With gravity off the emitter still turns: only the
    /// Doppler part remains (the GPU's straight path uses the same formula).
    /// Around a spinning hole: r^(3/4) sqrt(r^(3/2) - 3 r^(1/2) + 2a) /
    /// (r^(3/2) + a - lambda) in units of M (the prograde Keplerian emitter).
    pub fn emitter_g(&self, r: f64, lambda: f64) -> f64 {
        if let Spacetime::Kerr(k) = self {
            let (m, a) = (0.5 * k.hole.rs, k.spin);
            let (r, l) = (r / m, lambda / m);
            let x = r.sqrt();
            return (x * r).sqrt() * (x * r - 3.0 * x + 2.0 * a).sqrt() / (x * r + a - l);
        }
        let rs = self.holes().first().map_or(0.0, |h| h.rs);
        redshift::disk_redshift(r, rs, lambda)
    }

    /// The horizon's radius around each hole (its `rs`).
    pub fn horizon_radius(&self, hole: &Hole) -> f64 {
        match self {
            Spacetime::Kerr(k) => k.horizon(),
            _ => hole.rs,
        }
    }

    /// The photon orbit's radius around `hole`: 1.5 rs (none with gravity off).
    pub fn photon_orbit(&self, hole: &Hole) -> Option<f64> {
        match self {
            Spacetime::Flat(_) => None,
            Spacetime::Kerr(k) => Some(k.photon_orbit()),
            _ => Some(1.5 * hole.rs),
        }
    }

    /// The innermost stable circular orbit around `hole`: 3 rs (none with
    /// gravity off).
    pub fn isco(&self, hole: &Hole) -> Option<f64> {
        match self {
            Spacetime::Flat(_) => None,
            Spacetime::Kerr(k) => Some(k.isco()),
            _ => Some(3.0 * hole.rs),
        }
    }
}

/// A straight line from `x0` along `v0`: the first horizon it enters, the
/// thin disk's annulus around the first hole, or the sky.
fn trace_straight(holes: &[Hole], disk: Option<&Disk>, x0: DVec3, v0: DVec3) -> Outcome {
    let d = v0.normalize();
    // The first horizon along the line: (distance, hole).
    let mut first: Option<(f64, usize)> = None;
    for (i, h) in holes.iter().enumerate() {
        let rel = x0 - h.position;
        let b = rel.dot(d);
        let c = rel.length_squared() - h.rs * h.rs;
        if c < 0.0 {
            return Outcome::Captured { hole: i };
        }
        let disc = b * b - c;
        let t = -b - disc.max(0.0).sqrt();
        if disc > 0.0 && t > 0.0 && first.is_none_or(|(best, _)| t < best) {
            first = Some((t, i));
        }
    }
    let t_h = first.map_or(f64::INFINITY, |(t, _)| t);
    if let (Some(disk), Some(centre)) = (disk, holes.first()) {
        let n = disk.normal.normalize();
        let t = -(x0 - centre.position).dot(n) / d.dot(n);
        let p = x0 + t * d;
        let rho = (p - centre.position).length();
        if t > 0.0 && t < t_h && (disk.inner..=disk.outer).contains(&rho) {
            return Outcome::Disk {
                position: p,
                velocity: d,
            };
        }
    }
    match first {
        Some((_, hole)) => Outcome::Captured { hole },
        None => Outcome::Escaped { direction: d },
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn scene(toml: &str) -> Scene {
        Scene::from_toml(toml, "t.toml").expect("scene")
    }

    #[test]
    fn a_scene_picks_its_spacetime_and_gpu_path() {
        let one = Spacetime::of(&scene(""));
        assert!(matches!(one, Spacetime::Schwarzschild(_)));
        assert_eq!(one.gpu_path(), GpuPath::ClosedForm);
        let two = Spacetime::of(&Scene::load("binary").expect("preset"));
        assert_eq!(two.gpu_path(), GpuPath::Integrated);
        assert_eq!(two.holes().len(), 2);
        let flat = Spacetime::of(&Scene::load("no-gravity").expect("preset"));
        assert_eq!(flat.gpu_path(), GpuPath::Straight);
        assert_eq!(flat.isco(&flat.holes()[0]), None);
        assert_eq!(one.isco(&one.holes()[0]), Some(3.0));
        assert_eq!(one.photon_orbit(&one.holes()[0]), Some(1.5));
    }

    #[test]
    fn straight_rays_hit_what_line_geometry_says() {
        let flat = Spacetime::of(&scene("[physics]\ngravity = false\n"));
        let disk = Disk {
            normal: DVec3::Y,
            inner: 3.0,
            outer: 12.0,
        };
        let opt = TraceOptions::default();
        let x0 = DVec3::new(0.0, 0.0, -10.0);
        // Straight at the hole: captured.
        assert_eq!(
            flat.trace(Some(&disk), x0, DVec3::Z, &opt),
            Outcome::Captured { hole: 0 }
        );
        // Down onto the disk at 5 rs.
        let p = DVec3::new(0.0, 0.0, -5.0);
        match flat.trace(
            Some(&disk),
            DVec3::new(0.0, 2.0, -5.0),
            p - DVec3::new(0.0, 2.0, -5.0),
            &opt,
        ) {
            Outcome::Disk { position, .. } => assert!((position - p).length() < 1e-12),
            o => panic!("{o:?}"),
        }
        // Away from everything: the sky, in its own direction.
        match flat.trace(Some(&disk), x0, -DVec3::Z, &opt) {
            Outcome::Escaped { direction } => assert!((direction + DVec3::Z).length() < 1e-12),
            o => panic!("{o:?}"),
        }
    }

    #[test]
    fn the_emitter_redshift_is_the_kepler_formula() {
        let s = Spacetime::of(&scene(""));
        // A photon with no angular momentum about the axis: the transverse
        // and gravitational shifts only, sqrt(1 - 1.5 rs / r).
        assert!((s.emitter_g(6.0, 0.0) - 0.75f64.sqrt()).abs() < 1e-15);
    }
}
