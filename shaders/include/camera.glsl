// The camera: what a pixel sees. A projection maps a pixel (and the frame's
// sub-pixel jitter) to where its ray starts, its unit direction in the
// observer's own frame and the angle the pixel spans; the observer then
// turns that direction into a coordinate direction (and sets observer_g).
// This file is the only place that knows the projections (the binding camera
// convention, the README's "Cameras"): the pinhole, the equirectangular
// panorama (with omni-directional stereo) and the equidistant fisheye,
// mirrored by src/camera/mod.rs. A new projection is a new function here
// beside them, chosen in camera_ray(), with its twin in src/camera/mod.rs.
#ifndef CAMERA_GLSL
#define CAMERA_GLSL

#include "constants.glsl"
#include "params.glsl"
#include "variant.glsl"
#include "ray_state.glsl"
#include "metric.glsl"
#include "polarization.glsl"

// A pixel's ray.
struct PixelRay {
    vec3 origin;  // where it starts (world)
    vec3 dir;     // unit direction: in the observer's frame from a projection,
                  // a coordinate direction from camera_ray()
    float angle;  // the pixel's angular size (radians), unlensed
    bool valid;   // false: no ray (outside a fisheye's image circle)
};

// The pixel's place with the frame's sub-pixel jitter (0 = the pixel's
// centre), for accumulated anti-aliasing.
vec2 jittered(uvec2 px) {
    return vec2(px) + 0.5 + vec2(P.camera.jitter_x, P.camera.jitter_y);
}

// A direction from its components along right, up and forward.
vec3 camera_axes(float x, float y, float z) {
    return x * P.camera.right + y * P.camera.up + z * P.camera.forward;
}

// The pinhole: every ray from the camera's position through the pixel's
// place (plus jitter) on the image plane at distance 1; the pixel spans
// 2 tan(vfov / 2) / height at the centre.
PixelRay pinhole(uvec2 px) {
    uint w = P.camera.size.x, hgt = P.camera.size.y;
    float tan_half = P.camera.tan_half_fov, aspect = P.camera.aspect;
    vec2 q = jittered(px);
    float sx = (q.x * (2.0 / float(w)) - 1.0) * tan_half * aspect;
    float sy = (1.0 - q.y * (2.0 / float(hgt))) * tan_half;
    PixelRay ray;
    ray.origin = P.camera.position;
    pinhole_xy = vec2(sx, sy);
    ray.dir = normalize(P.camera.forward + sx * P.camera.right + sy * P.camera.up);
    ray.angle = 2.0 * tan_half / float(hgt);
    ray.valid = true;
    return ray;
}

// The equirectangular panorama: longitude across (-pi at the left edge,
// forward at the centre), latitude down (+pi/2 at the top). With ODS the
// image holds two panoramas, the left eye's on top: each column's ray starts
// from its eye's place on the viewing circle (diameter ipd), at right angles
// to the ray's horizontal direction.
PixelRay equirect(uvec2 px) {
    uint w = P.camera.size.x, hgt = P.camera.size.y;
    bool ods = int(P.camera.stereo) == STEREO_ODS;
    uint eye_h = ods ? max(hgt / 2u, 1u) : hgt;
    float eye = 0.0;
    if (ods) {
        eye = px.y >= eye_h ? 1.0 : -1.0;
        if (px.y >= eye_h) px.y = min(px.y - eye_h, eye_h - 1u);
    }
    vec2 q = jittered(px);
    float lon = (q.x * (2.0 / float(w)) - 1.0) * PI;
    float lat = (1.0 - q.y * (2.0 / float(eye_h))) * (0.5 * PI);
    float sl = sin(lon), cl = cos(lon), sa = sin(lat), ca = cos(lat);
    PixelRay ray;
    ray.origin = P.camera.position + (eye * 0.5 * P.camera.ipd) * camera_axes(cl, 0.0, -sl);
    ray.dir = normalize(camera_axes(ca * sl, sa, ca * cl));
    ray.angle = PI / float(eye_h);
    ray.valid = true;
    return ray;
}

