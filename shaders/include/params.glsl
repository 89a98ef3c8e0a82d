// Parameters of the ray march, one block per frame written by the host.
// Mirrored by `RaymarchParams` in src/passes/raymarch.rs; a test checks the
// two layouts agree (all vec4, so std430 and std140 lay it out alike). A
// read-only storage buffer rather than a uniform buffer: see RAYMARCH_BINDINGS
// in src/passes/mod.rs for the driver leak that avoids.
#ifndef PARAMS_GLSL
#define PARAMS_GLSL

#define MAX_HOLES 8

// Disk kinds (disk_normal.w).
#define DISK_NONE 0
#define DISK_THIN 1
#define DISK_VOLUME 2

// Sky kinds (sky.x).
#define SKY_BLACK 0
#define SKY_CHECKER 1
#define SKY_STARS 2
#define SKY_IMAGE 3
#define SKY_CATALOGUE 4

// Observer kinds (observer.w), as src/physics/observer.rs.
#define OBS_STATIC 0
#define OBS_ORBITING 1
#define OBS_FALLING 2
#define OBS_FLAT 3

// Temperature range of the blackbody table (log-spaced), kelvin.
#define LUT_MIN_K 500.0
#define LUT_MAX_K 100000.0

struct RaymarchParams {
    vec4 cam_pos;      // xyz: camera position; w: tan(vfov / 2)
    vec4 cam_right;    // xyz: right;           w: aspect (W / H)
    vec4 cam_up;       // xyz: camera up;       w: sub-pixel jitter x (pixels, 0 = centre)
    vec4 cam_fwd;      // xyz: forward;         w: sub-pixel jitter y (pixels, down)
    vec4 disk_normal;  // xyz: unit normal;     w: disk kind (the ray march compiles its own in: DISK_KIND)
    vec4 disk;         // x: inner radius, y: outer radius, z: brightness, w: Doppler beaming on
    vec4 disk_e1;      // xyz: in-plane basis vector (azimuth 0)
    vec4 disk_e2;      // xyz: e1 x normal (azimuth 90 degrees)
    vec4 disk_temp;    // x: peak temperature (K), y: NT profile at the peak, z: Doppler on, w: redshift on
    vec4 vol0;         // volumetric disk: x: half height, y: vertical falloff, z: radial falloff, w: noise scale
    vec4 plane_pos;    // grid plane: xyz: a point on it, w: 1 on / 0 off (compiled in: GRID_PLANE)
    vec4 plane_n;      // xyz: unit normal facing the camera, w: line spacing
    vec4 plane_u;      // xyz: in-plane axis, w: half size
    vec4 vol1;         // x: noise octaves, y: rotation time (speed x time), z: lit (emission scale), w: 1 blackbody / 0 colour map
    vec4 sky;          // x: sky kind (compiled in: SKY_KIND), y: checker squares or star density, z: brightness, w: galaxy band
    vec4 integ;        // x: tolerance, y: escape radius, z: gravity on (1/0), w: unused
    vec4 observer;     // xyz: the camera's velocity in the static frame (world axes); w: observer kind
    vec4 observer_r;   // xyz: unit vector from the reference hole to the camera; w: sqrt(1 - rs/r) (1: flat)
    vec4 disk_look;    // thin disk: x: structure, y: opacity, z: speed (x Keplerian), w: unused
    vec4 sky_m0;       // catalogue sky: rows of the world-to-galactic matrix (xyz);
    vec4 sky_m1;       //   sky_m0.w: flux of a magnitude-0 star
    vec4 sky_m2;
    uvec4 counts;      // x: hole count, y: width, z: height, w: step budget
    vec4 holes[MAX_HOLES]; // xyz: position, w: rs
};

layout(std430, binding = 1) readonly buffer RaymarchParamsBlock {
    RaymarchParams params;
} params_block;

// The parameters as the shader reads them: a private copy taken by
// read_params() at the top of main, before any branch. Lavapipe reads a
// buffer at a uniform address once for the SIMD group only where no lane can
// be masked off; inside a branch, a loop or after a return it reads it lane by
// lane in a loop of its own (measured: a tenth of the trace pass's time and
// a sixth of the disk pass's). Only the fields a pipeline uses are read.
RaymarchParams P;

void read_params() {
    P = params_block.params;
}

#endif
