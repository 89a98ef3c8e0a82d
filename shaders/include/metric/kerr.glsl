// One spinning (Kerr) hole: exact light paths in closed form, in Mino time
// (Gralla & Lupsasca 2020), the GPU twin of src/physics/kerr (which
// documents the mathematics and is tested against a step-by-step
// integrator and an independent reference). A pixel direction in the ZAMO's
// frame gives the photon's constants (lambda, eta) and the signs of its
// backward motion; the roots of the radial quartic pick one of four cases
// and give r(tau); theta(tau) crosses the equator at an arithmetic
// progression of Mino times, so the thin disk's crossings come without
// steps; the azimuth and the escape direction come from Carlson's
// integrals.
//
// Precision. The per-ray constants (the Boyer-Lindquist position, lambda
// and eta, the quartic's roots, the case and the arguments of the elliptic
// integrals at the camera and at the path's end) are computed in `kreal`:
// 64-bit floats where the device has shaderFloat64, since near the shadow's
// outline the roots' differences cancel far below f32 resolution (0.1
// relative error in r4 - r3 in plain f32, below 1e-9 in f64). Everything
// after (Carlson's integrals, the Jacobi functions, the crossings, the
// azimuth) runs in 32-bit floats, whose 1e-7 relative error keeps the
// escape direction within 1e-5 rad and the disk radius within 2e-4 rs
// (tests/kerr_gpu.rs); the geodesic AOV takes an escaping path's I_phi and
// Mino time in 64 bits too (KERR_ESCAPE64). A device without 64-bit floats
// gets the build with KERR_F32_ROOTS: the same path with kreal = float,
// exact away from a thin band around the shadow's outline.
//
// Units: M = 1 inside (lengths in rs = 2M = 1 at the boundary); the hole's
// frame has x = disk e1, y = the spin axis (the disk's normal), z = e2.
#ifndef METRIC_KERR_GLSL
#define METRIC_KERR_GLSL

// Loops stay loops: unrolled and inlined at every call, the kernels below
// make a shader that the driver takes minutes to compile.
#extension GL_EXT_control_flow_attributes : require

#include "params.glsl"
#include "variant.glsl"
#include "hit.glsl"
#include "disk.glsl"
#include "ray_state.glsl"
#include "volume.glsl"
#include "lightpath.glsl"
#include "metric/static_frame.glsl"

// The split ray march (raymarch.comp, on a CPU device, which runs every
// branch for every pixel, taken or not): its trace pass carries the common
// paths only, and leaves the rest (a polar motion that never crosses the
// equator, the radial case 4, and I_phi anywhere but on a case-2 path whose
// turning point lies outside the horizon: in most views the shadow's
// pixels whose path meets the disk first) to the second pass, which redoes
// their 2x2 quads with the whole of this file.
const bool METRIC_SPLITS_RARE = true;
const bool KERR_COMMON_ONLY = DISK_STAGE == DISK_STAGE_TRACE;
// The trace pass runs the build with 32-bit roots (passes/raymarch), exact
// away from the shadow's edge; a path whose roots r3 and r4 lie within a
// tenth of r4 of each other (near the photon orbits' double root, where
// their f32 difference loses its digits) goes to the second pass too.
#ifdef KERR_F32_ROOTS
#define KERR_NEAR_EDGE(rad) ((rad).kcase == 2 && (rad).r43 < 0.1 * (rad).r4)
#else
#define KERR_NEAR_EDGE(rad) false
#endif

// The turns of Newton's method that polish the quartic's roots
// (kerr_radial): on the cube roots of the Cardano estimate, then on the
// resolvent cubic. In 32 bits most estimates are already within a few
// units of the last place, but not all: with two turns on the resolvent a
// path at the top edge of gargantua's view (640x360) went astray and drew a
// star the one-dispatch image (64-bit roots) does not have; three match it
// (the Cardano cube roots need none). In 64 bits the estimates' 32-bit
// digits need doubling twice.
#ifdef KERR_F32_ROOTS
#define kreal float
#define kvec2 vec2
#define kvec3 vec3
const int KERR_CBRT_TURNS = 0, KERR_RESOLVENT_TURNS = 3;
#else
#define kreal double
#define kvec2 dvec2
#define kvec3 dvec3
const int KERR_CBRT_TURNS = 3, KERR_RESOLVENT_TURNS = 4;
#endif

// The geodesic AOV (the renderer's exact record of each path) takes an
// escaping path's I_phi and Mino time in 64 bits as well (below: from a
// camera near the horizon their 32-bit forms cancel, up to 1e-4 rad off at
// a* = 0.998 inside the ergoregion). The image keeps the 32-bit forms: the
// largest error seen is a quarter of a pixel of a 3840x2160 view of 50
// degrees, and the 64 bits would cost a CPU driver, which runs every
// branch, 70 % of the frame.
#if defined(GEODESIC_AOV) && !defined(KERR_F32_ROOTS)
#define KERR_ESCAPE64
#endif

// --------------------------------------------------------------- kernels

// Carlson's R_C(x, y), x >= 0, y > 0, by four duplication steps (each
// brings x and y some four times closer: from |s| <= 1 to below 0.004,
// s = (y - x) / (x + 2 y)) and its series to s^5 (error below 1e-13
// there): no inverse trigonometric or hyperbolic function and no branch
// (atan, atanh and their series would all run on a CPU driver). And
// R_C(1, 1 + e) for |e| < 0.03 (every duplication turn of R_J after the
// first) by its series to e^6, error below 2e-12. Written once (the macro)
// for one integral and for three or four at once (KERR_RJ).
#define KERR_RC(T)                                                                 \
    T kerr_rc_dup(T x, T y) {                                                      \
        [[unroll]] for (int i = 0; i < 4; ++i) {                                   \
            T l = 2.0 * sqrt(x * y) + y;                                           \
            x = 0.25 * (x + l);                                                    \
            y = 0.25 * (y + l);                                                    \
        }                                                                          \
        T imu = 3.0 / (x + 2.0 * y);                                               \
        T s = (1.0 / 3.0) * (y - x) * imu;                                         \
        return (1.0 + s * s * (0.3 + s * (1.0 / 7.0 + s * (0.375 + s * (9.0 / 22.0))))) * sqrt(imu); \
    }                                                                              \
    T kerr_rc_series(T e) {                                                        \
        return 1.0 + e * (-1.0 / 3.0 + e * (0.2 + e * (-1.0 / 7.0 + e * (1.0 / 9.0 \
                   + e * (-1.0 / 11.0 + e * (1.0 / 13.0))))));                     \
    }
KERR_RC(float)
KERR_RC(vec3)
KERR_RC(vec4)

// R_C(x, y), x >= 0, y != 0, the Cauchy principal value for y < 0 (DLMF
// 19.2.20: sqrt(x / (x - y)) R_C(x - y, -y)).
float kerr_rc(float x, float y) {
    return (y < 0.0 ? sqrt(x / (x - y)) : 1.0) * kerr_rc_dup(y < 0.0 ? x - y : x, abs(y));
}

// R_J's duplication is done when every argument is within 0.2 of the mean.
bool kerr_rj_done(float spread, float a) {
    return spread < 0.2 * a;
}

bool kerr_rj_done(vec3 spread, vec3 a) {
    return all(lessThan(spread, 0.2 * a));
}

bool kerr_rj_done(vec4 spread, vec4 a) {
    return all(lessThan(spread, 0.2 * a));
}