// The equidistant fisheye: the angle from forward grows linearly with the
// distance from the image's centre, vfov / 2 at the inscribed circle (180
// degrees: a dome master). Outside the circle no ray.
PixelRay fisheye(uvec2 px) {
    float w = float(P.camera.size.x), hgt = float(P.camera.size.y);
    float s = min(w, hgt);
    vec2 q = jittered(px);
    float x = (2.0 * q.x - w) / s, y = (hgt - 2.0 * q.y) / s;
    float rho = length(vec2(x, y));
    float theta = rho * P.camera.half_fov;
    vec2 u = rho > 0.0 ? vec2(x, y) / rho : vec2(0.0);
    PixelRay ray;
    ray.origin = P.camera.position;
    ray.dir = normalize(camera_axes(sin(theta) * u.x, sin(theta) * u.y, cos(theta)));
    ray.angle = 2.0 * P.camera.half_fov / s;
    ray.valid = rho <= 1.0;
    return ray;
}

// A falling camera's pixel direction (its own frame: the rain observer's,
// the flat frame of Painleve-Gullstrand coordinates; src/physics/rain.rs)
// as a coordinate direction, valid outside, at and inside the horizon
// (RAIN_FORM: one non-rotating hole). The photon arriving along -dir has
// E / omega = 1 + v d_r and transverse momentum |d_t|; traced back it moves
// out at the rate v + d_r against |d_t| across (outside, the static frame's
// squeezed direction). The camera measures g = omega / |E| of light from
// rest at infinity (E < 0: the other universe's).
//
// The camera's own place has its radial direction and speed from the host
// in f64, each one rounding (E = 1 + v d_r cancels where light comes from
// below, and near the photon orbit the path's constant amplifies its error
// twelvefold); an ODS eye off that place forms them here.
vec3 rain_to_coordinate(StaticFrame frame, vec3 dir) {
    bool eye = int(P.camera.stereo) == STEREO_ODS;
    float v = eye ? sqrt(frame.fall2) : P.observer.fall_speed;
    vec3 rh = eye ? frame.radial : P.observer.radial;
    float dr = dot(dir, rh);
    vec3 dt = dir - dr * rh;
    float en = 1.0 + v * dr;
    rain_energy = en;
    rain_k2 = en * en / max(dot(dt, dt), 1e-30);
    // No frame at rest to split the gravitational part from the rest
    // (disk_color): the camera's clock is taken as infinity's.
    observer_lapse = 1.0;
    // (E < 0: the other universe's light, g against its own infinity.)
    observer_g = 1.0 / max(abs(en), 1e-6);
    return normalize((v + dr) * rh + dt);
}

// A direction measured in the observer's own frame (src/physics/observer.rs)
// at `origin` as a coordinate direction: aberration by its velocity into the
// static frame there (the metric's, metric_static_frame), then that frame's
// radial squeeze; its clock and motion scale the redshift it measures
// (observer_g, observer_lapse). A falling camera of one non-rotating hole
// takes the rain form instead; one between a spinning hole's horizons (or
// just outside them) keeps its own direction (KERR_INSIDE).
vec3 observer_to_coordinate(vec3 origin, vec3 dir) {
    if (int(P.observer.kind) != OBS_FLAT) {
        StaticFrame frame = metric_static_frame(origin);
        if (RAIN_FORM) return rain_to_coordinate(frame, dir);
        if (KERR_INSIDE) {
            // No frame at rest inside a spinning hole: the direction stays
            // the falling camera's, for the metric's falling frame
            // (kerr_falling_camera); its clock is taken as infinity's.
            observer_lapse = 1.0;
            observer_g = 1.0;
            return dir;
        }
        vec3 beta = P.observer.velocity;
        float b2 = dot(beta, beta);
        float doppler = 1.0;
        if (OBSERVER_MOVES && b2 > 0.0) {
            float gam = inversesqrt(1.0 - b2);
            float bd = dot(beta, dir);
            dir = normalize((dir / gam - beta + (gam / (gam + 1.0)) * bd * beta) / (1.0 - bd));
            doppler = gam * (1.0 + dot(beta, dir));
        }
        vec3 rh = frame.radial;
        float dr = dot(dir, rh);
        dir = normalize(frame.lapse * dr * rh + (dir - dr * rh));
        observer_lapse = frame.lapse;
        observer_g = doppler / frame.lapse;
    }
    return dir;
}

// Pixel px's ray with its coordinate direction; sets observer_g.
PixelRay camera_ray(uvec2 px) {
    PixelRay ray;
    if (PROJECTION == PROJ_EQUIRECT) ray = equirect(px);
    else if (PROJECTION == PROJ_FISHEYE) ray = fisheye(px);
    else ray = pinhole(px);
    pol_dir_observer = ray.dir;
    pol_origin = ray.origin;
    ray.dir = observer_to_coordinate(ray.origin, ray.dir);
    return ray;
}

#endif
