#version 460
// Bloom upsample (Jimenez 2014): a tent filter over the smaller level, added
// into the larger one, so each level accumulates all smaller ones. The tent is
// four bilinear taps at (+-a, +-a) source texels: each tap is itself a 2x2
// tent, so four of them give a 3x3-wide tent; a = 0.707 radius gives the
// same spread (variance) as the nine-tap [1 2 1] tent at +-radius, for four
// filtered taps instead of nine (they are dear on a CPU driver).

#include "color.glsl"

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D src;             // level n + 1
layout(binding = 1, rgba16f) uniform image2D dst;      // level n, read and written

layout(push_constant) uniform Push {
    vec2 src_texel;   // 1 / size of level n + 1
    uvec2 dst_size;
    float radius;     // tent radius in source texels
} pc;

void main() {
    uvec2 p = gl_GlobalInvocationID.xy;
    if (p.x >= pc.dst_size.x || p.y >= pc.dst_size.y) return;
    vec2 uv = (vec2(p) + 0.5) / vec2(pc.dst_size);
    vec2 o = pc.src_texel * (0.70710678 * pc.radius);
    vec3 s = textureLod(src, uv + o, 0.0).rgb + textureLod(src, uv - o, 0.0).rgb
           + textureLod(src, uv + vec2(o.x, -o.y), 0.0).rgb + textureLod(src, uv + vec2(-o.x, o.y), 0.0).rgb;
    vec3 c = imageLoad(dst, ivec2(p)).rgb + 0.25 * s;
    imageStore(dst, ivec2(p), vec4(storable(c), 1.0));
}
