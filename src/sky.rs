//! Image skies, loaded on the CPU: an equirectangular panorama (PNG, JPEG,
//! Radiance HDR, OpenEXR) or a cube map of six faces, which is resampled into
//! a panorama so the GPU has one kind of sky texture. The mip chain is built
//! here too (2x2 box filter in linear light); the shader picks the level from
//! the ray's footprint.
//!
//! Panorama convention: u = 0.5 + atan2(z, x) / 2 pi (u = 0.5 looks along +x,
//! u grows toward +z), v = acos(y) / pi (v = 0 is straight up, +y).

use std::path::Path;

use crate::{Error, Result};

/// A linear-light RGBA f32 panorama with its mip chain (level 0 first).
#[derive(Clone, Debug)]
pub struct SkyTexture {
    pub width: u32,
    pub height: u32,
    pub levels: Vec<Vec<[f32; 4]>>,
    /// Kept as 32-bit floats on the GPU (the star grid's packed places);
    /// otherwise half floats, plenty for light.
    pub full_precision: bool,
}

fn srgb_to_linear(c: f32) -> f32 {
    if c <= 0.04045 {
        c / 12.92
    } else {
        ((c + 0.055) / 1.055).powf(2.4)
    }
}

/// Largest side of a sky image, pixels, and the most pixels in one: an 8K
/// panorama (8192x4096, about 700 MB as linear floats with its mips).
pub const MAX_SKY_SIDE: u32 = 8192;
pub const MAX_SKY_PIXELS: u64 = 8192 * 4096;

/// Decodes an image file to linear RGBA f32: 8- and 16-bit files are taken as
/// sRGB-encoded, float files (HDR, EXR) as linear. The size is read from the
/// header first: empty images and ones beyond [`MAX_SKY_SIDE`] or
/// [`MAX_SKY_PIXELS`] are refused before anything is decoded, and the
/// decoder runs under the same limits.
pub fn load_linear(path: &Path) -> Result<(u32, u32, Vec<[f32; 4]>)> {
    let bad =
        |e: &dyn std::fmt::Display| Error::Scene(format!("sky image {}: {e}", path.display()));
    let open = || {
        image::ImageReader::open(path)
            .map_err(|e| bad(&e))?
            .with_guessed_format()
            .map_err(|e| bad(&e))
    };
    let (w, h) = open()?.into_dimensions().map_err(|e| bad(&e))?;
    if w == 0 || h == 0 {
        return Err(bad(&format!("is empty ({w}x{h})")));
    }
    if w > MAX_SKY_SIDE || h > MAX_SKY_SIDE || u64::from(w) * u64::from(h) > MAX_SKY_PIXELS {
        return Err(bad(&format!(
            "is {w}x{h}: larger than the limit for sky images ({MAX_SKY_SIDE} per side, \
             {MAX_SKY_SIDE}x{} in all); downscale it",
            MAX_SKY_PIXELS / u64::from(MAX_SKY_SIDE)
        )));
    }
    let mut reader = open()?;
    let mut limits = image::Limits::default();
    limits.max_image_width = Some(MAX_SKY_SIDE);
    limits.max_image_height = Some(MAX_SKY_SIDE);
    limits.max_alloc = Some(MAX_SKY_PIXELS * 16 * 2);
    reader.limits(limits);
    let img = reader.decode().map_err(|e| bad(&e))?;
    let is_float = matches!(
        img,
        image::DynamicImage::ImageRgb32F(_) | image::DynamicImage::ImageRgba32F(_)
    );
    let rgba = img.into_rgba32f();
    let (w, h) = rgba.dimensions();
    let texels = rgba
        .pixels()
        .map(|p| {
            let [r, g, b, a] = p.0;
            if is_float {
                [r.max(0.0), g.max(0.0), b.max(0.0), a]
            } else {
                [srgb_to_linear(r), srgb_to_linear(g), srgb_to_linear(b), a]
            }
        })
        .collect();
    Ok((w, h, texels))
}

fn with_mips(width: u32, height: u32, base: Vec<[f32; 4]>) -> SkyTexture {
    let mut levels = vec![base];
    let (mut w, mut h) = (width, height);
    while w > 1 || h > 1 {
        let (nw, nh) = ((w / 2).max(1), (h / 2).max(1));
        let prev = levels.last().map(Vec::as_slice).unwrap_or(&[]);
        let at = |x: u32, y: u32| prev[(y.min(h - 1) * w + x.min(w - 1)) as usize];
        let mut next = Vec::with_capacity((nw * nh) as usize);
        for y in 0..nh {
            for x in 0..nw {
                let (a, b, c, d) = (
                    at(2 * x, 2 * y),
                    at(2 * x + 1, 2 * y),
                    at(2 * x, 2 * y + 1),
                    at(2 * x + 1, 2 * y + 1),
                );
                next.push(std::array::from_fn(|k| 0.25 * (a[k] + b[k] + c[k] + d[k])));
            }
        }
        levels.push(next);
        (w, h) = (nw, nh);
    }
    SkyTexture {
        width,
        height,
        levels,
        full_precision: false,
    }
}

