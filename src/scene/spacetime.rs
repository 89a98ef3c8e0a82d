//! The scene's spacetime: [`Scene::spacetime`] builds the one door to the
//! physics ([`crate::spacetime::Spacetime`]) from the scene's holes, its
//! gravity switch and its disk's axis, and [`Camera::viewer`] says where a
//! camera stands in the terms the door's questions take.

use glam::DVec3;

use super::{BlackHole, Camera, Scene, Stereo};
use crate::physics::Disk;
use crate::physics::Hole;
use crate::physics::observer::Observer;
use crate::spacetime::{Body, Emission, LightPath, Spacetime, Viewer};

/// What a scene's spacetime is built from: the holes, gravity, the disk's
/// normal. The renderer keeps its spacetime while this stays the same.
pub type SpacetimeKey = (Vec<BlackHole>, bool, [f64; 3]);

impl Scene {
    /// The polarized disk's emitter model from `[polarization]` (the field
    /// normalised; validated non-zero).
    pub fn emission(&self) -> Emission {
        let p = &self.polarization;
        Emission {
            field: DVec3::from(p.field).normalize(),
            spectral_index: p.spectral_index,
            emissivity_index: p.emissivity_index,
            fraction: p.fraction,
        }
    }

    /// What the spacetime is built from ([`SpacetimeKey`]).
    pub fn spacetime_key(&self) -> SpacetimeKey {
        (
            self.black_holes.clone(),
            self.physics.gravity,
            self.disk.normal,
        )
    }

    /// The spacetime of the scene's holes (with their spins), gravity on or
    /// off, and the disk's normal as its axis.
    pub fn spacetime(&self) -> Spacetime {
        let bodies: Vec<Body> = self
            .black_holes
            .iter()
            .map(|h| Body {
                hole: Hole {
                    position: DVec3::from(h.position),
                    rs: h.rs,
                },
                spin: h.spin,
            })
            .collect();
        Spacetime::new(&bodies, self.physics.gravity, DVec3::from(self.disk.normal))
    }

    /// The first hole's rs and spin a* as written (1 and 0 without a hole),
    /// for what the scene resolves before any spacetime exists (the disk's
    /// `"isco"`) and the photon-path plot.
    pub fn first_hole(&self) -> (f64, f64) {
        self.black_holes
            .first()
            .map_or((1.0, 0.0), |h| (h.rs, h.spin))
    }

    /// The thin disk as the f64 light paths take it (None for another kind:
    /// they describe thin-disk hits).
    pub fn thin_disk(&self) -> Option<Disk> {
        (self.disk.kind == super::DiskKind::Thin).then(|| Disk {
            normal: DVec3::from(self.disk.normal),
            inner: self.disk.inner_radius,
            outer: self.disk.outer_radius,
        })
    }

    /// The camera's observer (the pixel-to-ray mapping and its redshift).
    pub fn observer(&self) -> Observer {
        self.spacetime().camera_observer(&self.camera.viewer())
    }

