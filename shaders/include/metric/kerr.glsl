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
// Precision: this build computes the path in 64-bit floats (the device's
// shaderFloat64; a device without it is refused for a spinning hole, with a
// message). GLSL has no 64-bit sin, cos or inverse functions: the path
// needs only square roots and the four operations, plus cos and sin of
// double angles (kerr_cos_sin below) and an f32 estimate of one cube root
// or arccosine that Newton's method then refines in f64.
//
// Units: M = 1 inside (lengths in rs = 2M = 1 at the boundary); the hole's
// frame has x = disk e1, y = the spin axis (the disk's normal), z = e2.
#ifndef METRIC_KERR_GLSL
#define METRIC_KERR_GLSL

// Loops stay loops: unrolled and inlined at every call, the kernels below
// made a shader that the driver took minutes to compile.
#extension GL_EXT_control_flow_attributes : require

#include "params.glsl"
#include "variant.glsl"
#include "hit.glsl"
#include "disk.glsl"
#include "metric/static_frame.glsl"

// --------------------------------------------------------------- kernels

// cos and sin of a double angle: reduced by pi/2 in three parts (fdlibm's
// split), then Taylor series to x^23 on [-pi/4, pi/4].
dvec2 kerr_cos_sin(double x) {
    double q = round(x * 0.63661977236758134308lf);
    double r = (x - q * 1.57079632673412561417lf) - q * 6.07710050650619224932e-11lf;
    double r2 = r * r;
    // Taylor series, Horner in r^2: sin to r^23, cos to r^22 (1 / n!).
    const double S[11] = double[11](-1.0lf / 6.0lf, 1.0lf / 120.0lf, -1.0lf / 5040.0lf, 1.0lf / 362880.0lf,
        -1.0lf / 39916800.0lf, 1.0lf / 6227020800.0lf, -1.0lf / 1307674368000.0lf, 1.0lf / 355687428096000.0lf,
        -1.0lf / 121645100408832000.0lf, 1.0lf / 51090942171709440000.0lf, -1.0lf / 25852016738884976640000.0lf);
    const double C[11] = double[11](-0.5lf, 1.0lf / 24.0lf, -1.0lf / 720.0lf, 1.0lf / 40320.0lf,
        -1.0lf / 3628800.0lf, 1.0lf / 479001600.0lf, -1.0lf / 87178291200.0lf, 1.0lf / 20922789888000.0lf,
        -1.0lf / 6402373705728000.0lf, 1.0lf / 2432902008176640000.0lf, -1.0lf / 1124000727777607680000.0lf);
    double ps = 0.0lf, pc = 0.0lf;
    [[dont_unroll]] for (int i = 10; i >= 0; --i) {
        ps = ps * r2 + S[i];
        pc = pc * r2 + C[i];
    }
    double sn = r + r * r2 * ps;
    double cs = 1.0lf + r2 * pc;
    int k = int(q - 4.0lf * floor(q * 0.25lf));
    if (k == 0) return dvec2(cs, sn);
    if (k == 1) return dvec2(-sn, cs);
    if (k == 2) return dvec2(-cs, -sn);
    return dvec2(sn, -cs);
}

// Carlson's R_F (Numerical Recipes' duplication, tolerance 0.0025 with the
// fifth-order series: below 1e-16 relative).
double kerr_rf(double x, double y, double z) {
    double ave, dx, dy, dz;
    [[dont_unroll]] for (int i = 0; i < 40; ++i) {
        double sx = sqrt(x), sy = sqrt(y), sz = sqrt(z);
        double l = sx * (sy + sz) + sy * sz;
        x = 0.25lf * (x + l);
        y = 0.25lf * (y + l);
        z = 0.25lf * (z + l);
        ave = (x + y + z) / 3.0lf;
        dx = (ave - x) / ave;
        dy = (ave - y) / ave;
        dz = (ave - z) / ave;
        if (max(max(abs(dx), abs(dy)), abs(dz)) < 0.0025lf) break;
    }
    double e2 = dx * dy - dz * dz, e3 = dx * dy * dz;
    return (1.0lf + (e2 / 24.0lf - 0.1lf - 3.0lf * e3 / 44.0lf) * e2 + e3 / 14.0lf) / sqrt(ave);
}

// Carlson's R_C(x, y), x >= 0, y != 0; the Cauchy principal value for y < 0.
double kerr_rc(double x, double y) {
    double w = 1.0lf;
    if (y < 0.0lf) {
        w = sqrt(x) / sqrt(x - y);
        x = x - y;
        y = -y;
    }
    double ave, s;
    [[dont_unroll]] for (int i = 0; i < 40; ++i) {
        double l = 2.0lf * sqrt(x) * sqrt(y) + y;
        x = 0.25lf * (x + l);
        y = 0.25lf * (y + l);
        ave = (x + y + y) / 3.0lf;
        s = (y - ave) / ave;
        if (abs(s) < 0.0012lf) break;
    }
    return w * (1.0lf + s * s * (0.3lf + s * (1.0lf / 7.0lf + s * (0.375lf + s * 9.0lf / 22.0lf)))) / sqrt(ave);
}

