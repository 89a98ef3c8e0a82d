// Where a ray went: the outcome codes (binding: the geodesic AOV table in
// the README) and what a path hands to the shading.
#ifndef HIT_GLSL
#define HIT_GLSL

#include "variant.glsl"

#define OUT_ESCAPED 0
#define OUT_CAPTURED 1
#define OUT_DISK 2
#define OUT_NO_STEPS 3

struct Hit {
    int outcome;
    vec3 pos;   // disk crossing point
    vec3 dir;   // final direction (escaped)
    float g;    // redshift at a disk hit
    vec3 glow;  // light gathered from the disk on the way
    float trans; // transmittance of that disk (1: clear)
    bool disk_ahead; // the trace pass left thin-disk crossings to the disk pass
};

bool volumetric() {
    return DISK_KIND == DISK_VOLUME;
}

#endif
