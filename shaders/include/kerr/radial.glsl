// The radial motion of a light path around a spinning hole, in Mino time:
// the quartic's roots and case, r(tau), the path's ends, and the radial
// part of the azimuth, I_phi. The twin of src/physics/kerr/radial.rs.
#ifndef KERR_RADIAL_GLSL
#define KERR_RADIAL_GLSL

#include "kerr/precision.glsl"
#include "kerr/carlson.glsl"
#include "kerr/carlson64.glsl"
#include "kerr/legendre.glsl"

// The radial motion. The quartic R(r) = (r^2 + a^2 - a lambda)^2 - Delta
// (eta + (lambda - a)^2) has roots r1 <= r2 <= r3 <= r4 (case 2: the
// camera outside r4; case 1: between r2 and r3; case 3: r3, r4 complex;
// case 4: all four complex). Cases 1 and 2: r(X) from sn(X) with X =
// X_o + rate tau; case 3 from cn(xi) with xi = xi_o +- rate tau.
struct KerrRadial {
    int kcase;
    bool captured;
    float tau_end;
    float m, mc, kk, rate;
    float r1, r2, r3, r4;
    float r21, r31, r32, r41, r43;
    float ba, bb;        // case 3: A and B
    float x0;            // X (case 3: xi) at the camera
    float s_r;
    float i_phi_end;     // case 4: I_phi to the end (quadrature); an escape's in 64 bits
    bool end_exact;      // i_phi_end and tau_end64 hold an escape's, in 64 bits
    float tau_end64;
    vec2 rh, ah;         // the horizons r+, r- and a A+-, their weights in I_phi
    vec2 q_cam;          // case 2 (horizons inside r4): the camera's part of I_phi's R_J
    // The R_F arguments (cos^2, delta^2) and sin^2 of the camera's point
    // and of the path's end (infinity or the horizon), and their folds.
    vec3 rf_cam, rf_end;
    bool fold_cam, fold_end;
    KerrPoint cam, end;  // the camera's point and the path's end (infinity or the horizon)
    Agm agm;
};

// u-space integrand f(u) = u^4 R(1/u) (no cancellation at large r).
float kerr_f_u(float u, float a, float lam, float eta) {
    return 1.0 - (eta + lam * lam - a * a) * u * u + 2.0 * (eta + (lam - a) * (lam - a)) * u * u * u
         - a * a * eta * u * u * u * u;
}

#ifdef KERR_ESCAPE64
// An escape's Mino time and I_phi in 64 bits (where the forms hold).
void kerr_escape_set(inout KerrRadial k, dvec2 e) {
    k.end_exact = abs(e.y) < 1e30;  // (false for NaN)
    k.tau_end64 = float(e.x);
    k.i_phi_end = float(e.y);
}
#endif

// The quartic's roots, in kreal: R(r) = r^4 + A r^2 + B r + C (A = a^2 -
// eta - lambda^2, B = 2 (eta + (lambda - a)^2), C = -a^2 eta) factors as
// (r^2 + 2 z r + ...)(r^2 - 2 z r + ...) with z^2 = Z a root of the
// resolvent cubic; q1 and q2 then give the pairs -z +- sqrt(q1) and
// z +- sqrt(q2) (real where q >= 0).
void kerr_roots(kreal ca, kreal cb, kreal cc, out kreal z, out kreal q1, out kreal q2) {
    kreal p = -ca * ca / 12.0 - cc;
    kreal q = -ca / 3.0 * ((ca / 6.0) * (ca / 6.0) - cc) - cb * cb / 8.0;
    kreal disc = (p / 3.0) * (p / 3.0) * (p / 3.0) + (q / 2.0) * (q / 2.0);
    // z^2 = Z: an f32 estimate (trigonometric or Cardano), then Newton on
    // the resolvent cubic 16Z^3 + 8AZ^2 + (A^2 - 4C)Z - B^2/4 in kreal.
    float w;
    if (disc < 0.0) {
        float sp = float(sqrt(-p / 3.0));
        w = 2.0 * sp * cos(acos(clamp(float(-q / 2.0) / (sp * sp * sp), -1.0, 1.0)) / 3.0);
    } else {
        kreal sd = sqrt(disc);
        kreal u1 = -q / 2.0 + sd, u2 = -q / 2.0 - sd;
        kreal c1 = kreal(sign(float(u1)) * pow(abs(float(u1)), 1.0 / 3.0));
        kreal c2 = kreal(sign(float(u2)) * pow(abs(float(u2)), 1.0 / 3.0));
        [[unroll]] for (int i = 0; i < KERR_CBRT_TURNS; ++i) {
            if (c1 != 0.0) c1 -= (c1 * c1 * c1 - u1) / (3.0 * c1 * c1);
            if (c2 != 0.0) c2 -= (c2 * c2 * c2 - u2) / (3.0 * c2 * c2);
        }
        w = float(c1 + c2);
    }
    kreal zz = kreal(w) / 2.0 - ca / 6.0;
    [[unroll]] for (int i = 0; i < KERR_RESOLVENT_TURNS; ++i) {
        kreal f = ((16.0 * zz + 8.0 * ca) * zz + (ca * ca - 4.0 * cc)) * zz - cb * cb / 4.0;
        kreal df = (48.0 * zz + 16.0 * ca) * zz + (ca * ca - 4.0 * cc);
        if (df != 0.0) zz -= f / df;
    }
    z = sqrt(max(zz, 0.0));
    q1 = -ca / 2.0 - zz + cb / (4.0 * z);
    q2 = -ca / 2.0 - zz - cb / (4.0 * z);
}

