#version 460
// Bloom prefilter: the full-resolution HDR image down to a quarter of its
// size through a tent (linear B-spline) four source texels wide on each side,
// then the bright pass with a soft knee. The tent is separable and its eight
// weights per axis, (0.5 1.5 2.5 3.5 3.5 2.5 1.5 0.5) / 16, pair up into four
// bilinear taps at +-0.917 and +-2.75 texels (weights 0.375 and 0.125), so
// sixteen filtered taps read every one of the 8x8 texels it weighs. The tent
// is continuous: a bright pixel moving across texels changes the bloom
// smoothly, so no Karis average is needed against flicker (it would also dim
// thin bright lines such as the photon ring).

#include "color.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D src;
layout(binding = 1, rgba16f) uniform writeonly image2D dst;

layout(push_constant) uniform Push {
    vec2 src_texel;   // 1 / source size
    uvec2 dst_size;
    float threshold;  // bright pass: brightest channel above which light blooms
    float knee;       // soft knee width
} pc;

void main() {
    uvec2 p = gl_GlobalInvocationID.xy;
    if (p.x >= pc.dst_size.x || p.y >= pc.dst_size.y) return;
    vec2 uv = (vec2(p) + 0.5) / vec2(pc.dst_size);
    const vec4 OFFSET = vec4(-2.75, -0.9166667, 0.9166667, 2.75);
    const vec4 WEIGHT = vec4(0.125, 0.375, 0.375, 0.125);
    vec3 color = vec3(0.0);
    for (int j = 0; j < 4; ++j) {
        vec3 row = vec3(0.0);
        for (int i = 0; i < 4; ++i) {
            vec2 o = vec2(OFFSET[i], OFFSET[j]) * pc.src_texel;
            row += WEIGHT[i] * textureLod(src, uv + o, 0.0).rgb;
        }
        color += WEIGHT[j] * row;
    }
    // Soft-knee bright pass on the brightest channel.
    float br = max(color.r, max(color.g, color.b));
    float rq = clamp(br - pc.threshold + pc.knee, 0.0, 2.0 * pc.knee);
    rq = rq * rq / (4.0 * pc.knee + 1e-5);
    color *= max(rq, br - pc.threshold) / max(br, 1e-5);
    imageStore(dst, ivec2(p), vec4(storable(color), 1.0));
}
