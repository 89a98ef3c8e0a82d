// Skies for escaped rays: the checker, the procedural stars, an image, the
// real catalogue, and the grid plane behind the hole.
#ifndef SKY_GLSL
#define SKY_GLSL

#include "bindings.glsl"
#include "params.glsl"
#include "variant.glsl"
#include "blackbody.glsl"

// The image sky's panorama with mips, the catalogue's star grid with mips
// (src/stars.rs), or the colour table, unused, for the other skies.
layout(binding = RM_SKY) uniform sampler2D sky_tex;

// Steps of a star cell's packed light place along u (PLACE_STEPS in
// src/stars.rs).
#define STAR_PLACE_STEPS 4095.0

// A pixel's footprint on the sky: the change of the ray's final direction
// from this pixel to the next one across (x) and down (y), in radians (the
// ray differentials; unlensed, the pixel's angular size in two directions
// at right angles).
struct Footprint {
    vec3 x;
    vec3 y;
    float pixel;   // the unlensed pixel angle
};

// The footprint's largest extent, radians per pixel.
float footprint_size(Footprint f) {
    float a = dot(f.x, f.x), b = dot(f.x, f.y), c = dot(f.y, f.y);
    return sqrt(0.5 * (a + c) + sqrt(0.25 * (a - c) * (a - c) + b * b));
}

// PCG-style 3 -> 3 integer hash (Jarzynski & Olano, "Hash Functions for GPU
// Rendering", JCGT 2020), as floats in [0, 1).
vec3 hash33(uvec3 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.z; v.y += v.z * v.x; v.z += v.x * v.y;
    v ^= v >> 16u;
    v.x += v.y * v.z; v.y += v.z * v.x; v.z += v.x * v.y;
    return vec3(v) * (1.0 / 4294967296.0);
}

// The checker on the celestial sphere (lensing made plain): squares in
// longitude and latitude, so lensing shows as bent lines.
vec3 sky_checker(vec3 d) {
    float n = P.sky.scale;
    float phi = atan(d.z, d.x);
    float theta = acos(clamp(d.y, -1.0, 1.0));
    float u = (phi / (2.0 * 3.14159265) + 0.5) * n;
    float w = theta / 3.14159265 * (0.5 * n);
    bool odd = ((int(floor(u)) + int(floor(w))) & 1) == 1;
    vec3 c = odd ? vec3(0.85, 0.85, 0.9) : vec3(0.1, 0.14, 0.28);
    return c * P.sky.brightness;
}

// A deterministic star field: the sphere is cut into cells on the faces of a
// cube (CELLS x CELLS per face); a cell holds at most one star at a hashed
// place, with a hashed brightness (a steep power law: few bright stars, many
// faint) and blackbody temperature. A star is drawn as a Gaussian whose width
// is the pixel's angular size (or more), with its total flux fixed, so stars
// stay one or two pixels wide and keep their brightness at any resolution and
// do not shimmer as the camera moves. The cells around the direction are
// visited so stars near a cell edge are not cut.
const float CELLS = 160.0;

// The cube face d points into (+x, -x, +y, -y, +z, -z) and its place on it
// in [-1, 1]^2. Selects rather than branches: on a CPU driver every branch
// runs for every pixel, so three branches cost three divisions.
vec3 cube_face(vec3 d, out uint face, out vec2 uv) {
    vec3 a = abs(d);
    bool fx = a.x >= a.y && a.x >= a.z;
    bool fy = !fx && a.y >= a.z;
    float m = fx ? a.x : (fy ? a.y : a.z);
    float s = fx ? d.x : (fy ? d.y : d.z);
    vec2 p = fx ? d.zy : (fy ? d.xz : d.xy);
    face = (fx ? 0u : (fy ? 2u : 4u)) + (s > 0.0 ? 0u : 1u);
    uv = p * (1.0 / m);
    return a;
}

