// The camera: what a pixel sees. A projection maps a pixel (and the frame's
// sub-pixel jitter) to where its ray starts, its unit direction in the
// observer's own frame and the angle the pixel spans; the observer then
// turns that direction into a coordinate direction (and sets observer_g).
// This file is the only place that knows the pinhole (the binding camera
// convention, the README's "Scenes" and "Physics"), mirrored by
// src/camera/mod.rs. A new projection (a panorama, a dome, one eye of a
// stereo pair) is a new function here beside pinhole(), chosen in
// camera_ray(), with its twin in src/camera/mod.rs.
#ifndef CAMERA_GLSL
#define CAMERA_GLSL

#include "params.glsl"
#include "variant.glsl"
#include "ray_state.glsl"
#include "metric.glsl"

// A pixel's ray.
struct PixelRay {
    vec3 origin;  // where it starts (world)
    vec3 dir;     // unit direction: in the observer's frame from a projection,
                  // a coordinate direction from camera_ray()
    float angle;  // the pixel's angular size (radians), unlensed
};

// The pinhole: every ray from the camera's position through the pixel's
// place (plus jitter) on the image plane at distance 1; the pixel spans
// 2 tan(vfov / 2) / height at the centre.
PixelRay pinhole(uvec2 px) {
    uint w = P.camera.size.x, hgt = P.camera.size.y;
    float tan_half = P.camera.tan_half_fov, aspect = P.camera.aspect;
    // Sub-pixel jitter (0 = the pixel centre) for accumulated anti-aliasing.
    float sx = ((float(px.x) + 0.5 + P.camera.jitter_x) * (2.0 / float(w)) - 1.0) * tan_half * aspect;
    float sy = (1.0 - (float(px.y) + 0.5 + P.camera.jitter_y) * (2.0 / float(hgt))) * tan_half;
    PixelRay ray;
    ray.origin = P.camera.position;
    ray.dir = normalize(P.camera.forward + sx * P.camera.right + sy * P.camera.up);
    ray.angle = 2.0 * tan_half / float(hgt);
    return ray;
}

// A direction measured in the observer's own frame (src/physics/observer.rs)
// at `origin` as a coordinate direction: aberration by its velocity into the
// static frame there (the metric's, metric_static_frame), then that frame's
// radial squeeze; its clock and motion scale the redshift it measures
// (observer_g, observer_lapse).
vec3 observer_to_coordinate(vec3 origin, vec3 dir) {
    if (int(P.observer.kind) != OBS_FLAT) {
        StaticFrame frame = metric_static_frame(origin);
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
    PixelRay ray = pinhole(px);
    ray.dir = observer_to_coordinate(ray.origin, ray.dir);
    return ray;
}

#endif
