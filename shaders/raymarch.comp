#version 460
// Ray march: one invocation per pixel. Each camera ray follows its light
// path (metric.glsl, one metric per build: a non-rotating hole's closed
// form, lightpath.glsl; a spinning hole's closed form in Mino time,
// kerr/, outside, in the ergoregion and between the horizons; a straight
// line with gravity off; else the integrator of geodesic.glsl for several
// holes) until it falls into a horizon, hits the disk or escapes to the
// sky. Writes linear HDR, the polarized picture's Stokes parameters
// (POL_VIEW), or the geodesic or Stokes AOV.
//
// On a CPU driver, which runs every branch for every pixel, the work of one
// hole may be split in two dispatches (SPLIT_STAGE; src/deferred.rs says
// when): a trace pass over every pixel and a deferred pass, dispatched
// indirectly over the pixels the trace pass lists, for the rare, expensive
// paths. A non-rotating hole defers its thin disk: the trace pass shades
// every pixel's sky and lists the pixels whose path crosses the disk's
// annulus; the disk pass adds the disk in front, so the disk's cost stays
// with the pixels that show it. The spinning hole defers by its paths
// (METRIC_SPLITS_RARE): the trace pass carries the common ones and lists
// the 2x2 quads where a path needs the rest; the second pass redoes those
// quads whole, ray differentials and all.

#if !defined(GEODESIC_AOV) && !defined(NO_QUAD)
// Ray differentials from 2x2 quads of pixels (see main).
#extension GL_KHR_shader_subgroup_quad : require
#define RAY_DIFFERENTIALS
#endif
#ifdef SPLIT_PASSES
// The build of the split stages (raymarch_split.comp.spv): the deferred
// pass's work list, appended a SIMD group at a time (subgroup ballots). The
// other builds do not declare its buffers, so no pipeline that leaves them
// alone touches them.
#extension GL_KHR_shader_subgroup_ballot : require
#endif

layout(local_size_x = 8, local_size_y = 8) in;

#include "bindings.glsl"
#include "color.glsl"
#include "params.glsl"
#include "variant.glsl"
#include "ray_state.glsl"
#include "camera.glsl"
#include "sky.glsl"
#include "hit.glsl"
#include "metric.glsl"

#ifdef GEODESIC_AOV
// The geodesic AOV (docs/physics.md, "The geodesic AOV"): where each ray went.
layout(binding = RM_OUT_IMAGE, rgba32f) uniform writeonly image2D out_img;
#else
// Read back by the disk pass (the light behind the disk).
layout(binding = RM_OUT_IMAGE, rgba16f) uniform image2D out_img;
#endif
#ifdef SPLIT_PASSES
// The deferred pass's work: pixels packed x | y << 16, and their count.
layout(std430, binding = RM_DEFERRED_LIST) buffer DeferredList {
    uint count;
    uint px[];
} deferred_list;
// Its indirect dispatch: workgroups of 64 listed pixels, in rows of at most
// DEFERRED_ROW workgroups (a device may allow as few as 65,535 a side, and
// a 4K frame can list more groups of 64 than that; short rows also make
// every frame of 720p and up use several, so the tests see them).
#define DEFERRED_ROW 256u
layout(std430, binding = RM_DEFERRED_DISPATCH) buffer DeferredDispatch {
    uint groups_x;
    uint groups_y;
    uint groups_z;
} deferred_dispatch;
#endif

// The ray's Stokes vector: a thin-disk hit's, or the volumetric disk's sum
// along the ray (pol_volume, polarization.glsl), zeros elsewhere.
vec4 ray_stokes(Hit hit) {
    if (volumetric()) return pol_volume;
    return hit.outcome == OUT_DISK ? pol_stokes(hit.pol, hit.g) : vec4(0.0);
}

// Whether the ray has a Stokes vector to draw.
bool ray_polarized(Hit hit) {
    return hit.outcome == OUT_DISK || volumetric();
}