// Carlson's R_J(x, y, z, p), p > 0.
double kerr_rj(double x, double y, double z, double p) {
    double sum = 0.0lf, fac = 1.0lf;
    double ave, dx, dy, dz, dp;
    [[dont_unroll]] for (int i = 0; i < 40; ++i) {
        double sx = sqrt(x), sy = sqrt(y), sz = sqrt(z);
        double l = sx * (sy + sz) + sy * sz;
        double al = p * (sx + sy + sz) + sx * sy * sz;
        al *= al;
        double be = p * (p + l) * (p + l);
        sum += fac * kerr_rc(al, be);
        fac *= 0.25lf;
        x = 0.25lf * (x + l);
        y = 0.25lf * (y + l);
        z = 0.25lf * (z + l);
        p = 0.25lf * (p + l);
        ave = 0.2lf * (x + y + z + p + p);
        dx = (ave - x) / ave;
        dy = (ave - y) / ave;
        dz = (ave - z) / ave;
        dp = (ave - p) / ave;
        if (max(max(abs(dx), abs(dy)), max(abs(dz), abs(dp))) < 0.0015lf) break;
    }
    const double C1 = 3.0lf / 14.0lf, C2 = 1.0lf / 3.0lf, C3 = 3.0lf / 22.0lf, C4 = 3.0lf / 26.0lf;
    double ea = dx * (dy + dz) + dy * dz;
    double eb = dx * dy * dz;
    double ec = dp * dp;
    double ed = ea - 3.0lf * ec;
    double ee = eb + 2.0lf * dp * (ea - ec);
    double ans = 1.0lf + ed * (-C1 + 0.75lf * C3 * ed - 1.5lf * C4 * ee) + eb * (0.5lf * C2 + dp * (-2.0lf * C3 + dp * C4))
               + dp * ea * (C2 - dp * C3) - C2 * dp * ec;
    return 3.0lf * sum + fac * ans / (ave * sqrt(ave));
}

double kerr_k(double m) {
    return kerr_rf(0.0lf, 1.0lf - m, 1.0lf);
}

// F(phi | m) from s = sin(phi) (signed), c2 = cos^2(phi).
double kerr_f(double s, double c2, double m) {
    return s * kerr_rf(c2, 1.0lf - m * s * s, 1.0lf);
}

// Pi(n; phi | m), |phi| <= pi/2, n <= 1.
double kerr_pi(double n, double s, double c2, double m) {
    double d2 = 1.0lf - m * s * s;
    return s * kerr_rf(c2, d2, 1.0lf) + n / 3.0lf * s * s * s * kerr_rj(c2, d2, 1.0lf, 1.0lf - n * s * s);
}

// Pi(-N; phi | m), 0 <= phi <= pi/2, stable for large N (partner -m/N).
double kerr_pi_neg(double bn, double s, double c2, double m) {
    if (bn <= sqrt(m) || bn == 0.0lf) return kerr_pi(-bn, s, c2, m);
    double d2 = 1.0lf - m * s * s;
    double np = -m / bn;
    return s * kerr_rc(c2 * d2, (1.0lf + bn * s * s) * (1.0lf - np * s * s))
         + (-np / 3.0lf) * s * s * s * kerr_rj(c2, d2, 1.0lf, 1.0lf - np * s * s);
}

// Pi(n; phi | m) for any n (principal value past the pole, n > 1), c >= 0.
double kerr_pi_any(double n, double s, double c, double m) {
    if (n <= 1.0lf) return kerr_pi(n, s, c * c, m);
    double d2 = 1.0lf - m * s * s, n2 = m / n;
    return kerr_f(s, c * c, m) - kerr_pi(n2, s, c * c, m) + s * kerr_rc(c * c * d2, (1.0lf - n * s * s) * (1.0lf - n2 * s * s));
}

double kerr_pi_complete(double n, double m) {
    if (n <= 1.0lf) return kerr_rf(0.0lf, 1.0lf - m, 1.0lf) + n / 3.0lf * kerr_rj(0.0lf, 1.0lf - m, 1.0lf, 1.0lf - n);
    double n2 = m / n;
    return kerr_k(m) - (kerr_rf(0.0lf, 1.0lf - m, 1.0lf) + n2 / 3.0lf * kerr_rj(0.0lf, 1.0lf - m, 1.0lf, 1.0lf - n2));
}

