//! Validation of the values serde cannot check: each rule is one line built
//! from a few helpers, and a failure names the key path, the value and why.

use glam::DVec3;

use super::locate::Seg::{self, Idx, Key};
use super::locate::display_path;
use super::refusal::{refuse, refuse_fall_end};
use super::rule::{Check, fail, vec3};
use super::{Camera, CameraPath, DiskKind, MAX_HOLES, Scene, SkyKind, Stereo};
use crate::physics::observer::ObserverKind;
use crate::spacetime::{FALLING_MIN_R, Refusal, Spacetime};

/// Largest magnitude of any number in a scene: the GPU works in 32-bit
/// floats, and squares of lengths must stay far inside their range.
pub const LIMIT: f64 = 1e9;

/// The frame rates a scene may ask for (`[animation] fps`): MP4, WebM and
/// MOV through ffmpeg hold these, and a frame's time stays a number.
pub const MIN_FPS: f64 = 0.01;
pub const MAX_FPS: f64 = 1000.0;

/// Finite and at most [`LIMIT`] in size.
pub(super) trait InRange {
    fn in_range(&self) -> bool;
}

impl InRange for f64 {
    fn in_range(&self) -> bool {
        self.is_finite() && self.abs() <= LIMIT
    }
}

/// `ok`, or the failure.
pub(super) fn rule(
    ok: bool,
    path: &[Seg],
    value: impl std::fmt::Display,
    why: impl Into<String>,
) -> Check {
    if ok { Ok(()) } else { fail(path, value, why) }
}

fn finite3(path: &[Seg], v: &[f64; 3]) -> Check {
    rule(
        v.iter().all(|x| x.in_range()),
        path,
        vec3(v),
        "must be finite numbers of size at most 1e9",
    )
}

pub(super) fn direction(path: &[Seg], v: &[f64; 3]) -> Check {
    rule(
        v.iter().all(|x| x.in_range()) && DVec3::from(*v).length() >= 1e-9,
        path,
        vec3(v),
        "must be a finite, non-zero vector (sizes at most 1e9)",
    )
}

fn finite(path: &[Seg], v: f64) -> Check {
    rule(
        v.in_range(),
        path,
        v,
        "must be a finite number of size at most 1e9",
    )
}

fn positive(path: &[Seg], v: f64) -> Check {
    rule(
        v.in_range() && v >= 1.0 / LIMIT,
        path,
        v,
        "must be a finite number > 0, from 1e-9 to 1e9",
    )
}

fn non_negative(path: &[Seg], v: f64) -> Check {
    rule(
        v.in_range() && v >= 0.0,
        path,
        v,
        "must be a finite number >= 0, at most 1e9",
    )
}

fn count_in(path: &[Seg], v: u32, lo: u32, hi: u32) -> Check {
    rule(
        (lo..=hi).contains(&v),
        path,
        v,
        format!("must be {lo} to {hi}"),
    )
}

impl Scene {
    /// Checks every value; the first failure as (key path, value, reason).
    pub(super) fn validate(&self) -> Check {
        self.validate_camera_and_holes()?;
        self.validate_disk()?;
        self.validate_sky_and_plane()?;
        self.validate_rendering()?;
        self.validate_polarization()?;
        self.validate_animation()
    }

    fn validate_camera_and_holes(&self) -> Check {
        let n = self.black_holes.len();
        rule(
            n > 0,
            &[Key("black_hole")],
            "[]",
            "at least one black hole is needed",
        )?;
        rule(
            n <= MAX_HOLES,
            &[Key("black_hole")],
            format!("{n} entries"),
            format!("at most {MAX_HOLES} black holes are supported"),
        )?;
        for (i, h) in self.black_holes.iter().enumerate() {
            let key = |k| [Key("black_hole"), Idx(i), Key(k)];
            finite3(&key("position"), &h.position)?;
            positive(&key("rs"), h.rs)?;
            if let Some(m) = h.mass_solar {
                positive(&key("mass_solar"), m)?;
            }
            let spin = h.spin;
            rule(
                spin.in_range() && spin.abs() <= MAX_SPIN,
                &key("spin"),
                spin,
                format!("must be in [-{MAX_SPIN}, {MAX_SPIN}] (a* = a / M, signed)"),
            )?;
            rule(
                spin == 0.0 || n == 1,
                &key("spin"),
                spin,
                "a spinning hole must be the only hole: spinning fields do not add up, and no \
                 closed form exists for several",
            )?;
        }
        self.check_camera(&self.camera, &[Key("camera")])
    }