vec3 face_dir(uint face, vec2 uv) {
    vec3 d;
    if (face < 2u)      d = vec3(face == 0u ? 1.0 : -1.0, uv.y, uv.x);
    else if (face < 4u) d = vec3(uv.x, face == 2u ? 1.0 : -1.0, uv.y);
    else                d = vec3(uv.x, uv.y, face == 4u ? 1.0 : -1.0);
    return normalize(d);
}

vec3 sky_stars(vec3 d, float pixel_angle) {
    uint face;
    vec2 uv;
    cube_face(d, face, uv);
    vec2 g = (uv * 0.5 + 0.5) * CELLS;
    vec2 cell = floor(g);
    float sigma = max(0.6 * pixel_angle, 2e-5);
    float reach2 = 16.0 * sigma * sigma;
    // A star sits at least 0.1 cell from its cell's edge and is drawn out to
    // 4 sigma. When that reach is under 0.4 cell (pixels smaller than about a
    // fifth of a cell, as at 720p and up), the 2x2 cells nearest to d hold
    // every star that can touch it; for coarser pixels, the 3x3 around it.
    // The choice is the same for the whole image, so it costs no divergence.
    bool coarse = 4.0 * sigma > 0.4 * (2.0 / CELLS);
    vec2 side = coarse ? vec2(1.0) : sign(g - cell - 0.5);
    int lo = coarse ? -1 : 0;
    // Flux and flux-weighted temperature of the stars that reach d; one
    // colour-table lookup at the end instead of one per star (stars rarely
    // overlap, and on a CPU driver every lookup in the loop is paid for
    // every cell of every pixel).
    // One loop over the cells, its test after the body: a CPU driver runs a
    // loop's body until no lane of the SIMD group is left, so nested loops
    // tested before their bodies ran seven bodies for the 2x2 cells (the
    // counters step at the top, so a `continue` keeps them).
    float flux_sum = 0.0, temp_sum = 0.0;
    int i = lo - 1, j = lo;
    do {
        if (++i > 1) {
            i = lo;
            ++j;
        }
        vec2 c = cell + vec2(i, j) * side;
        if (any(lessThan(c, vec2(0.0))) || any(greaterThanEqual(c, vec2(CELLS)))) continue;
        vec3 h = hash33(uvec3(uvec2(c), face * 7919u + 17u));
        if (h.z > P.sky.scale) continue;  // star density: the chance a cell has a star
        vec2 suv = ((c + 0.1 + 0.8 * h.xy) / CELLS) * 2.0 - 1.0;
        vec3 s = face_dir(face, suv);
        vec3 h2 = hash33(uvec3(uvec2(c) + 4099u, face + 101u));
        // Brightness: power law, a few bright stars among many faint ones.
        float is = inversesqrt(max(h2.x, 1e-12));   // h^-1.5 without pow
        float flux = 5e-8 * min(is * is * is, 1000.0);
        float temp = mix(2800.0, 14000.0, h2.y * h2.y);
        // Chord length squared: the angle squared, for small angles.
        vec3 delta = d - s;
        float ang2 = dot(delta, delta);
        if (ang2 > reach2) continue;
        float w = exp(-0.5 * ang2 / (sigma * sigma)) / (6.2831853 * sigma * sigma);
        flux_sum += flux * w;
        temp_sum += flux * w * temp;
    } while (i < 1 || j < 1);
    vec3 sum = flux_sum > 0.0 ? blackbody(temp_sum / flux_sum) * flux_sum : vec3(0.0);
    // A faint galaxy band along a great circle tilted 60 degrees to the disk,
    // with a little large-scale texture.
    vec3 gal_n = normalize(vec3(0.0, 0.5, 0.866));
    float lat = dot(d, gal_n);
    vec3 h3 = hash33(uvec3(uvec2(floor((uv * 0.5 + 0.5) * 12.0)), face));
    float band = exp(-lat * lat / (2.0 * 0.12 * 0.12)) * (0.75 + 0.5 * h3.x);
    vec3 galaxy = vec3(0.9, 0.85, 0.75) * (P.sky.galaxy * band);
    return (sum + galaxy) * P.sky.brightness;
}

