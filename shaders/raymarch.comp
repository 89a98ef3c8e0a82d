#version 460
// Ray march: one invocation per pixel. Each camera ray follows the light-path
// equation of geodesic.glsl until it falls into a horizon, hits the thin disk,
// escapes to the sky, or runs out of its step budget. Writes linear HDR.

layout(local_size_x = 8, local_size_y = 8) in;

// One hole with gravity on: the plane (Binet) integrator; otherwise the
// general Cartesian one. A specialization constant, so the unused path is
// compiled out of each pipeline.
layout(constant_id = 0) const bool ONE_HOLE = false;
// The volumetric disk, likewise compiled in only where the scene has one:
// its code, even when skipped, costs lavapipe a factor of three.
layout(constant_id = 1) const bool VOLUME = false;

#include "params.glsl"
#include "geodesic.glsl"

#ifdef GEODESIC_AOV
// The geodesic AOV (the geodesic AOV table in the README): where each ray went.
layout(binding = 0, rgba32f) uniform writeonly image2D out_img;
#else
layout(binding = 0, rgba16f) uniform writeonly image2D out_img;
#endif
// Linear sRGB colour of luminance 1 per blackbody temperature, log-spaced
// from LUT_MIN_K to LUT_MAX_K (src/physics/blackbody.rs).
layout(binding = 2) uniform sampler2D disk_lut;

// Luminance-1 linear sRGB colour of a blackbody at t kelvin.
vec3 blackbody(float t) {
    float u = (log2(max(t, 1.0)) - log2(LUT_MIN_K)) / (log2(LUT_MAX_K) - log2(LUT_MIN_K));
    return textureLod(disk_lut, vec2(clamp(u, 0.0, 1.0), 0.5), 0.0).rgb;
}

// The image sky's panorama with mips (or the colour table, unused, when the
// sky is not an image).
layout(binding = 3) uniform sampler2D sky_tex;

#include "sky.glsl"

// Light of the thin disk at radius r whose light reaches us shifted by g_full
// (the conventions in the README, "Physics"): Novikov-Thorne temperature T(r), observed temperature
// g T coloured by the blackbody table, observed bolometric intensity g^4 times
// the emitted T^4. The switches pick which parts of g apply: the gravitational
// part sqrt(1 - rs/r), the kinematic (Doppler) rest, both, or neither.
vec3 disk_color(float r, float g_full) {
    float rs = P.holes[0].w;
    float r_in = P.disk.x;
    float f = max((1.0 - sqrt(r_in / r)) / (r * r * r), 0.0);
    float t_rel = sqrt(sqrt(f / P.disk_temp.y));   // T / T_peak
    float g_grav = sqrt(max(1.0 - rs / r, 1e-6));
    bool doppler = P.disk_temp.z > 0.5, redshift = P.disk_temp.w > 0.5;
    float g = doppler ? (redshift ? g_full : g_full / g_grav) : (redshift ? g_grav : 1.0);
    float t_obs = g * t_rel * P.disk_temp.x;
    vec3 c = blackbody(t_obs);
    float gt = g * t_rel;
    return c * (P.disk.z * gt * gt * gt * gt);
}

#include "noise.glsl"
#include "volume.glsl"

#define OUT_ESCAPED 0
#define OUT_CAPTURED 1
#define OUT_DISK 2
#define OUT_NO_STEPS 3

const float PI = 3.14159265358979;

struct Hit {
    int outcome;
    vec3 pos;   // disk crossing point
    vec3 dir;   // final direction (escaped)
    float g;    // redshift at a disk hit
    vec3 glow;  // light gathered from the volumetric disk on the way
    float trans; // transmittance of that volume (1: clear)
};

bool volumetric() {
    return VOLUME;
}