/// Loads an equirectangular panorama.
pub fn load_equirect(path: &Path) -> Result<SkyTexture> {
    let (w, h, texels) = load_linear(path)?;
    Ok(with_mips(w, h, texels))
}

/// The cube-map face and face coordinates (s, t in [0, 1], t down) of a
/// direction, by the Vulkan/OpenGL cube map convention; faces +x, -x, +y, -y,
/// +z, -z are 0 to 5.
pub fn cube_face(d: [f64; 3]) -> (usize, f64, f64) {
    let [x, y, z] = d;
    let (ax, ay, az) = (x.abs(), y.abs(), z.abs());
    let (face, sc, tc, ma) = if ax >= ay && ax >= az {
        if x > 0.0 {
            (0, -z, -y, ax)
        } else {
            (1, z, -y, ax)
        }
    } else if ay >= az {
        if y > 0.0 {
            (2, x, z, ay)
        } else {
            (3, x, -z, ay)
        }
    } else if z > 0.0 {
        (4, x, -y, az)
    } else {
        (5, -x, -y, az)
    };
    (face, 0.5 * (sc / ma + 1.0), 0.5 * (tc / ma + 1.0))
}

/// Loads six square faces (+x, -x, +y, -y, +z, -z) and resamples them into a
/// panorama four faces wide.
pub fn load_cubemap(paths: &[impl AsRef<Path>]) -> Result<SkyTexture> {
    if paths.len() != 6 {
        return Err(Error::Scene(format!(
            "a cube map needs 6 faces (+x, -x, +y, -y, +z, -z), got {}",
            paths.len()
        )));
    }
    let mut faces = Vec::with_capacity(6);
    for p in paths {
        let (w, h, t) = load_linear(p.as_ref())?;
        if w != h
            || faces
                .first()
                .is_some_and(|(fw, _, _): &(u32, u32, Vec<[f32; 4]>)| *fw != w)
        {
            return Err(Error::Scene(format!(
                "cube map face {} is {w}x{h}: faces must be square and all the same size",
                p.as_ref().display()
            )));
        }
        faces.push((w, h, t));
    }
    let n = faces[0].0;
    let (w, h) = (4 * n, 2 * n);
    let mut out = Vec::with_capacity((w * h) as usize);
    for row in 0..h {
        let theta = (f64::from(row) + 0.5) / f64::from(h) * std::f64::consts::PI;
        for col in 0..w {
            let phi = ((f64::from(col) + 0.5) / f64::from(w) - 0.5) * std::f64::consts::TAU;
            let d = [
                theta.sin() * phi.cos(),
                theta.cos(),
                theta.sin() * phi.sin(),
            ];
            let (f, s, t) = cube_face(d);
            let (_, _, tex) = &faces[f];
            // Bilinear within the face.
            let fx = (s * f64::from(n) - 0.5).clamp(0.0, f64::from(n - 1));
            let fy = (t * f64::from(n) - 0.5).clamp(0.0, f64::from(n - 1));
            let (x0, y0) = (fx.floor() as u32, fy.floor() as u32);
            let (x1, y1) = ((x0 + 1).min(n - 1), (y0 + 1).min(n - 1));
            let (ax, ay) = ((fx - f64::from(x0)) as f32, (fy - f64::from(y0)) as f32);
            let at = |x: u32, y: u32| tex[(y * n + x) as usize];
            let top = lerp4(at(x0, y0), at(x1, y0), ax);
            let bottom = lerp4(at(x0, y1), at(x1, y1), ax);
            out.push(lerp4(top, bottom, ay));
        }
    }
    Ok(with_mips(w, h, out))
}

fn lerp4(a: [f32; 4], b: [f32; 4], t: f32) -> [f32; 4] {
    std::array::from_fn(|k| a[k] + (b[k] - a[k]) * t)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cube_faces_follow_the_vulkan_convention() {
        assert_eq!(cube_face([1.0, 0.0, 0.0]), (0, 0.5, 0.5));
        assert_eq!(cube_face([0.0, 0.0, -1.0]), (5, 0.5, 0.5));
        // On +x, +y is up (t = 0 at the top) and -z is to the right (s grows).
        let (f, s, t) = cube_face([1.0, 0.5, -0.5]);
        assert_eq!(f, 0);
        assert!(s > 0.5 && t < 0.5);
    }

    #[test]
    fn mip_chain_halves_to_one_texel_and_keeps_the_mean() {
        let base: Vec<[f32; 4]> = (0..16 * 8).map(|i| [i as f32, 0.0, 0.0, 1.0]).collect();
        let sky = with_mips(16, 8, base.clone());
        assert_eq!(sky.levels.len(), 5);
        assert_eq!(sky.levels.last().map(Vec::len), Some(1));
        let mean = base.iter().map(|p| p[0]).sum::<f32>() / base.len() as f32;
        assert!((sky.levels[4][0][0] - mean).abs() < 1e-3);
    }

    #[test]
    fn missing_file_names_the_file() {
        let e = load_equirect(Path::new("/no/such/sky.hdr"))
            .unwrap_err()
            .to_string();
        assert!(e.contains("/no/such/sky.hdr"), "{e}");
    }
}
