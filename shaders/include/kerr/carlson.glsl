// Carlson's symmetric integrals R_C and R_J in 32-bit floats (R_F for four
// pairs at once is carlson_rf4 in elliptic.glsl): the twin of
// src/physics/kerr/elliptic.rs, which takes them from the ellip crate.
#ifndef KERR_CARLSON_GLSL
#define KERR_CARLSON_GLSL

#include "kerr/precision.glsl"

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

#endif
