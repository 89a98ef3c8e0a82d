//! The fall's law against closed forms and an independent quadrature.

use super::*;
use crate::physics::Hole;
use crate::spacetime::Body;

/// A hole of rs 1 at the origin spinning at `spin` about +y.
fn hole(spin: f64) -> Spacetime {
    let hole = Hole {
        position: DVec3::ZERO,
        rs: 1.0,
    };
    Spacetime::new(&[Body { hole, spin }], true, DVec3::Y)
}

fn falling(spin: f64, start: f64, line: DVec3) -> Fall {
    hole(spin).fall(start, line, ObserverKind::Falling)
}

/// Into a spinning hole the film follows the falling observers' proper
/// time: on the axis (Sigma = r^2 + a^2) dtau = sqrt((r^2 + a^2) / (2 r))
/// dr, on the equator r^2 / sqrt(2 r (r^2 + a^2)) dr, integrated here
/// independently (a 4096-step midpoint sum); at a tiny spin it is the
/// non-rotating law.
#[test]
fn a_spinning_fall_follows_its_proper_time() {
    let midpoint = |f: &dyn Fn(f64) -> f64, r0: f64, r1: f64| {
        let n = 4096;
        let h = (r1 - r0) / f64::from(n);
        (0..n)
            .map(|i| f(r0 + (f64::from(i) + 0.5) * h))
            .sum::<f64>()
            * h
    };
    let a = 0.9;
    // On the axis the distance is r (rs); from 4 rs to 0.3 rs, M = 1/2.
    let axis = falling(a, 4.0, DVec3::Y).proper_time(0.3, 4.0);
    let want = 0.5 * midpoint(&|r| ((r * r + a * a) / (2.0 * r)).sqrt(), 0.6, 8.0);
    assert!((axis - want).abs() < 1e-8 * want, "{axis} vs {want}");
    // On the equator the distance is sqrt(r^2 + a^2) (rs, a = 0.45 rs).
    let (d0, d1) = (
        (0.3f64.powi(2) + 0.45f64.powi(2)).sqrt(),
        (16.0f64 + 0.2025).sqrt(),
    );
    let eq = falling(a, d1, DVec3::Z).proper_time(d0, d1);
    let want = 0.5 * midpoint(&|r| r * r / (2.0 * r * (r * r + a * a)).sqrt(), 0.6, 8.0);
    assert!((eq - want).abs() < 1e-8 * want, "{eq} vs {want}");
    let tiny = falling(1e-9, 4.0, DVec3::new(0.6, 0.0, 0.8)).proper_time(0.3, 4.0);
    let law = 2.0 / 3.0 * (4f64.powf(1.5) - 0.3f64.powf(1.5));
    assert!((tiny - law).abs() < 1e-9 * law, "{tiny} vs {law}");
    // The fall's clock inverts it: half the fraction, half the time.
    let fall = falling(a, 4.0, DVec3::Y);
    let d = fall.distance_after(0.5, 0.3);
    let half = fall.proper_time(d, 4.0);
    assert!(
        (half - 0.5 * axis).abs() < 1e-9 * axis,
        "{half} vs {}",
        0.5 * axis
    );
    assert_eq!(fall.distance_after(1.0, 0.3), 0.3);
}

/// The radius along the line and the distance at a radius are inverses,
/// and the radius is Boyer-Lindquist's: on the axis the distance itself, on
/// the equator sqrt(d^2 - a^2).
#[test]
fn radius_and_distance_along_the_line_are_boyer_lindquist() {
    let a = 0.45;
    for (line, want) in [(DVec3::Y, 2.0), (DVec3::Z, (4.0f64 - a * a).sqrt())] {
        let fall = falling(0.9, 10.0, line);
        assert!((fall.radius_at(2.0) - want).abs() < 1e-14, "{line}");
        assert!((fall.distance_at(fall.radius_at(2.0)) - 2.0).abs() < 1e-14);
    }
    let tilted = falling(0.9, 10.0, DVec3::new(0.0, 0.6, 0.8));
    for r in [0.3, 0.7, 1.5, 6.0] {
        assert!((tilted.radius_at(tilted.distance_at(r)) - r).abs() < 1e-13);
    }
}

