// Parameters of the ray march, one block per frame written by the host.
// Mirrored by `RaymarchParams` in src/passes/raymarch/params.rs, built there
// in one place from the scene and the frame; tests/layout.rs checks every
// member's offset against the SPIR-V. A read-only storage buffer rather than a
// uniform buffer: see `BINDINGS` in src/passes/raymarch/mod.rs for the
// driver leak that avoids.
#ifndef PARAMS_GLSL
#define PARAMS_GLSL

#include "bindings.glsl"
#include "variant.glsl"

#define MAX_HOLES 8

// Disk kinds (disk.kind).
#define DISK_NONE 0
#define DISK_THIN 1
#define DISK_VOLUME 2

// Sky kinds (sky.kind).
#define SKY_BLACK 0
#define SKY_CHECKER 1
#define SKY_STARS 2
#define SKY_IMAGE 3
#define SKY_CATALOGUE 4

// Observer kinds (observer.kind), as src/physics/observer.rs.
#define OBS_STATIC 0
#define OBS_ORBITING 1
#define OBS_FALLING 2
#define OBS_FLAT 3
#define OBS_ZAMO 4

// Stereo (camera.stereo), as src/camera.
#define STEREO_NONE 0
#define STEREO_ODS 1

// Temperature range of the blackbody table (log-spaced), kelvin.
#define LUT_MIN_K 500.0
#define LUT_MAX_K 100000.0

// The block in named groups. Every vec3 is followed by a float, so each
// group is a whole number of 16-byte rows and std430 places every member
// where the #[repr(C)] Rust twin does (checked member by member).
struct CameraParams {
    vec3 position;  float tan_half_fov;  // tan(vfov / 2)
    vec3 right;     float aspect;        // width / height
    vec3 up;        float jitter_x;      // sub-pixel jitter, pixels (0: the pixel's centre)
    vec3 forward;   float jitter_y;      // (down)
    uvec2 size;                          // image width, height
    float half_fov;                      // vfov / 2, radians (fisheye; the projection is PROJECTION)
    float ipd;                           // ODS: the eyes' distance (rs)
    float stereo;                        // STEREO_*
    float pad[3];
    // What the f32 position and axes above leave of the f64 ones (xyz; w
    // unused): the spinning hole's 64-bit build forms a far camera's place
    // and pinhole rays from their sums (kerr/camera.glsl, kerr_pixel_dir).
    vec4 position_lo;
    vec4 right_lo;
    vec4 up_lo;
    vec4 forward_lo;
};

// The observer's motion; its frame at a ray's origin comes from the metric
// (metric_static_frame, metric.glsl).
struct ObserverParams {
    vec3 velocity;  float kind;          // velocity in the static frame (world axes); OBS_*
    vec3 radial;    float fall_speed;    // RAIN_FORM: hole-to-camera unit vector and sqrt(rs / r)
    float bl_r_hi;  float bl_r_lo;       // KERR_INSIDE: the camera's Boyer-Lindquist r (M), hi + lo in f64
    vec2 _pad;
};

struct MetricParams {
    vec4 holes[MAX_HOLES];               // xyz: position, w: rs
    uint hole_count;
    float gravity;                       // 1 on, 0 off (straight rays)
    float spin_hi;                       // a spinning hole's a*: hi + lo in f64
    float spin_lo;
};

struct IntegratorParams {
    float tolerance;                     // general integrator: local error tolerance
    float escape_radius;
    uint steps;                          // step budget per ray
    float pad;
};

struct DiskParams {
    vec3 normal;    float kind;          // unit normal; DISK_* (compiled in: DISK_KIND)
    vec3 e1;        float rotation_time; // in-plane basis (azimuth 0); speed x time (thin and volumetric)
    vec3 e2;        float structure;     // e1 x normal (azimuth 90 degrees); thin: contrast of filaments
    float inner;    float outer;         // radii
    float brightness;
    float beaming;                       // Doppler beaming on (1/0)
    float peak_temperature;              // kelvin
    float nt_peak;                       // Novikov-Thorne profile at its peak (the normaliser)
    float doppler;                       // Doppler colour shift on (1/0)
    float redshift;                      // gravitational redshift on (1/0)
    float opacity;                       // thin: opacity at average density
    float speed;                         // x Keplerian
    float profile;                       // 0 Newtonian, 1 Page-Thorne (the constants below)
    float pad;                           // (the spin travels in metric: spin_hi, spin_lo)
    vec4 pt_roots;                       // Page-Thorne: sqrt(ISCO / M), the roots of x^3 - 3x + 2a
    vec4 pt_coef;                        // Page-Thorne: the roots' log coefficients, 1.5 a
};

struct VolumeParams {
    float half_height;
    float falloff_v;                     // fall of density with height (exponent)
    float falloff_h;                     // fall of density with radius (exponent)
    float noise_scale;
    float octaves;
    float lit;                           // emission scale
    float blackbody;                     // 1 blackbody, 0 colour map
    float pad;
};

struct SkyParams {
    float kind;                          // SKY_* (compiled in: SKY_KIND)
    float scale;                         // checker squares, star density, the catalogue's grid or an image's width
    float brightness;
    float galaxy;                        // the galaxy band
    vec3 row0;      float star_flux;     // rows of the world-to-galactic matrix; flux of a magnitude-0 star
    vec3 row1;      float shift;         // 1: shifted by the camera's g (sky_shift)
    vec3 row2;      float other;         // 1: the other universe shows a copy of the sky
};

struct PlaneParams {
    vec3 position;  float enabled;       // a point on the grid plane; 1 on (compiled in: GRID_PLANE)
    vec3 normal;    float spacing;       // unit normal facing the camera; line spacing
    vec3 axis;      float half_size;     // in-plane axis; half the side of the square
};

struct PolarizationParams {
    vec3 field;     float fraction;      // the field on (e_(r), e_(phi), e_(z)), unit; polarized share
    float spectral_index;                // alpha
    float emissivity_index;              // n
    uint tiles;                          // field models side by side (1: one picture)
    float _pad;
    vec4 fields[4];                      // each one's field, unit (xyz; `fields`)
};

struct RaymarchParams {
    CameraParams camera;
    ObserverParams observer;
    MetricParams metric;
    IntegratorParams integrator;
    DiskParams disk;
    VolumeParams volume;
    SkyParams sky;
    PlaneParams plane;
    PolarizationParams polarization;
};

layout(std430, binding = RM_PARAMS) readonly buffer RaymarchParamsBlock {
    RaymarchParams params;
} params_block;

// The parameters as the shader reads them: a private copy taken by
// read_params() at the top of main, before any branch. Lavapipe reads a
// buffer at a uniform address once for the SIMD group only where no lane can
// be masked off; inside a branch, a loop or after a return it reads it lane by
// lane in a loop of its own (measured: a tenth of the trace pass's time and
// a sixth of the disk pass's). Only the fields a pipeline uses are read.
RaymarchParams P;

#include "baked.glsl"

void read_params() {
    P = params_block.params;
    P.metric.hole_count = HOLE_COUNT;
    bake_params();
}

#endif
