// One hole with gravity: the closed-form light path (lightpath.glsl), its
// thin-disk crossings on the line of nodes, the volumetric slabs along it and
// the light's travel time. metric_trace() is this metric's path, and it adds
// the thin disk's light as it crosses it.
#ifndef METRIC_SCHWARZSCHILD_GLSL
#define METRIC_SCHWARZSCHILD_GLSL

#include "constants.glsl"
#include "params.glsl"
#include "metric/static_frame.glsl"
#include "variant.glsl"
#include "ray_state.glsl"
#include "lightpath.glsl"
#include "hit.glsl"
#include "disk.glsl"
#include "volume.glsl"
#include "polarization.glsl"

// The frame at a ray's origin and a disk point's radius (static_frame.glsl).
NON_ROTATING_METRIC(true)

// The volumetric slab around one disk-plane crossing of a closed-form path:
// the angles where |height| < H, from the crossing's radius and the tilt of
// the orbit plane (widened for the path's curvature), sampled along five
// points of the exact path (volume_chords).
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
    volume_chords(pts, lambda, hit.glow, hit.trans);
}

const int VOLUME_CROSSINGS = 4;

// The time the light takes from angle phi on the path back to the camera
// (phi = 0), in the units of the scene (c = 1), by Simpson's rule over
// eight intervals of the exact path. Only the differences across the disk
// matter (what turns where while the light is on its way), and those are
// good to a few per cent.
//
// A camera at rest counts Schwarzschild time, dt/dphi = r^2 / (b (1 -
// rs/r)). A falling camera (RAIN_FORM), which crosses the horizon where
// that clock stops, counts ingoing time v = t + r*, finite through the
// horizon: dv/dphi = b / (1 + q) where the light moves inward and
// r^2 (1 + q) / (b (1 - rs/r)) where it moves outward, q = sqrt(1 - (b u /
// rs)^2 (1 - u)), plus r*(r) = r + rs ln|r / rs - 1| at the disk (its
// emitter's t = v - r*); the camera's own v is the frame's time.
float light_travel_time(LightPath path, float phi, float b, float rs) {
    const int N = 8;
    float h = phi / float(N);
    float sum = 0.0;
    for (int i = 0; i <= N; ++i) {
        float u = max(path_u(path, h * float(i)), 1e-6);
        float r = rs / u;
        float f;
        if (RAIN_FORM) {
            float q = b * u / rs;
            q = sqrt(max(1.0 - q * q * (1.0 - u), 0.0));
            // (The backward ray moving inward: the light moved outward.)
            f = path_moves_in(path, h * float(i)) ? r * r * (1.0 + q) / (b * max(1.0 - u, 1e-3))
                                                  : b / (1.0 + q);
        } else {
            f = r * r / (b * max(1.0 - u, 1e-3));
        }
        float w = (i == 0 || i == N) ? 1.0 : ((i & 1) == 1 ? 4.0 : 2.0);
        sum += w * f;
    }
    float time = sum * h / 3.0;
    if (RAIN_FORM) {
        float r_end = rs / max(path_u(path, phi), 1e-6);
        time += r_end + rs * log(max(abs(r_end / rs - 1.0), 1e-6));
    }
    return time;
}

// The thin disk's first crossing inside the annulus from angle `next` on
// (advanced past it): its light added to the hit, weighted by its opacity.
// True when the ray ends there (opaque, or the AOV's first hit).
//
// Every crossing lies on the line of nodes (where the orbit plane meets the
// disk plane), at angle phi0 + j pi: its direction from the hole is
// (-1)^j `node`, and its azimuth az0 + j pi, so no sine, cosine or
// arctangent is needed per crossing.
// The camera's side of the polarization (pol_camera_static) at its own
// place. A falling camera (RAIN_FORM) has them on its own frame, outside,
// at and inside the horizon: the constant's form is the static frame's in
// any frame boosted from it along r_hat (p^0 f_r - p_r f^0 is invariant
// under that boost, p x f . r_hat does not change), and the rain frame is
// one, continued through the horizon.
vec4 schwarzschild_pol_camera(vec3 c, float rs) {
    vec3 rel = pol_origin - c;
    vec3 beta = !RAIN_FORM && OBSERVER_MOVES ? P.observer.velocity : vec3(0.0);
    return pol_camera_static(length(rel) / rs, normalize(rel), beta);
}

