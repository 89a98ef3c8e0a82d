//! One pixel's light path as points, asked of the spacetime door: the
//! closed form of one hole, spinning or not (the non-rotating hole in the
//! spinning hole's form at a* = 0), integrated for several holes and the
//! `"flat"` mapping, a straight line with gravity off.

use glam::DVec3;

use super::{Metric, Spacetime, Viewer, trace_straight};
use crate::physics::observer::ObserverKind;
use crate::physics::{Disk, Hole, Outcome, TraceOptions, geodesic};

/// One pixel's backward light path as points (world), the camera's first,
/// and how it ends ([`Spacetime::light_path`]).
#[derive(Clone, Debug)]
pub struct LightPath {
    pub points: Vec<DVec3>,
    pub outcome: Outcome,
}

impl Spacetime {
    /// The backward light path of the pixel direction `d` (the camera
    /// observer's frame, as [`crate::camera::CameraFrame::pixel_ray`] gives
    /// it) from `viewer`'s place, as points (world), up to the thin `disk`,
    /// just outside a horizon, or `reach` (world units) from the first hole:
    /// one hole, spinning or not, in closed form (`samples` points even in
    /// Mino time, [`crate::physics::kerr::path`]); the `"flat"` mapping and
    /// several holes integrated (adaptive Dormand-Prince, tolerance 1e-12,
    /// a point per step); gravity off, a straight line of `samples` points.
    /// Refused, with the reason, for a camera inside a horizon (or in the
    /// falling frame's band of a spinning one) or a direction with no path.
    pub fn light_path(
        &self,
        disk: Option<&Disk>,
        viewer: &Viewer,
        d: DVec3,
        reach: f64,
        samples: usize,
    ) -> Result<LightPath, String> {
        let (x0, kind) = (viewer.position, viewer.observer);
        if let Some(h) = self
            .holes()
            .iter()
            .find(|h| (x0 - h.position).length() <= h.rs)
        {
            let r = (x0 - h.position).length();
            if !matches!(self.metric, Metric::Flat(_)) {
                return Err(format!(
                    "needs a camera outside the horizon; this one is {} rs from the centre of a hole of rs = {}",
                    crate::digits::apart(r / h.rs, 1.0),
                    h.rs
                ));
            }
        }
        // The non-rotating hole's closed form is the spinning hole's at a* =
        // 0, but for the "flat" mapping and a falling camera in the band
        // just outside the horizon (integrated from its rain-frame
        // direction instead, below).
        let closed = self
            .spinning_form()
            .filter(|f| kind != ObserverKind::Flat && !f.camera_inside_spinning(viewer));
        // (A ray through the centre, b = 0, has no closed form: integrated.)
        if let Some(Ok(path)) = closed.map(|f| f.light_path(disk, viewer, d, reach, samples)) {
            return Ok(path);
        }
        match &self.metric {
            Metric::Kerr(k) => {
                if self.camera_inside_spinning(viewer) {
                    return Err(
                        "needs a camera outside the horizon and its 5% band (the falling frame's)"
                            .into(),
                    );
                }
                let beta = self.observer(kind, x0).beta;
                let (dz, _) = crate::physics::kerr::to_zamo_frame(d.normalize(), beta);
                let (points, outcome) = k
                    .path(disk, x0, dz, reach, samples)
                    .ok_or("has no closed form along this direction (E = 0, a ray through the centre, or eta = 0 off the disk's plane)")?;
                Ok(LightPath { points, outcome })
            }
            Metric::Flat(holes) => Ok(straight_path(holes, disk, x0, d, reach, samples)),
            Metric::Schwarzschild(_) | Metric::Summed(_) => {
                let v0 = self.camera_observer(viewer).coordinate_direction(d);
                let opt = TraceOptions {
                    escape_radius: reach,
                    record_path: true,
                    ..TraceOptions::default()
                };
                let r = geodesic::trace(self.holes(), disk, x0, v0, &opt);
                let mut points = r.path;
                if let Outcome::Disk { position, .. } = r.outcome {
                    points.push(position);
                }
                Ok(LightPath {
                    points,
                    outcome: r.outcome,
                })
            }
        }
    }
}

