// Colour maps of the polarized picture, in sRGB (stored as they are into
// the 8-bit UNORM image, as the composite stores its encoded values).
// Inferno (matplotlib's, van der Walt and Smith 2015: perceptually uniform):
// its 256 entries as four quintic pieces fitted by least squares (within
// 2.2 8-bit steps of the table everywhere). Pieces picked by selects, not a
// table indexed at run time: a CPU driver copies a constant array into
// every invocation's memory, which cost the picture's pass 4 ms a 640x360
// frame on lavapipe. Afmhot (matplotlib's, as the EHT draws M87*): three
// ramps. The ticks' scale: blue through cyan to pale green, apart from both.

#define CMAP_INFERNO 0
#define CMAP_AFMHOT 1

// Piece k's coefficient of u^j: the j-th vec3 of the four given.
vec3 inferno_pick(float k, vec3 c0, vec3 c1, vec3 c2, vec3 c3) {
    return k < 1.0 ? c0 : k < 2.0 ? c1 : k < 3.0 ? c2 : c3;
}

vec3 inferno(float x) {
    float f = clamp(x, 0.0, 1.0) * 4.0;
    float k = min(floor(f), 3.0), u = f - k;
    // Pieces [0, 1/4], [1/4, 1/2], [1/2, 3/4], [3/4, 1]; u in [0, 1] on each.
    vec3 a0 = inferno_pick(k, vec3(0.00133484, 0.003858883, 0.007355747), vec3(0.3388007, 0.06129273, 0.4290628),
                           vec3(0.7330984, 0.2145116, 0.3315742), vec3(0.978244, 0.5542706, 0.04258035));
    vec3 a1 = inferno_pick(k, vec3(0.02542504, -0.1029907, 0.4787383), vec3(0.3950238, 0.1453425, 0.05539007),
                           vec3(0.3635594, 0.1976902, -0.2166227), vec3(0.07358627, 0.4586468, -0.5263981));
    vec3 a2 = inferno_pick(k, vec3(0.5697981, 1.613681, -0.1292291), vec3(0.01758368, 0.03671485, -0.2039711),
                           vec3(-0.03273247, 0.1385472, -0.2266059), vec3(-0.1402004, 0.02306258, 3.836777));
    vec3 a3 = inferno_pick(k, vec3(-0.1837107, -4.124355, 1.774373), vec3(-0.04496572, -0.1497943, 0.1385808),
                           vec3(-0.1578121, 0.03704791, 0.4165114), vec3(0.1252993, 0.06258454, -7.350786));
    vec3 a4 = inferno_pick(k, vec3(-0.1368504, 3.905561, -3.080322), vec3(0.06234134, 0.1750674, -0.1436088),
                           vec3(0.09914812, -0.03013964, -0.4545451), vec3(-0.6116935, -0.007393266, 7.526811));
    vec3 a5 = inferno_pick(k, vec3(0.06143241, -1.232264, 1.379092), vec3(-0.03629935, -0.05448554, 0.05680226),
                           vec3(-0.02760689, -0.003735032, 0.1861521), vec3(0.5692306, -0.09247249, -2.878243));
    vec3 c = a0 + u * (a1 + u * (a2 + u * (a3 + u * (a4 + u * a5))));
    return clamp(c, 0.0, 1.0);
}

vec3 afmhot(float x) {
    float t = 2.0 * clamp(x, 0.0, 1.0);
    return clamp(vec3(t, t - 0.5, t - 1.0), 0.0, 1.0);
}

vec3 colormap(uint map, float x) {
    if (map == CMAP_AFMHOT) return afmhot(x);
    return inferno(x);
}

// The ticks' colour for a fraction x in [0, 1] of the scale's top.
vec3 tick_color(float x) {
    float t = clamp(x, 0.0, 1.0);
    vec3 lo = vec3(0.15, 0.3, 1.0), mid = vec3(0.1, 0.9, 0.95), hi = vec3(0.85, 1.0, 0.8);
    return t < 0.5 ? mix(lo, mid, 2.0 * t) : mix(mid, hi, 2.0 * t - 1.0);
}
