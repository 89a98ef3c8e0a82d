#version 460
// Ray march: one invocation per pixel. Each camera ray follows the light-path
// equation of geodesic.glsl until it falls into a horizon, hits the thin disk,
// escapes to the sky, or runs out of its step budget. Writes linear HDR.

layout(local_size_x = 8, local_size_y = 8) in;

#include "params.glsl"
#include "geodesic.glsl"

layout(binding = 0, rgba16f) uniform writeonly image2D out_hdr;

#define OUT_ESCAPED 0
#define OUT_CAPTURED 1
#define OUT_DISK 2
#define OUT_NO_STEPS 3

const float PI = 3.14159265358979;

struct Hit {
    int outcome;
    vec3 pos;   // disk crossing point
    vec3 dir;   // final direction (escaped)
};

// Signed height above the disk plane.
float plane_dist(vec3 x) {
    return dot(x - P.holes[0].xyz, P.disk_normal.xyz);
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

Hit trace(vec3 x, vec3 v) {
    Hit hit;
    hit.outcome = OUT_NO_STEPS;
    hit.pos = vec3(0.0);
    hit.dir = v;
    float tol = P.integ.x;
    float r_esc = P.integ.y;
    bool gravity = P.integ.z > 0.5;
    bool thin = int(P.disk_normal.w) == DISK_THIN;
    vec3 c0 = P.holes[0].xyz;

    vec3 a = gravity ? accel(x, v) : vec3(0.0);
    float h = 0.05 * max(length(x - c0), 1.0);
    uint budget = P.counts.w;
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

        if (thin) {
            float d0 = plane_dist(x), d1 = plane_dist(xn);
            if ((d0 < 0.0) != (d1 < 0.0) || d1 == 0.0) {
                vec3 p = plane_crossing(x, v, xn, vn, h);
                float rho = length(p - c0);
                if (rho >= P.disk.x && rho <= P.disk.y) {
                    hit.outcome = OUT_DISK;
                    hit.pos = p;
                    return hit;
                }
            }
        }

        // Horizons and escape.
        float rmin = 1e30;
        for (uint k = 0u; k < P.counts.x; ++k) {
            float r = length(xn - P.holes[k].xyz);
            if (r < P.holes[k].w) {
                hit.outcome = OUT_CAPTURED;
                return hit;
            }
            rmin = min(rmin, r);
        }
        if (rmin > r_esc && dot(xn - c0, vn) > 0.0) {
            hit.outcome = OUT_ESCAPED;
            hit.dir = normalize(vn);
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

vec3 sky_color(vec3 d) {
    int kind = int(P.sky.x);
    if (kind == SKY_CHECKER) {
        float n = P.sky.y;
        float phi = atan(d.z, d.x);
        float theta = acos(clamp(d.y, -1.0, 1.0));
        float u = (phi / (2.0 * PI) + 0.5) * n;
        float w = theta / PI * (0.5 * n);
        bool odd = ((int(floor(u)) + int(floor(w))) & 1) == 1;
        vec3 c = odd ? vec3(0.85, 0.85, 0.9) : vec3(0.1, 0.14, 0.28);
        return c * P.sky.z;
    }
    return vec3(0.0);
}

// A simple radial colour for the thin disk: hot white-blue inside, orange
// outside, brightness falling with radius.
vec3 disk_color(vec3 p) {
    float rho = length(p - P.holes[0].xyz);
    float t = clamp((rho - P.disk.x) / max(P.disk.y - P.disk.x, 1e-6), 0.0, 1.0);
    vec3 inner = vec3(1.0, 0.92, 0.8);
    vec3 outer = vec3(1.0, 0.38, 0.08);
    float falloff = pow(max(P.disk.x, 1.0) / max(rho, 1e-3), 1.5);
    return mix(inner, outer, t) * (3.0 * falloff * P.disk.z);
}

void main() {
    uvec2 px = gl_GlobalInvocationID.xy;
    uint w = P.counts.y, hgt = P.counts.z;
    if (px.x >= w || px.y >= hgt) return;

    // Binding camera convention (DESIGN.md section 2).
    float tan_half = P.cam_pos.w, aspect = P.cam_right.w;
    float sx = (2.0 * (float(px.x) + 0.5) / float(w) - 1.0) * tan_half * aspect;
    float sy = (1.0 - 2.0 * (float(px.y) + 0.5) / float(hgt)) * tan_half;
    vec3 dir = normalize(P.cam_fwd.xyz + sx * P.cam_right.xyz + sy * P.cam_up.xyz);

    Hit hit = trace(P.cam_pos.xyz, dir);
    vec3 color = vec3(0.0);
    if (hit.outcome == OUT_ESCAPED) color = sky_color(hit.dir);
    else if (hit.outcome == OUT_DISK) color = disk_color(hit.pos);
    imageStore(out_hdr, ivec2(px), vec4(color, 1.0));
}
