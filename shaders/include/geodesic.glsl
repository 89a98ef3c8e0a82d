// Light paths around Schwarzschild holes (the conventions in the README, "Physics"):
//   x'' = -1.5 rs h^2 x / r^5,  h = |x cross x'|, x measured from the hole,
// which reproduces the exact spatial shape of null geodesics (Binet's
// u'' + u = 1.5 rs u^2). Several holes: accelerations summed (approximate).
//
// Integrated with the Dormand-Prince 5(4) embedded Runge-Kutta pair (Dormand &
// Prince 1980) with local error control: the step shrinks near a hole and
// grows far away.
#ifndef GEODESIC_GLSL
#define GEODESIC_GLSL

#include "params.glsl"

vec3 accel(vec3 x, vec3 v) {
    vec3 a = vec3(0.0);
    uint n = P.metric.hole_count;
    for (uint i = 0u; i < n; ++i) {
        vec3 d = x - P.metric.holes[i].xyz;
        float rs = P.metric.holes[i].w;
        float r2 = dot(d, d);
        vec3 hv = cross(d, v);
        float h2 = dot(hv, hv);
        float r5 = r2 * r2 * sqrt(r2);
        a += (-1.5 * rs * h2 / r5) * d;
    }
    return a;
}

// One Dormand-Prince step of size h from (x, v) with k1 = accel(x, v) given
// (first-same-as-last). Returns the new state, the new k1 and the error norm
// relative to tolerance (<= 1 means accept).
float dopri_step(vec3 x, vec3 v, vec3 a1, float h, float tol,
                 out vec3 xn, out vec3 vn, out vec3 an) {
    const float a21 = 1.0 / 5.0;
    const float a31 = 3.0 / 40.0, a32 = 9.0 / 40.0;
    const float a41 = 44.0 / 45.0, a42 = -56.0 / 15.0, a43 = 32.0 / 9.0;
    const float a51 = 19372.0 / 6561.0, a52 = -25360.0 / 2187.0, a53 = 64448.0 / 6561.0,
                a54 = -212.0 / 729.0;
    const float a61 = 9017.0 / 3168.0, a62 = -355.0 / 33.0, a63 = 46732.0 / 5247.0,
                a64 = 49.0 / 176.0, a65 = -5103.0 / 18656.0;
    const float b1 = 35.0 / 384.0, b3 = 500.0 / 1113.0, b4 = 125.0 / 192.0,
                b5 = -2187.0 / 6784.0, b6 = 11.0 / 84.0;
    const float e1 = 71.0 / 57600.0, e3 = -71.0 / 16695.0, e4 = 71.0 / 1920.0,
                e5 = -17253.0 / 339200.0, e6 = 22.0 / 525.0, e7 = -1.0 / 40.0;

    // Stage k_i = (velocity, acceleration) at stage state i.
    vec3 v1 = v;
    vec3 x2 = x + h * (a21 * v1);
    vec3 v2 = v + h * (a21 * a1);
    vec3 a2 = accel(x2, v2);
    vec3 x3 = x + h * (a31 * v1 + a32 * v2);
    vec3 v3 = v + h * (a31 * a1 + a32 * a2);
    vec3 a3 = accel(x3, v3);
    vec3 x4 = x + h * (a41 * v1 + a42 * v2 + a43 * v3);
    vec3 v4 = v + h * (a41 * a1 + a42 * a2 + a43 * a3);
    vec3 a4 = accel(x4, v4);
    vec3 x5 = x + h * (a51 * v1 + a52 * v2 + a53 * v3 + a54 * v4);
    vec3 v5 = v + h * (a51 * a1 + a52 * a2 + a53 * a3 + a54 * a4);
    vec3 a5 = accel(x5, v5);
    vec3 x6 = x + h * (a61 * v1 + a62 * v2 + a63 * v3 + a64 * v4 + a65 * v5);
    vec3 v6 = v + h * (a61 * a1 + a62 * a2 + a63 * a3 + a64 * a4 + a65 * a5);
    vec3 a6 = accel(x6, v6);
    xn = x + h * (b1 * v1 + b3 * v3 + b4 * v4 + b5 * v5 + b6 * v6);
    vn = v + h * (b1 * a1 + b3 * a3 + b4 * a4 + b5 * a5 + b6 * a6);
    an = accel(xn, vn);
    vec3 ex = h * (e1 * v1 + e3 * v3 + e4 * v4 + e5 * v5 + e6 * v6 + e7 * vn);
    vec3 ev = h * (e1 * a1 + e3 * a3 + e4 * a4 + e5 * a5 + e6 * a6 + e7 * an);
    float sx = tol * max(length(x - P.metric.holes[0].xyz), 1.0);
    float sv = tol * max(length(v), 1e-3);
    return max(length(ex) / sx, length(ev) / sv);
}

#endif
