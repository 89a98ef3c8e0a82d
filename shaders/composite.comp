#version 460
// Composite: bloom added to the HDR image, exposure in EV stops (times the
// metered exposure of exposure.comp when automatic), a filmic tone map,
// sRGB encoding and a small triangular dither so 8-bit gradients do not
// band. Tone maps: Narkowicz's one-line fit of the ACES RRT+ODT ("ACES Filmic
// Tone Mapping Curve", 2016) and Stephen Hill's fuller fit (the
// "BakingLab" RRT+ODT fit with the sRGB-to-ACES input and output matrices).

layout(local_size_x = 8, local_size_y = 8) in;

#include "color.glsl"

layout(binding = 0) uniform sampler2D hdr;
#ifdef HDR_OUTPUT
// --exr-post: bloom and exposure applied, no tone map, linear HDR out.
layout(binding = 1, rgba16f) uniform writeonly image2D ldr;
#else
layout(binding = 1, rgba8) uniform writeonly image2D ldr;
#endif
layout(binding = 2) uniform sampler2D bloom;   // level 0 of the bloom chain
// The automatic exposure (exposure.comp): one float at one address for every
// pixel, a single scalar load where a 1x1 texture would be fetched per pixel.
layout(std430, binding = 3) readonly buffer Metered {
    float exposure;
} metered;

#define TONEMAP_ACES_HILL 0
#define TONEMAP_ACES_NARKOWICZ 1
#define TONEMAP_LINEAR 2
#define TONEMAP_HUE_PRESERVING 3

layout(push_constant) uniform Push {
    float exposure;        // linear multiplier, 2^EV
    uint width;
    uint height;
    float bloom_strength;
    float dither;          // amplitude in 8-bit steps (0: off)
    float saturation;      // 1: as rendered
} pc;

// Specialization constants (src/passes/composite.rs, `Variant`): what a frame
// does not use is compiled out (a CPU driver runs every branch for every pixel).
layout(constant_id = 0) const bool UPSCALE = false;
layout(constant_id = 1) const uint TONEMAP = TONEMAP_ACES_HILL;
layout(constant_id = 2) const bool BLOOM = true;
layout(constant_id = 3) const bool AUTO_EXPOSURE = false;
// The saturation is not 1.
layout(constant_id = 4) const bool SATURATE = false;
// Each invocation finishes a 2x2 block of pixels, which lies inside one
// bilinear cell of the quarter-size bloom level (the output and the ray
// march the same size, a multiple of 4 on each side): four texel fetches
// of bloom for four pixels, where four filtered taps would read sixteen.
layout(constant_id = 5) const bool BLOCKS = false;
// The HDR image's alpha marks pixels with no ray (0: a fisheye's corners):
// kept black and transparent. Off, every pixel is opaque.
layout(constant_id = 6) const bool MASK = false;

vec3 aces_narkowicz(vec3 x) {
    const float a = 2.51, b = 0.03, c = 2.43, d = 0.59, e = 0.14;
    return clamp((x * (a * x + b)) / (x * (c * x + d) + e), 0.0, 1.0);
}

vec3 aces_hill(vec3 color) {
    const mat3 input_mat = mat3(0.59719, 0.07600, 0.02840,
                                0.35458, 0.90834, 0.13383,
                                0.04823, 0.01566, 0.83777);
    const mat3 output_mat = mat3(1.60475, -0.10208, -0.00327,
                                 -0.53108, 1.10813, -0.07276,
                                 -0.07367, -0.00605, 1.07602);
    vec3 v = input_mat * color;
    vec3 a = v * (v + 0.0245786) - 0.000090537;
    vec3 b = v * (0.983729 * v + 0.4329510) + 0.238081;
    return clamp(output_mat * (a / b), 0.0, 1.0);
}

// The tone curve on the brightest channel, the pixel scaled by it: hue and
// saturation are kept (a blue-white or orange-red blackbody stays so however
// bright) and no channel clips. The curve is Hill's RRT+ODT rational fit on
// one value, scaled so it tends to 1: 0.983729 a(m) / b(m); here divided by
// m in the same division.
vec3 hue_preserving(vec3 c) {
    float m = max(max(c.r, c.g), c.b);
    float a = m * (m + 0.0245786) - 0.000090537;
    float b = m * (0.983729 * m + 0.4329510) + 0.238081;
    float k = max(0.983729 * a, 0.0) / (b * m);
    return m > 1e-12 ? c * k : vec3(0.0);
}

