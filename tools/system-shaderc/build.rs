//! shaderc-sys (with `prefer-static-linking`) links a system's
//! `libshaderc_combined.a` where it finds one, in the first of these places:
//! `SHADERC_LIB_DIR`, `$VULKAN_SDK/lib`, pkg-config's `shaderc`, the
//! distribution's library folder; where it finds none it builds shaderc,
//! glslang and SPIRV-Tools from source (about six minutes on two cores).
//!
//! The Vulkan SDK's combined library holds glslang and SPIRV-Tools; Debian's
//! and Ubuntu's (libshaderc-dev) hold shaderc alone, and their glslang and
//! SPIRV-Tools are separate static libraries in the same folder (glslang-dev,
//! spirv-tools). This build script finds the folder the same way and, where
//! the combined library lacks glslang and the separate libraries are there,
//! links them after it. Anything else it leaves to shaderc-sys.
//!
//! (shaderc-sys's pkg-config probe also names the shared `libshaderc.so`,
//! which leaves glslang's symbols undefined; the linker drops it, as rustc
//! links with `--as-needed` and the static archives resolve everything, so
//! the build script carries one shaderc, all static: `ldd` on it names no
//! shaderc.)

use std::env;
use std::fs;
use std::path::{Path, PathBuf};

/// glslang's and SPIRV-Tools' static libraries, in link order (a library
/// before the ones it uses).
const LIBS: [&str; 10] = [
    "glslang",
    "MachineIndependent",
    "GenericCodeGen",
    "OSDependent",
    "OGLCompiler",
    "HLSL",
    "SPIRV",
    "glslang-default-resource-limits",
    "SPIRV-Tools-opt",
    "SPIRV-Tools",
];

/// The folder shaderc-sys searches first (its `get_search_dir`).
fn search_dir() -> Option<PathBuf> {
    if let Some(dir) = env::var_os("SHADERC_LIB_DIR") {
        return Some(PathBuf::from(dir));
    }
    if let Some(sdk) = env::var_os("VULKAN_SDK") {
        return Some(Path::new(&sdk).join("lib"));
    }
    let probed = pkg_config::Config::new()
        .cargo_metadata(false)
        .env_metadata(false)
        .probe("shaderc");
    if let Some(dir) = probed.ok().and_then(|lib| lib.link_paths.first().cloned()) {
        return Some(dir);
    }
    let arch = env::var("CARGO_CFG_TARGET_ARCH").ok()?;
    let arch = if arch == "x86" {
        "i386".to_string()
    } else {
        arch
    };
    let debian = PathBuf::from(format!("/usr/lib/{arch}-linux-gnu"));
    Some(if debian.is_dir() {
        debian
    } else {
        PathBuf::from("/usr/lib")
    })
}

/// Whether a static archive holds glslang's front end (its member
/// ShaderLang.cpp's object, named in the archive's tables).
fn holds_glslang(archive: &Path) -> bool {
    fs::read(archive).is_ok_and(|bytes| bytes.windows(10).any(|w| w == b"ShaderLang"))
}

fn main() {
    println!("cargo:rerun-if-env-changed=SHADERC_LIB_DIR");
    println!("cargo:rerun-if-env-changed=VULKAN_SDK");
    if env::var_os("CARGO_FEATURE_FROM_SOURCE").is_some()
        || env::var("CARGO_CFG_TARGET_OS").as_deref() != Ok("linux")
    {
        return;
    }
    let Some(dir) = search_dir() else { return };
    let combined = dir.join("libshaderc_combined.a");
    println!("cargo:rerun-if-changed={}", combined.display());
    if !combined.is_file() || holds_glslang(&combined) || !dir.join("libglslang.a").is_file() {
        return;
    }
    println!("cargo:rustc-link-search=native={}", dir.display());
    for lib in LIBS {
        if dir.join(format!("lib{lib}.a")).is_file() {
            println!("cargo:rustc-link-lib=static={lib}");
        }
    }
}