// Carlson's R_J(x, y, 1, p), p > 0 (every one this file needs has z = 1;
// Carlson 1995, DLMF 19.36.2): each duplication turn adds 4^-m R_C(1, 1 +
// e_m) / d_m with d = prod(sqrt p + sqrt x_i) and e = prod(sqrt p - sqrt
// x_i) / d, so |e| < 1, and it falls some 64-fold a turn: the first turn
// takes R_C by its own duplication (kerr_rc_dup), the rest its series.
// Until the arguments are within 0.2 of their mean; then the series to the
// seventh order, whose error there is below 2.2e-7 (the fifth order's, at
// 0.1, was below 1.5e-7: a turn of the loop fewer for the same accuracy,
// about one in six; measured against mpmath). The first turn comes before
// the loop (on a CPU driver a loop's body runs all of itself every turn),
// and the loop's body runs at least once, its test after it: a CPU driver
// runs a loop's body until no lane of the SIMD group is left, so a test
// before it cost one body more than the longest lane needs (nearly every
// SIMD group needs exactly one; a turn more only brings the arguments
// closer).
//
// Written once (the macro) for one integral and for three or four at once:
// a path's integrals at one point come in one loop instead of three or four.
#define KERR_RJ(T)                                                                                   \
    T kerr_rj(T x, T y, T p) {                                                                       \
        T z = T(1.0), sum, a;                                                                        \
        float fac = 0.25;                                                                            \
        {                                                                                            \
            T sx = sqrt(x), sy = sqrt(y), sp = sqrt(p);                                              \
            T l = sx * (sy + 1.0) + sy;                                                              \
            T id = 1.0 / ((sp + sx) * (sp + sy) * (sp + 1.0));                                       \
            sum = id * kerr_rc_dup(T(1.0), 1.0 + (sp - sx) * (sp - sy) * (sp - 1.0) * id);           \
            x = 0.25 * (x + l);                                                                      \
            y = 0.25 * (y + l);                                                                      \
            z = 0.25 * (z + l);                                                                      \
            p = 0.25 * (p + l);                                                                      \
            a = 0.2 * (x + y + z + p + p);                                                           \
        }                                                                                            \
        [[dont_unroll]] for (int i = 1; i < 16; ++i) {                                               \
            T sx = sqrt(x), sy = sqrt(y), sz = sqrt(z), sp = sqrt(p);                                \
            T l = sx * (sy + sz) + sy * sz;                                                          \
            T id = 1.0 / ((sp + sx) * (sp + sy) * (sp + sz));                                        \
            sum += fac * id * kerr_rc_series((sp - sx) * (sp - sy) * (sp - sz) * id);                \
            fac *= 0.25;                                                                             \
            x = 0.25 * (x + l);                                                                      \
            y = 0.25 * (y + l);                                                                      \
            z = 0.25 * (z + l);                                                                      \
            p = 0.25 * (p + l);                                                                      \
            a = 0.2 * (x + y + z + p + p);                                                           \
            if (kerr_rj_done(max(max(abs(a - x), abs(a - y)), max(abs(a - z), abs(a - p))), a)) break; \
        }                                                                                            \
        /* The series at the mean (DLMF 19.36.2), 4^-m a^(-3/2) times it. */                         \
        T ia = 1.0 / a;                                                                              \
        T bx = (a - x) * ia, by = (a - y) * ia, bz = (a - z) * ia;                                   \
        T bp = -0.5 * (bx + by + bz);                                                                \
        T xyz = bx * by * bz, p2 = bp * bp;                                                          \
        T e2 = bx * by + bx * bz + by * bz - 3.0 * p2;                                               \
        T e3 = xyz + 2.0 * e2 * bp + 4.0 * p2 * bp;                                                  \
        T e4 = (2.0 * xyz + e2 * bp + 3.0 * p2 * bp) * bp;                                           \
        T e5 = xyz * p2;                                                                             \
        T series = 1.0 - (3.0 / 14.0) * e2 + e3 * (1.0 / 6.0) + (9.0 / 88.0) * e2 * e2              \
                 - (3.0 / 22.0) * e4 - (9.0 / 52.0) * e2 * e3 + (3.0 / 26.0) * e5                   \
                 - (1.0 / 16.0) * e2 * e2 * e2 + (3.0 / 40.0) * e3 * e3 + (3.0 / 20.0) * e2 * e4     \
                 + (45.0 / 272.0) * e2 * e2 * e3 - (9.0 / 68.0) * (e3 * e4 + e2 * e5);              \
        return fac * ia * sqrt(ia) * series + 6.0 * sum;                                             \
    }
KERR_RJ(float)
KERR_RJ(vec3)
KERR_RJ(vec4)

#ifdef KERR_ESCAPE64
// ------------------------------------------- I_phi to infinity in 64 bits
//
// An escaping path's I_phi (and its Mino time) from the camera to infinity
// in 64-bit floats, where the device has them: both ends' points come from
// the roots (no Jacobi function, whose sine has no 64-bit form), so only
// Carlson's integrals are needed, and they need no trigonometry either. In
// 32 bits I_phi's closed forms lose digits to cancellation when the camera
// stands near the horizon (the two horizons' terms, or Pi near its pole):
// escape directions off by up to 1e-4 rad at a* = 0.998 from inside the
// ergoregion (tests/kerr_gpu.rs). R_C is the 32-bit kernel instantiated in
// double; R_J takes R_C by duplication at every turn (the 32-bit kernel's
// series after the first turn needs the arguments near each other, which a
// p far from x, y and 1 is not) and duplicates until its arguments are
// within 0.004 of their mean (series error there below 1e-14; measured
// against scipy over x, y in [0, 1.5], p in [1e-6, 1e6]: 1.6e-12). Their
// loops break inside the body: written as do-while with the 64-bit test in
// the condition, lavapipe (Mesa 22.3) returned R_F off by 5e-4 for some
// lanes.
KERR_RC(double)

double kerr_rj_d(double x, double y, double p) {
    double z = 1.0, sum = 0.0, fac = 1.0, a = 1.0;
    [[dont_unroll]] for (int i = 0; i < 24; ++i) {
        double sx = sqrt(x), sy = sqrt(y), sz = sqrt(z), sp = sqrt(p);
        double l = sx * (sy + sz) + sy * sz;
        double id = 1.0 / ((sp + sx) * (sp + sy) * (sp + sz));
        sum += fac * id * kerr_rc_dup(1.0, 1.0 + (sp - sx) * (sp - sy) * (sp - sz) * id);
        fac *= 0.25;
        x = 0.25 * (x + l);
        y = 0.25 * (y + l);
        z = 0.25 * (z + l);
        p = 0.25 * (p + l);
        a = 0.2 * (x + y + z + p + p);
        if (max(max(abs(a - x), abs(a - y)), max(abs(a - z), abs(a - p))) < 0.004 * a) break;
    }
    double ia = 1.0 / a;
    double bx = (a - x) * ia, by = (a - y) * ia, bz = (a - z) * ia;
    double bp = -0.5 * (bx + by + bz);
    double xyz = bx * by * bz, p2 = bp * bp;
    double e2 = bx * by + bx * bz + by * bz - 3.0 * p2;
    double e3 = xyz + 2.0 * e2 * bp + 4.0 * p2 * bp;
    double e4 = (2.0 * xyz + e2 * bp + 3.0 * p2 * bp) * bp;
    double e5 = xyz * p2;
    double series = 1.0 - (3.0 / 14.0) * e2 + e3 / 6.0 + (9.0 / 88.0) * e2 * e2 - (3.0 / 22.0) * e4
                  - (9.0 / 52.0) * e2 * e3 + (3.0 / 26.0) * e5;
    return fac * ia * sqrt(ia) * series + 6.0 * sum;
}

double kerr_rc_d(double x, double y) {
    return (y < 0.0 ? sqrt(x / (x - y)) : 1.0) * kerr_rc_dup(y < 0.0 ? x - y : x, abs(y));
}

// R_F(x, y, z) by duplication to within 0.004 of the mean, then the series
// of carlson_rf4.
double kerr_rf_d(double x, double y, double z) {
    double a = (x + y + z) / 3.0;
    [[dont_unroll]] for (int i = 0; i < 24; ++i) {
        double sx = sqrt(x), sy = sqrt(y), sz = sqrt(z);
        double l = sx * (sy + sz) + sy * sz;
        x = 0.25 * (x + l);
        y = 0.25 * (y + l);
        z = 0.25 * (z + l);
        a = (x + y + z) / 3.0;
        if (max(abs(a - x), max(abs(a - y), abs(a - z))) < 0.004 * a) break;
    }
    double ia = 1.0 / a;
    double dx = 1.0 - x * ia, dy = 1.0 - y * ia, dz = 1.0 - z * ia;
    double e2 = dx * dy - dz * dz, e3 = dx * dy * dz;
    double series = 1.0 - e2 * 0.1 + e3 / 14.0 + e2 * e2 / 24.0 - e2 * e3 * 3.0 / 44.0;
    return series * sqrt(ia);
}

