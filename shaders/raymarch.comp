#version 460
// Ray march: one invocation per pixel. Each camera ray follows its light
// path (closed form for one hole, lightpath.glsl; a straight line with
// gravity off; else the integrator of geodesic.glsl) until it falls into a
// horizon, hits the disk or escapes to the sky. Writes linear HDR.
//
// With one hole and a thin disk the work is split in two dispatches
// (DISK_STAGE): the trace pass shades every pixel's sky and lists the pixels
// whose path crosses the disk's annulus; the disk pass, dispatched
// indirectly over that list, adds the disk in front. On a CPU driver every
// branch costs every pixel, so this is what keeps the disk's cost to the
// pixels that show it.

#if !defined(GEODESIC_AOV) && !defined(NO_QUAD)
// Ray differentials from 2x2 quads of pixels (see main).
#extension GL_KHR_shader_subgroup_quad : require
#define RAY_DIFFERENTIALS
#endif
#ifdef DISK_SPLIT
// The build of the split stages (raymarch_split.comp.spv): the disk pass's
// work list, appended a SIMD group at a time. The other builds do not
// declare its buffers, so no pipeline that leaves them alone touches them.
#extension GL_KHR_shader_subgroup_ballot : require
#endif

layout(local_size_x = 8, local_size_y = 8) in;

// Specialization constants (src/passes/raymarch/mod.rs, `Variant`): code a
// scene does not use is compiled out of its pipeline. On a CPU driver such as
// lavapipe every branch runs under a mask for every pixel, taken or not, so
// this is what keeps the cost to the code a scene uses.
// One hole with gravity on: the closed-form path; otherwise the general
// Cartesian integrator.
layout(constant_id = 0) const bool ONE_HOLE = false;
// The disk kind (DISK_NONE, DISK_THIN, DISK_VOLUME).
layout(constant_id = 1) const int DISK_KIND = 1;
// The sky kind (SKY_BLACK, SKY_CHECKER, SKY_STARS, SKY_IMAGE, SKY_CATALOGUE).
layout(constant_id = 2) const int SKY_KIND = 2;
// The grid plane is drawn.
layout(constant_id = 3) const bool GRID_PLANE = false;
// The thin disk is seen as it was when its light left it (one hole).
layout(constant_id = 4) const bool LIGHT_DELAY = false;
// The thin disk has filaments and clumps (its `structure` key above 0).
layout(constant_id = 5) const bool THIN_STRUCTURE = false;
// Thin-disk crossings a ray may see (2 when the disk lets light through).
layout(constant_id = 6) const int THIN_CROSSINGS = 1;
// The volumetric disk glows as a blackbody at its shifted temperature (else
// the film's colour map).
layout(constant_id = 7) const bool VOLUME_BLACKBODY = false;
// Gravity off: rays are straight lines, traced in closed form.
layout(constant_id = 8) const bool STRAIGHT = false;
// Which part of the split thin-disk ray march this pipeline runs.
#define DISK_STAGE_ALL 0    // everything in one dispatch
#define DISK_STAGE_TRACE 1  // sky and captures, every pixel; lists disk pixels
#define DISK_STAGE_DISK 2   // the thin disk over the listed pixels
layout(constant_id = 9) const int DISK_STAGE = DISK_STAGE_ALL;
// The observer moves through the static frame (orbiting, falling): the
// pixel directions are aberrated.
layout(constant_id = 10) const bool OBSERVER_MOVES = false;

#include "color.glsl"
#include "params.glsl"
#include "geodesic.glsl"
#include "lightpath.glsl"

#ifdef GEODESIC_AOV
// The geodesic AOV (the geodesic AOV table in the README): where each ray went.
layout(binding = 0, rgba32f) uniform writeonly image2D out_img;
#else
// Read back by the disk pass (the light behind the disk).
layout(binding = 0, rgba16f) uniform image2D out_img;
#endif
#ifdef DISK_SPLIT
// The disk pass's work: pixels packed x | y << 16, and their count.
layout(std430, binding = 6) buffer DiskList {
    uint count;
    uint px[];
} disk_list;
// Its indirect dispatch: workgroups of 64 listed pixels, in rows of at most
// DISK_ROW workgroups (a device may allow as few as 65,535 a side, and a 4K
// frame can list more groups of 64 than that; short rows also make every
// frame of 720p and up use several, so the tests see them).
#define DISK_ROW 256u
layout(std430, binding = 7) buffer DiskDispatch {
    uint groups_x;
    uint groups_y;
    uint groups_z;
} disk_dispatch;
#endif
// Linear sRGB colour of luminance 1 per blackbody temperature, log-spaced
// from LUT_MIN_K to LUT_MAX_K (src/physics/blackbody.rs).
layout(binding = 2) uniform sampler2D disk_lut;

