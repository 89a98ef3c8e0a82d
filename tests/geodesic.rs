//! The GPU's geodesic AOV against the f64 CPU reference, ray by ray, for
//! several cameras and observers. Outcomes must agree except for rays within
//! 1e-3 rad of a shadow or disk edge; the escape direction, disk radius,
//! azimuth and redshift must agree to 1e-5 rad, 2e-4 rs, 1e-5 rad and 1e-5
//! (p99).
//!
//! Conditioning: the GPU starts from an f32 pixel direction, about 1e-7 rad
//! from the f64 one. Near the photon ring a ray's fate moves by much more
//! than 1e-5 for that nudge, so no f32 renderer can match there. Each ray's
//! condition is measured (the f64 closed form under 1e-7 rad nudges); the
//! percentiles are over the well-conditioned rays (nudge moves the result by
//! under a quarter of the tolerance), and every other ray must stay within
//! four times its own nudge sensitivity plus the tolerance.

mod common;

use blackhole::physics::closed_form::trace_closed;
use blackhole::physics::geodesic::{
    Disk, Hole, Outcome, TraceOptions, disk_azimuth, photon_lambda, trace,
};
use blackhole::physics::redshift::disk_redshift;
use glam::DVec3;

const DIR_TOL: f64 = 1e-5;
const RADIUS_TOL: f64 = 2e-4;
const G_TOL: f64 = 1e-5;

const W: u32 = 64;
const H: u32 = 36;

fn outcome_code(o: &Outcome) -> u32 {
    match o {
        Outcome::Escaped { .. } => 0,
        Outcome::Captured { .. } => 1,
        Outcome::Disk { .. } => 2,
        Outcome::NoSteps => 3,
    }
}

fn p99(v: &mut [f64]) -> f64 {
    if v.is_empty() {
        return 0.0;
    }
    v.sort_by(f64::total_cmp);
    v[((0.99 * v.len() as f64).ceil() as usize).clamp(1, v.len()) - 1]
}

struct Figures {
    rays: usize,
    edge: usize,
    /// Rays whose f32 rounding alone moves them past a quarter of the tolerance.
    ill_conditioned: usize,
    /// Outcome mismatches on rays whose outcome 1e-7 rad nudges do not change:
    /// real errors (a speckle), not f32 rounding.
    stable_mismatches: usize,
    /// GPU outcomes: escaped, captured, disk, out of steps.
    outcomes: [usize; 4],
    dir: Vec<f64>,
    radius: Vec<f64>,
    azimuth: Vec<f64>,
    g: Vec<f64>,
}

/// The f64 side of one camera: the scene's holes, thin disk and observer,
/// and the rays of its pixels traced by the integrator and, for one hole,
/// the closed form.
struct Reference {
    frame: blackhole::camera::CameraFrame,
    holes: Vec<Hole>,
    normal: DVec3,
    disk: Option<Disk>,
    observer: blackhole::physics::observer::Observer,
    opts: TraceOptions,
    /// One hole with gravity on: the closed form and the conditioning apply.
    closed_form: bool,
}

impl Reference {
    fn of(scene: &blackhole::Scene) -> Reference {
        let holes: Vec<Hole> = scene
            .black_holes
            .iter()
            .map(|h| Hole {
                position: DVec3::from(h.position),
                rs: h.rs,
            })
            .collect();
        let normal = DVec3::from(scene.disk.normal).normalize();
        let disk = Disk {
            normal,
            inner: scene.disk.inner_radius,
            outer: scene.disk.outer_radius,
        };
        Reference {
            frame: scene.camera.frame(),
            closed_form: holes.len() == 1 && scene.physics.gravity,
            holes,
            normal,
            disk: (scene.disk.kind == blackhole::scene::DiskKind::Thin).then_some(disk),
            observer: scene.observer(),
            opts: TraceOptions::default(),
        }
    }

    /// Pixel direction (the observer's frame) -> outcome, integrated.
    fn trace(&self, d: DVec3) -> Outcome {
        let v = self.observer.coordinate_direction(d);
        trace(
            &self.holes,
            self.disk.as_ref(),
            self.frame.position,
            v,
            &self.opts,
        )
        .outcome
    }

    /// The same in closed form.
    fn closed(&self, d: DVec3) -> Outcome {
        let v = self.observer.coordinate_direction(d);
        trace_closed(&self.holes[0], self.disk.as_ref(), self.frame.position, v)
    }