// The roots of a path whose lambda^2 + eta is large (-A >= KERR_FAR_ROOTS:
// a photon of energy near zero in the ergoregion, lambda = L / E and eta =
// Q / E^2 up to 1e10 and more, or a far camera's wide rays). Two roots lie
// near +-sqrt(-A) and two near the hole, where the resolvent's two largest
// roots almost coincide and its z loses the small pair's digits (by up to
// the small roots themselves at lambda = 1e4). Here the small pair comes
// from A r^2 + B r + C = 0 (R without its r^4, relatively 1 / -A smaller
// there), polished by Newton's method on R; the large pair from Vieta's
// sums (r1 + r4 = -(r2 + r3), r1 r4 = (r2 r3 (r2 + r3) - B) / (r2 + r3)).
// All four real, r1 < 0 < r2 < r3 < r4 (in this range A r^2 + B r + C
// always has two real roots, at least 2 sqrt(1 - a^2) apart).
const float KERR_FAR_ROOTS = 1e5;

kvec4 kerr_far_roots(kreal ca, kreal cb, kreal cc) {
    kreal t = -0.5 * (cb + sqrt(max(cb * cb - 4.0 * ca * cc, 0.0)));
    kvec2 s = kvec2(t / ca, t != 0.0 ? cc / t : 0.0);
    [[unroll]] for (int i = 0; i < 4; ++i) {
        s -= (((s * s + ca) * s + cb) * s + cc) / (((4.0 * s * s + 2.0 * ca) * s + cb));
    }
    kreal s1 = min(s.x, s.y), s2 = max(s.x, s.y), sum = s1 + s2;
    kreal prod = (s1 * s2 * sum - cb) / sum;
    kreal r4 = 0.5 * (sqrt(sum * sum - 4.0 * prod) - sum);
    return kvec4(prod / r4, s1, s2, r4);
}

