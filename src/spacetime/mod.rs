//! The spacetime seam, the one door to a hole's physics: what holes do to
//! light, built from values (the holes with their spins, gravity on or off,
//! the disk's axis; `Scene::spacetime` builds it from a scene, and nothing
//! here knows a scene), its metric one closed enum.
//! Each variant gives, in f64, the light path from an origin along a
//! direction ([`Spacetime::trace`]: closed form, integrated or straight),
//! the observer's frame at any origin ([`Spacetime::observer`]), the
//! redshift of a Keplerian emitter ([`Spacetime::emitter_g`]), the horizon,
//! the photon orbit and the ISCO, and which path the GPU takes
//! ([`Spacetime::gpu_path`]). The physics behind each lives in
//! [`crate::physics`]; the GLSL twins are `shaders/include/metric/*.glsl`.
//!
//! The spinning (Kerr) hole is [`Metric::Kerr`]: `spacetime/kerr.rs`
//! maps the scene's frame to the hole's around the closed form of
//! [`crate::physics::kerr`]; `shaders/include/metric/kerr.glsl` is its GPU
//! twin (the same function set as `schwarzschild.glsl`).

pub mod fall;
pub mod kerr;
pub mod path;
pub mod placement;
pub mod radii;

use glam::DVec3;

/// The polarized thin disk's emitter model and Stokes parameters: what the
/// door hands the renderer and the tests (physics/polarization.rs).
pub use crate::physics::polarization::{Emission, Stokes};
pub use fall::Fall;
pub use kerr::SpinningHole;
pub use path::LightPath;
pub use placement::{EndRefusal, FALLING_MIN_R, Refusal};

use crate::physics::observer::{Observer, ObserverKind};
use crate::physics::{Disk, Hole, Outcome, TraceOptions, closed_form, geodesic, redshift};

/// One hole as the spacetime takes it: its place and size (rs), and its
/// signed spin a* (0: non-rotating).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Body {
    pub hole: Hole,
    pub spin: f64,
}

/// Where a camera stands, as the spacetime's questions about it need it:
/// its place, the observer holding it, and whether it is an ODS pair (each
/// eye at its own place).
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Viewer {
    pub position: DVec3,
    pub observer: ObserverKind,
    pub ods: bool,
}

/// What a scene's holes do to light: the metric (one closed enum) and the
/// disk's axis, which sets a spinning hole's axis and an orbit's sense.
#[derive(Clone, Debug, PartialEq)]
pub struct Spacetime {
    metric: Metric,
    /// The disk's normal as given (not normalised: the observers normalise
    /// it where they need to).
    axis: DVec3,
}

/// The metric of a [`Spacetime`].
#[derive(Clone, Debug, PartialEq)]
pub enum Metric {
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
/// defines `metric_trace`; src/shaders.rs, `raymarch`, picks the module).
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
    /// The spacetime of `bodies` with `gravity` on or off, the disk's normal
    /// `axis` (a spinning hole's axis, an orbit's sense). A spinning hole is
    /// the only one of its scene (validation says so); with gravity off no
    /// hole spins.
    pub fn new(bodies: &[Body], gravity: bool, axis: DVec3) -> Self {
        let holes: Vec<Hole> = bodies.iter().map(|b| b.hole).collect();
        let metric = match bodies {
            _ if !gravity => Metric::Flat(holes),
            [one] if one.spin != 0.0 => Metric::Kerr(SpinningHole {
                hole: one.hole,
                spin: one.spin,
                axis: axis.normalize(),
            }),
            [one] => Metric::Schwarzschild(one.hole),
            _ => Metric::Summed(holes),
        };
        Spacetime { metric, axis }
    }

    /// One non-rotating hole in the spinning hole's form at a* = 0 (Mino
    /// time, Carlson's integrals; the same light paths): the AOVs take it
    /// where the device has 64-bit floats, for its 64-bit camera and roots
    /// (far cameras, the deep interior). None for every other metric.
    pub fn spinning_form(&self) -> Option<Spacetime> {
        let Metric::Schwarzschild(hole) = self.metric else {
            return None;
        };
        Some(Spacetime {
            metric: Metric::Kerr(SpinningHole {
                hole,
                spin: 0.0,
                axis: self.axis.normalize(),
            }),
            axis: self.axis,
        })
    }

    /// The metric.
    pub fn metric(&self) -> &Metric {
        &self.metric
    }

    /// The disk's normal the spacetime was built with.
    pub fn axis(&self) -> DVec3 {
        self.axis
    }

    /// Whether it is one non-rotating hole (its camera may fall through the
    /// horizon to [`FALLING_MIN_R`]).
    pub fn one_static_hole(&self) -> bool {
        matches!(self.metric, Metric::Schwarzschild(_))
    }

    /// The spin a* of the spacetime's hole: a spinning hole's, else 0 (with
    /// gravity off too: then no hole spins, and the disk is a non-rotating
    /// hole's). The GPU block carries it once, in its metric part.
    pub fn spin(&self) -> f64 {
        match &self.metric {
            Metric::Kerr(k) => k.spin,
            _ => 0.0,
        }
    }

