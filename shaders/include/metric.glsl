// The spacetime seam of the ray march: exactly one metric is compiled into
// each build of raymarch.comp, chosen by a define that build.rs sets (one
// SPIR-V module per metric, src/shaders.rs `raymarch`). Each file of
// metric/ defines the same set:
//
//   Hit metric_trace(vec3 origin, vec3 dir)  the camera ray's path from an
//       origin along a unit coordinate direction, to a horizon, the disk or
//       the sky, with the disk's light gathered on the way (hit.glsl);
//   const bool METRIC_SHADES_DISK  metric_trace adds the thin disk's light
//       itself (else the caller shades an opaque disk at hit.pos);
//   const bool METRIC_SPLITS_RARE  in the split builds (raymarch.comp, a
//       CPU device): the trace pass takes the common paths only and flags
//       (hit.deferred) the rest, whose 2x2 quads the second pass redoes
//       whole (else the second pass adds the thin disk in front);
//   StaticFrame metric_static_frame(vec3 origin)  the frame at rest at any
//       origin that the observer's velocity is measured in (its radial
//       direction and lapse; static_frame.glsl), so each ray of a camera
//       can start from its own place;
//   float metric_disk_radius(vec3 p)  the radius (rs) of a disk point at
//       world point p (a spinning hole's Boyer-Lindquist r);
//   float metric_gas_g(float r, float lambda)  the shift, as the camera
//       sees it, of the volumetric gas's Keplerian orbit at radius r toward
//       a photon of angular momentum lambda (volume.glsl declares it);
//   float metric_emitter_lapse2(float r, float rs, float ir)  the square of
//       a disk emitter's lapse at radius r, its clock against infinity
//       (disk.glsl declares it: the colour's switches split g by it);
//   kerr_zamo_g (ray_state.glsl)  the g of light from rest at infinity as
//       the camera's frame sees it before its own Doppler factor, which the
//       ray march's sky shift reads: a spinning hole's metric_trace sets it
//       per pixel (1 / E), every other metric leaves it at 1.
//
// The disk, the volumetric gas and the sky take what metric_trace returns
// and know nothing of orbit planes.
#ifndef METRIC_GLSL
#define METRIC_GLSL

#if defined(METRIC_SCHWARZSCHILD)
#include "metric/schwarzschild.glsl"
#elif defined(METRIC_FLAT)
#include "metric/flat.glsl"
#elif defined(METRIC_SUMMED)
#include "metric/summed.glsl"
#elif defined(METRIC_KERR)
#include "metric/kerr.glsl"
#else
#error "build raymarch.comp with one of METRIC_SCHWARZSCHILD, METRIC_FLAT, METRIC_SUMMED, METRIC_KERR"
#endif

#endif
