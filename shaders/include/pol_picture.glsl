// What the polarized picture's passes share (pol_ticks.comp, pol_map.comp):
// their push constants, the (blurred) Stokes image and where in it an output
// pixel's Stokes parameters lie.

#include "tiles.glsl"

layout(binding = 0) uniform sampler2D stokes;
layout(std430, binding = 2) readonly buffer Peak {
    vec4 peak;   // max I, max P (pol_peak.comp)
} scale;

#define VIEW_INTENSITY 0
#define VIEW_POLARIZED 1
#define VIEW_FRACTION 2

#define SCALE_LINEAR 0
#define SCALE_SQRT 1
#define SCALE_LOG 2

layout(push_constant) uniform Push {
    uvec2 out_size;     // the picture written
    uvec2 src_size;     // the ray march's size
    uint tiles;         // pictures side by side along x
    uint step;          // the blurred grid's step, ray-march pixels
    uint tile_texels;   // blurred texels of one tile along x (0: the ray march's own image)
    uint view;          // VIEW_*
    uint map;           // CMAP_*
    uint brightness;    // SCALE_*: how I (or P) is mapped to the colour map
    uint cells;         // tick cells of one tile along x
    float spacing;      // ticks' grid, output pixels (0: no ticks)
    float cut;          // no tick below this share of the brightest I
    float fraction;     // the top of the fraction's scale
    float beam;         // the beam's FWHM, output pixels (0: none)
} pc;

// Tile t's start along x, ray-march pixels (as polarization.glsl's pol_tile).
float tile_start(uint t) {
    return float(t * pc.src_size.x / pc.tiles);
}

// The tile of ray-march column x.
uint tile_at(float x) {
    return tile_index(uint(max(x, 0.0)), pc.tiles, pc.src_size.x);
}

// The tile of output position x, and its range in output pixels.
uint tile_of(float x, out float x0, out float x1) {
    float ox = float(pc.out_size.x) / float(pc.src_size.x);
    uint t = tile_at(x / ox);
    x0 = tile_start(t) * ox;
    x1 = tile_start(t + 1u) * ox;
    return t;
}

// The (blurred) Stokes parameters at output position p (pixels, continuous).
vec4 stokes_at(vec2 p) {
    // One picture, unblurred, at the ray march's size: its own texels.
    if (pc.tiles == 1u && pc.tile_texels == 0u && pc.out_size == pc.src_size) {
        return texelFetch(stokes, ivec2(p), 0);
    }
    vec2 s = p * vec2(pc.src_size) / vec2(pc.out_size);
    uint t = tile_at(s.x);
    float x0 = tile_start(t), x1 = tile_start(t + 1u);
    vec2 c;
    if (pc.tile_texels == 0u) {
        c = vec2(clamp(s.x, x0 + 0.5, x1 - 0.5), s.y);
    } else {
        float base = float(t * pc.tile_texels);
        c = vec2(clamp(base + (s.x - x0) / float(pc.step), base + 0.5,
                       base + float(pc.tile_texels) - 0.5),
                 s.y / float(pc.step));
    }
    return textureLod(stokes, c / vec2(textureSize(stokes, 0)), 0.0);
}
