//! `blackhole trace`: photon paths in a hole's equatorial plane for a fan of
//! impact parameters around the critical one, b_c = (3 sqrt 3 / 2) rs, drawn
//! from the f64 reference with the horizon, the photon sphere (1.5 rs) and the
//! innermost stable circular orbit (3 rs). Axes are in units of rs. For a
//! spinning hole the fan is split: rays passing on the side that turns with
//! the hole (prograde) and against it (retrograde), each around its own
//! critical impact parameter, drawn in closed form (Mino time,
//! `spacetime::kerr::equatorial_path`) in Boyer-Lindquist r and phi, with both circular photon
//! orbits and both ISCOs.

use std::path::Path;

use glam::DVec3;
use plotters::prelude::*;

use crate::physics::geodesic::{Hole, Outcome, TraceOptions, trace};
use crate::scene::Scene;
use crate::spacetime::kerr as kerr_path;
use crate::spacetime::radii;
use crate::{Error, Result};

/// `blackhole trace`: writes the SVG for the scene (or preset) named.
pub fn run(scene: Option<&str>, out: &Path) -> Result<std::process::ExitCode> {
    let scene = super::load_scene(scene)?;
    super::outputs::Output {
        flag: "--out",
        path: out,
        extensions: &["svg"],
        what: "SVG",
    }
    .check(&scene.input_files(), None)?;
    write_svg(&scene, out)?;
    println!("wrote {}", out.display());
    Ok(std::process::ExitCode::SUCCESS)
}

/// Impact parameters drawn, as multiples of b_c.
pub const FAN: [f64; 14] = [
    0.3, 0.6, 0.85, 0.95, 0.99, 0.999, 1.001, 1.01, 1.05, 1.15, 1.3, 1.6, 2.2, 3.0,
];

/// Multiples of each side's critical impact parameter drawn around a
/// spinning hole (both sides: twice as many paths, so fewer each).
pub const KERR_FAN: [f64; 7] = [0.6, 0.95, 0.99, 1.01, 1.05, 1.3, 2.0];

/// Mino-time samples along a spinning hole's path.
const KERR_SAMPLES: u32 = 4000;

/// One drawn path: impact parameter (units of rs), captured or not, and the
/// polylines (units of rs) that lie inside the plot.
pub struct PhotonPath {
    pub b: f64,
    pub captured: bool,
    pub pieces: Vec<Vec<(f64, f64)>>,
}

/// Clips segment p-q to the square [-e, e]² (Liang-Barsky); None if outside.
fn clip(p: (f64, f64), q: (f64, f64), e: f64) -> Option<((f64, f64), (f64, f64))> {
    let (dx, dy) = (q.0 - p.0, q.1 - p.1);
    let (mut t0, mut t1) = (0.0f64, 1.0f64);
    for (den, num) in [(-dx, p.0 + e), (dx, e - p.0), (-dy, p.1 + e), (dy, e - p.1)] {
        if den == 0.0 {
            if num < 0.0 {
                return None;
            }
        } else {
            let t = num / den;
            if den < 0.0 {
                t0 = t0.max(t);
            } else {
                t1 = t1.min(t);
            }
        }
    }
    (t0 <= t1).then(|| {
        let at = |t: f64| (p.0 + t * dx, p.1 + t * dy);
        (at(t0), at(t1))
    })
}

/// The parts of a polyline inside [-e, e]², as separate polylines.
fn clip_polyline(points: &[(f64, f64)], e: f64) -> Vec<Vec<(f64, f64)>> {
    let mut pieces: Vec<Vec<(f64, f64)>> = Vec::new();
    for w in points.windows(2) {
        let Some((a, b)) = clip(w[0], w[1], e) else {
            continue;
        };
        match pieces.last_mut() {
            Some(last) if last.last() == Some(&a) => last.push(b),
            _ => pieces.push(vec![a, b]),
        }
    }
    pieces
}

/// The fan `trace` draws for the first hole of `scene`: the non-rotating
/// hole's ([`photon_paths`]) or the spinning hole's equatorial paths
/// ([`kerr_photon_paths`]), inside the square of half-width `extent` rs.
pub fn scene_photon_paths(scene: &Scene, extent: f64) -> Vec<PhotonPath> {
    let (_, spin) = scene.first_hole();
    if spin == 0.0 {
        photon_paths(scene, extent)
    } else {
        kerr_photon_paths(spin, extent)
    }
}

/// Traces the fan for the first hole of `scene` (others are ignored: the plot
/// shows one hole's geometry). Rays come in from the left, moving along +x.
pub fn photon_paths(scene: &Scene, extent: f64) -> Vec<PhotonPath> {
    let rs = scene.black_holes.first().map_or(1.0, |h| h.rs);
    let hole = [Hole {
        position: DVec3::ZERO,
        rs,
    }];
    let bc = 1.5 * 3f64.sqrt() * rs;
    let start = 4.0 * extent * rs;
    let opts = TraceOptions {
        tolerance: 1e-10,
        escape_radius: start * 1.01,
        record_path: true,
        ..TraceOptions::default()
    };
    FAN.iter()
        .map(|k| {
            let b = k * bc;
            let r = trace(&hole, None, DVec3::new(-start, b, 0.0), DVec3::X, &opts);
            let points: Vec<(f64, f64)> = r.path.iter().map(|p| (p.x / rs, p.y / rs)).collect();
            PhotonPath {
                b: b / rs,
                captured: matches!(r.outcome, Outcome::Captured { .. }),
                pieces: clip_polyline(&points, extent),
            }
        })
        .collect()
}

