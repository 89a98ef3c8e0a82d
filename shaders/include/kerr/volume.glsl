// The volumetric disk along a spinning hole's closed-form path: the slab's
// windows around each equatorial crossing, sampled at five points of the
// exact path (volume_chords of volume.glsl), and the gas's shift.
#ifndef KERR_VOLUME_GLSL
#define KERR_VOLUME_GLSL

#include "params.glsl"
#include "ray_state.glsl"
#include "hit.glsl"
#include "volume.glsl"
#include "kerr/angular.glsl"
#include "kerr/interior.glsl"


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

// The polarized volume (POLARIZATION): the window's five points' (r, cos
// theta, s_r, s_th), the backward signs at each from its Mino time, and
// the ray's (a, lambda, eta, turn).
vec4 kerr_pol_pts[5];
vec4 kerr_pol_ray;

// A sample between two of them: r and cos theta along the chord (as the
// sample's place), the signs of the nearer point (they turn only where
// their motion does, and there its momentum's part is 0).
vec4 metric_pol_sample(vec3 p, vec3 p0, vec3 p1, int chord, float frac) {
    vec4 q0 = kerr_pol_pts[chord], q1 = kerr_pol_pts[chord + 1];
    vec2 rc = mix(q0.xy, q1.xy, frac);
    vec2 sg = frac < 0.5 ? q0.zw : q1.zw;
    return pol_volume_kerr(rc.x, rc.y, kerr_pol_ray.x, kerr_pol_ray.y, kerr_pol_ray.z, sg.x, sg.y, kerr_pol_ray.w);
}

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

// The radial part of the azimuth's rate at Mino time tau (radius r): from
// inside the horizons (KERR_INSIDE) that of the ingoing azimuth, per turn.
float kerr_volume_rate(KerrRadial rad, float a, float lam, float eta, float turn, float r, float tau) {
    if (KERR_INSIDE) {
        float sigma = kerr_radial_sign(rad, tau);
        return turn * kerr_ingoing_rates(rad, r, r - rad.rh.y, sigma, turn, a, lam, eta, 0.0, false).x;
    }
    return kerr_phi_rate_r(a, lam, r, rad.rh.x);
}

// turn: the sign of the photon's energy (kerr_camera): with E < 0 the
// azimuth runs the other way along the backward path. shift_o: from inside
// the horizons, the camera's phi~ - phi (kerr_ingoing_shift; each point's
// own taken off).
void kerr_volume(KerrRadial rad, KerrAngular ang, float a, float lam, float eta, float cp, float sp,
                 float to_m, bool in_slab, float turn, float shift_o, inout Hit hit) {
    float H = to_m * P.volume.half_height;
    float r_far = 1.5 * to_m * P.disk.outer;
    float u_lim = 1.0 / (1.05 * to_m * P.disk.outer);
    float half_gap = ang.kk / ang.w;
    float rate_y = sqrt(eta);
    int n0 = in_slab ? -1 : 0;
    kerr_pol_ray = vec4(a, lam, eta, turn);
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
            float tg = gm + float(k) * 0.57735027 * gh;
            gap += kerr_volume_rate(rad, a, lam, eta, turn, kerr_r_of(rad, kerr_radial_point(rad, tg)), tg);
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
            if (POLARIZATION != POL_OFF) {
                // The backward polar sign: that of d theta / d tau, of sn.
                float tk = ta + float(k) * h;
                kerr_pol_pts[k] = vec4(rk[k], ck[k], kerr_radial_sign(rad, tk), et.x * ang.w >= 0.0 ? 1.0 : -1.0);
            }
            q[k] = kerr_volume_rate(rad, a, lam, eta, turn, rk[k], ta + float(k) * h);
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
            // (Within 5 % of r+, where the world's azimuth winds without
            // end, the point's is held at that distance's: no gas lies
            // there, inside the photon sphere, and its chords stay short.)
            // (A window's last point, stepped by the addition theorem, may
            // overshoot an escape's end at infinity, where the case-3 form
            // turns negative: drawn in to r_far too.)
            float rw = rk[k] >= 0.0 ? min(rk[k], r_far) : r_far;
            float rh = rad.rh.x;
            float rb = abs(rw / rh - 1.0) < 0.05 ? rh * (rw < rh ? 0.95 : 1.05) : rw;
            float dphi = KERR_INSIDE ? turn * ph[k] + shift_o - kerr_ingoing_shift(kreal(rb), kreal(a))
                                     : turn * ph[k];
            pts[k] = kerr_world(rw, ck[k], dphi, a, cp, sp, to_m);
            if (POLARIZATION != POL_OFF) kerr_pol_pts[k].x = rw;
        } while (++k < 5);
        volume_chords(pts, lam, hit.glow, hit.trans);
        if (hit.trans < 0.003 || last) return;
    }
}

#endif
