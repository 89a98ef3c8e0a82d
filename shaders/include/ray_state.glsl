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

// A falling camera of one non-rotating hole (RAIN_FORM: the rain form of
// camera.glsl, src/physics/rain.rs): the photon's energy per unit
// of the frequency the camera sees, E / omega = 1 + v d_r (at most 0: the
// light came from the other universe of the eternal hole), and (E / p_t)^2,
// E over the photon's momentum across the radial direction, squared, from
// which the path's constant (rs / b)^2 = u0^2 (E / p_t)^2 is formed without
// the cancellation of du^2 + u0^2 (1 - u0) inside.
float rain_energy = 1.0;
float rain_k2 = -1.0;

// A spinning hole's camera: 1 / E = (1 - omega lambda) / alpha, what turns
// a shift seen from infinity into the one the camera's ZAMO (or, between
// the horizons, the falling camera itself) sees: the g of light from rest
// at infinity before the observer's own Doppler factor (set per pixel by
// metric/kerr.glsl; 1 for every other metric).
float kerr_zamo_g = 1.0;

// A pinhole pixel's place on the image plane at distance 1 (along right
// and up; pinhole() sets it): the spinning hole's 64-bit build forms the
// ray's direction again from it (kerr/camera.glsl, kerr_pixel_dir).
vec2 pinhole_xy = vec2(0.0);

// Per-pixel offset of the volume's samples within their spacing, set by
// main(): a fixed spacing would show as rings where rays run along the
// density gradient; a hashed offset turns them into fine, stable grain.
float volume_jitter = 0.5;

#endif
