//! The real sky: the Hipparcos catalogue (new reduction, van Leeuwen 2007,
//! ESA; CDS catalogue I/311) down to Hipparcos magnitude 7.5, 23,270 stars,
//! embedded as a compact table (`src/data/hipparcos.bin`, written by
//! `tools/hipparcos_to_bin.py`, which documents the format). ESA publishes the
//! Hipparcos data for free use with citation: "The Hipparcos and Tycho
//! Catalogues", ESA SP-1200 (1997), and F. van Leeuwen, "Hipparcos, the New
//! Reduction of the Raw Data", Astrophysics and Space Science Library 350
//! (2007).
//!
//! For the GPU the stars are binned into a grid on the faces of a cube in
//! galactic coordinates (`GRID` x `GRID` cells a face): each cell keeps its
//! stars' flux-weighted place inside the cell and their light (flux times
//! colour, summed). Coarser mip levels merge 2x2 cells (light summed, place
//! flux-weighted), so a pixel whose
//! footprint on the sky is wide reads one coarse cell instead of many fine
//! ones. The shader (`sky.glsl`, `sky_catalogue`) draws each star as a
//! Gaussian as wide as the pixel's footprint with its flux fixed.

use glam::{DMat3, DVec3};

use crate::physics::blackbody::{LUT_MAX_K, LUT_MIN_K, LUT_SIZE};
use crate::{Error, Result};

/// The embedded table.
pub const HIPPARCOS: &[u8] = include_bytes!("data/hipparcos.bin");

/// Cells along a cube face's side at level 0.
pub const GRID: u32 = 256;

/// Flux of a magnitude-0 star in the renderer's units (radiance times
/// steradians): a magnitude-0 star fills a 1280x720 pixel at about 200, and
/// the faintest kept (7.5) at about 0.2, so against the default disk the
/// brightest stars bloom and the faint ones are just seen. The grid stores fluxes relative
/// to it (so they stay normal numbers in half floats); `sky.glsl` multiplies.
pub const FLUX_MAG0: f64 = 1.5e-4;

/// One catalogue star.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Star {
    /// Right ascension and declination, radians (ICRS, epoch J1991.25).
    pub ra: f64,
    pub dec: f64,
    /// Hipparcos magnitude Hp.
    pub mag: f64,
    /// B-V colour index.
    pub bv: f64,
}

/// Reads the table format of `tools/hipparcos_to_bin.py`.
pub fn parse(bytes: &[u8]) -> Result<Vec<Star>> {
    let bad = |why: &str| Error::Other(format!("star table: {why}"));
    let body = bytes
        .strip_prefix(b"BHSTARS1")
        .ok_or_else(|| bad("not a BHSTARS1 table"))?;
    let (count, rest) = body
        .split_at_checked(4)
        .ok_or_else(|| bad("truncated header"))?;
    let count = u32::from_le_bytes([count[0], count[1], count[2], count[3]]) as usize;
    if rest.len() != count * 6 {
        return Err(bad(&format!(
            "{count} stars need {} bytes, the table has {}",
            count * 6,
            rest.len()
        )));
    }
    Ok(rest
        .chunks_exact(6)
        .map(|s| {
            let ra = f64::from(u16::from_le_bytes([s[0], s[1]])) * std::f64::consts::TAU / 65536.0;
            let dec =
                f64::from(i16::from_le_bytes([s[2], s[3]])) * std::f64::consts::FRAC_PI_2 / 32767.0;
            Star {
                ra,
                dec,
                mag: f64::from(s[4]) / 20.0 - 2.0,
                bv: f64::from(s[5] as i8) / 50.0,
            }
        })
        .collect())
}

/// Colour temperature from B-V (Ballesteros, "New insights into black
/// bodies", EPL 97, 34008, 2012).
pub fn temperature_from_bv(bv: f64) -> f64 {
    let bv = bv.clamp(-0.4, 2.0);
    4600.0 * (1.0 / (0.92 * bv + 1.7) + 1.0 / (0.92 * bv + 0.62))
}

/// ICRS (equatorial) to galactic coordinates: the rows are the galactic x
/// (toward the centre), y (longitude 90 degrees) and z (north galactic pole)
/// axes in equatorial coordinates (the Hipparcos definition, ESA SP-1200
/// vol. 1, section 1.5.3).
pub const EQUATORIAL_TO_GALACTIC: [[f64; 3]; 3] = [
    [-0.054_875_539_4, -0.873_437_104_7, -0.483_834_991_8],
    [0.494_109_453_6, -0.444_829_594_3, 0.746_982_248_9],
    [-0.867_666_135_7, -0.198_076_389_6, 0.455_983_794_5],
];