// Jacobi sn, cn, dn of any real u, 0 <= m < 1 (Bulirsch's recurrence on
// the arithmetic-geometric mean: one cos and sin, no inverse functions).
dvec3 kerr_sncndn(double u, double m) {
    double emc = 1.0lf - m;
    if (m < 1e-300lf) {
        dvec2 cs = kerr_cos_sin(u);
        return dvec3(cs.y, cs.x, 1.0lf);
    }
    double em[14], en[14];
    double a = 1.0lf, dn = 1.0lf, c = 1.0lf;
    int l = 0;
    [[dont_unroll]] for (int i = 0; i < 13; ++i) {
        l = i;
        em[i] = a;
        emc = sqrt(emc);
        en[i] = emc;
        c = 0.5lf * (a + emc);
        if (abs(a - emc) <= 3e-8lf * a) break;
        emc *= a;
        a = c;
    }
    dvec2 cs = kerr_cos_sin(u * c);
    double sn = cs.y, cn = cs.x;
    if (sn != 0.0lf) {
        a = cn / sn;
        c *= a;
        [[dont_unroll]] for (int i = l; i >= 0; --i) {
            double b = em[i];
            a *= c;
            c *= dn;
            dn = (en[i] + a) / (b + a);
            a = c / b;
        }
        a = 1.0lf / sqrt(c * c + 1.0lf);
        sn = sn >= 0.0lf ? a : -a;
        cn = c * sn;
    }
    return dvec3(sn, cn, sqrt(max(1.0lf - m * sn * sn, 0.0lf)));
}

// The integral of 1 / (1 + N sn^2) from 0 to any real psi (period 2K).
double kerr_pi_neg_continued(double bn, double psi, double m, double k) {
    double j = floor((psi + k) / (2.0lf * k));
    double pr = psi - 2.0lf * j * k;
    dvec3 e = kerr_sncndn(abs(pr), m);
    return 2.0lf * j * kerr_pi_neg(bn, 1.0lf, 0.0lf, m) + (pr < 0.0lf ? -1.0lf : 1.0lf) * kerr_pi_neg(bn, e.x, e.y * e.y, m);
}

// The integral of 1 / (1 - n sn^2) from 0 to xi in [0, 2K] (PV for n > 1).
double kerr_pi_of_xi(double n, double xi, double m, double k) {
    if (xi <= k) {
        dvec3 e = kerr_sncndn(xi, m);
        return kerr_pi_any(n, e.x, abs(e.y), m);
    }
    dvec3 e = kerr_sncndn(2.0lf * k - xi, m);
    return 2.0lf * kerr_pi_complete(n, m) - kerr_pi_any(n, e.x, abs(e.y), m);
}

// 16-point Gauss-Legendre on [-1, 1]: the positive nodes and their weights.
const double KERR_GL_X[8] = double[8](0.09501250983763744lf, 0.2816035507792589lf, 0.45801677765722737lf,
    0.6178762444026438lf, 0.755404408355003lf, 0.8656312023878318lf, 0.9445750230732326lf, 0.9894009349916499lf);
const double KERR_GL_W[8] = double[8](0.18945061045506864lf, 0.18260341504492364lf, 0.16915651939500265lf,
    0.1495959888165767lf, 0.12462897125553407lf, 0.0951585116824926lf, 0.062253523938647456lf, 0.027152459411754176lf);

// --------------------------------------------------------------- the path

struct KerrRadial {
    int kcase;        // GL's radial case 1..4
    bool captured;
    double tau_end;
    double m, k, rate;
    double r1, r2, r3, r4;  // real roots (case 3: r1, r2; case 4: unused)
    double x0;              // cases 1, 2: X at the camera
    double ba, bb, xi_o;    // case 3: A, B and xi at the camera
    double s_r;
    double i_phi_end;       // case 4: I_phi to infinity (quadrature)
};

// u-space integrand f(u) = u^4 R(1/u) (no cancellation at large r).
double kerr_f_u(double u, double a, double lam, double eta) {
    return 1.0lf - (eta + lam * lam - a * a) * u * u + 2.0lf * (eta + (lam - a) * (lam - a)) * u * u * u - a * a * eta * u * u * u * u;
}