// exp(-16 x), near enough for a soft profile: (1 - x)^16, zero past x = 1.
// Four squarings where an exponential is a range reduction and a polynomial
// on a CPU driver. As a Gaussian exp(-r^2 / (2 sigma^2)) with x = r^2 / (2
// sigma^2 (16 + 1)): within 1.4 % of the peak everywhere, the same total (2
// pi sigma^2), and 66 % of its height at 3 sigma.
float soft_profile(float x) {
    float k = max(1.0 - x, 0.0);
    k *= k;
    k *= k;
    k *= k;
    return k * k;
}

// The light one cell of the catalogue's star grid sheds on d: its texel
// `ip` at level `level`, whose corner is `o` cells from d's place g, mapped
// to pixels by q (see sky_catalogue). Each star is a Gaussian of sigma
// STAR_SIGMA pixels drawn with soft_profile.
const float STAR_SIGMA = 0.6;   // pixels
vec3 star_cell(ivec2 ip, vec2 o, int level, mat2 q) {
    // x: the light's place in the cell (integer part u in 4095ths,
    // fraction v in 4096ths); yzw: the stars' light (src/stars.rs).
    vec4 t = texelFetch(sky_tex, ip, level);
    float pu = floor(t.x);
    vec2 place = vec2(pu * (1.0 / STAR_PLACE_STEPS),
                      (t.x - pu) * ((STAR_PLACE_STEPS + 1.0) / STAR_PLACE_STEPS));
    vec2 p = q * (o + place);
    return soft_profile((1.0 / (34.0 * STAR_SIGMA * STAR_SIGMA)) * dot(p, p)) * t.yzw;
}

