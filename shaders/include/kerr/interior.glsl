// A falling camera between a spinning hole's horizons, or outside within 5 %
// of r+ (KERR_INSIDE): the GPU twin of src/physics/kerr/interior.rs, which
// documents the forms.
// No static frame or ZAMO exists there, so the pixel's photon comes from the
// falling frame built from the Boyer-Lindquist metric (the frame of an
// observer falling from rest at infinity with no angular momentum, its
// radial axis boosted along the fall). Every backward ray moves outward
// between the horizons and runs through r+ on the exterior's closed-form
// r(tau) and theta(tau) (no root lies between the horizons). Its azimuth
// is carried in its ingoing form phi~ = phi + a / (r+ - r-) ln|(r - r+) /
// (r - r-)|, whose rate along the path is finite at r+, by Gauss-Legendre
// quadrature in Mino time; the polar part in closed form. P(r+) = E (r+^2 +
// a^2) - a L <= 0: the light crossed the other universe's horizon (AOV
// outcome 5).
#ifndef KERR_INTERIOR_GLSL
#define KERR_INTERIOR_GLSL

#include "kerr/camera.glsl"
#include "kerr/radial.glsl"
#include "kerr/angular.glsl"

// The falling camera's photon along d: k as kerr_camera fills it. Between
// the horizons every backward ray moves outward (s_r = +1) and P(r+) picks
// the universe; a camera within KERR_INSIDE's band just outside r+ (where
// the ZAMO's frame, which the fall outruns there, degenerates) takes s_r
// from the photon's dr. 1 for light from our universe, -1 from the other
// one, 0 at E = 0.
int kerr_falling_camera(vec3 rel, vec3 d, out KerrCamera k) {
    kreal s;
    kvec3 dtr;
    kerr_place(rel, d, k, s, dtr);
    // The radius from f64 (the ObserverParams' note); theta and phi as placed.
    k.r = kreal(P.observer.bl_r_hi) + kreal(P.observer.bl_r_lo);
    kreal a = k.a, r = k.r, c = k.c, s2 = s * s;
    kreal sig = r * r + a * a * c * c;
    kreal delta = r * r - 2.0 * r + a * a;
    kreal big_a = (r * r + a * a) * (r * r + a * a) - a * a * delta * s2;
    // The faller: u_t = -1, u_phi = 0, u_theta = 0 (theta stays: Q = 0),
    // dr/dtau = -sqrt(2 r (r^2 + a^2)) / Sigma; its radial axis e_r, unit,
    // orthogonal to u, e_theta and e_phi (the metric's g(e_r, e_r) reduces
    // to Sigma^2 / A, so nothing of order 1 / Delta is formed). The photon
    // k = u - d_r e_r - d_theta e_theta - d_phi e_phi then has E = -k_t =
    // 1 + d_r sqrt(2 r (r^2 + a^2) / A) - d_phi 2 a r sin(theta) /
    // sqrt(Sigma A), L = k_phi = -d_phi sin(theta) sqrt(A / Sigma),
    // k_theta = -d_theta sqrt(Sigma), and k^r = -(sqrt(2 r (r^2 + a^2)) +
    // d_r sqrt(A)) / Sigma: each finite at r+, none cancelling there.
    kreal fall = sqrt(2.0 * r * (r * r + a * a)), sa = sqrt(big_a), ss = sqrt(sig);
    kreal en = 1.0 + dtr.x * fall / sa - dtr.z * 2.0 * a * r * s / (ss * sa);
    kreal l = -dtr.z * s * sa / ss;
    kreal pth = -ss * dtr.y;
    kreal k1 = -(fall + dtr.x * sa) / sig;
    k.alpha = 1.0;
    k.omega = 0.0;
    kreal rp = 1.0 + sqrt(1.0 - a * a);
    bool inside = r < rp;
    k.s_r = inside || k1 < 0.0 ? 1.0 : -1.0;
    k.s_th = pth > 0.0 ? -1.0 : 1.0;
    k.turn = en < 0.0 ? -1.0 : 1.0;
    if (en == 0.0) return 0;
    k.lam = l / en;
    k.eta = (pth * pth + c * c * (l * l / s2 - a * a * en * en)) / (en * en);
    k.theta_o = (pth / en) * (pth / en);
    k.inv_e = 1.0 / en;
    return !inside || en * 2.0 * rp - a * l > 0.0 ? 1 : -1;
}

// r - r- at the camera, from its f64 radius.
float kerr_above_inner(KerrCamera cam) {
    return float(cam.r - cam.a * cam.a / (1.0 + sqrt(1.0 - cam.a * cam.a)));
}

// phi~ - phi at r: a / (r+ - r-) ln|(r - r+) / (r - r-)| (0 at infinity).
float kerr_ingoing_shift(kreal r, kreal a) {
    kreal s = sqrt(1.0 - a * a);
    return float(a / (2.0 * s)) * log(float(abs((r - 1.0 - s) / (r - 1.0 + s))));
}

