//! What a frame is once it leaves the GPU: its pixels and the GPU time of each
//! pass. Shared by the renderer (which produces frames) and the output writers
//! (which store them), so neither depends on the other.

/// What a render produces.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum OutputKind {
    /// Tone-mapped, sRGB-encoded 8-bit RGBA.
    Ldr,
    /// Linear HDR RGBA, before tone mapping.
    Hdr,
    /// The geodesic AOV (docs/physics.md, "The geodesic AOV"), RGBA32F.
    Geodesic,
    /// The Stokes AOV (I, Q, U, V of the polarized thin disk), RGBA32F.
    Stokes,
    /// Linear HDR after bloom and exposure, before the tone map (`--exr-post`).
    HdrPost,
}

impl OutputKind {
    /// Bytes per texel of the image read back for this kind.
    pub fn texel_bytes(self) -> u64 {
        match self {
            OutputKind::Ldr => 4,
            OutputKind::Hdr | OutputKind::HdrPost => 8,
            OutputKind::Geodesic | OutputKind::Stokes => 16,
        }
    }

    /// One ray per pixel centre, RGBA32F, no post-processing: the geodesic
    /// and Stokes AOVs.
    pub fn is_aov(self) -> bool {
        matches!(self, OutputKind::Geodesic | OutputKind::Stokes)
    }
}

/// Pixels read back from the GPU, row 0 at the top.
#[derive(Clone, Debug)]
pub enum Pixels {
    Rgba8(Vec<u8>),
    Rgba32F(Vec<f32>),
}

impl Pixels {
    /// Decodes a tightly packed readback of an image of `kind`: 8-bit RGBA
    /// as it is, RGBA16F widened to f32, RGBA32F as it is.
    pub fn decode(kind: OutputKind, bytes: &[u8]) -> Self {
        match kind {
            OutputKind::Ldr => Pixels::Rgba8(bytes.to_vec()),
            OutputKind::Hdr | OutputKind::HdrPost => Pixels::Rgba32F(
                bytes
                    .chunks_exact(2)
                    .map(|c| half::f16::from_le_bytes([c[0], c[1]]).to_f32())
                    .collect(),
            ),
            OutputKind::Geodesic | OutputKind::Stokes => Pixels::Rgba32F(
                bytes
                    .chunks_exact(4)
                    .map(|c| f32::from_le_bytes([c[0], c[1], c[2], c[3]]))
                    .collect(),
            ),
        }
    }
}

/// One rendered frame.
#[derive(Clone, Debug)]
pub struct Frame {
    pub width: u32,
    pub height: u32,
    pub pixels: Pixels,
    pub timings: FrameTimings,
}

/// GPU time of one pass.
#[derive(Clone, Debug, PartialEq)]
pub struct PassTiming {
    pub name: String,
    pub ms: f64,
    /// Start, from the frame's first timestamp.
    pub start_ms: f64,
}

/// CPU time of each phase of one frame, milliseconds: building the graph
/// (and writing the parameters), compiling it, recording the command buffer,
/// submitting, waiting for the fence, and decoding the readback.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct CpuPhases {
    pub build_ms: f64,
    pub compile_ms: f64,
    pub record_ms: f64,
    pub submit_ms: f64,
    pub wait_ms: f64,
    pub readback_ms: f64,
}

impl CpuPhases {
    /// (name, milliseconds) in the order they happen.
    pub fn named(&self) -> [(&'static str, f64); 6] {
        [
            ("build", self.build_ms),
            ("compile", self.compile_ms),
            ("record", self.record_ms),
            ("submit", self.submit_ms),
            ("wait", self.wait_ms),
            ("readback", self.readback_ms),
        ]
    }
}

/// GPU time per pass of one frame (empty when the device has no timestamps).
#[derive(Clone, Debug, Default, PartialEq)]
pub struct FrameTimings {
    pub passes: Vec<PassTiming>,
    /// From the first pass's start to the last pass's end.
    pub frame_ms: f64,
    /// CPU phases (offscreen frames; the window fills what it can).
    pub cpu: CpuPhases,
    /// Wall time from the end of the submit to the fence (the frame's GPU
    /// time as the CPU sees it: the fall-back without timestamps).
    pub wall_ms: f64,
}

impl FrameTimings {
    /// Adds `other`'s times to these (the samples of one `--spp` frame):
    /// passes matched by name, new ones appended; frame and wall times summed.
    pub fn add(&mut self, other: &FrameTimings) {
        for p in &other.passes {
            match self.passes.iter_mut().find(|q| q.name == p.name) {
                Some(q) => q.ms += p.ms,
                None => self.passes.push(p.clone()),
            }
        }
        self.frame_ms += other.frame_ms;
        self.wall_ms += other.wall_ms;
    }
}

impl std::fmt::Display for FrameTimings {
    fn fmt(&self, f: &mut std::fmt::Formatter<'_>) -> std::fmt::Result {
        let parts: Vec<String> = self
            .passes
            .iter()
            .map(|p| format!("{} {:.2} ms", p.name, p.ms))
            .collect();
        write!(f, "{} (frame {:.2} ms)", parts.join(", "), self.frame_ms)
    }
}