    /// What one disk hit's numbers are: radius, azimuth, g as the observer
    /// sees it.
    fn disk_numbers(&self, d: DVec3, position: DVec3, velocity: DVec3) -> (f64, f64, f64) {
        let hole = &self.holes[0];
        let r = (position - hole.position).length();
        let az = disk_azimuth(hole.position, self.normal, position);
        let lambda = photon_lambda(hole, self.normal, position, velocity);
        (
            r,
            az,
            disk_redshift(r, hole.rs, lambda) * self.observer.g_factor(d),
        )
    }

    /// The four 1e-7 rad nudges of a pixel direction.
    fn nudges(&self, d: DVec3, by: f64) -> [DVec3; 4] {
        let (u, v) = (self.frame.right, self.frame.up);
        [u, -u, v, -v].map(|n| (d + by * n).normalize())
    }

    /// How far 1e-7 rad nudges move a ray's result: (direction, radius, g).
    fn sensitivity(&self, d: DVec3) -> (f64, f64, f64) {
        if !self.closed_form {
            return (0.0, 0.0, 0.0);
        }
        let base = self.closed(d);
        let mut worst = (0.0f64, 0.0f64, 0.0f64);
        for dn in self.nudges(d, 1e-7) {
            match (base, self.closed(dn)) {
                (Outcome::Escaped { direction: a }, Outcome::Escaped { direction: b }) => {
                    worst.0 = worst.0.max(a.cross(b).length().atan2(a.dot(b)));
                }
                (
                    Outcome::Disk {
                        position: pa,
                        velocity: va,
                    },
                    Outcome::Disk {
                        position: pb,
                        velocity: vb,
                    },
                ) => {
                    let (ra, _, ga) = self.disk_numbers(d, pa, va);
                    let (rb, _, gb) = self.disk_numbers(dn, pb, vb);
                    worst.1 = worst.1.max((ra - rb).abs());
                    worst.2 = worst.2.max((ga - gb).abs());
                }
                _ => worst = (f64::INFINITY, f64::INFINITY, f64::INFINITY),
            }
        }
        worst
    }

    /// A pixel whose GPU outcome differs from the integrator's `cpu`: allowed
    /// only within 1e-3 rad of an edge (a nudged ray changes outcome);
    /// counted as a stable mismatch where 1e-7 rad nudges leave the closed
    /// form's outcome alone.
    fn mismatch(
        &self,
        name: &str,
        at: (u32, u32),
        d: DVec3,
        gpu_code: u32,
        cpu: Outcome,
        f: &mut Figures,
    ) {
        let near_edge = self
            .nudges(d, 1e-3)
            .iter()
            .any(|&dn| outcome_code(&self.trace(dn)) != outcome_code(&cpu));
        assert!(
            near_edge,
            "{name}: ray {at:?} GPU {gpu_code} vs CPU {cpu:?}, not near an edge"
        );
        f.edge += 1;
        if self.closed_form {
            let code = outcome_code(&self.closed(d));
            if self
                .nudges(d, 1e-7)
                .iter()
                .all(|&dn| outcome_code(&self.closed(dn)) == code)
            {
                println!(
                    "{name}: ray {at:?} GPU {gpu_code} vs CPU {cpu:?}, stable under 1e-7 nudges"
                );
                f.stable_mismatches += 1;
            }
        }
    }

    /// A pixel whose outcome matches: its numbers against the tolerances
    /// (well-conditioned rays into the percentiles, the others within four
    /// times their own nudge sensitivity plus the tolerance).
    fn numbers(
        &self,
        name: &str,
        at: (u32, u32),
        d: DVec3,
        px: [f32; 4],
        cpu: Outcome,
        f: &mut Figures,
    ) {
        let kappa = self.sensitivity(d);
        match cpu {
            Outcome::Escaped { direction } => {
                let g = DVec3::new(f64::from(px[0]), f64::from(px[1]), f64::from(px[2]));
                let err = g.cross(direction).length().atan2(g.dot(direction));
                if kappa.0 > DIR_TOL / 4.0 {
                    f.ill_conditioned += 1;
                    assert!(
                        err <= 4.0 * kappa.0 + DIR_TOL,
                        "{name}: ray {at:?} direction off by {err:e}, its 1e-7 nudge moves it {:e}",
                        kappa.0
                    );
                } else {
                    f.dir.push(err);
                }
            }
            Outcome::Disk { position, velocity } => {
                let (r, az, g) = self.disk_numbers(d, position, velocity);
                let (er, eg) = ((f64::from(px[0]) - r).abs(), (f64::from(px[2]) - g).abs());
                let daz = (f64::from(px[1]) - az).rem_euclid(std::f64::consts::TAU);
                if kappa.1 > RADIUS_TOL / 4.0 || kappa.2 > G_TOL / 4.0 {
                    f.ill_conditioned += 1;
                    assert!(
                        er <= 4.0 * kappa.1 + RADIUS_TOL && eg <= 4.0 * kappa.2 + G_TOL,
                        "{name}: ray {at:?} radius off by {er:e}, g by {eg:e}; its 1e-7 nudge moves them {:e}, {:e}",
                        kappa.1,
                        kappa.2
                    );
                } else {
                    f.radius.push(er);
                    f.azimuth.push(daz.min(std::f64::consts::TAU - daz));
                    f.g.push(eg);
                }
            }
            Outcome::Captured { .. } | Outcome::NoSteps => {
                assert_eq!(&px[..3], &[0.0, 0.0, 0.0]);
            }
        }
    }
}

