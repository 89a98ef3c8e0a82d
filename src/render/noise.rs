//! The disks' precomputed noise: a tileable 2-D texture for the thin disk's
//! filaments and a tileable 3-D volume for the volumetric disk's gas, both
//! built on the CPU (src/render/resources.rs uploads them) so the ray march
//! reads one filtered fetch instead of evaluating octaves of noise.

/// A 32-bit hash of a lattice point (x, y, z) of octave `o` (integer
/// multiply-xorshift rounds), shared by both noises.
fn lattice_hash(x: u32, y: u32, z: u32, o: u32) -> u32 {
    let mut v = x
        .wrapping_mul(0x8da6_b343)
        .wrapping_add(y.wrapping_mul(0xd816_3841))
        .wrapping_add(z.wrapping_mul(0xcb1a_b31f))
        .wrapping_add(o.wrapping_mul(0x1656_67b1));
    v ^= v >> 15;
    v = v.wrapping_mul(0x2c1b_3c6d);
    v ^= v >> 12;
    v = v.wrapping_mul(0x297a_2d39);
    v ^= v >> 15;
    v
}

/// Side of the thin disk's noise texture, texels.
pub const NOISE_SIZE: u32 = 256;

/// The thin disk's structure: tileable value noise, four octaves of a
/// periodic lattice (8, 16, 32, 64 cells across) with quintic smoothing,
/// as 8-bit texels (mean about 0.5). The ray march reads it in the
/// co-moving angle and log radius (disk.glsl, `thin_disk_density`):
/// one filtered fetch instead of octaves of procedural noise per pixel.
pub fn disk_noise() -> Vec<u8> {
    let n = NOISE_SIZE as usize;
    // The octave picks the third lattice coordinate (as it always has: the
    // goldens were drawn with these values).
    let hash = |x: u32, y: u32, o: u32| -> f32 {
        (lattice_hash(x, y, o, 0) >> 8) as f32 / (1u32 << 24) as f32
    };
    let smooth = |t: f32| t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
    let mut field = vec![0.0f32; n * n];
    let mut amp = 1.0f32;
    let mut total = 0.0f32;
    for (octave, cells) in [8u32, 16, 32, 64].into_iter().enumerate() {
        let step = n as f32 / cells as f32;
        for y in 0..n {
            for x in 0..n {
                let (fx, fy) = (x as f32 / step, y as f32 / step);
                let (x0, y0) = (fx.floor() as u32, fy.floor() as u32);
                let (tx, ty) = (smooth(fx.fract()), smooth(fy.fract()));
                let o = octave as u32;
                let at = |i: u32, j: u32| hash(i % cells, j % cells, o);
                let top = at(x0, y0) + tx * (at(x0 + 1, y0) - at(x0, y0));
                let bottom = at(x0, y0 + 1) + tx * (at(x0 + 1, y0 + 1) - at(x0, y0 + 1));
                field[y * n + x] += amp * (top + ty * (bottom - top));
            }
        }
        total += amp;
        amp *= 0.55;
    }
    field
        .iter()
        .map(|v| ((v / total).clamp(0.0, 1.0) * 255.0).round() as u8)
        .collect()
}

/// Texels of the noise volume along x, y (the disk's axis) and z.
pub const VOLUME_NOISE_SIZE: [u32; 3] = [128, 64, 128];

/// The noise volume's period in lattice units of its first octave. The ray
/// march reads it at 1.6 lattice units per noise unit (the shader's noise
/// coordinates: the disk frame scaled by `noise_scale`, height stretched
/// four times), so it repeats every 10 noise units across (12.5 rs at the
/// default scale; the Keplerian shear turns each radius by its own angle as
/// the disk turns) and every 5 along the axis (more than the whole slab at
/// the default height and scale).
pub const VOLUME_NOISE_PERIOD: [f64; 3] = [16.0, 8.0, 16.0];

