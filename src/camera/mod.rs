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

/// How pixels map to rays.
#[derive(Clone, Copy, Debug, Default, PartialEq, Eq)]
pub enum Projection {
    /// Every ray from one point through the image plane at distance 1.
    #[default]
    Pinhole,
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

/// An orthonormal camera frame, by the binding convention.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct CameraFrame {
    pub position: DVec3,
    pub forward: DVec3,
    pub right: DVec3,
    pub up: DVec3,
    /// tan(vfov / 2).
    pub tan_half_fov: f64,
    pub projection: Projection,
}

impl CameraFrame {
    /// The frame at `position` looking toward `look_at`: `forward =
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
            projection: Projection::Pinhole,
        }
    }

    /// The ray through pixel (`col`, `row`) of a `width` x `height` image,
    /// row 0 at the top, offset by `jitter` pixels (0, 0: the centre; y down).
    pub fn pixel_ray(
        &self,
        col: u32,
        row: u32,
        width: u32,
        height: u32,
        jitter: (f64, f64),
    ) -> PixelRay {
        match self.projection {
            Projection::Pinhole => {
                let aspect = f64::from(width) / f64::from(height);
                let sx = (2.0 * (f64::from(col) + 0.5 + jitter.0) / f64::from(width) - 1.0)
                    * self.tan_half_fov
                    * aspect;
                let sy = (1.0 - 2.0 * (f64::from(row) + 0.5 + jitter.1) / f64::from(height))
                    * self.tan_half_fov;
                PixelRay {
                    origin: self.position,
                    dir: (self.forward + sx * self.right + sy * self.up).normalize(),
                    angle: self.pixel_angle(height),
                }
            }
        }
    }

    /// The unit direction of the ray through the centre of pixel (`col`,
    /// `row`), in the observer's frame.
    pub fn ray_dir(&self, col: u32, row: u32, width: u32, height: u32) -> DVec3 {
        self.pixel_ray(col, row, width, height, (0.0, 0.0)).dir
    }

    /// The angle one pixel of an image `height` pixels tall spans at its
    /// centre, radians.
    pub fn pixel_angle(&self, height: u32) -> f64 {
        match self.projection {
            Projection::Pinhole => 2.0 * self.tan_half_fov / f64::from(height.max(1)),
        }
    }
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
        let d = f.ray_dir(0, 0, 2, 2);
        assert!(d.x < 0.0 && d.y > 0.0);
        assert!((d.x / d.z + 0.5).abs() < 1e-12 && (d.y / d.z - 0.5).abs() < 1e-12);
        // Half a pixel of jitter to the right lands on the axis.
        let r = f.pixel_ray(0, 0, 2, 2, (0.5, 0.5));
        assert!((r.dir - f.forward).length() < 1e-12);
        assert!((r.angle - 1.0).abs() < 1e-12);
    }
}
