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
// Mino time in 64 bits too (KERR_ESCAPE64). The camera's place and a
// pinhole's rays enter in 64 bits as well (kerr/camera.glsl,
// kerr_pixel_dir): from 1e4 rs a 32-bit ray would pass the hole 1e-3 rs
// off. A device without 64-bit floats
// gets the build with KERR_F32_ROOTS: the same path with kreal = float,
// exact away from a thin band around the shadow's outline.
//
// Units: M = 1 inside (lengths in rs = 2M = 1 at the boundary); the hole's
// frame has x = disk e1, y = the spin axis (the disk's normal), z = e2.
#ifndef METRIC_KERR_GLSL
#define METRIC_KERR_GLSL

#include "params.glsl"
#include "variant.glsl"
#include "hit.glsl"
#include "disk.glsl"
#include "ray_state.glsl"
#include "volume.glsl"
#include "elliptic.glsl"
#include "metric/static_frame.glsl"
#include "kerr/precision.glsl"
#include "kerr/carlson.glsl"
#include "kerr/carlson64.glsl"
#include "kerr/legendre.glsl"
#include "kerr/radial.glsl"
#include "kerr/angular.glsl"
#include "kerr/camera.glsl"
#include "kerr/interior.glsl"
#include "kerr/volume.glsl"
#include "polarization.glsl"

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

// The ZAMO is the frame the closed form starts from: the observer's
// velocity (params.rs) is already relative to it, so no squeeze here.
StaticFrame metric_static_frame(vec3 origin) {
    StaticFrame f;
    f.radial = vec3(0.0, 1.0, 0.0);
    f.lapse = 1.0;
    f.fall2 = 0.0;
    return f;
}

const bool METRIC_SHADES_DISK = true;  // (in metric_trace's crossings)

// The emitter's lapse squared on the disk's plane at radius r (rs): the
// ZAMO's alpha^2 = r^2 Delta / A (Boyer-Lindquist r, M = 1), whose limit at
// a* = 0 is the non-rotating 1 - rs / r.
float metric_emitter_lapse2(float r, float rs, float ir) {
    float a = P.metric.spin_hi;
    float x = 2.0 * r / rs;
    float delta = x * x - 2.0 * x + a * a;
    float sum = x * x + a * a;
    return x * x * delta / (sum * sum - a * a * delta);
}

// BL radius (rs) of a disk hit at world point p: rho^2 = r^2 + a^2.
float metric_disk_radius(vec3 p) {
    kreal rho = kreal(length(p - P.metric.holes[0].xyz));
    kreal a = 0.5 * kreal(P.metric.holes[0].w) * kerr_spin();
    return float(sqrt(max(rho * rho - a * a, 0.0)));
}

// The first of the disk's crossings from the n-th on (an arithmetic
// progression of Mino times) inside its annulus: its Mino time t, its
// radius rc (M) and its radial point; `from` moves past it. False where the
// path meets none before its end (t, rc and end then stay as they were).
bool kerr_disk_crossing(KerrRadial rad, KerrAngular ang, float to_m, inout int from, inout float t,
                        inout float rc, inout KerrPoint end) {
    float r_in = to_m * P.disk.inner, r_out = to_m * P.disk.outer;
    [[dont_unroll]] for (int n = from; n < 8; ++n) {
        float tc = kerr_crossing_tau(ang, n);
        if (tc >= rad.tau_end) break;
        KerrPoint e = kerr_radial_point(rad, tc);
        float rn = kerr_r_of(rad, e);
        if (rn > 2e4 || rn < 0.0) break;
        if (rn >= r_in && rn <= r_out) {
            t = tc;
            rc = rn;
            end = e;
            from = n + 1;
            return true;
        }
        // The next crossing's test again after the body (the test at the
        // top alone costs a body more: see kerr_rj's loop).
        if (kerr_crossing_tau(ang, n + 1) >= rad.tau_end) break;
    }
    return false;
}

// The redshift of the prograde Keplerian emitter at BL radius rc (M) seen
// by the camera's ZAMO: ((1 - omega lambda) / alpha) r^(3/4)
// sqrt(r^(3/2) - 3 r^(1/2) + 2a) / (r^(3/2) + a - lambda).
float kerr_disk_g(float rc, float a, float lam) {
    float sr = sqrt(rc);
    return kerr_zamo_g * sqrt(sr * rc) * sqrt(max(sr * rc - 3.0 * sr + 2.0 * a, 0.0)) / (sr * rc + a - lam);
}

