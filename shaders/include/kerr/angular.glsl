// The polar motion of a light path around a spinning hole, in Mino time:
// theta(tau), the equatorial crossings, lambda G_phi, and the azimuth swept
// at the path's end (kerr_end, with the radial part of kerr/radial.glsl).
// The twin of src/physics/kerr/angular.rs.
#ifndef KERR_ANGULAR_GLSL
#define KERR_ANGULAR_GLSL

#include "kerr/radial.glsl"

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
// lambda G_phi from the camera's polar point (u0) to u1 (its point ep, Pi
// there: pi, the vortical Pi(n) or the ordinary Pi(-N)).
float kerr_polar_lg(KerrAngular g, float lam, float u0, float u1, KerrPoint ep, float pi) {
    float two_k = 2.0 * g.kk;
    if (!KERR_COMMON_ONLY && g.vortical) {
        float p1 = kerr_polar_pi(g, ep, pi);
        return abs(lam) < 1e-12 ? PI * (floor((u1 - g.kk) / two_k) - floor((u0 - g.kk) / two_k))
                                : g.coef * ((u1 - u0) + g.u_minus / (1.0 - g.u_minus) * (p1 - g.phi_p0));
    }
    float p1 = kerr_polar_pi(g, ep, pi);
    return abs(lam) < 1e-12 ? PI * (floor(u1 / two_k) - floor(u0 / two_k)) : g.coef * (p1 - g.phi_p0);
}

vec2 kerr_end(KerrRadial k, KerrAngular g, float a, float lam, float eta, float tau, KerrPoint e1) {
    float u0 = g.vortical ? g.v0 : g.psi0;
    float u1 = u0 + g.w * tau;
    KerrPoint ep = kerr_point_any(u1, g.agm, g.kk);
    vec4 x, y, p;
    kerr_rj_args(k, g, e1, ep, ep, x, y, p);
    vec3 rj = kerr_rj(x.xyz, y.xyz, p.xyz);
    float i_phi = kerr_i_phi(k, a, tau, e1, rj.xy);
    if (eta == 0.0) return vec2(0.0, -i_phi - lam * tau);
    float pi = !KERR_COMMON_ONLY && g.vortical ? kerr_pi(g.m / (1.0 - g.u_minus), ep, g.m, g.mc)
                                               : kerr_pi_neg_of(g.u_plus / g.one_m_up, ep, g.m, g.mc, rj.z);
    return vec2(kerr_cos_of(g, ep), -i_phi - kerr_polar_lg(g, lam, u0, u1, ep, pi));
}

#endif
