//! `render --aov stokes`'s numbers: each field model's picture measured
//! (`crate::polarimetry`) as it is and through the scene's beam, printed and
//! with `--json` written.

use std::path::Path;

use crate::frame::{Frame, Pixels};
use crate::polarimetry::{Figures, Plane, StokesImage};
use crate::{Error, Result, Scene};

/// One picture's numbers.
#[derive(serde::Serialize)]
struct Measured {
    field: [f64; 3],
    unblurred: Figures,
    /// Through the beam (absent without one).
    blurred: Option<Figures>,
}

/// Measures `frame` (a Stokes AOV of `scene`), prints the figures and
/// writes them to `json` when given.
pub fn report(scene: &Scene, frame: &Frame, json: Option<&Path>) -> Result<()> {
    let Pixels::Rgba32F(rgba) = &frame.pixels else {
        return Err(Error::Other(
            "the Stokes AOV was not read back as floats".into(),
        ));
    };
    let p = &scene.polarization;
    let mut measured = Vec::new();
    for ((x0, x1), field) in scene
        .picture_columns(frame.width)
        .into_iter()
        .zip(p.models())
    {
        let (w, h) = (x1 - x0, frame.height);
        let plane = Plane {
            width: w as usize,
            height: h as usize,
            scale: scene.image_plane_scale(&scene.camera, w, h),
            annulus: p.annulus,
        };
        let image =
            StokesImage::from_rgba(rgba, frame.width as usize, x0 as usize, x1 as usize, plane);
        let sigma = scene.beam_sigma_pixels(w, h);
        measured.push(Measured {
            field,
            unblurred: image.figures(),
            blurred: (sigma > 0.0).then(|| image.blurred(sigma).figures()),
        });
    }
    let scale = scene.image_plane_scale(
        &scene.camera,
        frame.width / measured.len().max(1) as u32,
        frame.height,
    );
    println!(
        "polarimetry (annulus {} to {} GM/c^2; {:.4} GM/c^2 = {:.4} uas a pixel; beam {} uas):",
        p.annulus[0],
        p.annulus[1],
        scale,
        scale * p.gravitational_angle_uas(),
        p.beam
    );
    let line = |f: &Figures| {
        format!(
            "|m|_net {:.4}  <|m|> {:.4}  |beta_2| {:.4}  arg beta_2 {:+.1} deg",
            f.m_net, f.m_mean, f.beta2_amplitude, f.beta2_phase_deg
        )
    };
    for m in &measured {
        let [x, y, z] = m.field;
        println!("  field [{x}, {y}, {z}]");
        println!("    unblurred   {}", line(&m.unblurred));
        match &m.blurred {
            Some(b) => println!("    beam {:>4} uas {}", p.beam, line(b)),
            None => println!("    (no beam: set [polarization] beam, microarcseconds)"),
        }
    }
    if let Some(path) = json {
        let doc = serde_json::json!({
            "annulus_gm": p.annulus,
            "gm_per_pixel": scale,
            "uas_per_gm": p.gravitational_angle_uas(),
            "beam_uas": p.beam,
            "pictures": measured,
        });
        let text = serde_json::to_string_pretty(&doc)
            .map_err(|e| Error::Other(format!("writing the Stokes numbers as JSON: {e}")))?;
        super::profile::write_text(path, &text)?;
        println!("wrote {}", path.display());
    }
    Ok(())
}
