// Polarized light of the thin disk (docs/polarization.md), the GPU twin of
// src/physics/polarization.rs: the one include through which every metric
// that shades the disk in closed form gives a disk hit its Stokes
// parameters. The metric hands over, at the crossing, the photon's
// ZAMO-frame momentum (the static frame's at a* = 0) and, at the camera,
// the photon's and the sky's north and west as ZAMO-frame 4-vectors
// (t, r, theta, phi); the emission in the gas's frame and the
// Walker-Penrose constant, which carries the electric vector to the camera
// in closed form, are here. Units M = 1.
//
// The constant of photon p and polarization f is kappa = (A - i B)(r - i a
// cos theta), A and B the bivector p ^ f's parts on the tetrad (see
// walker_penrose in the Rust twin); at the camera it is solved for f's two
// components across the ray. Far cameras: kappa's parts there are of the
// order of the impact parameter over r, so the camera's side runs in
// `preal` (64 bits where the device has them), the emitter's in 32.
#ifndef POLARIZATION_GLSL
#define POLARIZATION_GLSL

#include "tiles.glsl"

#include "params.glsl"
#include "variant.glsl"

// The camera side's precision: 64 bits in the spinning hole's build with
// 64-bit roots (the device has shaderFloat64), else 32.
#if defined(METRIC_KERR) && !defined(KERR_F32_ROOTS)
#define preal double
#define pvec2 dvec2
#define pvec3 dvec3
#define pvec4 dvec4
#else
#define preal float
#define pvec2 vec2
#define pvec3 vec3
#define pvec4 vec4
#endif

// The pixel's direction in the observer's own frame (camera_ray sets it):
// the sky's north and west are taken across it.
vec3 pol_dir_observer = vec3(0.0, 0.0, 1.0);
// And where its ray starts (an ODS eye's place on the viewing circle).
vec3 pol_origin = vec3(0.0);

// kappa (as a complex vec2) of p and f, ZAMO components at Boyer-Lindquist
// (r, cos theta = c) of a hole of spin a, in the precision T: the camera's
// side in preal (pol_kappa_camera), a volume sample's in 32 bits
// (pol_kappa_at).
#define POL_KAPPA_AT(name, T, T2, T4) \
    T2 name(T r, T c, T a, T4 p, T4 f) { \
        T s = sqrt(max(1.0 - c * c, 0.0)); \
        T rho2 = r * r + a * a, sig = r * r + a * a * c * c, delta = r * r - 2.0 * r + a * a; \
        T big_a = rho2 * rho2 - a * a * delta * s * s; \
        T alpha = sqrt(sig * delta / big_a), omega = 2.0 * a * r / big_a; \
        T s_varpi = sqrt(sig / big_a); /* sin theta / varpi, finite on the axis */ \
        T m0r = p.x * f.y - p.y * f.x, mrp = p.y * f.w - p.w * f.y; \
        T m0t = p.x * f.z - p.z * f.x, mpt = p.w * f.z - p.z * f.w; \
        T ka = sqrt(delta / sig) * ((1.0 - a * s * s * omega) / alpha * m0r + a * s * s_varpi * mrp); \
        T kb = (s / sqrt(sig)) * (rho2 * omega - a) / alpha * m0t + rho2 * s_varpi / sqrt(sig) * mpt; \
        /* (A - i B)(r - i a c) */ \
        T im_r = -a * c; \
        return T2(ka * r + kb * im_r, ka * im_r - kb * r); \
    }
POL_KAPPA_AT(pol_kappa_camera, preal, pvec2, pvec4)
POL_KAPPA_AT(pol_kappa_at, float, vec2, vec4)