    /// The backward light path through the centre of pixel (`col`, `row`)
    /// of a `width` x `height` image, as points (world) and how it ends,
    /// asked of the spacetime door ([`Spacetime::light_path`]): `samples`
    /// points, up to the thin disk, the horizon, or `reach` (world units)
    /// from the first hole (by default twice the camera's distance, at
    /// least 20 rs). Bad sizes, a pixel off the image or without a ray, and
    /// a camera the door cannot trace from are refused by name.
    pub fn light_path(
        &self,
        (col, row): (u32, u32),
        (width, height): (u32, u32),
        samples: usize,
        reach: Option<f64>,
    ) -> crate::Result<LightPath> {
        let usage = |m: String| crate::Error::Usage(m);
        if width == 0 || height == 0 || width > 65_536 || height > 65_536 {
            return Err(usage(format!(
                "light_path {width}x{height}: the image must be 1 to 65536 pixels a side"
            )));
        }
        if col >= width || row >= height {
            return Err(usage(format!(
                "light_path pixel ({col}, {row}): outside the {width}x{height} image"
            )));
        }
        if !(2..=1_000_000).contains(&samples) {
            return Err(usage(format!(
                "light_path samples = {samples}: must be in [2, 1000000]"
            )));
        }
        self.check_image_size(width, height)?;
        let ray = self
            .camera
            .frame()
            .pixel_ray(col, row, width, height, (0.0, 0.0))
            .ok_or_else(|| {
                usage(format!(
                    "light_path pixel ({col}, {row}): no ray there (outside the fisheye's circle)"
                ))
            })?;
        let (centre, rs) = self
            .black_holes
            .first()
            .map_or((DVec3::ZERO, 1.0), |h| (DVec3::from(h.position), h.rs));
        let reach = match reach {
            Some(r) if r.is_finite() && r > 0.0 && r <= 1e12 => r,
            Some(r) => {
                return Err(usage(format!(
                    "light_path reach = {r}: must be a distance in (0, 1e12]"
                )));
            }
            None => (2.0 * (ray.origin - centre).length()).max(20.0 * rs),
        };
        let disk = self.thin_disk();
        let viewer = Viewer {
            position: ray.origin,
            ..self.camera.viewer()
        };
        self.spacetime()
            .light_path(disk.as_ref(), &viewer, ray.dir, reach, samples)
            .map_err(|why| usage(format!("light_path {why}")))
    }
}

impl Camera {
    /// Where the camera stands, as the spacetime's questions take it.
    pub fn viewer(&self) -> Viewer {
        Viewer {
            position: DVec3::from(self.position),
            observer: self.observer,
            ods: self.stereo == Stereo::Ods,
        }
    }
}

#[cfg(test)]
mod tests {
    use crate::scene::Scene;
    use crate::spacetime::GpuPath;

    #[test]
    fn a_scene_picks_its_spacetime_and_gpu_path() {
        let one = Scene::default().spacetime();
        assert!(one.one_static_hole());
        assert_eq!(one.gpu_path(), GpuPath::ClosedForm);
        let two = Scene::load("binary").expect("preset").spacetime();
        assert_eq!(two.gpu_path(), GpuPath::Integrated);
        assert_eq!(two.holes().len(), 2);
        let flat = Scene::load("no-gravity").expect("preset").spacetime();
        assert_eq!(flat.gpu_path(), GpuPath::Straight);
        let spinning = Scene::load("gargantua").expect("preset").spacetime();
        assert_eq!(spinning.gpu_path(), GpuPath::Kerr);
    }

    #[test]
    fn a_non_rotating_hole_has_a_spinning_form_at_spin_zero_with_the_same_observers() {
        use crate::physics::observer::ObserverKind;
        use glam::DVec3;
        let one = Scene::default().spacetime();
        let form = one.spinning_form().expect("one non-rotating hole");
        assert_eq!(form.gpu_path(), GpuPath::Kerr);
        assert_eq!(form.spin(), 0.0);
        let hole = one.holes()[0];
        assert!((form.horizon_radius(&hole) - one.horizon_radius(&hole)).abs() < 1e-15);
        assert!((form.isco(&hole).unwrap_or(0.0) - one.isco(&hole).unwrap_or(1.0)).abs() < 1e-12);
        for preset in ["binary", "no-gravity", "gargantua"] {
            let s = Scene::load(preset).expect("preset").spacetime();
            assert!(s.spinning_form().is_none(), "{preset}");
        }
        // The observers' velocities through the static (= ZAMO) frame agree,
        // an orbiting one off the disk's plane on its great circle too.
        for kind in [
            ObserverKind::Static,
            ObserverKind::Falling,
            ObserverKind::Orbiting,
        ] {
            for at in [DVec3::new(0.0, 9.0, -3.0), DVec3::new(4.0, 0.0, -3.0)] {
                let (a, b) = (one.observer(kind, at).beta, form.observer(kind, at).beta);
                assert!((a - b).length() < 1e-12, "{kind:?} at {at}: {a} vs {b}");
            }
        }
    }
}
