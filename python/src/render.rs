//! `blackhole.Renderer`: one Vulkan device opened once, stills, HDR, the
//! AOVs and the profiler's timings as numpy arrays. The GIL is released
//! while the device works; Ctrl-C stops a render between its samples.

use std::sync::Mutex;
use std::sync::atomic::{AtomicBool, Ordering};
use std::time::Duration;

use blackhole::{OutputKind, Pixels, RendererOptions};
use numpy::{PyArray1, PyArrayMethods};
use pyo3::exceptions::PyValueError;
use pyo3::prelude::*;

use crate::scene::Scene;
use crate::values::whole;
use crate::{DeviceError, to_py};

/// Raised when Python sees a signal (Ctrl-C) during a render: the
/// renderer stops between samples ([`blackhole::Renderer::stop_when`]).
/// One for the process, as the signal is.
static STOP: AtomicBool = AtomicBool::new(false);

/// The renderer: opens the Vulkan device once (the first one, or
/// `BLACKHOLE_GPU`), builds pipelines as scenes need them and keeps them.
/// Safe to share between threads: calls take turns on the device.
#[pyclass(module = "blackhole", frozen)]
pub struct Renderer {
    inner: Mutex<Option<blackhole::Renderer>>,
    device: String,
}

/// Which moment of the animation an image shows.
#[derive(Clone, Copy)]
enum When {
    /// The scene as written (the command line's still).
    Still,
    /// Seconds into the animation.
    Time(f64),
    /// A frame's index (as `render --frames`).
    Frame(u64),
}

/// A frame index as the crate takes it (a negative one refused by name).
fn frame_index(frame: Option<i64>) -> PyResult<Option<u64>> {
    frame
        .map(|i| {
            u64::try_from(i)
                .map_err(|_| PyValueError::new_err(format!("frame = {i}: must be 0 or more")))
        })
        .transpose()
}

fn when(time: Option<f64>, frame: Option<u64>) -> PyResult<When> {
    match (time, frame) {
        (Some(_), Some(_)) => Err(PyValueError::new_err("give `time` or `frame`, not both")),
        (Some(t), None) if !t.is_finite() => Err(PyValueError::new_err(format!(
            "time = {t}: must be a finite number of seconds"
        ))),
        (Some(t), None) => Ok(When::Time(t)),
        (None, Some(i)) => Ok(When::Frame(i)),
        (None, None) => Ok(When::Still),
    }
}

impl Renderer {
    /// Runs `work` on the renderer in a thread of its own while this one
    /// waits without the GIL, looking for signals every 20 ms: on Ctrl-C
    /// the render stops between samples and KeyboardInterrupt is raised.
    fn run<T: Send>(
        &self,
        py: Python<'_>,
        work: impl FnOnce(&mut blackhole::Renderer) -> blackhole::Result<T> + Send,
    ) -> PyResult<T> {
        let job = || {
            let mut guard = self.inner.lock().map_err(|_| {
                blackhole::Error::Other("the renderer failed in another thread".into())
            })?;
            let r = guard
                .as_mut()
                .ok_or_else(|| blackhole::Error::Other("the renderer is closed".into()))?;
            work(r)
        };
        std::thread::scope(|s| {
            let handle = s.spawn(job);
            let mut interrupt = None;
            while !handle.is_finished() {
                py.allow_threads(|| std::thread::sleep(Duration::from_millis(20)));
                if interrupt.is_none()
                    && let Err(e) = py.check_signals()
                {
                    STOP.store(true, Ordering::SeqCst);
                    interrupt = Some(e);
                }
            }
            let result = py.allow_threads(|| handle.join());
            STOP.store(false, Ordering::SeqCst);
            if let Some(e) = interrupt {
                return Err(e);
            }
            match result {
                Ok(r) => r.map_err(to_py),
                Err(_) => Err(DeviceError::new_err(
                    "the renderer panicked (a bug: please report it)",
                )),
            }
        })
    }

    /// Renders one image of `kind`: the scene at `time` or `frame` with
    /// `spp` samples, as the command line's `render` does.
    fn frame(
        &self,
        py: Python<'_>,
        scene: &Scene,
        size: (u32, u32),
        kind: OutputKind,
        spp: u32,
        at: (Option<f64>, Option<u64>),
    ) -> PyResult<blackhole::Frame> {
        let moment = when(at.0, at.1)?;
        let scene = scene.inner.clone();
        self.run(py, move |r| {
            let (w, h) = size;
            match moment {
                // A still is frame 0 (its samples over frame 0's shutter),
                // or with the shutter closed the scene as written, as
                // `render --out` draws it.
                When::Still if scene.animation.shutter <= 0.0 => {
                    r.render_samples(&scene, w, h, kind, spp)
                }
                When::Still => {
                    r.render_samples_with(&|s| scene.at_sample(0, s, spp), w, h, kind, spp)
                }
                When::Time(t) => r.render_samples(&scene.at_time(t), w, h, kind, spp),
                When::Frame(i) => {
                    r.render_samples_with(&|s| scene.at_sample(i, s, spp), w, h, kind, spp)
                }
            }
        })
    }
}