// Luminance-1 linear sRGB colour of a blackbody at t kelvin.
vec3 blackbody(float t) {
    float u = (log2(max(t, 1.0)) - log2(LUT_MIN_K)) / (log2(LUT_MAX_K) - log2(LUT_MIN_K));
    return textureLod(disk_lut, vec2(clamp(u, 0.0, 1.0), 0.5), 0.0).rgb;
}

// The image sky's panorama with mips, the catalogue's star grid with mips
// (src/stars.rs), or the colour table, unused, for the other skies.
layout(binding = 3) uniform sampler2D sky_tex;
// The thin disk's tileable noise (src/render/noise.rs, `disk_noise`).
layout(binding = 4) uniform sampler2D disk_noise;
// The volumetric disk's noise volume, three octaves in r, g, b
// (src/render/noise.rs, `volume_noise`).
layout(binding = 5) uniform sampler3D volume_noise;

#include "sky.glsl"

// Light of the thin disk at radius r whose light reaches us shifted by g_full
// (the conventions in the README, "Physics"): Novikov-Thorne temperature T(r), observed temperature
// g T coloured by the blackbody table, observed bolometric intensity g^4 times
// the emitted T^4. The switches pick which parts of g apply: the gravitational
// part sqrt(1 - rs/r) (colour and brightness), the kinematic rest to the
// colour (Doppler) and to the brightness (beaming).
vec3 disk_color(float r, float g_full) {
    float rs = P.metric.holes[0].w;
    float r_in = P.disk.inner;
    // One reciprocal for the divisions (dear on a CPU driver).
    float ir = 1.0 / r;
    float f = max((1.0 - sqrt(r_in * ir)) * (ir * ir * ir), 0.0);
    float t_rel = sqrt(sqrt(f * (1.0 / P.disk.nt_peak)));   // T / T_peak
    // The gravitational part as this observer measures it: emitter's clock
    // against the camera's.
    float lapse2 = max(1.0 - rs * ir, 1e-6), inv_lapse = inversesqrt(lapse2);
    float g_grav = lapse2 * inv_lapse * (1.0 / P.observer.lapse);
    bool doppler = P.disk.doppler > 0.5, redshift = P.disk.redshift > 0.5, beaming = P.disk.beaming > 0.5;
    float g_kin = g_full * inv_lapse * P.observer.lapse;
    float g_base = redshift ? g_grav : 1.0;
    float g = doppler ? g_base * g_kin : g_base;          // colour
    float g_i = beaming ? g_base * g_kin : g_base;        // brightness
    vec3 c = blackbody(g * t_rel * P.disk.peak_temperature);
    float gt = g_i * t_rel;
    return c * (P.disk.brightness * gt * gt * gt * gt);
}

#include "volume.glsl"

// The thin disk's structure: its density (mean about 1) at u = rs / r (where
// the Keplerian angular velocity is omega) and azimuth az (disk frame) at
// rotation time t (speed x time). Each element
// turns with the Keplerian angular velocity of its radius, so the pattern
// shears (faster inside) and winds into ever finer arcs as time goes on.
// The tileable noise is read in the co-moving angle (once around the
// texture per turn) and stretched across log r: long thin arcs. One filtered
// fetch; the contrast curve squares it into bright filaments and dark lanes.
float thin_disk_density_at(float u, float omega, float az, float t) {
    float phi = az - omega * t;
    vec2 uv = vec2(phi * (1.0 / 6.2831853), -1.6 * log(u));
    float n = textureLod(disk_noise, uv, 0.0).r;
    float d = max(1.0 + 2.6 * (n - 0.5), 0.0);
    return mix(1.0, d * d, P.disk.structure);
}

