//! Light paths: x'' = -1.5 rs h² x / r⁵ (h = |x × x'|, x from the hole),
//! summed over holes, integrated in f64 with the Dormand-Prince 5(4) pair
//! (Dormand & Prince 1980) and local error control.
//!
//! Events are located precisely: the disk-plane crossing by root finding on
//! re-integrated partial steps; escape far enough (1e8 rs by default) that
//! the remaining bending is below 1e-15 rad, so the final direction is the
//! asymptotic one.
//!
//! Conserved along a one-hole path: h = |x × x'| and
//! v∞² = |x'|² - rs h² / r³, so the impact parameter is b = h / v∞.

use glam::DVec3;

/// One hole.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Hole {
    pub position: DVec3,
    pub rs: f64,
}

/// The thin disk, centred on the first hole.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Disk {
    pub normal: DVec3,
    pub inner: f64,
    pub outer: f64,
}

/// Integration settings.
#[derive(Clone, Copy, Debug)]
pub struct TraceOptions {
    /// Local relative error tolerance.
    pub tolerance: f64,
    /// Radius (from every hole) past which an outgoing ray has escaped.
    pub escape_radius: f64,
    /// Step budget (accepted and rejected steps).
    pub max_steps: usize,
    /// Keep every accepted point (for plots).
    pub record_path: bool,
}

impl Default for TraceOptions {
    fn default() -> Self {
        TraceOptions {
            tolerance: 1e-12,
            escape_radius: 1e8,
            max_steps: 1_000_000,
            record_path: false,
        }
    }
}

/// Where a ray went.
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Outcome {
    /// Left for infinity with this asymptotic unit direction.
    Escaped { direction: DVec3 },
    /// Fell through a horizon (index of the hole).
    Captured { hole: usize },
    /// Crossed the disk plane inside [inner, outer].
    Disk {
        position: DVec3,
        /// Ray tangent x' at the crossing (the photon moves along -x').
        velocity: DVec3,
    },
    /// Ran out of steps.
    NoSteps,
}

/// A traced ray.
#[derive(Clone, Debug)]
pub struct TraceResult {
    pub outcome: Outcome,
    pub steps: usize,
    pub path: Vec<DVec3>,
}

/// The acceleration of the light-path equation, summed over holes.
pub fn accel(holes: &[Hole], x: DVec3, v: DVec3) -> DVec3 {
    holes.iter().fold(DVec3::ZERO, |a, h| {
        let d = x - h.position;
        let r2 = d.length_squared();
        let h2 = d.cross(v).length_squared();
        a + d * (-1.5 * h.rs * h2 / (r2 * r2 * r2.sqrt()))
    })
}

#[derive(Clone, Copy)]
struct State {
    x: DVec3,
    v: DVec3,
    a: DVec3,
}

/// The Dormand-Prince 5(4) tableau: each stage's coefficients on the
/// earlier stages' derivatives, the fifth-order weights, and the error
/// weights (fifth minus fourth order; the last on the step's end, which the
/// next step reuses).
pub(crate) const DP_A: [&[f64]; 6] = [
    &[],
    &[1.0 / 5.0],
    &[3.0 / 40.0, 9.0 / 40.0],
    &[44.0 / 45.0, -56.0 / 15.0, 32.0 / 9.0],
    &[
        19372.0 / 6561.0,
        -25360.0 / 2187.0,
        64448.0 / 6561.0,
        -212.0 / 729.0,
    ],
    &[
        9017.0 / 3168.0,
        -355.0 / 33.0,
        46732.0 / 5247.0,
        49.0 / 176.0,
        -5103.0 / 18656.0,
    ],
];
pub(crate) const DP_B: [f64; 6] = [
    35.0 / 384.0,
    0.0,
    500.0 / 1113.0,
    125.0 / 192.0,
    -2187.0 / 6784.0,
    11.0 / 84.0,
];
pub(crate) const DP_E: [f64; 7] = [
    71.0 / 57600.0,
    0.0,
    -71.0 / 16695.0,
    71.0 / 1920.0,
    -17253.0 / 339200.0,
    22.0 / 525.0,
    -1.0 / 40.0,
];

/// sum of c[i] k[i], left to right, leaving out the zero weights.
fn weighted(c: &[f64], k: &[DVec3]) -> DVec3 {
    c.iter()
        .zip(k)
        .filter(|(c, _)| **c != 0.0)
        .map(|(c, k)| *c * *k)
        .reduce(|a, b| a + b)
        .unwrap_or(DVec3::ZERO)
}

/// One Dormand-Prince step; returns the new state and the error estimate
/// (position error, velocity error).
fn dopri(holes: &[Hole], s: State, h: f64) -> (State, f64, f64) {
    // Stage derivatives: of x (the velocities), of v (the accelerations).
    let (mut kv, mut ka) = (Vec::with_capacity(7), Vec::with_capacity(7));
    kv.push(s.v);
    ka.push(s.a);
    for coeffs in &DP_A[1..] {
        let x = s.x + h * weighted(coeffs, &kv);
        let v = s.v + h * weighted(coeffs, &ka);
        kv.push(v);
        ka.push(accel(holes, x, v));
    }
    let xn = s.x + h * weighted(&DP_B, &kv);
    let vn = s.v + h * weighted(&DP_B, &ka);
    let an = accel(holes, xn, vn);
    kv.push(vn);
    ka.push(an);
    let ex = h * weighted(&DP_E, &kv);
    let ev = h * weighted(&DP_E, &ka);
    (
        State {
            x: xn,
            v: vn,
            a: an,
        },
        ex.length(),
        ev.length(),
    )
}

