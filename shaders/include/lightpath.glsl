// Closed-form Schwarzschild light paths, the f32 twin of
// src/physics/closed_form.rs (which documents the mathematics and is tested
// against the step-by-step integrator). In units of rs, u = rs / r:
//   (du/dphi)^2 = u^3 - u^2 + c,  c = (rs / b)^2,
// solved by Jacobi elliptic functions: a ray's escape direction, capture and
// disk crossings come in constant time, with no steps.
//
// f32 near the critical impact parameter: everything is formed from
// e = 4/27 - c and from trigonometric root differences, so the only error is
// that of e itself (about 1e-8 absolute from the f32 pixel direction). A ray
// with |e| below ~1e-6 winds many times and its winding angle carries an
// error of ~|1e-8 / e| / 2 rad: the photon ring stays a thin, sharp line of
// rays that wind, and no ray ever runs out of steps.
#ifndef LIGHTPATH_GLSL
#define LIGHTPATH_GLSL

#include "constants.glsl"

// The polynomials below are evaluated by Estrin's scheme: pairs of terms
// combined by t^2, t^4, t^8, a tree a few products deep instead of Horner's
// chain of one multiply-add per term. A CPU driver runs a SIMD group's lanes
// in lock step, each step waiting on the last, so the chain's length, not
// its count of operations, is what a polynomial costs there.
// c[0] + c[1] t + ... + c[11] t^11.
float poly12(float t, const float c[12]) {
    float t2 = t * t, t4 = t2 * t2, t8 = t4 * t4;
    float p01 = c[0] + c[1] * t, p23 = c[2] + c[3] * t, p45 = c[4] + c[5] * t;
    float p67 = c[6] + c[7] * t, p89 = c[8] + c[9] * t, pab = c[10] + c[11] * t;
    return (p01 + p23 * t2) + t4 * (p45 + p67 * t2) + t8 * (p89 + pab * t2);
}

// cos and sin of x to full f32 precision: the angle reduced by pi/2 with
// a two-part constant, then Taylor polynomials on [-pi/4, pi/4].
vec2 cos_sin_precise(float x) {
    float q = round(x * 0.6366197723675814);
    float r = (x - q * 1.5707963705062866) + q * 4.371139000186243e-8;
    float r2 = r * r, r4 = r2 * r2, r8 = r4 * r4;
    // (Estrin's scheme, see poly12.)
    float s = r * ((1.0 - r2 * (1.0 / 6.0)) + r4 * ((1.0 / 120.0 - r2 * (1.0 / 5040.0)) + r4 * (1.0 / 362880.0)));
    float c = (1.0 - 0.5 * r2) + r4 * (1.0 / 24.0 - r2 * (1.0 / 720.0))
            + r8 * (1.0 / 40320.0 - r2 * (1.0 / 3628800.0));
    int k = int(q) & 3;
    if (k == 0) return vec2(c, s);
    if (k == 1) return vec2(-s, c);
    if (k == 2) return vec2(-c, -s);
    return vec2(s, -c);
}

// Inverse and hyperbolic functions to full f32 precision. Vulkan lets a
// driver's asin, asinh and sinh be far coarser (asin inherits atan's 4096
// ulp; asinh and sinh built from log and exp cancel near 0), and lavapipe's
// are: a 1e-4 error in asin moved disk points by 1e-2 rs. (sinh: by its
// series near 0, in light_path.)
float asin_precise(float x) {
    float ax = abs(x);
    bool big = ax > 0.5;
    // asin(x) = pi/2 - 2 asin(sqrt((1 - x) / 2)) above 0.5.
    float y = big ? sqrt(0.5 * (1.0 - ax)) : ax;
    float y2 = y * y;
    // Maclaurin series of asin to y^23: below 1e-9 relative for |y| <= 0.5.
    const float C[12] = float[12](1.0, 1.0 / 6.0, 3.0 / 40.0, 5.0 / 112.0, 35.0 / 1152.0,
        63.0 / 2816.0, 231.0 / 13312.0, 143.0 / 10240.0, 6435.0 / 557056.0,
        12155.0 / 1245184.0, 46189.0 / 5505024.0, 88179.0 / 12058624.0);
    float r = y * poly12(y2, C);
    if (big) r = 1.5707963267948966 - 2.0 * r;
    return x < 0.0 ? -r : r;
}

