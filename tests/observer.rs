//! The observers against closed forms: the shadow's angular radius seen by a
//! static observer (Synge: sin ψ = (b_c / r) √(1 - rs/r)) and by one falling
//! from rest at infinity (the same edge after aberration), both in f64 and
//! on the GPU to 1e-5 rad; the aberration formula; and g of light from
//! infinity seen at rest, 1 / √(1 - rs/r).

mod common;

use blackhole::physics::closed_form::trace_closed;
use blackhole::physics::geodesic::{Hole, Outcome};
use blackhole::physics::observer::{Observer, ObserverKind, fall_speed, orbit_speed};
use common::{assert_clean, blackhole, path_in, run, scratch};
use glam::DVec3;

const RS: f64 = 1.0;
const B_CRIT: f64 = 2.598_076_211_353_316; // 3√3/2 rs

fn hole() -> Hole {
    Hole {
        position: DVec3::ZERO,
        rs: RS,
    }
}

/// Synge's angle between the shadow's edge and the direction to the hole,
/// for an observer at rest at r.
fn synge(r: f64) -> f64 {
    let s = B_CRIT / r * (1.0 - RS / r).sqrt();
    if r >= 1.5 * RS {
        s.asin()
    } else {
        std::f64::consts::PI - s.asin()
    }
}

/// The same edge seen by an observer falling straight in at speed β toward
/// the hole: cos ψ' = (cos ψ + β) / (1 + β cos ψ) (aberration toward the
/// direction of motion, which is the direction to the hole).
fn falling_edge(r: f64) -> f64 {
    let b = fall_speed(r, RS);
    let c = synge(r).cos();
    ((c + b) / (1.0 + b * c)).acos()
}

/// The camera at (0, 0, -r) looking along +z at the hole; the pixel
/// direction at angle ψ from +z, toward +x.
fn pixel(psi: f64) -> DVec3 {
    DVec3::new(psi.sin(), 0.0, psi.cos())
}