// Cases 1 and 2: four real roots r1 <= r2 <= r3 <= r4; the camera outside r4 (case 2) or between r2 and r3
// (case 1). rp, rm: the horizons; ah: their weights in I_phi.
void kerr_radial_real(inout KerrRadial k, kreal a, kreal r_o, float s_r, kreal r1, kreal r2, kreal r3, kreal r4,
                      kreal rp, kreal rm, kvec2 ah) {
    kreal r21 = r2 - r1, r31 = r3 - r1, r32 = r3 - r2, r41 = r4 - r1, r42 = r4 - r2, r43 = r4 - r3;
    k.r1 = float(r1); k.r2 = float(r2); k.r3 = float(r3); k.r4 = float(r4);
    k.r21 = float(r21); k.r31 = float(r31); k.r32 = float(r32); k.r41 = float(r41); k.r43 = float(r43);
    kreal m = r32 * r41 / (r31 * r42), mc = r21 * r43 / (r31 * r42);
    k.m = float(m);
    k.mc = float(mc);
    k.rate = float(0.5 * sqrt(r31 * r42));
    if (r_o >= r4) {
        // sin^2 = (r - r4) r31 / ((r - r3) r41), cos^2 = r43 (r - r1) / ((r - r3) r41).
        k.kcase = 2;
        kreal den = 1.0 / ((r_o - r3) * r41);
        kreal c2 = r43 * (r_o - r1) * den;
        k.rf_cam = vec3(float(c2), float(mc + m * c2), float((r_o - r4) * r31 * den));
        k.captured = r4 < rp && s_r < 0.0;
        den = k.captured ? 1.0 / ((rp - r3) * r41) : 1.0 / r41;
        c2 = k.captured ? r43 * (rp - r1) * den : r43 * den;
        k.rf_end = vec3(float(c2), float(mc + m * c2), float((k.captured ? rp - r4 : 1.0) * r31 * den));
#ifdef KERR_ESCAPE64
        if (!k.captured && a != 0.0) {
            kreal d0 = 1.0 / ((r_o - r3) * r41);
            kerr_escape_set(k, kerr_escape2_d(dvec4(r1, r2, r3, r4), m, mc, 0.5 * sqrt(r31 * r42),
                                              dvec2((r_o - r4) * r31 * d0, r43 * (r_o - r1) * d0),
                                              dvec2(r31 / r41, r43 / r41), s_r, dvec2(rp, rm), ah));
        }
#endif
    } else {
        // sin^2 = (r - r2) r31 / ((r - r1) r32), cos^2 = r21 (r3 - r) / ((r - r1) r32).
        k.kcase = 1;
        k.captured = true;
        kreal den = 1.0 / ((r_o - r1) * r32);
        kreal c2 = r21 * (r3 - r_o) * den;
        k.rf_cam = vec3(float(c2), float(mc + m * c2), float((r_o - r2) * r31 * den));
        den = 1.0 / ((rp - r1) * r32);
        c2 = r21 * (r3 - rp) * den;
        k.rf_end = vec3(float(c2), float(mc + m * c2), float((rp - r2) * r31 * den));
        k.fold_end = s_r > 0.0;
    }
}

// Case 3: two real roots r1 < r2 and a complex pair z +- i sqrt(-q2).
// x(r) = (A (r - r1) - B (r - r2)) / (A (r - r1) + B (r - r2)) = cn xi:
// cos^2 = x^2, sin^2 = 4 A B (r - r1) (r - r2) / (A (r - r1) + B (r - r2))^2.
void kerr_radial_pair(inout KerrRadial k, kreal a, kreal r_o, float s_r, kreal z, kreal q1, kreal q2, kreal rp,
                      kreal rm, kvec2 ah) {
    k.kcase = 3;
    kreal r1 = -z - sqrt(q1), r2 = -z + sqrt(q1), y = sqrt(-q2);
    kreal r21 = r2 - r1;
    k.r1 = float(r1); k.r2 = float(r2); k.r21 = float(r21);
    kreal ba = sqrt((z - r2) * (z - r2) + y * y), bb = sqrt((z - r1) * (z - r1) + y * y);
    k.ba = float(ba); k.bb = float(bb);
    kreal i4ab = 1.0 / (4.0 * ba * bb);
    kreal m = ((ba + bb) * (ba + bb) - r21 * r21) * i4ab, mc = (r21 * r21 - (ba - bb) * (ba - bb)) * i4ab;
    k.m = float(m);
    k.mc = float(mc);
    k.rate = float(sqrt(ba * bb));
    kreal den = 1.0 / (ba * (r_o - r1) + bb * (r_o - r2));
    kreal x = (ba * (r_o - r1) - bb * (r_o - r2)) * den;
    k.rf_cam = vec3(float(x * x), float(mc + m * x * x), float(4.0 * ba * bb * (r_o - r1) * (r_o - r2) * den * den));
    k.fold_cam = x < 0.0;
    k.captured = s_r < 0.0;
    if (k.captured) {
        den = 1.0 / (ba * (rp - r1) + bb * (rp - r2));
        x = (ba * (rp - r1) - bb * (rp - r2)) * den;
        k.rf_end = vec3(float(x * x), float(mc + m * x * x), float(4.0 * ba * bb * (rp - r1) * (rp - r2) * den * den));
    } else {
        den = 1.0 / (ba + bb);
        x = (ba - bb) * den;
        k.rf_end = vec3(float(x * x), float(mc + m * x * x), float(4.0 * ba * bb * den * den));
    }
    k.fold_end = x < 0.0;
#ifdef KERR_ESCAPE64
    if (!k.captured && a != 0.0) {
        kreal d0 = 1.0 / (ba * (r_o - r1) + bb * (r_o - r2));
        kreal x0 = (ba * (r_o - r1) - bb * (r_o - r2)) * d0;
        kerr_escape_set(k, kerr_escape3_d(r1, r2, dvec2(ba, bb), m, mc, sqrt(ba * bb), x0,
                                          4.0 * ba * bb * (r_o - r1) * (r_o - r2) * d0 * d0, x,
                                          4.0 * ba * bb * den * den, dvec2(rp, rm), ah));
    }
#endif
}

