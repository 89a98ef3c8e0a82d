// The camera: a pixel's ray (the pinhole projection, binding convention)
// in the observer's frame, turned into a coordinate direction.
#ifndef CAMERA_GLSL
#define CAMERA_GLSL

#include "params.glsl"
#include "variant.glsl"
#include "ray_state.glsl"

// The coordinate direction of pixel px's camera ray (binding camera
// convention, the conventions in the README, "Physics"); sets observer_g.
vec3 pixel_ray(uvec2 px) {
    uint w = P.camera.size.x, hgt = P.camera.size.y;
    float tan_half = P.camera.tan_half_fov, aspect = P.camera.aspect;
    // Sub-pixel jitter (cam_up.w, cam_fwd.w; 0 = the pixel centre) for
    // accumulated anti-aliasing in the window.
    float sx = ((float(px.x) + 0.5 + P.camera.jitter_x) * (2.0 / float(w)) - 1.0) * tan_half * aspect;
    float sy = (1.0 - (float(px.y) + 0.5 + P.camera.jitter_y) * (2.0 / float(hgt))) * tan_half;
    vec3 dir = normalize(P.camera.forward + sx * P.camera.right + sy * P.camera.up);
    // The pixel's direction is measured in the observer's own frame
    // (src/physics/observer.rs): aberration by its velocity into the static
    // frame, then the static frame's radial squeeze into a coordinate
    // direction; its clock and motion scale the redshift it measures.
    if (int(P.observer.kind) != OBS_FLAT) {
        vec3 beta = P.observer.velocity;
        float b2 = dot(beta, beta);
        float doppler = 1.0;
        if (OBSERVER_MOVES && b2 > 0.0) {
            float gam = inversesqrt(1.0 - b2);
            float bd = dot(beta, dir);
            dir = normalize((dir / gam - beta + (gam / (gam + 1.0)) * bd * beta) / (1.0 - bd));
            doppler = gam * (1.0 + dot(beta, dir));
        }
        vec3 rh = P.observer.radial;
        float dr = dot(dir, rh);
        dir = normalize(P.observer.lapse * dr * rh + (dir - dr * rh));
        observer_g = doppler / P.observer.lapse;
    }
    return dir;
}

#endif