// Pi(n; phi | m) at the point sin phi = s >= 0, cos^2 phi = c2, F(phi) = f,
// any n (the principal value past the pole through the partner m / n, as
// kerr_pi), and the complete one.
double kerr_pi_d(double n, double s, double c2, double f, double m, double mc) {
    double s2 = s * s, d2 = mc + m * c2;
    bool pv = n > 1.0;
    double nn = pv ? m / n : n;
    double t = nn / 3.0 * s2 * s * kerr_rj_d(c2, d2, 1.0 - nn * s2);
    return pv ? s * kerr_rc_d(c2 * d2, (1.0 - n * s2) * (1.0 - nn * s2)) - t : f + t;
}

double kerr_pi_complete_d(double n, double kk, double m, double mc) {
    bool pv = n > 1.0;
    double nn = pv ? m / n : n;
    double t = nn / 3.0 * kerr_rj_d(0.0, mc, 1.0 - nn);
    return pv ? -t : kk + t;
}

// Case 2 (r_o >= r4) to infinity: (Mino time, I_phi). The camera's point
// (sin^2, cos^2) = sc, the end's se; a_h: the horizons' weights.
dvec2 kerr_escape2_d(dvec4 r, double m, double mc, double rate, dvec2 sc, dvec2 se, double s_r, dvec2 rh,
                     dvec2 ah) {
    double r31 = r.z - r.x, r41 = r.w - r.x, r43 = r.w - r.z;
    double s0 = sqrt(sc.x), s1 = sqrt(se.x);
    double f0 = s0 * kerr_rf_d(sc.y, mc + m * sc.y, 1.0), f1 = s1 * kerr_rf_d(se.y, mc + m * se.y, 1.0);
    double tau = (f1 - s_r * f0) / rate, sum = 0.0;
    for (int i = 0; i < 2; ++i) {
        double r4h = r.w - rh[i], r3h = r.z - rh[i];
        double n = r41 * r3h / (r31 * r4h);
        double j;
        if (r4h > 0.0) {
            // kerr_j's rearranged form (0 <= n < 1).
            double q = s1 * se.x * kerr_rj_d(se.y, mc + m * se.y, 1.0 - n * se.x)
                     - s_r * s0 * sc.x * kerr_rj_d(sc.y, mc + m * sc.y, 1.0 - n * sc.x);
            j = tau / r4h - r43 * r41 / (3.0 * rate * r31 * r4h * r4h) * q;
        } else {
            double dp = kerr_pi_d(n, s1, se.y, f1, m, mc) - s_r * kerr_pi_d(n, s0, sc.y, f0, m, mc);
            j = tau / r3h - r43 / (rate * r4h * r3h) * dp;
        }
        sum += ah[i] * j;
    }
    return dvec2(tau, sum);
}

// Case 3 (two real roots r1 < r2 < r_o, outward) to infinity: (Mino time,
// I_phi). The points' cn = x, x_end; A = ab.x, B = ab.y. Where a horizon
// sits at Pi's pole (n = 1) or at r2, NaN: the 32-bit forms take it.
dvec2 kerr_escape3_d(double r1, double r2, dvec2 ab, double m, double mc, double rate, double x0, double s20,
                     double x1, double s21, dvec2 rh, dvec2 ah) {
    double kk = kerr_rf_d(0.0, mc, 1.0);
    double s0 = sqrt(s20), s1 = sqrt(s21), c20 = x0 * x0, c21 = x1 * x1;
    double f0 = s0 * kerr_rf_d(c20, mc + m * c20, 1.0), f1 = s1 * kerr_rf_d(c21, mc + m * c21, 1.0);
    bool fold0 = x0 < 0.0, fold1 = x1 < 0.0;
    double tau = ((fold1 ? 2.0 * kk - f1 : f1) - (fold0 ? 2.0 * kk - f0 : f0)) / rate, sum = 0.0;
    double a = ab.x, b = ab.y;
    double w0 = s0 / sqrt(mc + m * c20), w1 = s1 / sqrt(mc + m * c21);
    for (int i = 0; i < 2; ++i) {
        double dm = b * (rh[i] - r2) - a * (rh[i] - r1);
        double dq = b * (rh[i] - r2) + a * (rh[i] - r1);
        double al = dq / dm, al2 = al * al;
        double n = al2 / (al2 - 1.0);
        if (abs(n - 1.0) < 1e-9 || abs(rh[i] - r2) < 1e-9 * (r2 - r1)) return dvec2(tau, 0.0 / 0.0);
        double gam = m + al2 / (1.0 - al2);
        double pc = fold0 || fold1 ? kerr_pi_complete_d(n, kk, m, mc) : 0.0;
        double p0 = kerr_pi_d(n, s0, c20, f0, m, mc), p1 = kerr_pi_d(n, s1, c21, f1, m, mc);
        p0 = fold0 ? 2.0 * pc - p0 : p0;
        p1 = fold1 ? 2.0 * pc - p1 : p1;
        double rr0 = p0 - al * w0 * kerr_rc_d(1.0, 1.0 + gam * w0 * w0);
        double rr1 = p1 - al * w1 * kerr_rc_d(1.0, 1.0 + gam * w1 * w1);
        double c1 = -(b + a) / dq, c2 = -((b - a) - (b + a) * dm / dq) / dm;
        sum += ah[i] * (c1 * tau + c2 * (rr1 - rr0) / ((1.0 - al2) * rate));
    }
    return dvec2(tau, sum);
}
#endif

// A point of an elliptic integral: amplitude phi in [0, pi/2] as s =
// sin(phi) >= 0 and c2 = cos^2(phi), f = F(phi | m); the value wanted there
// is sgn (fold ? 2 Pi_c - Pi(phi) : Pi(phi)) (an argument past K or
// negative), and j counts the periods 2K taken off.
struct KerrPoint {
    float s, c2, f, sgn, j;
    bool fold;
};

// Pi(n; phi | m) at a point, any n (the principal value past the pole,
// n s^2 > 1, through the partner m / n; DLMF 19.7.8).
float kerr_pi(float n, KerrPoint e, float m, float mc) {
    float s2 = e.s * e.s, d2 = mc + m * e.c2;
    bool pv = n > 1.0;
    float nn = pv ? m / n : n;
    float t = nn * (1.0 / 3.0) * s2 * e.s * kerr_rj(e.c2, d2, 1.0 - nn * s2);
    if (pv) {
        float pole = 1.0 - n * s2;
        pole = abs(pole) < 1e-6 ? (pole < 0.0 ? -1e-6 : 1e-6) : pole;
        return e.s * kerr_rc(e.c2 * d2, pole * (1.0 - nn * s2)) - t;
    }
    return e.f + t;
}

// Pi(-N; phi | m), N >= 0, stable for large N (near the spin axis N grows
// as 1 / lambda^2): past sqrt(m) through the partner -m / N.
// Its R_J's arguments (x, y, p) at a point (kerr_pi_neg_of finishes it, so
// that a caller may take several R_J in one call).
vec3 kerr_pi_neg_args(float bn, KerrPoint e, float m, float mc) {
    float np = bn > sqrt(m) ? m / bn : bn;
    return vec3(e.c2, mc + m * e.c2, 1.0 + np * e.s * e.s);
}

float kerr_pi_neg_of(float bn, KerrPoint e, float m, float mc, float rj) {
    float s2 = e.s * e.s, d2 = mc + m * e.c2;
    bool partner = bn > sqrt(m);
    float np = partner ? m / bn : bn;
    float t = np * (1.0 / 3.0) * s2 * e.s * rj;
    // R_C(x, y) = R_C(x / y, 1) / sqrt(y): y grows without bound near the
    // spin axis (N ~ 1 / lambda^2).
    float y = (1.0 + bn * s2) * (1.0 + np * s2);
    if (partner) return e.s * kerr_rc_dup(e.c2 * d2 / y, 1.0) * inversesqrt(y) + t;
    return e.f - t;
}

