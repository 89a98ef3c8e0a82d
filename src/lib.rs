//! blackhole: a black-hole renderer on explicit Vulkan, for holes that spin
//! or do not, each pixel's light path in closed form.
//!
//! Layers, from the bottom: [`vk`] wraps Vulkan (one concept per file),
//! [`graph`] schedules passes and derives every barrier, [`passes`] adds
//! effects to a graph, [`render`] runs frames, [`output`] writes files.
//! [`scene`] is the TOML scene schema; [`spacetime`] is the one door to a
//! hole's physics, on the f64 reference of [`physics`]; [`camera`] turns
//! pixels into rays; [`features`] and [`deferred`] decide what runs on the
//! device; [`settings`] reads the environment. docs/architecture.md draws
//! the whole tree.

#![warn(
    clippy::all,
    rust_2018_idioms,
    unsafe_op_in_unsafe_fn,
    clippy::undocumented_unsafe_blocks
)]

pub mod app;
pub mod camera;
pub mod cli;
pub mod deferred;
pub mod digits;
pub mod error;
pub mod features;
pub mod frame;
pub mod graph;
pub mod input;
pub mod output;
pub mod passes;
pub mod physics;
pub mod polarimetry;
pub mod render;
pub mod scene;
pub mod settings;
pub mod shaders;
pub mod sky;
pub mod spacetime;
pub mod stars;
pub mod vk;

pub use error::{Error, Result};
pub use frame::{Frame, FrameTimings, OutputKind, PassTiming, Pixels};
pub use render::{Renderer, RendererOptions};
pub use scene::Scene;