// kappa of p and f given on the falling frame (u, e_r, e_theta, e_phi; the
// frame of kerr/interior.glsl's falling camera) at Boyer-Lindquist (r, c)
// of spin a, in preal: its parts X, Y, sin(theta) Z, W in ingoing Kerr
// components, where every axis is finite through r+ (the 1 / Delta of the
// Boyer-Lindquist ones cancels: q = sqrt(r^2 + a^2), f = sqrt(2 r); the
// Rust twin's falling_parts).
pvec2 pol_kappa_falling(preal r, preal c, preal a, pvec4 p, pvec4 f) {
    preal s = sqrt(max(1.0 - c * c, 0.0));
    preal q = sqrt(r * r + a * a), fall = sqrt(2.0 * r), qf = q + fall;
    preal sig = r * r + a * a * c * c, delta = r * r - 2.0 * r + a * a;
    preal big_a = q * q * q * q - a * a * delta * s * s;
    preal sa = sqrt(big_a), k = sqrt(sig / big_a);
    // Each part over the axes u, e_r, e_theta, e_phi.
    pvec4 xs = pvec4(q / qf, (q * q * q - a * a * s * s * qf) / (qf * sa), 0.0, -a * s * k);
    pvec4 ys = pvec4(-q * fall / sig, sa / sig, 0.0, 0.0);
    pvec4 zs = pvec4(-a * s, s * a * q * fall / sa, 0.0, q * q * k);
    pvec4 ws = pvec4(0.0, 0.0, 1.0 / sqrt(sig), 0.0);
    preal ka = dot(p, xs) * dot(f, ys) - dot(p, ys) * dot(f, xs);
    preal kb = dot(p, zs) * dot(f, ws) - dot(p, ws) * dot(f, zs);
    preal im_r = -a * c;
    return pvec2(ka * r + kb * im_r, ka * im_r - kb * r);
}

// The same at an equatorial emitter (cos theta = 0), in 32 bits.
vec2 pol_kappa_equator(float r, float a, vec4 p, vec4 f) {
    float rho2 = r * r + a * a, delta = r * r - 2.0 * r + a * a;
    float big_a = rho2 * rho2 - a * a * delta;
    float alpha = r * sqrt(delta / big_a), omega = 2.0 * a * r / big_a, s_varpi = r * inversesqrt(big_a);
    float m0r = p.x * f.y - p.y * f.x, mrp = p.y * f.w - p.w * f.y;
    float m0t = p.x * f.z - p.z * f.x, mpt = p.w * f.z - p.z * f.w;
    float ka = (sqrt(delta) / r) * ((1.0 - a * omega) / alpha * m0r + a * s_varpi * mrp);
    float kb = (rho2 * omega - a) / (alpha * r) * m0t + rho2 * s_varpi / r * mpt;
    return vec2(ka * r, -kb * r);
}

// I_e = (r / rs)^-n sin(theta_B)^(1 + alpha) / |k_z| (r_rs: r in rs), for
// sin theta_B > 0 (where it is 0 the angle is undefined and I_e is taken as
// 0, as the Rust twin does; pow(0, y) is undefined for y <= 0).
float pol_emitted(float r_rs, float sin_b, float k_z) {
    return pow(r_rs, -P.polarization.emissivity_index) * pow(sin_b, 1.0 + P.polarization.spectral_index)
         / max(abs(k_z), 1e-6);
}

// The ZAMO-frame photon of constants (lambda, eta) crossing the equator at
// r (M) with backward signs s_r, s_th, per unit |E| (turn: the sign of E),
// future-pointing.
vec4 pol_equatorial_photon(float r, float a, float lam, float eta, float s_r, float s_th, float turn) {
    float rho2 = r * r + a * a, delta = r * r - 2.0 * r + a * a;
    float big_a = rho2 * rho2 - a * a * delta;
    float alpha = r * sqrt(delta / big_a), omega = 2.0 * a * r / big_a, varpi = sqrt(big_a) / r;
    float x = rho2 - a * lam, y = lam - a;
    float big_r = max(x * x - delta * (eta + y * y), 0.0);
    return vec4(turn * (1.0 - omega * lam) / alpha, -s_r * sqrt(big_r) / (r * sqrt(delta)),
                -s_th * sqrt(max(eta, 0.0)) / r, turn * lam / varpi);
}

// The emission towards the photon p (ZAMO components) at equatorial r (M):
// the gas's frame is the ZAMO's boosted along e_phi by the Keplerian speed,
// its vertical e_(z) = -e_theta. Returns kappa of p and the electric vector
// f = k x B / |k x B| (.xy), and I_e = (r / rs)^-n sin(theta_B)^(1 + alpha)
// / |k_z| (.z); .w = 0 where the angle is undefined (sin theta_B = 0).
vec4 pol_emit(float r, float a, vec4 p) {
    float rho2 = r * r + a * a, delta = r * r - 2.0 * r + a * a;
    float big_a = rho2 * rho2 - a * a * delta;
    float alpha = r * sqrt(delta / big_a), omega = 2.0 * a * r / big_a, varpi = sqrt(big_a) / r;
    float om = 1.0 / (r * sqrt(r) + a);
    float beta = varpi * (om - omega) / alpha, gam = inversesqrt(max(1.0 - beta * beta, 1e-12));
    float pt = gam * (p.x - beta * p.w);
    vec3 k = vec3(p.y, gam * (p.w - beta * p.x), -p.z) / pt;
    vec3 kb = cross(k, P.polarization.field);
    float sin_b = length(kb);
    vec3 fe = sin_b > 1e-7 ? kb / sin_b : vec3(0.0);
    vec4 f = vec4(gam * beta * fe.y, fe.x, -fe.z, gam * fe.y);
    float ie = sin_b > 1e-7 ? pol_emitted(0.5 * r, sin_b, k.z) : 0.0;
    return vec4(pol_kappa_equator(r, a, p, f), ie, sin_b > 1e-7 ? 1.0 : 0.0);
}

