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

// cos and sin of x to full f32 precision: the angle reduced by pi/2 with
// a two-part constant, then Taylor polynomials on [-pi/4, pi/4].
vec2 cos_sin_precise(float x) {
    float q = round(x * 0.6366197723675814);
    float r = (x - q * 1.5707963705062866) + q * 4.371139000186243e-8;
    float r2 = r * r;
    float s = r * (1.0 + r2 * (-1.0 / 6.0 + r2 * (1.0 / 120.0 + r2 * (-1.0 / 5040.0 + r2 * (1.0 / 362880.0)))));
    float c = 1.0 + r2 * (-0.5 + r2 * (1.0 / 24.0 + r2 * (-1.0 / 720.0 + r2 * (1.0 / 40320.0 + r2 * (-1.0 / 3628800.0)))));
    int k = int(q) & 3;
    if (k == 0) return vec2(c, s);
    if (k == 1) return vec2(-s, c);
    if (k == 2) return vec2(-c, -s);
    return vec2(s, -c);
}

// Inverse and hyperbolic functions to full f32 precision. Vulkan lets a
// driver's asin, asinh and sinh be far coarser (asin inherits atan's 4096
// ulp; asinh and sinh built from log and exp cancel near 0), and lavapipe's
// are: a 1e-4 error in asin moved disk points by 1e-2 rs.
float asin_precise(float x) {
    float ax = abs(x);
    bool big = ax > 0.5;
    // asin(x) = pi/2 - 2 asin(sqrt((1 - x) / 2)) above 0.5.
    float y = big ? sqrt(0.5 * (1.0 - ax)) : ax;
    float y2 = y * y;
    // Maclaurin series of asin to y^23: below 1e-9 relative for |y| <= 0.5.
    float p = 0.0;
    const float C[12] = float[12](1.0, 1.0 / 6.0, 3.0 / 40.0, 5.0 / 112.0, 35.0 / 1152.0,
        63.0 / 2816.0, 231.0 / 13312.0, 143.0 / 10240.0, 6435.0 / 557056.0,
        12155.0 / 1245184.0, 46189.0 / 5505024.0, 88179.0 / 12058624.0);
    for (int i = 11; i >= 0; --i) p = p * y2 + C[i];
    float r = y * p;
    if (big) r = 1.5707963267948966 - 2.0 * r;
    return x < 0.0 ? -r : r;
}

float sinh_precise(float x) {
    if (abs(x) < 0.25) {
        float x2 = x * x;
        return x * (1.0 + x2 * (1.0 / 6.0 + x2 * (1.0 / 120.0 + x2 * (1.0 / 5040.0))));
    }
    return sinh(x);
}

float asinh_precise(float x) {
    if (abs(x) < 0.25) {
        float x2 = x * x;
        return x * (1.0 - x2 * (1.0 / 6.0 - x2 * (3.0 / 40.0 - x2 * (15.0 / 336.0 - x2 * (105.0 / 3456.0)))));
    }
    return log(x + sqrt(x * x + 1.0));
}

// Carlson's R_F by duplication, to f32 precision.
float carlson_rf(float x, float y, float z) {
    for (int i = 0; i < 16; ++i) {
        float a = (x + y + z) * (1.0 / 3.0);
        float dx = 1.0 - x / a, dy = 1.0 - y / a, dz = 1.0 - z / a;
        if (max(abs(dx), max(abs(dy), abs(dz))) < 0.02) {
            float e2 = dx * dy - dz * dz;
            float e3 = dx * dy * dz;
            return (1.0 - e2 * 0.1 + e3 * (1.0 / 14.0) + e2 * e2 * (1.0 / 24.0)
                    - e2 * e3 * (3.0 / 44.0)) * inversesqrt(a);
        }
        float sx = sqrt(x), sy = sqrt(y), sz = sqrt(z);
        float l = sx * (sy + sz) + sy * sz;
        x = 0.25 * (x + l);
        y = 0.25 * (y + l);
        z = 0.25 * (z + l);
    }
    return inversesqrt((x + y + z) * (1.0 / 3.0));
}

// F(phi, k) for |phi| <= pi/2 from sin^2, cos^2 and 1 - k^2 sin^2.
float incomplete_f(float sin2, float cos2, float delta2) {
    return sqrt(max(sin2, 0.0)) * carlson_rf(max(cos2, 0.0), max(delta2, 0.0), 1.0);
}

// Jacobi sn and cn (parameter m = 1 - mc) by the arithmetic-geometric mean.
vec2 jacobi_sn_cn(float w, float mc) {
    float a[10], c[10];
    a[0] = 1.0;
    float b = sqrt(max(mc, 0.0));
    c[0] = sqrt(max(1.0 - mc, 0.0));
    int n = 0;
    while (n < 9 && abs(c[n]) > 1e-7 * a[n]) {
        a[n + 1] = 0.5 * (a[n] + b);
        c[n + 1] = 0.5 * (a[n] - b);
        b = sqrt(a[n] * b);
        ++n;
    }
    float phi = exp2(float(n)) * a[n] * w;
    for (int i = n; i >= 1; --i) {
        phi = 0.5 * (phi + asin_precise(clamp(c[i] * sin(phi) / a[i], -1.0, 1.0)));
    }
    return vec2(sin(phi), cos(phi));
}

#define PATH_SCATTERED 0
#define PATH_TRAPPED 1
#define PATH_PLUNGING 2

struct LightPath {
    int kind;
    float u1, d21, d32, u3;  // roots and differences (plunging: d21 = A)
    float mc;                // 1 - k^2
    float kk;                // K(k)
    float w0, rate;          // elliptic argument at the camera, dw/dphi (signed)
    float phi_end;           // angle swept to escape or capture
    bool escapes;
};