KerrRadial kerr_radial(double a, double lam, double eta, double r_o, double s_r) {
    KerrRadial k;
    k.s_r = s_r;
    k.i_phi_end = 0.0lf;
    double rp = 1.0lf + sqrt(1.0lf - a * a);
    double ca = a * a - eta - lam * lam;
    double cb = 2.0lf * (eta + (lam - a) * (lam - a));
    double cc = -a * a * eta;
    double p = -ca * ca / 12.0lf - cc;
    double q = -ca / 3.0lf * ((ca / 6.0lf) * (ca / 6.0lf) - cc) - cb * cb / 8.0lf;
    double disc = (p / 3.0lf) * (p / 3.0lf) * (p / 3.0lf) + (q / 2.0lf) * (q / 2.0lf);
    // z^2 = Z: an f32 estimate, then Newton on the resolvent cubic in f64.
    float w;
    if (disc < 0.0lf) {
        float sp = float(sqrt(-p / 3.0lf));
        w = 2.0 * sp * cos(acos(clamp(float(-q / 2.0lf) / (sp * sp * sp), -1.0, 1.0)) / 3.0);
    } else {
        double sd = sqrt(disc);
        double u1 = -q / 2.0lf + sd, u2 = -q / 2.0lf - sd;
        double c1 = double(sign(float(u1)) * pow(abs(float(u1)), 1.0 / 3.0));
        double c2 = double(sign(float(u2)) * pow(abs(float(u2)), 1.0 / 3.0));
        [[dont_unroll]] for (int i = 0; i < 3; ++i) {
            if (c1 != 0.0lf) c1 -= (c1 * c1 * c1 - u1) / (3.0lf * c1 * c1);
            if (c2 != 0.0lf) c2 -= (c2 * c2 * c2 - u2) / (3.0lf * c2 * c2);
        }
        w = float(c1 + c2);
    }
    double zz = double(w) / 2.0lf - ca / 6.0lf;
    [[dont_unroll]] for (int i = 0; i < 4; ++i) {
        double f = ((16.0lf * zz + 8.0lf * ca) * zz + (ca * ca - 4.0lf * cc)) * zz - cb * cb / 4.0lf;
        double df = (48.0lf * zz + 16.0lf * ca) * zz + (ca * ca - 4.0lf * cc);
        if (df != 0.0lf) zz -= f / df;
    }
    double z = sqrt(max(zz, 0.0lf));
    double q1 = -ca / 2.0lf - zz + cb / (4.0lf * z);
    double q2 = -ca / 2.0lf - zz - cb / (4.0lf * z);
    if (q1 >= 0.0lf && q2 >= 0.0lf) {
        double r1 = -z - sqrt(q1), r2 = -z + sqrt(q1), r3 = z - sqrt(q2), r4 = z + sqrt(q2);
        k.r1 = r1; k.r2 = r2; k.r3 = r3; k.r4 = r4;
        double r31 = r3 - r1, r32 = r3 - r2, r41 = r4 - r1, r42 = r4 - r2;
        k.m = r32 * r41 / (r31 * r42);
        k.rate = 0.5lf * sqrt(r31 * r42);
        k.k = kerr_k(k.m);
        double fo, x_end;
        if (r_o >= r4) {
            k.kcase = 2;
            double x2 = (r_o - r4) * r31 / ((r_o - r3) * r41);
            fo = kerr_f(sqrt(x2), 1.0lf - x2, k.m);
            double xi2 = r31 / r41;
            double f_inf = kerr_f(sqrt(xi2), 1.0lf - xi2, k.m);
            k.captured = false;
            x_end = f_inf;
            if (r4 < rp) {
                double xh2 = (rp - r4) * r31 / ((rp - r3) * r41);
                double fh = kerr_f(sqrt(xh2), 1.0lf - xh2, k.m);
                k.captured = s_r < 0.0lf;
                x_end = k.captured ? -fh : f_inf;
            }
        } else {
            k.kcase = 1;
            double x2 = (r_o - r2) * r31 / ((r_o - r1) * r32);
            fo = kerr_f(sqrt(x2), 1.0lf - x2, k.m);
            double xh2 = (rp - r2) * r31 / ((rp - r1) * r32);
            double fh = kerr_f(sqrt(xh2), 1.0lf - xh2, k.m);
            k.captured = true;
            x_end = s_r < 0.0lf ? -fh : 2.0lf * k.k - fh;
        }
        k.x0 = s_r * fo;
        k.tau_end = (x_end - k.x0) / k.rate;
    } else if (q1 >= 0.0lf) {
        k.kcase = 3;
        double r1 = -z - sqrt(q1), r2 = -z + sqrt(q1), y = sqrt(-q2);
        k.r1 = r1; k.r2 = r2;
        double ba = sqrt((z - r2) * (z - r2) + y * y), bb = sqrt((z - r1) * (z - r1) + y * y);
        k.ba = ba; k.bb = bb;
        k.m = ((ba + bb) * (ba + bb) - (r2 - r1) * (r2 - r1)) / (4.0lf * ba * bb);
        k.rate = sqrt(ba * bb);
        k.k = kerr_k(k.m);
        // xi(r) = F(arccos x3(r)), x3 = cn xi, in [0, 2K].
        double xo = (ba * (r_o - r1) - bb * (r_o - r2)) / (ba * (r_o - r1) + bb * (r_o - r2));
        double fo = kerr_f(sqrt(max(1.0lf - xo * xo, 0.0lf)), xo * xo, k.m);
        k.xi_o = xo >= 0.0lf ? fo : 2.0lf * k.k - fo;
        double xinf = (ba - bb) / (ba + bb);
        double fi = kerr_f(sqrt(max(1.0lf - xinf * xinf, 0.0lf)), xinf * xinf, k.m);
        double xi_inf = xinf >= 0.0lf ? fi : 2.0lf * k.k - fi;
        double xh = (ba * (rp - r1) - bb * (rp - r2)) / (ba * (rp - r1) + bb * (rp - r2));
        double fh = kerr_f(sqrt(max(1.0lf - xh * xh, 0.0lf)), xh * xh, k.m);
        double xi_h = xh >= 0.0lf ? fh : 2.0lf * k.k - fh;
        k.captured = s_r < 0.0lf;
        k.tau_end = k.captured ? (k.xi_o - xi_h) / k.rate : (xi_inf - k.xi_o) / k.rate;
    } else {
        // Case 4 (vortical only): no real root outside; an inward ray falls
        // in, an outward one escapes (its Mino time and I_phi by
        // Gauss-Legendre in u = 1/r).
        k.kcase = 4;
        k.captured = s_r < 0.0lf;
        double uo = 1.0lf / r_o, tau = 0.0lf, iphi = 0.0lf;
        [[dont_unroll]] for (int i = 0; i < 16; ++i) {
            double x = i < 8 ? -KERR_GL_X[7 - i] : KERR_GL_X[i - 8];
            double wt = i < 8 ? KERR_GL_W[7 - i] : KERR_GL_W[i - 8];
            double u = 0.5lf * uo * (x + 1.0lf), ww = 0.5lf * uo * wt;
            double rt = sqrt(kerr_f_u(u, a, lam, eta));
            tau += ww / rt;
            iphi += ww * a * (2.0lf * u - a * lam * u * u) / ((1.0lf - 2.0lf * u + a * a * u * u) * rt);
        }
        k.tau_end = tau;
        k.i_phi_end = iphi;
    }
    return k;
}

