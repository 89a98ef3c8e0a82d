// Pictures side by side along x (the polarized disk's field models): of n
// tiles in an image w pixels wide, tile t covers columns t w / n to
// (t + 1) w / n (integer division; src/scene/polarization.rs's
// picture_columns is the same on the host). The ray march (polarization.glsl)
// and the picture's passes (pol_picture.glsl) ask this one function.

#ifndef TILES_GLSL
#define TILES_GLSL

// The tile holding column c.
uint tile_index(uint c, uint n, uint w) {
    uint t = min(c * n / w, n - 1u);
    while (t > 0u && t * w / n > c) --t;
    while (t + 1u < n && (t + 1u) * w / n <= c) ++t;
    return t;
}

#endif
