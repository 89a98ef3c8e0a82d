//! Who holds the camera: how a pixel's direction, measured in the observer's
//! own orthonormal frame, becomes the ray's initial coordinate direction, and
//! how the observer's clock and motion scale the redshift it measures.
//!
//! - `Static`: at rest at its position. With r̂ the unit vector from the hole,
//!   d_r = d·r̂ and d_t = d - d_r r̂, the coordinate direction is
//!   normalize(√(1 - rs/r) d_r r̂ + d_t); a pixel at angle ψ from r̂ then
//!   has impact parameter b = r sin ψ / √(1 - rs/r) (Synge 1966). It measures
//!   g = g∞ / √(1 - rs/r).
//! - `Orbiting`: on the circular geodesic orbit through its position around
//!   the disk's axis, co-rotating with the disk, at speed √(rs / (2(r - rs)))
//!   in the static frame (r > 1.5 rs).
//! - `Falling`: falling radially from rest at infinity, speed √(rs/r) inward.
//!   Around one hole its pixels become rays by the rain form
//!   ([`super::rain`]), outside, at and inside the horizon, which needs no
//!   static frame: the coordinate direction normalize((v + d_r) r̂ + d_t)
//!   and g = g∞ / (1 + v d_r), the same as the aberrated static frame's
//!   outside (and, near the horizon, without its Lorentz factor's loss of
//!   digits). A pixel with 1 + v d_r <= 0 (inside only) sees light from
//!   the other universe.
//! - `Flat`: the pixel direction is the coordinate direction and g = g∞
//!   (what simple renderers do).
//!
//! Moving observers: the static frame's direction after relativistic
//! aberration, d_s = (d/γ - β + γ/(γ+1) (β·d) β) / (1 - β·d), and the Doppler
//! factor γ (1 + β·d_s) on top of the static observer's g.
//!
//! Several holes: the static frame is that of the hole nearest the camera
//! (its rs and centre); exact for one hole, an approximation otherwise, like
//! the summed light-path equation.

use glam::DVec3;
use serde::{Deserialize, Serialize};

use super::geodesic::Hole;

/// `[camera] observer`.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum ObserverKind {
    #[default]
    Static = 0,
    Orbiting = 1,
    Falling = 2,
    Flat = 3,
    /// The zero-angular-momentum observer of a spinning hole (at spin 0 the
    /// static one).
    Zamo = 4,
}

impl ObserverKind {
    pub const ALL: [ObserverKind; 5] = [
        ObserverKind::Static,
        ObserverKind::Zamo,
        ObserverKind::Orbiting,
        ObserverKind::Falling,
        ObserverKind::Flat,
    ];

    pub fn name(self) -> &'static str {
        match self {
            ObserverKind::Static => "static",
            ObserverKind::Orbiting => "orbiting",
            ObserverKind::Falling => "falling",
            ObserverKind::Flat => "flat",
            ObserverKind::Zamo => "zamo",
        }
    }
}

/// An observer at one place: everything the pixel-to-ray mapping needs.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct Observer {
    pub kind: ObserverKind,
    /// Unit vector from the reference hole to the camera.
    pub rhat: DVec3,
    /// √(1 - rs/r) (1 for `Flat` or with gravity off; 0 inside the horizon).
    pub lapse: f64,
    /// Velocity in the static frame, in world axes (|β| < 1).
    pub beta: DVec3,
    /// A falling observer of one hole: its fall speed v = √(rs/r) (above 1
    /// inside the horizon), for the rain form.
    pub rain: Option<f64>,
}

/// Speed of the circular geodesic orbit at r in the static frame.
pub fn orbit_speed(r: f64, rs: f64) -> f64 {
    (rs / (2.0 * (r - rs))).sqrt()
}

/// Speed of a radial fall from rest at infinity, in the static frame.
pub fn fall_speed(r: f64, rs: f64) -> f64 {
    (rs / r).sqrt()
}

/// The hole whose static frame the observer uses: the nearest.
pub fn reference_hole(holes: &[Hole], position: DVec3) -> Option<&Hole> {
    holes.iter().min_by(|a, b| {
        (a.position - position)
            .length()
            .total_cmp(&(b.position - position).length())
    })
}