// The bending a ray still gets beyond the escape radius, to first order in rs
// (integrating the perpendicular acceleration 1.5 rs b^3 / r^5 along the
// straight continuation): delta = rs / (2b) (2 - s (2 s^2 + 3 b^2) / R^3),
// with b the distance of the line from the hole and s = x . v along it.
vec3 asymptotic_direction(vec3 x, vec3 v) {
    vec3 d = normalize(v);
    vec3 bend = vec3(0.0);
    for (uint i = 0u; i < P.counts.x; ++i) {
        vec3 rel = x - P.holes[i].xyz;
        float s = dot(rel, d);
        vec3 perp = rel - s * d;
        float b = length(perp);
        float R = length(rel);
        if (b < 1e-6) continue;
        float delta = P.holes[i].w / (2.0 * b) * (2.0 - s * (2.0 * s * s + 3.0 * b * b) / (R * R * R));
        bend -= delta * perp / b;
    }
    return normalize(d + bend);
}

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

// Redshift g = nu_obs / nu_emit of light from a Keplerian emitter at p for a
// photon moving along -v (the conventions in the README, "Physics"): g = sqrt(1 - 1.5 rs / r) /
// (1 - Omega lambda), lambda = L / E from the conserved angular momentum
// x cross x' and the asymptotic speed |x'|^2 - rs h^2 / r^3.
float disk_redshift(vec3 p, vec3 x, vec3 v) {
    float rs = P.holes[0].w;
    float r = length(p - P.holes[0].xyz);
    vec3 d = x - P.holes[0].xyz;
    float rx = length(d);
    vec3 hv = cross(d, v);
    // With gravity off the ray is straight and |v| is its speed everywhere.
    float bend = P.integ.z > 0.5 ? rs * dot(hv, hv) / (rx * rx * rx) : 0.0;
    float vinf = sqrt(max(dot(v, v) - bend, 1e-20));
    float lambda = dot(cross(d, -v), P.disk_normal.xyz) / vinf;
    float omega = sqrt(0.5 * rs / (r * r * r));
    return sqrt(max(1.0 - 1.5 * rs / r, 0.0)) / (1.0 - omega * lambda);
}

// One classic Runge-Kutta step of Binet's equation u'' = -u + 1.5 rs u^2
// (u = 1/r, ' = d/dphi) for the state (u, u').
vec2 binet_rk4(vec2 s, float h, float rs) {
    vec2 k1 = vec2(s.y, -s.x + 1.5 * rs * s.x * s.x);
    vec2 s2 = s + 0.5 * h * k1;
    vec2 k2 = vec2(s2.y, -s2.x + 1.5 * rs * s2.x * s2.x);
    vec2 s3 = s + 0.5 * h * k2;
    vec2 k3 = vec2(s3.y, -s3.x + 1.5 * rs * s3.x * s3.x);
    vec2 s4 = s + h * k3;
    vec2 k4 = vec2(s4.y, -s4.x + 1.5 * rs * s4.x * s4.x);
    return s + (h / 6.0) * (k1 + 2.0 * k2 + 2.0 * k3 + k4);
}

