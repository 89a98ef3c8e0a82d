//! A scene's static parameters as specialisation constants
//! (shaders/include/baked.glsl): an offscreen render compiles them into its
//! ray march, where the driver folds them and no register holds them; the
//! window, whose panel changes them, reads them from the parameter block.
//! What changes from frame to frame (the camera, the observer, the disk's
//! turn) always comes from the block.

use super::params::RaymarchParams;

/// The baked values' table (baked_table.rs, which build.rs also reads to
/// write their GLSL): `BAKED_FIRST_ID` (the switch `BAKED`'s constant id),
/// `BAKED_NAMES` (the values' GLSL names, in `constant_id` order from
/// `BAKED_FIRST_ID + 1`), `BAKED_COUNT`, and `values`, each row's field of
/// a block.
macro_rules! baked_values {
    (first_id: $first:literal; $($name:ident, $glsl:literal, $rust:expr;)*) => {
        /// The switch `BAKED`'s constant id; the values follow it.
        pub const BAKED_FIRST_ID: u32 = $first;

        /// The GLSL names of the baked values, in `constant_id` order from
        /// `BAKED_FIRST_ID + 1` (tests/layout.rs checks them against every
        /// SPIR-V module).
        pub const BAKED_NAMES: [&str; BAKED_COUNT] = [$(stringify!($name)),*];

        /// How many values are baked.
        pub const BAKED_COUNT: usize = [$(stringify!($name)),*].len();

        /// Each row's value in `p`.
        fn values(p: &RaymarchParams) -> [f32; BAKED_COUNT] {
            [$(field(p, $rust)),*]
        }
    };
}

/// A row's field of `p` (the closure typed by this call).
fn field(p: &RaymarchParams, get: impl Fn(&RaymarchParams) -> f32) -> f32 {
    get(p)
}

include!("baked_table.rs");

/// The baked values of a scene: its parameter block's static part, bit for
/// bit as the block would carry it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Baked(pub [u32; BAKED_COUNT]);

impl Baked {
    /// The static part of `p` (a block built for the scene; its camera,
    /// observer and time are not read).
    pub fn of(p: &RaymarchParams) -> Baked {
        Baked(values(p).map(f32::to_bits))
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::passes::raymarch::FrameSpec;
    use crate::scene::Scene;

    fn baked(scene: &Scene, frame: &FrameSpec) -> Baked {
        Baked::of(&RaymarchParams::new(scene, &scene.spacetime(), frame))
    }

    /// Nothing baked moves with the camera, the frame or the time: a
    /// sequence (an orbit, a fall, the disk turning) builds its pipeline
    /// once, and the baked values are right in every frame.
    #[test]
    fn baked_values_are_the_same_in_every_frame_of_a_scene() {
        for name in ["default", "interstellar", "gargantua", "falling", "grid"] {
            let scene = Scene::load(name).unwrap();
            let first = baked(&scene, &FrameSpec::new(1, 1));
            let mut later = scene.clone();
            later.time = 12.5;
            later.camera.position = [3.0, -2.0, -9.0];
            later.camera.vfov_deg = 35.0;
            let frame = FrameSpec {
                jitter: (0.25, -0.25),
                ..FrameSpec::new(640, 360)
            };
            assert_eq!(first, baked(&later, &frame), "{name}");
        }
    }

    /// Every baked value is read from the block: a change of one scene key
    /// changes it.
    #[test]
    fn baked_values_follow_the_scene() {
        let scene = Scene::load("default").unwrap();
        let mut other = scene.clone();
        other.disk.inner_radius = 4.0;
        let frame = FrameSpec::new(1, 1);
        assert_ne!(baked(&scene, &frame), baked(&other, &frame));
    }

    /// `HOLE_COUNT` (a constant of every build, which read_params puts in
    /// place of the block's count) is the count the block carries.
    #[test]
    fn the_hole_count_constant_is_the_block_s() {
        for name in ["default", "binary", "no-gravity", "gargantua"] {
            let scene = Scene::load(name).unwrap();
            let spacetime = scene.spacetime();
            let block = RaymarchParams::new(&scene, &spacetime, &FrameSpec::new(1, 1));
            let variant = super::super::Variant::of(&scene, &spacetime, &block, false);
            assert_eq!(variant.holes, block.metric.hole_count, "{name}");
        }
    }
}
