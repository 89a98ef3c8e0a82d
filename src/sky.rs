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
    let mut fixed = Sanitised::default();
    let texels = rgba
        .pixels()
        .map(|p| {
            let [r, g, b, a] = p.0;
            if is_float {
                fixed.texel([r, g, b, a])
            } else {
                [srgb_to_linear(r), srgb_to_linear(g), srgb_to_linear(b), a]
            }
        })
        .collect();
    fixed.report(path);
    Ok((w, h, texels))
}

/// The largest value the sky texture holds: the largest finite half float.
/// A brighter texel would become infinite on the GPU, and filtering would
/// turn it into NaN that bloom and exposure spread over the whole frame.
pub const MAX_SKY_VALUE: f32 = 65504.0;

/// Counts of the values [`Sanitised::texel`] changed.
#[derive(Default)]
struct Sanitised {
    non_finite: u64,
    clamped: u64,
}

impl Sanitised {
    /// NaN and infinities to 0 (alpha to 1), negative light to 0, values
    /// above [`MAX_SKY_VALUE`] down to it, alpha into [0, 1].
    fn texel(&mut self, t: [f32; 4]) -> [f32; 4] {
        std::array::from_fn(|k| {
            let v = t[k];
            if !v.is_finite() {
                self.non_finite += 1;
                return if k == 3 { 1.0 } else { 0.0 };
            }
            if k == 3 {
                return v.clamp(0.0, 1.0);
            }
            if v > MAX_SKY_VALUE {
                self.clamped += 1;
            }
            v.clamp(0.0, MAX_SKY_VALUE)
        })
    }

    fn report(&self, path: &Path) {
        if self.non_finite > 0 {
            log::warn!(
                "sky image {}: {} values were NaN or infinite; drawn as 0",
                path.display(),
                self.non_finite
            );
        }
        if self.clamped > 0 {
            log::warn!(
                "sky image {}: {} values were above {MAX_SKY_VALUE} (the largest a half-float \
                 texture holds); clamped to it",
                path.display(),
                self.clamped
            );
        }
    }
}

/// A `w` x `h` image at half the size (at least 1), by a 2x2 box filter.
fn halve(w: u32, h: u32, prev: &[[f32; 4]]) -> Vec<[f32; 4]> {
    let (nw, nh) = ((w / 2).max(1), (h / 2).max(1));
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
    next
}

fn with_mips(width: u32, height: u32, base: Vec<[f32; 4]>) -> SkyTexture {
    let mut levels = vec![base];
    let (mut w, mut h) = (width, height);
    while w > 1 || h > 1 {
        let next = halve(w, h, levels.last().map(Vec::as_slice).unwrap_or(&[]));
        levels.push(next);
        (w, h) = ((w / 2).max(1), (h / 2).max(1));
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

/// Largest cube-map face used: faces four times this wide make a panorama
/// of [`MAX_SKY_SIDE`] x [`MAX_SKY_SIDE`]/2, the sky limit. Larger faces are
/// halved on load (a 2x2 box filter, one face at a time) until they fit.
pub const MAX_FACE_SIDE: u32 = MAX_SKY_SIDE / 4;

/// Loads six square faces (+x, -x, +y, -y, +z, -z) and resamples them into a
/// panorama four faces wide, of at most [`MAX_SKY_SIDE`] x [`MAX_SKY_SIDE`]/2
/// (faces past [`MAX_FACE_SIDE`] are reduced first, with a note).
pub fn load_cubemap(paths: &[impl AsRef<Path>]) -> Result<SkyTexture> {
    load_cubemap_within(paths, MAX_FACE_SIDE)
}

/// [`load_cubemap`] with faces reduced to at most `max_face` on a side.
fn load_cubemap_within(paths: &[impl AsRef<Path>], max_face: u32) -> Result<SkyTexture> {
    if paths.len() != 6 {
        return Err(Error::Scene(format!(
            "a cube map needs 6 faces (+x, -x, +y, -y, +z, -z), got {}",
            paths.len()
        )));
    }
    let mut faces: Vec<(u32, u32, Vec<[f32; 4]>)> = Vec::with_capacity(6);
    let mut side = None;
    for p in paths {
        let (w, h, mut t) = load_linear(p.as_ref())?;
        if w != h || *side.get_or_insert(w) != w {
            return Err(Error::Scene(format!(
                "cube map face {} is {w}x{h}: faces must be square and all the same size",
                p.as_ref().display()
            )));
        }
        let mut n = w;
        while n > max_face {
            t = halve(n, n, &t);
            n /= 2;
        }
        if n != w {
            log::info!(
                "cube map face {} is {w}x{w}: reduced to {n}x{n} (the panorama it makes is at most \
                 {}x{})",
                p.as_ref().display(),
                4 * max_face,
                2 * max_face
            );
        }
        faces.push((n, n, t));
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
    fn a_cube_map_of_large_faces_is_built_within_the_sky_limit() {
        let dir = tempfile::tempdir().expect("temp dir");
        let paths: Vec<_> = (0..6)
            .map(|i| {
                let p = dir.path().join(format!("face{i}.png"));
                image::RgbImage::from_pixel(40, 40, image::Rgb([40 * i as u8, 100, 100]))
                    .save(&p)
                    .expect("face");
                p
            })
            .collect();
        // Faces of 40 with a limit of 16: halved to 20, then 10.
        let sky = super::load_cubemap_within(&paths, 16).expect("loads");
        assert_eq!((sky.width, sky.height), (40, 20));
        assert!(sky.width <= 4 * 16);
        assert_eq!(super::MAX_FACE_SIDE * 4, super::MAX_SKY_SIDE);
    }

    #[test]
    fn missing_file_names_the_file() {
        let e = load_equirect(Path::new("/no/such/sky.hdr"))
            .unwrap_err()
            .to_string();
        assert!(e.contains("/no/such/sky.hdr"), "{e}");
    }
}
