// The spinning hole's precision and split switches (metric/kerr.glsl's
// parts all include this first): which paths the split's trace pass defers,
// the 32- or 64-bit per-ray constants (`kreal`), the Newton turns on the
// quartic's roots, and the 64-bit escape of the geodesic AOV.
#ifndef KERR_PRECISION_GLSL
#define KERR_PRECISION_GLSL

#include "variant.glsl"

// Loops stay loops: unrolled and inlined at every call, the kernels of
// include/kerr/ make a shader that the driver takes minutes to compile.
#extension GL_EXT_control_flow_attributes : require

// The split ray march (raymarch.comp, on a CPU device, which runs every
// branch for every pixel, taken or not): its trace pass carries the common
// paths only, and leaves the rest (a polar motion that never crosses the
// equator, the radial case 4, and I_phi anywhere but on a case-2 path whose
// turning point lies outside the horizon: in most views the shadow's
// pixels whose path meets the disk first) to the second pass, which redoes
// their 2x2 quads with the whole of this file.
const bool METRIC_SPLITS_RARE = true;
const bool KERR_COMMON_ONLY = SPLIT_STAGE == STAGE_TRACE;
// The trace pass runs the build with 32-bit roots (passes/raymarch), exact
// away from the shadow's edge; a path whose roots r3 and r4 lie within a
// tenth of r4 of each other (near the photon orbits' double root, where
// their f32 difference loses its digits) goes to the second pass too.
#ifdef KERR_F32_ROOTS
#define KERR_NEAR_EDGE(rad) ((rad).kcase == 2 && (rad).r43 < 0.1 * (rad).r4)
#else
#define KERR_NEAR_EDGE(rad) false
#endif

// The turns of Newton's method that polish the quartic's roots
// (kerr_radial): on the cube roots of the Cardano estimate, then on the
// resolvent cubic. In 32 bits most estimates are already within a few
// units of the last place, but not all: with two turns on the resolvent a
// path at the top edge of gargantua's view (640x360) went astray and drew a
// star the one-dispatch image (64-bit roots) does not have; three match it
// (the Cardano cube roots need none). In 64 bits the estimates' 32-bit
// digits need doubling twice.
#ifdef KERR_F32_ROOTS
#define kreal float
#define kvec2 vec2
#define kvec3 vec3
#define kvec4 vec4
const int KERR_CBRT_TURNS = 0, KERR_RESOLVENT_TURNS = 3;
#else
#define kreal double
#define kvec2 dvec2
#define kvec3 dvec3
#define kvec4 dvec4
const int KERR_CBRT_TURNS = 3, KERR_RESOLVENT_TURNS = 4;
#endif

// The geodesic AOV (the renderer's exact record of each path) takes an
// escaping path's I_phi and Mino time in 64 bits as well (below: from a
// camera near the horizon their 32-bit forms cancel, up to 1e-4 rad off at
// a* = 0.998 inside the ergoregion). The image keeps the 32-bit forms: the
// largest error seen is a quarter of a pixel of a 3840x2160 view of 50
// degrees, and the 64 bits would cost a CPU driver, which runs every
// branch, 70 % of the frame.
#if defined(GEODESIC_AOV) && !defined(KERR_F32_ROOTS)
#define KERR_ESCAPE64
#endif

#endif
