// The accretion disk's light, whatever path reached it: the emitter's
// colour and brightness at a radius and a redshift, the thin disk's
// structure, the disk frame's azimuth and height, and the redshift of a
// Keplerian emitter seen along a ray.
#ifndef DISK_GLSL
#define DISK_GLSL

#include "bindings.glsl"
#include "params.glsl"
#include "variant.glsl"
#include "blackbody.glsl"
#include "ray_state.glsl"

// The redshift g = nu_obs / nu_emit, seen from far away, of light from an
// emitter on a circular Keplerian orbit: sqrt(1 - 1.5 rs / r) / (1 - Omega
// lambda), with Omega = sqrt(rs / (2 r^3)) its angular velocity and lambda
// the photon's angular momentum about the disk's axis per unit energy (the
// conventions in the README, "Physics"). The one place the formula is
// written: callers pass 1 - 1.5 rs / r and Omega as they have them at hand,
// and `least` keeps the root real inside the photon orbit (gas).
float emitter_g(float one_minus_15u, float omega, float lambda, float least) {
    return sqrt(max(one_minus_15u, least)) / (1.0 - omega * lambda);
}

// The Keplerian angular velocity at radius r.
float keplerian_omega(float rs, float r) {
    return sqrt(0.5 * rs / (r * r * r));
}

// The thin disk's tileable noise (src/render/noise.rs, `disk_noise`).
layout(binding = RM_DISK_NOISE) uniform sampler2D disk_noise;

// Light of the thin disk at radius r whose light reaches us shifted by g_full
// (the conventions in the README, "Physics"): Novikov-Thorne temperature T(r), observed temperature
// g T coloured by the blackbody table, observed bolometric intensity g^4 times
// the emitted T^4. The switches pick which parts of g apply: the gravitational
// part sqrt(1 - rs/r) (colour and brightness), the kinematic rest to the
// colour (Doppler) and to the brightness (beaming).
// Page & Thorne (1974): T^4 ~ f / r with f their relativistic flux for the
// hole's spin (M = 1, x = sqrt(r / M)), zero inside the spin's ISCO; the
// constants come from src/physics/kerr (PageThorne), the peak normaliser
// in nt_peak.
float page_thorne(float r, float rs) {
    float x = sqrt(2.0 * r / rs);
    vec4 q = P.disk.pt_roots, c = P.disk.pt_coef;
    if (x <= q.x) return 0.0;
    float a = P.metric.spin_hi;  // (the spacetime's: 0 unless the hole spins)
    float br = x - q.x - c.w * log(x / q.x) - c.x * log((x - q.y) / (q.x - q.y))
             - c.y * log((x - q.z) / (q.x - q.z)) - c.z * log((x - q.w) / (q.x - q.w));
    float f = 1.5 / (x * x * (x * x * x - 3.0 * x + 2.0 * a)) * br;
    return max(f / (x * x), 0.0);
}

// The square of the emitter's lapse at radius r (rs; ir = 1 / r), its
// clock against infinity: each metric's (metric.glsl), defined after this
// file by the metric file that includes it.
float metric_emitter_lapse2(float r, float rs, float ir);

vec3 disk_color(float r, float g_full) {
    float rs = P.metric.holes[0].w;
    float r_in = P.disk.inner;
    // One reciprocal for the divisions (dear on a CPU driver).
    float ir = 1.0 / r;
    float f = PAGE_THORNE ? page_thorne(r, rs)
            : max((1.0 - sqrt(r_in * ir)) * (ir * ir * ir), 0.0);
    float t_rel = sqrt(sqrt(f * (1.0 / P.disk.nt_peak)));   // T / T_peak
    // The gravitational part as this observer measures it: emitter's clock
    // against the camera's.
    float lapse2 = max(metric_emitter_lapse2(r, rs, ir), 1e-6), inv_lapse = inversesqrt(lapse2);
    float g_grav = lapse2 * inv_lapse * (1.0 / observer_lapse);
    bool doppler = P.disk.doppler > 0.5, redshift = P.disk.redshift > 0.5, beaming = P.disk.beaming > 0.5;
    float g_kin = g_full * inv_lapse * observer_lapse;
    float g_base = redshift ? g_grav : 1.0;
    float g = doppler ? g_base * g_kin : g_base;          // colour
    float g_i = beaming ? g_base * g_kin : g_base;        // brightness
    vec3 c = blackbody(g * t_rel * P.disk.peak_temperature);
    float gt = g_i * t_rel;
    return c * (P.disk.brightness * gt * gt * gt * gt);
}

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
    return thin_disk_density_at(rs / r, keplerian_omega(rs, r), az, t);
}

// Azimuth of a point in the disk's frame (the AOV's convention).
float disk_azimuth(vec3 p) {
    vec3 d = p - P.metric.holes[0].xyz;
    return atan(dot(d, P.disk.e2), dot(d, P.disk.e1));
}

// Signed height above the disk plane.
float plane_dist(vec3 x) {
    return dot(x - P.metric.holes[0].xyz, P.disk.normal);
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
    return emitter_g(1.0 - 1.5 * rs / r, keplerian_omega(rs, r), lambda, 0.0);
}

#endif
