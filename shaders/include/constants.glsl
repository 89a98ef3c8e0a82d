// Numbers every shader may need, written once.
#ifndef CONSTANTS_GLSL
#define CONSTANTS_GLSL

const float PI = 3.14159265358979;

#endif
