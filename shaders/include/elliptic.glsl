// Elliptic functions in 32-bit floats, shared by the closed-form light
// paths of both kinds of hole (lightpath.glsl, metric/kerr.glsl): Carlson's
// R_F for four argument pairs at once, the arithmetic-geometric mean and
// Jacobi's sn and cn, and the complete integral K. Their f64 twins are in
// src/physics/closed_form.rs and src/physics/kerr/elliptic.rs.
#ifndef ELLIPTIC_GLSL
#define ELLIPTIC_GLSL

#include "precise.glsl"

// R_F(x, y, 1) for four argument pairs at once: one loop instead of four
// (every integral this file needs has z = 1). Duplication (each turn brings
// x, y, z four times closer together) until all are within 0.2 of their
// mean, then Carlson's series to seventh order (DLMF 19.36.1), whose error
// there is below f32 resolution. At least two turns: the first outside the
// loop (z = 1, so one square root of three is known), the loop's body at
// least once. Measured in f32 against mpmath (x in [0, 1.5] and down to
// 1e-7, y in [0, 1.5]): relative error at most 3.0e-7, p99 2.1e-7, 2.04
// turns on average. The loop holds only the duplication: on a CPU driver a
// loop's body runs for the whole SIMD group each turn, so the series waits
// until after it.
vec4 carlson_rf4(vec4 x, vec4 y) {
    // The first duplication with z = 1; the loop's body then runs at least
    // once more, as nearly every SIMD group needs anyway.
    vec4 sx0 = sqrt(x), sy0 = sqrt(y);
    vec4 l0 = sx0 * (sy0 + 1.0) + sy0;
    x = 0.25 * (x + l0);
    y = 0.25 * (y + l0);
    vec4 z = 0.25 * (1.0 + l0);
    for (int i = 1; i < 16; ++i) {
        vec4 sx = sqrt(x), sy = sqrt(y), sz = sqrt(z);
        vec4 l = sx * (sy + sz) + sy * sz;
        x = 0.25 * (x + l);
        y = 0.25 * (y + l);
        z = 0.25 * (z + l);
        // Tested after the duplication: a CPU driver runs a loop's body
        // until no lane of the SIMD group is left, so a test before it costs
        // one more body than the longest lane needs; one duplication more
        // than needed only brings the arguments closer.
        vec4 a = (x + y + z) * (1.0 / 3.0);
        vec4 dm = max(abs(a - x), max(abs(a - y), abs(a - z))) - 0.2 * a;
        if (max(max(dm.x, dm.y), max(dm.z, dm.w)) < 0.0) break;
    }
    vec4 a = (x + y + z) * (1.0 / 3.0);
    vec4 ia = 1.0 / a;
    vec4 dx = 1.0 - x * ia, dy = 1.0 - y * ia, dz = 1.0 - z * ia;
    vec4 e2 = dx * dy - dz * dz;
    vec4 e3 = dx * dy * dz;
    vec4 series = 1.0 - e2 * 0.1 + e3 * (1.0 / 14.0) + e2 * e2 * (1.0 / 24.0)
                - e2 * e3 * (3.0 / 44.0) - e2 * e2 * e2 * (5.0 / 208.0)
                + e3 * e3 * (3.0 / 104.0) + e2 * e2 * e3 * (1.0 / 16.0);
    return series * sqrt(ia);  // 1 / sqrt(a) from 1 / a: no second division
}

// Jacobi sn and cn (parameter m = 1 - mc) by the arithmetic-geometric mean
// and Bulirsch's descending recurrence (Numerical Recipes' sncndn): the
// means depend only on mc, so a path keeps them (AGM_STEPS fixed steps:
// c_n falls quadratically, below f32 resolution by the seventh step down to
// mc ~ 1e-12; a step past convergence leaves the result unchanged), and each
// sn costs one sine and cosine and a short rational recurrence: no inverse
// trigonometric function per step, so no error amplified by 2^n (measured
// in f32 against mpmath over mc in [1e-12, 1], u in [0, K]: p99 1.2e-7,
// max 2.4e-7, against 4.8e-6 and 1.4e-5 for the descent by arcsines).
const int AGM_STEPS = 7;

struct Agm {
    float a[AGM_STEPS + 1];  // a_0 = 1 .. a_N, the mean
    float b[AGM_STEPS];      // b_0 = sqrt(mc) .. b_{N-1}
    float inv_a[AGM_STEPS];  // 1 / a_0 .. 1 / a_{N-1}
};

Agm agm_of(float mc) {
    Agm g;
    g.a[0] = 1.0;
    float b = sqrt(max(mc, 0.0));
    for (int n = 0; n < AGM_STEPS; ++n) {
        g.b[n] = b;
        g.inv_a[n] = 1.0 / g.a[n];
        g.a[n + 1] = 0.5 * (g.a[n] + b);
        b = sqrt(g.a[n] * b);
    }
    return g;
}

// sn(w) and cn(w) for w in [0, K] (both >= 0 there).
vec2 jacobi_sn_cn(float w, Agm g) {
    vec2 cs0 = cos_sin_precise(w * g.a[AGM_STEPS]);
    // c: the cotangent of the amplitude, carried down the means.
    float cot = cs0.x / max(cs0.y, 1e-18);
    float c = g.a[AGM_STEPS] * cot;
    float a = cot, dn = 1.0;
    for (int i = AGM_STEPS - 1; i >= 0; --i) {
        a *= c;
        c *= dn;
        dn = (g.b[i] + a) / (g.a[i] + a);
        a = c * g.inv_a[i];
    }
    float sn = inversesqrt(c * c + 1.0);
    // At w = 0 (sin below 1e-18): sn = 0, cn = 1.
    return cs0.y < 1e-18 ? vec2(cs0.y, 1.0) : vec2(sn, c * sn);
}

// K(k) from mc = 1 - k^2 by Hastings' fit (Abramowitz and Stegun 17.3.34,
// error below 2e-8 for mc in (0, 1]): a logarithm and two short
// polynomials instead of the arithmetic-geometric mean's chain of seven
// square roots, each waiting on the last. So a pass that needs only K (the
// trace pass: the windows, the end point) never computes the means; one
// that evaluates sn computes them as well.
float complete_k(float mc) {
    float m2 = mc * mc;
    float a = (1.38629436112 + 0.09666344259 * mc) + m2 * ((0.03590092383 + 0.03742563713 * mc)
            + m2 * 0.01451196212);
    float b = (0.5 + 0.12498593597 * mc) + m2 * ((0.06880248576 + 0.03328355346 * mc)
            + m2 * 0.00441787012);
    return a - b * log(max(mc, 1e-30));
}

#endif