// The disk's light at a crossing, added to the hit (METRIC_SHADES_DISK):
// the last crossing a path may see (stop + 1 == THIN_CROSSINGS) is opaque;
// before it, where the structure thins the disk, its light weighted by its
// opacity. rc: BL r in M; the delay in the scene's time. Returns the
// crossing's opacity: below 1 the path goes on.
float kerr_disk_light(inout Hit hit, int stop, float rc, float to_m, vec3 pos, float g, float delay) {
    // BL r in the scene's units, as metric_disk_radius gives it.
    float r_disk = rc / to_m;
    float time = P.disk.rotation_time - (LIGHT_DELAY ? P.disk.speed * delay : 0.0);
    float dens = THIN_STRUCTURE ? thin_disk_density(r_disk, disk_azimuth(pos), time) : 1.0;
    float alpha = stop + 1 < THIN_CROSSINGS ? clamp(P.disk.opacity * dens, 0.0, 1.0) : 1.0;
    hit.glow += hit.trans * alpha * dens * disk_color(r_disk, g * observer_g);
    hit.trans *= 1.0 - alpha;
    return alpha;
}

// The camera's side of the polarization: kappa(p, n) and kappa(p, w)
// (.xy, .zw) of the photon along the pixel's ZAMO direction d and the sky's
// north and west across the observer's own direction, boosted into the
// ZAMO's frame. A falling camera between the horizons or in their band
// (KERR_INSIDE) has them on its own frame, the metric's falling frame
// (kerr/interior.glsl), unboosted.
vec4 kerr_pol_camera(KerrCamera cam, vec3 d) {
    kvec3 er, et, ep;
    kerr_triad(cam, er, et, ep);
    kvec3 dz = normalize(kerr_hole_frame(kerr_pixel_dir(d)));
    pvec4 p = pvec4(1.0, -dot(dz, er), -dot(dz, et), -dot(dz, ep));
    kvec3 dobs = normalize(kerr_hole_frame(kerr_observer_dir(pol_dir_observer)));
#ifdef KERR_F32_ROOTS
    kvec3 up = kerr_hole_frame(P.camera.up);
#else
    kvec3 up = kerr_hole_frame(camera_axis64(P.camera.up, P.camera.up_lo));
#endif
    kvec3 nn = normalize(up - dot(up, dobs) * dobs);
    kvec3 ww = cross(nn, dobs);
    kvec3 beta = OBSERVER_MOVES && !KERR_INSIDE ? kerr_hole_frame(P.observer.velocity) : kvec3(0.0);
    pvec4 n4 = pol_boost(beta, 0.0, nn), w4 = pol_boost(beta, 0.0, ww);
    n4 = pvec4(n4.x, dot(n4.yzw, er), dot(n4.yzw, et), dot(n4.yzw, ep));
    w4 = pvec4(w4.x, dot(w4.yzw, er), dot(w4.yzw, et), dot(w4.yzw, ep));
    // Across the photon as traced: the time parts from n.p = w.p = 0 (the
    // boost gives them so in exact arithmetic). The 32-bit aberration turns
    // the traced direction by ~1e-7 rad off the observer's, and far out
    // kappa(p, e_t) ~ r: at 2e4 rs an error of 4e-4 rad, which this takes.
    n4.x = dot(n4.yzw, p.yzw) / p.x;
    w4.x = dot(w4.yzw, p.yzw) / p.x;
    if (KERR_INSIDE) {
        return vec4(vec2(pol_kappa_falling(cam.r, cam.c, cam.a, p, n4)),
                    vec2(pol_kappa_falling(cam.r, cam.c, cam.a, p, w4)));
    }
    return vec4(vec2(pol_kappa_camera(cam.r, cam.c, cam.a, p, n4)), vec2(pol_kappa_camera(cam.r, cam.c, cam.a, p, w4)));
}

// The polarization of the n-th crossing (polarization.glsl; Hit.pol): the
// photon there from its constants, the backward radial sign from the
// crossing's radial point e (cases 1 and 2: r grows with sn^2, so the sign
// of sn cn; cases 3 and 4: s_r throughout) and the polar one alternating
// from the camera's (s_th (-1)^(n + h)); the camera's side from
// kerr_pol_camera.
vec4 kerr_polarization(KerrCamera cam, KerrRadial rad, KerrAngular ang, KerrPoint e, int n, float rc,
                       vec3 d) {
    float s_r = rad.kcase <= 2 ? e.sgn * (e.fold ? -1.0 : 1.0) : rad.s_r;
    int h = ang.s_th * ang.f_o > 0.0 ? 0 : 1;
    float s_th = ((n + h) & 1) == 0 ? ang.s_th : -ang.s_th;
    float af = float(cam.a);
    vec4 pe = pol_equatorial_photon(rc, af, float(cam.lam), float(cam.eta), s_r, s_th, cam.turn);
    vec4 em = pol_emit(rc, af, pe);
    vec4 k = kerr_pol_camera(cam, d);
    return pol_of(em, pol_angle(em.xy, k.xy, k.zw));
}