// A 4-vector of the observer moving at beta through the ZAMO, in the
// ZAMO's components (v0; v): (gamma (v0 + beta.v); v + ((gamma - 1)(b.v)
// / b^2 + gamma v0) beta).
pvec4 pol_boost(pvec3 beta, preal v0, pvec3 v) {
    preal b2 = dot(beta, beta);
    if (b2 == 0.0) return pvec4(v0, v);
    preal gam = 1.0 / sqrt(1.0 - b2), bv = dot(beta, v);
    return pvec4(gam * (v0 + bv), v + ((gam - 1.0) * bv / b2 + gam * v0) * beta);
}

// The non-rotating hole's side, coordinate-free in the static frame (a =
// 0, where kappa = r [(p^0 f_r - p_r f^0) + i (p x f) . r_hat]: no polar
// axis needed): 4-vectors as (t; world xyz) on the static frame at a point
// at distance r (any unit, the same at both ends) in the direction r_hat.
vec2 pol_kappa_static(float r, vec3 r_hat, vec4 p, vec4 f) {
    float a = p.x * dot(f.yzw, r_hat) - dot(p.yzw, r_hat) * f.x;
    return r * vec2(a, dot(cross(p.yzw, f.yzw), r_hat));
}

// The emission of the non-rotating hole's disk at r (rs units) towards the
// photon moving along the unit k_hat (static frame): the gas moves along
// e_phi = n x r_hat at beta = sqrt(M / (r - 2M)). As pol_emit: kappa (of
// the photon (1; k_hat)), I_e, defined.
vec4 pol_emit_static(float r, vec3 r_hat, vec3 normal, vec3 k_hat) {
    vec3 e_phi = cross(normal, r_hat);
    float beta = sqrt(0.5 / max(r - 1.0, 1e-6)), gam = inversesqrt(max(1.0 - beta * beta, 1e-12));
    float kp = dot(k_hat, e_phi);
    float pt = gam * (1.0 - beta * kp);
    vec3 k = vec3(dot(k_hat, r_hat), gam * (kp - beta), dot(k_hat, normal)) / pt;
    vec3 kb = cross(k, P.polarization.field);
    float sin_b = length(kb);
    vec3 fe = sin_b > 1e-7 ? kb / sin_b : vec3(0.0);
    vec4 f = vec4(gam * beta * fe.y, fe.x * r_hat + gam * fe.y * e_phi + fe.z * normal);
    float ie = sin_b > 1e-7 ? pol_emitted(r, sin_b, k.z) : 0.0;
    return vec4(pol_kappa_static(r, r_hat, vec4(1.0, k_hat), f), ie, sin_b > 1e-7 ? 1.0 : 0.0);
}

// At the non-rotating hole's camera (r rs from the hole, along r_hat),
// whose observer moves at beta through the static frame: kappa(p, n) and
// kappa(p, w) (.xy, .zw) of the photon along -dir and the sky's north and
// west across the observer's own direction.
vec4 pol_camera_static(float r, vec3 r_hat, vec3 beta) {
    vec3 d = pol_dir_observer;
    vec3 nn = normalize(P.camera.up - dot(P.camera.up, d) * d), ww = cross(nn, d);
    vec4 p = vec4(pol_boost(beta, 1.0, -d)), n4 = vec4(pol_boost(beta, 0.0, nn)), w4 = vec4(pol_boost(beta, 0.0, ww));
    // Across the photon as traced (see kerr_polarization).
    n4.x = dot(n4.yzw, p.yzw) / p.x;
    w4.x = dot(w4.yzw, p.yzw) / p.x;
    return vec4(pol_kappa_static(r, r_hat, p, n4), pol_kappa_static(r, r_hat, p, w4));
}