    /// The rules every camera obeys, wherever it comes from: `[camera]`, an
    /// `[[animation.keyframe]]` (`at` is then its key path) or any frame of
    /// an animation ([`Scene::check_frames`]).
    pub(super) fn check_camera(&self, c: &Camera, at: &[Seg]) -> Check {
        self.check_camera_in(&self.spacetime(), c, at)
    }

    /// [`Scene::check_camera`] in the scene's spacetime, built once by the
    /// caller (a sequence checks every frame's camera).
    pub(super) fn check_camera_in(&self, spacetime: &Spacetime, c: &Camera, at: &[Seg]) -> Check {
        // Called for every frame of a sequence: the messages (and their
        // key paths) are built only on failure.
        let key = |k: &'static str| [at, &[Key(k)]].concat();
        let in_range = |v: &[f64; 3]| v.iter().all(|x| x.in_range());
        if !in_range(&c.position) {
            finite3(&key("position"), &c.position)?;
        }
        if !in_range(&c.look_at) {
            finite3(&key("look_at"), &c.look_at)?;
        }
        if !in_range(&c.up) {
            finite3(&[Key("camera"), Key("up")], &c.up)?;
        }
        check_lens(c, at)?;
        check_view(c, at)?;
        // Inside a horizon first, then the eyes, then the observer's own
        // rules.
        let cam = DVec3::from(c.position);
        let placed = spacetime.placement(c.observer, cam);
        if let Err(r @ (Refusal::InsideHorizon { .. } | Refusal::InsideAbsorber { .. })) = placed {
            return refuse(c, at, r);
        }
        self.check_eyes(spacetime, c, cam)?;
        match placed {
            Ok(()) => Ok(()),
            Err(refusal) => refuse(c, at, refusal),
        }
    }

    /// Each ODS eye sits ipd / 2 from the camera: both outside every hole,
    /// with room to spare (an eye at the horizon sees nothing), or, for a
    /// falling camera of one non-rotating hole, both outside the
    /// singularity's neighbourhood as the camera is; and every place on the
    /// eyes' viewing circle obeys the observer's own rules (an eye inside
    /// the ergoregion of a static camera, or inside the photon sphere of an
    /// orbiting one, once rendered).
    fn check_eyes(&self, spacetime: &Spacetime, c: &Camera, cam: DVec3) -> Check {
        if c.stereo != Stereo::Ods || !self.physics.gravity {
            return Ok(());
        }
        let falls_in = c.observer == ObserverKind::Falling && spacetime.one_static_hole();
        let least = if falls_in { FALLING_MIN_R } else { 1.01 };
        for (i, h) in self.black_holes.iter().enumerate() {
            let r = (cam - DVec3::from(h.position)).length();
            if r - 0.5 * c.ipd <= least * h.rs {
                let why = format!(
                    "puts an eye within {least} rs of black_hole[{i}] (the camera is {r:.4} from \
                     it; each eye sits ipd / 2 from the camera)"
                );
                return fail(&[Key("camera"), Key("ipd")], c.ipd, why);
            }
        }
        let f = c.frame();
        for k in 0..64 {
            let t = std::f64::consts::TAU * f64::from(k) / 64.0;
            let eye = cam + 0.5 * c.ipd * (t.cos() * f.right - t.sin() * f.forward);
            if let Err(refusal) = spacetime.placement(c.observer, eye)
                && let Err((_, _, why)) = refuse(c, &[Key("camera")], refusal)
            {
                let why = format!(
                    "puts an eye at [{:.4}, {:.4}, {:.4}], which {why} (each eye is the \
                     observer's own place)",
                    eye.x, eye.y, eye.z
                );
                return fail(&[Key("camera"), Key("ipd")], c.ipd, why);
            }
        }
        Ok(())
    }

    /// The disk's inner radius as a message quotes it: `"isco"` resolves to
    /// a number the user never wrote, so that is said with it.
    fn inner_radius_quoted(&self) -> String {
        let (rs, spin) = self.first_hole();
        let isco = crate::spacetime::radii::isco(rs, spin.clamp(-1.0, 1.0));
        if self.inner_is_isco() {
            format!(
                "\"isco\": {}, the ISCO of black_hole[0] with rs = {rs} and spin = {spin}",
                crate::digits::significant(isco, 5)
            )
        } else {
            format!("{}", self.disk.inner_radius)
        }
    }