/// Equatorial paths around a hole spinning at `a` (a* != 0), coming in
/// from the left along +x at heights y0 (units of rs): lambda = -y0, eta =
/// 0, r and phi in closed form from Mino time (forward in time: phi = phi0
/// + I_phi + lambda tau).
pub fn kerr_photon_paths(a: f64, extent: f64) -> Vec<PhotonPath> {
    let start = 2.0 * 4.0 * extent; // in M = rs / 2
    let mut out = Vec::new();
    for prograde in [true, false] {
        let lambda_c = radii::critical_lambda(a, prograde);
        for k in KERR_FAN {
            let lambda = k * lambda_c;
            let y0 = -lambda;
            let (r_o, phi_o) = ((start * start + y0 * y0).sqrt(), y0.atan2(-start));
            // A point only every 0.02 rs (the plot's resolution).
            let (points, captured) =
                kerr_path::equatorial_path(a, lambda, (r_o, phi_o), KERR_SAMPLES, 0.02);
            out.push(PhotonPath {
                b: 0.5 * lambda.abs(),
                captured,
                pieces: clip_polyline(&points, extent),
            });
        }
    }
    out
}

fn circle(r: f64) -> Vec<(f64, f64)> {
    (0..=360)
        .map(|i| {
            let a = f64::from(i).to_radians();
            (r * a.cos(), r * a.sin())
        })
        .collect()
}

/// A circle drawn dashed on the plot, with its legend.
struct Ring {
    r: f64,
    label: String,
    color: RGBColor,
    dash: (u32, u32),
    width: u32,
}

/// What one plot shows: the hole's circles, its horizon and the paths.
struct Plot {
    caption: String,
    rings: Vec<Ring>,
    horizon: f64,
    horizon_label: String,
    paths: Vec<PhotonPath>,
    captured_label: String,
    escaped_label: String,
}

fn plot_of(scene: &Scene, extent: f64) -> Plot {
    let grey = RGBColor(120, 120, 120);
    let orange = RGBColor(230, 120, 0);
    let (_, spin) = scene.first_hole();
    if spin == 0.0 {
        return Plot {
            caption: "Photon paths around a Schwarzschild hole (b in units of rs)".into(),
            rings: vec![
                Ring {
                    r: 3.0,
                    label: "ISCO, 3 rs".into(),
                    color: grey,
                    dash: (6, 4),
                    width: 1,
                },
                Ring {
                    r: 1.5,
                    label: "photon sphere, 1.5 rs".into(),
                    color: orange,
                    dash: (4, 3),
                    width: 2,
                },
            ],
            horizon: 1.0,
            horizon_label: "horizon, rs".into(),
            paths: photon_paths(scene, extent),
            captured_label: "captured (b < b_c = 2.598 rs)".into(),
            escaped_label: "escapes (b > b_c)".into(),
        };
    }
    let a = spin.abs();
    let purple = RGBColor(140, 60, 170);
    let (pro, retro) = (
        radii::photon_orbit(1.0, a, true),
        radii::photon_orbit(1.0, a, false),
    );
    let (isco_pro, isco_retro) = (radii::isco(1.0, a), radii::isco(1.0, -a));
    let horizon = radii::horizon(1.0, spin);
    Plot {
        caption: format!(
            "Equatorial photon paths around a hole spinning at a* = {spin} (Boyer-Lindquist r, phi; rs)"
        ),
        rings: vec![
            Ring {
                r: isco_pro,
                label: format!("ISCO prograde {isco_pro:.3} rs, retrograde {isco_retro:.3} rs"),
                color: grey,
                dash: (6, 4),
                width: 1,
            },
            Ring {
                r: isco_retro,
                label: String::new(),
                color: grey,
                dash: (6, 4),
                width: 1,
            },
            Ring {
                r: pro,
                label: format!("prograde photon orbit, {pro:.3} rs"),
                color: orange,
                dash: (4, 3),
                width: 2,
            },
            Ring {
                r: retro,
                label: format!("retrograde photon orbit, {retro:.3} rs"),
                color: purple,
                dash: (4, 3),
                width: 2,
            },
        ],
        horizon,
        horizon_label: format!("horizon, {horizon:.3} rs"),
        paths: kerr_photon_paths(spin, extent),
        captured_label: "captured (|lambda| inside its side's critical value)".into(),
        escaped_label: "escapes (prograde below, retrograde above)".into(),
    }
}

