//! Cameras: what a pixel sees. A projection maps a pixel (and a sub-pixel
//! jitter) to where its ray starts, its unit direction in the observer's own
//! frame, and the angle the pixel spans. This module is the only place on the
//! CPU that knows the pinhole (the binding camera convention: +y up, the
//! camera looks from `position` toward `look_at`, row 0 at the top), the
//! twin of `shaders/include/camera.glsl`. The observer turns a direction
//! into a coordinate direction (`physics::observer`).
//!
//! A new projection (an equirectangular panorama, a planetarium dome, one
//! eye of a stereo pair) is a new variant of [`Projection`] with its arm in
//! [`CameraFrame::pixel_ray`], and a function beside `pinhole()` in
//! camera.glsl chosen in `camera_ray()`.

use glam::DVec3;
use serde::{Deserialize, Serialize};

/// How pixels map to rays (`[camera] projection`).
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Projection {
    /// Every ray from one point through the image plane at distance 1.
    #[default]
    Pinhole = 0,
    /// The whole sphere around the camera, longitude across and latitude
    /// down, forward at the image's centre (2:1 for square pixels).
    Equirect = 1,
    /// Equidistant fisheye centred on forward, its image circle inscribed in
    /// the image; `vfov_deg` is the field across the circle (180: a dome
    /// master). Pixels outside the circle have no ray.
    Fisheye = 2,
}

impl Projection {
    pub const ALL: [Projection; 3] = [
        Projection::Pinhole,
        Projection::Equirect,
        Projection::Fisheye,
    ];

    pub fn name(self) -> &'static str {
        match self {
            Projection::Pinhole => "pinhole",
            Projection::Equirect => "equirect",
            Projection::Fisheye => "fisheye",
        }
    }

    /// Its number on the GPU (`PROJ_*`, a specialisation constant of the
    /// ray march).
    pub fn gpu_id(self) -> u32 {
        match self {
            Projection::Pinhole => PROJ_PINHOLE,
            Projection::Equirect => PROJ_EQUIRECT,
            Projection::Fisheye => PROJ_FISHEYE,
        }
    }

    /// Whether `vfov_deg` suits this projection: in (0, 180) for the
    /// pinhole, (0, 360] across a fisheye's circle; unused by the panorama.
    /// The rule's words where it does not.
    pub fn check_vfov(self, vfov_deg: f64) -> Result<(), &'static str> {
        match self {
            Projection::Pinhole if !(vfov_deg > 0.0 && vfov_deg < 180.0) => {
                Err("must be in (0, 180) degrees")
            }
            Projection::Fisheye if !(vfov_deg > 0.0 && vfov_deg <= 360.0) => {
                Err("must be in (0, 360] degrees for a fisheye (the field across its circle)")
            }
            // Unread by the panorama, checked all the same: every number of
            // a scene is one some mode could use (a NaN here once passed).
            Projection::Equirect if !(vfov_deg > 0.0 && vfov_deg <= 360.0) => Err(
                "must be in (0, 360] degrees (the panorama does not read it; every number is checked)",
            ),
            _ => Ok(()),
        }
    }

    /// The field of view a camera switching to this projection starts with:
    /// a fisheye as a dome master (180 degrees); a pinhole given a field it
    /// cannot show, 60 degrees; otherwise `vfov_deg` as it was.
    pub fn suited_vfov(self, vfov_deg: f64) -> f64 {
        match self {
            Projection::Fisheye => 180.0,
            Projection::Pinhole if vfov_deg >= 180.0 => 60.0,
            _ => vfov_deg,
        }
    }

    /// Whether it can hold a stereo pair (omni-directional stereo: the
    /// panorama only).
    pub fn takes_stereo(self) -> bool {
        self == Projection::Equirect
    }

    /// What it shows, in a line (the window's panel).
    pub fn description(self) -> &'static str {
        match self {
            Projection::Pinhole => "a flat image plane, vfov_deg top to bottom",
            Projection::Equirect => "the whole sky around the camera (2:1, vfov_deg unused)",
            Projection::Fisheye => "equidistant, vfov_deg across the circle (180: a dome master)",
        }
    }

    /// Whether every pixel of the image has a ray (a fisheye's corners,
    /// outside its circle, have none: black and transparent).
    pub fn every_pixel_has_a_ray(self) -> bool {
        self != Projection::Fisheye
    }

    /// The height of an image `width` wide that shows this projection whole
    /// (with `stereo`): `view_height` for the pinhole (any shape), half the
    /// width for a panorama (2:1), the width for a stereo pair of panoramas
    /// or a dome.
    pub fn natural_height(self, stereo: Stereo, width: u32, view_height: u32) -> u32 {
        match (self, stereo) {
            (Projection::Pinhole, _) => view_height,
            (Projection::Equirect, Stereo::None) => (width / 2).max(1),
            (Projection::Equirect, Stereo::Ods) | (Projection::Fisheye, _) => width,
        }
    }
}