// One hole: the path stays in the plane of the hole, the camera and the ray,
// and its shape r(phi) obeys Binet's equation, the same curve as the Cartesian
// equation of geodesic.glsl, at a fraction of the cost: two numbers per step
// instead of six, and events in closed form. Disk crossings are where the
// orbit plane meets the disk plane (phi_0 + k pi), reached exactly; escape is
// u = 0, where the position's direction is the asymptotic direction.
Hit trace_planar(vec3 x, vec3 d) {
    Hit hit;
    hit.outcome = OUT_NO_STEPS;
    hit.pos = vec3(0.0);
    hit.dir = d;
    hit.g = 0.0;
    hit.glow = vec3(0.0);
    hit.trans = 1.0;
    vec3 c = P.holes[0].xyz;
    float rs = P.holes[0].w;
    vec3 rel = x - c;
    float r0 = length(rel);
    vec3 e1 = rel / r0;
    vec3 nrm = cross(e1, d);
    float sn = length(nrm);
    if (sn < 1e-7) {
        // A radial ray: straight in (captured) or straight out (escaped).
        hit.outcome = dot(d, e1) < 0.0 ? OUT_CAPTURED : OUT_ESCAPED;
        return hit;
    }
    nrm /= sn;
    vec3 e2 = cross(nrm, e1);
    vec2 s = vec2(1.0 / r0, -(dot(d, e1) / dot(d, e2)) / r0);
    // Conserved: 1/b^2 = u'^2 + u^2 - rs u^3.
    float inv_b2 = s.y * s.y + s.x * s.x - rs * s.x * s.x * s.x;

    const float NEVER = 1e30;
    float phi_next = NEVER;
    vec3 N = P.disk_normal.xyz;
    if (int(P.disk_normal.w) == DISK_THIN) {
        float a = dot(e1, N), b = dot(e2, N);
        if (abs(a) + abs(b) > 1e-6) {
            float phi0 = atan(-a, b);     // a cos(phi) + b sin(phi) = 0
            if (phi0 <= 1e-6) phi0 += PI; // the next crossing ahead of the camera
            phi_next = phi0;
        }
    }
    float dphi = P.integ.w;
    bool vol = volumetric();
    // The photon's angular momentum about the disk axis (runs backwards: -nrm).
    float lambda = -dot(nrm, N) / sqrt(max(inv_b2, 1e-30));
    // No disk crossing can come after this radius on the way out.
    float tail_u = 1.0 / max(max(10.0 * rs, int(P.disk_normal.w) != DISK_NONE ? P.disk.y : 0.0), 1e-6);
    float u_capture = 1.0 / rs;
    float phi = 0.0;
    uint budget = P.counts.w;
    for (uint i = 0u; i < budget; ++i) {
        // Steps shrink where the nonlinear term 1.5 rs u^2 matters.
        float h = dphi / (1.0 + 8.0 * rs * s.x);
        bool at_crossing = phi + h >= phi_next;
        if (at_crossing) h = phi_next - phi;
        vec2 sn2 = binet_rk4(s, h, rs);
        if (vol && sn2.x > 0.0) {
            vec3 pa = c + (cos(phi) * e1 + sin(phi) * e2) / s.x;
            vec3 pb = c + (cos(phi + h) * e1 + sin(phi + h) * e2) / min(sn2.x, u_capture);
            volume_segment(pa, pb, lambda, hit.glow, hit.trans);
            if (hit.trans < 0.003) {
                hit.outcome = OUT_CAPTURED;  // opaque: nothing behind shows
                return hit;
            }
        }
        if (sn2.x <= 0.0) {
            float phi_inf = phi + h * s.x / (s.x - sn2.x);
            hit.outcome = OUT_ESCAPED;
            hit.dir = cos(phi_inf) * e1 + sin(phi_inf) * e2;
            hit.pos = c + (cos(phi) * e1 + sin(phi) * e2) / s.x;  // last finite point
            return hit;
        }
        if (sn2.x >= u_capture) {
            hit.outcome = OUT_CAPTURED;
            return hit;
        }
        phi += h;
        s = sn2;
        // Outgoing beyond the disk and far from the hole: the rest of the path
        // is the straight tangent line plus the first-order remaining bend
        // (see asymptotic_direction), once that bend is small enough that its
        // second-order remainder is far below f32 noise.
        if (s.y < 0.0 && s.x < tail_u) {
            float q = length(s);                 // 1 / (distance of the tangent line)
            float bl = 1.0 / q;
            float R = 1.0 / s.x;
            float sl = -s.y / (s.x * q);         // along-line position, > 0 outgoing
            float delta = rs / (2.0 * bl) * (2.0 - sl * (2.0 * sl * sl + 3.0 * bl * bl) / (R * R * R));
            if (delta < 1e-3) {
                float phi_inf = phi + atan(s.x, -s.y) + delta;
                hit.outcome = OUT_ESCAPED;
                hit.dir = cos(phi_inf) * e1 + sin(phi_inf) * e2;
                hit.pos = c + R * (cos(phi) * e1 + sin(phi) * e2);
                return hit;
            }
        }
        if (at_crossing) {
            float r = 1.0 / s.x;
            if (r >= P.disk.x && r <= P.disk.y) {
                hit.outcome = OUT_DISK;
                hit.pos = c + r * (cos(phi) * e1 + sin(phi) * e2);
                // lambda = L/E about the disk axis; the photon runs backwards (-nrm).
                float omega = sqrt(0.5 * rs / (r * r * r));
                hit.g = sqrt(max(1.0 - 1.5 * rs / r, 0.0)) / (1.0 - omega * lambda);
                return hit;
            }
            phi_next += PI;
        }
    }
    return hit;
}