// The polarization of a crossing at pos, r rs from the hole, angle phi
// along the backward path in its plane (normal nrm) of constant cb = (rs /
// b)^2 (polarization.glsl; Hit.pol): the photon's static-frame direction
// from u' (its size from the orbit equation u'^2 = cb - u^2 (1 - u), its
// sign from the path on either side), the camera's side from its own place.
vec4 schwarzschild_polarization(LightPath path, float phi, float u, float cb, vec3 c, vec3 pos, vec3 nrm,
                                float rs) {
    float du = sqrt(max(cb - u * u * (1.0 - u), 0.0));
    du *= path_u(path, phi + 1e-3) >= path_u(path, phi - 1e-3) ? 1.0 : -1.0;
    vec3 r_hat = normalize(pos - c);
    // The backward ray's direction: -(u' / u) / sqrt(1 - u) along r_hat, 1
    // along phi_hat = nrm x r_hat; the photon runs the other way.
    vec3 k_hat = -normalize((-du / (u * sqrt(max(1.0 - u, 1e-12)))) * r_hat + cross(nrm, r_hat));
    vec4 em = pol_emit_static(1.0 / u, r_hat, P.disk.normal, k_hat);
    vec4 k = schwarzschild_pol_camera(c, rs);
    return pol_of(em, pol_angle(em.xy, k.xy, k.zw));
}

// The polarized volume (POLARIZATION): the ray's orbit plane (normal) and
// constant cb = (rs / b)^2, for its samples.
vec4 sch_pol_path;

// A sample at p on the chord from p0 to p1 of the path (volume_chords):
// the photon's static-frame direction there from the orbit equation at its
// radius (u' = +-sqrt(cb - u^2 (1 - u)), its sign where the chord's radius
// falls along the backward path), as schwarzschild_polarization.
vec4 metric_pol_sample(vec3 p, vec3 p0, vec3 p1, int chord, float frac) {
    vec3 c = P.metric.holes[0].xyz;
    float rs = P.metric.holes[0].w;
    vec3 rel = p - c;
    float r = length(rel) / rs, u = 1.0 / r;
    vec3 r_hat = rel * (u / rs), nrm = sch_pol_path.xyz;
    float du = sqrt(max(sch_pol_path.w - u * u * (1.0 - u), 0.0));
    du *= length(p1 - c) <= length(p0 - c) ? 1.0 : -1.0;
    vec3 k_hat = -normalize((-du / (u * sqrt(max(1.0 - u, 1e-12)))) * r_hat + cross(nrm, r_hat));
    return pol_volume_static(r, r_hat, k_hat);
}

bool thin_crossing(LightPath path, inout float next, float phi0, vec3 c, vec3 node, float az0,
                   float rs, float lambda, float b_imp, float cb, vec3 nrm, inout Hit hit) {
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
    float g = emitter_g(1.0 - 1.5 * u, omega, lambda, 0.0);
#ifdef GEODESIC_AOV
    hit.outcome = OUT_DISK;
    hit.pos = pos;
    hit.g = g;
    if (POLARIZATION != POL_OFF) hit.pol = schwarzschild_polarization(path, phi, u, cb, c, pos, nrm, rs);
    return true;
#else
    if (POLARIZATION == POL_VIEW) {
        // The polarized picture: the first crossing, as the Stokes AOV's.
        hit.outcome = OUT_DISK;
        hit.pos = pos;
        hit.g = g;
        hit.pol = schwarzschild_polarization(path, phi, u, cb, c, pos, nrm, rs);
        return true;
    }
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

// The volumetric disk along the path: the slabs where it crosses the disk's
// plane, at phi0 + k pi (the plane's node), each sampled by volume_crossing.
// True when the gas turned opaque (the hit is then captured).
bool volume_slabs(LightPath path, vec3 x, float phi0, float tilt, vec3 c, vec3 e1, vec3 e2,
                  float rs, float lambda, inout Hit hit) {
    vec3 N = P.disk.normal;
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
            return true;
        }
        phi += PI;
        if (phi - PI >= inside.y) break;
    }
    return false;
}

// One hole: the path lies in the plane of the hole, the camera and the ray,
// and its shape u(phi) is known in closed form (lightpath.glsl). Disk
// crossings are where the orbit plane meets the disk plane (phi_0 + k pi),
// u there straight from the formula; escape and capture come from the total
// sweep; no steps.
const bool METRIC_SHADES_DISK = true;
// The split's second pass adds the thin disk in front (raymarch.comp).
const bool METRIC_SPLITS_RARE = false;