// Case 4 (vortical only): no real root outside; an inward ray falls in, an
// outward one escapes (its Mino time and I_phi by Gauss-Legendre in u =
// 1/r).
void kerr_radial_none(inout KerrRadial k, kreal a, kreal lam, kreal eta, kreal r_o, float s_r) {
    k.kcase = 4;
    k.captured = s_r < 0.0;
    k.m = 0.0;
    k.mc = 1.0;
    k.rate = 1.0;
    float af = float(a), lf = float(lam), ef = float(eta);
    float uo = float(1.0 / r_o), tau = 0.0, iphi = 0.0;
    // (None in the split's trace pass, which defers case 4.)
    [[dont_unroll]] for (int i = 0; i < (KERR_COMMON_ONLY ? 0 : 16); ++i) {
        vec2 xw = kerr_gl_node(i);
        float u = 0.5 * uo * (xw.x + 1.0), ww = 0.5 * uo * xw.y;
        float rt = inversesqrt(kerr_f_u(u, af, lf, ef));
        tau += ww * rt;
        iphi += ww * af * (2.0 * u - af * lf * u * u) / (1.0 - 2.0 * u + af * af * u * u) * rt;
    }
    k.tau_end = tau;
    k.i_phi_end = iphi;
}

// The per-ray part, in kreal: the roots, the case, the modulus, and the
// R_F arguments at the two ends (kerr_radial_ends finishes it in f32).
KerrRadial kerr_radial(kreal a, kreal lam, kreal eta, kreal r_o, float s_r) {
    KerrRadial k;
    k.s_r = s_r;
    k.i_phi_end = 0.0;
    k.end_exact = false;
    k.tau_end64 = 0.0;
    k.fold_cam = false;
    k.fold_end = false;
    k.rf_cam = vec3(1.0, 1.0, 0.0);
    k.rf_end = vec3(1.0, 1.0, 0.0);
    k.r1 = k.r2 = k.r3 = k.r4 = 0.0;
    k.r21 = k.r31 = k.r32 = k.r41 = k.r43 = 1.0;
    k.ba = k.bb = 1.0;
    kreal rp = 1.0 + sqrt(1.0 - a * a), rm = a * a / rp;
    k.rh = vec2(float(rp), float(rm));
    kvec2 ah = kvec2(a * (2.0 * rp - a * lam) / (rp - rm), -a * (2.0 * rm - a * lam) / (rp - rm));
    k.ah = vec2(ah);
    kreal z, q1, q2;
    kreal ca = a * a - eta - lam * lam, cb = 2.0 * (eta + (lam - a) * (lam - a)), cc = -a * a * eta;
    if (-ca >= KERR_FAR_ROOTS) {
        kvec4 r = kerr_far_roots(ca, cb, cc);
        kerr_radial_real(k, a, r_o, s_r, r.x, r.y, r.z, r.w, rp, rm, ah);
        return k;
    }
    kerr_roots(ca, cb, cc, z, q1, q2);
    if (q1 >= 0.0 && q2 >= 0.0) {
        kerr_radial_real(k, a, r_o, s_r, -z - sqrt(q1), -z + sqrt(q1), z - sqrt(q2), z + sqrt(q2), rp, rm, ah);
    } else if (q1 >= 0.0) {
        kerr_radial_pair(k, a, r_o, s_r, z, q1, q2, rp, rm, ah);
    } else {
        kerr_radial_none(k, a, lam, eta, r_o, s_r);
    }
    return k;
}