double kerr_r_at(KerrRadial k, double tau) {
    if (k.kcase == 3) {
        double xi = k.xi_o + (k.s_r > 0.0lf ? k.rate * tau : -k.rate * tau);
        double cn = kerr_sncndn(xi, k.m).y;
        return ((k.bb * k.r2 - k.ba * k.r1) + (k.bb * k.r2 + k.ba * k.r1) * cn) / ((k.bb - k.ba) + (k.bb + k.ba) * cn);
    }
    double sn = kerr_sncndn(k.x0 + k.rate * tau, k.m).x;
    double s2 = sn * sn;
    if (k.kcase == 1) return (k.r2 * (k.r3 - k.r1) - k.r1 * (k.r3 - k.r2) * s2) / ((k.r3 - k.r1) - (k.r3 - k.r2) * s2);
    return (k.r4 * (k.r3 - k.r1) - k.r3 * (k.r4 - k.r1) * s2) / ((k.r3 - k.r1) - (k.r4 - k.r1) * s2);
}

// J_h by 16-point Gauss-Legendre along the closed-form r(tau), where the
// closed form is 0/0 (r_h = r_- next to r2).
double kerr_j_quadrature(KerrRadial k, double rh, double tau) {
    double sum = 0.0lf;
    [[dont_unroll]] for (int i = 0; i < 16; ++i) {
        double x = i < 8 ? -KERR_GL_X[7 - i] : KERR_GL_X[i - 8];
        double wt = i < 8 ? KERR_GL_W[7 - i] : KERR_GL_W[i - 8];
        sum += wt / (kerr_r_at(k, 0.5lf * tau * (x + 1.0lf)) - rh);
    }
    return 0.5lf * tau * sum;
}