/// Draws the plot as SVG text.
pub fn render_svg(scene: &Scene) -> Result<String> {
    let extent = 10.0;
    let plot = plot_of(scene, extent);
    let mut svg = String::new();
    {
        let plot_err =
            |e: &dyn std::fmt::Display| Error::Other(format!("drawing the photon paths: {e}"));
        let root = SVGBackend::with_string(&mut svg, (800, 800)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| plot_err(&e))?;
        let mut chart = ChartBuilder::on(&root)
            .caption(&plot.caption, ("sans-serif", 18))
            .margin(15)
            .x_label_area_size(40)
            .y_label_area_size(50)
            .build_cartesian_2d(-extent..extent, -extent..extent)
            .map_err(|e| plot_err(&e))?;
        chart
            .configure_mesh()
            .x_desc("x / rs")
            .y_desc("y / rs")
            .light_line_style(WHITE.mix(0.0))
            .draw()
            .map_err(|e| plot_err(&e))?;

        chart
            .draw_series(std::iter::once(Polygon::new(
                circle(plot.horizon),
                BLACK.filled(),
            )))
            .map_err(|e| plot_err(&e))?
            .label(plot.horizon_label.as_str())
            .legend(|(x, y)| Rectangle::new([(x, y - 5), (x + 20, y + 5)], BLACK.filled()));

        for ring in &plot.rings {
            let color = ring.color;
            let series = chart
                .draw_series(DashedLineSeries::new(
                    circle(ring.r),
                    ring.dash.0,
                    ring.dash.1,
                    color.stroke_width(ring.width),
                ))
                .map_err(|e| plot_err(&e))?;
            if !ring.label.is_empty() {
                series
                    .label(ring.label.as_str())
                    .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], color));
            }
        }
        let (red, blue) = (RGBColor(200, 30, 30), RGBColor(30, 80, 200));
        let mut labelled = (false, false);
        for p in &plot.paths {
            let color = if p.captured { red } else { blue };
            let series = chart
                .draw_series(
                    p.pieces
                        .iter()
                        .map(|piece| PathElement::new(piece.clone(), color.stroke_width(1))),
                )
                .map_err(|e| plot_err(&e))?;
            if p.captured && !labelled.0 {
                labelled.0 = true;
                series
                    .label(plot.captured_label.as_str())
                    .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], red));
            } else if !p.captured && !labelled.1 {
                labelled.1 = true;
                series
                    .label(plot.escaped_label.as_str())
                    .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], blue));
            }
        }
        chart
            .configure_series_labels()
            .background_style(WHITE.mix(0.85))
            .border_style(BLACK)
            .position(SeriesLabelPosition::LowerRight)
            .draw()
            .map_err(|e| plot_err(&e))?;
        root.present().map_err(|e| plot_err(&e))?;
    }
    Ok(svg)
}

/// Writes the plot to `path` (atomically).
pub fn write_svg(scene: &Scene, path: &Path) -> Result<()> {
    let svg = render_svg(scene)?;
    crate::output::write_atomically(path, |tmp| {
        std::fs::write(tmp, svg.as_bytes()).map_err(|source| Error::Io {
            path: path.to_owned(),
            source,
        })
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_fan_is_split_at_b_c_and_clipping_keeps_points_inside() {
        let paths = photon_paths(&Scene::default(), 10.0);
        for p in &paths {
            assert_eq!(p.captured, p.b < 1.5 * 3f64.sqrt(), "b = {}", p.b);
            assert!(!p.pieces.is_empty(), "b = {} crosses the plot", p.b);
            for piece in &p.pieces {
                assert!(
                    piece
                        .iter()
                        .all(|(x, y)| x.abs() <= 10.0 + 1e-9 && y.abs() <= 10.0 + 1e-9)
                );
            }
        }
        let svg = render_svg(&Scene::default()).expect("SVG");
        assert!(svg.starts_with("<svg") && svg.contains("photon sphere"));
    }

    #[test]
    fn a_spinning_hole_splits_the_fan_at_each_sides_critical_value() {
        for spin in [0.9, -0.6] {
            let paths = kerr_photon_paths(spin, 10.0);
            assert_eq!(paths.len(), 2 * KERR_FAN.len());
            for (i, p) in paths.iter().enumerate() {
                let k = KERR_FAN[i % KERR_FAN.len()];
                assert_eq!(p.captured, k < 1.0, "spin {spin}, path {i}, k {k}");
                assert!(!p.pieces.is_empty(), "spin {spin}, path {i}");
            }
            // Prograde rays pass closer: their critical value is smaller.
            let (pro, retro) = (
                paths[0].b / KERR_FAN[0],
                paths[KERR_FAN.len()].b / KERR_FAN[0],
            );
            assert!(pro < 2.598 && retro > 2.598, "{pro} {retro}");
        }
        let scene = Scene::from_toml("[[black_hole]]\nspin = 0.9\n", "t.toml").expect("scene");
        let svg = render_svg(&scene).expect("SVG");
        assert!(svg.contains("prograde photon orbit") && svg.contains("retrograde photon orbit"));
    }
}
