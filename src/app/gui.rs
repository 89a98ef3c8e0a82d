//! The window's panel (egui): every scene parameter grouped as in the TOML,
//! a preset picker, load and save, the frame rate, the GPU time of the frame
//! and of every pass, and the effective resolution. Edits are made on a draft
//! and go through the scene files' validation: an impossible value is shown
//! as an error and not applied.
//!
//! Drawn by egui-ash-renderer inside one graph pass after the present blit
//! (a colour-attachment write of the swapchain image, with dynamic rendering).

use std::sync::Arc;

use ash::vk;
use egui::{Color32, DragValue, Ui};

use crate::frame::FrameTimings;
use crate::graph::{Graph, ImageHandle, Mips};
use crate::physics::observer::ObserverKind;
use crate::render::Overlay;
use crate::scene::{DiskKind, PRESETS, Scene, SkyKind, Tonemap, VolumeColor};
use crate::spacetime::radii;
use crate::stars::SkyFrame;
use crate::vk::{Access, Gpu};
use crate::{Error, Result};

/// Windows narrower than this (in points) start with the panel folded to a
/// bar, so the view keeps most of the window.
const COLLAPSED_BELOW: f64 = 960.0;
/// The folded panel's width, points.
const BAR_WIDTH: f32 = 26.0;

/// What the panel shows besides the scene.
#[derive(Clone, Debug, Default)]
pub struct Stats {
    pub fps: f64,
    pub timings: FrameTimings,
    pub render_size: (u32, u32),
    /// The view: the part of the window the panel leaves free.
    pub view_size: (u32, u32),
    pub samples: u32,
    pub device: String,
}

/// Requests from the panel to the window.
#[derive(Clone, Debug, Default)]
pub struct PanelActions {
    /// A scene to switch to (preset or file), already validated.
    pub load: Option<Scene>,
    /// The render scale changed (None: auto).
    pub render_scale: Option<Option<f64>>,
}

/// The egui context, its winit input state and its Vulkan renderer.
pub struct Gui {
    pub ctx: egui::Context,
    pub state: egui_winit::State,
    renderer: egui_ash_renderer::Renderer<egui_ash_renderer::allocator::GpuAllocator>,
    command_pool: vk::CommandPool,
    /// The scene being edited (applied when it validates).
    pub draft: Scene,
    pub error: Option<String>,
    pub path: String,
    pub message: String,
    pub visible: bool,
    /// The panel folded to a thin bar (at start when the window is narrow).
    pub collapsed: bool,
    /// Physical pixels the panel covers at the window's left edge (0 when
    /// hidden): the view is drawn right of it.
    pub panel_px: u32,
    pub auto_scale: bool,
    /// Let the wheel take the camera inside the photon sphere.
    pub inside: bool,
    pub scale: f64,
    primitives: Vec<egui::ClippedPrimitive>,
    pixels_per_point: f32,
    format: vk::Format,
    gpu: Arc<Gpu>,
}

impl Gui {
    /// Creates the panel for a swapchain of `format`.
    pub fn new(
        gpu: &Arc<Gpu>,
        window: &winit::window::Window,
        format: vk::Format,
        frames_in_flight: usize,
        scene: &Scene,
    ) -> Result<Self> {
        let ctx = egui::Context::default();
        let state = egui_winit::State::new(
            ctx.clone(),
            egui::ViewportId::ROOT,
            window,
            Some(window.scale_factor() as f32),
            None,
            Some(gpu.max_image_dimension() as usize),
        );
        let renderer = egui_ash_renderer::Renderer::with_gpu_allocator(
            gpu.shared_allocator(),
            gpu.device.clone(),
            egui_ash_renderer::RenderMode::DynamicRendering(egui_ash_renderer::DynamicRendering {
                color_attachment_format: format,
                depth_attachment_format: None,
                stencil_attachment_format: None,
            }),
            egui_ash_renderer::Options {
                in_flight_frames: frames_in_flight,
                enable_depth_test: false,
                enable_depth_write: false,
                srgb_framebuffer: false,
            },
        )
        .map_err(|e| Error::Other(format!("creating the GUI renderer: {e}")))?;
        // SAFETY: valid device; destroyed in Drop.
        let command_pool = unsafe {
            gpu.device.create_command_pool(
                &vk::CommandPoolCreateInfo::default()
                    .queue_family_index(gpu.queue_family)
                    .flags(vk::CommandPoolCreateFlags::TRANSIENT),
                None,
            )
        }
        .map_err(|result| Error::Vulkan {
            what: "creating the GUI's command pool".into(),
            result,
        })?;
        Ok(Gui {
            ctx,
            state,
            renderer,
            command_pool,
            draft: scene.clone(),
            error: None,
            path: "scene.toml".into(),
            message: String::new(),
            visible: true,
            collapsed: f64::from(window.inner_size().width) / window.scale_factor()
                < COLLAPSED_BELOW,
            panel_px: 0,
            auto_scale: false,
            inside: false,
            scale: 1.0,
            primitives: Vec::new(),
            pixels_per_point: 1.0,
            format,
            gpu: gpu.clone(),
        })
    }

