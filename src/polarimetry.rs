//! The numbers scientists compare with the EHT's (docs/polarization.md,
//! "The numbers"), measured on a Stokes image (`--aov stokes`), in f64:
//! the net linear polarization fraction |m|_net = |sum (Q + iU)| / sum I, the
//! intensity-weighted mean fraction <|m|> = sum |Q + iU| / sum I, and
//! Palumbo, Wong & Prather's (2020) coefficient beta_2 = sum (Q + iU)
//! e^(-2 i phi) / sum I over the ring annulus (phi the position angle east
//! of north, about the image's centre), each on the image as it is and
//! through the telescope's Gaussian beam.

use std::f64::consts::PI;

/// One picture's figures.
#[derive(Clone, Copy, Debug, PartialEq, serde::Serialize)]
pub struct Figures {
    /// |m|_net.
    pub m_net: f64,
    /// <|m|>.
    pub m_mean: f64,
    /// |beta_2| and arg beta_2 in degrees (-180 to 180).
    pub beta2_amplitude: f64,
    pub beta2_phase_deg: f64,
}

/// The image plane of one picture: its size in pixels and its scale.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Plane {
    pub width: usize,
    pub height: usize,
    /// GM/c^2 per pixel (at the centre; linear across a pinhole's image).
    pub scale: f64,
    /// The annulus's radii, GM/c^2.
    pub annulus: [f64; 2],
}

/// A picture's Stokes parameters, I, Q, U per pixel (row-major, row 0 at
/// the top, north up and east to the left).
pub struct StokesImage {
    pub plane: Plane,
    pub iqu: Vec<[f64; 3]>,
}

impl StokesImage {
    /// Columns `x0..x1` of an RGBA32F Stokes image `width` pixels wide (one
    /// field model's picture).
    pub fn from_rgba(rgba: &[f32], width: usize, x0: usize, x1: usize, plane: Plane) -> Self {
        let height = plane.height;
        let mut iqu = Vec::with_capacity((x1 - x0) * height);
        for y in 0..height {
            for x in x0..x1 {
                let p = 4 * (y * width + x);
                let at = |c: usize| rgba.get(p + c).copied().unwrap_or(0.0) as f64;
                iqu.push([at(0), at(1), at(2)]);
            }
        }
        StokesImage { plane, iqu }
    }

    /// The figures of this image.
    pub fn figures(&self) -> Figures {
        let Plane {
            width,
            height,
            scale,
            annulus: [inner, outer],
        } = self.plane;
        let (mut i_all, mut q_all, mut u_all, mut p_all) = (0.0, 0.0, 0.0, 0.0);
        let (mut i_ring, mut b_re, mut b_im) = (0.0, 0.0, 0.0);
        for (k, [i, q, u]) in self.iqu.iter().copied().enumerate() {
            i_all += i;
            q_all += q;
            u_all += u;
            p_all += q.hypot(u);
            // The pixel's place on the image plane: x to the right (west),
            // y up (north); phi east of north.
            let x = ((k % width) as f64 + 0.5 - width as f64 / 2.0) * scale;
            let y = (height as f64 / 2.0 - (k / width) as f64 - 0.5) * scale;
            let rho = x.hypot(y);
            if rho >= inner && rho <= outer {
                let phi = (-x).atan2(y);
                let (s, c) = (2.0 * phi).sin_cos();
                // (Q + iU) e^(-2 i phi).
                b_re += q * c + u * s;
                b_im += u * c - q * s;
                i_ring += i;
            }
        }
        let ratio = |a: f64, b: f64| if b > 0.0 { a / b } else { 0.0 };
        Figures {
            m_net: ratio(q_all.hypot(u_all), i_all),
            m_mean: ratio(p_all, i_all),
            beta2_amplitude: ratio(b_re.hypot(b_im), i_ring),
            beta2_phase_deg: if i_ring > 0.0 {
                b_im.atan2(b_re) * 180.0 / PI
            } else {
                0.0
            },
        }
    }

