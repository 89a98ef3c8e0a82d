#version 460
// The polarized picture (docs/polarization.md, "The picture"): the (blurred)
// Stokes image drawn as the EHT draws its figures. A colour map of Stokes I
// (or of P, or of the fraction m = P / I) on the picture's own scale (its
// brightest pixel; linear, square root or logarithmic), and over it the
// ticks of pol_ticks.comp with a dark halo, coloured by the fraction, whose
// scale is a bar at the right edge (0 at the bottom to the emitted fraction
// at the top, a mark every tenth), and the beam's FWHM as a circle at each
// picture's lower left.

layout(local_size_x = 8, local_size_y = 8) in;

#include "colormap.glsl"
#include "pol_picture.glsl"

layout(binding = 1, rgba8) uniform writeonly image2D ldr;
layout(binding = 3, rgba32f) uniform readonly image2D tick_img;

// Distance from p to the segment q - e .. q + e.
float segment_distance(vec2 p, vec2 q, vec2 e) {
    float ee = dot(e, e);
    float k = ee > 0.0 ? clamp(dot(p - q, e) / ee, -1.0, 1.0) : 0.0;
    return length(p - q - k * e);
}

// The brightness v in [0, 1] on the picture's scale.
float brightness(float v) {
    v = clamp(v, 0.0, 1.0);
    if (pc.brightness == SCALE_SQRT) return sqrt(v);
    // Three decades below the peak.
    if (pc.brightness == SCALE_LOG) return v > 1e-3 ? 1.0 + log(v) / log(1e3) : 0.0;
    return v;
}

// The ticks' colour over c at p (tile from x0), from the 2x2 cells nearest p
// (a tick reaches at most 0.6 spacing and its width from its centre).
vec3 draw_ticks(vec3 c, vec2 p, uint t, float x0) {
    float s = pc.spacing;
    vec2 local = (p - vec2(x0, 0.0)) / s - 0.5;
    ivec2 first = ivec2(floor(local));
    float width = max(1.2, 0.12 * s);
    float halo = 0.0, cover = 0.0;
    vec3 col = vec3(0.0);
    ivec2 n = imageSize(tick_img);
    for (int k = 0; k < 4; ++k) {
        ivec2 cell = first + ivec2(k & 1, k >> 1);
        if (cell.x < 0 || cell.y < 0 || cell.x >= int(pc.cells) || cell.y >= n.y) continue;
        vec4 tick = imageLoad(tick_img, ivec2(int(t * pc.cells) + cell.x, cell.y));
        if (tick.w == 0.0) continue;
        vec2 q = vec2(x0, 0.0) + (vec2(cell) + 0.5) * s;
        float d = segment_distance(p, q, tick.xy);
        halo = max(halo, clamp(0.5 * width + 1.5 - d, 0.0, 1.0));
        float a = clamp(0.5 * width + 0.5 - d, 0.0, 1.0);
        if (a > cover) {
            cover = a;
            col = pc.view == VIEW_FRACTION ? vec3(1.0) : tick_color(tick.z);
        }
    }
    c = mix(c, vec3(0.0), 0.6 * halo);
    return mix(c, col, cover);
}

void main() {
    // The scale first, outside any branch: lavapipe reads a buffer at a
    // uniform address once for the SIMD group only there.
    vec4 peak = scale.peak;
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (px.x >= int(pc.out_size.x) || px.y >= int(pc.out_size.y)) return;
    vec2 p = vec2(px) + 0.5;
    vec4 st = stokes_at(p);
    float pol = length(st.yz);
    // (Branches on push constants, not selects: both sides of a select run.)
    float v;
    if (pc.view == VIEW_POLARIZED) {
        v = brightness(pol / max(peak.y, 1e-30));
    } else if (pc.view == VIEW_FRACTION) {
        v = st.x > pc.cut * peak.x && st.x > 0.0 ? pol / (st.x * max(pc.fraction, 1e-6)) : 0.0;
    } else {
        v = brightness(st.x / max(peak.x, 1e-30));
    }
    vec3 c = colormap(pc.map, v);
    float x0, x1;
    uint t = tile_of(p.x, x0, x1);
    if (pc.spacing > 0.0) c = draw_ticks(c, p, t, x0);
    if (pc.beam > 0.0) {
        float r = 0.5 * pc.beam, m = max(6.0, 0.03 * float(pc.out_size.y));
        vec2 centre = vec2(x0 + m + r, float(pc.out_size.y) - m - r);
        float ring = abs(length(p - centre) - r);
        c = mix(c, vec3(1.0), clamp(1.5 - ring, 0.0, 1.0));
    }
    // The fraction's scale at the right edge.
    float bw = max(4.0, 0.015 * float(pc.out_size.y));
    float bx = float(pc.out_size.x) - 2.0 * bw;
    float lo = 0.8 * float(pc.out_size.y), hi = 0.2 * float(pc.out_size.y);
    bool legend = pc.spacing > 0.0 || pc.view == VIEW_FRACTION;
    if (legend && p.x >= bx && p.x < bx + bw && p.y <= lo && p.y >= hi) {
        float f = (lo - p.y) / (lo - hi);
        c = pc.view == VIEW_FRACTION ? colormap(pc.map, f) : tick_color(f);
        float mark = abs(fract(f * 10.0 + 0.5) - 0.5) * (lo - hi) / 10.0;
        c = mix(c, vec3(0.0), 0.8 * clamp(1.0 - mark, 0.0, 1.0));
    }
    imageStore(ldr, px, vec4(c, 1.0));
}
