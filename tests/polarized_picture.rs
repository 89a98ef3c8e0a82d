//! The polarized picture and its numbers (docs/polarization.md, "The
//! picture", "The numbers"), on any device: the field models side by side
//! are each the model drawn alone, the m87 preset draws a ring with ticks and
//! the beam, the beam depolarizes, a radial or a toroidal field turns beta_2
//! as the EVPA pattern it makes must, and bad requests are refused by name.

mod common;

const CAMERA: &str = r#"
[[black_hole]]
spin = 0.5

[camera]
position = [120.0, -700.0, 0.0]
look_at  = [0.0, 0.0, 0.0]
up       = [0.0, 0.0, 1.0]
vfov_deg = 2.0

[disk]
kind = "thin"
inner_radius = 2.5
outer_radius = 6.0
"#;

fn scene(polarization: &str) -> String {
    format!("{CAMERA}\n[polarization]\n{polarization}\n")
}

#[test]
fn side_by_side_fields_are_each_field_alone() {
    let fields = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0], [0.0, 0.3, 1.0]];
    let list: Vec<String> = fields
        .iter()
        .map(|f| format!("[{}, {}, {}]", f[0], f[1], f[2]))
        .collect();
    let (w, h) = (20, 18);
    let (_, all) = common::render_aov_named(
        "stokes",
        &scene(&format!("fields = [{}]", list.join(", "))),
        3 * w,
        h,
        &[],
    );
    for (t, f) in list.iter().enumerate() {
        let (_, alone) =
            common::render_aov_named("stokes", &scene(&format!("field = {f}")), w, h, &[]);
        let mut lit = 0;
        for y in 0..h {
            for x in 0..w {
                let a = alone.get_pixel(x, y).0;
                let b = all.get_pixel(t as u32 * w + x, y).0;
                lit += usize::from(a[0] > 0.0);
                for c in 0..4 {
                    let tol = 1e-6 * a[0].abs().max(1e-30);
                    assert!(
                        (a[c] - b[c]).abs() <= tol,
                        "field {f}, pixel ({x}, {y}) channel {c}: alone {} side by side {}",
                        a[c],
                        b[c]
                    );
                }
            }
        }
        assert!(lit > 20, "field {f}: only {lit} pixels on the disk");
    }
}

#[test]
fn the_m87_picture_is_a_ring_with_ticks_and_the_beam() {
    let dir = common::scratch();
    let img = common::render_png(&dir, "m87", common::SceneSrc::Preset("m87"), 128, 128);
    let px = |x: u32, y: u32| img.get_pixel(x, y).0.map(f64::from);
    let lum = |p: [f64; 3]| p[0] + p[1] + p[2];
    // The shadow's middle is darker than the ring around it (afmhot: dark
    // red to white), at the same radius on four sides.
    let centre = lum(px(64, 64));
    let ring: f64 = [(64, 40), (64, 88), (40, 64), (88, 64)]
        .iter()
        .map(|&(x, y)| lum(px(x, y)))
        .fold(f64::INFINITY, f64::min);
    assert!(
        centre < 0.8 * ring,
        "centre {centre}, dimmest ring sample {ring}"
    );
    // afmhot never has more blue than red: blue-green pixels are the ticks
    // (left of the fraction's bar at the right edge).
    let ticks = (0..128)
        .flat_map(|y| (0..112).map(move |x| (x, y)))
        .filter(|&(x, y)| {
            let p = px(x, y);
            p[2] > p[0] + 40.0
        })
        .count();
    assert!(ticks > 100, "{ticks} tick pixels");
    // The beam's circle (white) in the lower left quarter.
    let white = (64..128)
        .flat_map(|y| (0..64).map(move |x| (x, y)))
        .filter(|&(x, y)| px(x, y).iter().all(|&c| c > 200.0))
        .count();
    assert!(white > 20, "{white} white pixels of the beam's circle");
}

