//! The panel's scene editor: every scene parameter grouped as in the TOML
//! (camera and holes, disk and physics, sky and plane, post and quality),
//! edited in place on the panel's draft; and the scene's save to TOML.

use egui::{Color32, DragValue, Ui};

use crate::physics::observer::ObserverKind;
use crate::scene::{DiskKind, Scene, SkyKind, Tonemap, VolumeColor};
use crate::spacetime::radii;
use crate::stars::SkyFrame;
use crate::{Error, Result};

/// Writes `scene` as TOML to `path` (atomically).
pub fn save_scene(scene: &Scene, path: &str) -> Result<()> {
    let text = scene.to_toml()?;
    let p = std::path::Path::new(path);
    crate::output::write_atomically(p, |tmp| {
        std::fs::write(tmp, &text).map_err(|source| Error::Io {
            path: p.to_owned(),
            source,
        })
    })
}

fn num(ui: &mut Ui, label: &str, v: &mut f64, speed: f64) {
    ui.horizontal(|ui| {
        ui.add(DragValue::new(v).speed(speed));
        ui.label(label);
    });
}

fn int(ui: &mut Ui, label: &str, v: &mut u32) {
    ui.horizontal(|ui| {
        ui.add(DragValue::new(v).speed(0.1));
        ui.label(label);
    });
}

fn vec3(ui: &mut Ui, label: &str, v: &mut [f64; 3], speed: f64) {
    ui.horizontal(|ui| {
        for x in v.iter_mut() {
            ui.add(DragValue::new(x).speed(speed));
        }
        ui.label(label);
    });
}

fn choice<T: PartialEq + Copy>(ui: &mut Ui, label: &str, v: &mut T, options: &[(T, &str)]) {
    ui.horizontal(|ui| {
        for (value, name) in options {
            ui.radio_value(v, *value, *name);
        }
        ui.label(label);
    });
}

/// `[camera] projection`, `stereo` and `ipd`. Picking the fisheye starts it
/// as a dome master (180 degrees); back to the pinhole, a field it cannot
/// show returns to 60 degrees.
fn projection_editor(ui: &mut Ui, c: &mut crate::scene::Camera) {
    use crate::camera::{Projection, Stereo};
    let before = c.projection;
    let options: Vec<(Projection, &str)> = Projection::ALL.iter().map(|p| (*p, p.name())).collect();
    choice(ui, "projection", &mut c.projection, &options);
    if c.projection != before {
        c.vfov_deg = c.projection.suited_vfov(c.vfov_deg);
        if !c.projection.takes_stereo() {
            c.stereo = Stereo::None;
        }
    }
    ui.label(c.projection.description());
    if c.projection.takes_stereo() {
        let mut ods = c.stereo == Stereo::Ods;
        ui.checkbox(&mut ods, "omni-directional stereo (left eye on top)");
        c.stereo = if ods { Stereo::Ods } else { Stereo::None };
        if ods {
            num(ui, "ipd (rs)", &mut c.ipd, 0.01);
        }
    }
}

/// Every scene key, grouped as in the TOML.
pub fn scene_editor(ui: &mut Ui, s: &mut Scene) {
    camera_and_holes(ui, s);
    disk_and_physics(ui, s);
    sky_and_plane(ui, s);
    polarization(ui, s);
    post_and_quality(ui, s);
}

/// `[polarization]`: the picture switched on and off and its view, the
/// field and the emitter's indices edited live.
fn polarization(ui: &mut Ui, s: &mut Scene) {
    use crate::scene::{Brightness, Colormap, PolarizedView};
    egui::CollapsingHeader::new("polarization").show(ui, |ui| {
        let p = &mut s.polarization;
        ui.checkbox(&mut p.enabled, "enabled (Stokes I with the ticks)");
        let views: Vec<_> = PolarizedView::ALL.iter().map(|v| (*v, v.name())).collect();
        choice(ui, "view", &mut p.view, &views);
        let maps: Vec<_> = Colormap::ALL.iter().map(|m| (*m, m.name())).collect();
        choice(ui, "colormap", &mut p.colormap, &maps);
        let scales: Vec<_> = Brightness::ALL.iter().map(|b| (*b, b.name())).collect();
        choice(ui, "brightness", &mut p.brightness, &scales);
        if p.fields.is_empty() {
            vec3(ui, "field (r, phi, z)", &mut p.field, 0.01);
        } else {
            for (i, f) in p.fields.iter_mut().enumerate() {
                vec3(ui, &format!("fields[{i}]"), f, 0.01);
            }
        }
        num(ui, "spectral_index", &mut p.spectral_index, 0.01);
        num(ui, "emissivity_index", &mut p.emissivity_index, 0.05);
        num(ui, "fraction", &mut p.fraction, 0.01);
        int(ui, "ticks", &mut p.ticks);
        num(ui, "tick_cut", &mut p.tick_cut, 0.005);
        num(ui, "beam (uas)", &mut p.beam, 0.1);
        num(ui, "mass_msun", &mut p.mass_msun, 1e7);
        num(ui, "distance_pc", &mut p.distance_pc, 1e4);
        ui.label(format!(
            "GM/c^2 = {:.3} microarcseconds",
            p.gravitational_angle_uas()
        ));
    });
}