/// Unit vector of right ascension `ra` and declination `dec`.
pub fn equatorial_vector(ra: f64, dec: f64) -> DVec3 {
    DVec3::new(dec.cos() * ra.cos(), dec.cos() * ra.sin(), dec.sin())
}

/// Galactic unit vector of an equatorial one.
pub fn to_galactic(eq: DVec3) -> DVec3 {
    let m = EQUATORIAL_TO_GALACTIC;
    DVec3::new(
        m[0][0] * eq.x + m[0][1] * eq.y + m[0][2] * eq.z,
        m[1][0] * eq.x + m[1][1] * eq.y + m[1][2] * eq.z,
        m[2][0] * eq.x + m[2][1] * eq.y + m[2][2] * eq.z,
    )
}

/// Which celestial frame the scene's axes follow (`[sky] frame`).
#[derive(Clone, Copy, Debug, PartialEq, Eq, serde::Deserialize, serde::Serialize)]
#[serde(rename_all = "lowercase")]
pub enum SkyFrame {
    /// The galactic centre along +z, the north galactic pole along +y: the
    /// default camera looks at the centre of the Milky Way.
    Galactic,
    /// Right ascension 0 along +z, the north celestial pole along +y.
    Equatorial,
}

/// The matrix taking a world direction to galactic coordinates, for a sky in
/// `frame` turned by `rotation_deg` about +y (counter-clockwise seen from
/// above), then tilted by `tilt_deg` about +z (counter-clockwise as the
/// default camera sees it). World axes: +x right, +y up, +z forward of the default camera;
/// seen from inside the celestial sphere facing +z with +y up, the frame's
/// longitude (or right ascension) grows to the left (east is left on the
/// sky), so the frame's y axis lies along world -x.
pub fn world_to_galactic(frame: SkyFrame, rotation_deg: f64, tilt_deg: f64) -> DMat3 {
    // World -> frame: frame x = world z, frame y = -world x, frame z = world y.
    let to_frame = DMat3::from_cols(
        DVec3::new(0.0, -1.0, 0.0),
        DVec3::new(0.0, 0.0, 1.0),
        DVec3::new(1.0, 0.0, 0.0),
    );
    // Undo the sky's turn first: a world direction d sees the sky point that
    // sat at R(-angle) d before the turn.
    let turn = DMat3::from_rotation_y(-rotation_deg.to_radians())
        * DMat3::from_rotation_z(-tilt_deg.to_radians());
    let frame_to_galactic = match frame {
        SkyFrame::Galactic => DMat3::IDENTITY,
        SkyFrame::Equatorial => {
            let m = EQUATORIAL_TO_GALACTIC;
            DMat3::from_cols(
                DVec3::new(m[0][0], m[1][0], m[2][0]),
                DVec3::new(m[0][1], m[1][1], m[2][1]),
                DVec3::new(m[0][2], m[1][2], m[2][2]),
            )
        }
    };
    frame_to_galactic * to_frame * turn
}

/// The cube face (0..6: +x, -x, +y, -y, +z, -z) and face coordinates in
/// [-1, 1] of a direction (the same convention as `sky.glsl`).
pub fn cube_face(d: DVec3) -> (usize, f64, f64) {
    let a = d.abs();
    if a.x >= a.y && a.x >= a.z {
        (if d.x > 0.0 { 0 } else { 1 }, d.z / a.x, d.y / a.x)
    } else if a.y >= a.z {
        (if d.y > 0.0 { 2 } else { 3 }, d.x / a.y, d.z / a.y)
    } else {
        (if d.z > 0.0 { 4 } else { 5 }, d.x / a.z, d.y / a.z)
    }
}

/// Steps of a cell's light place along u in a packed texel (see
/// [`pack_place`]; `STAR_PLACE_STEPS` in sky.glsl, checked by tests/layout.rs).
pub const PLACE_STEPS: f64 = 4095.0;

/// The place of a cell's light inside the cell (u, v in [0, 1]) packed into
/// one float: the integer part is u in 4095ths, the fraction v in 4096ths
/// (a cell at level 0 is about half a degree, so both are good to 1e-4
/// degree). The shader unpacks it in `sky_catalogue`.
pub fn pack_place(u: f64, v: f64) -> f32 {
    let v_scale = PLACE_STEPS / (PLACE_STEPS + 1.0);
    ((u.clamp(0.0, 1.0) * PLACE_STEPS).round() + v.clamp(0.0, 1.0) * v_scale) as f32
}