// J_h(tau) = the integral of 1 / (r - r_h) over Mino time.
double kerr_j(KerrRadial k, double rh, double tau) {
    if (k.kcase == 2) {
        double r31 = k.r3 - k.r1, r41 = k.r4 - k.r1, r43 = k.r4 - k.r3;
        double n = r41 * (k.r3 - rh) / (r31 * (k.r4 - rh));
        double pp = 0.0lf;
        [[dont_unroll]] for (int i = 0; i < 2; ++i) {
            dvec3 e = kerr_sncndn(k.x0 + (i == 0 ? 0.0lf : k.rate * tau), k.m);
            pp += (i == 0 ? -1.0lf : 1.0lf) * kerr_pi(n, e.x, e.y * e.y, k.m);
        }
        return tau / (k.r3 - rh) - r43 / (k.rate * (k.r4 - rh) * (k.r3 - rh)) * pp;
    }
    if (k.kcase == 1) {
        double r21 = k.r2 - k.r1, r31 = k.r3 - k.r1, r32 = k.r3 - k.r2;
        if (abs(rh - k.r2) < 1e-6lf * r21) return kerr_j_quadrature(k, rh, tau);
        double n = r32 * (k.r1 - rh) / (r31 * (k.r2 - rh));
        double dp = 0.0lf;
        [[dont_unroll]] for (int i = 0; i < 2; ++i) {
            double x = k.x0 + (i == 0 ? 0.0lf : k.rate * tau);
            dp += (i == 0 ? -1.0lf : 1.0lf) * (x < 0.0lf ? -1.0lf : 1.0lf) * kerr_pi_of_xi(n, abs(x), k.m, k.k);
        }
        return tau / (k.r1 - rh) - r21 / (k.rate * (k.r2 - rh) * (k.r1 - rh)) * dp;
    }
    // Case 3.
    if (abs(rh - k.r2) < 1e-6lf * (k.r2 - k.r1)) return kerr_j_quadrature(k, rh, tau);
    double a = k.ba, b = k.bb;
    double dm = b * (rh - k.r2) - a * (rh - k.r1);
    double dp = b * (rh - k.r2) + a * (rh - k.r1);
    double al = dp / dm;
    double c1 = -(b + a) / dp;
    double c2 = -((b - a) - (b + a) * dm / dp) / dm;
    double n = al * al / (al * al - 1.0lf);
    double gam = k.m + al * al / (1.0lf - al * al);
    double xi1 = k.xi_o + (k.s_r > 0.0lf ? k.rate * tau : -k.rate * tau);
    double rr[2];
    [[dont_unroll]] for (int i = 0; i < 2; ++i) {
        double xi = i == 0 ? k.xi_o : xi1;
        dvec3 e = kerr_sncndn(xi, k.m);
        double w = e.x / e.z;
        double y = 1.0lf + gam * w * w;
        double rc = y > 0.0lf ? kerr_rc(1.0lf, y) : sqrt(1.0lf / (1.0lf - y)) * kerr_rc(1.0lf - y, -y);
        rr[i] = (kerr_pi_of_xi(n, xi, k.m, k.k) - al * w * rc) / (1.0lf - al * al);
    }
    return (c1 * (xi1 - k.xi_o) + c2 * (rr[1] - rr[0])) / k.rate * (k.s_r > 0.0lf ? 1.0lf : -1.0lf);
}

// I_phi(tau): the integral of a (2 r - a lambda) / Delta over Mino time.
double kerr_i_phi(KerrRadial k, double a, double lam, double tau) {
    if (a == 0.0lf) return 0.0lf;
    if (k.kcase == 4) return k.i_phi_end;
    double rp = 1.0lf + sqrt(1.0lf - a * a), rm = a * a / rp;
    double sum = 0.0lf;
    // One loop over the two horizons: one copy of kerr_j in the shader.
    [[dont_unroll]] for (int i = 0; i < 2; ++i) {
        double rh = i == 0 ? rp : rm;
        double ah = (i == 0 ? 1.0lf : -1.0lf) * (2.0lf * rh - a * lam) / (rp - rm);
        sum += ah * kerr_j(k, rh, tau);
    }
    return a * sum;
}

// The polar motion: ordinary (eta > 0) or vortical (eta < 0).
struct KerrAngular {
    bool vortical;
    double w, m, k;
    double u_plus, one_m_up, f_o, s_th;  // ordinary
    double u_minus, v0, hemi;            // vortical
};

KerrAngular kerr_angular(double a, double lam, double eta, double c_o, double theta_o, double s_th) {
    KerrAngular g;
    double h = eta + lam * lam - a * a;
    double s = sqrt(h * h + 4.0lf * a * a * eta);
    g.s_th = s_th;
    g.vortical = eta < 0.0lf;
    if (!g.vortical) {
        g.w = sqrt(s);
        g.u_plus = h >= 0.0lf ? 2.0lf * eta / (h + s) : (s - h) / (2.0lf * a * a);
        double um = (h + s) / 2.0lf;
        g.one_m_up = a * a + um > 0.0lf ? lam * lam / (a * a + um) : 1.0lf - g.u_plus;
        g.m = a * a * g.u_plus / s;
        g.k = kerr_k(g.m);
        double so2 = 1.0lf - c_o * c_o;
        double den = a * a * c_o * c_o + um;
        double upc = den > 0.0lf ? theta_o * so2 / den : g.u_plus - c_o * c_o;
        double sin2 = g.u_plus > 0.0lf ? c_o * c_o * s / (g.u_plus * den) : 0.0lf;
        double cos2 = g.u_plus > 0.0lf ? um * upc / (g.u_plus * den) : 1.0lf;
        double y = den > 0.0lf ? um / den : 1.0lf;
        g.f_o = (c_o < 0.0lf ? -1.0lf : 1.0lf) * sqrt(max(sin2, 0.0lf)) * kerr_rf(max(cos2, 0.0lf), y, 1.0lf);
    } else {
        double a2up = (s - h) / 2.0lf, a2um = (-h - s) / 2.0lf;
        double up = a2up / (a * a), um = a2um / (a * a);
        g.u_plus = up;
        g.u_minus = um;
        g.m = 1.0lf - um / up;
        g.k = kerr_k(g.m);
        double sn2 = clamp((c_o * c_o - um) * up / (c_o * c_o * (up - um)), 0.0lf, 1.0lf);
        double fv = kerr_f(sqrt(sn2), 1.0lf - sn2, g.m);
        bool away = s_th * (c_o < 0.0lf ? -1.0lf : 1.0lf) < 0.0lf;
        g.w = sqrt(a2up);
        g.v0 = away ? fv : -fv;
        g.hemi = c_o < 0.0lf ? -1.0lf : 1.0lf;
    }
    return g;
}