/// The numbers of a 64 x 36 `--aov stokes` of the test's camera.
fn numbers(polarization: &str) -> serde_json::Value {
    let dir = common::scratch();
    let out = common::path_in(&dir, "stokes.exr");
    let json = common::path_in(&dir, "numbers.json");
    let mut c = common::render_scene(&dir, &scene(polarization), &["--aov", "stokes"]);
    c.arg("--out").arg(&out).arg("--json").arg(&json);
    let (code, stdout, stderr) = common::run(c);
    common::assert_clean(code, &stdout, &stderr);
    assert!(
        stdout.contains("|m|_net") && stdout.contains("arg beta_2"),
        "{stdout}"
    );
    serde_json::from_str(&std::fs::read_to_string(&json).expect("JSON written")).expect("JSON")
}

#[test]
fn the_beam_depolarizes_and_beta2_follows_the_field() {
    let doc =
        numbers("fields = [[1.0, 0.0, 0.0], [0.0, 1.0, 0.0]]\nbeam = 20.0\nannulus = [2.0, 15.0]");
    let pictures = doc["pictures"].as_array().expect("pictures");
    assert_eq!(pictures.len(), 2, "{doc}");
    let f = |p: &serde_json::Value, which: &str, key: &str| p[which][key].as_f64().unwrap();
    for p in pictures {
        let (sharp, blurred) = (f(p, "unblurred", "m_mean"), f(p, "blurred", "m_mean"));
        // Nothing depolarizes the emission but the beam: <|m|> is the
        // emitted fraction, and lower through the beam.
        assert!((sharp - 0.7).abs() < 1e-4, "{p}");
        assert!(blurred < 0.95 * sharp, "{p}");
        // The net polarization is a sum: the beam keeps it (to its edge losses).
        let (n0, n1) = (f(p, "unblurred", "m_net"), f(p, "blurred", "m_net"));
        assert!((n0 - n1).abs() <= 0.05 * n0.max(1e-3), "{p}");
    }
    // A radial field draws a toroidal EVPA pattern (beta_2 negative real);
    // a toroidal one a radial pattern (positive real): to within what the
    // 17 degree tilt, the motion and the bending turn.
    let radial = f(&pictures[0], "unblurred", "beta2_phase_deg").abs();
    let toroidal = f(&pictures[1], "unblurred", "beta2_phase_deg").abs();
    assert!(radial > 150.0, "radial field: arg beta_2 {radial}");
    assert!(toroidal < 30.0, "toroidal field: arg beta_2 {toroidal}");
}

#[test]
fn polarized_requests_that_cannot_be_met_are_refused_by_name() {
    let dir = common::scratch();
    let flat = format!("{}\n[physics]\ngravity = false\n", scene("enabled = true"));
    let e = common::refused_early(common::render_scene(&dir, &flat, &[]));
    assert!(
        e.contains("polarization.enabled") && e.contains("gravity"),
        "{e}"
    );
    let out = common::path_in(&dir, "pol.exr");
    let mut c = common::render_scene(&dir, &scene("enabled = true"), &[]);
    c.arg("--out").arg(&out);
    let e = common::refused_early(c);
    assert!(e.contains("8 bits") && e.contains("--aov stokes"), "{e}");
    let json = common::path_in(&dir, "n.json");
    let mut c = common::render_scene(&dir, &scene(""), &[]);
    c.arg("--json").arg(&json);
    let e = common::refused_early(c);
    assert!(e.contains("--json") && e.contains("--aov stokes"), "{e}");
    for bad in [
        "beam = -1.0",
        "ticks = 500",
        "annulus = [5.0, 2.0]",
        "mass_msun = 0.0",
        "colormap = \"jet\"",
        "fields = [[0.0, 0.0, 0.0]]",
    ] {
        let e = common::refused_early(common::render_scene(&dir, &scene(bad), &[]));
        let key = bad.split(' ').next().unwrap_or(bad);
        assert!(e.contains("polarization.") || e.contains(key), "{bad}: {e}");
    }
    assert!(!out.exists() && !json.exists());
}