// The radial path in f32, from F at the camera and at the end (R_F of
// rf_cam, rf_end, computed with the polar motion's in one carlson_rf4).
void kerr_radial_ends(inout KerrRadial k, float f_cam, float f_end) {
    k.kk = complete_k(k.mc);
    k.agm = agm_of(k.mc);
    k.cam = KerrPoint(sqrt(k.rf_cam.z), k.rf_cam.x, f_cam, k.s_r, 0.0, false);
    k.end = KerrPoint(sqrt(k.rf_end.z), k.rf_end.x, f_end, 1.0, 0.0, k.fold_end);
    if (k.kcase == 2) {
        k.x0 = k.s_r * f_cam;
        k.tau_end = ((k.captured ? -f_end : f_end) - k.x0) / k.rate;
        k.end.sgn = k.captured ? -1.0 : 1.0;
    } else if (k.kcase == 1) {
        k.x0 = k.s_r * f_cam;
        k.tau_end = ((k.s_r < 0.0 ? -f_end : 2.0 * k.kk - f_end) - k.x0) / k.rate;
        k.end.sgn = k.s_r < 0.0 ? -1.0 : 1.0;
    } else if (k.kcase == 3) {
        k.x0 = k.fold_cam ? 2.0 * k.kk - f_cam : f_cam;
        // xi_end - xi_o without the 2K that cancels when both fold alike.
        float d = (k.fold_end ? -f_end : f_end) - (k.fold_cam ? -f_cam : f_cam)
                + 2.0 * k.kk * (float(k.fold_end) - float(k.fold_cam));
        k.tau_end = (k.captured ? -d : d) / k.rate;
        k.cam.sgn = 1.0;
        k.cam.fold = k.fold_cam;
    }
    if (k.end_exact) k.tau_end = k.tau_end64;
}

// The point of the path at Mino time tau (its sn, cn and F).
// (One Jacobi evaluation for every case: on a CPU driver a second call in
// a branch would run for every path.)
KerrPoint kerr_radial_point(KerrRadial k, float tau) {
    bool c3 = k.kcase == 3;
    float x = k.x0 + (c3 ? k.s_r : 1.0) * k.rate * tau;
    return kerr_point_2k(c3 ? x : abs(x), c3 || x >= 0.0 ? 1.0 : -1.0, k.agm, k.kk);
}

float kerr_r_of(KerrRadial k, KerrPoint e) {
    float s2 = e.s * e.s;
    if (k.kcase == 2) return k.r4 + k.r43 * k.r41 * s2 / max(k.r31 - k.r41 * s2, 1e-30);
    if (k.kcase == 1) return k.r2 + k.r21 * k.r32 * s2 / (k.r31 - k.r32 * s2);
    float cn = e.fold ? -sqrt(e.c2) : sqrt(e.c2);
    return ((k.bb * k.r2 - k.ba * k.r1) + (k.bb * k.r2 + k.ba * k.r1) * cn) / ((k.bb - k.ba) + (k.bb + k.ba) * cn);
}

// J_h by 16-point Gauss-Legendre along the closed-form r(tau), where the
// closed form is 0/0 (r_h = r_- next to r2).
float kerr_j_quadrature(KerrRadial k, float rh, float tau) {
    float sum = 0.0;
    int i = 0;
    [[dont_unroll]] do {
        vec2 xw = kerr_gl_node(i);
        sum += xw.y / (kerr_r_of(k, kerr_radial_point(k, 0.5 * tau * (xw.x + 1.0))) - rh);
    } while (++i < 16);
    return 0.5 * tau * sum;
}

// Pi at a point of the radial path, with its fold and sign.
float kerr_pi_signed(float n, KerrPoint e, float pc, KerrRadial k) {
    float v = kerr_pi(n, e, k.m, k.mc);
    return e.sgn * (e.fold ? 2.0 * pc - v : v);
}

