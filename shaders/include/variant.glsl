// The ray march's specialisation constants (one pipeline per scene variant,
// src/passes/raymarch/mod.rs `Variant`, ids checked by tests/layout.rs).
#ifndef VARIANT_GLSL
#define VARIANT_GLSL

// Specialization constants (src/passes/raymarch/mod.rs, `Variant`): code a
// scene does not use is compiled out of its pipeline. On a CPU driver such as
// lavapipe every branch runs under a mask for every pixel, taken or not, so
// this is what keeps the cost to the code a scene uses. (The metric is
// chosen at build time instead, metric.glsl: one SPIR-V module each.)
// The disk kind (DISK_NONE, DISK_THIN, DISK_VOLUME).
layout(constant_id = 0) const int DISK_KIND = 1;
// The sky kind (SKY_BLACK, SKY_CHECKER, SKY_STARS, SKY_IMAGE, SKY_CATALOGUE).
layout(constant_id = 1) const int SKY_KIND = 2;
// The grid plane is drawn.
layout(constant_id = 2) const bool GRID_PLANE = false;
// The thin disk is seen as it was when its light left it (one hole).
layout(constant_id = 3) const bool LIGHT_DELAY = false;
// The thin disk has filaments and clumps (its `structure` key above 0).
layout(constant_id = 4) const bool THIN_STRUCTURE = false;
// Thin-disk crossings a ray may see (2 when the disk lets light through).
layout(constant_id = 5) const int THIN_CROSSINGS = 1;
// The volumetric disk glows as a blackbody at its shifted temperature (else
// the film's colour map).
layout(constant_id = 6) const bool VOLUME_BLACKBODY = false;
// Which part of the split ray march this pipeline runs (src/deferred.rs: a
// second pass deferred to the rare, expensive paths).
#define STAGE_ALL 0       // everything in one dispatch
#define STAGE_TRACE 1     // every pixel's common path; lists the rest
#define STAGE_DEFERRED 2  // the listed pixels (the thin disk; the rare paths)
layout(constant_id = 7) const int SPLIT_STAGE = STAGE_ALL;
// The observer moves through the static frame (orbiting, falling): the
// pixel directions are aberrated.
layout(constant_id = 8) const bool OBSERVER_MOVES = false;
// The thin disk's temperature follows Page and Thorne's relativistic flux
// (else the Newtonian profile).
layout(constant_id = 9) const bool PAGE_THORNE = false;
// How pixels become rays (camera.glsl), as src/camera `Projection`.
#define PROJ_PINHOLE 0
#define PROJ_EQUIRECT 1
#define PROJ_FISHEYE 2
layout(constant_id = 10) const int PROJECTION = PROJ_PINHOLE;
// A falling camera of one non-rotating hole: pixels become rays by the rain
// form (camera.glsl), which holds outside, at and inside the horizon, and
// the path starts from the camera's own point (lightpath.glsl, path_u).
layout(constant_id = 11) const bool RAIN_FORM = false;
// A falling camera between a spinning hole's horizons or just outside the
// outer one (within 5 % of r+, where the ZAMO's frame degenerates): its
// pixels are directions in the falling frame built from the metric
// (kerr/interior.glsl), and each path's azimuth and time run in their
// ingoing forms through r+.
layout(constant_id = 12) const bool KERR_INSIDE = false;
// The number of holes (at most MAX_HOLES): read_params (params.glsl) puts
// it in the parameters, so the loops over the holes run to a constant.
layout(constant_id = 13) const uint HOLE_COUNT = 1u;
// The polarized thin disk (polarization.glsl): off, the polarized view
// (Stokes I and ticks), or the Stokes AOV (GEODESIC_AOV builds).
#define POL_OFF 0
#define POL_VIEW 1
#define POL_STOKES 2
layout(constant_id = 14) const int POLARIZATION = POL_OFF;

#endif