float kerr_pi_neg(float bn, KerrPoint e, float m, float mc) {
    vec3 q = kerr_pi_neg_args(bn, e, m, mc);
    return kerr_pi_neg_of(bn, e, m, mc, kerr_rj(q.x, q.y, q.z));
}

// The complete Pi(n | m) (n > 1: the principal value) and Pi(-N | m).
float kerr_pi_complete(float n, float kk, float m, float mc) {
    bool pv = n > 1.0;
    float nn = pv ? m / n : n;
    float t = nn * (1.0 / 3.0) * kerr_rj(0.0, mc, 1.0 - nn);
    return pv ? -t : kk + t;
}

// The point at K (phi = pi/2), where the incomplete integrals are complete.
KerrPoint kerr_point_k(float kk) {
    return KerrPoint(1.0, 0.0, kk, 1.0, 0.0, false);
}

// The point of argument u in [0, 2K] (folded at K: sn(2K - u) = sn u).
KerrPoint kerr_point_2k(float u, float sgn, Agm g, float kk) {
    KerrPoint e;
    e.fold = u > kk;
    e.f = max(e.fold ? 2.0 * kk - u : u, 0.0);
    vec2 sc = jacobi_sn_cn(e.f, g);
    e.s = sc.x;
    e.c2 = sc.y * sc.y;
    e.sgn = sgn;
    e.j = 0.0;
    return e;
}

// The point of any real argument u, reduced by periods 2K into [-K, K).
KerrPoint kerr_point_any(float u, Agm g, float kk) {
    float j = floor((u + kk) / (2.0 * kk));
    float pr = u - 2.0 * j * kk;
    KerrPoint e = kerr_point_2k(abs(pr), pr < 0.0 ? -1.0 : 1.0, g, kk);
    e.j = j;
    return e;
}

// 16-point Gauss-Legendre on [-1, 1]: node i and its weight. The positive
// nodes and weights as vec4s picked by a one-hot mask, not an indexed
// array: a CPU driver builds a constant array indexed in a loop in every
// invocation, lane by lane, wherever the loop may run (about a tenth of the
// trace pass's code when it was one).
vec2 kerr_gl_node(int i) {
    int j = i < 8 ? 7 - i : i - 8;
    vec4 lo = vec4(equal(ivec4(j), ivec4(0, 1, 2, 3))), hi = vec4(equal(ivec4(j), ivec4(4, 5, 6, 7)));
    float x = dot(lo, vec4(0.09501250983763744, 0.2816035507792589, 0.45801677765722737, 0.6178762444026438))
            + dot(hi, vec4(0.755404408355003, 0.8656312023878318, 0.9445750230732326, 0.9894009349916499));
    float w = dot(lo, vec4(0.18945061045506864, 0.18260341504492364, 0.16915651939500265, 0.1495959888165767))
            + dot(hi, vec4(0.12462897125553407, 0.0951585116824926, 0.062253523938647456, 0.027152459411754176));
    return vec2(i < 8 ? -x : x, w);
}

// 8-point Gauss-Legendre on [-1, 1]: the positive nodes and their weights.
const float KERR_GL8_X[4] = float[4](0.1834346424956498, 0.5255324099163290, 0.7966664774136267,
    0.9602898564975363);
const float KERR_GL8_W[4] = float[4](0.3626837833783620, 0.3137066458778873, 0.2223810344533745,
    0.1012285362903763);