// The same from the radius (u = rs / r, omega Keplerian).
float thin_disk_density(float r, float az, float t) {
    float rs = P.metric.holes[0].w;
    return thin_disk_density_at(rs / r, sqrt(0.5 * rs / (r * r * r)), az, t);
}

// Azimuth of a point in the disk's frame (the AOV's convention).
float disk_azimuth(vec3 p) {
    vec3 d = p - P.metric.holes[0].xyz;
    return atan(dot(d, P.disk.e2), dot(d, P.disk.e1));
}

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
    vec3 glow;  // light gathered from the disk on the way
    float trans; // transmittance of that disk (1: clear)
    bool disk_ahead; // the trace pass left thin-disk crossings to the disk pass
};

bool volumetric() {
    return DISK_KIND == DISK_VOLUME;
}

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

// Signed height above the disk plane.
float plane_dist(vec3 x) {
    return dot(x - P.metric.holes[0].xyz, P.disk.normal);
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
    float rs = P.metric.holes[0].w;
    float r = length(p - P.metric.holes[0].xyz);
    vec3 d = x - P.metric.holes[0].xyz;
    float rx = length(d);
    vec3 hv = cross(d, v);
    // With gravity off the ray is straight and |v| is its speed everywhere.
    float bend = P.metric.gravity > 0.5 ? rs * dot(hv, hv) / (rx * rx * rx) : 0.0;
    float vinf = sqrt(max(dot(v, v) - bend, 1e-20));
    float lambda = dot(cross(d, -v), P.disk.normal) / vinf;
    float omega = sqrt(0.5 * rs / (r * r * r));
    return sqrt(max(1.0 - 1.5 * rs / r, 0.0)) / (1.0 - omega * lambda);
}

// The volumetric slab around one disk-plane crossing of a closed-form path:
// the angles where |height| < H, from the crossing's radius and the tilt of
// the orbit plane (widened for the path's curvature). Four chords between
// five points of the exact path carry VOLUME_SAMPLES samples spread evenly
// along them, offset by the pixel's jitter: a fixed count, because on a CPU
// driver a SIMD group runs as many samples as its longest ray would take, and
// the jitter turns the coarser spacing into fine grain that the window's
// accumulation and `render --spp` average away.
const int VOLUME_SAMPLES = 12;

void volume_crossing(LightPath path, float phi_j, float tilt, vec2 inside, vec3 c, vec3 e1,
                     vec3 e2, float rs, float lambda, inout Hit hit) {
    float H = P.volume.half_height;
    float r_j = rs / path_u(path, clamp(phi_j, 0.0, path.phi_end));
    // At most half-way to the neighbouring crossings, so no angle is counted
    // twice when the path stays in the slab from one crossing to the next.
    float half_width = min(1.3 * asin(min(H / max(tilt * r_j, 1e-6), 1.0)), 0.5 * PI);
    // Only where the path is inside the outer radius: the gas ends there,
    // and samples spread over a path running off to infinity would miss it.
    float a = max(phi_j - half_width, inside.x);
    float b = min(phi_j + half_width, inside.y);
    if (b <= a) return;
    vec3 pts[5];
    for (int k = 0; k < 5; ++k) {
        float phi = mix(a, b, 0.25 * float(k));
        float u = max(path_u(path, phi), 1e-6);
        pts[k] = c + (rs / u) * (cos(phi) * e1 + sin(phi) * e2);
    }
    vec4 len = vec4(length(pts[1] - pts[0]), length(pts[2] - pts[1]),
                    length(pts[3] - pts[2]), length(pts[4] - pts[3]));
    vec4 ends = vec4(len.x, len.x + len.y, len.x + len.y + len.z, len.x + len.y + len.z + len.w);
    float ds = ends.w / float(VOLUME_SAMPLES);
    for (int s = 0; s < VOLUME_SAMPLES; ++s) {
        float t = (float(s) + volume_jitter) * ds;
        // Which chord holds t, and where along it (selects, not dynamic
        // indexing: an index a masked-off lane computes must stay in range).
        bvec3 past = greaterThanEqual(vec3(t), ends.xyz);
        float start = past.z ? ends.z : past.y ? ends.y : past.x ? ends.x : 0.0;
        float l = past.z ? len.w : past.y ? len.z : past.x ? len.y : len.x;
        vec3 p0 = past.z ? pts[3] : past.y ? pts[2] : past.x ? pts[1] : pts[0];
        vec3 p1 = past.z ? pts[4] : past.y ? pts[3] : past.x ? pts[2] : pts[1];
        vec3 p = mix(p0, p1, clamp((t - start) / max(l, 1e-9), 0.0, 1.0));
        float r;
        float dens = volume_density(p, r);
        vec3 emit;
        if (VOLUME_BLACKBODY) {
            float omega = sqrt(0.5 * rs / (r * r * r));
            float g = sqrt(max(1.0 - 1.5 * rs / r, 1e-4)) / (1.0 - omega * lambda);
            emit = disk_color(max(r, 1.0001 * P.disk.inner), g * observer_g);
        } else {
            emit = volume_colormap(r);
        }
        hit.glow += hit.trans * emit * (dens * P.volume.lit * ds);
        hit.trans *= exp(-dens * 0.8 * ds);
    }
}

