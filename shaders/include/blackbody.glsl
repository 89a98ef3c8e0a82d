// The colour of a blackbody: a table of linear sRGB colours of luminance 1,
// log-spaced in temperature (src/physics/blackbody.rs), bound at RM_DISK_LUT.
#ifndef BLACKBODY_GLSL
#define BLACKBODY_GLSL

#include "bindings.glsl"
#include "params.glsl"

// Linear sRGB colour of luminance 1 per blackbody temperature, log-spaced
// from LUT_MIN_K to LUT_MAX_K (src/physics/blackbody.rs).
layout(binding = RM_DISK_LUT) uniform sampler2D disk_lut;

// Luminance-1 linear sRGB colour of a blackbody at t kelvin.
vec3 blackbody(float t) {
    float u = (log2(max(t, 1.0)) - log2(LUT_MIN_K)) / (log2(LUT_MAX_K) - log2(LUT_MIN_K));
    return textureLod(disk_lut, vec2(clamp(u, 0.0, 1.0), 0.5), 0.0).rgb;
}

#endif
