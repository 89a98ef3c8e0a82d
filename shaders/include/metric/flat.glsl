// Gravity off: straight rays, traced in closed form (the holes still
// absorb). metric_trace() is this metric's path; the caller shades the disk
// it stops at.
#ifndef METRIC_FLAT_GLSL
#define METRIC_FLAT_GLSL

#include "params.glsl"
#include "metric/static_frame.glsl"
#include "variant.glsl"
#include "hit.glsl"
#include "disk.glsl"
#include "volume.glsl"

// The frame at a ray's origin and a disk point's radius (static_frame.glsl).
NON_ROTATING_METRIC(false)

// Gravity off: the ray is the line x + t d. It ends at the first horizon it
// enters (the holes still absorb), at the thin disk's plane inside the
// annulus, or at the sky in its own direction; the volumetric disk is
// gathered along the part of the line inside the slab, in chords of at most
// 16 samples (the step-by-step path's spacing), up to the horizon.
const bool METRIC_SHADES_DISK = false;
const bool METRIC_SPLITS_RARE = false;  // (no split build)

Hit metric_trace(vec3 x, vec3 d) {
    Hit hit = hit_start(OUT_ESCAPED, x, d);
    float t_h = 1e30;
    for (uint k = 0u; k < P.metric.hole_count; ++k) {
        vec3 rel = x - P.metric.holes[k].xyz;
        float rs = P.metric.holes[k].w;
        float b = dot(rel, d);
        float cc = dot(rel, rel) - rs * rs;
        float disc = b * b - cc;
        float t = -b - sqrt(max(disc, 0.0));
        if (cc < 0.0) t_h = 0.0;                              // inside a horizon
        else if (disc > 0.0 && t > 0.0) t_h = min(t_h, t);
    }
    vec3 c0 = P.metric.holes[0].xyz;
    vec3 N = P.disk.normal;
    float y0 = plane_dist(x), dn = dot(d, N);
    if (DISK_KIND == DISK_THIN) {
        float t_d = -y0 / dn;
        vec3 p = x + t_d * d;
        float rho = length(p - c0);
        if (t_d > 0.0 && t_d < t_h && rho >= P.disk.inner && rho <= P.disk.outer) {
            hit.outcome = OUT_DISK;
            hit.pos = p;
            hit.g = disk_redshift(p, x, d);
            hit.delay = t_d;  // (straight at c = 1: the distance)
            return hit;
        }
    } else if (DISK_KIND == DISK_VOLUME) {
        // Where |height| < H along the line, before any horizon.
        float H = P.volume.half_height;
        float ta = abs(dn) > 1e-9 ? (-H - y0) / dn : (abs(y0) < H ? 0.0 : 1e30);
        float tb = abs(dn) > 1e-9 ? (H - y0) / dn : (abs(y0) < H ? 1e30 : -1e30);
        float t0 = max(min(ta, tb), 0.0);
        // Not past the disk's outer edge: the farthest point of the line
        // within the outer radius of the hole.
        vec3 rel = x - c0;
        float s = dot(rel, d);
        float far = -s + sqrt(max(P.disk.outer * P.disk.outer - (dot(rel, rel) - s * s), 0.0));
        float t1 = min(min(max(ta, tb), t_h), far);
        float lambda = dot(cross(rel, -d), N);
        const float CHORD = 16.0 * VOLUME_DS;
        for (float t = t0; t < t1; t += CHORD) {
            volume_segment(x + t * d, x + min(t + CHORD, t1) * d, lambda, hit.glow, hit.trans);
            if (hit.trans < 0.003) break;
        }
        if (hit.trans < 0.003) {
            hit.outcome = OUT_CAPTURED;
            return hit;
        }
    }
    if (t_h < 1e29) hit.outcome = OUT_CAPTURED;
    return hit;
}

#endif