// The sRGB transfer curve for c in [0, 1]. Above the linear toe,
// 1.055 c^(1/2.4) - 0.055 is replaced by a minimax fit in 1, c^(1/2),
// c^(1/4), c^(3/4) and c (two square roots instead of a pow, which a CPU
// driver builds from log2 and exp2, and one fewer than a fit without the
// constant): off by at most 0.009 of an 8-bit step over [0.0031308, 1] (in
// f32), far below the dither.
vec3 srgb_encode(vec3 c) {
    vec3 lo = c * 12.92;
    vec3 s1 = sqrt(c), s2 = sqrt(s1);
    vec3 hi = -0.06461145 + 1.12268523 * s1 + 0.19613488 * s2 - 0.33550675 * (s1 * s2)
            + 0.08133251 * c;
    return mix(hi, lo, lessThanEqual(c, vec3(0.0031308)));
}

// Integer hash (Jarzynski & Olano 2020, PCG-style): 32 random bits.
uint hash(uvec2 p) {
    uint v = p.x * 1664525u + p.y * 1013904223u;
    v = v * 747796405u + 2891336453u;
    uint w = ((v >> ((v >> 28u) + 4u)) ^ v) * 277803737u;
    return (w >> 22u) ^ w;
}

// Exposure, saturation, tone map, sRGB and dither of pixel px, stored (with
// MASK, scaled by the ray march's alpha and carrying it).
void finish(ivec2 px, vec3 c, float alpha) {
    alpha = MASK ? alpha : 1.0;
    c *= alpha;
    c *= AUTO_EXPOSURE ? pc.exposure * metered.exposure : pc.exposure;
    if (SATURATE) {
        float l = luminance(c);
        c = max(l + pc.saturation * (c - l), 0.0);
    }
#ifdef HDR_OUTPUT
    imageStore(ldr, px, vec4(storable(c), alpha));
    return;
#endif
    vec3 t = TONEMAP == TONEMAP_HUE_PRESERVING ? hue_preserving(c)
           : TONEMAP == TONEMAP_ACES_HILL ? aces_hill(c)
           : TONEMAP == TONEMAP_ACES_NARKOWICZ ? aces_narkowicz(c)
           : clamp(c, 0.0, 1.0);
    vec3 s = srgb_encode(t);
    // Triangular dither of +-1 step, zero mean: the sum of two uniform
    // numbers, the hash's two 16-bit halves.
    uint hb = hash(uvec2(px));
    float n = float((hb & 0xffffu) + (hb >> 16u)) * (1.0 / 65536.0) - 1.0;
    s += n * pc.dither / 255.0;
    imageStore(ldr, px, vec4(clamp(s * alpha, 0.0, 1.0), alpha));
}

void main() {
    if (BLOCKS) {
        ivec2 base = 2 * ivec2(gl_GlobalInvocationID.xy);
        if (base.x >= int(pc.width) || base.y >= int(pc.height)) return;
        // Pixel p's bloom coordinate is (p + 0.5) / 4 - 0.5 texels: for the
        // block at 2X that is cell X/2 - 1 at fractions 0.625, 0.875 (X
        // even) or cell (X - 1)/2 at 0.125, 0.375 (X odd); clamped at the
        // edges as the sampler clamps.
        ivec2 blk = ivec2(gl_GlobalInvocationID.xy);
        ivec2 odd = blk & 1;
        ivec2 cell = (blk >> 1) - 1 + odd;
        vec2 f0 = mix(vec2(0.625), vec2(0.125), vec2(odd));
        ivec2 last = textureSize(bloom, 0) - 1;
        ivec2 c0 = clamp(cell, ivec2(0), last), c1 = clamp(cell + 1, ivec2(0), last);
        vec3 b00 = texelFetch(bloom, c0, 0).rgb, b10 = texelFetch(bloom, ivec2(c1.x, c0.y), 0).rgb;
        vec3 b01 = texelFetch(bloom, ivec2(c0.x, c1.y), 0).rgb, b11 = texelFetch(bloom, c1, 0).rgb;
        for (int dy = 0; dy < 2; ++dy) {
            for (int dx = 0; dx < 2; ++dx) {
                vec2 f = f0 + 0.25 * vec2(dx, dy);
                vec3 b = mix(mix(b00, b10, f.x), mix(b01, b11, f.x), f.y);
                ivec2 px = base + ivec2(dx, dy);
                vec4 h = texelFetch(hdr, px, 0);
                finish(px, h.rgb + pc.bloom_strength * b, h.a);
            }
        }
        return;
    }
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (px.x >= int(pc.width) || px.y >= int(pc.height)) return;
    vec2 uv = (vec2(px) + 0.5) / vec2(pc.width, pc.height);
    // The ray march may run at a fraction of the output size (the window's
    // render scale): then it is upscaled here, bilinearly.
    vec4 h = UPSCALE ? textureLod(hdr, uv, 0.0) : texelFetch(hdr, px, 0);
    vec3 c = h.rgb;
    if (BLOOM) {
        c += pc.bloom_strength * textureLod(bloom, uv, 0.0).rgb;
    }
    finish(px, c, h.a);
}
