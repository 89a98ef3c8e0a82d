#version 460
// The polarized picture's scale: the brightest Stokes I and the largest
// polarized intensity P = |Q + iU| of the (blurred) Stokes image, found by one
// workgroup (each invocation strides over the texels, then a reduction in
// shared memory). Every picture of a side-by-side set shares them, so the
// field models compare on one scale.

layout(local_size_x = 256) in;

layout(binding = 0) uniform sampler2D stokes;
layout(std430, binding = 1) writeonly buffer Peak {
    vec4 peak;   // max I, max P, 0, 0
} result;

layout(push_constant) uniform Push {
    uvec2 size;
} pc;

shared vec2 best[256];

void main() {
    uint t = gl_LocalInvocationIndex;
    vec2 m = vec2(0.0);
    uint n = pc.size.x * pc.size.y;
    for (uint i = t; i < n; i += 256u) {
        vec4 s = texelFetch(stokes, ivec2(i % pc.size.x, i / pc.size.x), 0);
        m = max(m, vec2(s.x, length(s.yz)));
    }
    best[t] = m;
    barrier();
    for (uint half_n = 128u; half_n > 0u; half_n >>= 1u) {
        if (t < half_n) best[t] = max(best[t], best[t + half_n]);
        barrier();
    }
    if (t == 0u) result.peak = vec4(best[0], 0.0, 0.0);
}