/// The projections' numbers in the ray march (`shaders/include/camera.glsl`;
/// tests/layout.rs checks them against the GLSL source).
pub const PROJ_PINHOLE: u32 = 0;
pub const PROJ_EQUIRECT: u32 = 1;
pub const PROJ_FISHEYE: u32 = 2;
/// The stereo layouts' numbers (the parameter block's `camera.stereo`).
pub const STEREO_NONE: u32 = 0;
pub const STEREO_ODS: u32 = 1;

/// `[camera] stereo`: one image, or two eyes.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq, Deserialize, Serialize)]
#[serde(rename_all = "lowercase")]
pub enum Stereo {
    #[default]
    None = 0,
    /// Omni-directional stereo (with `equirect`): the left eye's panorama in
    /// the top half, the right eye's in the bottom, each column's ray from
    /// its eye's place on a circle of diameter `ipd` around the camera.
    Ods = 1,
}

impl Stereo {
    /// Its number on the GPU (`STEREO_*`).
    pub fn gpu_id(self) -> u32 {
        match self {
            Stereo::None => STEREO_NONE,
            Stereo::Ods => STEREO_ODS,
        }
    }
}

/// A pixel's ray.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct PixelRay {
    /// Where it starts (world).
    pub origin: DVec3,
    /// Unit direction in the observer's frame.
    pub dir: DVec3,
    /// The pixel's angular size, radians (unlensed).
    pub angle: f64,
}

/// An orthonormal camera frame, by the binding convention, and its
/// projection.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraFrame {
    pub position: DVec3,
    pub forward: DVec3,
    pub right: DVec3,
    pub up: DVec3,
    /// tan(vfov / 2) (the pinhole).
    pub tan_half_fov: f64,
    /// vfov / 2, radians (the fisheye's field from centre to circle).
    pub half_fov: f64,
    pub projection: Projection,
    pub stereo: Stereo,
    /// The distance between the two eyes (ODS), in rs.
    pub ipd: f64,
}

impl CameraFrame {
    /// The pinhole frame at `position` looking toward `look_at`: `forward =
    /// normalize(look_at - position)`, `right = normalize(cross(up,
    /// forward))`, `up = cross(forward, right)`.
    pub fn new(position: DVec3, look_at: DVec3, up: DVec3, vfov_deg: f64) -> Self {
        let forward = (look_at - position).normalize();
        let right = up.cross(forward).normalize();
        CameraFrame {
            position,
            forward,
            right,
            up: forward.cross(right),
            tan_half_fov: (vfov_deg.to_radians() * 0.5).tan(),
            half_fov: vfov_deg.to_radians() * 0.5,
            projection: Projection::Pinhole,
            stereo: Stereo::None,
            ipd: 0.0,
        }
    }

    /// The same frame with another projection (and stereo, `ipd`).
    pub fn with_projection(mut self, projection: Projection, stereo: Stereo, ipd: f64) -> Self {
        self.projection = projection;
        self.stereo = stereo;
        self.ipd = ipd;
        self
    }

    /// The height of one eye's image: half the image's for ODS (the left
    /// eye on top), else all of it.
    pub fn eye_height(&self, height: u32) -> u32 {
        match self.stereo {
            Stereo::Ods => (height / 2).max(1),
            Stereo::None => height.max(1),
        }
    }