// The path of a ray starting at u0 with du/dphi = du (> 0 inward).
LightPath light_path(float u0, float du) {
    LightPath p;
    float c = du * du + u0 * u0 * (1.0 - u0);
    float e = 4.0 / 27.0 - c;
    bool inward = du > 0.0;
    if (e > 0.0) {
        float theta = 2.0 * asin_precise(min(sqrt(6.75 * c), 1.0));
        float theta_c = 2.0 * asin_precise(min(sqrt(6.75 * e), 1.0));
        float t = theta * (1.0 / 3.0);
        const float S = 1.1547005383792515;  // 2 / sqrt(3)
        float d21 = S * sin(t);
        float d31 = S * sin(t + 1.0471975511965976);
        float d32 = S * sin(theta_c * (1.0 / 3.0));
        float sth = sin(theta * (1.0 / 6.0));
        float sum12 = (4.0 / 3.0) * sth * sth;
        p.u1 = 0.5 * (sum12 - d21);
        float u2 = p.u1 + d21;
        p.u3 = 1.0 - sum12;
        p.d21 = d21;
        p.d32 = d32;
        p.mc = d32 / d31;
        p.kk = carlson_rf(0.0, p.mc, 1.0);
        float rate = 0.5 * sqrt(d31);
        float g0 = du * du;
        if (u0 < 2.0 / 3.0) {
            p.kind = PATH_SCATTERED;
            float a1 = u0 - p.u1, a3 = p.u3 - u0;
            float u2m = (a1 > 0.0 && a3 > 0.0) ? g0 / (a1 * a3) : u2 - u0;
            p.w0 = incomplete_f(a1 / d21, max(u2m, 0.0) / d21, a3 / d31);
            float w_esc = incomplete_f(-p.u1 / d21, u2 / d21, p.u3 / d31);
            p.escapes = true;
            if (inward) {
                p.phi_end = (2.0 * p.kk - w_esc - p.w0) / rate;
                p.rate = rate;
            } else {
                p.phi_end = (p.w0 - w_esc) / rate;
                p.rate = -rate;
            }
        } else {
            p.kind = PATH_TRAPPED;
            float a1 = u0 - p.u1, a2 = u0 - u2;
            float um3 = max((a1 > 0.0 && a2 > 0.0) ? g0 / (a1 * a2) : u0 - p.u3, 0.0);
            float up2 = um3 + d32;
            p.w0 = incomplete_f(um3 / up2, d32 / up2, d32 * a1 / (d31 * up2));
            float hm3 = 1.0 - p.u3, hp2 = hm3 + d32;
            float w_h = incomplete_f(hm3 / hp2, d32 / hp2, d32 * (1.0 - p.u1) / (d31 * hp2));
            p.escapes = false;
            if (inward) {
                p.phi_end = (w_h - p.w0) / rate;
                p.rate = rate;
            } else {
                p.phi_end = (w_h + p.w0) / rate;
                p.rate = -rate;
            }
        }
    } else {
        p.kind = PATH_PLUNGING;
        float alpha = 2.0 * asinh_precise(sqrt(-6.75 * e));
        float ch = cosh(alpha * (1.0 / 3.0)), sh = sinh_precise(alpha * (1.0 / 3.0));
        p.u1 = 1.0 / 3.0 - (2.0 / 3.0) * ch;
        float n2 = sh * sh * (1.0 / 3.0);
        float A = sqrt(ch * ch + n2);
        p.d21 = A;
        p.d32 = 0.0;
        p.u3 = 0.0;
        p.mc = n2 / (2.0 * A * (A + ch));
        p.kk = carlson_rf(0.0, p.mc, 1.0);
        float rate = sqrt(A);
        float m = 1.0 - p.mc;
        // W1(u) = F(acos((A - v) / (A + v)), k), v = u - u1.
        float v = u0 - p.u1;
        float cp = (A - v) / (A + v), s2 = 4.0 * A * v / ((A + v) * (A + v));
        float f = incomplete_f(s2, cp * cp, 1.0 - m * s2);
        p.w0 = v > A ? 2.0 * p.kk - f : f;
        if (inward) {
            v = 1.0 - p.u1;
            p.escapes = false;
            p.rate = rate;
        } else {
            v = -p.u1;
            p.escapes = true;
            p.rate = -rate;
        }
        cp = (A - v) / (A + v);
        s2 = 4.0 * A * v / ((A + v) * (A + v));
        f = incomplete_f(s2, cp * cp, 1.0 - m * s2);
        float w_end = v > A ? 2.0 * p.kk - f : f;
        p.phi_end = abs(w_end - p.w0) / rate;
    }
    p.phi_end = max(p.phi_end, 0.0);
    return p;
}

// u = rs / r at angle phi along the path.
float path_u(LightPath p, float phi) {
    float w = p.w0 + p.rate * phi;
    float k2 = 2.0 * p.kk;
    if (p.kind == PATH_PLUNGING) {
        bool far_half = w > p.kk;
        float cn = jacobi_sn_cn(far_half ? k2 - w : max(w, 0.0), p.mc).y;
        if (far_half) cn = -cn;
        return p.u1 + p.d21 * (1.0 - cn) / (1.0 + cn);
    }
    float wr = w - k2 * floor(w / k2);
    if (wr > p.kk) wr = k2 - wr;
    vec2 sc = jacobi_sn_cn(wr, p.mc);
    if (p.kind == PATH_SCATTERED) return p.u1 + p.d21 * sc.x * sc.x;
    return p.u3 + p.d32 * sc.x * sc.x / max(sc.y * sc.y, 1e-30);
}

#endif