// The sign of dr/dtau of the backward path at Mino time tau.
float kerr_radial_sign(KerrRadial k, float tau) {
    float x = k.x0 + k.rate * tau;
    if (k.kcase == 2) return x < 0.0 ? -1.0 : 1.0;
    if (k.kcase == 1) return mod(x, 2.0 * k.kk) < k.kk ? 1.0 : -1.0;
    return k.s_r;
}

// The rates along the backward path at r (moving out: sigma = 1) of the
// ingoing azimuth, a (sigma sqrt(R) - turn (2r - a lambda)) / Delta, and of
// the ingoing time, (r^2 + a^2) (turn P - sigma sqrt(R)) / Delta + turn a
// (lambda - a sin^2 theta) (ct = cos theta; only where timed). Delta =
// (r - r+) (r - r-), dm = r - r- given (near r- it must not come from a
// difference of rounded radii). Where the light crosses a horizon both are
// 0 / 0 there: rationalised by R = P^2 - Delta K (P = r^2 + a^2 - a lambda,
// K = eta + (lambda - a)^2); elsewhere through f(u) = u^4 R(1 / u), which
// does not overflow far out.
vec2 kerr_ingoing_rates(KerrRadial rad, float r, float dm, float sigma, float turn, float a, float lam, float eta,
                        float ct, bool timed) {
    // (A node a rounding past an escape's end at infinity: its limit there.)
    float u = r > 0.0 && r < 1e30 ? 1.0 / r : 0.0;
    float f = max(kerr_f_u(u, a, lam, eta), 0.0);
    float sq = r * r * sqrt(f);
    float x = 2.0 * r - a * lam;
    float delta = (r - rad.rh.x) * dm;
    float big_k = eta + (lam - a) * (lam - a);
    bool near = abs(delta) < 0.1 && sigma * turn * x > 0.0;
    float phi_rate = near ? sigma * a * (2.0 * x + delta - big_k) / (sq + sigma * turn * x)
                   : u < 0.25 ? a * (sigma * sqrt(f) - turn * (2.0 - a * lam * u) * u) / (1.0 - 2.0 * u + a * a * u * u)
                             : a * (sigma * sq - turn * x) / delta;
    if (!timed) return vec2(phi_rate, 0.0);
    float p = r * r + a * a - a * lam;
    float t_rate = near ? (r * r + a * a) * big_k / (turn * p + sigma * sq)
                        : (r * r + a * a) * (turn * p - sigma * sq) / delta;
    return vec2(phi_rate, t_rate + turn * a * (lam - a * (1.0 - ct * ct)));
}

// 8-point Gauss-Legendre node i of [mid - half, mid + half]: (point, weight).
vec2 kerr_gl8(int i, float mid, float half_w) {
    float x = i < 4 ? -KERR_GL8_X[3 - i] : KERR_GL8_X[i - 4];
    float w = i < 4 ? KERR_GL8_W[3 - i] : KERR_GL8_W[i - 4];
    return vec2(mid + half_w * x, half_w * w);
}