    /// The holes.
    pub fn holes(&self) -> &[Hole] {
        match &self.metric {
            Metric::Flat(h) | Metric::Summed(h) => h,
            Metric::Schwarzschild(h) => std::slice::from_ref(h),
            Metric::Kerr(k) => std::slice::from_ref(&k.hole),
        }
    }

    /// The hole whose frame an observer at `position` uses: the nearest.
    pub fn reference_hole(&self, position: DVec3) -> Option<&Hole> {
        crate::physics::observer::reference_hole(self.holes(), position)
    }

    /// The path the ray march takes.
    pub fn gpu_path(&self) -> GpuPath {
        match &self.metric {
            Metric::Flat(_) => GpuPath::Straight,
            Metric::Schwarzschild(_) => GpuPath::ClosedForm,
            Metric::Summed(_) => GpuPath::Integrated,
            Metric::Kerr(_) => GpuPath::Kerr,
        }
    }

    /// Where a ray from `x0` along `v0` (a coordinate direction; for a
    /// spinning hole, the direction in the ZAMO's frame at `x0`) ends: the
    /// sky (with its final direction), a horizon, or the thin `disk`.
    pub fn trace(&self, disk: Option<&Disk>, x0: DVec3, v0: DVec3, opt: &TraceOptions) -> Outcome {
        match &self.metric {
            Metric::Schwarzschild(hole) => closed_form::trace_closed(hole, disk, x0, v0),
            Metric::Summed(holes) => geodesic::trace(holes, disk, x0, v0, opt).outcome,
            Metric::Flat(holes) => trace_straight(holes, disk, x0, v0),
            Metric::Kerr(k) => k.trace(disk, x0, v0),
        }
    }

    /// The observer of `kind` at `position` (any origin): the frame its
    /// pixel directions are measured in (an orbit's sense from the disk's
    /// axis). Around a spinning hole the frame is the ZAMO's, and the
    /// observer's velocity is relative to it (zero where it cannot stand:
    /// validation refuses such cameras).
    pub fn observer(&self, kind: ObserverKind, position: DVec3) -> Observer {
        if let Metric::Kerr(k) = &self.metric {
            // At a* = 0 an orbiting observer off the disk's plane keeps the
            // non-rotating hole's circular geodesic through its place (the
            // spinning hole's turns about the axis at the Keplerian rate).
            let beta = if k.spin == 0.0 && kind == ObserverKind::Orbiting {
                Observer::new(kind, position, &[k.hole], self.axis, true).beta
            } else {
                k.observer_velocity(kind, position).unwrap_or(DVec3::ZERO)
            };
            return Observer {
                kind,
                rhat: DVec3::Y,
                lapse: 1.0,
                beta,
                rain: None,
            };
        }
        let gravity = !matches!(self.metric, Metric::Flat(_));
        Observer::new(kind, position, self.holes(), self.axis, gravity)
    }

    /// The observer holding a camera (`viewer`'s observer at its place).
    pub fn camera_observer(&self, viewer: &Viewer) -> Observer {
        self.observer(viewer.observer, viewer.position)
    }

    /// Why the polarized thin disk (`--aov stokes`) cannot be computed for
    /// this scene, if it cannot: it is carried in closed form for one hole
    /// (spinning or not), for every camera the scene can hold, outside the
    /// horizon and falling through it (docs/polarization.md).
    pub fn polarization_refusal(&self) -> Option<String> {
        match &self.metric {
            Metric::Flat(_) => Some("needs gravity on (physics.gravity = true)".into()),
            Metric::Summed(h) => Some(format!(
                "is exact for one hole; this scene has {} (their paths are integrated)",
                h.len()
            )),
            Metric::Schwarzschild(_) | Metric::Kerr(_) => None,
        }
    }

    /// Whether a camera is a falling camera between a spinning hole's
    /// horizons, or just outside the outer one (within
    /// [`crate::physics::kerr::FALLING_FRAME_BAND`] of r+): the ray march's
    /// `KERR_INSIDE` path, its photons from the metric's falling frame.
    pub fn camera_inside_spinning(&self, viewer: &Viewer) -> bool {
        self.camera_inside_radius(viewer).is_some()
    }

    /// The Boyer-Lindquist r (M) of such a camera; None for every other.
    pub fn camera_inside_radius(&self, viewer: &Viewer) -> Option<f64> {
        let Metric::Kerr(k) = &self.metric else {
            return None;
        };
        let r = k.radius_of(viewer.position);
        let band = (1.0 + crate::physics::kerr::FALLING_FRAME_BAND) * k.r_plus_m();
        // (ODS eyes each stand at their own r: outside r+ they keep the
        // exterior's frames; inside, validation refuses them.)
        let ods = viewer.ods && r > k.r_plus_m();
        (viewer.observer == ObserverKind::Falling && r < band && !ods).then_some(r)
    }

