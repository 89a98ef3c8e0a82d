#version 460
// Bloom downsample (Jimenez, "Next Generation Post Processing in Call of Duty:
// Advanced Warfare", SIGGRAPH 2014): 13 bilinear taps as five overlapping 2x2
// boxes (centre box 0.5, corner boxes 0.125 each), which removes the aliasing
// of a plain 2x2 box. The first level (from the full-resolution HDR image)
// weights each box by 1 / (1 + luma), Karis's average, so single very bright
// pixels cannot flicker, and applies the bright-pass threshold with a soft knee.

layout(local_size_x = 8, local_size_y = 8) in;

#include "color.glsl"

layout(binding = 0) uniform sampler2D src;
layout(binding = 1, rgba16f) uniform writeonly image2D dst;

layout(push_constant) uniform Push {
    vec2 src_texel;   // 1 / source size
    uvec2 dst_size;
    float threshold;  // bright pass: luminance above which light blooms
    float knee;       // soft knee width
    uint first;       // 1: Karis average and threshold (the prefilter)
} pc;

vec3 tap(vec2 uv, vec2 o) {
    return textureLod(src, uv + o * pc.src_texel, 0.0).rgb;
}

vec3 box(vec3 a, vec3 b, vec3 c, vec3 d) {
    vec3 s = 0.25 * (a + b + c + d);
    return s;
}

float karis(vec3 s) {
    return 1.0 / (1.0 + luminance(s));
}

void main() {
    uvec2 p = gl_GlobalInvocationID.xy;
    if (p.x >= pc.dst_size.x || p.y >= pc.dst_size.y) return;
    vec2 uv = (vec2(p) + 0.5) / vec2(pc.dst_size);

    vec3 a = tap(uv, vec2(-2.0, -2.0)), b = tap(uv, vec2(0.0, -2.0)), c = tap(uv, vec2(2.0, -2.0));
    vec3 d = tap(uv, vec2(-1.0, -1.0)), e = tap(uv, vec2(1.0, -1.0));
    vec3 f = tap(uv, vec2(-2.0, 0.0)), g = tap(uv, vec2(0.0, 0.0)), h = tap(uv, vec2(2.0, 0.0));
    vec3 i = tap(uv, vec2(-1.0, 1.0)), j = tap(uv, vec2(1.0, 1.0));
    vec3 k = tap(uv, vec2(-2.0, 2.0)), l = tap(uv, vec2(0.0, 2.0)), m = tap(uv, vec2(2.0, 2.0));

    vec3 b0 = box(d, e, i, j);       // centre
    vec3 b1 = box(a, b, f, g);       // top left
    vec3 b2 = box(b, c, g, h);       // top right
    vec3 b3 = box(f, g, k, l);       // bottom left
    vec3 b4 = box(g, h, l, m);       // bottom right
    vec3 color;
    if (pc.first == 1u) {
        float w0 = 0.5 * karis(b0), w1 = 0.125 * karis(b1), w2 = 0.125 * karis(b2),
              w3 = 0.125 * karis(b3), w4 = 0.125 * karis(b4);
        color = (w0 * b0 + w1 * b1 + w2 * b2 + w3 * b3 + w4 * b4) / (w0 + w1 + w2 + w3 + w4);
        // Soft-knee bright pass on the brightest channel.
        float br = max(color.r, max(color.g, color.b));
        float rq = clamp(br - pc.threshold + pc.knee, 0.0, 2.0 * pc.knee);
        rq = rq * rq / (4.0 * pc.knee + 1e-5);
        color *= max(rq, br - pc.threshold) / max(br, 1e-5);
    } else {
        color = 0.5 * b0 + 0.125 * (b1 + b2 + b3 + b4);
    }
    imageStore(dst, ivec2(p), vec4(color, 1.0));
}