impl Observer {
    /// The observer of `kind` at `position`. `disk_normal` sets the orbit's
    /// sense; with gravity off every observer is in flat space (lapse 1) and
    /// only its velocity remains.
    pub fn new(
        kind: ObserverKind,
        position: DVec3,
        holes: &[Hole],
        disk_normal: DVec3,
        gravity: bool,
    ) -> Observer {
        let Some(hole) = reference_hole(holes, position) else {
            return Observer {
                kind: ObserverKind::Flat,
                rhat: DVec3::Z,
                lapse: 1.0,
                beta: DVec3::ZERO,
                rain: None,
            };
        };
        let rel = position - hole.position;
        let r = rel.length();
        let rhat = rel / r;
        let lapse = if gravity && kind != ObserverKind::Flat {
            (1.0 - hole.rs / r).max(0.0).sqrt()
        } else {
            1.0
        };
        let beta = match kind {
            ObserverKind::Static | ObserverKind::Flat | ObserverKind::Zamo => DVec3::ZERO,
            ObserverKind::Falling => -fall_speed(r, hole.rs).min(0.999_999) * rhat,
            ObserverKind::Orbiting => {
                let along = disk_normal.normalize().cross(rhat);
                if along.length() < 1e-9 || r <= 1.5 * hole.rs {
                    DVec3::ZERO
                } else {
                    orbit_speed(r, hole.rs).min(0.999_999) * along.normalize()
                }
            }
        };
        let rain = (gravity && kind == ObserverKind::Falling && holes.len() == 1)
            .then(|| fall_speed(r, hole.rs));
        Observer {
            kind,
            rhat,
            lapse,
            beta,
            rain,
        }
    }

    /// The energy at infinity per unit of the frequency this observer sees,
    /// E / ω, of light arriving along pixel direction `d`: 1 + v d_r in the
    /// rain form (at most 0: from the other universe), else positive.
    pub fn energy(&self, d: DVec3) -> f64 {
        match self.rain {
            Some(v) => 1.0 + v * d.dot(self.rhat),
            None => 1.0 / self.g_factor(d),
        }
    }

    fn gamma(&self) -> f64 {
        1.0 / (1.0 - self.beta.length_squared()).sqrt()
    }

    /// The static frame's unit direction of a pixel seen in the observer's
    /// frame as `d` (relativistic aberration).
    pub fn static_direction(&self, d: DVec3) -> DVec3 {
        let b = self.beta;
        if b == DVec3::ZERO {
            return d;
        }
        let g = self.gamma();
        let bd = b.dot(d);
        ((d / g - b + (g / (g + 1.0)) * bd * b) / (1.0 - bd)).normalize()
    }

    /// The ray's initial coordinate direction for pixel direction `d`.
    pub fn coordinate_direction(&self, d: DVec3) -> DVec3 {
        if self.kind == ObserverKind::Flat {
            return d;
        }
        if let Some(v) = self.rain {
            let dr = d.dot(self.rhat);
            return ((v + dr) * self.rhat + (d - dr * self.rhat)).normalize();
        }
        let ds = self.static_direction(d);
        let dr = ds.dot(self.rhat);
        let dt = ds - dr * self.rhat;
        (self.lapse * dr * self.rhat + dt).normalize()
    }

    /// What multiplies the redshift g∞ (seen from rest at infinity) of light
    /// arriving along pixel direction `d`, to give the g this observer
    /// measures: γ (1 + β·d_s) / √(1 - rs/r).
    pub fn g_factor(&self, d: DVec3) -> f64 {
        if self.kind == ObserverKind::Flat {
            return 1.0;
        }
        if let Some(v) = self.rain {
            // (E < 0: light from the other universe, against its infinity.)
            let e = 1.0 + v * d.dot(self.rhat);
            return 1.0 / e.abs().max(1e-6);
        }
        let doppler = if self.beta == DVec3::ZERO {
            1.0
        } else {
            self.gamma() * (1.0 + self.beta.dot(self.static_direction(d)))
        };
        doppler / self.lapse
    }
}