/// The inverse of [`pack_place`].
pub fn unpack_place(p: f32) -> (f64, f64) {
    let p = f64::from(p);
    let whole = p.floor();
    (
        whole / PLACE_STEPS,
        (p - whole) * ((PLACE_STEPS + 1.0) / PLACE_STEPS),
    )
}

/// Linear sRGB colour of luminance 1 of a blackbody at `t` kelvin, from the
/// colour table by linear interpolation in log T (as the disk's colours).
fn star_colour(lut: &[[f32; 4]], t: f64) -> [f64; 3] {
    let x = ((t.max(1.0).ln() - LUT_MIN_K.ln()) / (LUT_MAX_K.ln() - LUT_MIN_K.ln())
        * LUT_SIZE as f64
        - 0.5)
        .clamp(0.0, LUT_SIZE as f64 - 1.0);
    let i = (x.floor() as usize).min(LUT_SIZE - 2);
    let f = x - i as f64;
    let (a, b) = (lut[i], lut[i + 1]);
    [0, 1, 2].map(|k| f64::from(a[k]) + f * (f64::from(b[k]) - f64::from(a[k])))
}

/// The star grid with its mips, level 0 first: each level is (6 n) x n
/// RGBA texels (faces side by side), a texel holding the place of the
/// cell's light inside the cell ([`pack_place`]) and the light of its stars:
/// the sum of each star's flux (relative to a magnitude-0 star) times its
/// colour of luminance 1, in linear sRGB. So the luminance of a texel's
/// light is its flux, and the shader needs no colour lookup.
pub fn star_grid(stars: &[Star]) -> Vec<Vec<[f32; 4]>> {
    let n = GRID as usize;
    let lut = crate::physics::blackbody::lut_rgba();
    // Sums per cell: (flux, flux * u, flux * v, flux * R, flux * G, flux * B).
    let mut sums = vec![[0.0f64; 6]; 6 * n * n];
    for s in stars {
        let g = to_galactic(equatorial_vector(s.ra, s.dec));
        let (face, u, v) = cube_face(g);
        let gu = ((u * 0.5 + 0.5) * n as f64).clamp(0.0, n as f64 - 1e-9);
        let gv = ((v * 0.5 + 0.5) * n as f64).clamp(0.0, n as f64 - 1e-9);
        let (cu, cv) = (gu.floor(), gv.floor());
        let flux = 10f64.powf(-0.4 * s.mag);
        let colour = star_colour(&lut, temperature_from_bv(s.bv));
        let cell = &mut sums[v_index(face, cu as usize, cv as usize, n)];
        cell[0] += flux;
        cell[1] += flux * (gu - cu);
        cell[2] += flux * (gv - cv);
        for k in 0..3 {
            cell[3 + k] += flux * colour[k];
        }
    }
    let mut levels = Vec::new();
    let mut size = n;
    loop {
        levels.push(
            sums.iter()
                .map(|c| {
                    if c[0] > 0.0 {
                        [
                            pack_place(c[1] / c[0], c[2] / c[0]),
                            c[3] as f32,
                            c[4] as f32,
                            c[5] as f32,
                        ]
                    } else {
                        [pack_place(0.5, 0.5), 0.0, 0.0, 0.0]
                    }
                })
                .collect(),
        );
        if size == 1 {
            break;
        }
        // Merge 2x2 cells; places move to the parent's cell units.
        let half = size / 2;
        let mut next = vec![[0.0f64; 6]; 6 * half * half];
        for face in 0..6 {
            for y in 0..size {
                for x in 0..size {
                    let c = sums[v_index(face, x, y, size)];
                    if c[0] == 0.0 {
                        continue;
                    }
                    let p = &mut next[v_index(face, x / 2, y / 2, half)];
                    p[0] += c[0];
                    p[1] += 0.5 * (c[1] + c[0] * (x % 2) as f64);
                    p[2] += 0.5 * (c[2] + c[0] * (y % 2) as f64);
                    for k in 3..6 {
                        p[k] += c[k];
                    }
                }
            }
        }
        sums = next;
        size = half;
    }
    levels
}