// --------------------------------------------------------------- the path

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
    kreal ca = a * a - eta - lam * lam;
    kreal cb = 2.0 * (eta + (lam - a) * (lam - a));
    kreal cc = -a * a * eta;
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
    kreal z = sqrt(max(zz, 0.0));
    kreal q1 = -ca / 2.0 - zz + cb / (4.0 * z);
    kreal q2 = -ca / 2.0 - zz - cb / (4.0 * z);
    if (q1 >= 0.0 && q2 >= 0.0) {
        kreal r1 = -z - sqrt(q1), r2 = -z + sqrt(q1), r3 = z - sqrt(q2), r4 = z + sqrt(q2);
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
    } else if (q1 >= 0.0) {
        // x(r) = (A (r - r1) - B (r - r2)) / (A (r - r1) + B (r - r2)) = cn xi:
        // cos^2 = x^2, sin^2 = 4 A B (r - r1) (r - r2) / (A (r - r1) + B (r - r2))^2.
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
    } else {
        // Case 4 (vortical only): no real root outside; an inward ray falls
        // in, an outward one escapes (its Mino time and I_phi by
        // Gauss-Legendre in u = 1/r).
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

// The polar motion: ordinary (eta > 0: theta oscillates about the
// equator) or vortical (eta < 0: in one hemisphere). Ordinary: cos theta =
// sqrt(u+) cn(psi), psi = w tau + s_th (K - F_o); vortical: cos theta =
// hemi sqrt(u-) / dn(v), v = v0 + w tau.
struct KerrAngular {
    bool vortical;
    float w, m, mc, kk;
    float u_plus, one_m_up, f_o, s_th;  // ordinary
    float u_minus, v0, hemi;            // vortical
    vec3 rf;                            // R_F arguments and sin^2 of F_o (or F of v0)
    float sign_f;
    bool complement;                    // rf gives K - F_o (ordinary)
    float coef;                         // lambda / (w (1 - u+)) (vortical: lambda / w)
    float psi0;                         // psi at the camera (ordinary)
    vec2 star;                          // sin^2, cos^2 of the camera's point (K - F_o; vortical F)
    KerrPoint cam;                      // the camera's point of psi (v)
    float phi_comp, phi_p0;             // G_phi's complete Pi and the camera's part (kerr_phi_start)
    Agm agm;
};

KerrAngular kerr_angular(kreal a, kreal lam, kreal eta, kreal c_o, kreal theta_o, float s_th) {
    KerrAngular g;
    kreal h = eta + lam * lam - a * a;
    kreal s = sqrt(h * h + 4.0 * a * a * eta);
    g.s_th = s_th;
    g.vortical = eta < 0.0;
    g.u_minus = 0.0;
    g.v0 = 0.0;
    g.hemi = 1.0;
    g.f_o = 0.0;
    g.complement = false;
    if (!g.vortical) {
        g.w = float(sqrt(s));
        kreal up = h >= 0.0 ? 2.0 * eta / (h + s) : (s - h) / (2.0 * a * a);
        kreal um = (h + s) / 2.0;
        g.u_plus = float(up);
        kreal omu = a * a + um > 0.0 ? lam * lam / (a * a + um) : 1.0 - up;
        g.one_m_up = float(omu);
        g.coef = float(lam / (sqrt(s) * omu));
        kreal m = a * a * up / s, mc = (s - a * a * up) / s;
        g.m = float(m);
        g.mc = float(mc);
        kreal so2 = 1.0 - c_o * c_o;
        kreal den = a * a * c_o * c_o + um;
        kreal upc = den > 0.0 ? theta_o * so2 / den : up - c_o * c_o;
        kreal sin2 = up > 0.0 ? c_o * c_o * s / (up * den) : 0.0;
        kreal cos2 = up > 0.0 ? um * upc / (up * den) : 1.0;
        kreal y = den > 0.0 ? um / den : 1.0;
        sin2 = max(sin2, 0.0);
        cos2 = max(cos2, 0.0);
        g.sign_f = c_o < 0.0 ? -1.0 : 1.0;
        // Near the turning point (the pole, for a camera near the axis)
        // psi_o = K - F_o is small and everything past the pole hangs on
        // it: there it comes straight from the complementary amplitude,
        // K - F(phi) = F(phi*) with sin^2 phi* = cos^2 phi / delta^2
        // (not from K and F_o, whose f32 difference would keep only
        // their absolute error).
        g.complement = cos2 < 0.5 * y;
        g.star = vec2(float(cos2 / y), float(mc * sin2 / y));
        g.rf = g.complement ? vec3(g.star.y, float(mc / y), g.star.x) : vec3(float(cos2), float(y), float(sin2));
    } else if (!KERR_COMMON_ONLY) {  // (the split's trace pass defers it)
        kreal a2up = (s - h) / 2.0, a2um = (-h - s) / 2.0;
        kreal up = a2up / (a * a), um = a2um / (a * a);
        g.u_plus = float(up);
        g.u_minus = float(um);
        kreal m = 1.0 - um / up;
        g.m = float(m);
        g.mc = float(um / up);
        kreal sn2 = clamp((c_o * c_o - um) * up / (c_o * c_o * (up - um)), 0.0, 1.0);
        g.rf = vec3(float(1.0 - sn2), float(um / up + m * (1.0 - sn2)), float(sn2));
        g.star = vec2(float(sn2), float(1.0 - sn2));
        bool away = s_th * (c_o < 0.0 ? -1.0 : 1.0) < 0.0;
        g.w = float(sqrt(a2up));
        g.coef = float(lam / sqrt(a2up));
        g.sign_f = away ? 1.0 : -1.0;
        g.hemi = c_o < 0.0 ? -1.0 : 1.0;
    }
    return g;
}

// From R_F's value: K, the means, and the camera's point (no Jacobi
// function needed: its amplitude is known).
void kerr_angular_start(inout KerrAngular g, float f) {
    g.kk = complete_k(g.mc);
    g.agm = agm_of(g.mc);
    g.cam = KerrPoint(sqrt(g.star.x), g.star.y, f, g.sign_f, 0.0, false);
    if (g.vortical) {
        g.v0 = g.sign_f * f;
        return;
    }
    // G = K - F_o's magnitude; psi_o = s_th G above the equator (the
    // north turning point at psi = 0), s_th (2K - G) below (the south one
    // at 2K), the point taken from the nearer turning point.
    float big_g = g.complement ? f : g.kk - f;
    g.cam.f = big_g;
    g.f_o = g.sign_f * (g.kk - big_g);
    bool north = g.sign_f > 0.0;
    g.psi0 = g.s_th * (north ? big_g : 2.0 * g.kk - big_g);
    g.cam.sgn = north ? g.s_th : -g.s_th;
    g.cam.j = north ? 0.0 : g.s_th;
}

float kerr_crossing_tau(KerrAngular g, int n) {
    float sf = g.s_th * g.f_o;
    float h = sf > 0.0 ? 0.0 : 1.0;
    return (2.0 * (float(n) + h) * g.kk + sf) / g.w;
}

// cos theta at the point e1 of the polar motion.
float kerr_cos_of(KerrAngular g, KerrPoint e1) {
    if (g.vortical) return g.hemi * sqrt(g.u_minus) * inversesqrt(g.mc + g.m * e1.c2);
    return sqrt(g.u_plus) * sqrt(e1.c2) * (mod(e1.j, 2.0) == 0.0 ? 1.0 : -1.0);
}

// cos theta at Mino time tau.
float kerr_cos_at(KerrAngular g, float tau) {
    return kerr_cos_of(g, kerr_point_any((g.vortical ? g.v0 : g.psi0) + g.w * tau, g.agm, g.kk));
}

// The arguments (x, y, p) of the R_J that the common paths need, one
// integral a lane: kerr_i_phi's case-2 form at the radial point er for both
// horizons (where that form holds), and G_phi's Pi(-N) at two polar points
// ea, eb (ordinary motion; the path's end has one, passes it twice and
// takes the first three). Where not needed, arguments that end the
// duplication at once.
void kerr_rj_args(KerrRadial k, KerrAngular g, KerrPoint er, KerrPoint ea, KerrPoint eb, out vec4 x, out vec4 y,
                  out vec4 p) {
    bool radial = kerr_i_phi_case2(k), polar = !g.vortical;
    float bn = g.u_plus / g.one_m_up;
    vec3 qa = polar ? kerr_pi_neg_args(bn, ea, g.m, g.mc) : vec3(1.0);
    vec3 qb = polar ? kerr_pi_neg_args(bn, eb, g.m, g.mc) : vec3(1.0);
    x = vec4(vec2(radial ? er.c2 : 1.0), qa.x, qb.x);
    y = vec4(vec2(radial ? k.mc + k.m * er.c2 : 1.0), qa.y, qb.y);
    p = vec4(radial ? 1.0 - kerr_i_phi_n(k) * er.s * er.s : vec2(1.0), qa.z, qb.z);
}

// G_phi's Pi from the camera to the polar point e (Pi there: pi), the
// periods 2K taken off counted.
float kerr_polar_pi(KerrAngular g, KerrPoint e, float pi) {
    return (e.j != 0.0 ? 2.0 * e.j * g.phi_comp : 0.0) + e.sgn * pi;
}

// The parts of I_phi and G_phi fixed for the path, once (the thin disk's
// light may stop it twice): I_phi's camera part, G_phi's complete Pi (for
// each period of the polar motion crossed) and its Pi at the camera, four
// R_J in one call; the path's end (kerr_end) then takes three.
void kerr_phi_start(inout KerrRadial k, inout KerrAngular g) {
    KerrPoint e0 = g.cam, top = kerr_point_k(g.kk);
    vec4 x, y, p;
    kerr_rj_args(k, g, k.cam, top, e0, x, y, p);
    vec4 rj = kerr_rj(x, y, p);
    k.q_cam = -k.cam.sgn * k.cam.s * k.cam.s * k.cam.s * rj.xy;
    if (!KERR_COMMON_ONLY && g.vortical) {
        float n = g.m / (1.0 - g.u_minus);
        g.phi_comp = kerr_pi_complete(n, g.kk, g.m, g.mc);
        g.phi_p0 = kerr_polar_pi(g, e0, kerr_pi(n, e0, g.m, g.mc));
    } else {
        float bn = g.u_plus / g.one_m_up;
        g.phi_comp = kerr_pi_neg_of(bn, top, g.m, g.mc, rj.z);
        g.phi_p0 = kerr_polar_pi(g, e0, kerr_pi_neg_of(bn, e0, g.m, g.mc, rj.w));
    }
}

// cos theta at Mino time tau and the azimuth swept from the camera there,
// -(I_phi + lambda G_phi) (lambda times the integral of 1 / sin^2 theta);
// e1: the radial point at tau (kerr_phi_start first). An equatorial ray
// (eta = 0 in the plane) keeps theta = pi/2 and lambda G_phi = lambda tau.
vec2 kerr_end(KerrRadial k, KerrAngular g, float a, float lam, float eta, float tau, KerrPoint e1) {
    float u0 = g.vortical ? g.v0 : g.psi0;
    float u1 = u0 + g.w * tau;
    KerrPoint ep = kerr_point_any(u1, g.agm, g.kk);
    vec4 x, y, p;
    kerr_rj_args(k, g, e1, ep, ep, x, y, p);
    vec3 rj = kerr_rj(x.xyz, y.xyz, p.xyz);
    float i_phi = kerr_i_phi(k, a, tau, e1, rj.xy);
    if (eta == 0.0) return vec2(0.0, -i_phi - lam * tau);
    float two_k = 2.0 * g.kk, lg;
    if (!KERR_COMMON_ONLY && g.vortical) {
        float n = g.m / (1.0 - g.u_minus);
        float p1 = kerr_polar_pi(g, ep, kerr_pi(n, ep, g.m, g.mc));
        lg = abs(lam) < 1e-12 ? PI * (floor((u1 - g.kk) / two_k) - floor((u0 - g.kk) / two_k))
                              : g.coef * ((u1 - u0) + g.u_minus / (1.0 - g.u_minus) * (p1 - g.phi_p0));
    } else {
        float bn = g.u_plus / g.one_m_up;
        float p1 = kerr_polar_pi(g, ep, kerr_pi_neg_of(bn, ep, g.m, g.mc, rj.z));
        lg = abs(lam) < 1e-12 ? PI * (floor(u1 / two_k) - floor(u0 / two_k)) : g.coef * (p1 - g.phi_p0);
    }
    return vec2(kerr_cos_of(g, ep), -i_phi - lg);
}

// --------------------------------------------------------------- the volumetric disk

// (1 - omega lambda) / alpha at the camera: what turns a shift seen from
// infinity into the one the camera's ZAMO sees (set by metric_trace).
float kerr_zamo_g = 1.0;

// The gas's shift (volume.glsl): a prograde Keplerian emitter at the
// Boyer-Lindquist radius of disk-frame distance r (rs), as the thin disk's
// in metric_trace, no nearer than the disk's inner radius (inside it, the
// inner edge's shift). lambda in M.
float metric_gas_g(float r, float lambda) {
    float rs = P.metric.holes[0].w;
    float a = P.metric.spin_hi;
    float rho = 2.0 * r / rs;
    float x = max(sqrt(max(rho * rho - a * a, 0.0)), 2.0 * P.disk.inner / rs);
    float sx = sqrt(x);
    return kerr_zamo_g * observer_g * sqrt(sx * x) * sqrt(max(sx * x - 3.0 * sx + 2.0 * a, 1e-4))
         / (sx * x + a - lambda);
}

// The two parts of d(phi)/d(tau) along the backward path: the radial one,
// -a (2 r - a lambda) / Delta (kept finite at the horizon r_h), and the
// polar one, -lambda / sin^2 theta (kept finite at the axis).
float kerr_phi_rate_r(float a, float lam, float r, float r_h) {
    float rr = max(r, 1.01 * r_h);
    return -a * (2.0 * rr - a * lam) / (rr * rr - 2.0 * rr + a * a);
}

float kerr_phi_rate_th(float lam, float ct) {
    return -lam / max(1.0 - ct * ct, 1e-4);
}

// The world point at Boyer-Lindquist (r, cos theta) and azimuth phi_o +
// dphi (cp, sp: cos and sin of the camera's phi_o; to_m: M per world unit).
vec3 kerr_world(float r, float ct, float dphi, float a, float cp, float sp, float to_m) {
    vec2 cs = vec2(cos(dphi), sin(dphi));
    float cph = cp * cs.x - sp * cs.y, sph = sp * cs.x + cp * cs.y;
    float rho_s = sqrt((r * r + a * a) * max(1.0 - ct * ct, 0.0));
    return P.metric.holes[0].xyz + (rho_s * cph * P.disk.e1 + r * ct * P.disk.normal - rho_s * sph * P.disk.e2) / to_m;
}

// The volumetric slab along the closed-form path: around each crossing of
// the equator (an arithmetic progression of Mino times), the Mino times
// where |height| < H (from the height's rate there, r sqrt(eta), widened
// for the path's curvature and at most half-way to the neighbouring
// crossings), sampled along five points of the exact path (volume_chords).
// From the crossing behind the camera when the camera is in the slab, else
// from the one ahead; four in all, none farther out than 1.5 outer radii,
// and each window drawn in to about the outer radius.
//
// r and theta at the points are exact: r(tau) and theta(tau) in closed
// form, at the window's first point and its step, the rest by the addition
// theorem of sn, cn and dn (two Jacobi evaluations per motion instead of
// five). The azimuth, whose exact value (Carlson's R_J at each window) would
// cost several times the sampling, is carried from the camera in its two
// parts: the polar one (lambda G_phi) in closed form at each window's start
// (near the axis its rate is a spike no rule follows), the radial one
// -a (2 r - a lambda) / Delta, smooth along the path in Mino time, by
// two-point Gauss-Legendre across the gaps; across a window both by
// Simpson's rule (near the equator both rates are smooth). Against the
// azimuth in closed form at each window, blurred images differ by 4 levels
// of 255 at the 99th percentile: the gas's grain, not a displacement.
//
// Known: a ray that falls into the hole passing through the slab's upper
// layer, far (in polar phase) from its next equatorial crossing, gets no
// window: over the shadow the slab's top edge sits a pixel or two lower
// (640x360, the interstellar view) than the non-rotating path draws it.
const int VOLUME_CROSSINGS = 4;

// lambda G_phi at Mino time tau for the ordinary polar motion (as
// kerr_end), from the camera's part and the complete integral that
// kerr_phi_start computed once for the path.
float kerr_polar_phi(KerrAngular g, float lam, float tau) {
    float u1 = g.psi0 + g.w * tau;
    if (abs(lam) < 1e-12) return PI * (floor(u1 / (2.0 * g.kk)) - floor(g.psi0 / (2.0 * g.kk)));
    KerrPoint e1 = kerr_point_any(u1, g.agm, g.kk);
    float n = g.u_plus / g.one_m_up;
    return g.coef * (kerr_polar_pi(g, e1, kerr_pi_neg(n, e1, g.m, g.mc)) - g.phi_p0);
}

// sn, cn and dn of any real argument u (sn and cn change sign every 2K);
// m + mc = 1.
vec3 kerr_scd(float u, Agm g, float kk, float m, float mc) {
    float j = floor((u + kk) / (2.0 * kk));
    float pr = u - 2.0 * j * kk;
    vec2 sc = jacobi_sn_cn(min(abs(pr), kk), g);
    float odd = mod(j, 2.0) == 0.0 ? 1.0 : -1.0;
    return vec3(sc.x * (pr < 0.0 ? -odd : odd), odd * sc.y, sqrt(mc + m * sc.y * sc.y));
}

// sn, cn and dn of u + v from those of u and of v (the addition theorem).
vec3 kerr_scd_add(vec3 p, vec3 q, float m) {
    float den = 1.0 / (1.0 - m * p.x * p.x * q.x * q.x);
    return vec3(p.x * q.y * q.z + q.x * p.y * p.z,
                p.y * q.y - p.x * q.x * p.z * q.z,
                p.z * q.z - m * p.x * q.x * p.y * q.y) * den;
}

// r at the radial path's point of sn, cn (as kerr_r_of).
float kerr_r_scd(KerrRadial k, vec3 e) {
    float s2 = e.x * e.x;
    if (k.kcase == 2) return k.r4 + k.r43 * k.r41 * s2 / max(k.r31 - k.r41 * s2, 1e-30);
    if (k.kcase == 1) return k.r2 + k.r21 * k.r32 * s2 / (k.r31 - k.r32 * s2);
    return ((k.bb * k.r2 - k.ba * k.r1) + (k.bb * k.r2 + k.ba * k.r1) * e.y) / ((k.bb - k.ba) + (k.bb + k.ba) * e.y);
}

void kerr_volume(KerrRadial rad, KerrAngular ang, float a, float lam, float eta, float cp, float sp,
                 float to_m, bool in_slab, inout Hit hit) {
    float H = to_m * P.volume.half_height;
    float r_far = 1.5 * to_m * P.disk.outer;
    float u_lim = 1.0 / (1.05 * to_m * P.disk.outer);
    float half_gap = ang.kk / ang.w;
    float rate_y = sqrt(eta);
    float r_h = rad.rh.x;
    int n0 = in_slab ? -1 : 0;
    // The polar part's constants (ordinary motion: eta > 0).
    // Where the radial part of the azimuth (from the camera's) is known.
    float t_known = 0.0, phr_known = 0.0;
    [[dont_unroll]] for (int j = 0; j < VOLUME_CROSSINGS; ++j) {
        float tc = kerr_crossing_tau(ang, n0 + j);
        if (tc - half_gap >= rad.tau_end) break;
        // Whether the next window lies past the path's end, tested again
        // at the body's exits (a test at the top alone costs a body more:
        // see kerr_rj's loop).
        bool last = kerr_crossing_tau(ang, n0 + j + 1) - half_gap >= rad.tau_end;
        float rn = kerr_r_of(rad, kerr_radial_point(rad, min(max(tc, 0.0), rad.tau_end)));
        float half_w = min(1.3 * H / (max(rn, 1.0) * rate_y), half_gap);
        // Only where the path is inside the outer radius (about): the gas
        // ends there, and samples spread over a path running off to
        // infinity would miss it. On the side of the crossing where r
        // grows, u = 1 / r falls at the Mino-time rate sqrt(f(u)), f(u) =
        // u^4 R(1 / u): the slower of its values at the crossing and at the
        // outer radius bounds the time to get there.
        float un = 1.0 / max(rn, 1e-6);
        float speed = sqrt(max(min(kerr_f_u(un, a, lam, eta), kerr_f_u(u_lim, a, lam, eta)), 1e-8));
        float cap = min(half_w, max(un - u_lim, 0.0) / speed);
        float xc = rad.x0 + rad.rate * tc;
        bool grows_after = rad.kcase == 2 ? xc > 0.0 : rad.kcase != 3 || rad.s_r > 0.0;
        bool grows_before = rad.kcase == 2 ? xc < 0.0 : rad.kcase != 3 || rad.s_r < 0.0;
        float ta = max(tc - (grows_before ? cap : half_w), t_known);
        float tb = min(tc + (grows_after ? cap : half_w), rad.tau_end);
        if (tb <= ta || rn > r_far) {
            if (last) return;
            continue;
        }
        // The radial part across the gap from the last window (two-point
        // Gauss-Legendre: r(tau) is smooth there).
        float gm = 0.5 * (ta + t_known), gh = 0.5 * (ta - t_known);
        float gap = 0.0;
        int k = -1;
        [[dont_unroll]] do {
            float r = kerr_r_of(rad, kerr_radial_point(rad, gm + float(k) * 0.57735027 * gh));
            gap += kerr_phi_rate_r(a, lam, r, r_h);
        } while ((k += 2) <= 1);
        float phr0 = phr_known + gh * gap;
        // The polar part at the window's start in closed form (near the
        // axis its rate is a narrow spike no rule would follow).
        float pht0 = -kerr_polar_phi(ang, lam, ta);
        // Five points a step h apart: r and theta at the first and the
        // step in closed form, the rest by the addition theorem.
        float h = 0.25 * (tb - ta);
        float sr = rad.kcase == 3 ? rad.s_r : 1.0;
        vec3 er = kerr_scd(rad.x0 + sr * rad.rate * ta, rad.agm, rad.kk, rad.m, rad.mc);
        vec3 dr = kerr_scd(sr * rad.rate * h, rad.agm, rad.kk, rad.m, rad.mc);
        vec3 et = kerr_scd(ang.psi0 + ang.w * ta, ang.agm, ang.kk, ang.m, ang.mc);
        vec3 dt = kerr_scd(ang.w * h, ang.agm, ang.kk, ang.m, ang.mc);
        float sq_up = sqrt(ang.u_plus);
        float rk[5], ck[5], rate[5], q[5];
        k = 0;
        [[dont_unroll]] do {
            rk[k] = kerr_r_scd(rad, er);
            ck[k] = sq_up * et.y;
            q[k] = kerr_phi_rate_r(a, lam, rk[k], r_h);
            rate[k] = q[k] + kerr_phi_rate_th(lam, ck[k]);
            er = kerr_scd_add(er, dr, rad.m);
            et = kerr_scd_add(et, dt, ang.m);
        } while (++k < 5);
        // Across the window (near the equator, where both rates are
        // smooth): Simpson's rule to the even points, the three-point rule
        // exact for a quadratic rate to the odd ones.
        float ph0 = phr0 + pht0;
        float ph2 = ph0 + h / 3.0 * (rate[0] + 4.0 * rate[1] + rate[2]);
        float ph[5];
        ph[0] = ph0;
        ph[1] = ph0 + h / 12.0 * (5.0 * rate[0] + 8.0 * rate[1] - rate[2]);
        ph[2] = ph2;
        ph[3] = ph2 + h / 12.0 * (5.0 * rate[2] + 8.0 * rate[3] - rate[4]);
        ph[4] = ph2 + h / 3.0 * (rate[2] + 4.0 * rate[3] + rate[4]);
        // The radial part alone carried on to the next gap.
        phr_known = phr0 + h / 3.0 * (q[0] + 4.0 * q[1] + 2.0 * q[2] + 4.0 * q[3] + q[4]);
        t_known = tb;
        // Points past r_far (a window reaching the end of an escaping path,
        // at infinity) are drawn in to it: no gas there, and finite chords.
        vec3 pts[5];
        k = 0;
        [[dont_unroll]] do {
            pts[k] = kerr_world(min(rk[k], r_far), ck[k], ph[k], a, cp, sp, to_m);
        } while (++k < 5);
        volume_chords(pts, lam, hit.glow, hit.trans);
        if (hit.trans < 0.003 || last) return;
    }
}

// --------------------------------------------------------------- the metric

// The coordinate time (in M) the light takes from Mino time tau on the path
// back to the camera (tau = 0): the integral of dt/dtau = ((r^2 + a^2) /
// Delta) (r^2 + a^2 - a lambda) + a (lambda - a sin^2 theta) (positive along
// a future-directed path outside the horizon), by 8-point Gauss-Legendre
// along the closed-form r(tau) and cos theta(tau). Mino time keeps the
// integrand smooth through turning points; only differences across the disk
// matter (what has turned while the light was on its way), and those are
// good to a few per cent, as the non-rotating path's.
float kerr_travel_time(KerrRadial rad, KerrAngular ang, float a, float lam, float tau) {
    float sum = 0.0;
    int i = 0;
    [[dont_unroll]] do {
        float x = i < 4 ? -KERR_GL8_X[3 - i] : KERR_GL8_X[i - 4];
        float w = i < 4 ? KERR_GL8_W[3 - i] : KERR_GL8_W[i - 4];
        float tn = 0.5 * tau * (x + 1.0);
        float r = kerr_r_of(rad, kerr_radial_point(rad, tn));
        float ct = kerr_cos_at(ang, tn);
        float rho2 = r * r + a * a;
        float delta = max(r * r - 2.0 * r + a * a, 1e-6);
        sum += w * ((rho2 / delta) * (rho2 - a * lam) + a * (lam - a * (1.0 - ct * ct)));
    } while (++i < 8);
    return 0.5 * tau * sum;
}

// The spin a* as its two f32 halves (params.rs): exact to f64.
kreal kerr_spin() {
    return kreal(P.metric.spin_hi) + kreal(P.metric.spin_lo);
}

// The ZAMO is the frame the closed form starts from: the observer's
// velocity (params.rs) is already relative to it, so no squeeze here.
StaticFrame metric_static_frame(vec3 origin) {
    StaticFrame f;
    f.radial = vec3(0.0, 1.0, 0.0);
    f.lapse = 1.0;
    return f;
}

const bool METRIC_SHADES_DISK = true;  // (in metric_trace's crossings)

// BL radius (rs) of a disk hit at world point p: rho^2 = r^2 + a^2.
float metric_disk_radius(vec3 p) {
    kreal rho = kreal(length(p - P.metric.holes[0].xyz));
    kreal a = 0.5 * kreal(P.metric.holes[0].w) * kerr_spin();
    return float(sqrt(max(rho * rho - a * a, 0.0)));
}

Hit metric_trace(vec3 x, vec3 d) {
    Hit hit = hit_start(OUT_CAPTURED, x, d);
    vec3 e1 = P.disk.e1, nrm = P.disk.normal, e2 = P.disk.e2;
    vec3 rel = x - P.metric.holes[0].xyz;
    kreal a = kerr_spin();
    // Lengths in M = rs / 2: position and direction in the hole's frame.
    kreal to_m = 2.0 / kreal(P.metric.holes[0].w);
    kvec3 p = to_m * kvec3(dot(rel, e1), dot(rel, nrm), dot(rel, e2));
    kvec3 dd = normalize(kvec3(dot(d, e1), dot(d, nrm), dot(d, e2)));
    // On the spin axis phi is undefined and lambda = 0 for every ray: the
    // camera moves 1e-6 of its distance off the axis, where the near-axis
    // form (the partner of Pi(-N), N ~ 1 / lambda^2) carries each ray's
    // sweep of phi past the pole.
    if (p.x * p.x + p.z * p.z < 1e-12 * dot(p, p)) p.x = 1e-6 * length(p);
    // Boyer-Lindquist position and the ZAMO there (no trigonometry: cos
    // and sin of theta and phi straight from the coordinates).
    kreal w = dot(p, p) - a * a;
    kreal r = sqrt(0.5 * (w + sqrt(w * w + 4.0 * a * a * p.y * p.y)));
    kreal c = p.y / r;
    kreal s = sqrt(max(1.0 - c * c, 0.0));
    kreal rho = sqrt(r * r + a * a);
    kreal ph_len = sqrt(p.x * p.x + p.z * p.z);
    kreal cp = ph_len > 0.0 ? p.x / ph_len : 1.0, sp = ph_len > 0.0 ? -p.z / ph_len : 0.0;
    kreal sig = r * r + a * a * c * c;
    kreal delta = r * r - 2.0 * r + a * a;
    kreal big_a = (r * r + a * a) * (r * r + a * a) - a * a * delta * s * s;
    kreal alpha = sqrt(sig * delta / big_a), omega = 2.0 * a * r / big_a, varpi = sqrt(big_a / sig) * s;
    kreal rs = sqrt(sig);
    kvec3 er = kvec3(r * s * cp, rho * c, -r * s * sp) / rs;
    kvec3 et = kvec3(rho * c * cp, -r * s, -rho * c * sp) / rs;
    kvec3 ep = kvec3(-sp, 0.0, -cp);
    kreal dr = dot(dd, er), dt = dot(dd, et), dph = dot(dd, ep);
    kreal en = alpha - omega * varpi * dph;
    if (en <= 0.0) return hit;  // E <= 0: cannot come from infinity
    kreal l = -varpi * dph;
    kreal pth = rs * dt;
    kreal qq = pth * pth + c * c * (l * l / (s * s) - a * a * en * en);
    kreal lam = l / en, eta = qq / (en * en);
    float s_r = dr < 0.0 ? -1.0 : 1.0, s_th = dt < 0.0 ? -1.0 : 1.0;
    kreal theta_o = (pth / en) * (pth / en);
    KerrRadial rad = kerr_radial(a, lam, eta, r, s_r);
    KerrAngular ang = kerr_angular(a, lam, eta, c, theta_o, s_th);
    // F at the camera and at the path's end, and the polar F_o, in one
    // loop of Carlson's duplication.
    vec4 sn2 = vec4(rad.rf_cam.z, rad.rf_end.z, ang.rf.z, 0.0);
    vec4 f = sqrt(sn2) * carlson_rf4(vec4(rad.rf_cam.x, rad.rf_end.x, ang.rf.x, 1.0),
                                     vec4(rad.rf_cam.y, rad.rf_end.y, ang.rf.y, 1.0));
    kerr_radial_ends(rad, f.x, f.y);  // (case 4: sin^2 = 0 at both ends, so f = 0)
    kerr_angular_start(ang, f.z);
    // The split's trace pass: the rarer paths to the second pass.
    if (KERR_COMMON_ONLY && (rad.kcase == 4 || eta < 0.0 || KERR_NEAR_EDGE(rad))) {
        hit.deferred = true;
        return hit;
    }
    kerr_phi_start(rad, ang);
    float af = float(a), lamf = float(lam);
    // The shifts are measured by the camera's ZAMO (disk.glsl, volume.glsl).
    kerr_zamo_g = float((1.0 - omega * lam) / alpha);
    observer_lapse = float(alpha);
    if (volumetric() && eta > 0.0 && rad.kcase != 4) {
        bool in_slab = abs(dot(rel, nrm)) < 1.5 * P.volume.half_height;
        kerr_volume(rad, ang, af, lamf, float(eta), float(cp), float(sp), float(to_m), in_slab, hit);
        if (hit.trans < 0.003) {
            hit.outcome = OUT_CAPTURED;  // opaque: nothing behind shows
            return hit;
        }
    }
    // The disk's crossings inside its annulus (an arithmetic progression of
    // Mino times; the radius there in closed form). The first stops the
    // path, unless the disk's structure thins it there (THIN_CROSSINGS = 2):
    // then its light is added here, weighted by its opacity, and the path
    // goes on to the next crossing (drawn opaque by the ray march) or the
    // sky, as the non-rotating path does.
    int from = 0;
    float cpf = float(cp), spf = float(sp);
    [[dont_unroll]] for (int stop = 0; stop < THIN_CROSSINGS; ++stop) {
        bool on_disk = false;
        float t = rad.tau_end, rc = 0.0;
        KerrPoint end = KerrPoint(0.0, 1.0, 0.0, 1.0, 0.0, false);
        if (DISK_KIND == DISK_THIN && eta > 0.0 && rad.kcase != 4) {
            float r_in = float(to_m) * P.disk.inner, r_out = float(to_m) * P.disk.outer;
            [[dont_unroll]] for (int n = from; n < 8; ++n) {
                float tc = kerr_crossing_tau(ang, n);
                if (tc >= rad.tau_end) break;
                KerrPoint e = kerr_radial_point(rad, tc);
                float rn = kerr_r_of(rad, e);
                if (rn > 2e4 || rn < 0.0) break;
                if (rn >= r_in && rn <= r_out) {
                    on_disk = true;
                    t = tc;
                    rc = rn;
                    end = e;
                    from = n + 1;
                    break;
                }
                // The next crossing's test again after the body (the test
                // at the top alone costs a body more: see kerr_rj's loop).
                if (kerr_crossing_tau(ang, n + 1) >= rad.tau_end) break;
            }
        }
        if (!on_disk && rad.captured) return hit;
        if (!on_disk) end = rad.end;
        if (KERR_COMMON_ONLY && af != 0.0 && !(rad.kcase == 2 && rad.rh.x <= rad.r4)) {
            hit.deferred = true;  // I_phi needs kerr_j: to the second pass
            return hit;
        }
        // The azimuth there: phi = phi_o + dphi.
        vec2 ct = kerr_end(rad, ang, af, lamf, float(eta), t, end);
        float dphi = ct.y;
        vec2 cs = cos_sin_precise(dphi);
        float cph = cpf * cs.x - spf * cs.y, sph = spf * cs.x + cpf * cs.y;
        if (on_disk) {
            // The world point (rho cos phi, 0, -rho sin phi) and the redshift
            // of the prograde Keplerian emitter there, seen by the ZAMO:
            // ((1 - omega lambda) / alpha) r^(3/4) sqrt(r^(3/2) - 3 r^(1/2) + 2a)
            // / (r^(3/2) + a - lambda).
            float rho_c = sqrt(rc * rc + af * af) / float(to_m);
            vec3 pos = P.metric.holes[0].xyz + rho_c * cph * e1 - rho_c * sph * e2;
            float sr = sqrt(rc);
            float g = kerr_zamo_g * sqrt(sr * rc) * sqrt(max(sr * rc - 3.0 * sr + 2.0 * af, 0.0))
                    / (sr * rc + af - lamf);
            float delay = 0.0;
#ifndef GEODESIC_AOV
            if (LIGHT_DELAY) delay = kerr_travel_time(rad, ang, af, lamf, t) / float(to_m);
            // The disk's light, added here (METRIC_SHADES_DISK): the last
            // crossing a path may see is opaque; before it, where the
            // structure thins the disk, its light weighted by its opacity,
            // and the path goes on. (BL r in the scene's units, as
            // metric_disk_radius gives it.)
            float r_disk = rc / float(to_m);
            float time = P.disk.rotation_time - (LIGHT_DELAY ? P.disk.speed * delay : 0.0);
            float dens = THIN_STRUCTURE ? thin_disk_density(r_disk, disk_azimuth(pos), time) : 1.0;
            float alpha = stop + 1 < THIN_CROSSINGS ? clamp(P.disk.opacity * dens, 0.0, 1.0) : 1.0;
            hit.glow += hit.trans * alpha * dens * disk_color(r_disk, g * observer_g);
            hit.trans *= 1.0 - alpha;
            if (alpha < 1.0) continue;
#endif
            hit.outcome = OUT_DISK;
            hit.pos = pos;
            hit.g = g;
            hit.delay = delay;
            return hit;
        }
        float cos_end = ct.x;
        float sin_end = sqrt(max(1.0 - cos_end * cos_end, 0.0));
        hit.outcome = OUT_ESCAPED;
        hit.dir = normalize(sin_end * cph * e1 + cos_end * nrm - sin_end * sph * e2);
        return hit;
    }
    return hit;
}

#endif
