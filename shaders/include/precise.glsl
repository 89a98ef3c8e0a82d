// Elementary functions to full f32 precision where a driver's are coarser
// or dearer: cos and sin with a two-part reduction, asin, asinh, sin on
// [0, pi/3], and the Estrin polynomial they share. Used by the closed-form
// light paths of both kinds of hole.
#ifndef PRECISE_GLSL
#define PRECISE_GLSL

// The polynomials below are evaluated by Estrin's scheme: pairs of terms
// combined by t^2, t^4, t^8, a tree a few products deep instead of Horner's
// chain of one multiply-add per term. A CPU driver runs a SIMD group's lanes
// in lock step, each step waiting on the last, so the chain's length, not
// its count of operations, is what a polynomial costs there.
// c[0] + c[1] t + ... + c[11] t^11.
float poly12(float t, const float c[12]) {
    float t2 = t * t, t4 = t2 * t2, t8 = t4 * t4;
    float p01 = c[0] + c[1] * t, p23 = c[2] + c[3] * t, p45 = c[4] + c[5] * t;
    float p67 = c[6] + c[7] * t, p89 = c[8] + c[9] * t, pab = c[10] + c[11] * t;
    return (p01 + p23 * t2) + t4 * (p45 + p67 * t2) + t8 * (p89 + pab * t2);
}

// cos and sin of x to full f32 precision: the angle reduced by pi/2 with
// a two-part constant, then Taylor polynomials on [-pi/4, pi/4].
vec2 cos_sin_precise(float x) {
    float q = round(x * 0.6366197723675814);
    float r = (x - q * 1.5707963705062866) + q * 4.371139000186243e-8;
    float r2 = r * r, r4 = r2 * r2, r8 = r4 * r4;
    // (Estrin's scheme, see poly12.)
    float s = r * ((1.0 - r2 * (1.0 / 6.0)) + r4 * ((1.0 / 120.0 - r2 * (1.0 / 5040.0)) + r4 * (1.0 / 362880.0)));
    float c = (1.0 - 0.5 * r2) + r4 * (1.0 / 24.0 - r2 * (1.0 / 720.0))
            + r8 * (1.0 / 40320.0 - r2 * (1.0 / 3628800.0));
    int k = int(q) & 3;
    if (k == 0) return vec2(c, s);
    if (k == 1) return vec2(-s, c);
    if (k == 2) return vec2(-c, -s);
    return vec2(s, -c);
}

// Inverse and hyperbolic functions to full f32 precision. Vulkan lets a
// driver's asin, asinh and sinh be far coarser (asin inherits atan's 4096
// ulp; asinh and sinh built from log and exp cancel near 0), and lavapipe's
// are: a 1e-4 error in asin moved disk points by 1e-2 rs. (sinh: by its
// series near 0, in light_path.)
float asin_precise(float x) {
    float ax = abs(x);
    bool big = ax > 0.5;
    // asin(x) = pi/2 - 2 asin(sqrt((1 - x) / 2)) above 0.5.
    float y = big ? sqrt(0.5 * (1.0 - ax)) : ax;
    float y2 = y * y;
    // Maclaurin series of asin to y^23: below 1e-9 relative for |y| <= 0.5.
    const float C[12] = float[12](1.0, 1.0 / 6.0, 3.0 / 40.0, 5.0 / 112.0, 35.0 / 1152.0,
        63.0 / 2816.0, 231.0 / 13312.0, 143.0 / 10240.0, 6435.0 / 557056.0,
        12155.0 / 1245184.0, 46189.0 / 5505024.0, 88179.0 / 12058624.0);
    float r = y * poly12(y2, C);
    if (big) r = 1.5707963267948966 - 2.0 * r;
    return x < 0.0 ? -r : r;
}

// atan2(y, x) to full f32 precision, by asin_precise of the smaller of
// the sine and cosine (at most 1/sqrt(2), where its series converges
// fastest): the driver's atan is good to 4096 ulp only.
float atan2_precise(float y, float x) {
    float ih = inversesqrt(max(x * x + y * y, 1e-37));
    float s = abs(y) * ih, c = abs(x) * ih;
    float a = s <= c ? asin_precise(s) : 1.5707963267948966 - asin_precise(c);
    if (x < 0.0) a = 3.141592653589793 - a;
    return y < 0.0 ? -a : a;
}

// sin x for x in [0, pi/3] by its Taylor series to x^13 (error below 2e-9):
// no range reduction, which a driver's sin does for any argument.
float sin_third(float x) {
    float x2 = x * x, x4 = x2 * x2, x8 = x4 * x4;
    return x * ((1.0 - x2 * (1.0 / 6.0)) + x4 * (1.0 / 120.0 - x2 * (1.0 / 5040.0))
              + x8 * ((1.0 / 362880.0 - x2 * (1.0 / 39916800.0)) + x4 * (1.0 / 6227020800.0)));
}

float asinh_precise(float x) {
    if (abs(x) < 0.25) {
        float x2 = x * x;
        return x * (1.0 - x2 * (1.0 / 6.0 - x2 * (3.0 / 40.0 - x2 * (15.0 / 336.0 - x2 * (105.0 / 3456.0)))));
    }
    return log(x + sqrt(x * x + 1.0));
}

#endif