fn compare(name: &str, position: [f64; 3], extra: &str) -> Figures {
    let vfov = if extra.contains("vfov_deg") {
        ""
    } else {
        "vfov_deg = 60.0\n"
    };
    let (scene, gpu) = common::render_aov(
        &format!(
            "[camera]\nposition = [{}, {}, {}]\n{vfov}{extra}",
            position[0], position[1], position[2]
        ),
        W,
        H,
    );
    let reference = Reference::of(&scene);
    let mut f = Figures {
        rays: 0,
        edge: 0,
        ill_conditioned: 0,
        stable_mismatches: 0,
        outcomes: [0; 4],
        dir: vec![],
        radius: vec![],
        azimuth: vec![],
        g: vec![],
    };
    let mut counts = [0usize; 4];
    for row in 0..H {
        for col in 0..W {
            f.rays += 1;
            let d = reference
                .frame
                .ray_dir(col, row, W, H)
                .expect("a pinhole ray");
            let cpu = reference.trace(d);
            let px = gpu.get_pixel(col, row).0;
            let gpu_code = px[3] as u32;
            assert!(
                gpu_code <= 3 && px[3] == gpu_code as f32,
                "alpha is an outcome code: {px:?}"
            );
            assert_ne!(
                gpu_code, 3,
                "GPU ray ({col},{row}) ran out of steps at default quality"
            );
            counts[gpu_code as usize] += 1;
            if gpu_code != outcome_code(&cpu) {
                reference.mismatch(name, (col, row), d, gpu_code, cpu, &mut f);
            } else {
                reference.numbers(name, (col, row), d, px, cpu, &mut f);
            }
        }
    }
    assert!(
        counts[0] > 0 && counts[1] > 0,
        "{name}: camera sees sky and shadow: {counts:?}"
    );
    f.outcomes = counts;
    f
}

#[test]
fn gpu_geodesic_aov_matches_the_f64_reference() {
    let cameras = [
        ("near", [0.0, 1.0, -6.0], "static"),
        ("far", [0.0, 2.0, -40.0], "static"),
        ("above", [0.0, 14.0, -4.0], "static"),
        ("edge-on", [0.0, 0.0, -15.0], "static"),
        ("near", [0.0, 1.0, -6.0], "orbiting"),
        ("near", [0.0, 1.0, -6.0], "falling"),
        ("near", [0.0, 1.0, -6.0], "flat"),
    ];
    for (camera, pos, observer) in cameras {
        let name = format!("{camera}/{observer}");
        let mut f = compare(&name, pos, &format!("observer = \"{observer}\"\n"));
        assert!(
            f.dir.len() >= 100 && f.radius.len() >= 20,
            "{name}: too few well-conditioned escapes ({}) or disk hits ({}) to measure",
            f.dir.len(),
            f.radius.len()
        );
        let (d, r, a, g) = (
            p99(&mut f.dir),
            p99(&mut f.radius),
            p99(&mut f.azimuth),
            p99(&mut f.g),
        );
        println!(
            "{name:16} rays {} (edge {}, ill-conditioned {}), escape dir p99 {d:.2e} rad ({} rays), disk radius p99 {r:.2e} rs, azimuth p99 {a:.2e} rad, g p99 {g:.2e} ({} disk rays)",
            f.rays,
            f.edge,
            f.ill_conditioned,
            f.dir.len(),
            f.radius.len()
        );
        assert!(f.edge * 10 < f.rays, "{name}: too many edge rays");
        assert!(
            f.ill_conditioned * 10 < f.rays,
            "{name}: too many ill-conditioned rays"
        );
        assert!(d <= DIR_TOL, "{name}: escape direction p99 {d:e}");
        assert!(r <= RADIUS_TOL, "{name}: disk radius p99 {r:e}");
        assert!(a <= 1e-5, "{name}: azimuth p99 {a:e}");
        assert!(g <= G_TOL, "{name}: redshift p99 {g:e}");
    }
}

