//! Photons of energy near zero: inside a spinning hole's ergoregion a
//! camera's pixels run through E = 0, the edge between the photons that
//! come from the sky (E > 0) and those that cannot (E < 0), and near it
//! lambda = L / E and eta = Q / E^2 run to 1e5 and 1e10. Their paths must
//! stay as exact as any other: each such pixel of the geodesic AOV against
//! the Kerr-Schild integration (src/physics/kerr/schild.rs, which takes the
//! photon's momentum as it is and never divides by E), in both builds
//! (64-bit roots where the device has them, and `BLACKHOLE_NO_F64=1`).
//! Resolvent-cubic roots once drew such pixels (E = 1e-5 to 1e-4) as the
//! shadow where the disk is.

mod common;

use blackhole::physics::kerr::{self, KerrDisk, KerrOutcome, frame::Constants, schild};

#[test]
fn photons_of_energy_near_zero_in_the_ergoregion_keep_their_disk() {
    // Boyer-Lindquist r = 0.74 rs of a* = 0.99, just above the disk, the
    // view past the hole the way it turns: 121 pixels of 320 x 180 have
    // |E| < 1e-3, the smallest 8e-7.
    let (spin, (w, h)) = (0.99, (320u32, 180u32));
    let toml = format!(
        "[[black_hole]]\nspin = {spin}\n[camera]\nposition = [0.0, 0.1, -0.885]\n\
         look_at = [-1.0, -0.3, -2.0]\nvfov_deg = 60.0\nobserver = \"zamo\"\n\
         [disk]\ninner_radius = {}\nouter_radius = 12.0\n",
        kerr::r_isco(spin) / 2.0
    );
    for env in [&[][..], &[("BLACKHOLE_NO_F64", "1")][..]] {
        let (scene, gpu) = common::render_aov_with(&toml, w, h, env);
        let frame = scene.camera.frame();
        let disk = Some(KerrDisk {
            inner: scene.disk.inner_radius,
            outer: scene.disk.outer_radius,
        });
        let (mut pixels, mut smallest, mut on_disk) = (0, f64::INFINITY, 0);
        let (mut worst_r, mut worst_g, mut worst_dir) = (0.0f64, 0.0f64, 0.0f64);
        for y in 0..h {
            for x in 0..w {
                let d = frame.ray_dir(x, y, w, h).expect("a pinhole ray");
                let energy = Constants::of(2.0 * frame.position, d, spin).energy;
                if energy.abs() >= 1e-3 {
                    continue;
                }
                pixels += 1;
                smallest = smallest.min(energy.abs());
                let p = gpu.get_pixel(x, y).0.map(f64::from);
                let reference = schild::trace_schild(frame.position, d, spin, disk);
                let what = format!(
                    "{env:?} pixel ({x}, {y}), E = {energy:.2e}: GPU {p:?}, Kerr-Schild {reference:?}"
                );
                match reference {
                    KerrOutcome::Disk { r, g, .. } => {
                        assert_eq!(p[3], 2.0, "{what}");
                        on_disk += 1;
                        worst_r = worst_r.max((p[0] - r).abs());
                        worst_g = worst_g.max((p[2] - g).abs());
                    }
                    KerrOutcome::Escaped(v) => {
                        assert_eq!(p[3], 0.0, "{what}");
                        let u = glam::DVec3::new(p[0], p[1], p[2]);
                        worst_dir = worst_dir.max(2.0 * (0.5 * (u - v).length()).min(1.0).asin());
                    }
                    KerrOutcome::Captured => assert_eq!(p[3], 1.0, "{what}"),
                }
            }
        }
        println!(
            "{env:?}: {pixels} pixels of |E| < 1e-3 (smallest {smallest:.1e}), {on_disk} on the disk: radius within {worst_r:.1e} rs, g within {worst_g:.1e}, escapes within {worst_dir:.1e} rad"
        );
        assert!(
            pixels >= 100 && smallest < 1e-5 && on_disk >= 50,
            "the frame holds such photons"
        );
        assert!(worst_r <= 2e-4 && worst_g <= 1e-5 && worst_dir <= 1e-5);
    }
}
