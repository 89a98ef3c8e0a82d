// The ray march's descriptor bindings, declared once: every file of the ray
// march binds its resource by these names, and src/passes/raymarch/mod.rs
// (`BINDINGS`) lists the same names in the same order, with their kinds;
// tests/layout.rs checks the numbers here, that table, and the bindings in
// each SPIR-V module of the ray march against each other.
#ifndef BINDINGS_GLSL
#define BINDINGS_GLSL

#define RM_OUT_IMAGE 0          // storage image: the HDR radiance, or the geodesic AOV
#define RM_PARAMS 1             // storage buffer: the parameter block (params.glsl)
#define RM_DISK_LUT 2           // sampled: the blackbody colour table (blackbody.glsl)
#define RM_SKY 3                // sampled: the image sky (sky.glsl)
#define RM_DISK_NOISE 4         // sampled: the thin disk's noise (disk.glsl)
#define RM_VOLUME_NOISE 5       // sampled: the volumetric disk's noise (volume.glsl)
#define RM_DEFERRED_LIST 6      // storage buffer: the split's list of deferred pixels
#define RM_DEFERRED_DISPATCH 7  // storage buffer: the deferred pass's indirect dispatch

#endif