/// The photon ring at high zoom: a 4e-4 rad field across the shadow's edge
/// (6e-6 rad a pixel) for a static camera at 15 rs, with the disk's plane
/// through the camera and the hole, so the rays just outside the edge wind
/// and cross the disk again and again: thinner and thinner images of the
/// disk, down to single pixels. Every ray whose fate 1e-7 rad nudges do not
/// change must have the f64 reference's outcome: no speckles.
#[test]
fn photon_ring_at_high_zoom_has_no_speckles() {
    let r: f64 = 15.0;
    let psi = (2.598_076_211_353_316 / r * (1.0 - 1.0 / r).sqrt()).asin();
    let (w, h) = (f64::from(W), f64::from(H));
    let vfov = 2.0 * (2e-4 / (w / h)).atan();
    // The look direction at Synge's angle from the hole, 0.3 rad round it.
    let look = [
        psi.sin() * 0.3f64.cos(),
        psi.sin() * 0.3f64.sin(),
        -r + psi.cos(),
    ];
    let extra = format!(
        "look_at = [{:.17e}, {:.17e}, {:.17e}]\nvfov_deg = {:.17e}\n[disk]\nnormal = [1.0, 0.0, 0.0]\n[sky]\nkind = \"black\"\n",
        look[0],
        look[1],
        look[2],
        vfov.to_degrees()
    );
    let f = compare("ring", [0.0, 0.0, -r], &extra);
    println!(
        "ring: rays {} (escaped, captured, disk: {:?}; outcome differs {}, of which stable under 1e-7 nudges {}), ill-conditioned {}, disk hits compared {}",
        f.rays,
        &f.outcomes[..3],
        f.edge,
        f.stable_mismatches,
        f.ill_conditioned,
        f.radius.len()
    );
    assert!(f.outcomes[2] > 0, "the zoomed view shows no disk image");
    assert_eq!(f.stable_mismatches, 0, "speckles in the photon ring");
}

/// Two holes take the general Cartesian integrator (accelerations summed, an
/// approximation of two-centre gravity that both sides share). The redshift
/// uses one-hole conserved quantities, so it is not compared here.
#[test]
fn two_holes_follow_the_f64_reference() {
    let extra = "[[black_hole]]\nposition = [-2.5, 0.0, 0.0]\nrs = 0.6\n\n[[black_hole]]\nposition = [2.5, 0.0, 0.0]\nrs = 0.6\n";
    let mut f = compare("binary", [0.0, 1.5, -15.0], extra);
    let (d, r, a) = (p99(&mut f.dir), p99(&mut f.radius), p99(&mut f.azimuth));
    println!(
        "binary           rays {} (edge {}), escape dir p99 {d:.2e} rad, disk radius p99 {r:.2e} rs, azimuth p99 {a:.2e} rad ({} disk rays)",
        f.rays,
        f.edge,
        f.radius.len()
    );
    assert!(f.edge * 10 < f.rays, "too many edge rays");
    assert!(
        d <= 1e-3 && r <= 1e-2 && a <= 1e-2,
        "binary: {d:e} {r:e} {a:e}"
    );
}

/// The accuracy-versus-cost table of docs/performance.md: the one-hole closed form,
/// and the general integrator (the binary preset's two holes) at three
/// tolerances, against the f64 reference. Run with
/// `cargo test --release --test geodesic -- --ignored --nocapture`; the
/// milliseconds come from `blackhole profile` on the same scenes.
#[test]
#[ignore = "docs/performance.md's accuracy table: minutes on lavapipe, run by hand with --ignored"]
fn accuracy_versus_quality() {
    let mut f = compare("default", [0.0, 0.8, -15.0], "");
    println!(
        "closed form (one hole): escape dir p99 {:.1e} rad, disk radius p99 {:.1e} rs",
        p99(&mut f.dir),
        p99(&mut f.radius)
    );
    for tol in ["1e-4", "1e-5", "1e-6"] {
        let extra = format!(
            "[[black_hole]]\nposition = [-2.5, 0.0, 0.0]\nrs = 0.6\n\n[[black_hole]]\nposition = [2.5, 0.0, 0.0]\nrs = 0.6\n[quality]\ntolerance = {tol}\n"
        );
        let mut f = compare("binary", [0.0, 1.5, -15.0], &extra);
        println!(
            "integrator (two holes), tolerance {tol}: escape dir p99 {:.1e} rad, disk radius p99 {:.1e} rs, edge rays {}",
            p99(&mut f.dir),
            p99(&mut f.radius),
            f.edge
        );
    }
}

