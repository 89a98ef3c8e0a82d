use super::*;
use crate::physics::kerr::polarized::stokes;
use crate::physics::kerr::r_isco;
use crate::physics::sphere_direction;

/// Transporting the photon's own covector is the geodesic equation: the
/// Christoffel form meets the Hamiltonian flow (dual-number gradients).
#[test]
fn transporting_the_photon_is_the_geodesic_flow() {
    for (a, x, p) in [
        (0.9, DVec3::new(3.0, -2.0, 1.5), DVec3::new(0.3, -0.7, 0.2)),
        (0.0, DVec3::new(-5.0, 1.0, 0.4), DVec3::new(-0.1, 0.4, 0.9)),
        (-0.6, DVec3::new(1.2, 1.9, -0.8), DVec3::new(0.5, 0.5, -0.5)),
    ] {
        let p_t = -1.1;
        let (_, dp) = backward(x, p, p_t, a);
        let rate = transport_rate(x, a, [p_t, p.x, p.y, p.z], [p_t, p.x, p.y, p.z]);
        assert!(rate[0].abs() < 1e-13, "{a}: p_T changes: {}", rate[0]);
        let got = DVec3::new(rate[1], rate[2], rate[3]);
        assert!(
            (got + dp).length() < 1e-12 * (1.0 + dp.length()),
            "{a}: {got} vs {}",
            -dp
        );
    }
}

/// The closed form (the Walker-Penrose constant) and the step-by-step
/// parallel transport agree ray by ray: the angle to 1e-6 rad and I to
/// 1e-6 relative, over cameras far, near and in the ergoregion, several
/// spins (0 among them) and observers (falling through the horizon too),
/// wherever sin(theta_B) and |k_z| are
/// above 1e-2.
#[test]
fn the_walker_penrose_constant_meets_the_transported_vector() {
    let em = Emission::default();
    let mut compared = 0;
    for (spin, at, obs) in [
        (0.9, DVec3::new(1.0, 2.0, -10.0), KerrObserver::Zamo),
        (0.0, DVec3::new(0.5, 1.5, -8.0), KerrObserver::Static),
        (-0.7, DVec3::new(2.0, -1.0, -6.0), KerrObserver::Falling),
        (0.99, DVec3::new(0.8, 0.1, 0.2), KerrObserver::Zamo),
        (0.5, DVec3::new(-3.0, 0.8, 1.0), KerrObserver::Orbiting),
        // Falling between the horizons (Boyer-Lindquist r = 0.67 r+ of
        // a* = 0.9, 0.63 rs of a* = 0) and in the band just outside
        // (1.015 r+ of a* = 0.7): the falling frame's own photons.
        (0.9, DVec3::new(0.1, 0.25, -0.55), KerrObserver::Falling),
        (0.0, DVec3::new(0.3, 0.35, -0.42), KerrObserver::Falling),
        (0.7, DVec3::new(0.0, 0.3, -0.88), KerrObserver::Falling),
    ] {
        let disk = KerrDisk {
            inner: r_isco(spin) / 2.0,
            outer: 8.0,
        };
        let up = DVec3::new(0.1, 1.0, 0.2).normalize();
        let before = compared;
        for k in 0..160 {
            let d = sphere_direction(k, 160);
            let want = stokes_transported(at, d, up, spin, obs, disk, &em)
                .expect("placed")
                .stokes;
            let got = stokes(at, d, up, spin, obs, disk, &em)
                .expect("placed")
                .stokes;
            if want.i == 0.0 && got.i == 0.0 {
                continue;
            }
            let near = stokes(
                at,
                (d + 1e-6 * DVec3::X).normalize(),
                up,
                spin,
                obs,
                disk,
                &em,
            )
            .expect("placed")
            .stokes;
            if (near.i == 0.0) != (got.i == 0.0) {
                continue; // at the annulus's or the shadow's edge
            }
            agree(&format!("{spin} {at} {obs:?} {d}"), &want, &got);
            compared += 1;
        }
        assert!(
            compared - before >= 5,
            "{spin} {at} {obs:?}: {} rays",
            compared - before
        );
    }
    assert!(compared > 100, "{compared}");
}

/// The volumetric disk's samples off the equator: where the transported
/// path crosses a plane Z = h, the closed form's sample there (the photon
/// from its constants and the signs the path has there, the Walker-Penrose
/// constant solved at the camera) meets the transport: the angle to 1e-6
/// rad and I to 1e-6 relative, above and below the plane, several spins
/// and observers, wherever sin(theta_B) is above 1e-2.
#[test]
fn each_volume_sample_in_closed_form_meets_the_transported_vector() {
    use crate::physics::kerr::observer_velocity;
    use crate::physics::kerr::polarized::volume::{SamplePoint, sample_stokes};
    let em = Emission {
        field: DVec3::new(0.3, 0.8, 0.5).normalize(),
        ..Emission::default()
    };
    let mut compared = 0;
    for (spin, at, obs, height) in [
        (0.9, DVec3::new(1.0, 2.0, -10.0), KerrObserver::Zamo, 0.6),
        (0.0, DVec3::new(0.5, 1.5, -8.0), KerrObserver::Static, -0.9),
        (
            -0.7,
            DVec3::new(2.0, -1.0, -6.0),
            KerrObserver::Falling,
            1.5,
        ),
        (
            0.5,
            DVec3::new(-3.0, 0.8, 1.0),
            KerrObserver::Orbiting,
            -0.4,
        ),
    ] {
        let disk = KerrDisk {
            inner: r_isco(spin) / 2.0,
            outer: 8.0,
        };
        let up = DVec3::new(0.1, 1.0, 0.2).normalize();
        let beta = observer_velocity(obs, 2.0 * at, spin).expect("placed");
        let before = compared;
        for k in 0..120 {
            let d = sphere_direction(k, 120);
            let Some(want) = volume_sample_transported(at, d, up, spin, beta, height, disk, &em)
            else {
                continue;
            };
            let point = SamplePoint {
                r: want.r,
                cos_theta: want.cos_theta,
                s_r: want.s_r,
                s_theta: want.s_theta,
            };
            let got = sample_stokes(at, d, up, spin, obs, point, disk.inner, &em).expect("placed");
            if want.sin_b < 1e-2 {
                continue;
            }
            let (want, got) = (want.stokes, got.stokes);
            agree(&format!("{spin} {at} {obs:?} {height} {d}"), &want, &got);
            compared += 1;
        }
        assert!(
            compared - before >= 5,
            "{spin} {at} {obs:?}: {} rays",
            compared - before
        );
    }
    assert!(compared > 40, "{compared}");
}

/// The closed form `got` meets the transport `want`: I to 1e-6 relative,
/// the angle to 1e-6 rad.
fn agree(what: &str, want: &Stokes, got: &Stokes) {
    assert!(
        (want.i - got.i).abs() < 1e-6 * want.i,
        "{what}: I {} vs {}",
        got.i,
        want.i
    );
    let dchi = (2.0 * (want.angle() - got.angle())).sin().abs() / 2.0;
    assert!(
        dchi < 1e-6,
        "{what}: chi {} vs {}",
        got.angle(),
        want.angle()
    );
}
