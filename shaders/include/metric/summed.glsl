// Several holes: their pulls summed (an approximation) and integrated
// step by step (geodesic.glsl), with the disk plane's crossings located on
// each step and the bending left beyond the escape radius. metric_trace() is
// this metric's path; the caller shades the disk it stops at.
#ifndef METRIC_SUMMED_GLSL
#define METRIC_SUMMED_GLSL

#include "params.glsl"
#include "metric/static_frame.glsl"
#include "variant.glsl"
#include "geodesic.glsl"
#include "hit.glsl"
#include "disk.glsl"
#include "volume.glsl"

// The frame at a ray's origin and a disk point's radius (static_frame.glsl).
NON_ROTATING_METRIC(true)

// The bending a ray still gets beyond the escape radius, to first order in rs
// (integrating the perpendicular acceleration 1.5 rs b^3 / r^5 along the
// straight continuation): delta = rs / (2b) (2 - s (2 s^2 + 3 b^2) / R^3),
// with b the distance of the line from the hole and s = x . v along it.
vec3 asymptotic_direction(vec3 x, vec3 v) {
    vec3 d = normalize(v);
    vec3 bend = vec3(0.0);
    for (uint i = 0u; i < P.metric.hole_count; ++i) {
        vec3 rel = x - P.metric.holes[i].xyz;
        float s = dot(rel, d);
        vec3 perp = rel - s * d;
        float b = length(perp);
        float R = length(rel);
        if (b < 1e-6) continue;
        float delta = P.metric.holes[i].w / (2.0 * b) * (2.0 - s * (2.0 * s * s + 3.0 * b * b) / (R * R * R));
        bend -= delta * perp / b;
    }
    return normalize(d + bend);
}

// Cubic Hermite position between two states, t in [0, 1].
vec3 hermite(vec3 x0, vec3 v0, vec3 x1, vec3 v1, float h, float t) {
    float t2 = t * t, t3 = t2 * t;
    return (2.0 * t3 - 3.0 * t2 + 1.0) * x0 + (t3 - 2.0 * t2 + t) * h * v0
         + (-2.0 * t3 + 3.0 * t2) * x1 + (t3 - t2) * h * v1;
}

// The disk-plane crossing inside a step, located by secant iterations on the
// Hermite interpolant.
vec3 plane_crossing(vec3 x0, vec3 v0, vec3 x1, vec3 v1, float h) {
    float ta = 0.0, tb = 1.0;
    float da = plane_dist(x0), db = plane_dist(x1);
    vec3 p = x1;
    for (int i = 0; i < 6; ++i) {
        float t = clamp(ta + (tb - ta) * da / (da - db), 0.0, 1.0);
        p = hermite(x0, v0, x1, v1, h, t);
        float d = plane_dist(p);
        if (abs(d) < 1e-6) break;
        if ((d < 0.0) == (da < 0.0)) { ta = t; da = d; } else { tb = t; db = d; }
    }
    return p;
}

const bool METRIC_SHADES_DISK = false;
const bool METRIC_SPLITS_RARE = false;  // (no split build)

Hit metric_trace(vec3 x, vec3 v) {
    Hit hit = hit_start(OUT_NO_STEPS, vec3(0.0), v);
    bool vol = volumetric();
    float tol = P.integrator.tolerance;
    float r_esc = P.integrator.escape_radius;
    bool gravity = P.metric.gravity > 0.5;
    bool thin = DISK_KIND == DISK_THIN;
    vec3 c0 = P.metric.holes[0].xyz;

    vec3 a = gravity ? accel(x, v) : vec3(0.0);
    float h = 0.05 * max(length(x - c0), 1.0);
    uint budget = P.integrator.steps;
    for (uint i = 0u; i < budget; ++i) {
        vec3 xn, vn, an;
        float err = 0.0;
        if (gravity) {
            err = dopri_step(x, v, a, h, tol, xn, vn, an);
            if (err > 1.0) {
                h *= clamp(0.9 * pow(err, -0.2), 0.2, 1.0);
                continue;
            }
        } else {
            xn = x + h * v; vn = v; an = vec3(0.0);
        }

        if (vol) {
            // lambda from the (one-hole) conserved quantities; approximate for several.
            vec3 dd = x - c0;
            vec3 hv = cross(dd, v);
            float rr = length(dd);
            float vinf = sqrt(max(dot(v, v) - (gravity ? P.metric.holes[0].w * dot(hv, hv) / (rr * rr * rr) : 0.0), 1e-20));
            float lambda = dot(cross(dd, -v), P.disk.normal) / vinf;
            volume_segment(x, xn, lambda, hit.glow, hit.trans);
            if (hit.trans < 0.003) {
                hit.outcome = OUT_CAPTURED;
                return hit;
            }
        }
        if (thin) {
            float d0 = plane_dist(x), d1 = plane_dist(xn);
            if ((d0 < 0.0) != (d1 < 0.0) || d1 == 0.0) {
                vec3 p = plane_crossing(x, v, xn, vn, h);
                // A crossing inside a horizon (a hole in the disk's plane)
                // comes after the ray fell in.
                for (uint k = 0u; k < P.metric.hole_count; ++k) {
                    if (length(p - P.metric.holes[k].xyz) < P.metric.holes[k].w) {
                        hit.outcome = OUT_CAPTURED;
                        return hit;
                    }
                }
                float rho = length(p - c0);
                if (rho >= P.disk.inner && rho <= P.disk.outer) {
                    hit.outcome = OUT_DISK;
                    hit.pos = p;
                    // lambda and v_inf are conserved: any consistent state will do.
                    hit.g = disk_redshift(p, xn, vn);
                    return hit;
                }
            }
        }

        // Horizons and escape.
        float rmin = 1e30;
        for (uint k = 0u; k < P.metric.hole_count; ++k) {
            float r = length(xn - P.metric.holes[k].xyz);
            if (r < P.metric.holes[k].w) {
                hit.outcome = OUT_CAPTURED;
                return hit;
            }
            rmin = min(rmin, r);
        }
        if (rmin > r_esc && dot(xn - c0, vn) > 0.0) {
            hit.outcome = OUT_ESCAPED;
            hit.dir = gravity ? asymptotic_direction(xn, vn) : normalize(vn);
            hit.pos = xn;
            return hit;
        }

        x = xn; v = vn; a = an;
        float grow = gravity ? clamp(0.9 * pow(max(err, 1e-10), -0.2), 1.0, 5.0) : 2.0;
        // Never step further than half the distance to the nearest hole, so a
        // step cannot jump over a horizon or cross the disk plane twice.
        h = min(h * grow, 0.5 * rmin);
    }
    return hit;
}

#endif