// The electric vector's angle east of north at the camera, as (cos 2 chi,
// sin 2 chi): kappa = c1 kappa(p, n) + c2 kappa(p, w) for real c1, c2 (the
// gauge part along p drops out), chi = atan2(-c2, c1). kn, kw: kappa(p, n)
// and kappa(p, w) at the camera.
vec2 pol_angle(vec2 kappa, vec2 kn, vec2 kw) {
    float det = kn.x * kw.y - kw.x * kn.y;
    float c1 = (kappa.x * kw.y - kw.x * kappa.y) / det;
    float c2 = (kn.x * kappa.y - kappa.x * kn.y) / det;
    // cos 2 chi = (c1^2 - c2^2) / |c|^2, sin 2 chi = -2 c1 c2 / |c|^2.
    float n2 = max(c1 * c1 + c2 * c2, 1e-37);
    return vec2((c1 * c1 - c2 * c2) / n2, -2.0 * c1 * c2 / n2);
}

// A disk hit's polarization (Hit.pol): (cos 2 chi, sin 2 chi) from
// pol_angle, I_e and whether the angle is defined from pol_emit.
vec4 pol_of(vec4 emitted, vec2 angle) {
    return vec4(angle, emitted.zw);
}

// The Stokes vector of a disk hit from its pol_of and the observed g: I =
// g^(3 + alpha) I_e, P = fraction I (0 where the angle is undefined), Q =
// P cos 2 chi, U = P sin 2 chi, V = 0.
vec4 pol_stokes(vec4 pol, float g) {
    float i = pow(max(g, 0.0), 3.0 + P.polarization.spectral_index) * pol.z;
    float p = P.polarization.fraction * i * pol.w;
    return vec4(i, p * pol.xy, 0.0);
}

// Field models side by side (`fields`, up to four): pixel px's tile t covers
// columns t W / n to (t + 1) W / n; the camera sees each tile as a whole
// image of that width, with its own field. Returns px's column in its tile
// (the image's own pixel where there is one model).
uvec2 pol_tile(uvec2 px) {
    uint n = clamp(P.polarization.tiles, 1u, 4u);
    if (n == 1u) return px;
    uint w = P.camera.size.x;
    uint t = tile_index(px.x, n, w);
    uint x0 = t * w / n;
    P.camera.size.x = (t + 1u) * w / n - x0;
    P.camera.aspect = float(P.camera.size.x) / float(P.camera.size.y);
    P.polarization.field = P.polarization.fields[t].xyz;
    return uvec2(px.x - x0, px.y);
}

// The volumetric disk (volume.glsl): each sample emits as the thin disk
// does, from its own place, and its electric vector is carried to the
// camera by its own Walker-Penrose constant; the ray's Stokes vector is the
// sum over the samples (pol_volume). The camera's side, kappa(p, n) and
// kappa(p, w) (.xy, .zw), is the metric's, once a ray (pol_cam_k), and so
// is its own measure of the photon's energy at infinity (pol_cam_g: a
// sample's g = pol_cam_g / its gas energy per unit E).
vec4 pol_cam_k = vec4(1.0, 0.0, 0.0, 1.0);
float pol_cam_g = 1.0;
vec4 pol_volume = vec4(0.0);

// The electric vector emitted along k (the gas's frame, unit): f = k x B /
// |k x B|, and sin(theta_B) = |k x B|; 0 where the angle is undefined.
vec3 pol_across(vec3 k, out float sin_b) {
    vec3 kb = cross(k, P.polarization.field);
    sin_b = length(kb);
    return sin_b > 1e-7 ? kb / sin_b : vec3(0.0);
}

// A volume sample's emissivity per unit length and density in the gas's
// frame, (r / rs)^-n sin(theta_B)^(1 + alpha) (0 where undefined: P = 0).
float pol_volume_j(float r_rs, float sin_b) {
    return sin_b > 1e-7 ? pow(r_rs, -P.polarization.emissivity_index) * pow(sin_b, 1.0 + P.polarization.spectral_index)
                        : 0.0;
}

