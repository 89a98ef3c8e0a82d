// The volumetric disk (the film look): a slab of glowing
// gas around the first hole whose density falls with height and radius, cut
// into filaments by octaves of gradient noise that turn with the Keplerian
// angular velocity of their radius (so the inner parts shear ahead of the
// outer ones). The noise is read from a precomputed tileable volume
// (src/render/noise.rs, `volume_noise`). Light is gathered by
// emission-absorption: colour += T * emission * ds, T *= exp(-sigma ds).
#ifndef VOLUME_GLSL
#define VOLUME_GLSL

#include "bindings.glsl"
#include "params.glsl"
#include "variant.glsl"
#include "ray_state.glsl"
#include "disk.glsl"
#include "polarization.glsl"

// The volumetric disk's noise volume, three octaves in r, g, b
// (src/render/noise.rs, `volume_noise`).
layout(binding = RM_VOLUME_NOISE) uniform sampler3D volume_noise;

// The noise volume's period in lattice units of its first octave
// (VOLUME_NOISE_PERIOD in src/render/noise.rs, checked by tests/layout.rs).
#define VOLUME_NOISE_PERIOD_XZ 16.0
#define VOLUME_NOISE_PERIOD_Y 8.0

// The film look's colour map: white-yellow inside to deep orange outside.
vec3 volume_colormap(float r) {
    float t = clamp((r - P.disk.inner) / max(P.disk.outer - P.disk.inner, 1e-3), 0.0, 1.0);
    vec3 inner = vec3(1.0, 0.85, 0.55);
    vec3 outer = vec3(0.9, 0.35, 0.08);
    return mix(inner, outer, sqrt(t)) * P.disk.brightness;
}

// Density at p (0 outside the slab).
float volume_density(vec3 p, out float r) {
    vec3 d = p - P.metric.holes[0].xyz;
    vec3 n = P.disk.normal;
    float y = dot(d, n);
    vec3 q = d - y * n;
    r = length(q);
    float H = P.volume.half_height;
    float r_in = P.disk.inner, r_out = P.disk.outer;
    if (abs(y) >= H || r >= r_out || r <= 0.9 * r_in) return 0.0;
    float dens = pow(1.0 - abs(y) / H, P.volume.falloff_v)                 // vertical falloff
               * pow(r_in / r, P.volume.falloff_h)                          // radial falloff
               * smoothstep(0.9 * r_in, 1.1 * r_in, r)
               * (1.0 - smoothstep(0.75 * r_out, r_out, r));
    if (dens < 1e-4) return 0.0;
    // Turn the noise field with the local Keplerian angular velocity.
    float rs = P.metric.holes[0].w;
    float angle = -keplerian_omega(rs, r) * P.disk.rotation_time;
    float ca = cos(angle), sa = sin(angle);
    vec2 xz = vec2(dot(q, P.disk.e1), dot(q, P.disk.e2));
    xz = vec2(ca * xz.x - sa * xz.y, sa * xz.x + ca * xz.y);
    vec3 np = vec3(xz.x, y * 4.0, xz.y) * P.volume.noise_scale;
    // Fractal sum of octaves, then a contrast curve: filaments and gaps.
    // The noise volume holds octaves 1 to 3 (one fetch); octaves 4 to 6 are
    // the same volume at eight times the frequency. A loop, so a CPU driver
    // runs the second fetch only when the scene asks for it.
    int octaves = int(P.volume.octaves);
    // Gradient noise's features are about 1.6 times the size of simplex
    // noise's at the same frequency (what noise_scale was tuned on).
    vec3 tc = np * (1.6 / vec3(VOLUME_NOISE_PERIOD_XZ, VOLUME_NOISE_PERIOD_Y, VOLUME_NOISE_PERIOD_XZ));
    float noise = 0.0;
    float amp = 1.0;
    for (int i = 0; i < (octaves + 2) / 3; ++i) {
        vec3 o = textureLod(volume_noise, tc, 0.0).rgb * 2.0 - 1.0;
        int left = octaves - 3 * i;
        noise += amp * dot(o, vec3(1.0, left > 1 ? 0.5 : 0.0, left > 2 ? 0.25 : 0.0));
        amp *= 0.125;
        tc *= 8.0;
    }
    return dens * clamp(0.55 + 0.9 * noise, 0.0, 2.0) * 3.0;
}

