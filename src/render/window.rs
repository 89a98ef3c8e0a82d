//! Frames onto a swapchain image (the window): two frames in flight, the
//! progressive accumulation of an unchanged view, the overlay (the GUI
//! panel) and the capture of a presented frame.

use ash::vk;

use super::{Accumulation, Renderer, SceneFrame, add_scene_frame, import_mean};
use crate::frame::{Frame, FrameTimings, OutputKind, Pixels};
use crate::graph::{Graph, ImageHandle};
use crate::passes::{self, copy};
use crate::scene::Scene;
use crate::vk::{Access, ImageBinding, ImageDesc};
use crate::{Error, Result};

/// How the window wants one frame drawn.
#[derive(Clone, Copy, Debug)]
pub struct ViewOptions {
    /// Size of the ray march (the window's size times the render scale).
    pub render_size: (u32, u32),
    /// The view's first column on the swapchain image: the frame is drawn
    /// over the rest of its width (the panel covers the columns left of it).
    pub view_x: u32,
    /// Sub-pixel jitter of the ray march, in pixels (0, 0 = pixel centres).
    pub jitter: (f32, f32),
    /// Which sample of an unchanged view this frame is; `None` turns the
    /// progressive accumulation off.
    pub sample: Option<u32>,
}

/// Something drawn over the frame on the swapchain image (the GUI panel).
pub trait Overlay {
    /// Adds the overlay's passes; `target` is the swapchain image, holding
    /// the frame already.
    fn add_passes<'a>(&'a mut self, graph: &mut Graph<'a>, target: &mut ImageHandle);
}

/// A swapchain image to draw onto, with its semaphores.
pub struct SwapchainTarget<'t> {
    pub desc: ImageDesc,
    pub binding: ImageBinding,
    /// Signalled by the acquire; waited at [`Access::Acquired`]'s stages.
    pub acquired: vk::Semaphore,
    /// Signalled when the frame is done; presentation waits on it.
    pub rendered: vk::Semaphore,
    pub overlay: Option<&'t mut dyn Overlay>,
    /// Also copy the finished image to the host ([`Renderer::take_capture`]).
    pub capture: bool,
}

impl Renderer {
    /// Waits for the frame slot the next windowed frame will use (call it
    /// before acquiring a swapchain image, so the slot's acquire semaphore is
    /// free again); returns that slot's last frame's GPU timings.
    pub fn begin_window_frame(&mut self) -> Result<Option<FrameTimings>> {
        self.slots[self.next_slot].wait()
    }

    /// Draws `scene` onto a swapchain image (the window): the frame recipe at
    /// `view.render_size`, a blit onto the image, then the overlay, in the
    /// slot [`Renderer::begin_window_frame`] waited for. Does not wait for
    /// the GPU.
    pub fn draw_to_swapchain(
        &mut self,
        scene: &Scene,
        view: ViewOptions,
        target: SwapchainTarget<'_>,
    ) -> Result<()> {
        let (w, h) = view.render_size;
        self.check_size(w, h)?;
        self.check_size(target.desc.width, target.desc.height)?;
        let slot_index = self.next_slot;
        self.next_slot = (self.next_slot + 1) % self.slots.len();
        let plan = self.start_frame(
            slot_index,
            scene,
            view.render_size,
            view.jitter,
            OutputKind::Ldr,
        )?;

        // The running mean follows the render size; a new one starts over.
        let mut sample = view.sample;
        if let Some(s) = sample.as_mut()
            && self.ensure_mean((w, h))?
        {
            *s = 0;
        }

        let (out_w, out_h) = (target.desc.width, target.desc.height);
        let mut g = Graph::new(out_w, out_h);
        let mean_handle = match (sample, self.mean.as_ref()) {
            (Some(_), Some((img, state))) => {
                Some(import_mean(&mut g, (img.desc, img.binding(), *state)))
            }
            _ => None,
        };
        let accumulation = match (mean_handle, sample) {
            (Some(mean), Some(index)) => Some(Accumulation { mean, index }),
            _ => None,
        };
        let frame = SceneFrame {
            scene,
            plan: &plan,
            params: self.slots[slot_index].params.binding(),
            size: (w, h),
            output: OutputKind::Ldr,
            accumulation,
        };
        let ldr = add_scene_frame(&mut g, &self.pipelines, &self.resources, frame);
        let mut swap = g.import_image(
            "swapchain",
            target.desc,
            target.binding,
            Access::Acquired,
            Some(Access::Present),
        );
        passes::present::add_blit_to(&mut g, &ldr, &mut swap, view.view_x.min(out_w - 1));
        if let Some(o) = target.overlay {
            o.add_passes(&mut g, &mut swap);
        }
        if target.capture {
            let needed = u64::from(out_w) * u64::from(out_h) * 4;
            let gpu = self.gpu.clone();
            let readback = self.slots[slot_index]
                .ensure_readback(&gpu, needed)?
                .binding();
            let mut buf =
                g.import_buffer("capture", readback, Access::Nothing, Some(Access::HostRead));
            copy::add_copy_to_buffer(&mut g, &swap, &mut buf);
            self.capture = Some((slot_index, out_w, out_h, target.desc.format));
        }
        let waits = [(target.acquired, Access::Acquired.info().stage)];
        let left = self.slots[slot_index].submit(&self.gpu, g, &waits, &[target.rendered])?;
        self.keep_mean_state(&left);
        Ok(())
    }

    /// The last frame drawn with `capture`, as 8-bit RGBA (waits for it).
    pub fn take_capture(&mut self) -> Result<Frame> {
        let (slot, width, height, format) = self
            .capture
            .take()
            .ok_or_else(|| Error::Other("no frame was captured".into()))?;
        self.wait_idle()?;
        let readback = self.slots[slot]
            .readback
            .as_ref()
            .ok_or_else(|| Error::Other("capture buffer missing".into()))?;
        let needed = (u64::from(width) * u64::from(height) * 4) as usize;
        let mut bytes = readback.mapped()?[..needed].to_vec();
        if matches!(
            format,
            vk::Format::B8G8R8A8_UNORM | vk::Format::B8G8R8A8_SRGB
        ) {
            for px in bytes.chunks_exact_mut(4) {
                px.swap(0, 2);
            }
        }
        Ok(Frame {
            width,
            height,
            pixels: Pixels::Rgba8(bytes),
            timings: FrameTimings::default(),
        })
    }
}