double kerr_crossing_tau(KerrAngular g, int n) {
    double sf = g.s_th * g.f_o;
    double h = sf > 0.0lf ? 0.0lf : 1.0lf;
    return (2.0lf * (double(n) + h) * g.k + sf) / g.w;
}

double kerr_cos_theta(KerrAngular g, double tau) {
    if (g.vortical) return g.hemi * sqrt(g.u_minus) / kerr_sncndn(g.v0 + g.w * tau, g.m).z;
    return sqrt(g.u_plus) * kerr_sncndn(g.w * tau + g.s_th * (g.k - g.f_o), g.m).y;
}

// lambda G_phi(tau) = lambda times the integral of 1 / sin^2 theta.
double kerr_lambda_g(KerrAngular g, double lam, double tau) {
    const double PI_D = 3.14159265358979323846lf;
    if (g.vortical) {
        double um = g.u_minus, n = g.m / (1.0lf - um);
        double comp = kerr_rf(0.0lf, 1.0lf - g.m, 1.0lf) + n / 3.0lf * kerr_rj(0.0lf, 1.0lf - g.m, 1.0lf, 1.0lf - n);
        double v0 = g.v0, v1 = g.v0 + g.w * tau;
        if (lam == 0.0lf) return PI_D * (floor((v1 - g.k) / (2.0lf * g.k)) - floor((v0 - g.k) / (2.0lf * g.k)));
        double pv[2];
        [[dont_unroll]] for (int i = 0; i < 2; ++i) {
            double v = i == 0 ? v0 : v1;
            double j = floor((v + g.k) / (2.0lf * g.k));
            double vr = v - 2.0lf * j * g.k;
            dvec3 e = kerr_sncndn(abs(vr), g.m);
            pv[i] = 2.0lf * j * comp + (vr < 0.0lf ? -1.0lf : 1.0lf) * kerr_pi(n, e.x, e.y * e.y, g.m);
        }
        return lam / g.w * ((v1 - v0) + um / (1.0lf - um) * (pv[1] - pv[0]));
    }
    double psi0 = g.s_th * (g.k - g.f_o), psi1 = g.w * tau + psi0;
    if (lam == 0.0lf) return PI_D * (floor(psi1 / (2.0lf * g.k)) - floor(psi0 / (2.0lf * g.k)));
    double n = g.u_plus / g.one_m_up;
    double dp = 0.0lf;
    [[dont_unroll]] for (int i = 0; i < 2; ++i) {
        dp += (i == 0 ? -1.0lf : 1.0lf) * kerr_pi_neg_continued(n, i == 0 ? psi0 : psi1, g.m, g.k);
    }
    return lam / (g.w * g.one_m_up) * dp;
}

// --------------------------------------------------------------- the metric

// The spin a* as its two f32 halves (params.rs): exact to f64.
double kerr_spin() {
    return double(P.metric.spin_hi) + double(P.metric.spin_lo);
}

// The ZAMO is the frame the closed form starts from: the observer's
// velocity (params.rs) is already relative to it, so no squeeze here.
StaticFrame metric_static_frame(vec3 origin) {
    StaticFrame f;
    f.radial = vec3(0.0, 1.0, 0.0);
    f.lapse = 1.0;
    return f;
}

const bool METRIC_SHADES_DISK = false;

// BL radius (rs) of a disk hit at world point p: rho^2 = r^2 + a^2.
float metric_disk_radius(vec3 p) {
    double rho = double(length(p - P.metric.holes[0].xyz));
    double a = 0.5lf * double(P.metric.holes[0].w) * kerr_spin();
    return float(sqrt(max(rho * rho - a * a, 0.0lf)));
}

