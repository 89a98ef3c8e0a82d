//! Colour of a blackbody: the Planck spectrum integrated against the CIE 1931
//! 2-degree colour-matching functions, converted to linear sRGB (D65).
//!
//! The matching functions use the multi-lobe Gaussian fit of Wyman, Sloan and
//! Shirley, "Simple Analytic Approximations to the CIE XYZ Color Matching
//! Functions" (JCGT 2013), accurate to within the spread of the tabulated data
//! for this use.

/// x̄, ȳ, z̄ at wavelength `nm` (Wyman et al. 2013, multi-lobe fit).
pub fn cie_cmf(nm: f64) -> [f64; 3] {
    let g = |x: f64, mu: f64, s1: f64, s2: f64| {
        let t = (x - mu) / if x < mu { s1 } else { s2 };
        (-0.5 * t * t).exp()
    };
    let x = 1.056 * g(nm, 599.8, 37.9, 31.0) + 0.362 * g(nm, 442.0, 16.0, 26.7)
        - 0.065 * g(nm, 501.1, 20.4, 26.2);
    let y = 0.821 * g(nm, 568.8, 46.9, 40.5) + 0.286 * g(nm, 530.9, 16.3, 31.1);
    let z = 1.217 * g(nm, 437.0, 11.8, 36.0) + 0.681 * g(nm, 459.0, 26.0, 13.8);
    [x, y, z]
}

/// Planck's spectral radiance at wavelength `nm` and temperature `t` kelvin,
/// up to a constant factor (the colour is normalised afterwards).
pub fn planck(nm: f64, t: f64) -> f64 {
    // c2 = h c / k in nm K.
    const C2: f64 = 1.438_776_877e7;
    let l = nm * 1e-3; // micrometres, to keep the numbers tame
    1.0 / (l.powi(5) * ((C2 / (nm * t)).exp_m1()))
}

/// CIE XYZ of a blackbody at `t` kelvin, normalised to Y = 1.
pub fn blackbody_xyz(t: f64) -> [f64; 3] {
    let mut xyz = [0.0; 3];
    let mut nm = 360.0;
    while nm <= 830.0 {
        let p = planck(nm, t);
        let c = cie_cmf(nm);
        for k in 0..3 {
            xyz[k] += p * c[k];
        }
        nm += 1.0;
    }
    let y = xyz[1];
    [xyz[0] / y, 1.0, xyz[2] / y]
}

/// CIE XYZ to linear sRGB (D65 white).
pub fn xyz_to_linear_srgb(c: [f64; 3]) -> [f64; 3] {
    let [x, y, z] = c;
    [
        3.240_454_2 * x - 1.537_138_5 * y - 0.498_531_4 * z,
        -0.969_266_0 * x + 1.876_010_8 * y + 0.041_556_0 * z,
        0.055_643_4 * x - 0.204_025_9 * y + 1.057_225_2 * z,
    ]
}

/// Linear sRGB colour of a blackbody at `t` kelvin with luminance 1; colours
/// outside the sRGB gamut are clipped to it (negative parts removed) and
/// brought back to luminance 1.
pub fn blackbody_srgb(t: f64) -> [f64; 3] {
    let rgb = xyz_to_linear_srgb(blackbody_xyz(t)).map(|v| v.max(0.0));
    let lum = 0.212_639 * rgb[0] + 0.715_169 * rgb[1] + 0.072_192 * rgb[2];
    rgb.map(|v| v / lum)
}

/// Range of the temperature lookup table, in kelvin (log-spaced).
pub const LUT_MIN_K: f64 = 500.0;
/// Upper end of the lookup table.
pub const LUT_MAX_K: f64 = 100_000.0;
/// Entries in the lookup table.
pub const LUT_SIZE: usize = 256;

/// Temperature of lookup-table entry `i` (texel centre).
pub fn lut_temperature(i: usize) -> f64 {
    let t = (i as f64 + 0.5) / LUT_SIZE as f64;
    (LUT_MIN_K.ln() + t * (LUT_MAX_K.ln() - LUT_MIN_K.ln())).exp()
}

/// The table the shader samples: linear sRGB with luminance 1, RGBA f32.
pub fn lut_rgba() -> Vec<[f32; 4]> {
    (0..LUT_SIZE)
        .map(|i| {
            let c = blackbody_srgb(lut_temperature(i));
            [c[0] as f32, c[1] as f32, c[2] as f32, 1.0]
        })
        .collect()
}

#[cfg(test)]
mod tests {
    use super::*;

    /// Chromaticity of the Planckian locus (published CIE 1931 values).
    #[test]
    fn planckian_locus_chromaticities() {
        let known = [
            (2000.0, 0.5267, 0.4133),
            (3000.0, 0.4369, 0.4041),
            (4000.0, 0.3805, 0.3768),
            (6500.0, 0.3135, 0.3236),
            (10000.0, 0.2807, 0.2884),
        ];
        for (t, x0, y0) in known {
            let [x, y, z] = blackbody_xyz(t);
            let (cx, cy) = (x / (x + y + z), y / (x + y + z));
            assert!(
                (cx - x0).abs() < 0.004 && (cy - y0).abs() < 0.004,
                "{t} K: ({cx:.4}, {cy:.4})"
            );
        }
    }

    #[test]
    fn hot_is_blue_cool_is_red_6500_is_near_white() {
        let red = blackbody_srgb(1500.0);
        assert!(red[0] > red[1] && red[1] > red[2]);
        let blue = blackbody_srgb(40_000.0);
        assert!(blue[2] > blue[0]);
        let white = blackbody_srgb(6500.0);
        let (lo, hi) = white
            .iter()
            .fold((f64::MAX, 0.0f64), |(l, h), &v| (l.min(v), h.max(v)));
        assert!(hi / lo < 1.15, "{white:?}");
    }

    #[test]
    fn table_has_unit_luminance_and_spans_the_range() {
        let lut = lut_rgba();
        assert_eq!(lut.len(), LUT_SIZE);
        for c in &lut {
            let lum = 0.212_639 * c[0] + 0.715_169 * c[1] + 0.072_192 * c[2];
            assert!((lum - 1.0).abs() < 1e-5);
        }
        assert!(lut_temperature(0) > LUT_MIN_K && lut_temperature(LUT_SIZE - 1) < LUT_MAX_K);
    }
}
