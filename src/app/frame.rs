//! One frame of the window: the clock (frame time, scene time, automatic
//! render scale), the panel's draft applied where it validates, progressive
//! refinement of a still view, the frame drawn onto the swapchain image, and
//! the saved view (F12) and screenshot.

use std::path::PathBuf;
use std::time::{Duration, Instant};

use super::fall::WindowFall;
use super::gui::Stats;
use super::{AUTO_TARGET_MS, MAX_SAMPLES, Orbit, Running, WindowOptions};
use crate::frame::{Frame, OutputKind};
use crate::render::{SwapchainTarget, ViewOptions};
use crate::scene::Scene;
use crate::{Error, Result};

impl Running {
    /// Draws and presents one frame.
    pub(super) fn frame(&mut self, options: &WindowOptions) -> Result<()> {
        self.tick();
        let renderer = self
            .renderer
            .as_mut()
            .ok_or_else(|| Error::Other("renderer already shut down".into()))?;
        if let Some(t) = renderer.begin_window_frame()? {
            self.timings = t;
        }
        if self.resized {
            renderer.wait_idle()?;
            let size = self.window.inner_size();
            self.swapchain
                .recreate((size.width.max(1), size.height.max(1)))?;
            self.gui.set_format(self.swapchain.format)?;
            renderer.trim()?;
            self.resized = false;
        }
        let Some(image) = self.swapchain.acquire()? else {
            self.resized = true;
            return Ok(());
        };
        let (w, h) = (image.desc.width, image.desc.height);

        // The panel edits a draft; apply it only when it validates.
        let device = renderer.device_name().to_owned();
        let stats = self.stats(device);
        self.gui.draft.camera = self.orbit.camera();
        // The panel shows the scale in use (auto moves it).
        self.gui.auto_scale = self.auto_scale;
        self.gui.scale = self.scale;
        let actions = self.gui.run(&self.window, &self.scene, &stats)?;
        // The view is the part of the window right of the panel: the ray
        // march renders that part, centred there, at the render scale.
        let view_x = self.gui.panel_px.min(w - 1);
        let view_w = w - view_x;
        self.view = (view_x, view_w, h);
        let render_size = (
            ((f64::from(view_w) * self.scale).round() as u32).clamp(1, view_w),
            ((f64::from(h) * self.scale).round() as u32).clamp(1, h),
        );
        self.render_size = render_size;
        self.orbit.allow_inside = self.gui.inside;
        let previous = self.scene.clone();
        if let Some(s) = actions.load {
            self.loaded = s.clone();
            self.scene = s;
            self.orbit = Orbit::from_camera(&self.scene.camera);
            self.fall = None;
        } else {
            match self.gui.draft.check() {
                Ok(()) => {
                    self.gui.error = None;
                    if self.gui.draft.camera != self.orbit.camera() {
                        self.orbit = Orbit::from_camera(&self.gui.draft.camera);
                    }
                    self.scene = self.gui.draft.clone();
                    self.scene.base_dir = self.loaded.base_dir.clone();
                }
                Err(e) => self.gui.error = Some(e.to_string()),
            }
        }
        self.prepare(previous)?;
        if let Some(scale) = actions.render_scale {
            self.auto_scale = scale.is_none();
            if let Some(s) = scale {
                self.scale = s;
            }
        }
        self.step_fall(actions.fall);
        self.scene.camera = self.orbit.camera();
        let mut drawn = self.scene.clone();
        drawn.time = self.time;

        let jitter = self.next_sample(&drawn, render_size);
        // With --screenshot every frame is copied out, so whichever frame
        // turns out to be the last (--frames, Esc, closing) can be written.
        let capture = options.screenshot.is_some();
        let renderer = self
            .renderer
            .as_mut()
            .ok_or_else(|| Error::Other("renderer already shut down".into()))?;
        renderer.draw_to_swapchain(
            &drawn,
            ViewOptions {
                render_size,
                view_x,
                jitter: (jitter.0 as f32, jitter.1 as f32),
                sample: Some(self.samples),
            },
            SwapchainTarget {
                desc: image.desc,
                binding: image.binding,
                acquired: image.acquired,
                rendered: image.rendered,
                overlay: Some(&mut self.gui),
                capture,
            },
        )?;
        if !self.swapchain.present(image.index, image.rendered)? {
            self.resized = true;
        }
        self.presented += 1;
        if self.wants_f12 {
            self.wants_f12 = false;
            self.save_view()?;
        }
        Ok(())
    }

    /// The renderer made ready for the scene. A sky image that cannot be
    /// read is an error in the panel, not the end of the program: the scene
    /// that worked (`previous`) is kept.
    fn prepare(&mut self, previous: Scene) -> Result<()> {
        let renderer = self
            .renderer
            .as_mut()
            .ok_or_else(|| Error::Other("renderer already shut down".into()))?;
        if let Err(e) = renderer.prepare_scene(&self.scene) {
            self.gui.error = Some(e.to_string());
            self.scene = previous;
            self.gui.draft = self.scene.clone();
            renderer.prepare_scene(&self.scene)?;
        }
        Ok(())
    }

    /// What the panel shows of the window's state.
    fn stats(&self, device: String) -> Stats {
        Stats {
            fps: self.fps,
            timings: self.timings.clone(),
            render_size: self.render_size,
            view_size: (self.view.1, self.view.2),
            samples: self.samples,
            device,
            camera: super::fall::camera_status(&self.scene),
            falling: self.fall.is_some(),
        }
    }

