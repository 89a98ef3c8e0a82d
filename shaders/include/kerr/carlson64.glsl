// Carlson's R_C, R_J and R_F in 64-bit floats, and with them an escaping
// path's Mino time and I_phi to infinity (KERR_ESCAPE64: the geodesic AOV
// on a device with 64-bit floats). Empty in every other build.
#ifndef KERR_CARLSON64_GLSL
#define KERR_CARLSON64_GLSL

#include "kerr/carlson.glsl"

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

#endif
