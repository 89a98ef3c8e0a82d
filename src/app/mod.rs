//! `blackhole window`: the real-time demo. A winit 0.30 `ApplicationHandler`
//! owns the window, the surface and swapchain, the renderer (the same frame
//! graph and passes as offscreen) and the egui panel. Each frame: wait for
//! the frame slot, acquire an image, run the panel, draw the recipe onto the
//! image through the graph (blit, then the GUI pass), present.

pub mod camera;
mod display;
pub mod editors;
pub mod fall;
mod frame;
pub mod gui;

use std::path::PathBuf;
use std::process::ExitCode;
use std::sync::Arc;
use std::time::Instant;

use winit::application::ApplicationHandler;
use winit::event::{ElementState, MouseButton, MouseScrollDelta, WindowEvent};
use winit::event_loop::{ActiveEventLoop, ControlFlow, EventLoop};
use winit::keyboard::{Key, NamedKey};
use winit::window::{Window, WindowId};

use crate::frame::FrameTimings;
use crate::render::{FRAMES_IN_FLIGHT, Renderer};
use crate::scene::Scene;
use crate::vk::{Gpu, Instance, PresentMode, Swapchain};
use crate::{Error, Result};
use camera::Orbit;
use gui::Gui;

/// Frame time the automatic render scale aims at (20 frames a second).
const AUTO_TARGET_MS: f64 = 50.0;
/// Most samples the still view accumulates.
const MAX_SAMPLES: u32 = 4096;

/// What `blackhole window` was asked.
#[derive(Clone, Debug)]
pub struct WindowOptions {
    pub scene: Scene,
    pub width: u32,
    pub height: u32,
    /// Fraction of the window's size the ray march runs at; None: automatic.
    pub render_scale: Option<f64>,
    pub present: PresentMode,
    /// Exit after this many presented frames.
    pub frames: Option<u64>,
    /// Write the last presented frame (with the panel) here as PNG when
    /// the window closes.
    pub screenshot: Option<PathBuf>,
}

/// Opens the window and runs until it is closed (or `--frames` is reached).
pub fn run(options: WindowOptions) -> Result<ExitCode> {
    display::check_display()?;
    let event_loop = EventLoop::new().map_err(|e| {
        Error::Usage(format!(
            "cannot open a window: {} (no display? set DISPLAY (X11) or WAYLAND_DISPLAY, or run under Xvfb)",
            display::without_source_location(&e.to_string())
        ))
    })?;
    event_loop.set_control_flow(ControlFlow::Wait);
    let mut app = App {
        options,
        running: None,
        error: None,
        validation: (0, 0, false),
    };
    event_loop
        .run_app(&mut app)
        .map_err(|e| Error::Other(format!("window event loop: {e}")))?;
    if let Some(e) = app.error {
        return Err(e);
    }
    let (errors, warnings, enabled) = app.validation;
    if enabled {
        eprintln!("validation: {errors} errors, {warnings} warnings");
    }
    Ok(if errors + warnings > 0 {
        ExitCode::from(3)
    } else {
        ExitCode::SUCCESS
    })
}

struct App {
    options: WindowOptions,
    running: Option<Running>,
    error: Option<Error>,
    /// Validation counts and whether it was on, kept after shutdown.
    validation: (u32, u32, bool),
}

/// Everything alive while the window is open. Fields drop in order: the
/// panel and the swapchain (both wait for the GPU), then the renderer, then
/// the window.
struct Running {
    gui: Gui,
    swapchain: Swapchain,
    renderer: Option<Renderer>,
    window: Arc<Window>,
    /// The scene as loaded (R resets to it).
    loaded: Scene,
    /// The scene drawn (the camera follows `orbit`).
    scene: Scene,
    orbit: Orbit,
    /// A fall into the hole in progress (the panel's "fall in").
    fall: Option<fall::WindowFall>,
    paused: bool,
    time: f64,
    last_frame: Instant,
    fps: f64,
    /// Smoothed seconds per frame.
    frame_s: f64,
    timings: FrameTimings,
    scale: f64,
    auto_scale: bool,
    /// The view the running mean belongs to, and its sample count.
    still: Option<(Scene, (u32, u32))>,
    samples: u32,
    resized: bool,
    minimized: bool,
    dragging: Option<MouseButton>,
    cursor: Option<(f64, f64)>,
    presented: u64,
    /// The view's place in the window: first column, width, height (the
    /// part the panel leaves free).
    view: (u32, u32, u32),
    /// The ray march's size last frame.
    render_size: (u32, u32),
    wants_f12: bool,
    /// F pressed: fall in, or return from a fall (as the panel's button).
    wants_fall: bool,
    started: Instant,
    /// Keys held down (to ignore duplicate presses).
    keys_down: Vec<Key>,
}

