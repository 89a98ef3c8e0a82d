//! The deferred pass: the ray march's rare, expensive paths traced again in
//! a second dispatch, over a list of the pixels that need them.
//!
//! On a CPU driver (lavapipe) every branch of a shader runs for every pixel
//! of a SIMD group, taken or not, so code that few pixels need costs all of
//! them. Split, the ray march runs a trace pass over every pixel with that
//! code compiled out, which lists the pixels that need it, and a deferred
//! pass dispatched indirectly over the list with the whole shader:
//!
//! - one non-rotating hole with a thin disk defers the disk: the trace pass
//!   shades every pixel's sky and lists the pixels whose path crosses the
//!   disk's annulus; the deferred pass (`raymarch disk`) adds the disk's
//!   light in front;
//! - one spinning hole defers its rare paths (any disk): the trace pass
//!   carries the common ones (`shaders/include/kerr/precision.glsl`,
//!   `KERR_COMMON_ONLY`) and lists the 2x2 quads where a path needs the
//!   rest; the deferred pass (`raymarch rare`) redoes those quads whole.
//!
//! Listed pixels pay for their path twice, so the split pays only where the
//! deferred share of the frame is small: [`pays`] estimates it on the CPU
//! from a coarse grid of the frame's rays. A GPU already skips the code in
//! the SIMD groups that do not need it, so only a CPU device splits
//! ([`device_splits`]). This module decides; `passes/raymarch` records the
//! two dispatches and the list between them; the shader's stages are
//! `SPLIT_STAGE` of `shaders/include/variant.glsl`.

use ash::vk;
use glam::DVec3;

use crate::physics::Outcome;
use crate::scene::Scene;
use crate::spacetime::{GpuPath, Metric, Spacetime};
use crate::vk::DeviceInfo;

/// The largest share of the pixels crossing the thin disk at which the split
/// ray march pays. Measured on lavapipe at 1280x720 (frame ms, split against
/// one dispatch, by the share of disk pixels): falling 4 % 57 / 68, edge-on
/// 13 % 50 / 58, default 23 % 55 / 60, top-down 49 % 67 / 61, doppler 60 %
/// 80 / 62; the difference crosses zero near a third.
pub const MAX_DISK_SHARE: f64 = 0.3;

/// The largest share of the pixels whose paths the spinning hole's trace
/// pass defers at which its split ray march pays (the deferred 2x2 quads
/// cost the whole shader again, about twice the trace pass's per pixel).
pub const MAX_DEFERRED_SHARE: f64 = 0.3;

/// Whether a device can split the ray march, and gains by it: a CPU device
/// with quad and ballot operations in compute shaders (the trace pass lists
/// whole quads a SIMD group at a time).
pub fn device_splits(info: &DeviceInfo, quads: bool) -> bool {
    quads && info.ballot_compute && info.kind == vk::PhysicalDeviceType::CPU
}

/// Whether a ray march on `path` has a deferred pass at all: one
/// non-rotating hole with a thin disk, or one spinning hole.
pub fn applies(path: GpuPath, thin_disk: bool) -> bool {
    match path {
        GpuPath::ClosedForm => thin_disk,
        GpuPath::Kerr => true,
        GpuPath::Straight | GpuPath::Integrated => false,
    }
}

/// Whether splitting the ray march pays for this frame: the share of a 16 x
/// 9 grid of the frame's rays, traced in closed form on the CPU (about 0.1
/// ms), that cross the thin disk's annulus (one non-rotating hole) is below
/// [`MAX_DISK_SHARE`], or that the spinning hole's trace pass would defer
/// ([`crate::spacetime::SpinningHole::defers`]) is below
/// [`MAX_DEFERRED_SHARE`].
pub fn pays(scene: &Scene, spacetime: &Spacetime, width: u32, height: u32) -> bool {
    let disk = scene.thin_disk();
    let thin = disk.as_ref();
    let frame = scene.camera.frame();
    let viewer = scene.camera.viewer();
    let observer = spacetime.camera_observer(&viewer);
    // The share of a grid's rays for which `counts` holds.
    let share = |counts: &dyn Fn(DVec3, DVec3) -> bool| {
        let (cols, rows) = (16u32, 9u32);
        let mut n = 0;
        for row in 0..rows {
            for col in 0..cols {
                // The pixel at the centre of each cell of the grid.
                let x = ((2 * col + 1) * width / (2 * cols)).min(width - 1);
                let y = ((2 * row + 1) * height / (2 * rows)).min(height - 1);
                let Some(ray) = frame.pixel_ray(x, y, width, height, (0.0, 0.0)) else {
                    continue;
                };
                if counts(ray.origin, observer.coordinate_direction(ray.dir)) {
                    n += 1;
                }
            }
        }
        f64::from(n) / f64::from(cols * rows)
    };
    match spacetime.metric() {
        Metric::Kerr(_) if spacetime.camera_inside_spinning(&viewer) => false,
        Metric::Kerr(hole) => share(&|x0, d| hole.defers(thin, x0, d)) < MAX_DEFERRED_SHARE,
        Metric::Schwarzschild(_) if thin.is_some() => {
            let on_disk = |x0, d| {
                let outcome = spacetime.trace(thin, x0, d, &Default::default());
                matches!(outcome, Outcome::Disk { .. })
            };
            share(&on_disk) < MAX_DISK_SHARE
        }
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn pays_at_720p(scene: &Scene) -> bool {
        pays(scene, &scene.spacetime(), 1280, 720)
    }

    /// The presets' shares of disk pixels at 1280x720 (the geodesic AOV):
    /// falling 4 %, edge-on 13 %, default 23 %, top-down 49 %, doppler 60 %.
    #[test]
    fn the_split_is_taken_where_the_disk_fills_little_of_the_view() {
        let pays = |name: &str| pays_at_720p(&Scene::load(name).unwrap());
        for name in ["falling", "edge-on", "default"] {
            assert!(pays(name), "{name}");
        }
        for name in [
            "top-down",
            "doppler",
            "interstellar",
            "no-gravity",
            "binary",
        ] {
            assert!(!pays(name), "{name}");
        }
    }

    /// The spinning hole splits where its trace pass defers few paths (the
    /// presets, the default view spun up), not where the shadow fills the
    /// view (measured at 1280x720 on lavapipe: deferred share 0.33, split
    /// 582 to 651 ms a frame against 613 to 617 in one dispatch; 0.27, 518
    /// to 527 against 664 to 669; the default view at a* = 0.9, 0.02).
    #[test]
    fn the_spinning_hole_splits_where_few_paths_are_deferred() {
        let spun = |toml: &str| Scene::from_toml(toml, "test.toml").unwrap();
        for name in ["gargantua", "kerr-doppler"] {
            assert!(pays_at_720p(&Scene::load(name).unwrap()), "{name}");
        }
        assert!(pays_at_720p(&spun("[[black_hole]]\nspin = 0.9\n")));
        let close = "[[black_hole]]\nspin = 0.9\n[camera]\nposition = [0.0, 0.4, -3.0]\n";
        assert!(!pays_at_720p(&spun(close)));
    }

    #[test]
    fn only_the_closed_forms_defer() {
        assert!(applies(GpuPath::ClosedForm, true));
        assert!(!applies(GpuPath::ClosedForm, false));
        assert!(applies(GpuPath::Kerr, false));
        assert!(!applies(GpuPath::Integrated, true));
        assert!(!applies(GpuPath::Straight, true));
    }
}