const int VOLUME_CROSSINGS = 4;

// Coordinate time the light takes from angle phi on the path back to the
// camera (phi = 0), in the units of the scene (c = 1): the integral of dt/dphi = r^2 / (b (1 - rs/r))
// by Simpson's rule over eight intervals of the exact path. Only the
// differences across the disk matter (what turns where while the light is
// on its way), and those are good to a few per cent.
float light_travel_time(LightPath path, float phi, float b, float rs) {
    const int N = 8;
    float h = phi / float(N);
    float sum = 0.0;
    for (int i = 0; i <= N; ++i) {
        float u = max(path_u(path, h * float(i)), 1e-6);
        float r = rs / u;
        float f = r * r / (b * max(1.0 - u, 1e-3));
        float w = (i == 0 || i == N) ? 1.0 : ((i & 1) == 1 ? 4.0 : 2.0);
        sum += w * f;
    }
    return sum * h / 3.0;
}

// The thin disk's first crossing inside the annulus from angle `next` on
// (advanced past it): its light added to the hit, weighted by its opacity.
// True when the ray ends there (opaque, or the AOV's first hit).
//
// Every crossing lies on the line of nodes (where the orbit plane meets the
// disk plane), at angle phi0 + j pi: its direction from the hole is
// (-1)^j `node`, and its azimuth az0 + j pi, so no sine, cosine or
// arctangent is needed per crossing.
bool thin_crossing(LightPath path, inout float next, float phi0, vec3 c, vec3 node, float az0,
                   float rs, float lambda, float b_imp, inout Hit hit) {
    float phi = min(first_crossing_in(path, path.win_a, next),
                    first_crossing_in(path, path.win_b, next));
    if (phi >= 1e29) {
        next = 1e30;
        return false;
    }
    next = phi + PI;
    float u = path_u(path, phi);
    float r = rs / u;
    // The windows' edges are rounded; the radius decides.
    if (r < P.disk.inner || r > P.disk.outer) return false;
    float j = round((phi - phi0) * (1.0 / PI));
    float odd = j - 2.0 * floor(0.5 * j);
    vec3 pos = c + (r * (1.0 - 2.0 * odd)) * node;
    // Keplerian omega = sqrt(rs / (2 r^3)) and 1.5 rs / r, from u = rs / r.
    float omega = u * sqrt(0.5 * u) * (1.0 / rs);
    float g = sqrt(max(1.0 - 1.5 * u, 0.0)) / (1.0 - omega * lambda);
#ifdef GEODESIC_AOV
    hit.outcome = OUT_DISK;
    hit.pos = pos;
    hit.g = g;
    return true;
#else
    float t = P.disk.rotation_time;
    if (LIGHT_DELAY) t -= P.disk.speed * light_travel_time(path, phi, b_imp, rs);
    // (u and omega at hand: no division or square root again.)
    float dens = THIN_STRUCTURE ? thin_disk_density_at(u, omega, az0 + odd * PI, t) : 1.0;
    float alpha = clamp(P.disk.opacity * dens, 0.0, 1.0);
    hit.glow += hit.trans * alpha * dens * disk_color(r, g * observer_g);
    hit.trans *= 1.0 - alpha;
    if (hit.trans < 0.003) {
        hit.outcome = OUT_CAPTURED;  // opaque: nothing behind shows
        return true;
    }
    return false;
#endif
}