// A spinning hole's volume sample at Boyer-Lindquist (r, cos theta = c)
// (M): the photon of constants (lam, eta) there with backward signs s_r,
// s_th (ZAMO components: p^(r) = -s_r sqrt(R / (Sigma Delta)), p^(theta) =
// -s_th sqrt(Theta / Sigma)), the gas on a circular orbit at the
// Keplerian angular velocity of the equatorial radius x at its distance
// from the axis (as metric_gas_g: (r^2 + a^2) sin^2 - a^2 = x^2, no nearer
// than the disk's inner edge), the ZAMO's frame boosted along e_phi; the
// field on its e_r, e_phi and -e_theta (the disk's radial, toroidal and
// vertical at the equator). Returns kappa (.xy), pol_volume_j (.z) and
// 1 / the gas's energy per unit E (.w).
vec4 pol_volume_kerr(float r, float c, float a, float lam, float eta, float s_r, float s_th, float turn) {
    float s2 = max(1.0 - c * c, 1e-12);
    float rho2 = r * r + a * a, sig = r * r + a * a * c * c, delta = r * r - 2.0 * r + a * a;
    float big_a = rho2 * rho2 - a * a * delta * s2;
    float alpha = sqrt(sig * delta / big_a), omega = 2.0 * a * r / big_a, varpi = sqrt(big_a / sig * s2);
    float xx = rho2 - a * lam, yy = lam - a;
    float big_r = max(xx * xx - delta * (eta + yy * yy), 0.0);
    float big_th = max(eta + (a * a - lam * lam / s2) * c * c, 0.0);
    vec4 p = vec4(turn * (1.0 - omega * lam) / alpha, -s_r * sqrt(big_r / (sig * delta)), -s_th * sqrt(big_th / sig),
                  turn * lam / varpi);
    float x = max(sqrt(max(r * r * s2 - a * a * c * c, 0.0)), 2.0 * P.disk.inner / P.metric.holes[0].w);
    float beta = clamp(varpi * (1.0 / (x * sqrt(x) + a) - omega) / alpha, -0.999999, 0.999999);
    float gam = inversesqrt(1.0 - beta * beta);
    float pt = gam * (p.x - beta * p.w);
    float sin_b;
    vec3 fe = pol_across(vec3(p.y, gam * (p.w - beta * p.x), -p.z) / pt, sin_b);
    vec4 f = vec4(gam * beta * fe.y, fe.x, -fe.z, gam * fe.y);
    return vec4(pol_kappa_at(r, c, a, p, f), pol_volume_j(0.5 * r, sin_b), 1.0 / pt);
}

// The non-rotating hole's volume sample r rs from the hole along r_hat,
// the photon along k_hat (static frame), coordinate-free as
// pol_emit_static: the gas moves along e_phi = v x r_hat (v: -e_theta, the
// unit vector across r_hat towards the disk's normal) at the Keplerian
// angular velocity of its distance from the axis (no nearer than the inner
// edge). Returns as pol_volume_kerr.
vec4 pol_volume_static(float r, vec3 r_hat, vec3 k_hat) {
    vec3 n = P.disk.normal;
    vec3 v = n - dot(n, r_hat) * r_hat;
    float sin_t = length(v);
    v = sin_t > 1e-6 ? v / sin_t : n;
    vec3 e_phi = cross(v, r_hat);
    float x = max(r * sin_t, P.disk.inner / P.metric.holes[0].w);
    float lapse = sqrt(max(1.0 - 1.0 / r, 1e-6));
    // varpi Omega / alpha in M: (2 r sin) (2 x)^-3/2 / lapse.
    float beta = min(2.0 * r * sin_t * pow(2.0 * x, -1.5) / lapse, 0.999999);
    float gam = inversesqrt(1.0 - beta * beta);
    float kp = dot(k_hat, e_phi);
    float pt = gam * (1.0 - beta * kp);
    float sin_b;
    vec3 fe = pol_across(vec3(dot(k_hat, r_hat), gam * (kp - beta), dot(k_hat, v)) / pt, sin_b);
    vec4 f = vec4(gam * beta * fe.y, fe.x * r_hat + gam * fe.y * e_phi + fe.z * v);
    return vec4(pol_kappa_static(r, r_hat, vec4(1.0, k_hat), f), pol_volume_j(r, sin_b), lapse / pt);
}

// What a sample of pol_volume_kerr or pol_volume_static adds to the ray's
// Stokes vector, per unit of its weight (transmission x density x length):
// I = g^(2 + alpha) j (the length is the camera's, hence one power of g
// less than the thin disk's), P = fraction I at the angle its constant
// gives at the camera.
vec4 pol_volume_seen(vec4 em) {
    float i = pow(max(pol_cam_g * em.w, 0.0), 2.0 + P.polarization.spectral_index) * em.z;
    vec2 angle = pol_angle(em.xy, pol_cam_k.xy, pol_cam_k.zw);
    return vec4(i, (P.polarization.fraction * i) * angle, 0.0);
}

#endif
