// The spinning hole's camera: where it stands in Boyer-Lindquist
// coordinates and, for a camera outside the horizon, a pixel's photon
// measured by the ZAMO there (its constants lambda, eta and the signs of
// the backward motion). The twin of src/physics/kerr/frame.rs.
#ifndef KERR_CAMERA_GLSL
#define KERR_CAMERA_GLSL

#include "params.glsl"
#include "ray_state.glsl"
#include "kerr/precision.glsl"

// The spin a* as its two f32 halves (params.rs): exact to f64.
kreal kerr_spin() {
    return kreal(P.metric.spin_hi) + kreal(P.metric.spin_lo);
}

// The camera's place and a pixel's photon: the Boyer-Lindquist position,
// the ZAMO there (alpha, omega), the constants lambda and eta, and the
// signs of the backward motion (kerr_camera).
struct KerrCamera {
    kreal a, to_m;       // the spin; M per world unit
    kreal r, c, cp, sp;  // r, cos theta, cos and sin of phi
    kreal alpha, omega;  // the ZAMO's lapse and angular velocity
    kreal lam, eta, theta_o;
    float s_r, s_th;
    float turn;          // the sign of the photon's energy E (see kerr_camera)
    kreal inv_e;         // 1 / E, E per unit energy the camera measures
};

// A world vector in the hole's frame (x = e1, y = the spin axis, z = e2).
// In the 64-bit build the frame is made orthonormal in f64 (e2 = e1 x n,
// as the host's disk_basis), so that the camera's place and its rays turn
// into it rigidly (a skew of 1e-7 would move a far camera's rays by 1e-7
// of its distance across).
#ifdef KERR_F32_ROOTS
kvec3 kerr_hole_frame(vec3 v) {
    return kvec3(dot(v, P.disk.e1), dot(v, P.disk.normal), dot(v, P.disk.e2));
}
#else
kvec3 kerr_hole_frame(dvec3 v) {
    dvec3 n = normalize(dvec3(P.disk.normal));
    dvec3 e1 = dvec3(P.disk.e1);
    e1 = normalize(e1 - dot(e1, n) * n);
    return dvec3(dot(v, e1), dot(v, n), dot(v, cross(e1, n)));
}

kvec3 kerr_hole_frame(vec3 v) {
    return kerr_hole_frame(dvec3(v));
}
#endif

// The camera's place (world, from the hole) and the coordinate direction
// of its ray d, in kreal. In the 64-bit build a pinhole's are formed again
// from the f64 position and axes (their f32 parts and what those leave,
// params.glsl) and the pixel's place on the image plane: far out (1e4 rs)
// a ray passes the hole at 1e-4 of the camera's distance, and a 32-bit
// direction or place would move it by 1e-3 rs. The observer's aberration
// as observer_to_coordinate's (none for the falling camera between the
// horizons, whose frame is its own).
kvec3 kerr_camera_rel(vec3 rel) {
#ifndef KERR_F32_ROOTS
    if (PROJECTION == PROJ_PINHOLE) {
        return dvec3(P.camera.position) - dvec3(P.metric.holes[0].xyz) + dvec3(P.camera.position_lo.xyz);
    }
#endif
    return kvec3(rel);
}

#ifndef KERR_F32_ROOTS
// A camera axis in f64: its f32 part and what that leaves.
dvec3 camera_axis64(vec3 hi, vec4 lo) {
    return dvec3(hi) + dvec3(lo.xyz);
}
#endif

// The pixel's direction in the observer's own frame (d_obs, as the
// projection gave it), in kreal.
kvec3 kerr_observer_dir(vec3 d_obs) {
#ifndef KERR_F32_ROOTS
    if (PROJECTION == PROJ_PINHOLE) {
        return normalize(camera_axis64(P.camera.forward, P.camera.forward_lo)
                         + double(pinhole_xy.x) * camera_axis64(P.camera.right, P.camera.right_lo)
                         + double(pinhole_xy.y) * camera_axis64(P.camera.up, P.camera.up_lo));
    }
#endif
    return kvec3(d_obs);
}

kvec3 kerr_pixel_dir(vec3 d) {
#ifndef KERR_F32_ROOTS
    if (PROJECTION == PROJ_PINHOLE) {
        dvec3 dir = kerr_observer_dir(d);
        dvec3 beta = dvec3(P.observer.velocity);
        double b2 = dot(beta, beta);
        if (!KERR_INSIDE && OBSERVER_MOVES && int(P.observer.kind) != OBS_FLAT && b2 > 0.0) {
            double gam = 1.0 / sqrt(1.0 - b2), bd = dot(beta, dir);
            dir = normalize((dir / gam - beta + (gam / (gam + 1.0)) * bd * beta) / (1.0 - bd));
        }
        return dir;
    }
#endif
    return kvec3(d);
}