Hit metric_trace(vec3 x, vec3 d) {
    Hit hit = hit_start(OUT_CAPTURED, x, d);
    vec3 e1 = P.disk.e1, nrm = P.disk.normal, e2 = P.disk.e2;
    vec3 rel = x - P.metric.holes[0].xyz;
    KerrCamera cam;
    if (KERR_INSIDE) {
        int universe = kerr_falling_camera(rel, d, cam);
        if (universe < 0) hit.outcome = OUT_OTHER_UNIVERSE;
        if (universe <= 0) return hit;
    } else if (!kerr_camera(rel, d, cam)) {
        return hit;  // E = 0 exactly: the edge between the signs
    }
    kreal lam = cam.lam, eta = cam.eta;
    KerrRadial rad = kerr_radial(cam.a, lam, eta, cam.r, cam.s_r);
    KerrAngular ang = kerr_angular(cam.a, lam, eta, cam.c, cam.theta_o, cam.s_th);
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
    float af = float(cam.a), lamf = float(lam), to_m = float(cam.to_m);
    // The shifts are measured by the camera's ZAMO (disk.glsl, volume.glsl),
    // or inside by the falling camera itself.
    kerr_zamo_g = float(cam.inv_e);
    observer_lapse = float(cam.alpha);
    if (volumetric() && eta > 0.0 && rad.kcase != 4) {
        if (POLARIZATION != POL_OFF) {
            pol_cam_k = kerr_pol_camera(cam, d);
            pol_cam_g = kerr_zamo_g * observer_g;
        }
        bool in_slab = abs(dot(rel, nrm)) < 1.5 * P.volume.half_height;
        float shift_o = KERR_INSIDE ? kerr_ingoing_shift(cam.r, cam.a) : 0.0;
        kerr_volume(rad, ang, af, lamf, float(eta), float(cam.cp), float(cam.sp), to_m, in_slab, cam.turn,
                    shift_o, hit);
        if (hit.trans < 0.003) {
            hit.outcome = OUT_CAPTURED;  // opaque: nothing behind shows
            return hit;
        }
    }
    // The disk's crossings inside its annulus (the radius there in closed
    // form). The first stops the path, unless the disk's structure thins it
    // there (THIN_CROSSINGS = 2): then its light is added here, weighted by
    // its opacity, and the path goes on to the next crossing (drawn opaque
    // by the ray march) or the sky, as the non-rotating path does.
    int from = 0;
    float cpf = float(cam.cp), spf = float(cam.sp);
    [[dont_unroll]] for (int stop = 0; stop < THIN_CROSSINGS; ++stop) {
        float t = rad.tau_end, rc = 0.0;
        KerrPoint end = KerrPoint(0.0, 1.0, 0.0, 1.0, 0.0, false);
        bool on_disk = DISK_KIND == DISK_THIN && eta > 0.0 && rad.kcase != 4
                    && kerr_disk_crossing(rad, ang, to_m, from, t, rc, end);
        // (E < 0: not from the sky.)
        if (!on_disk && (rad.captured || cam.turn < 0.0)) return hit;
        if (!on_disk) end = rad.end;
        if (KERR_COMMON_ONLY && af != 0.0 && !(rad.kcase == 2 && rad.rh.x <= rad.r4)) {
            hit.deferred = true;  // I_phi needs kerr_j: to the second pass
            return hit;
        }
        // The azimuth there: phi = phi_o + dphi.
        vec2 ct;
        if (KERR_INSIDE) {
            ct = kerr_inside_end(rad, ang, cam, lamf, float(eta), t, on_disk ? rc : 1e31);
        } else {
            ct = kerr_end(rad, ang, af, lamf, float(eta), t, end);
            ct.y *= cam.turn;
        }
        vec2 cs = cos_sin_precise(ct.y);
        float cph = cpf * cs.x - spf * cs.y, sph = spf * cs.x + cpf * cs.y;
        if (on_disk) {
            // The world point (rho cos phi, 0, -rho sin phi), rho^2 = r^2 + a^2.
            float rho_c = sqrt(rc * rc + af * af) / to_m;
            vec3 pos = P.metric.holes[0].xyz + rho_c * cph * e1 - rho_c * sph * e2;
            float g = kerr_disk_g(rc, af, lamf);
            float delay = 0.0;
#ifndef GEODESIC_AOV
            // (The polarized picture takes the first crossing, as the
            // Stokes AOV does.)
            if (POLARIZATION != POL_VIEW) {
                if (LIGHT_DELAY) {
                    delay = KERR_INSIDE ? kerr_inside_delay(rad, ang, cam, lamf, float(eta), t, rc)
                                        : cam.turn * kerr_travel_time(rad, ang, af, lamf, t) / to_m;
                }
                if (kerr_disk_light(hit, stop, rc, to_m, pos, g, delay) < 1.0) continue;
            }
#endif
            hit.outcome = OUT_DISK;
            hit.pos = pos;
            hit.g = g;
            if (POLARIZATION != POL_OFF) {
                hit.pol = kerr_polarization(cam, rad, ang, end, from - 1, rc, d);
            }
            hit.delay = delay;
            return hit;
        }
        float sin_end = sqrt(max(1.0 - ct.x * ct.x, 0.0));
        hit.outcome = OUT_ESCAPED;
        hit.dir = normalize(sin_end * cph * e1 + ct.x * nrm - sin_end * sph * e2);
        return hit;
    }
    return hit;
}

#endif
