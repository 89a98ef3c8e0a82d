// Colour helpers shared by the post-processing shaders.
#ifndef COLOR_GLSL
#define COLOR_GLSL

// Rec. 709 / sRGB luminance of linear RGB.
float luminance(vec3 c) {
    return dot(c, vec3(0.2126, 0.7152, 0.0722));
}

// Light as a half-float image can hold it: NaN (from any source) becomes 0
// and values past the largest finite half float are held at it (a larger one
// would be stored as infinity), so no pixel carries NaN or infinity into
// bloom, exposure or the output. Every store of light into a 16-bit float
// image goes through it.
#define HALF_MAX 65504.0  // sky.rs MAX_SKY_VALUE (tests/layout.rs)
vec3 storable(vec3 c) {
    return clamp(mix(c, vec3(0.0), isnan(c)), vec3(0.0), vec3(HALF_MAX));
}

// The same for signed values (the polarized picture's Stokes Q and U):
// NaN becomes 0, each held within +-HALF_MAX.
vec3 storable_signed(vec3 c) {
    return clamp(mix(c, vec3(0.0), isnan(c)), vec3(-HALF_MAX), vec3(HALF_MAX));
}

#endif
