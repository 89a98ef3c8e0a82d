//! Scenes: the TOML schema ([`schema`]), loading and presets ([`load`]),
//! validation with messages that name the key, the value and the line
//! ([`validate`]), and camera animation ([`animation`]).

pub mod animation;
mod frames;
pub mod keys;
pub mod load;
mod locate;
pub mod polarization;
mod refusal;
mod rule;
pub mod schema;
mod spacetime;
mod validate;

pub use crate::spacetime::FALLING_MIN_R;
pub use animation::{Animation, CameraPath, Keyframe};
pub use frames::MAX_SEQUENCE_FRAMES;
pub use load::{PRESETS, preset_names};
pub use polarization::{Brightness, Colormap, Polarization, PolarizedView};
pub use schema::*;
pub use spacetime::SpacetimeKey;

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn default_preset_equals_the_defaults_of_omitted_keys() {
        let parsed = Scene::builtin_default().expect("default preset parses");
        assert_eq!(parsed, Scene::default());
        assert_eq!(
            Scene::from_toml("", "empty").expect("empty parses"),
            Scene::default()
        );
    }

    #[test]
    fn every_preset_round_trips_through_toml() {
        for (name, _, _) in PRESETS {
            let scene = Scene::load(name).expect("preset loads");
            let text = scene.to_toml().expect("serializes");
            let back = Scene::from_toml(&text, "saved").expect("reads back");
            assert_eq!(back, scene, "{name}");
        }
    }

    #[test]
    fn check_names_the_key_of_an_impossible_edit() {
        let mut scene = Scene::default();
        scene.disk.outer_radius = 1.0;
        let e = scene.check().unwrap_err().to_string();
        assert!(e.contains("disk.outer_radius = 1"), "{e}");
    }

    #[test]
    fn negative_rs_names_key_value_and_line() {
        let src =
            "[camera]\nvfov_deg = 50.0\n\n[[black_hole]]\nposition = [0.0, 0.0, 0.0]\nrs = -1.0\n";
        let e = Scene::from_toml(src, "s.toml").unwrap_err().to_string();
        assert_eq!(
            e,
            "s.toml:6: black_hole[0].rs = -1: must be a finite number > 0, from 1e-9 to 1e9"
        );
    }

    #[test]
    fn second_hole_error_points_at_its_own_line() {
        let src =
            "[[black_hole]]\nrs = 1.0\n[[black_hole]]\nposition = [5.0, 0.0, 0.0]\nrs = 0.0\n";
        let e = Scene::from_toml(src, "s.toml").unwrap_err().to_string();
        assert!(e.starts_with("s.toml:5: black_hole[1].rs = 0"), "{e}");
    }

    #[test]
    fn unknown_key_is_rejected_with_its_line() {
        let src = "[disk]\ninner_radius = 3.0\nouter_radus = 12.0\n";
        let e = Scene::from_toml(src, "s.toml").unwrap_err().to_string();
        assert!(
            e.starts_with("s.toml:3: unknown field `outer_radus`"),
            "{e}"
        );
        assert!(!e.contains('\n'), "one line: {e}");
    }

    #[test]
    fn wrong_type_names_the_line_and_text() {
        let src = "[camera]\nvfov_deg = \"wide\"\n";
        let e = Scene::from_toml(src, "s.toml").unwrap_err().to_string();
        assert!(e.starts_with("s.toml:2: "), "{e}");
        assert!(e.contains("vfov_deg = \"wide\""), "{e}");
    }

    #[test]
    fn impossible_values_are_rejected() {
        let cases = [
            (
                "[disk]\ninner_radius = 12.0\nouter_radius = 3.0\n",
                "disk.outer_radius",
            ),
            ("[disk]\nnormal = [0.0, 0.0, 0.0]\n", "disk.normal"),
            ("[camera]\nvfov_deg = 180.0\n", "camera.vfov_deg"),
            ("[camera]\nvfov_deg = nan\n", "camera.vfov_deg"),
            ("[quality]\nsteps = 0\n", "quality.steps"),
            ("[camera]\nposition = [0.0, 0.0, 0.5]\n", "camera.position"),
            (
                "[camera]\nup = [0.0, 0.0, 1.0]\nposition = [0.0, 0.0, -10.0]\n",
                "camera.up",
            ),
            ("[[black_hole]]\nrs = inf\n", "black_hole[0].rs"),
        ];
        for (src, key) in cases {
            let e = Scene::from_toml(src, "s.toml").unwrap_err().to_string();
            assert!(e.contains(key), "{src:?} -> {e}");
            assert!(e.starts_with("s.toml:"), "{e}");
        }
    }

    /// `inner_radius` omitted is `"isco"`, as the built-in default scene
    /// writes it: the spin's ISCO (Bardeen, Press & Teukolsky: 1.2370 M at
    /// a* = 0.998, 8.9944 M at -0.998; 3 rs at 0), and a number stays.
    #[test]
    fn an_omitted_inner_radius_is_the_spins_isco() {
        for (src, want) in [
            ("[[black_hole]]\nspin = 0.998\n", 0.5 * 1.2370),
            ("[[black_hole]]\nspin = -0.998\n", 0.5 * 8.9944),
            ("", 3.0),
            (
                "[[black_hole]]\nspin = 0.998\n[disk]\ninner_radius = 2.5\n",
                2.5,
            ),
        ] {
            let r = Scene::from_toml(src, "s.toml").unwrap().disk.inner_radius;
            assert!((r - want).abs() < 1e-4, "{src:?}: {r}");
        }
    }

    #[test]
    fn camera_convention_matches_design() {
        let f = Camera::default().frame();
        // Looking toward +z from -z with +y up: +x is to the screen's right.
        assert!(f.right.x > 0.99);
        assert!(f.forward.z > 0.99);
        assert!(f.up.y > 0.99);
        // Top-left pixel points up and left, the centre straight ahead.
        let d = f.ray_dir(0, 0, 4, 2).expect("a pinhole ray");
        assert!(d.x < 0.0 && d.y > f.forward.y);
        let c = f.ray_dir(1, 0, 3, 1).expect("a pinhole ray");
        assert!((c - f.forward).length() < 1e-12);
    }

    /// The volumetric disk's inner edge is held outside the photon orbit of
    /// the scene's own hole: 1.5 rs without spin, the prograde orbit (0.78
    /// rs at a* = 0.9) around a spinning one.
    #[test]
    fn a_volumetric_disk_may_reach_a_spinning_holes_photon_orbit() {
        let scene = |spin: f64, inner: f64| {
            Scene::from_toml(
                &format!(
                    "[[black_hole]]\nspin = {spin}\n[disk]\nkind = \"volumetric\"\ninner_radius = {inner}\n"
                ),
                "t.toml",
            )
        };
        let e = scene(0.0, 1.2).unwrap_err().to_string();
        assert!(e.contains("1.5 rs = 1.5"), "{e}");
        assert!(scene(0.9, 1.2).is_ok());
        let e = scene(0.9, 0.7).unwrap_err().to_string();
        assert!(e.contains("prograde photon orbit, 0.7"), "{e}");
    }
}
