#version 460
// Bloom upsample (Jimenez 2014): a 3x3 tent filter over the smaller level,
// added into the larger one, so each level accumulates all smaller ones.

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
    vec2 o = pc.src_texel * pc.radius;
    vec3 s = 4.0 * textureLod(src, uv, 0.0).rgb;
    s += 2.0 * (textureLod(src, uv + vec2(o.x, 0.0), 0.0).rgb + textureLod(src, uv - vec2(o.x, 0.0), 0.0).rgb
              + textureLod(src, uv + vec2(0.0, o.y), 0.0).rgb + textureLod(src, uv - vec2(0.0, o.y), 0.0).rgb);
    s += textureLod(src, uv + o, 0.0).rgb + textureLod(src, uv - o, 0.0).rgb
       + textureLod(src, uv + vec2(o.x, -o.y), 0.0).rgb + textureLod(src, uv + vec2(-o.x, o.y), 0.0).rgb;
    vec3 c = imageLoad(dst, ivec2(p)).rgb + s / 16.0;
    imageStore(dst, ivec2(p), vec4(c, 1.0));
}
