#version 460
// The telescope's beam (docs/polarization.md, "The picture"): a Gaussian
// blur of the Stokes image, one axis a dispatch, applied to I, Q and U alike
// (so the angle of the sum is drawn, and beam depolarization shows). Each
// output texel is the blurred image at its centre, on a grid `step` input
// pixels apart along the axis (a Gaussian of sigma >= 2 step varies little
// between grid points): the cost per input pixel stays the same at any beam.
// Outside the picture the sky is dark (zero Stokes), so flux is kept and the
// edge darkens as a telescope's would; side-by-side pictures (tiles along x)
// do not blur into one another.

layout(local_size_x = 8, local_size_y = 8) in;

// (Sampled, read texel by texel: the picture's half floats or the AOV's
// 32-bit ones alike.)
layout(binding = 0) uniform sampler2D src;
layout(binding = 1, rgba32f) uniform writeonly image2D dst;

layout(push_constant) uniform Push {
    uvec2 src_size;     // the image read
    uvec2 dst_size;     // the image written
    uint axis;          // 0: along x (tiles apply), 1: along y
    uint step;          // input pixels between output texels along the axis
    uint tiles;         // pictures side by side along x
    uint tile_texels;   // output texels of one tile along x (axis 0)
    float sigma;        // the beam's sigma, input pixels
    int radius;         // taps each side (about 3.5 sigma)
} pc;

void main() {
    ivec2 o = ivec2(gl_GlobalInvocationID.xy);
    if (o.x >= int(pc.dst_size.x) || o.y >= int(pc.dst_size.y)) return;
    // Along the axis: the input range this texel's picture covers, and the
    // texel's centre in input pixel coordinates.
    int lo = 0, hi = int(pc.axis == 0u ? pc.src_size.x : pc.src_size.y);
    float centre;
    if (pc.axis == 0u) {
        uint t = uint(o.x) / pc.tile_texels;
        uint local = uint(o.x) - t * pc.tile_texels;
        lo = int(t * pc.src_size.x / pc.tiles);
        hi = int((t + 1u) * pc.src_size.x / pc.tiles);
        centre = float(lo) + (float(local) + 0.5) * float(pc.step);
    } else {
        centre = (float(o.y) + 0.5) * float(pc.step);
    }
    int first = int(floor(centre)) - pc.radius, last = int(floor(centre)) + pc.radius;
    float inv = 1.0 / pc.sigma;
    vec4 sum = vec4(0.0);
    float total = 0.0;
    for (int i = first; i <= last; ++i) {
        float d = (float(i) + 0.5 - centre) * inv;
        float w = exp(-0.5 * d * d);
        total += w;
        if (i < lo || i >= hi) continue;
        ivec2 p = pc.axis == 0u ? ivec2(i, o.y) : ivec2(o.x, i);
        sum += w * texelFetch(src, p, 0);
    }
    imageStore(dst, o, sum / total);
}