/// The edge by bisection on the f64 closed form, through the observer.
fn cpu_edge(kind: ObserverKind, r: f64) -> f64 {
    let x0 = DVec3::new(0.0, 0.0, -r);
    let obs = Observer::new(kind, x0, &[hole()], DVec3::Y, true);
    let captured = |psi: f64| {
        matches!(
            trace_closed(&hole(), None, x0, obs.coordinate_direction(pixel(psi))),
            Outcome::Captured { .. }
        )
    };
    let (mut lo, mut hi) = (1e-9, std::f64::consts::PI - 1e-9);
    assert!(captured(lo) && !captured(hi));
    for _ in 0..80 {
        let mid = 0.5 * (lo + hi);
        if captured(mid) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

#[test]
fn static_and_falling_shadow_edges_match_closed_forms_in_f64() {
    for r in [2.0, 4.0, 15.0, 100.0] {
        let e = cpu_edge(ObserverKind::Static, r);
        assert!(
            (e - synge(r)).abs() < 1e-9,
            "static r {r}: {e} vs {}",
            synge(r)
        );
        let e = cpu_edge(ObserverKind::Falling, r);
        assert!(
            (e - falling_edge(r)).abs() < 1e-9,
            "falling r {r}: {e} vs {}",
            falling_edge(r)
        );
        // The flat mapping draws a larger shadow (b = r sin ψ / √(1 - rs/r·sin²ψ)).
        assert!(cpu_edge(ObserverKind::Flat, r) > synge(r));
    }
}

#[test]
fn aberration_follows_the_formula_and_g_of_light_from_infinity() {
    let x0 = DVec3::new(3.0, 0.4, -5.0);
    let r = x0.length();
    let holes = [hole()];
    // At rest: 1 / √(1 - rs/r), whatever the direction.
    let st = Observer::new(ObserverKind::Static, x0, &holes, DVec3::Y, true);
    for d in [DVec3::X, DVec3::Y, -x0.normalize()] {
        assert!((st.g_factor(d) - 1.0 / (1.0 - RS / r).sqrt()).abs() < 1e-12);
    }
    for kind in [ObserverKind::Falling, ObserverKind::Orbiting] {
        let o = Observer::new(kind, x0, &holes, DVec3::Y, true);
        let speed = o.beta.length();
        let expected = if kind == ObserverKind::Falling {
            fall_speed(r, RS)
        } else {
            orbit_speed(r, RS)
        };
        assert!((speed - expected).abs() < 1e-12, "{kind:?} speed {speed}");
        let bhat = o.beta / speed;
        let gamma = 1.0 / (1.0 - speed * speed).sqrt();
        for i in 0..20 {
            // A direction at angle θ' from the motion, in the observer's frame.
            let t = 0.1 + 0.15 * f64::from(i);
            let side = bhat.any_orthonormal_vector();
            let d = t.cos() * bhat + t.sin() * side;
            let ds = o.static_direction(d);
            let expected = (t.cos() - speed) / (1.0 - speed * t.cos());
            assert!((ds.dot(bhat) - expected).abs() < 1e-12, "{kind:?} θ' {t}");
            // Aberration turns d toward beta within their plane.
            assert!(
                ds.dot(bhat.cross(side)).abs() < 1e-12,
                "{kind:?} θ' {t}: out of plane"
            );
            // Doppler: γ (1 + β cos θ_s) = 1 / (γ (1 - β cos θ')).
            let g = o.g_factor(d) * (1.0 - RS / r).sqrt();
            assert!((g - 1.0 / (gamma * (1.0 - speed * t.cos()))).abs() < 1e-12);
        }
    }
}

/// The GPU's shadow edge through its geodesic AOV: the camera looks at the
/// predicted edge with a field of view 4e-4 rad wide over 64 columns (6e-6
/// rad each); the edge found must be within 1e-5 rad of the closed form.
fn gpu_edge(observer: &str, r: f64, predicted: f64) -> f64 {
    const W: u32 = 64;
    const H: u32 = 4;
    let half_width = 2e-4;
    let vfov = 2.0 * (half_width / (f64::from(W) / f64::from(H))).atan();
    let look = DVec3::new(0.0, 0.0, -r) + pixel(predicted);
    let dir = scratch();
    let scene = path_in(&dir, "scene.toml");
    std::fs::write(
        &scene,
        format!(
            "[camera]\nposition = [0.0, 0.0, {}]\nlook_at = [{:.17e}, 0.0, {:.17e}]\nvfov_deg = {:.17e}\nobserver = \"{observer}\"\n[disk]\nkind = \"none\"\n[sky]\nkind = \"black\"\n",
            -r,
            look.x,
            look.z,
            vfov.to_degrees()
        ),
    )
    .unwrap();
    let out = path_in(&dir, "aov.exr");
    let mut c = blackhole();
    c.args([
        "render", "--aov", "geodesic", "--width", "64", "--height", "4",
    ])
    .arg("--scene")
    .arg(&scene)
    .arg("--out")
    .arg(&out);
    let (code, stdout, stderr) = run(c);
    assert_clean(code, &stdout, &stderr);
    let img = image::open(&out).unwrap().to_rgba32f();
    // Row 1: columns to the right look further from the hole.
    let outcome = |c: u32| img.get_pixel(c, 1).0[3];
    let first_escape = (0..W)
        .find(|&c| outcome(c) == 0.0)
        .expect("some column escapes");
    assert!(first_escape > 0, "{observer} r {r}: no captured column");
    assert!(
        (first_escape..W).all(|c| outcome(c) == 0.0)
            && (0..first_escape).all(|c| outcome(c) == 1.0),
        "{observer} r {r}: not one clean edge"
    );
    let sx = |c: u32| (2.0 * (f64::from(c) + 0.5) / f64::from(W) - 1.0) * half_width;
    predicted + 0.5 * (sx(first_escape - 1) + sx(first_escape)).atan()
}

#[test]
fn gpu_shadow_edges_match_closed_forms_to_1e5_rad() {
    for r in [2.0, 4.0, 15.0, 100.0] {
        let e = gpu_edge("static", r, synge(r));
        println!(
            "static  r {r:5}: Synge {:.7} rad, GPU edge {e:.7} (columns 6.25e-6 rad wide)",
            synge(r)
        );
        assert!(
            (e - synge(r)).abs() <= 1e-5,
            "static r {r}: {e} vs {}",
            synge(r)
        );
    }
    // 1.01 rs: where the fall used to stop (the camera now crosses the
    // horizon: the next test).
    for r in [1.01, 4.0, 15.0] {
        let p = falling_edge(r);
        let e = gpu_edge("falling", r, p);
        println!(
            "falling r {r:5}: aberrated Synge {p:.7} rad, GPU edge {e:.7} (columns 6.25e-6 rad wide)"
        );
        assert!((e - p).abs() <= 1e-5, "falling r {r}: {e} vs {p}");
    }
}

/// The edge of the black region seen by a camera falling from rest at
/// infinity at r <= rs, straight down (psi from the direction to the
/// hole), from the rain frame's constants alone: a pixel at psi has E / omega
/// = 1 - v cos psi and L / omega = r sin psi (v = sqrt(rs / r)), so b = r
/// sin psi / (1 - v cos psi), and light from the sky needs b < b_c. At the
/// crossing (v = 1) b = rs cot(psi / 2): the edge is 2 atan(rs / b_c) =
/// 42.10 degrees.
fn rain_edge(r: f64) -> f64 {
    let v = fall_speed(r, RS);
    let b = |psi: f64| r * psi.sin() / (1.0 - v * psi.cos());
    // Past the other universe's cone (1 - v cos psi > 0), b falls with psi.
    let (mut lo, mut hi) = ((1.0 / v).min(1.0).acos() + 1e-12, std::f64::consts::PI);
    for _ in 0..100 {
        let mid = 0.5 * (lo + hi);
        if b(mid) > B_CRIT {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    0.5 * (lo + hi)
}

/// A camera falling through the horizon: the GPU's shadow edge (the last
/// captured column before the sky) against the rain frame's closed form, to
/// 1e-5 rad, at the crossing (42.10 degrees, independent of any code) and
/// inside, halfway and a tenth of the way to the centre.
#[test]
fn gpu_shadow_edge_of_a_camera_falling_through_the_horizon() {
    let crossing = 2.0 * (RS / B_CRIT).atan();
    assert!((crossing.to_degrees() - 42.10).abs() < 0.005);
    assert!((rain_edge(RS) - crossing).abs() < 1e-12);
    for r in [1.0, 0.999, 0.5, 0.1] {
        let p = rain_edge(r);
        let e = gpu_edge("falling", r, p);
        println!(
            "falling r {r:5} (inside): rain frame {:.5} deg, GPU edge {:.5} deg",
            p.to_degrees(),
            e.to_degrees()
        );
        assert!((e - p).abs() <= 1e-5, "falling r {r}: {e} vs {p}");
    }
}