    /// Whether the disk's inner radius is the ISCO (`"isco"`, written or
    /// omitted) rather than a number of the user's.
    fn inner_is_isco(&self) -> bool {
        let (rs, spin) = self.first_hole();
        self.disk.inner_radius == crate::spacetime::radii::isco(rs, spin.clamp(-1.0, 1.0))
    }

    fn validate_disk(&self) -> Check {
        let d = &self.disk;
        let key = |k| [Key("disk"), Key(k)];
        direction(&key("normal"), &d.normal)?;
        // A derived inner radius (the ISCO, which scales with rs) is checked
        // against the outer one only where there is a disk to draw: with
        // kind = "none" a hole of rs = 1e9 keeps its default radii.
        let derived = self.inner_is_isco();
        if !derived {
            non_negative(&key("inner_radius"), d.inner_radius)?;
        }
        finite(&key("outer_radius"), d.outer_radius)?;
        rule(
            (derived && d.kind == DiskKind::None)
                || (d.outer_radius.in_range() && d.outer_radius > d.inner_radius),
            &key("outer_radius"),
            d.outer_radius,
            format!(
                "must be finite and greater than inner_radius ({})",
                self.inner_radius_quoted()
            ),
        )?;
        non_negative(&key("brightness"), d.brightness)?;
        rule(
            d.temperature_k.in_range() && d.temperature_k > 0.0,
            &key("temperature_k"),
            d.temperature_k,
            "must be a finite temperature > 0 kelvin",
        )?;
        positive(&key("height"), d.height)?;
        positive(&key("noise_scale"), d.noise_scale)?;
        non_negative(&key("density_v"), d.density_v)?;
        non_negative(&key("density_h"), d.density_h)?;
        non_negative(&key("lit"), d.lit)?;
        for (name, v) in [("structure", d.structure), ("opacity", d.opacity)] {
            rule((0.0..=1.0).contains(&v), &key(name), v, "must be in [0, 1]")?;
        }
        finite(&key("speed"), d.speed)?;
        count_in(&key("noise_octaves"), d.noise_octaves, 1, 8)?;
        // The photon orbit of the spacetime's hole (1.5 rs; a spinning
        // hole's prograde one; none with gravity off).
        let spacetime = self.spacetime();
        let photon = spacetime
            .holes()
            .first()
            .and_then(|h| spacetime.photon_orbit(h))
            .unwrap_or(0.0);
        let bound = if spacetime.gpu_path() != crate::spacetime::GpuPath::Kerr {
            format!("1.5 rs = {photon}")
        } else {
            format!("the prograde photon orbit, {photon:.4} rs")
        };
        rule(
            d.kind != DiskKind::Volumetric || (d.inner_radius > 0.0 && d.inner_radius >= photon),
            &key("inner_radius"),
            self.inner_radius_quoted(),
            format!(
                "must be > 0 and outside the photon sphere (>= {bound}) for a volumetric \
                 disk, whose gas is sampled along paths that leave it"
            ),
        )
    }

    fn validate_sky_and_plane(&self) -> Check {
        let s = &self.sky;
        let key = |k| [Key("sky"), Key(k)];
        rule(
            s.kind != SkyKind::Image || s.image.is_some(),
            &key("kind"),
            "\"image\"",
            "needs sky.image = \"panorama file\"",
        )?;
        rule(
            s.kind != SkyKind::Cubemap || s.cubemap.as_ref().is_some_and(|c| c.len() == 6),
            &key("kind"),
            "\"cubemap\"",
            "needs sky.cubemap = [six files: +x, -x, +y, -y, +z, -z]",
        )?;
        finite(&key("rotation_deg"), s.rotation_deg)?;
        finite(&key("tilt_deg"), s.tilt_deg)?;
        rule(
            s.star_density.in_range() && (0.0..=1.0).contains(&s.star_density),
            &key("star_density"),
            s.star_density,
            "must be in [0, 1]",
        )?;
        non_negative(&key("galaxy"), s.galaxy)?;
        rule(s.squares > 0, &key("squares"), 0, "must be at least 1")?;
        non_negative(&key("brightness"), s.brightness)?;

        let gp = &self.plane;
        let key = |k| [Key("grid_plane"), Key(k)];
        finite3(&key("position"), &gp.position)?;
        direction(&key("normal"), &gp.normal)?;
        positive(&key("spacing"), gp.spacing)?;
        positive(&key("size"), gp.size)
    }