// The real sky (src/stars.rs): the Hipparcos stars binned on the faces of a
// cube in galactic coordinates, one texel per cell (the place of its light
// in the cell, its stars' flux relative to a magnitude-0 star times their
// colour), with mips that merge 2x2 cells.
//
// Each star is drawn where the lensing puts it and as the lensing shapes
// it: the pixel's footprint (the ray differentials A = [f.x f.y], the final
// direction's change per pixel) maps a star's offset on the sky, delta, to
// an offset in pixels, p = (A^T A)^-1 A^T delta, and the star is a Gaussian
// of sigma 0.6 pixel there, divided by the pixel's solid angle sqrt(det A^T
// A). So a star keeps its flux at any resolution, and near the hole its
// images stretch along the lensed arcs and brighten by the magnification
// (tests/sky.rs checks the point-lens magnification).
//
// The level is the finest whose cells are at least 2.5 times the reach of
// that Gaussian along the footprint's longest axis, so the 2x2 cells
// nearest to d hold every star that can touch it: four fetches whatever the
// footprint. Stars closer than about one cell at that level (four to eight
// pixels) blend into one point at their light's centroid, their flux summed.
// The Milky Way is a faint band along the galactic plane, wider and brighter
// toward the galactic centre.
vec3 sky_catalogue(vec3 dw, Footprint f) {
    mat3 m = transpose(mat3(P.sky.row0, P.sky.row1, P.sky.row2));
    vec3 d = m * dw;   // (a unit vector turned)
    vec3 ax = m * f.x, ay = m * f.y;
    float m11 = dot(ax, ax), m12 = dot(ax, ay), m22 = dot(ay, ay);
    // The solid angle of a pixel, at least 1/MAX_GAIN of the unlensed one:
    // at a critical curve the linear footprint degenerates and a star would
    // flash up without bound; a pixel's real magnification stays finite.
    const float MAX_GAIN = 50.0;
    float min_area = f.pixel * f.pixel / MAX_GAIN;
    float det = max(m11 * m22 - m12 * m12, min_area * min_area);
    float area = sqrt(det);
    // footprint_size squared: its outer square root is folded into the level.
    float size2 = 0.5 * (m11 + m22) + sqrt(0.25 * (m11 - m22) * (m11 - m22) + m12 * m12);
    uint face;
    vec2 uv;
    vec3 ad = cube_face(d, face, uv);
    float n0 = P.sky.scale;
    // The reach is 3 STAR_SIGMA size; the level, ceil(log2(x)) for x =
    // 1.25 n0 reach. (Multiplications by reciprocals here and below:
    // divisions are dear on a CPU driver.)
    // ceil(log2(x)) from the exponent bits of x^2 = m 2^e (m in [0.5, 1)):
    // log2(x) lies in [(e - 1) / 2, e / 2), so its ceiling is (e + 1) >> 1
    // (one level coarser at an exact power of two, which is as safe), and
    // 2^-level from bits: a CPU driver builds sqrt, log2 and exp2 at a cost.
    float x_scale = 3.0 * STAR_SIGMA * 1.25 * n0;
    int e;
    frexp(max(size2, 1e-14) * (x_scale * x_scale), e);
    int li = clamp((e + 1) >> 1, 0, 7);
    float n = n0 * uintBitsToFloat(uint(127 - li) << 23u);
    vec2 g = (uv * 0.5 + 0.5) * n;
    vec2 cell = min(floor(g), vec2(n - 1.0));
    vec2 side = sign(g - cell - 0.5);
    // A star's offset from d in pixels, linear in its offset from g in cells:
    // on the face, d = normalize(e_u u + e_v v + e_n), and dd/du, dd/dv are
    // e_u, e_v less their part along d, over |e_u u + e_v v + e_n| (which is
    // 1 / max |d_i|, d being a unit vector). Against
    // the exact offset the error is second order in the offset (a few cells
    // of a face cut into n): below 1% of a star's place in pixels at the
    // finest level, and the stars of coarser levels are wider still.
    vec3 e_u = face < 2u ? vec3(0.0, 0.0, 1.0) : vec3(1.0, 0.0, 0.0);
    vec3 e_v = (face == 2u || face == 3u) ? vec3(0.0, 0.0, 1.0) : vec3(0.0, 1.0, 0.0);
    float to_dir = (2.0 / n) * max(ad.x, max(ad.y, ad.z));
    vec3 du = (e_u - d * dot(d, e_u)) * to_dir, dv = (e_v - d * dot(d, e_v)) * to_dir;
    // p = (A^T A)^-1 A^T J (cells), A = [ax ay], J = [du dv].
    mat2 ata_inv = mat2(m22, -m12, -m12, m11) * (1.0 / det);
    mat2 atj = mat2(dot(ax, du), dot(ay, du), dot(ax, dv), dot(ay, dv));
    mat2 q = ata_inv * atj;
    // The 2x2 cells as four calls, not a loop with a skip: a CPU driver
    // runs every lane through every cell anyway, and the loop's masks cost
    // more.
    // A cell clamped at a face's edge is the same cell twice: counted once.
    vec2 c1 = clamp(cell + side, vec2(0.0), vec2(n - 1.0));
    vec2 once = vec2(notEqual(c1, cell));
    int x0 = int(face) * int(n) + int(cell.x), x1 = int(face) * int(n) + int(c1.x);
    int y0 = int(cell.y), y1 = int(c1.y);
    vec2 o0 = cell - g, o1 = c1 - g;
    vec3 light = star_cell(ivec2(x0, y0), o0, li, q)
               + once.x * star_cell(ivec2(x1, y0), vec2(o1.x, o0.y), li, q)
               + once.y * (star_cell(ivec2(x0, y1), vec2(o0.x, o1.y), li, q)
                           + once.x * star_cell(ivec2(x1, y1), o1, li, q));
    vec3 stars = light * (P.sky.star_flux / (6.2831853 * STAR_SIGMA * STAR_SIGMA * area));
    float cos_l = d.x * inversesqrt(max(dot(d.xy, d.xy), 1e-12));
    float toward_centre = 0.5 + 0.5 * cos_l;
    float width = 0.07 + 0.08 * toward_centre * toward_centre;
    // exp(-z^2 / (2 width^2)) by soft_profile.
    float fall = soft_profile((1.0 / 32.0) * d.z * d.z / (width * width));
    float band = fall * (0.35 + 0.65 * toward_centre * toward_centre);
    vec3 galaxy = vec3(0.9, 0.85, 0.75) * (P.sky.galaxy * band);
    return (stars + galaxy) * P.sky.brightness;
}

