#version 460
// Composite: exposure, a filmic tone map (Narkowicz's ACES fit, 2016) and sRGB
// encoding into an 8-bit image.

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0) uniform sampler2D hdr;
layout(binding = 1, rgba8) uniform writeonly image2D ldr;

layout(push_constant) uniform Push {
    float exposure;  // linear multiplier, 2^EV
    uint width;
    uint height;
} pc;

vec3 aces_narkowicz(vec3 x) {
    const float a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
    return clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0, 1.0);
}

vec3 srgb_encode(vec3 c) {
    vec3 lo = c * 12.92;
    vec3 hi = 1.055 * pow(c, vec3(1.0 / 2.4)) - 0.055;
    return mix(hi, lo, lessThanEqual(c, vec3(0.0031308)));
}

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (px.x >= int(pc.width) || px.y >= int(pc.height)) return;
    vec3 c = texelFetch(hdr, px, 0).rgb * pc.exposure;
    imageStore(ldr, px, vec4(srgb_encode(aces_narkowicz(c)), 1.0));
}