/// The volumetric disk's noise: three octaves of periodic Perlin gradient
/// noise (lattice spacing 1, 1/2 and 1/4 noise units), one per channel
/// (r, g, b; a unused), each in [0, 1] around 0.5. The ray march reads the
/// volume with a repeating trilinear sampler and sums the channels it needs
/// (volume.glsl, `volume_density`): one fetch for three octaves instead of
/// three evaluations of simplex noise per sample, and a second fetch at
/// eight times the frequency for octaves four to six.
pub fn volume_noise() -> Vec<u8> {
    let [w, h, d] = VOLUME_NOISE_SIZE.map(|v| v as usize);
    // Perlin's twelve edge gradients.
    const G: [[f64; 3]; 12] = [
        [1.0, 1.0, 0.0],
        [-1.0, 1.0, 0.0],
        [1.0, -1.0, 0.0],
        [-1.0, -1.0, 0.0],
        [1.0, 0.0, 1.0],
        [-1.0, 0.0, 1.0],
        [1.0, 0.0, -1.0],
        [-1.0, 0.0, -1.0],
        [0.0, 1.0, 1.0],
        [0.0, -1.0, 1.0],
        [0.0, 1.0, -1.0],
        [0.0, -1.0, -1.0],
    ];
    let fade = |t: f64| t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
    let lerp = |a: f64, b: f64, t: f64| a + t * (b - a);
    let mut out = vec![0u8; w * h * d * 4];
    for octave in 0..3u32 {
        let freq = f64::from(1u32 << octave);
        // Lattice cells along each axis in one period.
        let cells = VOLUME_NOISE_PERIOD.map(|p| (p * freq).round() as u32);
        for z in 0..d {
            for y in 0..h {
                for x in 0..w {
                    let p = [
                        x as f64 / w as f64 * f64::from(cells[0]),
                        y as f64 / h as f64 * f64::from(cells[1]),
                        z as f64 / d as f64 * f64::from(cells[2]),
                    ];
                    let i = p.map(|v| v.floor());
                    let f = [p[0] - i[0], p[1] - i[1], p[2] - i[2]];
                    let corner = |dx: u32, dy: u32, dz: u32| -> f64 {
                        let c = [
                            (i[0] as u32 + dx) % cells[0],
                            (i[1] as u32 + dy) % cells[1],
                            (i[2] as u32 + dz) % cells[2],
                        ];
                        let g = G[(lattice_hash(c[0], c[1], c[2], octave) % 12) as usize];
                        g[0] * (f[0] - f64::from(dx))
                            + g[1] * (f[1] - f64::from(dy))
                            + g[2] * (f[2] - f64::from(dz))
                    };
                    let (u, v, t) = (fade(f[0]), fade(f[1]), fade(f[2]));
                    let n = lerp(
                        lerp(
                            lerp(corner(0, 0, 0), corner(1, 0, 0), u),
                            lerp(corner(0, 1, 0), corner(1, 1, 0), u),
                            v,
                        ),
                        lerp(
                            lerp(corner(0, 0, 1), corner(1, 0, 1), u),
                            lerp(corner(0, 1, 1), corner(1, 1, 1), u),
                            v,
                        ),
                        t,
                    );
                    let texel = ((z * h + y) * w + x) * 4;
                    out[texel + octave as usize] =
                        ((n * 0.5 + 0.5).clamp(0.0, 1.0) * 255.0).round() as u8;
                }
            }
        }
    }
    out
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Each octave of the noise volume is centred on 0.5 with the spread
    /// of simplex noise (the contrast curve in volume.glsl was tuned on
    /// simplex noise), and tiles: the last texel continues into the first.
    #[test]
    fn the_noise_volume_has_three_centred_octaves_that_tile() {
        let v = volume_noise();
        let [w, h, d] = VOLUME_NOISE_SIZE.map(|v| v as usize);
        assert_eq!(v.len(), w * h * d * 4);
        for octave in 0..3 {
            let vals: Vec<f64> = v
                .iter()
                .skip(octave)
                .step_by(4)
                .map(|&b| f64::from(b) / 255.0 * 2.0 - 1.0)
                .collect();
            let mean = vals.iter().sum::<f64>() / vals.len() as f64;
            let std =
                (vals.iter().map(|x| (x - mean).powi(2)).sum::<f64>() / vals.len() as f64).sqrt();
            eprintln!("octave {octave}: mean {mean:.4}, std {std:.4}");
            assert!(mean.abs() < 0.02, "octave {octave}: mean {mean}");
            assert!((0.2..0.35).contains(&std), "octave {octave}: std {std}");
        }
        // Neighbouring texels across the wrap differ as little as inside.
        let at = |x: usize, y: usize, z: usize| f64::from(v[((z * h + y) * w + x) * 4]);
        let (mut across, mut inside) = (0.0, 0.0);
        for z in 0..d {
            for y in 0..h {
                across += (at(w - 1, y, z) - at(0, y, z)).abs();
                inside += (at(w / 2 - 1, y, z) - at(w / 2, y, z)).abs();
            }
        }
        assert!(
            across < 1.5 * inside,
            "across the wrap {across}, inside {inside}"
        );
    }
}
