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
#include "elliptic.glsl"
#include "variant.glsl"

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
    vec3 cam;                // sn, cn, dn at the camera's own w0 (path_u)
};

// The path's four incomplete integrals F = sqrt(sin2) R_F(cos2, delta2, 1)
// at the points uu: the camera, the end, the annulus' two edges (light_path
// sets the roots and the case first, and clamps the edges; u2, u3, d21, d31
// and A are its, g0 = du^2 at the camera). Their arguments per case (see src/physics/closed_form.rs):
//   scattered: sin2 = (u - u1)/(u2 - u1), cos2 = (u2 - u)/(u2 - u1), delta2 = (u3 - u)/(u3 - u1)
//   trapped:   sin2 = (u - u3)/(u - u2), cos2 = (u3 - u2)/(u - u2), delta2 = (u3 - u2)(u - u1)/((u3 - u1)(u - u2))
//   plunging:  cos = (A - v)/(A + v), sin2 = 4Av/(A + v)^2, delta2 = 1 - k^2 sin2, v = u - u1
// Differences from the root at the camera come from g0, without cancellation.
vec4 path_integrals(LightPath p, vec4 uu, float u0, float g0, float u2, float u3, float d21, float d31,
                    float A, out vec3 cam) {
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
        vec4 iu = 1.0 / (um3 + p.d32);
        sin2 = um3 * iu;
        cos2 = p.d32 * iu;
        delta2 = p.mc * a1 * iu;  // mc = d32 / d31
    } else {
        vec4 ia = 1.0 / (A + a1);
        vec4 cp = (A - a1) * ia;
        sin2 = 4.0 * A * a1 * ia * ia;
        cos2 = cp * cp;
        delta2 = 1.0 - (1.0 - p.mc) * sin2;
    }
    cam = sqrt(max(vec3(sin2.x, cos2.x, delta2.x), 0.0));
    if (p.kind == PATH_PLUNGING && a1.x > A) cam.y = -cam.y;  // past the plunge's pi/2
    vec4 w = sqrt(max(sin2, 0.0)) * carlson_rf4(max(cos2, 0.0), max(delta2, 0.0));
    w = mix(w, vec4(p.kk), at_k);
    // Plunging: past phi = pi/2 (v > A), F = 2K - F(pi - phi).
    if (p.kind == PATH_PLUNGING) {
        w = mix(w, 2.0 * p.kk - w, greaterThan(a1, vec4(A)));
    }
    return w;
}

// The path of a ray starting at u0 with du/dphi = du (> 0 inward) and the
// constant c = (rs / b)^2 (= du^2 + u0^2 (1 - u0)); u_lo < u_hi bound an
// annulus (the thin disk's: rs / outer, rs / inner) whose elliptic-argument
// windows the path keeps. At and inside the horizon (u0 >= 1) a path is of
// the trapped kind (c < 4/27: out through the horizon to its turning point
// and back into the hole) or plunging (out to the sky), and its backward
// ray starts outward (du < 0): the same formulas.
//
// Written as one straight line of code: each case only chooses the
// arguments of the same three elliptic integrals (at the camera, at the end,
// and K). On a CPU Vulkan driver such as lavapipe every branch of a shader
// runs for every pixel under a mask, so three cases with their own integrals
// would cost three times as much.
LightPath light_path(float u0, float du, float c, float u_lo, float u_hi) {
    LightPath p;
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

    // The end point: escape (u = 0) or the horizon (u = 1).
    p.escapes = p.kind == PATH_SCATTERED || (p.kind == PATH_PLUNGING && !inward);
    float u_end = p.escapes ? 0.0 : 1.0;

    // The means for sn (computed only where a pass evaluates sn), and K.
    p.agm = agm_of(p.mc);
    p.kk = complete_k(p.mc);
    p.inv_2k = 0.5 / p.kk;

    // Four incomplete integrals (path_integrals): at the camera, at the
    // end, and at the annulus' two edges, clamped to where the case's
    // formula holds (u <= u2 scattered, u >= u3 trapped).
    vec4 uu = vec4(u0, u_end, u_lo, u_hi);
    if (p.kind == PATH_SCATTERED) uu.zw = min(uu.zw, u2);
    if (p.kind == PATH_TRAPPED) uu.zw = max(uu.zw, u3);
    vec4 w = path_integrals(p, uu, u0, g0, u2, u3, d21, d31, A, p.cam);
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

// Whether the backward ray moves inward (u grows) at angle phi: u grows
// with w on the plunge, and on (0, K) of each 2K period of the others.
bool path_moves_in(LightPath p, float phi) {
    float w = p.w0 + p.rate * phi;
    float wr = w - 2.0 * p.kk * floor(w * p.inv_2k);
    bool grows = p.kind == PATH_PLUNGING || wr < p.kk;
    return grows == (p.rate > 0.0);
}

// u = rs / r at angle phi along the path: one sn/cn evaluation whatever the
// kind (see light_path for why).
//
// A falling camera's plunging paths (RAIN_FORM) take a short sweep from the
// camera's own point by the addition theorem, cn(w0 + d) = (cn0 cn_d - sn0
// sn_d dn0 dn_d) / (1 - k^2 sn0^2 sn_d^2), instead of from w0: inside the
// horizon w0 lies past K, its rounding is some ulps of 2K, and the nearly
// radial rays seen from there have r(phi) so steep (dr/dphi ~ r^2 / b) that
// it moved a distant disk crossing by 3e-4 rs. Only where the denominator
// stays above 1/4: near the photon orbit (k -> 1) it cancels, and there
// the direct form is the better.
float path_u(LightPath p, float phi) {
    float w = p.w0 + p.rate * phi;
    float k2 = 2.0 * p.kk;
    float d = p.rate * phi;
    // (sn_d <= sin d up to pi/2, as am d <= d: the denominator's least.)
    float sd_most = sin(min(abs(d), HALF_PI));
    float least = 1.0 - (1.0 - p.mc) * p.cam.x * p.cam.x * sd_most * sd_most;
    bool from_camera = RAIN_FORM && p.kind == PATH_PLUNGING && abs(d) <= p.kk && least > 0.25;
    // Scattered and trapped: sn^2 has period 2K and is even, so [0, K].
    // Plunging: w in [0, 2K), and cn(2K - w) = -cn(w).
    float wr = w - k2 * floor(w * p.inv_2k);
    wr = wr > p.kk ? k2 - wr : wr;
    bool plunging = p.kind == PATH_PLUNGING;
    bool far_half = w > p.kk;
    float arg = plunging ? (far_half ? k2 - w : max(w, 0.0)) : wr;
    vec2 sc = jacobi_sn_cn(from_camera ? abs(d) : arg, p.agm);
    if (from_camera) {
        float sd = d < 0.0 ? -sc.x : sc.x;
        float m = 1.0 - p.mc;
        float dn_d = sqrt(max(1.0 - m * sd * sd, 0.0));
        vec3 c = p.cam;
        float cn_w = (c.y * sc.y - c.x * sd * c.z * dn_d) / (1.0 - m * c.x * c.x * sd * sd);
        return p.u1 + p.d21 * (1.0 - cn_w) / (1.0 + cn_w);
    }
    float cn = plunging && far_half ? -sc.y : sc.y;
    float sn2 = sc.x * sc.x;
    if (plunging) return p.u1 + p.d21 * (1.0 - cn) / (1.0 + cn);
    if (p.kind == PATH_SCATTERED) return p.u1 + p.d21 * sn2;
    return p.u3 + p.d32 * sn2 / max(cn * cn, 1e-30);
}

#endif
