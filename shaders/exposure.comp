#version 460
// Automatic exposure, metered as game engines do (a histogram of log
// luminance, the mean of a band of its percentiles): one workgroup reads a
// grid of at most 256 x 144 pixels of the HDR image, bins the log2 luminance
// of the lit ones (the black shadow and empty sky would pull the mean down
// without saying anything about the light), each weighted by its brightness,
// and writes the exposure that brings the band's mean luminance to the key
// value (pc.key: passes/exposure.rs's KEY, 0.45; above mid grey, since the
// band is weighted toward the bright pixels). The result goes to a one-float
// storage buffer: a
// uniform-address buffer load is one scalar load on a CPU driver, where a
// texel fetch is a per-pixel gather.

layout(local_size_x = 256) in;

#include "color.glsl"

layout(binding = 0) uniform sampler2D hdr;
layout(std430, binding = 1) writeonly buffer Result {
    float exposure;
} result;

layout(push_constant) uniform Push {
    uvec2 size;       // HDR image size
    float low;        // band of the lit pixels' histogram metered, as fractions
    float high;
    float key;        // luminance the band's mean is brought to
} pc;

const int BINS = 64;
const float LOG_MIN = -10.0;   // log2 luminance range of the histogram
const float LOG_MAX = 12.0;
const float LIT = 1e-3;        // luminance below which a pixel is not metered

shared uint hist[BINS];

void main() {
    uint t = gl_LocalInvocationIndex;
    if (t < uint(BINS)) hist[t] = 0u;
    barrier();
    uvec2 n = min(pc.size, uvec2(256u, 144u));
    vec2 scale = vec2(pc.size) / vec2(n);
    for (uint i = t; i < n.x * n.y; i += 256u) {
        vec2 s = vec2(float(i % n.x), float(i / n.x));
        ivec2 p = ivec2((s + 0.5) * scale);
        float l = luminance(texelFetch(hdr, p, 0).rgb);
        if (l > LIT) {
            float f = (log2(l) - LOG_MIN) / (LOG_MAX - LOG_MIN);
            uint b = uint(clamp(f * float(BINS), 0.0, float(BINS - 1)));
            // Brighter pixels weigh more (about l^0.73, up to 2^16 each so
            // the 36,864 samples cannot overflow): the light that fills the
            // frame sets its exposure, not a sky of faint stars around a
            // small bright disk.
            atomicAdd(hist[b], uint(exp2(16.0 * float(b) / float(BINS - 1))));
        }
    }
    barrier();
    if (t != 0u) return;
    uint total = 0u;
    for (int b = 0; b < BINS; ++b) total += hist[b];
    float lo = pc.low * float(total), hi = pc.high * float(total);
    float acc = 0.0, weight = 0.0, sum = 0.0;
    for (int b = 0; b < BINS; ++b) {
        float count = float(hist[b]);
        // The part of this bin inside the band [lo, hi].
        float part = clamp(acc + count, lo, hi) - clamp(acc, lo, hi);
        float centre = LOG_MIN + (float(b) + 0.5) * ((LOG_MAX - LOG_MIN) / float(BINS));
        sum += part * centre;
        weight += part;
        acc += count;
    }
    // Nothing lit: the exposure of a frame whose band sits at the key.
    float mean_log = weight > 0.0 ? sum / weight : log2(pc.key);
    result.exposure = pc.key / exp2(mean_log);
}