Hit metric_trace(vec3 x, vec3 d) {
    Hit hit = hit_start(OUT_CAPTURED, x, d);
    vec3 e1 = P.disk.e1, nrm = P.disk.normal, e2 = P.disk.e2;
    vec3 rel = x - P.metric.holes[0].xyz;
    double a = kerr_spin();
    // Lengths in M = rs / 2: position and direction in the hole's frame.
    double to_m = 2.0lf / double(P.metric.holes[0].w);
    dvec3 p = to_m * dvec3(dot(rel, e1), dot(rel, nrm), dot(rel, e2));
    dvec3 dd = normalize(dvec3(dot(d, e1), dot(d, nrm), dot(d, e2)));
    // Boyer-Lindquist position and the ZAMO there (no trigonometry: cos
    // and sin of theta and phi straight from the coordinates).
    double w = dot(p, p) - a * a;
    double r = sqrt(0.5lf * (w + sqrt(w * w + 4.0lf * a * a * p.y * p.y)));
    double c = p.y / r;
    double s = sqrt(max(1.0lf - c * c, 0.0lf));
    double rho = sqrt(r * r + a * a);
    double ph_len = sqrt(p.x * p.x + p.z * p.z);
    double cp = ph_len > 0.0lf ? p.x / ph_len : 1.0lf, sp = ph_len > 0.0lf ? -p.z / ph_len : 0.0lf;
    double sig = r * r + a * a * c * c;
    double delta = r * r - 2.0lf * r + a * a;
    double big_a = (r * r + a * a) * (r * r + a * a) - a * a * delta * s * s;
    double alpha = sqrt(sig * delta / big_a), omega = 2.0lf * a * r / big_a, varpi = sqrt(big_a / sig) * s;
    double rs = sqrt(sig);
    dvec3 er = dvec3(r * s * cp, rho * c, -r * s * sp) / rs;
    dvec3 et = dvec3(rho * c * cp, -r * s, -rho * c * sp) / rs;
    dvec3 ep = dvec3(-sp, 0.0lf, -cp);
    double dr = dot(dd, er), dt = dot(dd, et), dph = dot(dd, ep);
    double en = alpha - omega * varpi * dph;
    if (en <= 0.0lf) return hit;  // E <= 0: cannot come from infinity
    double l = -varpi * dph;
    double pth = rs * dt;
    double qq = pth * pth + c * c * (l * l / (s * s) - a * a * en * en);
    double lam = l / en, eta = qq / (en * en);
    double s_r = dr < 0.0lf ? -1.0lf : 1.0lf, s_th = dt < 0.0lf ? -1.0lf : 1.0lf;
    double theta_o = (pth / en) * (pth / en);
    KerrRadial rad = kerr_radial(a, lam, eta, r, s_r);
    KerrAngular ang = kerr_angular(a, lam, eta, c, theta_o, s_th);
    // The first crossing of the disk's annulus, if any (an arithmetic
    // progression of Mino times; the radius there in closed form).
    bool on_disk = false;
    double t = rad.tau_end, rc = 0.0lf;
    if (DISK_KIND == DISK_THIN && eta > 0.0lf) {
        double r_in = to_m * double(P.disk.inner), r_out = to_m * double(P.disk.outer);
        [[dont_unroll]] for (int n = 0; n < 8; ++n) {
            double tc = kerr_crossing_tau(ang, n);
            if (tc >= rad.tau_end) break;
            double rn = kerr_r_at(rad, tc);
            if (rn > 2e4lf) break;
            if (rn >= r_in && rn <= r_out) {
                on_disk = true;
                t = tc;
                rc = rn;
                break;
            }
        }
    }
    if (!on_disk && rad.captured) return hit;
    // The azimuth there: phi = phi_o + dphi (an equatorial ray, eta = 0 in
    // the plane, keeps theta = pi/2 and lambda G_phi = lambda tau).
    double dphi = -kerr_i_phi(rad, a, lam, t) - (eta != 0.0lf ? kerr_lambda_g(ang, lam, t) : lam * t);
    dvec2 cs = kerr_cos_sin(dphi);
    double cph = cp * cs.x - sp * cs.y, sph = sp * cs.x + cp * cs.y;
    if (on_disk) {
        // The world point (rho cos phi, 0, -rho sin phi) and the redshift of
        // the prograde Keplerian emitter there, seen by the ZAMO:
        // ((1 - omega lambda) / alpha) r^(3/4) sqrt(r^(3/2) - 3 r^(1/2) + 2a)
        // / (r^(3/2) + a - lambda).
        double rho_c = sqrt(rc * rc + a * a) / to_m;
        hit.outcome = OUT_DISK;
        hit.pos = P.metric.holes[0].xyz + float(rho_c * cph) * e1 - float(rho_c * sph) * e2;
        double sr = sqrt(rc);
        hit.g = float(((1.0lf - omega * lam) / alpha) * sqrt(sr * rc) * sqrt(sr * rc - 3.0lf * sr + 2.0lf * a)
                      / (sr * rc + a - lam));
        return hit;
    }
    double cos_end = eta != 0.0lf ? kerr_cos_theta(ang, t) : 0.0lf;
    double sin_end = sqrt(max(1.0lf - cos_end * cos_end, 0.0lf));
    hit.outcome = OUT_ESCAPED;
    hit.dir = normalize(float(sin_end * cph) * e1 + float(cos_end) * nrm - float(sin_end * sph) * e2);
    return hit;
}

#endif
