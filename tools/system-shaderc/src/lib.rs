//! Nothing to call: this crate's build script adds the link lines that make
//! a distribution's static shaderc whole (see build.rs).