    /// The redshift g = nu_obs / nu_emit, seen from far away, of light from
    /// an emitter on a circular Keplerian orbit at `r` around the first hole,
    /// for a photon of angular momentum `lambda` about the disk's axis (per
    /// unit energy). With gravity off the emitter still turns: only the
    /// Doppler part remains (the GPU's straight path uses the same formula).
    /// Around a spinning hole: r^(3/4) sqrt(r^(3/2) - 3 r^(1/2) + 2a) /
    /// (r^(3/2) + a - lambda) in units of M (the prograde Keplerian emitter).
    pub fn emitter_g(&self, r: f64, lambda: f64) -> f64 {
        if let Metric::Kerr(k) = &self.metric {
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
        match &self.metric {
            Metric::Kerr(k) => k.horizon(),
            _ => hole.rs,
        }
    }

    /// The photon orbit's radius around `hole`: 1.5 rs (none with gravity off).
    pub fn photon_orbit(&self, hole: &Hole) -> Option<f64> {
        match &self.metric {
            Metric::Flat(_) => None,
            Metric::Kerr(k) => Some(k.photon_orbit()),
            _ => Some(1.5 * hole.rs),
        }
    }

    /// The circular photon orbit farthest out around `hole`: 1.5 rs, or a
    /// spinning hole's retrograde one (none with gravity off).
    pub fn outer_photon_orbit(&self, hole: &Hole) -> Option<f64> {
        match &self.metric {
            Metric::Flat(_) => None,
            Metric::Kerr(k) => Some(radii::photon_orbit(k.hole.rs, k.spin, false)),
            _ => Some(1.5 * hole.rs),
        }
    }

    /// The distance from the first hole's centre, in the disk's plane, of
    /// Boyer-Lindquist radius `r` (scene units): sqrt(r^2 + a^2) around a
    /// spinning hole, r itself otherwise.
    pub fn equatorial_distance(&self, r: f64) -> f64 {
        match &self.metric {
            Metric::Kerr(k) => fall::distance_of(r, 0.5 * k.spin * k.hole.rs, 0.0),
            _ => r,
        }
    }

    /// The innermost stable circular orbit around `hole`: 3 rs (none with
    /// gravity off).
    pub fn isco(&self, hole: &Hole) -> Option<f64> {
        match &self.metric {
            Metric::Flat(_) => None,
            Metric::Kerr(k) => Some(k.isco()),
            _ => Some(3.0 * hole.rs),
        }
    }
}

/// A straight line from `x0` along `v0`: the first horizon it enters, the
/// thin disk's annulus around the first hole, or the sky.
pub(crate) fn trace_straight(holes: &[Hole], disk: Option<&Disk>, x0: DVec3, v0: DVec3) -> Outcome {
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

    fn body(x: f64, rs: f64, spin: f64) -> Body {
        Body {
            hole: Hole {
                position: DVec3::new(x, 0.0, 0.0),
                rs,
            },
            spin,
        }
    }

    #[test]
    fn the_holes_and_gravity_pick_the_metric_and_gpu_path() {
        let one = Spacetime::new(&[body(0.0, 1.0, 0.0)], true, DVec3::Y);
        assert!(one.one_static_hole());
        assert_eq!(one.gpu_path(), GpuPath::ClosedForm);
        let two = Spacetime::new(&[body(-5.0, 1.0, 0.0), body(5.0, 1.0, 0.0)], true, DVec3::Y);
        assert_eq!(two.gpu_path(), GpuPath::Integrated);
        assert_eq!(two.holes().len(), 2);
        let flat = Spacetime::new(&[body(0.0, 1.0, 0.0)], false, DVec3::Y);
        assert_eq!(flat.gpu_path(), GpuPath::Straight);
        assert_eq!(flat.isco(&flat.holes()[0]), None);
        assert_eq!(one.isco(&one.holes()[0]), Some(3.0));
        assert_eq!(one.photon_orbit(&one.holes()[0]), Some(1.5));
        let spinning = Spacetime::new(&[body(0.0, 1.0, 0.5)], true, DVec3::new(0.0, 2.0, 0.0));
        assert_eq!(spinning.gpu_path(), GpuPath::Kerr);
        assert_eq!(spinning.spin(), 0.5);
        // A spinning hole's axis is the disk's, normalised; with gravity off
        // nothing spins.
        match spinning.metric() {
            Metric::Kerr(k) => assert_eq!(k.axis, DVec3::Y),
            m => panic!("{m:?}"),
        }
        let off = Spacetime::new(&[body(0.0, 1.0, 0.5)], false, DVec3::Y);
        assert_eq!((off.gpu_path(), off.spin()), (GpuPath::Straight, 0.0));
    }

    #[test]
    fn straight_rays_hit_what_line_geometry_says() {
        let flat = Spacetime::new(&[body(0.0, 1.0, 0.0)], false, DVec3::Y);
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
        let s = Spacetime::new(&[body(0.0, 1.0, 0.0)], true, DVec3::Y);
        // A photon with no angular momentum about the axis: the transverse
        // and gravitational shifts only, sqrt(1 - 1.5 rs / r).
        assert!((s.emitter_g(6.0, 0.0) - 0.75f64.sqrt()).abs() < 1e-15);
    }
}