#ifndef GEODESIC_AOV
// The polarized picture (POL_VIEW): the ray march writes the Stokes
// parameters I, Q, U of a disk hit (as the Stokes AOV does, in a half-float
// image: the picture's passes draw them) in place of its light; the sky is
// dark (storable_signed: Q and U are signed).
vec4 picture_stokes(Hit hit) {
    return vec4(storable_signed(ray_stokes(hit).xyz), 1.0);
}
#endif

#ifdef SPLIT_PASSES
// The trace pass: lists this SIMD group's pixels that need the deferred pass
// (one atomic per group; the dispatch grows to cover the list). Whole quads
// (a need the same in all four lanes) stay four consecutive entries from a
// multiple of four, so a listed quad is a subgroup quad again there.
void list_deferred(uvec2 px, bool need) {
    uvec4 ballot = subgroupBallot(need);
    uint n = subgroupBallotBitCount(ballot);
    uint base = 0u;
    if (subgroupElect() && n > 0u) {
        base = atomicAdd(deferred_list.count, n);
        // Both sides grow with the count, so the largest count wins both.
        uint groups = (base + n + 63u) / 64u;
        atomicMax(deferred_dispatch.groups_x, min(groups, DEFERRED_ROW));
        atomicMax(deferred_dispatch.groups_y, (groups + DEFERRED_ROW - 1u) / DEFERRED_ROW);
    }
    base = subgroupBroadcastFirst(base);
    if (need) deferred_list.px[base + subgroupBallotExclusiveBitCount(ballot)] = px.x | (px.y << 16u);
}

// The disk pass: one listed pixel per invocation. Its path again (the same
// closed form), now with the thin disk's crossings, in front of what the
// trace pass wrote (the sky, or black where the ray is captured); an opaque
// disk hides it.
void disk_pass() {
    uint i = (gl_WorkGroupID.y * DEFERRED_ROW + gl_WorkGroupID.x) * 64u + gl_LocalInvocationIndex;
    if (i >= deferred_list.count) return;
    uint packed = deferred_list.px[i];
    ivec2 px = ivec2(packed & 0xffffu, packed >> 16u);
    PixelRay ray = camera_ray(POLARIZATION == POL_VIEW ? pol_tile(uvec2(px)) : uvec2(px));
    Hit hit = metric_trace(ray.origin, ray.dir);
    if (POLARIZATION == POL_VIEW) {
        // The polarized picture's Stokes parameters where the disk is hit
        // (the trace pass left zeros).
        hit.g *= observer_g;
        if (ray_polarized(hit)) imageStore(out_img, px, picture_stokes(hit));
        return;
    }
    vec3 behind = hit.trans < 0.003 ? vec3(0.0) : imageLoad(out_img, px).rgb;
    imageStore(out_img, px, vec4(storable(hit.glow + hit.trans * behind), 1.0));
}
#endif

#ifdef GEODESIC_AOV
// The geodesic AOV's record of the path (its outcome in alpha).
vec4 path_record(Hit hit) {
    vec4 aov = vec4(0.0, 0.0, 0.0, float(hit.outcome));
    if (hit.outcome == OUT_ESCAPED) {
        aov.xyz = hit.dir;
    } else if (hit.outcome == OUT_DISK) {
        vec3 d = hit.pos - P.metric.holes[0].xyz;
        aov.x = metric_disk_radius(hit.pos);
        aov.y = atan(dot(d, P.disk.e2), dot(d, P.disk.e1));
        aov.z = hit.g;
    }
    return aov;
}
#endif