// Sample spacing along a ray, in rs.
const float VOLUME_DS = 0.2;

// The redshift g = nu_obs / nu_emit, as the camera sees it, of the gas on a
// Keplerian orbit at radius r (rs, the disk frame's distance from the hole)
// toward a photon of angular momentum lambda (in the metric's own units):
// each metric defines it (metric.glsl).
float metric_gas_g(float r, float lambda);

// The light the gas at radius r emits toward a photon of angular momentum
// lambda: the blackbody at its shifted temperature (as the thin disk), or
// the film's colour map.
vec3 volume_emission(float r, float lambda) {
    if (!VOLUME_BLACKBODY) return volume_colormap(r);
    return disk_color(max(r, 1.0001 * P.disk.inner), metric_gas_g(r, lambda));
}

// The light gathered at a sample of density dens at radius r, standing for
// a length ds of the path.
void volume_light(float r, float dens, float ds, float lambda, inout vec3 acc, inout float trans) {
    vec3 emit = volume_emission(r, lambda);
    acc += trans * emit * (dens * P.volume.lit * ds);
    trans *= exp(-dens * 0.8 * ds);
}

// A closed-form path's polarized sample at p, a fraction frac along its
// chord (0 to 3) from p0 to p1 (volume_chords): the emission there,
// pol_volume_kerr's or pol_volume_static's (polarization.glsl), from the
// photon the metric knows at that point of its path.
vec4 metric_pol_sample(vec3 p, vec3 p0, vec3 p1, int chord, float frac);

// The samples a closed-form path gives the slab around one of its crossings
// of the disk plane: four chords between five points of the exact path
// carry VOLUME_SAMPLES samples spread evenly along them, offset by the
// pixel's jitter. A fixed count, because on a CPU driver a SIMD group runs
// as many samples as its longest ray would take, and the jitter turns the
// coarser spacing into fine grain that the window's accumulation and
// `render --spp` average away.
const int VOLUME_SAMPLES = 12;

void volume_chords(vec3 pts[5], float lambda, inout vec3 acc, inout float trans) {
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
        float frac = clamp((t - start) / max(l, 1e-9), 0.0, 1.0);
        vec3 q = mix(p0, p1, frac);
        float r;
        float dens = volume_density(q, r);
        // Polarized (the picture, the Stokes AOV): each sample's Stokes
        // vector as the camera sees it, weighted as its light.
        if (POLARIZATION != POL_OFF && dens > 0.0) {
            int chord = past.z ? 3 : past.y ? 2 : past.x ? 1 : 0;
            pol_volume += (trans * dens * ds) * pol_volume_seen(metric_pol_sample(q, p0, p1, chord, frac));
        }
        volume_light(r, dens, ds, lambda, acc, trans);
    }
}

// Gathers light along the chord from a to b (the general path). lambda: the photon's angular
// momentum about the disk axis (for the Doppler shift of each sample).
void volume_segment(vec3 a, vec3 b, float lambda, inout vec3 acc, inout float trans) {
    vec3 n = P.disk.normal;
    vec3 c = P.metric.holes[0].xyz;
    float ya = dot(a - c, n), yb = dot(b - c, n);
    float H = P.volume.half_height;
    if ((ya > H && yb > H) || (ya < -H && yb < -H)) return;
    float len = length(b - a);
    int count = int(clamp(ceil(len / VOLUME_DS), 1.0, 16.0));
    float ds = len / float(count);
    for (int k = 0; k < count; ++k) {
        vec3 p = mix(a, b, (float(k) + volume_jitter) / float(count));
        float r;
        float dens = volume_density(p, r);
        if (dens <= 0.0) continue;
        vec3 emit = volume_emission(r, lambda);
        float sigma = dens * 0.8;
        acc += trans * emit * (dens * P.volume.lit * ds);
        trans *= exp(-sigma * ds);
    }
}

#endif