    /// The ray through pixel (`col`, `row`) of a `width` x `height` image,
    /// row 0 at the top, offset by `jitter` pixels (0, 0: the centre; y
    /// down). `None` for a pixel with no ray (outside a fisheye's circle).
    pub fn pixel_ray(
        &self,
        col: u32,
        row: u32,
        width: u32,
        height: u32,
        jitter: (f64, f64),
    ) -> Option<PixelRay> {
        let (w, h) = (f64::from(width.max(1)), f64::from(height.max(1)));
        let c = f64::from(col) + 0.5 + jitter.0;
        let angle = self.pixel_angle(width, height);
        let along = |x: f64, y: f64, z: f64| x * self.right + y * self.up + z * self.forward;
        match self.projection {
            Projection::Pinhole => {
                let r = f64::from(row) + 0.5 + jitter.1;
                let sx = (2.0 * c / w - 1.0) * self.tan_half_fov * (w / h);
                let sy = (1.0 - 2.0 * r / h) * self.tan_half_fov;
                Some(PixelRay {
                    origin: self.position,
                    dir: (self.forward + sx * self.right + sy * self.up).normalize(),
                    angle,
                })
            }
            Projection::Equirect => {
                // ODS: the left eye's rows on top, the right eye's below.
                let eh = self.eye_height(height);
                let (eye, row) = match self.stereo {
                    Stereo::Ods if row >= eh => (1.0, (row - eh).min(eh - 1)),
                    Stereo::Ods => (-1.0, row),
                    Stereo::None => (0.0, row),
                };
                let r = f64::from(row) + 0.5 + jitter.1;
                let lon = (2.0 * c / w - 1.0) * std::f64::consts::PI;
                let lat = (1.0 - 2.0 * r / f64::from(eh)) * std::f64::consts::FRAC_PI_2;
                let (sl, cl) = lon.sin_cos();
                let (sa, ca) = lat.sin_cos();
                let offset = eye * 0.5 * self.ipd * along(cl, 0.0, -sl);
                Some(PixelRay {
                    origin: self.position + offset,
                    dir: along(ca * sl, sa, ca * cl).normalize(),
                    angle,
                })
            }
            Projection::Fisheye => {
                let r = f64::from(row) + 0.5 + jitter.1;
                let s = w.min(h);
                let x = (2.0 * c - w) / s;
                let y = (h - 2.0 * r) / s;
                let rho = x.hypot(y);
                if rho > 1.0 {
                    return None;
                }
                let theta = rho * self.half_fov;
                let (st, ct) = theta.sin_cos();
                // At the centre (rho = 0) the direction is forward.
                let (ux, uy) = if rho > 0.0 {
                    (x / rho, y / rho)
                } else {
                    (0.0, 0.0)
                };
                Some(PixelRay {
                    origin: self.position,
                    dir: along(st * ux, st * uy, ct).normalize(),
                    angle,
                })
            }
        }
    }

    /// The unit direction of the ray through the centre of pixel (`col`,
    /// `row`), in the observer's frame (`None`: no ray there).
    pub fn ray_dir(&self, col: u32, row: u32, width: u32, height: u32) -> Option<DVec3> {
        self.pixel_ray(col, row, width, height, (0.0, 0.0))
            .map(|r| r.dir)
    }

    /// The angle one pixel of a `width` x `height` image spans at the
    /// image's centre (a panorama: at its equator, down), radians.
    pub fn pixel_angle(&self, width: u32, height: u32) -> f64 {
        let (w, h) = (f64::from(width.max(1)), f64::from(height.max(1)));
        match self.projection {
            Projection::Pinhole => 2.0 * self.tan_half_fov / h,
            Projection::Equirect => std::f64::consts::PI / f64::from(self.eye_height(height)),
            Projection::Fisheye => 2.0 * self.half_fov / w.min(h),
        }
    }
}

/// The radical inverse of `i` in `base` (Halton sequence), in [0, 1): where
/// a pixel's samples fall, across the pixel (the window's and `--spp`'s
/// jitter, bases 2 and 3) and in time (the shutter, base 5).
pub fn halton(mut i: u32, base: u32) -> f64 {
    let mut f = 1.0;
    let mut r = 0.0;
    while i > 0 {
        f /= f64::from(base);
        r += f * f64::from(i % base);
        i /= base;
    }
    r
}

/// Sample `n`'s offset from the pixel's centre, in pixels (x right, y
/// down): Halton's bases 2 and 3 centred on the pixel for n >= 1, the
/// centre itself for n = 0. The window's progressive refinement and
/// `--spp` take their samples from it.
pub fn jitter(n: u32) -> (f64, f64) {
    if n == 0 {
        return (0.0, 0.0);
    }
    (halton(n, 2) - 0.5, halton(n, 3) - 0.5)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn the_pinhole_follows_the_binding_convention() {
        let f = CameraFrame::new(DVec3::new(0.0, 0.0, -10.0), DVec3::ZERO, DVec3::Y, 90.0);
        // Looking toward +z with +y up: +x is to the screen's right.
        assert!(f.right.x > 0.99 && f.forward.z > 0.99 && f.up.y > 0.99);
        // The top-left pixel of a 2x2 image looks up and left, at 45 degrees
        // off the axis in each direction (tan(45) * (1 - 1/2)).
        let d = f.ray_dir(0, 0, 2, 2).unwrap();
        assert!(d.x < 0.0 && d.y > 0.0);
        assert!((d.x / d.z + 0.5).abs() < 1e-12 && (d.y / d.z - 0.5).abs() < 1e-12);
        // Half a pixel of jitter to the right lands on the axis.
        let r = f.pixel_ray(0, 0, 2, 2, (0.5, 0.5)).unwrap();
        assert!((r.dir - f.forward).length() < 1e-12);
        assert!((r.angle - 1.0).abs() < 1e-12);
    }
}