    /// Follows a new swapchain format (rebuilding the GUI pipeline if it changed).
    pub fn set_format(&mut self, format: vk::Format) -> Result<()> {
        if format != self.format {
            self.renderer
                .set_render_mode(egui_ash_renderer::RenderMode::DynamicRendering(
                    egui_ash_renderer::DynamicRendering {
                        color_attachment_format: format,
                        depth_attachment_format: None,
                        stencil_attachment_format: None,
                    },
                ))
                .map_err(|e| Error::Other(format!("rebuilding the GUI renderer: {e}")))?;
            self.format = format;
        }
        Ok(())
    }

    /// Runs the panel for this frame (edits `self.draft`), uploads egui's
    /// texture changes and keeps the triangles for the overlay pass.
    pub fn run(
        &mut self,
        window: &winit::window::Window,
        applied: &Scene,
        stats: &Stats,
    ) -> Result<PanelActions> {
        let input = self.state.take_egui_input(window);
        let mut actions = PanelActions::default();
        let ctx = self.ctx.clone();
        // The panel's right edge, in points (0: hidden).
        let mut edge = 0.0f32;
        let output = ctx.run_ui(input, |ui| {
            if !self.visible {
                return;
            }
            if self.collapsed {
                let bar = egui::Panel::left("bar")
                    .resizable(false)
                    .exact_size(BAR_WIDTH)
                    .show(ui, |ui| {
                        if ui
                            .button("»")
                            .on_hover_text("show the panel (H hides it)")
                            .clicked()
                        {
                            self.collapsed = false;
                        }
                    });
                edge = bar.response.rect.max.x;
            } else {
                let panel = egui::Panel::left("parameters")
                    .default_size(300.0)
                    .show(ui, |ui| {
                        if ui
                            .button("«")
                            .on_hover_text("fold the panel to a bar (H hides it)")
                            .clicked()
                        {
                            self.collapsed = true;
                        }
                        egui::ScrollArea::vertical().show(ui, |ui| {
                            self.panel(ui, applied, stats, &mut actions);
                        });
                    });
                edge = panel.response.rect.max.x;
            }
        });
        // Rounded down: the view's first column sits under the panel's
        // edge, so no column of the window is left undrawn.
        self.panel_px = (edge * output.pixels_per_point).floor().max(0.0) as u32;
        self.state
            .handle_platform_output(window, output.platform_output);
        for (id, deltas) in &output.textures_delta.set {
            for delta in deltas {
                self.renderer
                    .set_texture(self.gpu.queue, self.command_pool, *id, delta)
                    .map_err(|e| Error::Other(format!("uploading a GUI texture: {e}")))?;
            }
        }
        if !output.textures_delta.free.is_empty() {
            // Frames in flight may still sample them: wait first.
            // SAFETY: valid device.
            unsafe { self.gpu.device.device_wait_idle() }.map_err(|result| Error::Vulkan {
                what: "waiting before freeing GUI textures".into(),
                result,
            })?;
            for id in &output.textures_delta.free {
                self.renderer
                    .free_texture(*id)
                    .map_err(|e| Error::Other(format!("freeing a GUI texture: {e}")))?;
            }
        }
        self.pixels_per_point = output.pixels_per_point;
        self.primitives = if self.visible {
            self.ctx.tessellate(output.shapes, output.pixels_per_point)
        } else {
            Vec::new()
        };
        Ok(actions)
    }