// sin x for x in [0, pi/3] by its Taylor series to x^13 (error below 2e-9):
// no range reduction, which a driver's sin does for any argument.
float sin_third(float x) {
    float x2 = x * x, x4 = x2 * x2, x8 = x4 * x4;
    return x * ((1.0 - x2 * (1.0 / 6.0)) + x4 * (1.0 / 120.0 - x2 * (1.0 / 5040.0))
              + x8 * ((1.0 / 362880.0 - x2 * (1.0 / 39916800.0)) + x4 * (1.0 / 6227020800.0)));
}

float asinh_precise(float x) {
    if (abs(x) < 0.25) {
        float x2 = x * x;
        return x * (1.0 - x2 * (1.0 / 6.0 - x2 * (3.0 / 40.0 - x2 * (15.0 / 336.0 - x2 * (105.0 / 3456.0)))));
    }
    return log(x + sqrt(x * x + 1.0));
}

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

#define PATH_SCATTERED 0
#define PATH_TRAPPED 1
#define PATH_PLUNGING 2

struct LightPath {
    int kind;
    float u1, d21, d32, u3;  // roots and differences (plunging: d21 = A)
    float mc;                // 1 - k^2
    float kk;                // K(k)
    float inv_2k;            // 1 / 2K
    float w0, rate;          // elliptic argument at the camera, dw/dphi (signed)
    float inv_rate;          // 1 / rate (a division is dear on a CPU driver)
    float phi_end;           // angle swept to escape or capture
    bool escapes;
    Agm agm;                 // the means for sn and cn at this k
    // Where u lies in [u_lo, u_hi] (the disk's annulus): intervals of w,
    // (a.x, a.y) and (b.x, b.y), possibly empty or outside the path.
    vec2 win_a, win_b;
};