    /// The fall into the hole (app/fall.rs): started or ended by the panel
    /// (`asked`) or F, and the orbit moved along it.
    fn step_fall(&mut self, asked: Option<bool>) {
        let key = std::mem::take(&mut self.wants_fall).then_some(self.fall.is_none());
        match asked.or(key) {
            Some(true) => {
                self.fall = WindowFall::start(&self.orbit, &self.scene);
                // The fall's end too: a camera that crosses a spinning
                // hole's horizon switches ray march there (KERR_INSIDE),
                // built now rather than at the crossing.
                if let (Some(f), Some(renderer)) = (&self.fall, self.renderer.as_mut()) {
                    let mut end = self.scene.clone();
                    let t = self.scene.animation.fall_seconds;
                    end.camera = f.orbit_after(&self.orbit, &self.scene, t).camera();
                    if let Err(e) = renderer.prepare_scene(&end) {
                        self.gui.error = Some(e.to_string());
                        self.fall = None;
                    }
                }
            }
            Some(false) => {
                if let Some(f) = self.fall.take() {
                    self.orbit = f.before;
                }
            }
            None => {}
        }
        if let Some(f) = &self.fall {
            self.orbit = f.orbit_at(&self.orbit, &self.scene, Instant::now());
        }
    }

    /// The clock: the frame time's running mean, the scene's time (unless
    /// paused) and the automatic render scale.
    fn tick(&mut self) {
        let now = Instant::now();
        let dt = now
            .duration_since(self.last_frame)
            .min(Duration::from_millis(500));
        self.last_frame = now;
        let dt_s = dt.as_secs_f64();
        // Average the frame time, not the rate: frames in flight make single
        // intervals uneven.
        if dt_s > 0.0 {
            self.frame_s = if self.frame_s == 0.0 {
                dt_s
            } else {
                0.9 * self.frame_s + 0.1 * dt_s
            };
            self.fps = 1.0 / self.frame_s;
        }
        if !self.paused {
            self.time += dt_s;
        }
        // Automatic render scale: cost goes with the pixel count, so the
        // scale moves by sqrt(target / measured), in 5% steps and only when
        // off by more than 20%, so a still view keeps one size and refines.
        if self.auto_scale && dt_s > 0.0 && self.samples == 0 {
            let ideal = (self.scale * (AUTO_TARGET_MS / (dt_s * 1e3)).sqrt()).clamp(0.1, 1.0);
            if (ideal / self.scale - 1.0).abs() > 0.2 {
                self.scale = (ideal * 20.0).round() / 20.0;
            }
        }
    }

    /// Progressive refinement while nothing changes: the sample count of
    /// the unchanged view and this frame's sub-pixel jitter (none for the
    /// first sample).
    fn next_sample(&mut self, drawn: &Scene, render_size: (u32, u32)) -> (f64, f64) {
        let mut key = drawn.clone();
        if drawn.disk.kind != crate::scene::DiskKind::Volumetric {
            key.time = 0.0;
        }
        let still = Some((key, render_size));
        if still == self.still {
            self.samples = (self.samples + 1).min(MAX_SAMPLES);
        } else {
            self.samples = 0;
            self.still = still;
        }
        // The polarized picture is of the rays through the pixel centres
        // (as `--aov stokes`): not refined.
        if drawn.polarization.enabled {
            return (0.0, 0.0);
        }
        crate::camera::jitter(self.samples)
    }

    /// F12: the view at full quality (the free view's full width, no
    /// panel, in the scene's projection) as PNG.
    fn save_view(&mut self) -> Result<()> {
        let renderer = self
            .renderer
            .as_mut()
            .ok_or_else(|| Error::Other("renderer already shut down".into()))?;
        // The view's width (the part of the window the panel leaves free);
        // the height the projection's own shape asks: the view's for the
        // pinhole, half the width for a panorama (2:1), the width for a
        // stereo pair of panoramas or a dome.
        let (_, w, view_h) = self.view;
        let camera = &self.scene.camera;
        let h = camera.projection.natural_height(camera.stereo, w, view_h);
        renderer.wait_idle()?;
        let mut scene = self.scene.clone();
        scene.time = self.time;
        let frame = renderer.render(&scene, w, h, OutputKind::Ldr)?;
        let stamp = std::time::SystemTime::now()
            .duration_since(std::time::UNIX_EPOCH)
            .map(|d| d.as_secs())
            .unwrap_or(0);
        let path = PathBuf::from(format!("blackhole-{stamp}.png"));
        crate::output::write_frame(&frame, &path, crate::output::FileFormat::Png)?;
        self.gui.message = format!("saved {}", path.display());
        log::info!("saved {}", path.display());
        Ok(())
    }

    /// `--screenshot`: the last presented frame, as the window showed it.
    pub(super) fn save_capture(&mut self, path: &std::path::Path) -> Result<()> {
        let renderer = self
            .renderer
            .as_mut()
            .ok_or_else(|| Error::Other("renderer already shut down".into()))?;
        let frame: Frame = renderer.take_capture()?;
        crate::output::write_frame(&frame, path, crate::output::FileFormat::Png)?;
        log::info!("wrote {}", path.display());
        Ok(())
    }
}
