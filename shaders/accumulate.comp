#version 460
// Progressive refinement: while the view does not change, each frame's
// jittered ray-march result is folded into a running mean, so the image
// converges to an anti-aliased still (a box filter over the pixel). Sample n
// (0-based) has weight 1 / (n + 1); sample 0 overwrites whatever was there.

layout(local_size_x = 8, local_size_y = 8) in;

layout(binding = 0, rgba16f) uniform readonly image2D sample_img;
layout(binding = 1, rgba32f) uniform image2D mean_img;

layout(push_constant) uniform Push {
    uint width;
    uint height;
    float weight;   // 1 / (n + 1)
} pc;

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (px.x >= int(pc.width) || px.y >= int(pc.height)) return;
    vec4 s = imageLoad(sample_img, px);
    vec4 m = pc.weight >= 1.0 ? s : mix(imageLoad(mean_img, px), s, pc.weight);
    imageStore(mean_img, px, m);
}