#ifndef GEODESIC_AOV
// The colour the path brings back: the sky (and the grid plane) where it
// escaped, the disk where it stopped at it, under what it gathered on the
// way (glow, transmittance).
vec3 path_color(Hit hit, Footprint fp, float pixel_angle) {
    vec3 color = vec3(0.0);
    // (The other universe's sky, [sky] other_universe = "mirror", is a copy
    // of ours without the grid plane.)
    if (hit.outcome == OUT_ESCAPED || hit.far_sky) {
        color = sky_color(hit.dir, fp);
        if (!hit.far_sky) grid_plane(hit.pos, hit.dir, pixel_angle, color);
        // Light from rest at infinity, as the camera sees it: brightness
        // by g^4, colour as 6500 K blackbody light's (the switch sky_shift).
        if (P.sky.shift > 0.5) {
            float g = observer_g * kerr_zamo_g, g2 = g * g;
            color *= (g2 * g2) * blackbody(6500.0 * g) / blackbody(6500.0);
        }
    }
    else if (!METRIC_SHADES_DISK && hit.outcome == OUT_DISK) {
        // The disk where the path stopped at it (several holes, gravity
        // off): opaque. (The closed-form path adds the disk's light as it
        // goes.)
        float r = metric_disk_radius(hit.pos);
        // (Seen as it was when its light left: the spinning hole's path
        // sets the delay; the others here have none.)
        float t = P.disk.rotation_time - (LIGHT_DELAY ? P.disk.speed * hit.delay : 0.0);
        float dens = THIN_STRUCTURE ? thin_disk_density(r, disk_azimuth(hit.pos), t) : 1.0;
        color = dens * disk_color(r, hit.g);
    }
    return hit.glow + hit.trans * color;
}
#endif