// The path of a ray starting at u0 with du/dphi = du (> 0 inward); u_lo <
// u_hi bound an annulus (the thin disk's: rs / outer, rs / inner) whose
// elliptic-argument windows the path keeps.
//
// Written as one straight line of code: each case only chooses the
// arguments of the same three elliptic integrals (at the camera, at the end,
// and K). On a CPU Vulkan driver such as lavapipe every branch of a shader
// runs for every pixel under a mask, so three cases with their own integrals
// would cost three times as much.
LightPath light_path(float u0, float du, float u_lo, float u_hi) {
    LightPath p;
    float c = du * du + u0 * u0 * (1.0 - u0);
    float e = 4.0 / 27.0 - c;
    bool inward = du > 0.0;
    bool three = e > 0.0;
    float g0 = du * du;  // (u0 - u1)(u0 - u2)(u0 - u3)

    // Three real roots: theta = acos(1 - 27c/2), pi - theta from e.
    float theta = 2.0 * asin_precise(min(sqrt(6.75 * max(c, 0.0)), 1.0));
    float theta_c = 2.0 * asin_precise(min(sqrt(6.75 * max(e, 0.0)), 1.0));
    const float S = 1.1547005383792515;  // 2 / sqrt(3)
    // One sine for t = theta / 3 in [0, pi/3]: its cosine from it, sin(t +
    // pi/3) by the addition formula, and 4/3 sin^2(t/2) = 2/3 (1 - cos t)
    // as 2/3 sin^2 t / (1 + cos t), without the cancellation for small t.
    // (On a CPU driver a sine is a range reduction and a polynomial.)
    float st = sin_third(theta * (1.0 / 3.0));
    float ct = sqrt(max(1.0 - st * st, 0.0));
    float d21 = S * st;
    float d31 = S * (0.5 * st + 0.8660254037844386 * ct);
    float d32 = S * sin_third(theta_c * (1.0 / 3.0));
    float sum12 = (2.0 / 3.0) * st * st / (1.0 + ct);
    float u1_three = 0.5 * (sum12 - d21);
    float u2 = u1_three + d21;
    float u3 = 1.0 - sum12;
    // One real root: u1 = 1/3 - 2/3 cosh(alpha/3), the pair m +- in with
    // m - u1 = cosh(alpha/3), n^2 = sinh^2(alpha/3) / 3. One exponential
    // for both (y = alpha/3): cosh y = (e^y + e^-y)/2, and sinh y the same
    // way except near 0, where that cancels and its series is exact to f32.
    float y = (2.0 / 3.0) * asinh_precise(sqrt(6.75 * max(-e, 0.0)));
    float ey = exp(y), iey = 1.0 / ey, y2 = y * y;
    float ch = 0.5 * (ey + iey);
    float sh = y < 0.25 ? y * (1.0 + y2 * (1.0 / 6.0 + y2 * (1.0 / 120.0 + y2 * (1.0 / 5040.0))))
                        : 0.5 * (ey - iey);
    float n2 = sh * sh * (1.0 / 3.0);
    float A = sqrt(ch * ch + n2);

    p.u1 = three ? u1_three : 1.0 / 3.0 - (2.0 / 3.0) * ch;
    p.u3 = u3;
    p.d21 = three ? d21 : A;
    p.d32 = d32;
    p.mc = (three ? d32 : n2) / (three ? d31 : 2.0 * A * (A + ch));  // one division
    p.kind = three ? (u0 < 2.0 / 3.0 ? PATH_SCATTERED : PATH_TRAPPED) : PATH_PLUNGING;
    float rate = three ? 0.5 * sqrt(d31) : sqrt(A);
    float m = 1.0 - p.mc;

    // The end point: escape (u = 0) or the horizon (u = 1).
    p.escapes = p.kind == PATH_SCATTERED || (p.kind == PATH_PLUNGING && !inward);
    float u_end = p.escapes ? 0.0 : 1.0;

    // The means for sn (computed only where a pass evaluates sn), and K.
    p.agm = agm_of(p.mc);
    p.kk = complete_k(p.mc);
    p.inv_2k = 0.5 / p.kk;

    // Four incomplete integrals F = sqrt(sin2) R_F(cos2, delta2, 1): at the
    // camera, at the end, and at the annulus' two edges (clamped to where
    // the case's formula holds: u <= u2 scattered, u >= u3 trapped). Their
    // arguments per case (see src/physics/closed_form.rs):
    //   scattered: sin2 = (u - u1)/(u2 - u1), cos2 = (u2 - u)/(u2 - u1), delta2 = (u3 - u)/(u3 - u1)
    //   trapped:   sin2 = (u - u3)/(u - u2), cos2 = (u3 - u2)/(u - u2), delta2 = (u3 - u2)(u - u1)/((u3 - u1)(u - u2))
    //   plunging:  cos = (A - v)/(A + v), sin2 = 4Av/(A + v)^2, delta2 = 1 - k^2 sin2, v = u - u1
    // Differences from the root at the camera come from g0, without cancellation.
    vec4 uu = vec4(u0, u_end, u_lo, u_hi);
    if (p.kind == PATH_SCATTERED) uu.zw = min(uu.zw, u2);
    if (p.kind == PATH_TRAPPED) uu.zw = max(uu.zw, u3);
    vec4 a1 = uu - p.u1;
    vec4 sin2, cos2, delta2;
    bvec4 at_k = bvec4(false);
    if (p.kind == PATH_SCATTERED) {
        vec4 a3 = u3 - uu;
        float u2m0 = (a1.x > 0.0 && a3.x > 0.0) ? g0 / (a1.x * a3.x) : u2 - u0;
        vec4 u2m = vec4(max(u2m0, 0.0), u2 - uu.yzw);
        // Reciprocals once: a division is dear on a CPU driver.
        float i21 = 1.0 / d21;
        sin2 = a1 * i21;
        cos2 = u2m * i21;
        delta2 = a3 * (1.0 / d31);
        // An annulus edge the path never reaches is clamped to the
        // periapsis, where F is K (p.kk, above): R_F(0, y, 1) there
        // would keep the SIMD group longest in the duplication loop, and most
        // sky rays pass outside the disk. R_F(1, 1, 1) = 1 takes one turn.
        at_k = lessThanEqual(u2m, vec4(0.0));
        cos2 = mix(cos2, vec4(1.0), at_k);
        delta2 = mix(delta2, vec4(1.0), at_k);
    } else if (p.kind == PATH_TRAPPED) {
        float a2 = u0 - u2;
        float um30 = max((a1.x > 0.0 && a2 > 0.0) ? g0 / (a1.x * a2) : u0 - u3, 0.0);
        vec4 um3 = vec4(um30, uu.yzw - u3);
        vec4 iu = 1.0 / (um3 + d32);
        sin2 = um3 * iu;
        cos2 = d32 * iu;
        delta2 = p.mc * a1 * iu;  // mc = d32 / d31
    } else {
        vec4 ia = 1.0 / (A + a1);
        vec4 cp = (A - a1) * ia;
        sin2 = 4.0 * A * a1 * ia * ia;
        cos2 = cp * cp;
        delta2 = 1.0 - m * sin2;
    }
    vec4 w = sqrt(max(sin2, 0.0)) * carlson_rf4(max(cos2, 0.0), max(delta2, 0.0));
    w = mix(w, vec4(p.kk), at_k);
    // Plunging: past phi = pi/2 (v > A), F = 2K - F(pi - phi).
    if (p.kind == PATH_PLUNGING) {
        w = mix(w, 2.0 * p.kk - w, greaterThan(a1, vec4(A)));
    }
    p.w0 = w.x;
    float w_end = w.y;
    // u in [u_lo, u_hi]: scattered on the way in (w in [W(u_lo), W(u_hi)])
    // and mirrored about the periapsis w = K; trapped mirrored about the
    // turning point w = 0; plunging once.
    p.win_a = w.zw;
    p.win_b = p.kind == PATH_SCATTERED ? 2.0 * p.kk - w.wz
            : p.kind == PATH_TRAPPED ? -w.wz : w.zw;
    // Scattered inward: through the periapsis (w = K) and out to 2K - w_esc.
    if (p.kind == PATH_SCATTERED && inward) w_end = 2.0 * p.kk - w_end;
    if (p.kind == PATH_TRAPPED && !inward) w_end = -w_end;
    p.rate = inward ? rate : -rate;
    p.inv_rate = 1.0 / p.rate;
    p.phi_end = max((w_end - p.w0) * p.inv_rate, 0.0);
    return p;
}