Hit trace(vec3 x, vec3 v) {
    Hit hit;
    hit.outcome = OUT_NO_STEPS;
    hit.pos = vec3(0.0);
    hit.dir = v;
    hit.g = 0.0;
    hit.glow = vec3(0.0);
    hit.trans = 1.0;
    bool vol = volumetric();
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

        if (vol) {
            // lambda from the (one-hole) conserved quantities; approximate for several.
            vec3 dd = x - c0;
            vec3 hv = cross(dd, v);
            float rr = length(dd);
            float vinf = sqrt(max(dot(v, v) - (gravity ? P.holes[0].w * dot(hv, hv) / (rr * rr * rr) : 0.0), 1e-20));
            float lambda = dot(cross(dd, -v), P.disk_normal.xyz) / vinf;
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
                float rho = length(p - c0);
                if (rho >= P.disk.x && rho <= P.disk.y) {
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

void main() {
    uvec2 px = gl_GlobalInvocationID.xy;
    uint w = P.counts.y, hgt = P.counts.z;
    if (px.x >= w || px.y >= hgt) return;

    // Binding camera convention (the conventions in the README, "Physics").
    float tan_half = P.cam_pos.w, aspect = P.cam_right.w;
    // Sub-pixel jitter (cam_up.w, cam_fwd.w; 0 = the pixel centre) for
    // accumulated anti-aliasing in the window.
    float sx = (2.0 * (float(px.x) + 0.5 + P.cam_up.w) / float(w) - 1.0) * tan_half * aspect;
    float sy = (1.0 - 2.0 * (float(px.y) + 0.5 + P.cam_fwd.w) / float(hgt)) * tan_half;
    vec3 dir = normalize(P.cam_fwd.xyz + sx * P.cam_right.xyz + sy * P.cam_up.xyz);

    volume_jitter = hash33(uvec3(px, 7u)).x;
    Hit hit = ONE_HOLE ? trace_planar(P.cam_pos.xyz, dir) : trace(P.cam_pos.xyz, dir);
#ifdef GEODESIC_AOV
    vec4 aov = vec4(0.0, 0.0, 0.0, float(hit.outcome));
    if (hit.outcome == OUT_ESCAPED) {
        aov.xyz = hit.dir;
    } else if (hit.outcome == OUT_DISK) {
        vec3 d = hit.pos - P.holes[0].xyz;
        aov.x = length(d);
        aov.y = atan(dot(d, P.disk_e2.xyz), dot(d, P.disk_e1.xyz));
        aov.z = hit.g;
    }
    imageStore(out_img, ivec2(px), aov);
#else
    vec3 color = vec3(0.0);
    if (hit.outcome == OUT_ESCAPED) {
        float pixel_angle = 2.0 * tan_half / float(hgt);
        color = sky_color(hit.dir, pixel_angle);
        grid_plane(hit.pos, hit.dir, pixel_angle, color);
    }
    else if (hit.outcome == OUT_DISK) color = disk_color(length(hit.pos - P.holes[0].xyz), hit.g);
    color = hit.glow + hit.trans * color;
    imageStore(out_img, ivec2(px), vec4(color, 1.0));
#endif
}