/// Gravity off: every ray is the straight line along its coordinate
/// direction, so the reference is closed-form geometry written here (not the
/// shader's method): the first horizon the line enters, the disk plane
/// inside the annulus before it, else the sky in the ray's own direction.
/// Two holes, the second inside the disk's annulus, so some lines meet its
/// horizon before the disk's plane.
#[test]
fn straight_rays_follow_lines_through_horizons_and_the_disk() {
    let (scene, gpu) = common::render_aov(
        "[camera]\nposition = [0.0, 2.5, -8.0]\nvfov_deg = 70.0\n\n\
         [[black_hole]]\nposition = [0.0, 0.0, 0.0]\nrs = 1.0\n\n\
         [[black_hole]]\nposition = [6.0, 0.0, 1.0]\nrs = 0.8\n\n\
         [physics]\ngravity = false\n",
        W,
        H,
    );
    let frame = scene.camera.frame();
    let observer = scene.observer();
    let centre = DVec3::from(scene.black_holes[0].position);
    let normal = DVec3::from(scene.disk.normal).normalize();
    let (inner, outer) = (scene.disk.inner_radius, scene.disk.outer_radius);
    // (outcome code, escape direction or (radius, azimuth, 0)).
    let line = |d: DVec3| -> (u32, DVec3) {
        let v = observer.coordinate_direction(d).normalize();
        let x = frame.position;
        let mut t_h = f64::INFINITY;
        for h in &scene.black_holes {
            let rel = x - DVec3::from(h.position);
            let (b, cc) = (rel.dot(v), rel.length_squared() - h.rs * h.rs);
            let disc = b * b - cc;
            if disc > 0.0 && -b - disc.sqrt() > 0.0 {
                t_h = t_h.min(-b - disc.sqrt());
            }
        }
        let t_d = -(x - centre).dot(normal) / v.dot(normal);
        let p = x + t_d * v;
        let rho = (p - centre).length();
        if t_d > 0.0 && t_d < t_h && (inner..=outer).contains(&rho) {
            (2, DVec3::new(rho, disk_azimuth(centre, normal, p), 0.0))
        } else if t_h.is_finite() {
            (1, DVec3::ZERO)
        } else {
            (0, v)
        }
    };
    let (mut counts, mut edge) = ([0usize; 3], 0);
    let (mut dir_err, mut radius_err): (Vec<f64>, Vec<f64>) = (vec![], vec![]);
    for row in 0..H {
        for col in 0..W {
            let d = frame.ray_dir(col, row, W, H).expect("a pinhole ray");
            let (code, want) = line(d);
            let px = gpu.get_pixel(col, row).0;
            if px[3] as u32 != code {
                let e = 1e-4;
                let near_edge = [frame.right, -frame.right, frame.up, -frame.up]
                    .iter()
                    .any(|&n| line((d + e * n).normalize()).0 != code);
                assert!(near_edge, "ray ({col},{row}): GPU {} vs line {code}", px[3]);
                edge += 1;
                continue;
            }
            counts[code as usize] += 1;
            let got = DVec3::new(f64::from(px[0]), f64::from(px[1]), f64::from(px[2]));
            match code {
                0 => dir_err.push(got.cross(want).length().atan2(got.dot(want))),
                2 => radius_err.push((got.x - want.x).abs()),
                _ => assert_eq!(&px[..3], &[0.0, 0.0, 0.0]),
            }
        }
    }
    println!(
        "straight lines: outcomes {counts:?} (edge {edge}), escape dir p99 {:.2e} rad, disk radius p99 {:.2e} rs",
        p99(&mut dir_err),
        p99(&mut radius_err)
    );
    assert!(
        counts.iter().all(|&n| n >= 20),
        "the view must hold sky, horizons and disk: {counts:?}"
    );
    assert!(edge * 20 < (W * H) as usize, "too many edge rays: {edge}");
    assert!(p99(&mut dir_err) <= 1e-6, "escape direction");
    assert!(p99(&mut radius_err) <= 1e-4, "disk radius");
}
