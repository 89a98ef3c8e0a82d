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
use egui::{Color32, Ui};

use super::editors;
use crate::frame::FrameTimings;
use crate::graph::{Graph, ImageHandle, Mips};
use crate::render::Overlay;
use crate::scene::{PRESETS, Scene};
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
    /// Where the camera is (app/fall.rs, `camera_status`).
    pub camera: String,
    /// A fall into the hole is in progress.
    pub falling: bool,
}

/// Requests from the panel to the window.
#[derive(Clone, Debug, Default)]
pub struct PanelActions {
    /// A scene to switch to (preset or file), already validated.
    pub load: Option<Scene>,
    /// The render scale changed (None: auto).
    pub render_scale: Option<Option<f64>>,
    /// Start a fall into the hole from the current view (true) or return
    /// to the view it started from (false).
    pub fall: Option<bool>,
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
        self.view_controls(ui, stats, actions);
        ui.separator();
        self.scene_files(ui, applied, actions);
        if !self.message.is_empty() {
            ui.label(&self.message);
        }
        if let Some(e) = &self.error {
            ui.colored_label(Color32::from_rgb(255, 90, 90), format!("not applied: {e}"));
        }
        ui.separator();
        editors::scene_editor(ui, &mut self.draft);
    }

    /// The view's controls: the render scale, how far in the wheel goes,
    /// the fall in (or the return) and the line of where the camera is.
    fn view_controls(&mut self, ui: &mut Ui, stats: &Stats, actions: &mut PanelActions) {
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
        ui.horizontal(|ui| {
            if stats.falling {
                if ui
                    .button("return")
                    .on_hover_text("back to the view the fall started from")
                    .clicked()
                {
                    actions.fall = Some(false);
                }
            } else if ui
                .button("fall in")
                .on_hover_text(
                    "drop from rest into the hole from this view, as [animation] camera = \"fall\" \
                     does (through the horizon of a non-rotating hole)",
                )
                .clicked()
            {
                actions.fall = Some(true);
            }
            ui.label(&stats.camera);
        });
    }

    /// The scene's files: a preset, or a scene file loaded or saved.
    fn scene_files(&mut self, ui: &mut Ui, applied: &Scene, actions: &mut PanelActions) {
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
                self.message = match editors::save_scene(applied, &self.path) {
                    Ok(()) => format!("saved {}", self.path),
                    Err(e) => e.to_string(),
                };
            }
        });
    }
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