impl App {
    fn start(&mut self, event_loop: &ActiveEventLoop) -> Result<Running> {
        let attrs = Window::default_attributes()
            .with_title("blackhole")
            .with_inner_size(winit::dpi::PhysicalSize::new(
                self.options.width,
                self.options.height,
            ));
        let window = Arc::new(
            event_loop
                .create_window(attrs)
                .map_err(|e| Error::Other(format!("creating the window: {e}")))?,
        );
        let (display, handle) = handles(&window)?;
        let exts = ash_window::enumerate_required_extensions(display)
            .map_err(|result| Error::Vulkan {
                what: "listing the window system's Vulkan extensions".into(),
                result,
            })?
            .to_vec();
        let settings = crate::settings::get();
        let instance = Instance::with_extensions(settings.validation_mode(), &exts)?;
        // SAFETY: the handles come from a live window that outlives the surface
        // (the swapchain, which owns the surface, drops before the window).
        let surface = unsafe {
            ash_window::create_surface(&instance.entry, &instance.instance, display, handle, None)
        }
        .map_err(|result| Error::Vulkan {
            what: "creating the window's Vulkan surface".into(),
            result,
        })?;
        let surface_fn = ash::khr::surface::Instance::new(&instance.entry, &instance.instance);
        let check = |_: &Instance, pd: ash::vk::PhysicalDevice, family: u32| {
            // SAFETY: the surface and device belong to this instance.
            unsafe { surface_fn.get_physical_device_surface_support(pd, family, surface) }
                .unwrap_or(false)
        };
        let gpu = Gpu::open(instance, Some(&check), settings.gpu())?;
        let size = window.inner_size();
        let swapchain = Swapchain::new(
            &gpu,
            surface,
            (size.width.max(1), size.height.max(1)),
            self.options.present,
            FRAMES_IN_FLIGHT,
        )?;
        // The panel changes the scene's static parameters between frames:
        // read from the parameter block, not compiled in (a pipeline each).
        let options = crate::RendererOptions {
            bake: false,
            ..Default::default()
        };
        let renderer = Renderer::with_gpu(gpu.clone(), options)?;
        let scene = self.options.scene.clone();
        let gui = Gui::new(&gpu, &window, swapchain.format, FRAMES_IN_FLIGHT, &scene)?;
        log::info!(
            "window {}x{} on {}, present mode {:?}",
            swapchain.extent.width,
            swapchain.extent.height,
            gpu.info.name,
            swapchain.mode
        );
        Ok(Running {
            orbit: Orbit::from_camera(&scene.camera),
            fall: None,
            loaded: scene.clone(),
            scene,
            gui,
            swapchain,
            renderer: Some(renderer),
            window,
            paused: false,
            time: 0.0,
            last_frame: Instant::now(),
            fps: 0.0,
            frame_s: 0.0,
            timings: FrameTimings::default(),
            scale: self.options.render_scale.unwrap_or(0.5),
            auto_scale: self.options.render_scale.is_none(),
            still: None,
            samples: 0,
            resized: false,
            minimized: false,
            dragging: None,
            cursor: None,
            presented: 0,
            view: (0, size.width.max(1), size.height.max(1)),
            render_size: (1, 1),
            wants_f12: false,
            wants_fall: false,
            keys_down: Vec::new(),
            started: Instant::now(),
        })
    }

    fn fail(&mut self, event_loop: &ActiveEventLoop, e: Error) {
        if self.error.is_none() {
            self.error = Some(e);
        }
        self.stop(event_loop);
    }

    /// Writes the screenshot if asked, shuts down in order (checking for
    /// leaks) and leaves the loop.
    fn stop(&mut self, event_loop: &ActiveEventLoop) {
        if let Some(mut r) = self.running.take() {
            let secs = r.started.elapsed().as_secs_f64();
            eprintln!(
                "presented {} frames in {secs:.1} s ({:.1} frames a second)",
                r.presented,
                r.presented as f64 / secs.max(1e-9)
            );
            // Where the view was (tests find its centre by this line).
            eprintln!(
                "view at x {} width {} height {}",
                r.view.0, r.view.1, r.view.2
            );
            if let Some(path) = self.options.screenshot.clone() {
                if r.presented > 0 {
                    if let Err(e) = r.save_capture(&path) {
                        self.error.get_or_insert(e);
                    }
                }
            }
            if let Some(renderer) = r.renderer.take() {
                let (e, w) = renderer.validation_counts();
                self.validation = (e, w, renderer.validation_enabled());
                drop(r);
                if let Err(err) = renderer.shutdown() {
                    self.error.get_or_insert(err);
                }
            }
        }
        event_loop.exit();
    }
}

