// Legendre's forms on top of Carlson's: a point of an elliptic integral
// (KerrPoint: its amplitude, F, fold and periods), Pi(n; phi | m) for any n,
// the complete Pi, and the Gauss-Legendre nodes of the quadratures. The
// twin of src/physics/kerr/elliptic.rs's Legendre forms.
#ifndef KERR_LEGENDRE_GLSL
#define KERR_LEGENDRE_GLSL

#include "constants.glsl"
#include "elliptic.glsl"
#include "kerr/carlson.glsl"

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

#endif