/// `[camera]` and `[[black_hole]]`.
fn camera_and_holes(ui: &mut Ui, s: &mut Scene) {
    egui::CollapsingHeader::new("camera")
        .default_open(true)
        .show(ui, |ui| {
            vec3(ui, "position", &mut s.camera.position, 0.05);
            vec3(ui, "look_at", &mut s.camera.look_at, 0.05);
            vec3(ui, "up", &mut s.camera.up, 0.01);
            num(ui, "vfov_deg", &mut s.camera.vfov_deg, 0.2);
            projection_editor(ui, &mut s.camera);
            let options: Vec<(ObserverKind, &str)> =
                ObserverKind::ALL.iter().map(|k| (*k, k.name())).collect();
            choice(ui, "observer", &mut s.camera.observer, &options);
            ui.label(match s.camera.observer {
                ObserverKind::Static => "at rest where it is",
                ObserverKind::Orbiting => "on a circular orbit, moving with the disk",
                ObserverKind::Falling => "falling straight in from rest far away",
                ObserverKind::Flat => {
                    "pixel directions used as coordinate directions (simple renderers)"
                }
                ObserverKind::Zamo => {
                    "turning with the spinning hole's frame dragging, no angular momentum"
                }
            });
        });
    egui::CollapsingHeader::new("black holes").show(ui, |ui| {
        if s.black_holes.len() > 1 {
            ui.colored_label(
                Color32::YELLOW,
                "Several holes: accelerations are summed. An approximation, exact for one hole only.",
            );
        }
        let mut remove = None;
        let inner = &mut s.disk.inner_radius;
        for (i, h) in s.black_holes.iter_mut().enumerate() {
            ui.label(format!("black_hole[{i}]"));
            vec3(ui, "position", &mut h.position, 0.05);
            num(ui, "rs", &mut h.rs, 0.01);
            let before = h.spin;
            ui.add(egui::Slider::new(&mut h.spin, -0.9999..=0.9999).text("spin a*"));
            let (rs, a) = (h.rs, h.spin);
            if i == 0 {
                follow_isco(inner, rs, before, a);
            }
            if a != 0.0 {
                ui.label(format!(
                    "horizon {:.3} rs; circular photon orbits {:.3} rs (prograde), {:.3} rs \
                     (retrograde); ISCO {:.3} rs (the disk's turning direction)",
                    radii::horizon(rs, a),
                    radii::photon_orbit(rs, a, true),
                    radii::photon_orbit(rs, a, false),
                    radii::isco(rs, a),
                ));
                ui.label(
                    "spinning (Kerr): light paths exact, in closed form (Mino time; 32-bit, \
                     the roots in 64-bit where the device has them); one hole only, thin disk",
                );
            }
            if i > 0 && ui.button("remove").clicked() {
                remove = Some(i);
            }
        }
        if let Some(i) = remove {
            s.black_holes.remove(i);
        }
        if ui.button("add a hole").clicked() {
            s.black_holes.push(crate::scene::BlackHole {
                position: [6.0, 0.0, 0.0],
                ..Default::default()
            });
        }
    });
}

/// A disk whose inner edge is at the ISCO of spin `before` stays at the
/// ISCO of spin `after` (the slider moves the edge with it); any other
/// inner radius is left as the user set it.
pub fn follow_isco(inner: &mut f64, rs: f64, before: f64, after: f64) {
    let isco = |a: f64| radii::isco(rs, a);
    if before != after && (*inner - isco(before)).abs() <= 1e-9 * inner.abs() {
        *inner = isco(after);
    }
}

/// `[disk]` and `[physics]`.
fn disk_and_physics(ui: &mut Ui, s: &mut Scene) {
    egui::CollapsingHeader::new("disk").show(ui, |ui| {
        let d = &mut s.disk;
        choice(
            ui,
            "kind",
            &mut d.kind,
            &[
                (DiskKind::Thin, "thin"),
                (DiskKind::Volumetric, "volumetric"),
                (DiskKind::None, "none"),
            ],
        );
        vec3(ui, "normal", &mut d.normal, 0.01);
        num(ui, "inner_radius", &mut d.inner_radius, 0.05);
        num(ui, "outer_radius", &mut d.outer_radius, 0.05);
        num(ui, "brightness", &mut d.brightness, 0.01);
        num(ui, "temperature_k", &mut d.temperature_k, 20.0);
        num(ui, "speed", &mut d.speed, 0.01);
        ui.label("thin:");
        num(ui, "structure", &mut d.structure, 0.01);
        num(ui, "opacity", &mut d.opacity, 0.01);
        ui.label("volumetric:");
        num(ui, "height", &mut d.height, 0.01);
        num(ui, "density_v", &mut d.density_v, 0.01);
        num(ui, "density_h", &mut d.density_h, 0.01);
        num(ui, "noise_scale", &mut d.noise_scale, 0.01);
        int(ui, "noise_octaves", &mut d.noise_octaves);
        num(ui, "lit", &mut d.lit, 0.01);
        choice(
            ui,
            "color",
            &mut d.color,
            &[
                (VolumeColor::Blackbody, "blackbody"),
                (VolumeColor::Colormap, "colormap"),
            ],
        );
    });
    egui::CollapsingHeader::new("physics").show(ui, |ui| {
        ui.checkbox(&mut s.physics.gravity, "gravity");
        ui.checkbox(&mut s.physics.doppler, "doppler");
        ui.checkbox(&mut s.physics.beaming, "beaming");
        ui.checkbox(
            &mut s.physics.gravitational_redshift,
            "gravitational_redshift",
        );
        ui.checkbox(&mut s.physics.sky_shift, "sky_shift");
    });
}