fn handles(
    window: &Window,
) -> Result<(
    raw_window_handle::RawDisplayHandle,
    raw_window_handle::RawWindowHandle,
)> {
    use raw_window_handle::{HasDisplayHandle, HasWindowHandle};
    let d = window
        .display_handle()
        .map_err(|e| Error::Other(format!("the window's display handle: {e}")))?;
    let w = window
        .window_handle()
        .map_err(|e| Error::Other(format!("the window's handle: {e}")))?;
    Ok((d.as_raw(), w.as_raw()))
}

impl ApplicationHandler for App {
    fn resumed(&mut self, event_loop: &ActiveEventLoop) {
        if self.running.is_some() {
            return;
        }
        match self.start(event_loop) {
            Ok(r) => {
                r.window.request_redraw();
                self.running = Some(r);
            }
            Err(e) => self.fail(event_loop, e),
        }
    }

    fn window_event(&mut self, event_loop: &ActiveEventLoop, _id: WindowId, event: WindowEvent) {
        let Some(r) = self.running.as_mut() else {
            return;
        };
        let consumed = r.gui.state.on_window_event(&r.window, &event).consumed;
        // X11 may deliver one press twice (with input methods): act on the
        // first press of a key until it is released.
        let mut first_press = false;
        if let WindowEvent::KeyboardInput { event: k, .. } = &event {
            let key = k.logical_key.clone();
            if k.state == ElementState::Pressed {
                first_press = !k.repeat && !r.keys_down.contains(&key);
                if first_press {
                    r.keys_down.push(key);
                }
            } else {
                r.keys_down.retain(|d| *d != key);
            }
        }
        match event {
            WindowEvent::CloseRequested => self.stop(event_loop),
            WindowEvent::Resized(size) => {
                r.minimized = size.width == 0 || size.height == 0;
                r.resized = true;
                if !r.minimized {
                    r.window.request_redraw();
                }
            }
            WindowEvent::MouseInput { state, button, .. }
                if !consumed || state == ElementState::Released =>
            {
                r.dragging = (state == ElementState::Pressed).then_some(button);
            }
            WindowEvent::CursorMoved { position, .. } => {
                let p = (position.x, position.y);
                if let (Some(button), Some(last)) = (r.dragging, r.cursor) {
                    let (dx, dy) = (p.0 - last.0, p.1 - last.1);
                    let h = f64::from(r.swapchain.extent.height);
                    match button {
                        MouseButton::Left => r.orbit.rotate(dx, dy, h),
                        MouseButton::Right => r.orbit.pan(dx, dy, h),
                        _ => {}
                    }
                }
                r.cursor = Some(p);
            }
            WindowEvent::MouseWheel { delta, .. } if !consumed => {
                let steps = match delta {
                    MouseScrollDelta::LineDelta(_, y) => f64::from(y),
                    MouseScrollDelta::PixelDelta(p) => p.y / 40.0,
                };
                r.orbit.zoom(steps, &r.scene.spacetime());
            }
            WindowEvent::KeyboardInput { event, .. } if !consumed && first_press => {
                match event.logical_key.as_ref() {
                    Key::Named(NamedKey::Escape) => self.stop(event_loop),
                    Key::Named(NamedKey::Space) => r.paused = !r.paused,
                    Key::Named(NamedKey::F12) => r.wants_f12 = true,
                    Key::Character(c) => match c {
                        "1" | "2" | "3" => {
                            let n = c.as_bytes()[0] - b'0';
                            r.orbit = camera::preset_view(n, &r.orbit);
                        }
                        "r" | "R" => {
                            r.scene = r.loaded.clone();
                            r.gui.draft = r.loaded.clone();
                            r.orbit = Orbit::from_camera(&r.loaded.camera);
                            r.fall = None;
                            r.time = 0.0;
                        }
                        "h" | "H" => r.gui.visible = !r.gui.visible,
                        "f" | "F" => r.wants_fall = true,
                        _ => {}
                    },
                    _ => {}
                }
            }
            WindowEvent::RedrawRequested => {
                if r.minimized {
                    return;
                }
                match r.frame(&self.options) {
                    Ok(()) => {}
                    Err(e) => return self.fail(event_loop, e),
                }
                let r = match self.running.as_mut() {
                    Some(r) => r,
                    None => return,
                };
                if self.options.frames.is_some_and(|n| r.presented >= n) {
                    return self.stop(event_loop);
                }
                r.window.request_redraw();
            }
            _ => {}
        }
    }
}