// The integrals of kerr_ingoing_rates from the camera (r_o, d_o = r_o - r-
// from the f64 radius) to Mino time tau, 8-point Gauss-Legendre on panels:
// of one unit of the Jacobi argument in Mino time (r(tau) is analytic
// within about K' of the real line, so each panel is good to 1e-10; case 4,
// which has no real root and escapes, in u = 1 / r). A camera within 0.05 M
// of the inner horizon first goes out 0.1 M in r itself (dtau = dr /
// sqrt(R)), on panels graded from r-'s pole just behind it, where r - r- is
// d_o plus the node's offset, exact; the Mino time so spent starts the rest.
vec2 kerr_ingoing_sweep(KerrRadial rad, KerrAngular ang, float a, float lam, float eta, float turn,
                        float r_o, float d_o, float c_o, float tau, bool timed) {
    vec2 sum = vec2(0.0);
    float t0 = 0.0, r_1 = r_o;
    if (d_o < 0.05) {
        r_1 = min(r_o + 0.1, 0.5 * (r_o + rad.rh.x));
        float off = 0.0, h = 2.0 * d_o;
        [[dont_unroll]] for (int panel = 0; panel < 16 && off < r_1 - r_o; ++panel) {
            float off1 = panel == 15 ? r_1 - r_o : min(off + h, r_1 - r_o);
            [[dont_unroll]] for (int i = 0; i < 8; ++i) {
                vec2 n = kerr_gl8(i, 0.5 * (off + off1), 0.5 * (off1 - off));
                float r = r_o + n.x;
                float dt = n.y * inversesqrt(max(kerr_f_u(1.0 / r, a, lam, eta), 1e-30)) / (r * r);
                sum += dt * kerr_ingoing_rates(rad, r, d_o + n.x, 1.0, turn, a, lam, eta, c_o, timed);
                t0 += dt;
            }
            off = off1;
            h *= 3.0;
        }
    }
    if (rad.kcase == 4) {
        float u1 = 1.0 / r_1;
        [[dont_unroll]] for (int i = 0; i < 16; ++i) {
            vec2 xw = kerr_gl_node(i);
            float u = 0.5 * u1 * (xw.x + 1.0), r = 1.0 / max(u, 1e-20);
            float rt = inversesqrt(max(kerr_f_u(u, a, lam, eta), 1e-30));
            sum += 0.5 * u1 * xw.y * rt * kerr_ingoing_rates(rad, r, r - rad.rh.y, 1.0, turn, a, lam, eta, 0.0, false);
        }
        return sum;
    }
    // Graded from r-'s pole, (r_1 - r-) / sqrt(R) behind, up to the unit.
    float wide = 1.0 / rad.rate;
    float sq_1 = r_1 * r_1 * sqrt(max(kerr_f_u(1.0 / r_1, a, lam, eta), 0.0));
    float h = min(2.0 * (d_o + r_1 - r_o) / max(sq_1, 1e-30), wide);
    [[dont_unroll]] for (int panel = 0; panel < 40 && t0 < tau; ++panel) {
        float t1 = panel == 39 ? tau : min(t0 + h, tau);
        h = min(3.0 * h, wide);
        [[dont_unroll]] for (int i = 0; i < 8; ++i) {
            vec2 n = kerr_gl8(i, 0.5 * (t1 + t0), 0.5 * (t1 - t0));
            float r = kerr_r_of(rad, kerr_radial_point(rad, n.x));
            float ct = timed ? kerr_cos_at(ang, n.x) : 0.0;
            sum += n.y * kerr_ingoing_rates(rad, r, r - rad.rh.y, kerr_radial_sign(rad, n.x), turn, a, lam, eta, ct,
                                            timed);
        }
        t0 = t1;
    }
    return sum;
}

// The Mino-time-tau point of the path from a falling camera between the
// horizons: cos theta there and the azimuth swept from the camera, phi -
// phi_o = [phi~ - phi]_o + the ingoing sweep - turn lambda G_phi - [phi~ -
// phi] at the end (r_end, infinite for the sky).
vec2 kerr_inside_end(KerrRadial rad, KerrAngular ang, KerrCamera cam, float lam, float eta, float tau,
                     float r_end) {
    float a = float(cam.a);
    float u0 = ang.vortical ? ang.v0 : ang.psi0;
    float u1 = u0 + ang.w * tau;
    KerrPoint ep = kerr_point_any(u1, ang.agm, ang.kk);
    float lg = lam * tau, ct = 0.0;
    if (eta != 0.0) {
        float pi = ang.vortical ? kerr_pi(ang.m / (1.0 - ang.u_minus), ep, ang.m, ang.mc)
                                : kerr_pi_neg(ang.u_plus / ang.one_m_up, ep, ang.m, ang.mc);
        lg = kerr_polar_lg(ang, lam, u0, u1, ep, pi);
        ct = kerr_cos_of(ang, ep);
    }
    float sweep = kerr_ingoing_sweep(rad, ang, a, lam, eta, cam.turn, float(cam.r), kerr_above_inner(cam),
                                     float(cam.c), tau, false).x;
    float end_shift = r_end < 1e30 ? kerr_ingoing_shift(kreal(r_end), cam.a) : 0.0;
    return vec2(ct, kerr_ingoing_shift(cam.r, cam.a) + sweep - cam.turn * lg - end_shift);
}

// The light's travel time from the disk at Mino time tau (BL radius rc) to
// the falling camera in the scene's time: ingoing time v = t + r* (finite
// through r+), plus r*(rc) = rc + (2 r+ ln|rc - r+| - 2 r- ln|rc - r-|) /
// (r+ - r-) at the disk, whose emitter keeps t = v - r*; the camera's own v
// is the frame's time (as the non-rotating rain form's).
float kerr_inside_delay(KerrRadial rad, KerrAngular ang, KerrCamera cam, float lam, float eta, float tau,
                        float rc) {
    float a = float(cam.a);
    float v = kerr_ingoing_sweep(rad, ang, a, lam, eta, cam.turn, float(cam.r), kerr_above_inner(cam), float(cam.c),
                                 tau, true).y;
    float rp = rad.rh.x, rm = rad.rh.y;
    float r_star = rc + (2.0 * rp * log(abs(rc - rp)) - 2.0 * rm * log(abs(rc - rm))) / (rp - rm);
    return (v + r_star) / float(cam.to_m);
}

#endif