// One hole: the path lies in the plane of the hole, the camera and the ray,
// and its shape u(phi) is known in closed form (lightpath.glsl). Disk
// crossings are where the orbit plane meets the disk plane (phi_0 + k pi),
// u there straight from the formula; escape and capture come from the total
// sweep; no steps.
Hit trace_planar(vec3 x, vec3 d) {
    Hit hit;
    hit.outcome = OUT_NO_STEPS;
    hit.pos = vec3(0.0);
    hit.dir = d;
    hit.g = 0.0;
    hit.glow = vec3(0.0);
    hit.trans = 1.0;
    hit.disk_ahead = false;
    vec3 c = P.metric.holes[0].xyz;
    float rs = P.metric.holes[0].w;
    vec3 rel = x - c;
    float r0 = length(rel), ir0 = 1.0 / r0;
    vec3 e1 = rel * ir0;
    vec3 nrm = cross(e1, d);
    float sn = length(nrm);
    if (sn < 1e-7) {
        // A radial ray: straight in (captured) or straight out (escaped).
        hit.outcome = dot(d, e1) < 0.0 ? OUT_CAPTURED : OUT_ESCAPED;
        hit.pos = x;
        return hit;
    }
    nrm *= 1.0 / sn;
    vec3 e2 = cross(nrm, e1);
    float u0 = rs * ir0;
    float du = -(dot(d, e1) / dot(d, e2)) * u0;
    // The thin disk's annulus in u (anything for other disks).
    float u_lo = rs / max(P.disk.outer, 1e-6), u_hi = rs / max(P.disk.inner, 1e-6);
    LightPath path = light_path(u0, du, u_lo, min(u_hi, 1.0));
    // Impact parameter b (world units) and the photon's angular momentum
    // about the disk axis (the ray runs backwards: -nrm).
    float b_imp = rs * inversesqrt(max(du * du + u0 * u0 * (1.0 - u0), 1e-30));
    vec3 N = P.disk.normal;
    float lambda = -dot(nrm, N) * b_imp;

    const int kind = DISK_KIND;
    float na = dot(e1, N), nb = dot(e2, N);
    float tilt = length(vec2(na, nb));
    if (kind != DISK_NONE && tilt > 1e-6) {
        float phi0 = atan(-na, nb);       // a cos(phi) + b sin(phi) = 0
        if (kind == DISK_THIN) {
            // The plane crossings inside the annulus: the first crossing
            // angle in either window where u is in [rs/outer, rs/inner]; one
            // evaluation of the path each. Where the disk is thin (its
            // structure, its opacity) the light behind comes through: the
            // next crossing (THIN_CROSSINGS = 2), then the sky.
            // A loop, not two calls: on a CPU driver a branch costs every
            // lane, taken or not, but a loop's later turns run only while a
            // lane of the SIMD group still needs them (the first always runs).
            float next = phi0 <= 1e-6 ? phi0 + PI : phi0;  // the next crossing ahead
            if (DISK_STAGE == DISK_STAGE_TRACE) {
                // Left to the disk pass: any crossing in the windows.
                hit.disk_ahead = min(first_crossing_in(path, path.win_a, next),
                                     first_crossing_in(path, path.win_b, next)) < 1e29;
            } else {
                vec3 node = (nb * e1 - na * e2) / tilt;      // cos(phi0) e1 + sin(phi0) e2
                float az0 = THIN_STRUCTURE ? disk_azimuth(c + node) : 0.0;
                for (int k = 0; k < THIN_CROSSINGS; ++k) {
                    if (thin_crossing(path, next, phi0, c, node, az0, rs, lambda, b_imp, hit)) return hit;
                    if (next >= 1e29) break;
                }
            }
        } else if (volumetric()) {
            // From the crossing behind the camera when the camera is in the
            // slab (the same for every pixel, so no divergence), else from the
            // one ahead; four in all. Later slabs are the thin rings of rays
            // that wind, and every extra one costs the whole SIMD group.
            bool camera_in_slab = abs(dot(x - c, N)) < 1.5 * P.volume.half_height;
            float phi = camera_in_slab ? phi0 - PI : (phi0 <= 1e-6 ? phi0 + PI : phi0);
            // The angles where the path is inside the outer radius (u >= u_lo):
            // scattered, between the annulus windows' outer ends; plunging,
            // from the first window on; trapped rays never leave it.
            vec2 w_in = path.kind == PATH_SCATTERED ? vec2(path.win_a.x, path.win_b.y)
                      : vec2(path.win_a.x, 1e30);
            vec2 f_in = (w_in - path.w0) / path.rate;
            vec2 inside = path.kind == PATH_TRAPPED ? vec2(0.0, path.phi_end)
                        : vec2(max(min(f_in.x, f_in.y), 0.0), min(max(f_in.x, f_in.y), path.phi_end));
            // The test at the end of the body, as in carlson_rf4: a CPU
            // driver runs the first body for every SIMD group anyway (a slab
            // past the path's end adds nothing), and a test before the body
            // would run one body more than the longest lane needs.
            for (int j = 0; j < VOLUME_CROSSINGS; ++j) {
                volume_crossing(path, phi, tilt, inside, c, e1, e2, rs, lambda, hit);
                if (hit.trans < 0.003) {
                    hit.outcome = OUT_CAPTURED;  // opaque: nothing behind shows
                    return hit;
                }
                phi += PI;
                if (phi - PI >= inside.y) break;
            }
        }
    }
    if (path.escapes) {
        float phi = path.phi_end;
        hit.outcome = OUT_ESCAPED;
        vec2 cs = cos_sin_precise(phi);
        hit.dir = cs.x * e1 + cs.y * e2;
        // A point on the asymptote: it passes the hole at distance b.
        hit.pos = c + b_imp * cross(hit.dir, nrm);
    } else {
        hit.outcome = OUT_CAPTURED;
    }
    return hit;
}