// The first angle phi0 + j pi (j >= 0) inside the path's w-window `win`
// (and before phi_end), or a huge value if there is none.
float first_crossing_in(LightPath p, vec2 win, float phi0) {
    vec2 f = (win - p.w0) * p.inv_rate;
    float lo = max(min(f.x, f.y), 0.0), hi = min(max(f.x, f.y), p.phi_end);
    float phi = phi0 + max(ceil((lo - phi0) * (1.0 / PI)), 0.0) * PI;
    return (hi >= lo && phi <= hi) ? phi : 1e30;
}

// u = rs / r at angle phi along the path: one sn/cn evaluation whatever the
// kind (see light_path for why).
float path_u(LightPath p, float phi) {
    float w = p.w0 + p.rate * phi;
    float k2 = 2.0 * p.kk;
    // Scattered and trapped: sn^2 has period 2K and is even, so [0, K].
    // Plunging: w in [0, 2K), and cn(2K - w) = -cn(w).
    float wr = w - k2 * floor(w * p.inv_2k);
    wr = wr > p.kk ? k2 - wr : wr;
    bool plunging = p.kind == PATH_PLUNGING;
    bool far_half = w > p.kk;
    float arg = plunging ? (far_half ? k2 - w : max(w, 0.0)) : wr;
    vec2 sc = jacobi_sn_cn(arg, p.agm);
    float cn = plunging && far_half ? -sc.y : sc.y;
    float sn2 = sc.x * sc.x;
    if (plunging) return p.u1 + p.d21 * (1.0 - cn) / (1.0 + cn);
    if (p.kind == PATH_SCATTERED) return p.u1 + p.d21 * sn2;
    return p.u3 + p.d32 * sn2 / max(cn * cn, 1e-30);
}

#endif