// An equirectangular panorama (src/sky.rs for the convention), sampled with
// the mip level of the pixel's footprint (its longest axis, lensing
// included) over the angle of one panorama texel at the equator.
vec3 sky_image(vec3 d, float pixel_angle) {
    float u = 0.5 + atan(d.z, d.x) * (1.0 / 6.2831853);
    float v = acos(clamp(d.y, -1.0, 1.0)) * (1.0 / 3.14159265);
    float texel = 6.2831853 / max(P.sky.scale, 1.0);
    float lod = max(log2(max(pixel_angle / texel, 1e-6)), 0.0);
    return textureLod(sky_tex, vec2(u, v), lod).rgb * P.sky.brightness;
}

// The grid plane behind the hole: a finite square of lines that
// escaping rays reach along their final straight line (the path is straight
// to well under a pixel out there), drawn over the sky.
void grid_plane(vec3 p, vec3 d, float pixel_angle, inout vec3 color) {
    if (!GRID_PLANE) return;
    vec3 n = P.plane.normal;
    float dn = dot(d, n);
    if (dn >= -1e-6) return;                         // moving away from its face
    float t = dot(P.plane.position - p, n) / dn;
    vec3 q = p + t * d;
    if (dot(q - P.metric.holes[0].xyz, d) <= 0.0) return;   // behind the outgoing ray
    vec3 rel = q - P.plane.position;
    vec3 v_axis = cross(n, P.plane.axis);
    vec2 uv = vec2(dot(rel, P.plane.axis), dot(rel, v_axis));
    if (any(greaterThan(abs(uv), vec2(P.plane.half_size)))) return;
    vec2 cell = uv / P.plane.spacing;
    vec2 dist = abs(cell - round(cell));             // 0 on a line
    // Filter the lines by the pixel's footprint on the plane (in cells,
    // unlensed): soft edges as wide as a pixel, and the mean coverage once
    // the cells shrink below a few pixels, instead of moire.
    const float HALF_WIDTH = 0.04;
    float fp = pixel_angle * t / (abs(dn) * P.plane.spacing);
    float aa = max(0.5 * fp, 0.01);
    vec2 cover = 1.0 - smoothstep(HALF_WIDTH - aa, HALF_WIDTH + aa, dist);
    float line = max(cover.x, cover.y);
    float mean = 1.0 - (1.0 - 2.0 * HALF_WIDTH) * (1.0 - 2.0 * HALF_WIDTH);
    line = mix(line, mean, smoothstep(0.25, 0.75, fp));
    vec3 base = vec3(0.02, 0.025, 0.04);
    color = mix(base, vec3(0.9, 0.75, 0.35), line);
}

// The sky seen by an escaped ray whose pixel covers footprint f.
vec3 sky_color(vec3 d, Footprint f) {
    const int kind = SKY_KIND;
    if (kind == SKY_IMAGE) return sky_image(d, footprint_size(f));
    if (kind == SKY_CHECKER) return sky_checker(d);
    if (kind == SKY_STARS) return sky_stars(d, footprint_size(f));
    if (kind == SKY_CATALOGUE) return sky_catalogue(d, f);
    return vec3(0.0);
}

#endif