/// Gravity off: the line from `x0` along `d` to where [`trace_straight`]
/// ends it (a horizon, the disk) or to `reach` from the first hole, as
/// `samples` points.
fn straight_path(
    holes: &[Hole],
    disk: Option<&Disk>,
    x0: DVec3,
    d: DVec3,
    reach: f64,
    samples: usize,
) -> LightPath {
    let d = d.normalize();
    let outcome = trace_straight(holes, disk, x0, d);
    let centre = holes.first().map_or(DVec3::ZERO, |h| h.position);
    // Along the line: where |x0 + t d - centre| = reach, or the end.
    let rel = x0 - centre;
    let b = rel.dot(d);
    let far = -b
        + (b * b - rel.length_squared() + reach * reach)
            .max(0.0)
            .sqrt();
    let length = match outcome {
        Outcome::Disk { position, .. } => (position - x0).length(),
        Outcome::Captured { hole } => holes.get(hole).map_or(0.0, |h| {
            let rel = x0 - h.position;
            let b = rel.dot(d);
            -b - (b * b - rel.length_squared() + h.rs * h.rs).max(0.0).sqrt()
        }),
        _ => far.max(0.0),
    };
    let n = samples.max(2);
    let points = (0..=n)
        .map(|i| x0 + d * (length * i as f64 / n as f64))
        .collect();
    LightPath { points, outcome }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::spacetime::Body;

    fn one(spin: f64, gravity: bool) -> Spacetime {
        let hole = Hole {
            position: DVec3::new(1.0, -0.5, 2.0),
            rs: 2.0,
        };
        Spacetime::new(&[Body { hole, spin }], gravity, DVec3::new(0.1, 1.0, 0.0))
    }

    fn viewer(kind: ObserverKind) -> Viewer {
        Viewer {
            position: DVec3::new(1.5, 6.0, -28.0),
            observer: kind,
            ods: false,
        }
    }

    fn disk(s: &Spacetime) -> Disk {
        Disk {
            normal: s.axis().normalize(),
            inner: 6.0,
            outer: 24.0,
        }
    }

    #[test]
    fn the_non_rotating_closed_form_path_ends_where_the_integrated_one_does() {
        let s = one(0.0, true);
        let disk = disk(&s);
        let mut seen = [0usize; 3];
        for kind in [
            ObserverKind::Static,
            ObserverKind::Falling,
            ObserverKind::Orbiting,
        ] {
            let v = viewer(kind);
            for (dx, dy) in [
                (0.0, 0.0),
                (0.15, 0.05),
                (-0.3, -0.1),
                (0.05, 0.2),
                (0.6, 0.3),
            ] {
                let toward = (s.holes()[0].position - v.position).normalize();
                let d = (toward + DVec3::new(dx, dy, 0.0)).normalize();
                let closed = s.light_path(Some(&disk), &v, d, 80.0, 500).expect("a path");
                let opt = TraceOptions {
                    escape_radius: 80.0,
                    ..TraceOptions::default()
                };
                let x = s.camera_observer(&v).coordinate_direction(d);
                let want = geodesic::trace(s.holes(), Some(&disk), v.position, x, &opt).outcome;
                let end = *closed.points.last().expect("points");
                assert!(
                    (closed.points[0] - v.position).length() < 1e-9,
                    "{kind:?} {d}: starts at {} not {}",
                    closed.points[0],
                    v.position
                );
                let r = (end - s.holes()[0].position).length();
                match (closed.outcome, want) {
                    (Outcome::Disk { position, .. }, Outcome::Disk { position: p2, .. }) => {
                        assert!(
                            (position - p2).length() < 1e-7,
                            "{kind:?} {d}: {position} vs {p2}"
                        );
                        assert!(
                            (end - p2).length() < 1e-7,
                            "{kind:?} {d}: ends at {end}, not {p2}"
                        );
                        seen[2] += 1;
                    }
                    (Outcome::Captured { .. }, Outcome::Captured { .. }) => {
                        // (At the horizon: a ray through the centre,
                        // integrated, ends just inside it.)
                        assert!(r <= 2.0 * 1.001 + 1e-9, "{kind:?} {d}: ends at r {r}");
                        seen[1] += 1;
                    }
                    (Outcome::Escaped { .. }, Outcome::Escaped { .. }) => {
                        assert!((r - 80.0).abs() < 1e-6, "{kind:?} {d}: ends at r {r}");
                        seen[0] += 1;
                    }
                    (a, b) => panic!("{kind:?} {d}: {a:?} vs {b:?}"),
                }
            }
        }
        assert!(seen.iter().all(|&n| n > 0), "every ending: {seen:?}");
    }

    #[test]
    fn a_path_without_gravity_is_a_straight_line_and_a_camera_inside_is_refused() {
        let s = one(0.0, false);
        let v = viewer(ObserverKind::Static);
        let d = DVec3::new(0.3, -0.2, 1.0).normalize();
        let path = s.light_path(None, &v, d, 50.0, 10).expect("a line");
        assert_eq!(path.points.len(), 11);
        for p in &path.points {
            let off = (*p - v.position) - (*p - v.position).dot(d) * d;
            assert!(off.length() < 1e-12);
        }
        let end = *path.points.last().expect("points");
        assert!(((end - s.holes()[0].position).length() - 50.0).abs() < 1e-9);
        for spin in [0.0, 0.7] {
            let inside = Viewer {
                position: s.holes()[0].position + DVec3::new(0.5, 0.2, 0.0),
                observer: ObserverKind::Falling,
                ods: false,
            };
            let e = one(spin, true)
                .light_path(None, &inside, d, 50.0, 10)
                .expect_err("inside the horizon");
            assert!(e.contains("outside the horizon"), "{e}");
        }
    }
}