// Gravity off: the ray is the line x + t d. It ends at the first horizon it
// enters (the holes still absorb), at the thin disk's plane inside the
// annulus, or at the sky in its own direction; the volumetric disk is
// gathered along the part of the line inside the slab, in chords of at most
// 16 samples (the step-by-step path's spacing), up to the horizon.
Hit trace_straight(vec3 x, vec3 d) {
    Hit hit;
    hit.outcome = OUT_ESCAPED;
    hit.pos = x;
    hit.dir = d;
    hit.g = 0.0;
    hit.glow = vec3(0.0);
    hit.trans = 1.0;
    hit.disk_ahead = false;
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

Hit trace(vec3 x, vec3 v) {
    Hit hit;
    hit.outcome = OUT_NO_STEPS;
    hit.pos = vec3(0.0);
    hit.dir = v;
    hit.g = 0.0;
    hit.glow = vec3(0.0);
    hit.trans = 1.0;
    hit.disk_ahead = false;
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

// The coordinate direction of pixel px's camera ray (binding camera
// convention, the conventions in the README, "Physics"); sets observer_g.
vec3 pixel_ray(uvec2 px) {
    uint w = P.camera.size.x, hgt = P.camera.size.y;
    float tan_half = P.camera.tan_half_fov, aspect = P.camera.aspect;
    // Sub-pixel jitter (cam_up.w, cam_fwd.w; 0 = the pixel centre) for
    // accumulated anti-aliasing in the window.
    float sx = ((float(px.x) + 0.5 + P.camera.jitter_x) * (2.0 / float(w)) - 1.0) * tan_half * aspect;
    float sy = (1.0 - (float(px.y) + 0.5 + P.camera.jitter_y) * (2.0 / float(hgt))) * tan_half;
    vec3 dir = normalize(P.camera.forward + sx * P.camera.right + sy * P.camera.up);
    // The pixel's direction is measured in the observer's own frame
    // (src/physics/observer.rs): aberration by its velocity into the static
    // frame, then the static frame's radial squeeze into a coordinate
    // direction; its clock and motion scale the redshift it measures.
    if (int(P.observer.kind) != OBS_FLAT) {
        vec3 beta = P.observer.velocity;
        float b2 = dot(beta, beta);
        float doppler = 1.0;
        if (OBSERVER_MOVES && b2 > 0.0) {
            float gam = inversesqrt(1.0 - b2);
            float bd = dot(beta, dir);
            dir = normalize((dir / gam - beta + (gam / (gam + 1.0)) * bd * beta) / (1.0 - bd));
            doppler = gam * (1.0 + dot(beta, dir));
        }
        vec3 rh = P.observer.radial;
        float dr = dot(dir, rh);
        dir = normalize(P.observer.lapse * dr * rh + (dir - dr * rh));
        observer_g = doppler / P.observer.lapse;
    }
    return dir;
}

#ifdef DISK_SPLIT
// The trace pass: lists this SIMD group's pixels that need the disk pass
// (one atomic per group; the dispatch grows to cover the list).
void list_for_disk(uvec2 px, bool need) {
    uvec4 ballot = subgroupBallot(need);
    uint n = subgroupBallotBitCount(ballot);
    uint base = 0u;
    if (subgroupElect() && n > 0u) {
        base = atomicAdd(disk_list.count, n);
        // Both sides grow with the count, so the largest count wins both.
        uint groups = (base + n + 63u) / 64u;
        atomicMax(disk_dispatch.groups_x, min(groups, DISK_ROW));
        atomicMax(disk_dispatch.groups_y, (groups + DISK_ROW - 1u) / DISK_ROW);
    }
    base = subgroupBroadcastFirst(base);
    if (need) disk_list.px[base + subgroupBallotExclusiveBitCount(ballot)] = px.x | (px.y << 16u);
}

// The disk pass: one listed pixel per invocation. Its path again (the same
// closed form), now with the thin disk's crossings, in front of what the
// trace pass wrote (the sky, or black where the ray is captured); an opaque
// disk hides it.
void disk_pass() {
    uint i = (gl_WorkGroupID.y * DISK_ROW + gl_WorkGroupID.x) * 64u + gl_LocalInvocationIndex;
    if (i >= disk_list.count) return;
    uint packed = disk_list.px[i];
    ivec2 px = ivec2(packed & 0xffffu, packed >> 16u);
    Hit hit = trace_planar(P.camera.position, pixel_ray(uvec2(px)));
    vec3 behind = hit.trans < 0.003 ? vec3(0.0) : imageLoad(out_img, px).rgb;
    imageStore(out_img, px, vec4(storable(hit.glow + hit.trans * behind), 1.0));
}
#endif

void main() {
    read_params();  // first, outside any branch (params.glsl)
#ifdef DISK_SPLIT
    if (DISK_STAGE == DISK_STAGE_DISK) {
        disk_pass();
        return;
    }
#endif
    uint w = P.camera.size.x, hgt = P.camera.size.y;
#ifdef RAY_DIFFERENTIALS
    // The 64 invocations of a group cover its 8x8 tile in 2x2 quads
    // (subgroup quads are four consecutive invocations), so each pixel can
    // read its right or left and its lower or upper neighbour's final
    // direction. Lanes past the image's edge trace a clamped pixel for their
    // quad and store nothing.
    uint li = gl_LocalInvocationIndex;
    uint quad = li >> 2u;
    uvec2 in_quad = uvec2(li & 1u, (li >> 1u) & 1u);
    uvec2 px_raw = gl_WorkGroupID.xy * 8u + 2u * uvec2(quad & 3u, quad >> 2u) + in_quad;
    bool inside = px_raw.x < w && px_raw.y < hgt;
    uvec2 px = min(px_raw, uvec2(w - 1u, hgt - 1u));
#else
    uvec2 px = gl_GlobalInvocationID.xy;
    if (px.x >= w || px.y >= hgt) return;
#endif

    vec3 dir = pixel_ray(px);
    float tan_half = P.camera.tan_half_fov;

    // The volume's sample offset: per pixel, and per accumulated frame (salted
    // by the sub-pixel jitter, zero for a single offscreen frame) so the
    // window's accumulation averages the grain away.
    volume_jitter = hash33(uvec3(px, 7u + floatBitsToUint(P.camera.jitter_x) + 3u * floatBitsToUint(P.camera.jitter_y))).x;
    Hit hit = ONE_HOLE ? trace_planar(P.camera.position, dir)
            : STRAIGHT ? trace_straight(P.camera.position, dir)
            : trace(P.camera.position, dir);
    hit.g *= observer_g;
#ifdef GEODESIC_AOV
    vec4 aov = vec4(0.0, 0.0, 0.0, float(hit.outcome));
    if (hit.outcome == OUT_ESCAPED) {
        aov.xyz = hit.dir;
    } else if (hit.outcome == OUT_DISK) {
        vec3 d = hit.pos - P.metric.holes[0].xyz;
        aov.x = length(d);
        aov.y = atan(dot(d, P.disk.e2), dot(d, P.disk.e1));
        aov.z = hit.g;
    }
    imageStore(out_img, ivec2(px), aov);
#else
    vec3 color = vec3(0.0);
    float pixel_angle = 2.0 * tan_half / float(hgt);
    // The pixel's footprint on the sky: the change of the final direction
    // from one pixel to the next, across and down. Unlensed, pixel_angle in
    // two directions at right angles to it.
    vec3 t1 = normalize(cross(hit.dir, abs(hit.dir.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0)));
    Footprint fp = Footprint(pixel_angle * t1, pixel_angle * cross(hit.dir, t1), pixel_angle);
#ifdef RAY_DIFFERENTIALS
    // Lensed: from the quad's neighbours (one-sided differences), where the
    // neighbour escaped too and its direction is near (not across the
    // shadow's edge or the photon ring's discontinuities).
    bool escaped = hit.outcome == OUT_ESCAPED;
    vec3 dh = subgroupQuadSwapHorizontal(hit.dir);
    vec3 dv = subgroupQuadSwapVertical(hit.dir);
    bool eh = subgroupQuadSwapHorizontal(escaped);
    bool ev = subgroupQuadSwapVertical(escaped);
    vec3 ax = (dh - hit.dir) * (in_quad.x == 0u ? 1.0 : -1.0);
    vec3 ay = (dv - hit.dir) * (in_quad.y == 0u ? 1.0 : -1.0);
    // Past the image's edge a neighbour is the clamped pixel itself (no
    // difference): not a footprint either.
    const float NEAR = 0.3;
    float tiny = 1e-3 * pixel_angle;
    float lx = length(ax), ly = length(ay);
    bool okx = eh && lx < NEAR && lx > tiny, oky = ev && ly < NEAR && ly > tiny;
    // With one neighbour's difference only, the other axis is the unlensed
    // pixel angle at right angles to it (one cross product for either case:
    // on a CPU driver both branches would run).
    vec3 known = okx ? ax : ay;
    vec3 across = (pixel_angle * (okx ? 1.0 : -1.0)) * normalize(cross(hit.dir, known + 1e-12 * t1));
    if (okx || oky) {
        fp.x = okx ? ax : across;
        fp.y = oky ? ay : across;
    }
#endif
    if (hit.outcome == OUT_ESCAPED) {
        color = sky_color(hit.dir, fp);
        grid_plane(hit.pos, hit.dir, pixel_angle, color);
    }
    else if (!ONE_HOLE && hit.outcome == OUT_DISK) {
        // The general and straight paths' disk (several holes, gravity off): opaque. (The
        // closed-form path adds the disk's light as it goes; compiled out.)
        float r = length(hit.pos - P.metric.holes[0].xyz);
        float dens = THIN_STRUCTURE ? thin_disk_density(r, disk_azimuth(hit.pos), P.disk.rotation_time) : 1.0;
        color = dens * disk_color(r, hit.g);
    }
    color = hit.glow + hit.trans * color;
#ifdef DISK_SPLIT
    if (DISK_STAGE == DISK_STAGE_TRACE) list_for_disk(px, hit.disk_ahead && inside);
#endif
#ifdef RAY_DIFFERENTIALS
    if (!inside) return;
#endif
    imageStore(out_img, ivec2(px), vec4(storable(color), 1.0));
#endif
}