fn nearest(holes: &[Hole], x: DVec3) -> f64 {
    holes
        .iter()
        .map(|h| (x - h.position).length())
        .fold(f64::INFINITY, f64::min)
}

/// Traces a ray from `x0` with initial tangent `v0` (any length; the camera
/// convention uses unit length).
pub fn trace(
    holes: &[Hole],
    disk: Option<&Disk>,
    x0: DVec3,
    v0: DVec3,
    opt: &TraceOptions,
) -> TraceResult {
    let centre = holes.first().map_or(DVec3::ZERO, |h| h.position);
    let plane = |x: DVec3| disk.map_or(0.0, |d| (x - centre).dot(d.normal));
    let mut s = State {
        x: x0,
        v: v0,
        a: accel(holes, x0, v0),
    };
    let mut path = Vec::new();
    if opt.record_path {
        path.push(x0);
    }
    let mut h = 0.01 * nearest(holes, x0).max(1.0);
    let tol = opt.tolerance;
    for step in 0..opt.max_steps {
        let (n, ex, ev) = dopri(holes, s, h);
        let scale_x = tol * (s.x - centre).length().max(1.0);
        let scale_v = tol * s.v.length().max(1e-6);
        let err = (ex / scale_x).max(ev / scale_v);
        if !err.is_finite() || err > 1.0 {
            let shrink = if err.is_finite() {
                (0.9 * err.powf(-0.2)).clamp(0.1, 0.9)
            } else {
                0.1
            };
            h *= shrink;
            continue;
        }

        if let Some(d) = disk {
            let (d0, d1) = (plane(s.x), plane(n.x));
            if (d0 < 0.0) != (d1 < 0.0) || d1 == 0.0 {
                // Root of the plane distance along the step, by bisection on
                // re-integrated partial steps (each as accurate as a full step).
                let (mut lo, mut hi) = (0.0f64, 1.0f64);
                let mut hit = n;
                for _ in 0..60 {
                    let mid = 0.5 * (lo + hi);
                    let (m, _, _) = dopri(holes, s, mid * h);
                    if (plane(m.x) < 0.0) == (d0 < 0.0) {
                        lo = mid;
                    } else {
                        hi = mid;
                        hit = m;
                    }
                }
                // A crossing inside a horizon (a hole in the disk's plane)
                // comes after the ray fell in.
                if let Some(i) = holes
                    .iter()
                    .position(|h| (hit.x - h.position).length() < h.rs)
                {
                    return TraceResult {
                        outcome: Outcome::Captured { hole: i },
                        steps: step + 1,
                        path,
                    };
                }
                let rho = (hit.x - centre).length();
                if rho >= d.inner && rho <= d.outer {
                    if opt.record_path {
                        path.push(hit.x);
                    }
                    return TraceResult {
                        outcome: Outcome::Disk {
                            position: hit.x,
                            velocity: hit.v,
                        },
                        steps: step + 1,
                        path,
                    };
                }
            }
        }

        for (i, hole) in holes.iter().enumerate() {
            if (n.x - hole.position).length() < hole.rs {
                if opt.record_path {
                    path.push(n.x);
                }
                return TraceResult {
                    outcome: Outcome::Captured { hole: i },
                    steps: step + 1,
                    path,
                };
            }
        }
        s = n;
        if opt.record_path {
            path.push(s.x);
        }
        let rmin = nearest(holes, s.x);
        if rmin > opt.escape_radius && (s.x - centre).dot(s.v) > 0.0 {
            return TraceResult {
                outcome: Outcome::Escaped {
                    direction: s.v.normalize(),
                },
                steps: step + 1,
                path,
            };
        }
        let grow = (0.9 * err.max(1e-12).powf(-0.2)).clamp(1.0, 5.0);
        h = (h * grow).min(0.5 * rmin);
    }
    TraceResult {
        outcome: Outcome::NoSteps,
        steps: opt.max_steps,
        path,
    }
}

/// Asymptotic speed v∞ of a one-hole path from its state: |x'|² - rs h²/r³.
pub fn speed_at_infinity(hole: &Hole, x: DVec3, v: DVec3) -> f64 {
    let d = x - hole.position;
    let r = d.length();
    let h2 = d.cross(v).length_squared();
    (v.length_squared() - hole.rs * h2 / (r * r * r))
        .max(0.0)
        .sqrt()
}

/// Photon angular momentum per energy about the disk axis, λ = L/E, for a ray
/// traced backwards with tangent `v` at `x` (the photon moves along -v).
/// Positive when the photon co-rotates with a disk turning counter-clockwise
/// seen from +normal.
pub fn photon_lambda(hole: &Hole, normal: DVec3, x: DVec3, v: DVec3) -> f64 {
    let d = x - hole.position;
    let vinf = speed_at_infinity(hole, x, v);
    d.cross(-v).dot(normal.normalize()) / vinf
}

/// Azimuth of a disk point in the disk frame: atan2 over a basis (e1, e2) of
/// the plane with e1 = x̂ projected (ẑ if the normal is along x), e2 = e1 × n;
/// for normal +y this is world atan2(z, x).
pub fn disk_azimuth(centre: DVec3, normal: DVec3, p: DVec3) -> f64 {
    let (e1, e2) = disk_basis(normal);
    let d = p - centre;
    d.dot(e2).atan2(d.dot(e1))
}

/// The disk frame's in-plane basis (see [`disk_azimuth`]).
pub fn disk_basis(normal: DVec3) -> (DVec3, DVec3) {
    let n = normal.normalize();
    let mut e1 = DVec3::X - n * n.x;
    if e1.length() < 1e-6 {
        e1 = DVec3::Z - n * n.z;
    }
    let e1 = e1.normalize();
    (e1, e1.cross(n))
}
