// A scene's static parameters as specialisation constants
// (src/passes/raymarch/baked.rs, ids checked by tests/layout.rs).
// An offscreen render compiles them into its ray march (BAKED), where the
// driver folds them: a hole at the origin, a disk normal along y, a switch
// that is off take their products by 0 and 1 and their branches away, and
// no register holds them across the shader (a CPU driver spills what it
// cannot keep: about a quarter of the trace pass's instructions were
// moves to and from the stack). The window, whose panel changes them
// between frames, reads them from the parameter block (BAKED false). What
// changes from frame to frame (the camera, the observer, the disk's
// turn) always comes from the block.
#ifndef BAKED_GLSL
#define BAKED_GLSL

layout(constant_id = 14) const bool BAKED = false;
layout(constant_id = 15) const float BAKED_HOLE_X = 0.0;
layout(constant_id = 16) const float BAKED_HOLE_Y = 0.0;
layout(constant_id = 17) const float BAKED_HOLE_Z = 0.0;
layout(constant_id = 18) const float BAKED_RS = 0.0;
layout(constant_id = 19) const float BAKED_GRAVITY = 0.0;
layout(constant_id = 20) const float BAKED_SPIN_HI = 0.0;
layout(constant_id = 21) const float BAKED_SPIN_LO = 0.0;
layout(constant_id = 22) const float BAKED_DISK_NORMAL_X = 0.0;
layout(constant_id = 23) const float BAKED_DISK_NORMAL_Y = 0.0;
layout(constant_id = 24) const float BAKED_DISK_NORMAL_Z = 0.0;
layout(constant_id = 25) const float BAKED_DISK_E1_X = 0.0;
layout(constant_id = 26) const float BAKED_DISK_E1_Y = 0.0;
layout(constant_id = 27) const float BAKED_DISK_E1_Z = 0.0;
layout(constant_id = 28) const float BAKED_DISK_E2_X = 0.0;
layout(constant_id = 29) const float BAKED_DISK_E2_Y = 0.0;
layout(constant_id = 30) const float BAKED_DISK_E2_Z = 0.0;
layout(constant_id = 31) const float BAKED_DISK_STRUCTURE = 0.0;
layout(constant_id = 32) const float BAKED_DISK_INNER = 0.0;
layout(constant_id = 33) const float BAKED_DISK_OUTER = 0.0;
layout(constant_id = 34) const float BAKED_DISK_BRIGHTNESS = 0.0;
layout(constant_id = 35) const float BAKED_DISK_BEAMING = 0.0;
layout(constant_id = 36) const float BAKED_DISK_PEAK_TEMPERATURE = 0.0;
layout(constant_id = 37) const float BAKED_DISK_NT_PEAK = 0.0;
layout(constant_id = 38) const float BAKED_DISK_DOPPLER = 0.0;
layout(constant_id = 39) const float BAKED_DISK_REDSHIFT = 0.0;
layout(constant_id = 40) const float BAKED_DISK_OPACITY = 0.0;
layout(constant_id = 41) const float BAKED_DISK_SPEED = 0.0;
layout(constant_id = 42) const float BAKED_DISK_PROFILE = 0.0;
layout(constant_id = 43) const float BAKED_DISK_PT_ROOTS_X = 0.0;
layout(constant_id = 44) const float BAKED_DISK_PT_ROOTS_Y = 0.0;
layout(constant_id = 45) const float BAKED_DISK_PT_ROOTS_Z = 0.0;
layout(constant_id = 46) const float BAKED_DISK_PT_ROOTS_W = 0.0;
layout(constant_id = 47) const float BAKED_DISK_PT_COEF_X = 0.0;
layout(constant_id = 48) const float BAKED_DISK_PT_COEF_Y = 0.0;
layout(constant_id = 49) const float BAKED_DISK_PT_COEF_Z = 0.0;
layout(constant_id = 50) const float BAKED_DISK_PT_COEF_W = 0.0;
layout(constant_id = 51) const float BAKED_VOLUME_HALF_HEIGHT = 0.0;
layout(constant_id = 52) const float BAKED_VOLUME_FALLOFF_V = 0.0;
layout(constant_id = 53) const float BAKED_VOLUME_FALLOFF_H = 0.0;
layout(constant_id = 54) const float BAKED_VOLUME_NOISE_SCALE = 0.0;
layout(constant_id = 55) const float BAKED_VOLUME_OCTAVES = 0.0;
layout(constant_id = 56) const float BAKED_VOLUME_LIT = 0.0;
layout(constant_id = 57) const float BAKED_VOLUME_BLACKBODY = 0.0;
layout(constant_id = 58) const float BAKED_SKY_BRIGHTNESS = 0.0;
layout(constant_id = 59) const float BAKED_SKY_GALAXY = 0.0;
layout(constant_id = 60) const float BAKED_SKY_ROW0_X = 0.0;
layout(constant_id = 61) const float BAKED_SKY_ROW0_Y = 0.0;
layout(constant_id = 62) const float BAKED_SKY_ROW0_Z = 0.0;
layout(constant_id = 63) const float BAKED_SKY_STAR_FLUX = 0.0;
layout(constant_id = 64) const float BAKED_SKY_ROW1_X = 0.0;
layout(constant_id = 65) const float BAKED_SKY_ROW1_Y = 0.0;
layout(constant_id = 66) const float BAKED_SKY_ROW1_Z = 0.0;
layout(constant_id = 67) const float BAKED_SKY_SHIFT = 0.0;
layout(constant_id = 68) const float BAKED_SKY_ROW2_X = 0.0;
layout(constant_id = 69) const float BAKED_SKY_ROW2_Y = 0.0;
layout(constant_id = 70) const float BAKED_SKY_ROW2_Z = 0.0;
layout(constant_id = 71) const float BAKED_SKY_OTHER = 0.0;
layout(constant_id = 72) const float BAKED_PLANE_POSITION_X = 0.0;
layout(constant_id = 73) const float BAKED_PLANE_POSITION_Y = 0.0;
layout(constant_id = 74) const float BAKED_PLANE_POSITION_Z = 0.0;
layout(constant_id = 75) const float BAKED_PLANE_ENABLED = 0.0;
layout(constant_id = 76) const float BAKED_PLANE_NORMAL_X = 0.0;
layout(constant_id = 77) const float BAKED_PLANE_NORMAL_Y = 0.0;
layout(constant_id = 78) const float BAKED_PLANE_NORMAL_Z = 0.0;
layout(constant_id = 79) const float BAKED_PLANE_SPACING = 0.0;
layout(constant_id = 80) const float BAKED_PLANE_AXIS_X = 0.0;
layout(constant_id = 81) const float BAKED_PLANE_AXIS_Y = 0.0;
layout(constant_id = 82) const float BAKED_PLANE_AXIS_Z = 0.0;
layout(constant_id = 83) const float BAKED_PLANE_HALF_SIZE = 0.0;
// The sky's scale (the catalogue's grid: its level's arithmetic folds).
layout(constant_id = 84) const float BAKED_SKY_SCALE = 0.0;

