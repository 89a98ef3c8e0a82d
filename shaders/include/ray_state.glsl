// What main() sets once per pixel before the path is traced, and the
// shading along the path reads: the observer's factor on redshifts and the
// volume's sample offset.
#ifndef RAY_STATE_GLSL
#define RAY_STATE_GLSL

// What turns g seen from infinity into g seen by the camera's observer
// (src/physics/observer.rs), set by camera_ray() (camera.glsl).
float observer_g = 1.0;

// The lapse sqrt(1 - rs/r) of the static frame at the ray's origin, as the
// observer's clock runs against infinity (1 for a flat observer), set by
// camera_ray(): the disk's gravitational shift is measured against it.
float observer_lapse = 1.0;

// Per-pixel offset of the volume's samples within their spacing, set by
// main(): a fixed spacing would show as rings where rays run along the
// density gradient; a hashed offset turns them into fine, stable grain.
float volume_jitter = 0.5;

#endif