/// The frame's pixels as a C-contiguous (H, W, 4) array.
fn to_array<'py>(py: Python<'py>, frame: blackhole::Frame) -> PyResult<Bound<'py, PyAny>> {
    let shape = [frame.height as usize, frame.width as usize, 4];
    Ok(match frame.pixels {
        Pixels::Rgba8(v) => PyArray1::from_vec(py, v).reshape(shape)?.into_any(),
        Pixels::Rgba32F(v) => PyArray1::from_vec(py, v).reshape(shape)?.into_any(),
    })
}

#[pymethods]
impl Renderer {
    /// Opens the Vulkan device (validation as `BLACKHOLE_VALIDATION` says).
    #[new]
    fn new(py: Python<'_>) -> PyResult<Self> {
        let mut r = py
            .allow_threads(|| blackhole::Renderer::new(RendererOptions::default()))
            .map_err(to_py)?;
        r.stop_when(&STOP);
        let device = r.device_name().to_string();
        Ok(Renderer {
            inner: Mutex::new(Some(r)),
            device,
        })
    }

    /// The device's name.
    #[getter]
    fn device(&self) -> String {
        self.device.clone()
    }

    /// A still: uint8 (H, W, 4) sRGB, the pixels `render --out x.png`
    /// writes; with `hdr=True` float32 (H, W, 4) linear, what `--out x.exr`
    /// writes. `spp` samples a pixel; `time` (seconds into the animation)
    /// or `frame` (its index) as the command line's frames.
    #[pyo3(signature = (scene, width, height, *, hdr = false, spp = 1, time = None, frame = None))]
    #[allow(clippy::too_many_arguments)]
    fn render<'py>(
        &self,
        py: Python<'py>,
        scene: &Scene,
        width: i64,
        height: i64,
        hdr: bool,
        spp: i64,
        time: Option<f64>,
        frame: Option<i64>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let kind = if hdr {
            OutputKind::Hdr
        } else {
            OutputKind::Ldr
        };
        let size = (whole("width", width, 1)?, whole("height", height, 1)?);
        let spp = whole("spp", spp, 0)?;
        let f = self.frame(py, scene, size, kind, spp, (time, frame_index(frame)?))?;
        to_array(py, f)
    }

    /// An AOV, float32 (H, W, 4): `"geodesic"` (where each pixel's light
    /// path went: docs/physics.md; channel 3 the outcome code,
    /// `blackhole.OUTCOMES`) or `"stokes"` (I, Q, U, V of the disk: a thin
    /// disk's hit, or the volumetric gas summed along the ray).
    #[pyo3(signature = (scene, kind, width, height, *, time = None, frame = None))]
    #[allow(clippy::too_many_arguments)]
    fn aov<'py>(
        &self,
        py: Python<'py>,
        scene: &Scene,
        kind: &str,
        width: i64,
        height: i64,
        time: Option<f64>,
        frame: Option<i64>,
    ) -> PyResult<Bound<'py, PyAny>> {
        let kind = match kind {
            "geodesic" => OutputKind::Geodesic,
            "stokes" => OutputKind::Stokes,
            other => {
                return Err(PyValueError::new_err(format!(
                    "aov `{other}`: the AOVs are \"geodesic\" and \"stokes\""
                )));
            }
        };
        let size = (whole("width", width, 1)?, whole("height", height, 1)?);
        let f = self.frame(py, scene, size, kind, 1, (time, frame_index(frame)?))?;
        to_array(py, f)
    }

    /// GPU time per pass over `frames` frames after `warmup` (what
    /// `blackhole profile --json` writes), as a dict.
    #[pyo3(signature = (scene, width, height, *, frames = 10, warmup = 1))]
    fn profile<'py>(
        &self,
        py: Python<'py>,
        scene: &Scene,
        width: i64,
        height: i64,
        frames: i64,
        warmup: i64,
    ) -> PyResult<Bound<'py, PyAny>> {
        let (width, height) = (whole("width", width, 1)?, whole("height", height, 1)?);
        let (frames, warmup) = (whole("frames", frames, 1)?, whole("warmup", warmup, 0)?);
        let scene = scene.inner.clone();
        let json = self.run(py, move |r| {
            let (report, _) =
                blackhole::cli::profile::run_frames(r, &scene, width, height, warmup, frames)?;
            Ok(report.to_json())
        })?;
        py.import("json")?.call_method1("loads", (json,))
    }

    /// Validation messages so far (errors, warnings): both 0 in a correct
    /// program (validation on: `BLACKHOLE_VALIDATION=1`).
    fn validation_counts(&self, py: Python<'_>) -> PyResult<(u32, u32)> {
        self.run(py, |r| Ok(r.validation_counts()))
    }

    /// Closes the device now (a closed renderer raises DeviceError).
    fn close(&self, py: Python<'_>) -> PyResult<()> {
        let taken = self.inner.lock().ok().and_then(|mut g| g.take());
        match taken {
            Some(r) => py.allow_threads(|| r.shutdown()).map_err(to_py),
            None => Ok(()),
        }
    }

    fn __enter__(slf: Py<Self>) -> Py<Self> {
        slf
    }

    fn __exit__(
        &self,
        py: Python<'_>,
        _t: PyObject,
        _v: PyObject,
        _tb: PyObject,
    ) -> PyResult<bool> {
        self.close(py)?;
        Ok(false)
    }

    fn __repr__(&self) -> String {
        format!("Renderer(device={:?})", self.device)
    }
}
