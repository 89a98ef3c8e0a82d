#version 460
// Bloom downsample (Jimenez, "Next Generation Post Processing in Call of Duty:
// Advanced Warfare", SIGGRAPH 2014): 13 bilinear taps as five overlapping 2x2
// boxes (centre box 0.5, corner boxes 0.125 each), which removes the aliasing
// of a plain 2x2 box. The first level comes from bloom_prefilter.comp.

#include "color.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D src;
layout(binding = 1, rgba16f) uniform writeonly image2D dst;

layout(push_constant) uniform Push {
    vec2 src_texel;   // 1 / source size
    uvec2 dst_size;
} pc;

vec3 tap(vec2 uv, vec2 o) {
    return textureLod(src, uv + o * pc.src_texel, 0.0).rgb;
}

vec3 box(vec3 a, vec3 b, vec3 c, vec3 d) {
    return 0.25 * (a + b + c + d);
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
    vec3 color = 0.5 * b0 + 0.125 * (b1 + b2 + b3 + b4);
    imageStore(dst, ivec2(p), vec4(storable(color), 1.0));
}