    fn panel(&mut self, ui: &mut Ui, applied: &Scene, stats: &Stats, actions: &mut PanelActions) {
        ui.heading("blackhole");
        ui.label(format!(
            "{:.1} fps on {}  |  frame {:.2} ms GPU",
            stats.fps, stats.device, stats.timings.frame_ms
        ));
        ui.label(format!(
            "render {}x{} of view {}x{}  |  {} samples",
            stats.render_size.0,
            stats.render_size.1,
            stats.view_size.0,
            stats.view_size.1,
            stats.samples
        ));
        egui::CollapsingHeader::new("GPU time per pass").show(ui, |ui| {
            egui::Grid::new("passes").striped(true).show(ui, |ui| {
                for p in &stats.timings.passes {
                    ui.label(&p.name);
                    ui.label(format!("{:.3} ms", p.ms));
                    ui.end_row();
                }
            });
        });
        ui.horizontal(|ui| {
            let before = (self.auto_scale, self.scale);
            ui.checkbox(&mut self.auto_scale, "auto scale");
            ui.add_enabled(
                !self.auto_scale,
                egui::Slider::new(&mut self.scale, 0.1..=1.0).text("render scale"),
            );
            if before != (self.auto_scale, self.scale) {
                actions.render_scale = Some((!self.auto_scale).then_some(self.scale));
            }
        });
        ui.checkbox(
            &mut self.inside,
            "let the wheel go inside the photon orbits (1.5 rs at spin 0)",
        );
        ui.separator();
        ui.horizontal(|ui| {
            ui.label("preset");
            egui::ComboBox::from_id_salt("preset")
                .selected_text("choose...")
                .show_ui(ui, |ui| {
                    for (name, what, _) in PRESETS {
                        if ui
                            .selectable_label(false, *name)
                            .on_hover_text(*what)
                            .clicked()
                        {
                            match Scene::load(name) {
                                Ok(s) => {
                                    self.draft = s.clone();
                                    actions.load = Some(s);
                                }
                                Err(e) => self.message = e.to_string(),
                            }
                        }
                    }
                });
        });
        ui.horizontal(|ui| {
            ui.text_edit_singleline(&mut self.path);
            if ui.button("Load").clicked() {
                match Scene::load(&self.path) {
                    Ok(s) => {
                        self.draft = s.clone();
                        self.message = format!("loaded {}", self.path);
                        actions.load = Some(s);
                    }
                    Err(e) => self.message = e.to_string(),
                }
            }
            if ui.button("Save").clicked() {
                self.message = match save_scene(applied, &self.path) {
                    Ok(()) => format!("saved {}", self.path),
                    Err(e) => e.to_string(),
                };
            }
        });
        if !self.message.is_empty() {
            ui.label(&self.message);
        }
        if let Some(e) = &self.error {
            ui.colored_label(Color32::from_rgb(255, 90, 90), format!("not applied: {e}"));
        }
        ui.separator();
        scene_editor(ui, &mut self.draft);
    }
}

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
        match c.projection {
            Projection::Fisheye => c.vfov_deg = 180.0,
            Projection::Pinhole if c.vfov_deg >= 180.0 => c.vfov_deg = 60.0,
            _ => {}
        }
        if c.projection != Projection::Equirect {
            c.stereo = Stereo::None;
        }
    }
    ui.label(match c.projection {
        Projection::Pinhole => "a flat image plane, vfov_deg top to bottom",
        Projection::Equirect => "the whole sky around the camera (2:1, vfov_deg unused)",
        Projection::Fisheye => "equidistant, vfov_deg across the circle (180: a dome master)",
    });
    if c.projection == Projection::Equirect {
        let mut ods = c.stereo == Stereo::Ods;
        ui.checkbox(&mut ods, "omni-directional stereo (left eye on top)");
        c.stereo = if ods { Stereo::Ods } else { Stereo::None };
        if ods {
            num(ui, "ipd (rs)", &mut c.ipd, 0.01);
        }
    }
}

/// Every scene key, grouped as in the TOML.
fn scene_editor(ui: &mut Ui, s: &mut Scene) {
    camera_and_holes(ui, s);
    disk_and_physics(ui, s);
    sky_and_plane(ui, s);
    post_and_quality(ui, s);
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
            if i == 0 {
                follow_isco(inner, h.rs, before, h.spin);
            }
            if h.spin != 0.0 {
                let (rs, a) = (h.rs, h.spin);
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

impl Overlay for Gui {
    fn add_passes<'a>(&'a mut self, graph: &mut Graph<'a>, target: &mut ImageHandle) {
        if self.primitives.is_empty() {
            return;
        }
        let extent = vk::Extent2D {
            width: target.desc.width,
            height: target.desc.height,
        };
        let ppp = self.pixels_per_point;
        let renderer = &mut self.renderer;
        let primitives = &self.primitives;
        let mut pass = graph.add_pass("gui");
        let out = pass.write(target, Access::ColorAttachmentWrite, Mips::ALL);
        pass.record(move |ctx| {
            let attachment = [vk::RenderingAttachmentInfo::default()
                .image_view(ctx.view(&out, 0))
                .image_layout(vk::ImageLayout::COLOR_ATTACHMENT_OPTIMAL)
                .load_op(vk::AttachmentLoadOp::LOAD)
                .store_op(vk::AttachmentStoreOp::STORE)];
            let info = vk::RenderingInfo::default()
                .render_area(vk::Rect2D {
                    offset: vk::Offset2D::default(),
                    extent,
                })
                .layer_count(1)
                .color_attachments(&attachment);
            // SAFETY: the graph put the image in COLOR_ATTACHMENT_OPTIMAL;
            // dynamic rendering is enabled on windowed devices.
            unsafe { ctx.gpu.device.cmd_begin_rendering(ctx.cmd, &info) };
            let drawn = renderer.cmd_draw(ctx.cmd, extent, ppp, primitives);
            // SAFETY: paired with the begin above.
            unsafe { ctx.gpu.device.cmd_end_rendering(ctx.cmd) };
            drawn.map_err(|e| Error::Other(format!("drawing the GUI: {e}")))
        });
    }
}

impl Drop for Gui {
    fn drop(&mut self) {
        // SAFETY: every frame that used the pool's buffers has finished.
        unsafe {
            let _ = self.gpu.device.device_wait_idle();
            self.gpu
                .device
                .destroy_command_pool(self.command_pool, None);
        }
    }
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