/// Index of cell (x, y) of `face` in a level `n` cells a side, faces side by
/// side along x.
fn v_index(face: usize, x: usize, y: usize, n: usize) -> usize {
    y * 6 * n + face * n + x
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_table_holds_the_catalogue_down_to_7_5_brightest_first() {
        let stars = parse(HIPPARCOS).unwrap();
        assert_eq!(stars.len(), 23_270);
        assert!(stars.windows(2).all(|w| w[0].mag <= w[1].mag));
        // Sirius first: HIP 32349, RA 6h45m09s, Dec -16d42m58s, Hp -1.09.
        let s = stars[0];
        assert!((s.ra.to_degrees() - 101.287).abs() < 0.01, "{s:?}");
        assert!((s.dec.to_degrees() + 16.716).abs() < 0.01, "{s:?}");
        assert!((s.mag + 1.09).abs() < 0.03, "{s:?}");
        assert!(stars.iter().all(|s| s.mag <= 7.5 + 1e-9));
    }

    #[test]
    fn a_bad_table_is_refused_with_a_reason() {
        assert!(parse(b"nope").is_err());
        let mut t = HIPPARCOS.to_vec();
        t.pop();
        let e = parse(&t).unwrap_err().to_string();
        assert!(e.contains("bytes"), "{e}");
    }

    #[test]
    fn galactic_axes_match_their_published_equatorial_places() {
        // The galactic centre at RA 266.405, Dec -28.936; the north galactic
        // pole at RA 192.859, Dec 27.128 (J2000, ESA SP-1200).
        let gc = to_galactic(equatorial_vector(
            266.405f64.to_radians(),
            (-28.936f64).to_radians(),
        ));
        assert!((gc - DVec3::X).length() < 1e-4, "{gc}");
        let ngp = to_galactic(equatorial_vector(
            192.859f64.to_radians(),
            27.128f64.to_radians(),
        ));
        assert!((ngp - DVec3::Z).length() < 1e-4, "{ngp}");
    }

    #[test]
    fn temperatures_follow_the_colour_index() {
        // The Sun (B-V 0.65) near 5,800 K; hot blue stars above 10,000 K.
        assert!((temperature_from_bv(0.65) - 5_800.0).abs() < 200.0);
        assert!(temperature_from_bv(-0.2) > 10_000.0);
        assert!(temperature_from_bv(1.5) < 4_000.0);
    }

    #[test]
    fn the_grid_keeps_every_star_s_flux_at_every_level() {
        let stars = parse(HIPPARCOS).unwrap();
        let total: f64 = stars.iter().map(|s| 10f64.powf(-0.4 * s.mag)).sum();
        let grid = star_grid(&stars);
        assert_eq!(grid.len(), 9);
        for level in &grid {
            // The light's luminance is the flux (colours have luminance 1).
            let sum: f64 = level
                .iter()
                .map(|t| {
                    0.212_639 * f64::from(t[1])
                        + 0.715_169 * f64::from(t[2])
                        + 0.072_192 * f64::from(t[3])
                })
                .sum();
            assert!((sum / total - 1.0).abs() < 1e-4, "{sum} vs {total}");
            assert!(level.iter().all(|t| {
                let (u, v) = unpack_place(t[0]);
                (0.0..=1.0).contains(&u) && (0.0..=1.0).contains(&v)
            }));
        }
    }

    #[test]
    fn a_place_survives_packing_to_a_ten_thousandth_of_a_cell() {
        for (u, v) in [
            (0.0, 0.0),
            (1.0, 1.0),
            (0.1234, 0.8765),
            (0.5, 0.999),
            (0.999, 0.001),
        ] {
            let (pu, pv) = unpack_place(pack_place(u, v));
            assert!(
                (pu - u).abs() < 2e-4 && (pv - v).abs() < 3e-4,
                "{u} {v} -> {pu} {pv}"
            );
        }
    }

    #[test]
    fn a_star_s_colour_follows_its_temperature() {
        let lut = crate::physics::blackbody::lut_rgba();
        let (red, blue) = (star_colour(&lut, 3_000.0), star_colour(&lut, 20_000.0));
        assert!(red[0] > red[2] && blue[2] > blue[0]);
        let exact = crate::physics::blackbody::blackbody_srgb(5_800.0);
        let table = star_colour(&lut, 5_800.0);
        for k in 0..3 {
            assert!(
                (exact[k] - table[k]).abs() < 1e-3 * exact[k].max(0.1),
                "{exact:?} {table:?}"
            );
        }
    }
}