Hit metric_trace(vec3 x, vec3 d) {
    Hit hit = hit_start(OUT_NO_STEPS, vec3(0.0), d);
    // E <= 0 inside the horizon: the light crossed the other universe's
    // horizon into the hole, not ours (none in a hole formed by collapse).
    // Its path there is the same closed form (the orbit's shape knows only
    // b); with a mirror sky it is followed to that universe's infinity, past
    // no disk.
    bool other = RAIN_FORM && rain_energy <= 0.0;
    if (other && P.sky.other < 0.5) {
        hit.outcome = OUT_OTHER_UNIVERSE;
        hit.pos = x;
        return hit;
    }
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
        hit.far_sky = other && hit.outcome == OUT_ESCAPED;
        hit.outcome = other ? OUT_OTHER_UNIVERSE : hit.outcome;
        hit.pos = x;
        return hit;
    }
    nrm *= 1.0 / sn;
    vec3 e2 = cross(nrm, e1);
    float u0 = rs * ir0;
    float du = -(dot(d, e1) / dot(d, e2)) * u0;
    // The thin disk's annulus in u (anything for other disks).
    float u_lo = rs / max(P.disk.outer, 1e-6), u_hi = rs / max(P.disk.inner, 1e-6);
    // The path's constant (rs / b)^2; a falling camera has it from the
    // photon's energy (rain_k2, camera.glsl).
    float cb = RAIN_FORM ? u0 * u0 * rain_k2 : du * du + u0 * u0 * (1.0 - u0);
    LightPath path = light_path(u0, du, cb, u_lo, min(u_hi, 1.0));
    // Impact parameter b (world units) and the photon's angular momentum
    // about the disk axis (the ray runs backwards: -nrm).
    float b_imp = rs * inversesqrt(max(cb, 1e-30));
    vec3 N = P.disk.normal;
    float lambda = -dot(nrm, N) * b_imp;

    const int kind = DISK_KIND;
    float na = dot(e1, N), nb = dot(e2, N);
    float tilt = length(vec2(na, nb));
    if (kind != DISK_NONE && tilt > 1e-6 && !other) {
        // a cos(phi) + b sin(phi) = 0. A falling camera's, to full
        // precision: from inside the horizon the rays run out nearly
        // radially, r(phi) is steep (dr/dphi ~ r^2 / b, 500 at 12 rs), and
        // the driver's atan moved the disk crossing by 7e-4 rs. (The
        // cameras at rest keep the driver's: their goals hold with it.)
        float phi0 = RAIN_FORM ? atan2_precise(-na, nb) : atan(-na, nb);
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
            if (SPLIT_STAGE == STAGE_TRACE) {
                // Left to the disk pass: any crossing in the windows.
                hit.deferred = min(first_crossing_in(path, path.win_a, next),
                                   first_crossing_in(path, path.win_b, next)) < 1e29;
            } else {
                vec3 node = (nb * e1 - na * e2) / tilt;      // cos(phi0) e1 + sin(phi0) e2
                float az0 = THIN_STRUCTURE ? disk_azimuth(c + node) : 0.0;
                for (int k = 0; k < THIN_CROSSINGS; ++k) {
                    if (thin_crossing(path, next, phi0, c, node, az0, rs, lambda, b_imp, cb, nrm, hit)) return hit;
                    if (next >= 1e29) break;
                }
            }
        } else if (volumetric()) {
            if (POLARIZATION != POL_OFF) {
                pol_cam_k = schwarzschild_pol_camera(c, rs);
                pol_cam_g = observer_g;
                sch_pol_path = vec4(nrm, cb);
            }
            if (volume_slabs(path, x, phi0, tilt, c, e1, e2, rs, lambda, hit)) return hit;
        }
    }
    if (path.escapes) {
        float phi = path.phi_end;
        hit.outcome = other ? OUT_OTHER_UNIVERSE : OUT_ESCAPED;
        hit.far_sky = other;
        vec2 cs = cos_sin_precise(phi);
        hit.dir = cs.x * e1 + cs.y * e2;
        // A point on the asymptote: it passes the hole at distance b.
        hit.pos = c + b_imp * cross(hit.dir, nrm);
    } else {
        hit.outcome = other ? OUT_OTHER_UNIVERSE : OUT_CAPTURED;
    }
    return hit;
}

#endif
