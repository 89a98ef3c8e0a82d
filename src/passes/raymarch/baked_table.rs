// The baked values of the ray march: the switch BAKED's constant_id
// (`first_id`: the variant's constants come before it), then one row each:
// the GLSL constant (its constant_id follows BAKED's, in this order), the parameter block's field
// it overwrites in the shader's copy `P` as GLSL names it, and the same
// field of `RaymarchParams` in Rust. build.rs writes the constants and
// `bake_params()` of shaders/include/baked.glsl from this table
// (`baked_values.glsl`), and src/passes/raymarch/baked.rs reads the
// values from a block with it: a baked field is one row here.
baked_values! {
    first_id: 15;
    BAKED_HOLE_X, "metric.holes[0].x", |p| p.metric.holes[0][0];
    BAKED_HOLE_Y, "metric.holes[0].y", |p| p.metric.holes[0][1];
    BAKED_HOLE_Z, "metric.holes[0].z", |p| p.metric.holes[0][2];
    BAKED_RS, "metric.holes[0].w", |p| p.metric.holes[0][3];
    BAKED_GRAVITY, "metric.gravity", |p| p.metric.gravity;
    BAKED_SPIN_HI, "metric.spin_hi", |p| p.metric.spin_hi;
    BAKED_SPIN_LO, "metric.spin_lo", |p| p.metric.spin_lo;
    BAKED_DISK_NORMAL_X, "disk.normal.x", |p| p.disk.normal[0];
    BAKED_DISK_NORMAL_Y, "disk.normal.y", |p| p.disk.normal[1];
    BAKED_DISK_NORMAL_Z, "disk.normal.z", |p| p.disk.normal[2];
    BAKED_DISK_E1_X, "disk.e1.x", |p| p.disk.e1[0];
    BAKED_DISK_E1_Y, "disk.e1.y", |p| p.disk.e1[1];
    BAKED_DISK_E1_Z, "disk.e1.z", |p| p.disk.e1[2];
    BAKED_DISK_E2_X, "disk.e2.x", |p| p.disk.e2[0];
    BAKED_DISK_E2_Y, "disk.e2.y", |p| p.disk.e2[1];
    BAKED_DISK_E2_Z, "disk.e2.z", |p| p.disk.e2[2];
    BAKED_DISK_STRUCTURE, "disk.structure", |p| p.disk.structure;
    BAKED_DISK_INNER, "disk.inner", |p| p.disk.inner;
    BAKED_DISK_OUTER, "disk.outer", |p| p.disk.outer;
    BAKED_DISK_BRIGHTNESS, "disk.brightness", |p| p.disk.brightness;
    BAKED_DISK_BEAMING, "disk.beaming", |p| p.disk.beaming;
    BAKED_DISK_PEAK_TEMPERATURE, "disk.peak_temperature", |p| p.disk.peak_temperature;
    BAKED_DISK_NT_PEAK, "disk.nt_peak", |p| p.disk.nt_peak;
    BAKED_DISK_DOPPLER, "disk.doppler", |p| p.disk.doppler;
    BAKED_DISK_REDSHIFT, "disk.redshift", |p| p.disk.redshift;
    BAKED_DISK_OPACITY, "disk.opacity", |p| p.disk.opacity;
    BAKED_DISK_SPEED, "disk.speed", |p| p.disk.speed;
    BAKED_DISK_PT_ROOTS_X, "disk.pt_roots.x", |p| p.disk.pt_roots[0];
    BAKED_DISK_PT_ROOTS_Y, "disk.pt_roots.y", |p| p.disk.pt_roots[1];
    BAKED_DISK_PT_ROOTS_Z, "disk.pt_roots.z", |p| p.disk.pt_roots[2];
    BAKED_DISK_PT_ROOTS_W, "disk.pt_roots.w", |p| p.disk.pt_roots[3];
    BAKED_DISK_PT_COEF_X, "disk.pt_coef.x", |p| p.disk.pt_coef[0];
    BAKED_DISK_PT_COEF_Y, "disk.pt_coef.y", |p| p.disk.pt_coef[1];
    BAKED_DISK_PT_COEF_Z, "disk.pt_coef.z", |p| p.disk.pt_coef[2];
    BAKED_DISK_PT_COEF_W, "disk.pt_coef.w", |p| p.disk.pt_coef[3];
    BAKED_VOLUME_HALF_HEIGHT, "volume.half_height", |p| p.volume.half_height;
    BAKED_VOLUME_FALLOFF_V, "volume.falloff_v", |p| p.volume.falloff_v;
    BAKED_VOLUME_FALLOFF_H, "volume.falloff_h", |p| p.volume.falloff_h;
    BAKED_VOLUME_NOISE_SCALE, "volume.noise_scale", |p| p.volume.noise_scale;
    BAKED_VOLUME_OCTAVES, "volume.octaves", |p| p.volume.octaves;
    BAKED_VOLUME_LIT, "volume.lit", |p| p.volume.lit;
    BAKED_SKY_BRIGHTNESS, "sky.brightness", |p| p.sky.brightness;
    BAKED_SKY_GALAXY, "sky.galaxy", |p| p.sky.galaxy;
    BAKED_SKY_ROW0_X, "sky.row0.x", |p| p.sky.row0[0];
    BAKED_SKY_ROW0_Y, "sky.row0.y", |p| p.sky.row0[1];
    BAKED_SKY_ROW0_Z, "sky.row0.z", |p| p.sky.row0[2];
    BAKED_SKY_STAR_FLUX, "sky.star_flux", |p| p.sky.star_flux;
    BAKED_SKY_ROW1_X, "sky.row1.x", |p| p.sky.row1[0];
    BAKED_SKY_ROW1_Y, "sky.row1.y", |p| p.sky.row1[1];
    BAKED_SKY_ROW1_Z, "sky.row1.z", |p| p.sky.row1[2];
    BAKED_SKY_SHIFT, "sky.shift", |p| p.sky.shift;
    BAKED_SKY_ROW2_X, "sky.row2.x", |p| p.sky.row2[0];
    BAKED_SKY_ROW2_Y, "sky.row2.y", |p| p.sky.row2[1];
    BAKED_SKY_ROW2_Z, "sky.row2.z", |p| p.sky.row2[2];
    BAKED_SKY_OTHER, "sky.other", |p| p.sky.other;
    BAKED_PLANE_POSITION_X, "plane.position.x", |p| p.plane.position[0];
    BAKED_PLANE_POSITION_Y, "plane.position.y", |p| p.plane.position[1];
    BAKED_PLANE_POSITION_Z, "plane.position.z", |p| p.plane.position[2];
    BAKED_PLANE_NORMAL_X, "plane.normal.x", |p| p.plane.normal[0];
    BAKED_PLANE_NORMAL_Y, "plane.normal.y", |p| p.plane.normal[1];
    BAKED_PLANE_NORMAL_Z, "plane.normal.z", |p| p.plane.normal[2];
    BAKED_PLANE_SPACING, "plane.spacing", |p| p.plane.spacing;
    BAKED_PLANE_AXIS_X, "plane.axis.x", |p| p.plane.axis[0];
    BAKED_PLANE_AXIS_Y, "plane.axis.y", |p| p.plane.axis[1];
    BAKED_PLANE_AXIS_Z, "plane.axis.z", |p| p.plane.axis[2];
    BAKED_PLANE_HALF_SIZE, "plane.half_size", |p| p.plane.half_size;
    // The sky's scale (the catalogue's grid: its level's arithmetic folds).
    BAKED_SKY_SCALE, "sky.scale", |p| p.sky.scale;
}
