//! `blackhole trace`: photon paths in a hole's equatorial plane for a fan of
//! impact parameters around the critical one, b_c = (3 sqrt 3 / 2) rs, drawn
//! from the f64 reference with the horizon, the photon sphere (1.5 rs) and the
//! innermost stable circular orbit (3 rs). Axes are in units of rs.

use std::path::Path;

use glam::DVec3;
use plotters::prelude::*;

use crate::physics::geodesic::{Hole, Outcome, TraceOptions, trace};
use crate::scene::Scene;
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

fn circle(r: f64) -> Vec<(f64, f64)> {
    (0..=360)
        .map(|i| {
            let a = f64::from(i).to_radians();
            (r * a.cos(), r * a.sin())
        })
        .collect()
}

/// Draws the plot as SVG text.
pub fn render_svg(scene: &Scene) -> Result<String> {
    let extent = 10.0;
    let paths = photon_paths(scene, extent);
    let mut svg = String::new();
    {
        let plot_err =
            |e: &dyn std::fmt::Display| Error::Other(format!("drawing the photon paths: {e}"));
        let root = SVGBackend::with_string(&mut svg, (800, 800)).into_drawing_area();
        root.fill(&WHITE).map_err(|e| plot_err(&e))?;
        let mut chart = ChartBuilder::on(&root)
            .caption(
                "Photon paths around a Schwarzschild hole (b in units of rs)",
                ("sans-serif", 20),
            )
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

        let grey = RGBColor(120, 120, 120);
        chart
            .draw_series(DashedLineSeries::new(
                circle(3.0),
                6,
                4,
                grey.stroke_width(1),
            ))
            .map_err(|e| plot_err(&e))?
            .label("ISCO, 3 rs")
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], grey));
        let orange = RGBColor(230, 120, 0);
        chart
            .draw_series(DashedLineSeries::new(
                circle(1.5),
                4,
                3,
                orange.stroke_width(2),
            ))
            .map_err(|e| plot_err(&e))?
            .label("photon sphere, 1.5 rs")
            .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], orange));
        chart
            .draw_series(std::iter::once(Polygon::new(circle(1.0), BLACK.filled())))
            .map_err(|e| plot_err(&e))?
            .label("horizon, rs")
            .legend(|(x, y)| Rectangle::new([(x, y - 5), (x + 20, y + 5)], BLACK.filled()));

        let (red, blue) = (RGBColor(200, 30, 30), RGBColor(30, 80, 200));
        let mut labelled = (false, false);
        for p in &paths {
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
                    .label("captured (b < b_c = 2.598 rs)")
                    .legend(move |(x, y)| PathElement::new([(x, y), (x + 20, y)], red));
            } else if !p.captured && !labelled.1 {
                labelled.1 = true;
                series
                    .label("escapes (b > b_c)")
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
}
