// The static frame of the nearest hole at a point, shared by the metrics
// whose holes do not spin: the unit direction away from the hole and the
// lapse sqrt(1 - rs/r) (the radial squeeze of directions and the clock
// against infinity). Mirrors Observer::new in src/physics/observer.rs.
#ifndef STATIC_FRAME_GLSL
#define STATIC_FRAME_GLSL

#include "params.glsl"

struct StaticFrame {
    vec3 radial;  // unit, from the reference hole to the point
    float lapse;  // sqrt(1 - rs/r) (0 inside the horizon); 1 without gravity
    float fall2;  // rs / r, the square of a radial fall's speed from rest at
                  // infinity (the rain form, camera.glsl); 0 without gravity
};

// The frame at `x` of the hole nearest to it; with `gravity` false only
// the direction (lapse 1). The loop runs to HOLE_COUNT, a constant
// (params.glsl): with a count from the parameter block, a CPU driver ran
// it over all MAX_HOLES slots in every pixel and read `holes[nearest]`
// from a copy on the stack lane by lane; with one hole it folds away.
StaticFrame static_frame_at(vec3 x, bool gravity) {
    uint nearest = 0u;
    float best = 1e30;
    for (uint k = 0u; k < P.metric.hole_count; ++k) {
        float d = length(x - P.metric.holes[k].xyz);
        if (d < best) {
            best = d;
            nearest = k;
        }
    }
    vec4 hole = P.metric.holes[nearest];
    vec3 rel = x - hole.xyz;
    float r = length(rel);
    StaticFrame f;
    f.radial = rel / r;
    f.lapse = gravity ? sqrt(max(1.0 - hole.w / r, 0.0)) : 1.0;
    f.fall2 = gravity ? hole.w / r : 0.0;
    return f;
}

// metric_static_frame, metric_disk_radius, metric_gas_g and
// metric_emitter_lapse2 (metric.glsl) of a metric whose holes do not spin;
// `gravity` false: directions only (the gas's shift stays the first hole's
// Keplerian one, as the thin disk's, and so does the emitter's lapse,
// 1 - rs / r, which the disk's colour switches split g by). Expanded after
// disk.glsl.
#define NON_ROTATING_METRIC(gravity) \
    StaticFrame metric_static_frame(vec3 origin) { \
        return static_frame_at(origin, gravity); \
    } \
    float metric_disk_radius(vec3 p) { \
        return length(p - P.metric.holes[0].xyz); \
    } \
    float metric_gas_g(float r, float lambda) { \
        float rs = P.metric.holes[0].w; \
        return emitter_g(1.0 - 1.5 * rs / r, keplerian_omega(rs, r), lambda, 1e-4) * observer_g; \
    } \
    float metric_emitter_lapse2(float r, float rs, float ir) { \
        return 1.0 - rs * ir; \
    }

#endif
