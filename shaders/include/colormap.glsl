// Colour maps of the polarized picture, in sRGB (stored as they are into
// the 8-bit UNORM image, as the composite stores its encoded values).
// Inferno (matplotlib's, van der Walt and Smith 2015: perceptually uniform):
// 33 of its entries, linearly interpolated (within 4 8-bit steps of the
// 256-entry table). Afmhot (matplotlib's, as the EHT draws M87*): three
// ramps. The ticks' scale: blue through cyan to pale green, apart from both.

#define CMAP_INFERNO 0
#define CMAP_AFMHOT 1

const vec3 INFERNO[33] = vec3[33](
    vec3(0.0015, 0.0005, 0.0139), vec3(0.0140, 0.0112, 0.0719), vec3(0.0423, 0.0281, 0.1411),
    vec3(0.0820, 0.0433, 0.2153), vec3(0.1293, 0.0473, 0.2908), vec3(0.1834, 0.0403, 0.3550),
    vec3(0.2383, 0.0366, 0.3964), vec3(0.2908, 0.0456, 0.4186), vec3(0.3415, 0.0623, 0.4294),
    vec3(0.3915, 0.0809, 0.4331), vec3(0.4412, 0.0993, 0.4316), vec3(0.4910, 0.1172, 0.4256),
    vec3(0.5409, 0.1347, 0.4151), vec3(0.5907, 0.1526, 0.4003), vec3(0.6401, 0.1714, 0.3811),
    vec3(0.6887, 0.1922, 0.3576), vec3(0.7357, 0.2159, 0.3302), vec3(0.7805, 0.2433, 0.2995),
    vec3(0.8224, 0.2752, 0.2661), vec3(0.8605, 0.3119, 0.2306), vec3(0.8943, 0.3534, 0.1936),
    vec3(0.9232, 0.3994, 0.1552), vec3(0.9470, 0.4492, 0.1153), vec3(0.9654, 0.5022, 0.0739),
    vec3(0.9784, 0.5579, 0.0349), vec3(0.9860, 0.6158, 0.0256), vec3(0.9879, 0.6753, 0.0653),
    vec3(0.9841, 0.7361, 0.1295), vec3(0.9746, 0.7977, 0.2063), vec3(0.9606, 0.8591, 0.2980),
    vec3(0.9476, 0.9174, 0.4107), vec3(0.9545, 0.9659, 0.5404), vec3(0.9884, 0.9984, 0.6449)
);

vec3 inferno(float x) {
    float f = clamp(x, 0.0, 1.0) * 32.0;
    int i = min(int(f), 31);
    return mix(INFERNO[i], INFERNO[i + 1], f - float(i));
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