/// Where a fall ends: a non-rotating hole's falling camera at 0.05 rs, a
/// spinning hole's at 1.01 (1 + 1e-3) r- on its line, any other observer at
/// 1.05 times the horizon's distance; and the ends it refuses.
#[test]
fn the_end_and_its_refusals() {
    let r_plus: f64 = 0.5 * (1.0 + 0.19f64.sqrt());
    let outside = hole(0.9).fall(20.0, DVec3::NEG_Z, ObserverKind::Static);
    let end = 1.05 * (r_plus * r_plus + 0.45 * 0.45).sqrt();
    assert!((outside.end(None) - end).abs() < 1e-12);
    assert!(!outside.interior());
    let r_end = 1.01 * 1.001 * 0.5 * 0.81 / (2.0 * r_plus);
    for (line, rho) in [
        (DVec3::NEG_Z, (r_end * r_end + 0.45 * 0.45).sqrt()),
        (DVec3::Y, r_end),
    ] {
        let fall = falling(0.9, 20.0, line);
        assert!((fall.end(None) - rho).abs() < 1e-12, "{line}");
        assert!((fall.radius_at(fall.end(None)) - r_end).abs() < 1e-12);
        assert_eq!(fall.check_end(fall.end(None)), Ok(()));
    }
    assert_eq!(falling(0.0, 20.0, DVec3::Z).end(None), FALLING_MIN_R);
    assert_eq!(falling(0.0, 20.0, DVec3::Z).end(Some(2.0)), 2.0);
    assert_eq!(
        falling(0.0, 20.0, DVec3::Z).check_end(0.01),
        Err(EndRefusal::TooClose)
    );
    assert!(matches!(
        falling(0.9, 20.0, DVec3::Y).check_end(0.1),
        Err(EndRefusal::TooDeep { .. })
    ));
    // A fall only goes inward: an end at or beyond the start is refused.
    assert_eq!(
        falling(0.0, 20.0, DVec3::Z).check_end(20.0),
        Err(EndRefusal::NotInward { start: 20.0 })
    );
    assert_eq!(falling(0.0, 20.0, DVec3::Z).check_end(19.9), Ok(()));
    assert!(matches!(
        outside.check_end(0.5),
        Err(EndRefusal::Inside { .. })
    ));
    // Several holes, gravity off or another observer: no interior.
    let two = Spacetime::new(
        &[
            Body {
                hole: Hole {
                    position: DVec3::ZERO,
                    rs: 1.0,
                },
                spin: 0.0,
            },
            Body {
                hole: Hole {
                    position: DVec3::X * 10.0,
                    rs: 1.0,
                },
                spin: 0.0,
            },
        ],
        true,
        DVec3::Y,
    );
    assert!(!two.fall(20.0, DVec3::Z, ObserverKind::Falling).interior());
    assert_eq!(
        two.fall(20.0, DVec3::Z, ObserverKind::Falling).end(None),
        1.05
    );
}

/// The free-fall law: r^(3/2) falls linearly in proper time, through the
/// horizon where the closed form says.
#[test]
fn a_fall_follows_the_free_fall_law_through_the_horizon() {
    let fall = falling(0.0, 20.0, DVec3::NEG_Z);
    let end = fall.end(None);
    let r = |f: f64| fall.distance_after(f, end);
    assert!((r(0.0) - 20.0).abs() < 1e-12);
    assert!((r(1.0) - 0.05).abs() < 1e-12);
    let frac = (20f64.powf(1.5) - 1.0) / (20f64.powf(1.5) - 0.05f64.powf(1.5));
    assert!((r(frac) - 1.0).abs() < 1e-9, "{}", r(frac));
    let lin = |f: f64| r(f).powf(1.5);
    assert!(((lin(0.2) - lin(0.4)) - (lin(0.6) - lin(0.8))).abs() < 1e-9);
    assert!(fall.inside_horizon(0.99) && !fall.inside_horizon(1.01));
}