    fn validate_rendering(&self) -> Check {
        let q = &self.quality;
        let key = |k| [Key("quality"), Key(k)];
        rule(q.steps > 0, &key("steps"), 0, "must be at least 1")?;
        rule(
            q.tolerance.in_range() && q.tolerance > 0.0 && q.tolerance < 1.0,
            &key("tolerance"),
            q.tolerance,
            "must be in (0, 1)",
        )?;
        rule(
            q.escape_radius.in_range() && q.escape_radius >= 0.0,
            &key("escape_radius"),
            q.escape_radius,
            "must be a finite number >= 0 (0 = automatic)",
        )?;

        let b = &self.bloom;
        let key = |k| [Key("bloom"), Key(k)];
        non_negative(&key("strength"), b.strength)?;
        non_negative(&key("threshold"), b.threshold)?;
        non_negative(&key("knee"), b.knee)?;
        count_in(&key("levels"), b.levels, 1, 8)?;
        positive(&key("radius"), b.radius)?;
        let p = &self.post;
        finite(&[Key("post"), Key("exposure_ev")], p.exposure_ev)?;
        rule(
            (0.0..1.0).contains(&p.meter_low),
            &[Key("post"), Key("meter_low")],
            p.meter_low,
            "must be in [0, 1)",
        )?;
        rule(
            p.saturation.in_range() && (0.0..=4.0).contains(&p.saturation),
            &[Key("post"), Key("saturation")],
            p.saturation,
            "must be in [0, 4]",
        )?;
        rule(
            p.meter_high > p.meter_low && p.meter_high <= 1.0,
            &[Key("post"), Key("meter_high")],
            p.meter_high,
            "must be in (meter_low, 1]",
        )
    }

    fn validate_animation(&self) -> Check {
        let a = &self.animation;
        let spacetime = self.spacetime();
        let key = |k| [Key("animation"), Key(k)];
        // (What the video containers hold, and each frame's time resolvable.)
        rule(
            (MIN_FPS..=MAX_FPS).contains(&a.fps),
            &key("fps"),
            a.fps,
            format!("must be from {MIN_FPS} to {MAX_FPS} frames a second (what a video holds)"),
        )?;
        rule(
            a.orbit_radius.in_range() && a.orbit_radius >= 0.0,
            &key("orbit_radius"),
            a.orbit_radius,
            "must be a finite number (radius >= 0)",
        )?;
        for (name, v) in [
            ("orbit_speed_deg", a.orbit_speed_deg),
            ("inclination_deg", a.inclination_deg),
        ] {
            rule(v.in_range(), &key(name), v, "must be a finite number")?;
        }
        rule(
            (0.0..=1.0).contains(&a.shutter),
            &key("shutter"),
            a.shutter,
            "must be in [0, 1] (the fraction of a frame's interval the shutter is open)",
        )?;
        rule(
            a.inclination_deg.abs() < 90.0,
            &key("inclination_deg"),
            a.inclination_deg,
            "must be between -90 and 90 (the camera's up is +y)",
        )?;
        // The disk as it was when its light left: timed along one hole's
        // exact paths (or straight ones); summed paths carry no clock, and
        // the volumetric gas is drawn at the frame's time.
        let several = self.black_holes.len() > 1 && self.physics.gravity;
        rule(
            !a.light_travel_time || !(several || self.disk.kind == DiskKind::Volumetric),
            &key("light_travel_time"),
            a.light_travel_time,
            if several {
                "works with one hole (or gravity off): with several the summed light paths carry no clock"
            } else {
                "works with the thin disk: the volumetric gas is drawn as it is at the frame's time"
            },
        )?;
        positive(&key("fall_seconds"), a.fall_seconds)?;
        if let Some(end) = a.fall_end_radius {
            positive(&key("fall_end_radius"), end)?;
            let position = DVec3::from(self.camera.position);
            let fall = spacetime.fall_from(position, self.camera.observer, DVec3::Y);
            if let Err(refusal) = fall.check_end(end) {
                return refuse_fall_end(end, refusal);
            }
        }
        rule(
            a.camera != CameraPath::Keyframes || !a.keyframes.is_empty(),
            &key("camera"),
            "\"keyframes\"",
            "needs at least one [[animation.keyframe]]",
        )?;
        for (i, k) in a.keyframes.iter().enumerate() {
            rule(
                k.time.in_range() && (i == 0 || k.time > a.keyframes[i - 1].time),
                &[Key("animation"), Key("keyframe"), Idx(i), Key("time")],
                k.time,
                "keyframe times must be finite and increasing",
            )?;
            let at = [Key("animation"), Key("keyframe"), Idx(i)];
            self.check_camera_in(&spacetime, &k.camera(&self.camera), &at)?;
        }
        if a.camera == CameraPath::Orbit {
            self.check_orbit()?;
        }
        Ok(())
    }