/// `[sky]` and `[grid_plane]`.
fn sky_and_plane(ui: &mut Ui, s: &mut Scene) {
    egui::CollapsingHeader::new("sky").show(ui, |ui| {
        choice(
            ui,
            "kind",
            &mut s.sky.kind,
            &[
                (SkyKind::Catalogue, "catalogue"),
                (SkyKind::Stars, "stars"),
                (SkyKind::Checker, "checker"),
                (SkyKind::Image, "image"),
                (SkyKind::Cubemap, "cubemap"),
                (SkyKind::Black, "black"),
            ],
        );
        choice(
            ui,
            "frame",
            &mut s.sky.frame,
            &[
                (SkyFrame::Galactic, "galactic"),
                (SkyFrame::Equatorial, "equatorial"),
            ],
        );
        num(ui, "rotation_deg", &mut s.sky.rotation_deg, 0.5);
        num(ui, "tilt_deg", &mut s.sky.tilt_deg, 0.5);
        let mut image = s.sky.image.clone().unwrap_or_default();
        ui.horizontal(|ui| {
            ui.text_edit_singleline(&mut image);
            ui.label("image");
        });
        s.sky.image = (!image.is_empty()).then_some(image);
        num(ui, "star_density", &mut s.sky.star_density, 0.01);
        num(ui, "galaxy", &mut s.sky.galaxy, 0.001);
        int(ui, "squares", &mut s.sky.squares);
        num(ui, "brightness", &mut s.sky.brightness, 0.01);
    });
    egui::CollapsingHeader::new("grid_plane").show(ui, |ui| {
        let p = &mut s.plane;
        ui.checkbox(&mut p.enabled, "enabled");
        vec3(ui, "position", &mut p.position, 0.1);
        vec3(ui, "normal", &mut p.normal, 0.01);
        num(ui, "spacing", &mut p.spacing, 0.05);
        num(ui, "size", &mut p.size, 0.5);
    });
}

/// `[bloom]`, `[post]` and `[quality]`.
fn post_and_quality(ui: &mut Ui, s: &mut Scene) {
    egui::CollapsingHeader::new("bloom").show(ui, |ui| {
        let b = &mut s.bloom;
        num(ui, "strength", &mut b.strength, 0.01);
        num(ui, "threshold", &mut b.threshold, 0.01);
        num(ui, "knee", &mut b.knee, 0.01);
        int(ui, "levels", &mut b.levels);
        num(ui, "radius", &mut b.radius, 0.01);
    });
    egui::CollapsingHeader::new("post").show(ui, |ui| {
        ui.checkbox(&mut s.post.auto_exposure, "auto_exposure");
        num(ui, "exposure_ev", &mut s.post.exposure_ev, 0.05);
        num(ui, "saturation", &mut s.post.saturation, 0.01);
        choice(
            ui,
            "tonemap",
            &mut s.post.tonemap,
            &[
                (Tonemap::HuePreserving, "hue-preserving"),
                (Tonemap::AcesHill, "aces-hill"),
                (Tonemap::AcesNarkowicz, "aces-narkowicz"),
                (Tonemap::Linear, "linear"),
            ],
        );
        ui.checkbox(&mut s.post.dither, "dither");
    });
    egui::CollapsingHeader::new("quality").show(ui, |ui| {
        int(ui, "steps", &mut s.quality.steps);
        num(ui, "tolerance", &mut s.quality.tolerance, 1e-6);
        num(ui, "escape_radius", &mut s.quality.escape_radius, 1.0);
    });
}

#[cfg(test)]
mod tests {
    use super::follow_isco;

    #[test]
    fn a_disk_at_the_isco_follows_the_spin_and_another_stays() {
        // Bardeen, Press & Teukolsky: ISCO 6 M at a* = 0, 1.2370 M at 0.998
        // (prograde), 8.9944 M at -0.998 (retrograde); rs = 2 M.
        let mut inner = 3.0;
        follow_isco(&mut inner, 1.0, 0.0, 0.998);
        assert!((inner - 0.5 * 1.2370).abs() < 1e-4, "{inner}");
        follow_isco(&mut inner, 1.0, 0.998, -0.998);
        assert!((inner - 0.5 * 8.9944).abs() < 1e-3, "{inner}");
        let mut fixed = 5.0;
        follow_isco(&mut fixed, 1.0, 0.0, 0.9);
        assert_eq!(fixed, 5.0);
    }
}
