// Numbers every shader may need, written once.
#ifndef CONSTANTS_GLSL
#define CONSTANTS_GLSL

const float PI = 3.14159265358979;
const float HALF_PI = 1.5707963267948966;

#endif