    /// An orbit (a circle of latitude about `look_at`) that passes inside a
    /// horizon is refused as a whole, whichever frames land there.
    fn check_orbit(&self) -> Check {
        let a = &self.animation;
        let target = DVec3::from(self.camera.look_at);
        let radius = if a.orbit_radius > 0.0 {
            a.orbit_radius
        } else {
            (DVec3::from(self.camera.position) - target).length()
        };
        let inc = a.inclination_deg.to_radians();
        let (centre, rho) = (target + DVec3::Y * radius * inc.sin(), radius * inc.cos());
        for (i, h) in self.black_holes.iter().enumerate() {
            let v = DVec3::from(h.position) - centre;
            let across = (v.x * v.x + v.z * v.z).sqrt();
            let closest = (v.y * v.y + (across - rho) * (across - rho)).sqrt();
            rule(
                closest > h.rs,
                &[Key("animation"), Key("orbit_radius")],
                a.orbit_radius,
                format!(
                    "the orbit (radius {radius:.4} about camera.look_at) passes inside the horizon of \
                     black_hole[{i}] (closest approach {closest:.4}, rs = {})",
                    h.rs
                ),
            )?;
        }
        Ok(())
    }
}

/// The largest |a*| a scene may set.
pub const MAX_SPIN: f64 = 0.9999;

/// The projection's own rules: its field of view, the stereo layout and the
/// eyes' distance.
fn check_lens(c: &Camera, at: &[Seg]) -> Check {
    let key = |k: &'static str| [at, &[Key(k)]].concat();
    if let Err(why) = c.projection.check_vfov(c.vfov_deg) {
        return fail(&key("vfov_deg"), c.vfov_deg, why);
    }
    let lens = |k: &'static str| [Key("camera"), Key(k)];
    if c.stereo == Stereo::Ods && !c.projection.takes_stereo() {
        return fail(
            &lens("stereo"),
            "\"ods\"",
            format!(
                "needs camera.projection = \"equirect\" (it is \"{}\")",
                c.projection.name()
            ),
        );
    }
    if !(c.ipd.in_range() && c.ipd >= 0.0) {
        return fail(&lens("ipd"), c.ipd, "must be a finite distance >= 0 (rs)");
    }
    if c.stereo == Stereo::Ods && c.ipd <= 0.0 {
        return fail(&lens("ipd"), c.ipd, "must be > 0 with stereo = \"ods\"");
    }
    Ok(())
}

/// A view direction, and an up that is not along it.
fn check_view(c: &Camera, at: &[Seg]) -> Check {
    let key = |k: &'static str| [at, &[Key(k)]].concat();
    let fwd = DVec3::from(c.look_at) - DVec3::from(c.position);
    if fwd.length() < 1e-9 {
        let why = format!("must differ from {}", display_path(&key("position")));
        return fail(&key("look_at"), vec3(&c.look_at), why);
    }
    if DVec3::from(c.up).cross(fwd.normalize()).length() >= 1e-6 {
        return Ok(());
    }
    if at == [Key("camera")] {
        fail(
            &key("up"),
            vec3(&c.up),
            "must not be zero or parallel to the view direction",
        )
    } else {
        let why = format!(
            "makes the view direction parallel to camera.up = {}",
            vec3(&c.up)
        );
        fail(&key("look_at"), vec3(&c.look_at), why)
    }
}