// J_h(tau) = the integral of 1 / (r - r_h) over Mino time from the camera
// (point e0) to Mino time tau (point e1).
float kerr_j(KerrRadial k, float rh, float tau, KerrPoint e0, KerrPoint e1) {
    if (k.kcase == 2) {
        // tau / r3h - r43 / (rate r4h r3h) (Pi(n; X1) - Pi(n; X0)).
        float r4h = k.r4 - rh;
        float n = k.r41 * (k.r3 - rh) / (k.r31 * r4h);
        if (rh > k.r4) {
            // The horizon beyond r4 (a captured ray that turns inside it):
            // n > 1 and the path lies past Pi's pole (the horizon), the
            // principal value.
            float dp = e1.sgn * kerr_pi(n, e1, k.m, k.mc) - e0.sgn * kerr_pi(n, e0, k.m, k.mc);
            return tau / (k.r3 - rh) - k.r43 / (k.rate * r4h * (k.r3 - rh)) * dp;
        }
        // With Pi = X + (n/3) s^3 R_J and X1 - X0 = rate tau, rearranged so
        // that nothing cancels where r3 meets the horizon (lambda near
        // 2 r_h / a, where R(r_h) = (2 r_h - a lambda)^2 vanishes): 0 <= n < 1.
        vec2 c2 = vec2(e0.c2, e1.c2), s = vec2(e0.s, e1.s);
        vec4 rj = kerr_rj(vec4(c2, 1.0, 1.0), vec4(k.mc + k.m * c2, 1.0, 1.0), vec4(1.0 - n * s * s, 1.0, 1.0));
        float q = dot(vec2(-e0.sgn, e1.sgn) * s * s * s, rj.xy);
        return tau / r4h - k.r43 * k.r41 / (3.0 * k.rate * k.r31 * r4h * r4h) * q;
    }
    if (abs(rh - k.r2) < 1e-4 * k.r21) return kerr_j_quadrature(k, rh, tau);
    if (k.kcase == 1) {
        float n = k.r32 * (k.r1 - rh) / (k.r31 * (k.r2 - rh));
        float pc = e0.fold || e1.fold ? kerr_pi_complete(n, k.kk, k.m, k.mc) : 0.0;
        float dp = kerr_pi_signed(n, e1, pc, k) - kerr_pi_signed(n, e0, pc, k);
        return tau / (k.r1 - rh) - k.r21 / (k.rate * (k.r2 - rh) * (k.r1 - rh)) * dp;
    }
    // Case 3.
    float a = k.ba, b = k.bb;
    float dm = b * (rh - k.r2) - a * (rh - k.r1);
    float dq = b * (rh - k.r2) + a * (rh - k.r1);
    float al = dq / dm;
    float c1 = -(b + a) / dq;
    float c2 = -((b - a) - (b + a) * dm / dq) / dm;
    float n = al * al / (al * al - 1.0);
    if (abs(n - 1.0) < 0.05) return kerr_j_quadrature(k, rh, tau);
    float gam = k.m + al * al / (1.0 - al * al);
    float pc = e0.fold || e1.fold ? kerr_pi_complete(n, k.kk, k.m, k.mc) : 0.0;
    float rr[2];
    int i = 0;
    [[dont_unroll]] do {
        KerrPoint e = i == 0 ? e0 : e1;
        float w = e.s * inversesqrt(k.mc + k.m * e.c2);
        rr[i] = (kerr_pi_signed(n, e, pc, k) - al * w * kerr_rc(1.0, 1.0 + gam * w * w)) / (1.0 - al * al);
    } while (++i < 2);
    return c1 * tau + k.s_r / k.rate * c2 * (rr[1] - rr[0]);
}

// kerr_j's case-2 form holds for both horizons where they lie inside r4
// (every ray that escapes); its Pi's characteristics n for the two.
bool kerr_i_phi_case2(KerrRadial k) {
    return k.kcase == 2 && k.rh.x <= k.r4;
}

vec2 kerr_i_phi_n(KerrRadial k) {
    return k.r41 * (k.r3 - k.rh) / (k.r31 * (k.r4 - k.rh));
}

// I_phi(tau): the integral of a (2 r - a lambda) / Delta over Mino time,
// e1 the path's point at tau; rj: the R_J of its case-2 form at e1 for the
// two horizons (kerr_end), k.q_cam their camera's part (kerr_phi_start).
float kerr_i_phi(KerrRadial k, float a, float tau, KerrPoint e1, vec2 rj) {
    if (a == 0.0) return 0.0;
    if (k.kcase == 4 || k.end_exact && tau == k.tau_end) return k.i_phi_end;
    if (kerr_i_phi_case2(k)) {
        // kerr_j's rearranged form for both horizons at once.
        vec2 r4h = k.r4 - k.rh;
        vec2 q = k.q_cam + e1.sgn * e1.s * e1.s * e1.s * rj;
        return dot(k.ah, tau / r4h - k.r43 * k.r41 / (3.0 * k.rate * k.r31 * r4h * r4h) * q);
    }
    if (KERR_COMMON_ONLY) return 0.0;  // (metric_trace deferred the path)
    float sum = 0.0;
    // One loop over the two horizons: one copy of kerr_j in the shader
    // (tested after its body, as kerr_rj's loop: before it, a third kerr_j).
    int i = 0;
    [[dont_unroll]] do {
        sum += k.ah[i] * kerr_j(k, k.rh[i], tau, k.cam, e1);
    } while (++i < 2);
    return sum;
}

#endif
