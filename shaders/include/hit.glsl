// Where a ray went: the outcome codes (binding: the geodesic AOV table in
// the README) and what a path hands to the shading.
#ifndef HIT_GLSL
#define HIT_GLSL

#include "variant.glsl"

#define OUT_ESCAPED 0
#define OUT_CAPTURED 1
#define OUT_DISK 2
#define OUT_NO_STEPS 3
#define OUT_NO_RAY 4     // no ray: outside a fisheye's image circle
#define OUT_OTHER_UNIVERSE 5  // from inside the horizon: light from the eternal hole's other universe

struct Hit {
    int outcome;
    vec3 pos;   // disk crossing point
    vec3 dir;   // final direction (escaped)
    float g;    // redshift at a disk hit
    vec3 glow;  // light gathered from the disk on the way
    float trans; // transmittance of that disk (1: clear)
    bool deferred; // the split's trace pass left this path to its second pass (the thin
                   // disk's crossings; a spinning hole's rarer paths: metric.glsl)
    float delay; // LIGHT_DELAY: the light's travel time from the disk hit to the camera
                 // (scene units, c = 1), for paths that leave the disk's shading to main
    vec4 pol;     // POLARIZATION: a disk hit's (cos 2 chi, sin 2 chi, I_e, angle defined)
                  // (polarization.glsl, pol_of)
    bool far_sky; // OUT_OTHER_UNIVERSE whose path reached the other universe's infinity
                  // along dir ([sky] other_universe = "mirror" shows a copy of the sky)
};

// A path's hit before it has gone anywhere: `outcome` until the path says
// otherwise, at `pos` heading along `dir`, no disk light gathered yet.
Hit hit_start(int outcome, vec3 pos, vec3 dir) {
    Hit hit;
    hit.outcome = outcome;
    hit.pos = pos;
    hit.dir = dir;
    hit.g = 0.0;
    hit.glow = vec3(0.0);
    hit.trans = 1.0;
    hit.deferred = false;
    hit.delay = 0.0;
    hit.far_sky = false;
    hit.pol = vec4(0.0);
    return hit;
}

bool volumetric() {
    return DISK_KIND == DISK_VOLUME;
}

#endif
