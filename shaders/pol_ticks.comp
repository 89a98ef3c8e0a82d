#version 460
// The polarized picture's ticks, one invocation a cell of the tick grid
// (each picture of a side-by-side set has its own, from its left edge): the
// tick at the cell's centre along the electric vector (chi east of north;
// on the image north is up and east to the left), its half-length 0.6
// spacing times P over the picture's largest P, coloured by the fraction
// m = P / I over the emitted fraction. No tick where Stokes I is below the
// cut (a share of the brightest I) or P is 0. pol_map.comp draws them.

layout(local_size_x = 8, local_size_y = 8) in;

#include "pol_picture.glsl"

layout(binding = 1, rgba32f) uniform writeonly image2D tick_img;   // half-extent xy, m, drawn

void main() {
    vec4 peak = scale.peak;   // outside any branch (see pol_map.comp)
    ivec2 c = ivec2(gl_GlobalInvocationID.xy);
    ivec2 n = imageSize(tick_img);
    if (c.x >= n.x || c.y >= n.y) return;
    uint t = uint(c.x) / pc.cells;
    float x0 = tile_start(t) * float(pc.out_size.x) / float(pc.src_size.x);
    float x1 = tile_start(t + 1u) * float(pc.out_size.x) / float(pc.src_size.x);
    vec2 q = vec2(x0 + (float(uint(c.x) - t * pc.cells) + 0.5) * pc.spacing,
                  (float(c.y) + 0.5) * pc.spacing);
    vec4 st = stokes_at(q);
    float pol = length(st.yz);
    bool drawn = q.x < x1 && q.y < float(pc.out_size.y) && st.x > pc.cut * peak.x
              && st.x > 0.0 && pol > 0.0 && peak.y > 0.0;
    float h = 0.6 * pc.spacing * pol / max(peak.y, 1e-30);
    float chi = 0.5 * atan(st.z, st.y);
    float m = pol / (max(st.x, 1e-30) * max(pc.fraction, 1e-6));
    imageStore(tick_img, c, drawn ? vec4(-h * sin(chi), -h * cos(chi), m, 1.0) : vec4(0.0));
}
