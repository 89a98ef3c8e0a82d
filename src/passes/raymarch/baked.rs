//! A scene's static parameters as specialisation constants
//! (shaders/include/baked.glsl): an offscreen render compiles them into its
//! ray march, where the driver folds them and no register holds them; the
//! window, whose panel changes them, reads them from the parameter block.
//! What changes from frame to frame (the camera, the observer, the disk's
//! turn) always comes from the block.

use super::params::RaymarchParams;

/// The first baked constant's id (`BAKED`, then the values in
/// [`BAKED_NAMES`] order).
pub const BAKED_FIRST_ID: u32 = 14;

/// How many values are baked.
pub const BAKED_COUNT: usize = 70;

/// The GLSL names of the baked values, in `constant_id` order from
/// `BAKED_FIRST_ID + 1` (tests/layout.rs checks them against baked.glsl).
pub const BAKED_NAMES: [&str; BAKED_COUNT] = [
    "BAKED_HOLE_X",
    "BAKED_HOLE_Y",
    "BAKED_HOLE_Z",
    "BAKED_RS",
    "BAKED_GRAVITY",
    "BAKED_SPIN_HI",
    "BAKED_SPIN_LO",
    "BAKED_DISK_NORMAL_X",
    "BAKED_DISK_NORMAL_Y",
    "BAKED_DISK_NORMAL_Z",
    "BAKED_DISK_E1_X",
    "BAKED_DISK_E1_Y",
    "BAKED_DISK_E1_Z",
    "BAKED_DISK_E2_X",
    "BAKED_DISK_E2_Y",
    "BAKED_DISK_E2_Z",
    "BAKED_DISK_STRUCTURE",
    "BAKED_DISK_INNER",
    "BAKED_DISK_OUTER",
    "BAKED_DISK_BRIGHTNESS",
    "BAKED_DISK_BEAMING",
    "BAKED_DISK_PEAK_TEMPERATURE",
    "BAKED_DISK_NT_PEAK",
    "BAKED_DISK_DOPPLER",
    "BAKED_DISK_REDSHIFT",
    "BAKED_DISK_OPACITY",
    "BAKED_DISK_SPEED",
    "BAKED_DISK_PROFILE",
    "BAKED_DISK_PT_ROOTS_X",
    "BAKED_DISK_PT_ROOTS_Y",
    "BAKED_DISK_PT_ROOTS_Z",
    "BAKED_DISK_PT_ROOTS_W",
    "BAKED_DISK_PT_COEF_X",
    "BAKED_DISK_PT_COEF_Y",
    "BAKED_DISK_PT_COEF_Z",
    "BAKED_DISK_PT_COEF_W",
    "BAKED_VOLUME_HALF_HEIGHT",
    "BAKED_VOLUME_FALLOFF_V",
    "BAKED_VOLUME_FALLOFF_H",
    "BAKED_VOLUME_NOISE_SCALE",
    "BAKED_VOLUME_OCTAVES",
    "BAKED_VOLUME_LIT",
    "BAKED_VOLUME_BLACKBODY",
    "BAKED_SKY_BRIGHTNESS",
    "BAKED_SKY_GALAXY",
    "BAKED_SKY_ROW0_X",
    "BAKED_SKY_ROW0_Y",
    "BAKED_SKY_ROW0_Z",
    "BAKED_SKY_STAR_FLUX",
    "BAKED_SKY_ROW1_X",
    "BAKED_SKY_ROW1_Y",
    "BAKED_SKY_ROW1_Z",
    "BAKED_SKY_SHIFT",
    "BAKED_SKY_ROW2_X",
    "BAKED_SKY_ROW2_Y",
    "BAKED_SKY_ROW2_Z",
    "BAKED_SKY_OTHER",
    "BAKED_PLANE_POSITION_X",
    "BAKED_PLANE_POSITION_Y",
    "BAKED_PLANE_POSITION_Z",
    "BAKED_PLANE_ENABLED",
    "BAKED_PLANE_NORMAL_X",
    "BAKED_PLANE_NORMAL_Y",
    "BAKED_PLANE_NORMAL_Z",
    "BAKED_PLANE_SPACING",
    "BAKED_PLANE_AXIS_X",
    "BAKED_PLANE_AXIS_Y",
    "BAKED_PLANE_AXIS_Z",
    "BAKED_PLANE_HALF_SIZE",
    "BAKED_SKY_SCALE",
];

/// The baked values of a scene: its parameter block's static part, bit for
/// bit as the block would carry it.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Hash)]
pub struct Baked(pub [u32; BAKED_COUNT]);

impl Baked {
    /// The static part of `p` (a block built for the scene; its camera,
    /// observer and time are not read).
    pub fn of(p: &RaymarchParams) -> Baked {
        Baked(
            [
                p.metric.holes[0][0],
                p.metric.holes[0][1],
                p.metric.holes[0][2],
                p.metric.holes[0][3],
                p.metric.gravity,
                p.metric.spin_hi,
                p.metric.spin_lo,
                p.disk.normal[0],
                p.disk.normal[1],
                p.disk.normal[2],
                p.disk.e1[0],
                p.disk.e1[1],
                p.disk.e1[2],
                p.disk.e2[0],
                p.disk.e2[1],
                p.disk.e2[2],
                p.disk.structure,
                p.disk.inner,
                p.disk.outer,
                p.disk.brightness,
                p.disk.beaming,
                p.disk.peak_temperature,
                p.disk.nt_peak,
                p.disk.doppler,
                p.disk.redshift,
                p.disk.opacity,
                p.disk.speed,
                p.disk.profile,
                p.disk.pt_roots[0],
                p.disk.pt_roots[1],
                p.disk.pt_roots[2],
                p.disk.pt_roots[3],
                p.disk.pt_coef[0],
                p.disk.pt_coef[1],
                p.disk.pt_coef[2],
                p.disk.pt_coef[3],
                p.volume.half_height,
                p.volume.falloff_v,
                p.volume.falloff_h,
                p.volume.noise_scale,
                p.volume.octaves,
                p.volume.lit,
                p.volume.blackbody,
                p.sky.brightness,
                p.sky.galaxy,
                p.sky.row0[0],
                p.sky.row0[1],
                p.sky.row0[2],
                p.sky.star_flux,
                p.sky.row1[0],
                p.sky.row1[1],
                p.sky.row1[2],
                p.sky.shift,
                p.sky.row2[0],
                p.sky.row2[1],
                p.sky.row2[2],
                p.sky.other,
                p.plane.position[0],
                p.plane.position[1],
                p.plane.position[2],
                p.plane.enabled,
                p.plane.normal[0],
                p.plane.normal[1],
                p.plane.normal[2],
                p.plane.spacing,
                p.plane.axis[0],
                p.plane.axis[1],
                p.plane.axis[2],
                p.plane.half_size,
                p.sky.scale,
            ]
            .map(f32::to_bits),
        )
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