// Overwrites the block's copy with the baked values (a no-op unless BAKED).
void bake_params() {
    if (!BAKED) return;
    P.metric.holes[0].x = BAKED_HOLE_X;
    P.metric.holes[0].y = BAKED_HOLE_Y;
    P.metric.holes[0].z = BAKED_HOLE_Z;
    P.metric.holes[0].w = BAKED_RS;
    P.metric.gravity = BAKED_GRAVITY;
    P.metric.spin_hi = BAKED_SPIN_HI;
    P.metric.spin_lo = BAKED_SPIN_LO;
    P.disk.normal.x = BAKED_DISK_NORMAL_X;
    P.disk.normal.y = BAKED_DISK_NORMAL_Y;
    P.disk.normal.z = BAKED_DISK_NORMAL_Z;
    P.disk.e1.x = BAKED_DISK_E1_X;
    P.disk.e1.y = BAKED_DISK_E1_Y;
    P.disk.e1.z = BAKED_DISK_E1_Z;
    P.disk.e2.x = BAKED_DISK_E2_X;
    P.disk.e2.y = BAKED_DISK_E2_Y;
    P.disk.e2.z = BAKED_DISK_E2_Z;
    P.disk.structure = BAKED_DISK_STRUCTURE;
    P.disk.inner = BAKED_DISK_INNER;
    P.disk.outer = BAKED_DISK_OUTER;
    P.disk.brightness = BAKED_DISK_BRIGHTNESS;
    P.disk.beaming = BAKED_DISK_BEAMING;
    P.disk.peak_temperature = BAKED_DISK_PEAK_TEMPERATURE;
    P.disk.nt_peak = BAKED_DISK_NT_PEAK;
    P.disk.doppler = BAKED_DISK_DOPPLER;
    P.disk.redshift = BAKED_DISK_REDSHIFT;
    P.disk.opacity = BAKED_DISK_OPACITY;
    P.disk.speed = BAKED_DISK_SPEED;
    P.disk.profile = BAKED_DISK_PROFILE;
    P.disk.pt_roots.x = BAKED_DISK_PT_ROOTS_X;
    P.disk.pt_roots.y = BAKED_DISK_PT_ROOTS_Y;
    P.disk.pt_roots.z = BAKED_DISK_PT_ROOTS_Z;
    P.disk.pt_roots.w = BAKED_DISK_PT_ROOTS_W;
    P.disk.pt_coef.x = BAKED_DISK_PT_COEF_X;
    P.disk.pt_coef.y = BAKED_DISK_PT_COEF_Y;
    P.disk.pt_coef.z = BAKED_DISK_PT_COEF_Z;
    P.disk.pt_coef.w = BAKED_DISK_PT_COEF_W;
    P.volume.half_height = BAKED_VOLUME_HALF_HEIGHT;
    P.volume.falloff_v = BAKED_VOLUME_FALLOFF_V;
    P.volume.falloff_h = BAKED_VOLUME_FALLOFF_H;
    P.volume.noise_scale = BAKED_VOLUME_NOISE_SCALE;
    P.volume.octaves = BAKED_VOLUME_OCTAVES;
    P.volume.lit = BAKED_VOLUME_LIT;
    P.volume.blackbody = BAKED_VOLUME_BLACKBODY;
    P.sky.brightness = BAKED_SKY_BRIGHTNESS;
    P.sky.galaxy = BAKED_SKY_GALAXY;
    P.sky.row0.x = BAKED_SKY_ROW0_X;
    P.sky.row0.y = BAKED_SKY_ROW0_Y;
    P.sky.row0.z = BAKED_SKY_ROW0_Z;
    P.sky.star_flux = BAKED_SKY_STAR_FLUX;
    P.sky.row1.x = BAKED_SKY_ROW1_X;
    P.sky.row1.y = BAKED_SKY_ROW1_Y;
    P.sky.row1.z = BAKED_SKY_ROW1_Z;
    P.sky.shift = BAKED_SKY_SHIFT;
    P.sky.row2.x = BAKED_SKY_ROW2_X;
    P.sky.row2.y = BAKED_SKY_ROW2_Y;
    P.sky.row2.z = BAKED_SKY_ROW2_Z;
    P.sky.other = BAKED_SKY_OTHER;
    P.plane.position.x = BAKED_PLANE_POSITION_X;
    P.plane.position.y = BAKED_PLANE_POSITION_Y;
    P.plane.position.z = BAKED_PLANE_POSITION_Z;
    P.plane.enabled = BAKED_PLANE_ENABLED;
    P.plane.normal.x = BAKED_PLANE_NORMAL_X;
    P.plane.normal.y = BAKED_PLANE_NORMAL_Y;
    P.plane.normal.z = BAKED_PLANE_NORMAL_Z;
    P.plane.spacing = BAKED_PLANE_SPACING;
    P.plane.axis.x = BAKED_PLANE_AXIS_X;
    P.plane.axis.y = BAKED_PLANE_AXIS_Y;
    P.plane.axis.z = BAKED_PLANE_AXIS_Z;
    P.plane.half_size = BAKED_PLANE_HALF_SIZE;
    P.sky.scale = BAKED_SKY_SCALE;
}

#endif