    /// The image through a Gaussian beam of standard deviation `sigma`
    /// pixels (cut at 4 sigma; dark beyond the picture's edges, so flux is
    /// kept), as `shaders/pol_beam.comp` blurs it.
    pub fn blurred(&self, sigma: f64) -> StokesImage {
        let (w, h) = (self.plane.width, self.plane.height);
        let radius = (4.0 * sigma).ceil() as isize;
        let kernel: Vec<f64> = (-radius..=radius)
            .map(|k| (-0.5 * (k as f64 / sigma).powi(2)).exp())
            .collect();
        let total: f64 = kernel.iter().sum();
        let pass = |src: &[[f64; 3]], along_x: bool| -> Vec<[f64; 3]> {
            let mut out = vec![[0.0; 3]; w * h];
            for y in 0..h {
                for x in 0..w {
                    let mut acc = [0.0; 3];
                    for (j, kw) in kernel.iter().enumerate() {
                        let d = j as isize - radius;
                        let (sx, sy) = if along_x {
                            (x as isize + d, y as isize)
                        } else {
                            (x as isize, y as isize + d)
                        };
                        if sx < 0 || sy < 0 || sx >= w as isize || sy >= h as isize {
                            continue;
                        }
                        let v = src[sy as usize * w + sx as usize];
                        for c in 0..3 {
                            acc[c] += kw * v[c];
                        }
                    }
                    out[y * w + x] = acc.map(|a| a / total);
                }
            }
            out
        };
        let across = pass(&self.iqu, true);
        StokesImage {
            plane: self.plane,
            iqu: pass(&across, false),
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn plane(n: usize) -> Plane {
        Plane {
            width: n,
            height: n,
            scale: 1.0,
            annulus: [2.0, 10.0],
        }
    }

    /// A ring whose electric vector makes angle `offset` with the radial
    /// direction everywhere: chi = phi + offset, so (Q + iU) = P e^(2 i chi)
    /// and beta_2 = m e^(2 i offset) exactly (phase 2 offset).
    fn ring(offset: f64, m: f64) -> StokesImage {
        let n = 32;
        let mut iqu = Vec::new();
        for k in 0..n * n {
            let x = (k % n) as f64 + 0.5 - 16.0;
            let y = 16.0 - (k / n) as f64 - 0.5;
            let rho = x.hypot(y);
            let i = if (4.0..8.0).contains(&rho) { 1.0 } else { 0.0 };
            let chi = (-x).atan2(y) + offset;
            iqu.push([i, m * i * (2.0 * chi).cos(), m * i * (2.0 * chi).sin()]);
        }
        StokesImage {
            plane: plane(n),
            iqu,
        }
    }

    #[test]
    fn a_radial_ring_has_beta2_real_and_no_net_polarization() {
        let f = ring(0.0, 0.5).figures();
        assert!((f.beta2_amplitude - 0.5).abs() < 1e-12, "{f:?}");
        assert!(f.beta2_phase_deg.abs() < 1e-9, "{f:?}");
        assert!((f.m_mean - 0.5).abs() < 1e-12, "{f:?}");
        // Symmetric about the centre: the net polarization cancels.
        assert!(f.m_net < 1e-12, "{f:?}");
    }

    #[test]
    fn a_tilted_pattern_turns_beta2_by_twice_the_tilt() {
        // Ticks at 60 degrees from radial (a spiral): arg beta_2 = 120 deg.
        let f = ring(PI / 3.0, 0.3).figures();
        assert!((f.beta2_phase_deg - 120.0).abs() < 1e-9, "{f:?}");
        let g = ring(-PI / 4.0, 0.3).figures();
        assert!((g.beta2_phase_deg + 90.0).abs() < 1e-9, "{g:?}");
    }

    #[test]
    fn a_uniform_vector_is_all_net_and_the_beam_keeps_it() {
        let n = 24;
        let iqu = vec![[2.0, 0.6, -0.8]; n * n];
        let img = StokesImage {
            plane: plane(n),
            iqu,
        };
        let f = img.figures();
        assert!((f.m_net - 0.5).abs() < 1e-12 && (f.m_mean - 0.5).abs() < 1e-12);
        // A beam blurs the edges but cannot turn a uniform vector.
        let b = img.blurred(3.0).figures();
        assert!(
            (b.m_net - 0.5).abs() < 1e-12 && (b.m_mean - 0.5).abs() < 1e-12,
            "{b:?}"
        );
    }

    #[test]
    fn the_beam_depolarizes_a_ring_of_turning_vectors() {
        let sharp = ring(0.0, 0.5);
        let blurred = sharp.blurred(4.0).figures();
        // Neighbouring vectors at different angles cancel in the blur.
        assert!(blurred.m_mean < 0.9 * sharp.figures().m_mean, "{blurred:?}");
        // Symmetric still: beta_2 stays real (arg 0).
        assert!(blurred.beta2_phase_deg.abs() < 1e-6, "{blurred:?}");
    }
}
