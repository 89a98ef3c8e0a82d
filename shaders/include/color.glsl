// Colour helpers shared by the post-processing shaders.
#ifndef COLOR_GLSL
#define COLOR_GLSL

// Rec. 709 / sRGB luminance of linear RGB.
float luminance(vec3 c) {
    return dot(c, vec3(0.2126, 0.7152, 0.0722));
}

#endif