// The flat triad (e_r, e_theta, e_phi) at the camera's place, in the
// hole's frame (x = e1, y = the spin axis, z = e2).
void kerr_triad(KerrCamera k, out kvec3 er, out kvec3 et, out kvec3 ep) {
    kreal a = k.a, r = k.r, c = k.c, cp = k.cp, sp = k.sp;
    kreal s = sqrt(max(1.0 - c * c, 0.0));
    kreal rho = sqrt(r * r + a * a), rs = sqrt(r * r + a * a * c * c);
    er = kvec3(r * s * cp, rho * c, -r * s * sp) / rs;
    et = kvec3(rho * c * cp, -r * s, -rho * c * sp) / rs;
    ep = kvec3(-sp, 0.0, -cp);
}

// The camera's Boyer-Lindquist place from rel (from the hole): k.a, k.to_m,
// k.r, k.c, k.cp, k.sp and sin theta (s); the unit direction d along the
// flat triad there (e_r, e_theta, e_phi) in dtr.
void kerr_place(vec3 rel, vec3 d, inout KerrCamera k, out kreal s, out kvec3 dtr) {
    kreal a = kerr_spin();
    k.a = a;
    // Lengths in M = rs / 2: position and direction in the hole's frame.
    k.to_m = 2.0 / kreal(P.metric.holes[0].w);
    kvec3 p = k.to_m * kerr_hole_frame(kerr_camera_rel(rel));
    kvec3 dd = normalize(kerr_hole_frame(kerr_pixel_dir(d)));
    // On the spin axis phi is undefined and lambda = 0 for every ray: the
    // camera moves 1e-6 of its distance off the axis, where the near-axis
    // form (the partner of Pi(-N), N ~ 1 / lambda^2) carries each ray's
    // sweep of phi past the pole.
    if (p.x * p.x + p.z * p.z < 1e-12 * dot(p, p)) p.x = 1e-6 * length(p);
    // Boyer-Lindquist position (no trigonometry: cos and sin of theta and
    // phi straight from the coordinates).
    kreal w = dot(p, p) - a * a;
    kreal r = sqrt(0.5 * (w + sqrt(w * w + 4.0 * a * a * p.y * p.y)));
    kreal c = p.y / r;
    s = sqrt(max(1.0 - c * c, 0.0));
    kreal rho = sqrt(r * r + a * a);
    kreal ph_len = sqrt(p.x * p.x + p.z * p.z);
    k.r = r;
    k.c = c;
    k.cp = ph_len > 0.0 ? p.x / ph_len : 1.0;
    k.sp = ph_len > 0.0 ? -p.z / ph_len : 0.0;
    kvec3 er, et, ep;
    kerr_triad(k, er, et, ep);
    dtr = kvec3(dot(dd, er), dot(dd, et), dot(dd, ep));
}

// The camera at rel (from the hole) and the photon arriving along d (the
// ZAMO's frame, world axes). A photon with E < 0 (inside the ergoregion)
// keeps lambda = L / E and eta = Q / E^2, finite, and the same r and theta
// motion per unit |E| of Mino time; its azimuth and time run the other way
// along the backward ray (turn = -1), and it cannot have come from
// infinity (the disk where it lies inside the ergoregion, or the horizon).
// False only at E = 0 exactly, where lambda and eta are unbounded.
bool kerr_camera(vec3 rel, vec3 d, out KerrCamera k) {
    kreal s;
    kvec3 dtr;
    kerr_place(rel, d, k, s, dtr);
    kreal a = k.a, r = k.r, c = k.c;
    // The ZAMO there.
    kreal sig = r * r + a * a * c * c;
    kreal delta = r * r - 2.0 * r + a * a;
    kreal big_a = (r * r + a * a) * (r * r + a * a) - a * a * delta * s * s;
    k.alpha = sqrt(sig * delta / big_a);
    k.omega = 2.0 * a * r / big_a;
    kreal varpi = sqrt(big_a / sig) * s;
    kreal rs = sqrt(sig);
    kreal dr = dtr.x, dt = dtr.y, dph = dtr.z;
    kreal en = k.alpha - k.omega * varpi * dph;
    kreal l = -varpi * dph;
    kreal pth = rs * dt;
    kreal qq = pth * pth + c * c * (l * l / (s * s) - a * a * en * en);
    k.lam = l / en;
    k.eta = qq / (en * en);
    k.s_r = dr < 0.0 ? -1.0 : 1.0;
    k.s_th = dt < 0.0 ? -1.0 : 1.0;
    k.theta_o = (pth / en) * (pth / en);
    k.turn = en < 0.0 ? -1.0 : 1.0;
    k.inv_e = (1.0 - k.omega * k.lam) / k.alpha;
    return en != 0.0;
}

#endif