void main() {
    read_params();  // first, outside any branch (params.glsl)
#ifdef SPLIT_PASSES
    if (!METRIC_SPLITS_RARE && SPLIT_STAGE == STAGE_DEFERRED) {
        disk_pass();
        return;
    }
#endif
    uint w = P.camera.size.x, hgt = P.camera.size.y;
#ifdef RAY_DIFFERENTIALS
    // The 64 invocations of a group cover its 8x8 tile in 2x2 quads
    // (subgroup quads are four consecutive invocations), so each pixel can
    // read its right or left and its lower or upper neighbour's final
    // direction. Lanes past the image's edge trace a clamped pixel for their
    // quad and store nothing.
    uint li = gl_LocalInvocationIndex;
    uint quad = li >> 2u;
    uvec2 in_quad = uvec2(li & 1u, (li >> 1u) & 1u);
    uvec2 px_raw = gl_WorkGroupID.xy * 8u + 2u * uvec2(quad & 3u, quad >> 2u) + in_quad;
    bool listed = true;
#ifdef SPLIT_PASSES
    if (METRIC_SPLITS_RARE && SPLIT_STAGE == STAGE_DEFERRED) {
        // The second pass of a split by paths: the listed quads, four
        // consecutive invocations each (lanes past the list's end trace a
        // pixel and store nothing).
        uint i = (gl_WorkGroupID.y * DEFERRED_ROW + gl_WorkGroupID.x) * 64u + li;
        listed = i < deferred_list.count;
        uint packed = deferred_list.px[min(i, deferred_list.count - 1u)];
        px_raw = uvec2(packed & 0xffffu, packed >> 16u);
    }
#endif
    bool inside = listed && px_raw.x < w && px_raw.y < hgt;
    uvec2 px = min(px_raw, uvec2(w - 1u, hgt - 1u));
#else
    uvec2 px = gl_GlobalInvocationID.xy;
    if (px.x >= w || px.y >= hgt) return;
#endif

    // (Field models side by side: each tile is an image of its own.)
    PixelRay ray = camera_ray(POLARIZATION != POL_OFF ? pol_tile(px) : px);

    // The volume's sample offset: per pixel, and per accumulated frame (salted
    // by the sub-pixel jitter, zero for a single offscreen frame) so the
    // window's accumulation averages the grain away.
    volume_jitter = hash33(uvec3(px, 7u + floatBitsToUint(P.camera.jitter_x) + 3u * floatBitsToUint(P.camera.jitter_y))).x;
    // A pixel with no ray (outside a fisheye's circle) traces nothing, but
    // stays in its quad for the neighbours' differences.
    Hit hit = hit_start(OUT_NO_RAY, ray.origin, ray.dir);
    if (ray.valid) hit = metric_trace(ray.origin, ray.dir);
    hit.g *= observer_g;
#ifdef GEODESIC_AOV
    // The Stokes AOV (POL_STOKES): I, Q, U, V of a disk hit, zeros elsewhere.
    imageStore(out_img, ivec2(px), POLARIZATION == POL_STOKES ? ray_stokes(hit) : path_record(hit));
#else
    float pixel_angle = ray.angle;
    // The pixel's footprint on the sky: the change of the final direction
    // from one pixel to the next, across and down. Unlensed, pixel_angle in
    // two directions at right angles to it. (Here, not in a function of its
    // own: with these quad operations in a called function, the split's
    // trace pass listed almost no pixels on lavapipe, Mesa 22.3.)
    vec3 t1 = normalize(cross(hit.dir, abs(hit.dir.y) < 0.9 ? vec3(0.0, 1.0, 0.0) : vec3(1.0, 0.0, 0.0)));
    Footprint fp = Footprint(pixel_angle * t1, pixel_angle * cross(hit.dir, t1), pixel_angle);
#ifdef RAY_DIFFERENTIALS
    // Lensed: from the quad's neighbours (one-sided differences), where the
    // neighbour escaped too and its direction is near (not across the
    // shadow's edge or the photon ring's discontinuities).
    bool escaped = hit.outcome == OUT_ESCAPED;
    vec3 dh = subgroupQuadSwapHorizontal(hit.dir);
    vec3 dv = subgroupQuadSwapVertical(hit.dir);
    bool eh = subgroupQuadSwapHorizontal(escaped);
    bool ev = subgroupQuadSwapVertical(escaped);
    vec3 ax = (dh - hit.dir) * (in_quad.x == 0u ? 1.0 : -1.0);
    vec3 ay = (dv - hit.dir) * (in_quad.y == 0u ? 1.0 : -1.0);
    // Past the image's edge a neighbour is the clamped pixel itself (no
    // difference): not a footprint either.
    const float NEAR = 0.3;
    float tiny = 1e-3 * pixel_angle;
    float lx = length(ax), ly = length(ay);
    bool okx = eh && lx < NEAR && lx > tiny, oky = ev && ly < NEAR && ly > tiny;
    // With one neighbour's difference only, the other axis is the unlensed
    // pixel angle at right angles to it (one cross product for either case:
    // on a CPU driver both branches would run).
    vec3 known = okx ? ax : ay;
    vec3 across = (pixel_angle * (okx ? 1.0 : -1.0)) * normalize(cross(hit.dir, known + 1e-12 * t1));
    if (okx || oky) {
        fp.x = okx ? ax : across;
        fp.y = oky ? ay : across;
    }
#endif
    vec4 value;
    if (POLARIZATION == POL_VIEW) {
        value = ray_polarized(hit) ? picture_stokes(hit) : vec4(0.0, 0.0, 0.0, 1.0);
    } else {
        value = vec4(storable(path_color(hit, fp, pixel_angle)), 1.0);
    }
#ifdef SPLIT_PASSES
    if (METRIC_SPLITS_RARE) {
        // The whole quad if any of its lanes was deferred and one lies in
        // the image (its lanes past the edge listed too, storing nothing).
        bool q = hit.deferred;
        q = q || subgroupQuadSwapHorizontal(q);
        q = q || subgroupQuadSwapVertical(q);
        bool any_inside = inside || subgroupQuadSwapHorizontal(inside);
        any_inside = any_inside || subgroupQuadSwapVertical(any_inside);
        if (SPLIT_STAGE == STAGE_TRACE) list_deferred(px_raw, q && any_inside);
    } else if (SPLIT_STAGE == STAGE_TRACE) {
        list_deferred(px, hit.deferred && inside && ray.valid);
    }
#endif
#ifdef RAY_DIFFERENTIALS
    if (!inside) return;
#endif
    // No ray: black and transparent (alpha 0 reaches the PNG and the EXR).
    imageStore(out_img, ivec2(px), ray.valid ? value : vec4(0.0));
#endif
}
