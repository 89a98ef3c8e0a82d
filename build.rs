//! Compiles every `shaders/*.comp` to SPIR-V with shaderc, resolving `#include`
//! from `shaders/include/`. A GLSL error fails the build with the file and line.

use std::path::{Path, PathBuf};

// Linked for its build script's link lines only: the static glslang and
// SPIRV-Tools a distribution's shaderc leaves out (tools/system-shaderc).
use system_shaderc as _;

/// Extra builds of a shader with preprocessor macros: (source, output stem, defines).
const VARIANTS: &[(&str, &str, &[&str])] =
    &[("composite.comp", "composite_hdr.comp", &["HDR_OUTPUT"])];

/// The ray march is built once per metric (shaders/include/metric.glsl) and
/// kind: (metric define, stem part) x (kind defines, stem part), the split
/// stages for the closed forms (one hole, spinning or not) only. No plain build: raymarch.comp
/// needs a metric. src/shaders.rs names each module.
const METRICS: &[(&str, &str)] = &[
    ("METRIC_SCHWARZSCHILD", "schwarzschild"),
    ("METRIC_FLAT", "flat"),
    ("METRIC_SUMMED", "summed"),
    ("METRIC_KERR", "kerr"),
    ("METRIC_KERR KERR_F32_ROOTS", "kerr_f32"),
];
const RAYMARCH_KINDS: &[(&[&str], &str)] = &[
    (&[], ""),
    (&["GEODESIC_AOV"], "_aov"),
    (&["NO_QUAD"], "_no_quad"),
    (&["SPLIT_PASSES"], "_split"),
];

/// Every (output stem, defines) build of the source file `name`.
fn builds_of(name: &str) -> Vec<(String, Vec<&'static str>)> {
    if name == "raymarch.comp" {
        let mut builds = Vec::new();
        for (metric, m) in METRICS {
            for (defines, k) in RAYMARCH_KINDS {
                if *k == "_split"
                    && !metric.starts_with("METRIC_SCHWARZSCHILD")
                    && !metric.starts_with("METRIC_KERR")
                {
                    continue;
                }
                let mut d: Vec<&str> = metric.split(' ').collect();
                d.extend_from_slice(defines);
                builds.push((format!("raymarch_{m}{k}.comp"), d));
            }
        }
        return builds;
    }
    let mut builds = vec![(name.to_owned(), Vec::new())];
    for (source, stem, defines) in VARIANTS {
        if *source == name {
            builds.push((stem.to_string(), defines.to_vec()));
        }
    }
    builds
}

/// One build's SPIR-V (or its errors), by its index among the builds.
type Compiled = (usize, Result<Vec<u8>, String>);

fn main() {
    if let Err(e) = run() {
        // One line per error, as `file:line: message`, then fail the build.
        eprintln!("{e}");
        std::process::exit(1);
    }
}

fn run() -> Result<(), String> {
    let root = PathBuf::from(std::env::var("CARGO_MANIFEST_DIR").map_err(|e| e.to_string())?);
    let out = PathBuf::from(std::env::var("OUT_DIR").map_err(|e| e.to_string())?);
    let shader_dir = root.join("shaders");
    let include_dir = shader_dir.join("include");
    println!("cargo:rerun-if-changed={}", shader_dir.display());
    println!("cargo:rerun-if-changed={}", include_dir.display());
    println!("cargo:rerun-if-changed=src/passes/raymarch/baked_table.rs");

    let mut sources: Vec<PathBuf> = std::fs::read_dir(&shader_dir)
        .map_err(|e| format!("{}: {e}", shader_dir.display()))?
        .filter_map(|e| e.ok().map(|e| e.path()))
        .filter(|p| p.extension().is_some_and(|x| x == "comp"))
        .collect();
    sources.sort();
    for entry in
        std::fs::read_dir(&include_dir).map_err(|e| format!("{}: {e}", include_dir.display()))?
    {
        let p = entry.map_err(|e| e.to_string())?.path();
        println!("cargo:rerun-if-changed={}", p.display());
    }

    // Every build of every source, compiled on as many threads as there are
    // cores (each with its own compiler): the largest part of a first build
    // after the crates.
    let mut jobs = Vec::new();
    for src in &sources {
        println!("cargo:rerun-if-changed={}", src.display());
        let name = src
            .file_name()
            .map(|n| n.to_string_lossy().into_owned())
            .unwrap_or_default();
        for (stem, defines) in builds_of(&name) {
            jobs.push((src.as_path(), stem, defines));
        }
    }
    let threads = std::thread::available_parallelism().map_or(1, |n| n.get());
    let next = std::sync::atomic::AtomicUsize::new(0);
    let results: Vec<Vec<Compiled>> = std::thread::scope(|scope| {
        let workers: Vec<_> = (0..threads.min(jobs.len()))
            .map(|_| {
                scope.spawn(|| {
                    let mut done = Vec::new();
                    let compiler = shaderc::Compiler::new();
                    loop {
                        let i = next.fetch_add(1, std::sync::atomic::Ordering::Relaxed);
                        let Some((src, _, defines)) = jobs.get(i) else {
                            break;
                        };
                        let words = match &compiler {
                            Ok(c) => compile(c, src, &include_dir, defines),
                            Err(e) => Err(format!("starting shaderc: {e}")),
                        };
                        done.push((i, words));
                    }
                    done
                })
            })
            .collect();
        workers
            .into_iter()
            .map(|w| w.join().unwrap_or_default())
            .collect()
    });
    let mut results: Vec<_> = results.into_iter().flatten().collect();
    results.sort_by_key(|(i, _)| *i);
    if results.len() != jobs.len() {
        return Err("a shader compiler thread stopped early".to_string());
    }
    let mut errors = Vec::new();
    for (i, words) in results {
        let stem = &jobs[i].1;
        match words {
            Ok(words) => {
                let dst = out.join(format!("{stem}.spv"));
                std::fs::write(&dst, words).map_err(|e| format!("{}: {e}", dst.display()))?;
            }
            Err(e) => errors.push(format!("{stem}: {e}")),
        }
    }
    if errors.is_empty() {
        Ok(())
    } else {
        Err(errors.join("\n"))
    }
}

/// The baked values' table (src/passes/raymarch/baked_table.rs), read here
/// as (first id, [(GLSL name, the field of `P` it overwrites)]); the crate
/// reads the same rows with its own `baked_values!`.
macro_rules! baked_values {
    (first_id: $first:literal; $($name:ident, $glsl:literal, $rust:expr;)*) => {
        const BAKED_FIRST_ID: u32 = $first;
        const BAKED: &[(&str, &str)] = &[$((stringify!($name), $glsl)),*];
    };
}
include!("src/passes/raymarch/baked_table.rs");

/// The name under which shaders/include/baked.glsl includes the text
/// [`baked_values_glsl`] writes.
const BAKED_VALUES: &str = "baked_values.glsl";

/// The baked values as GLSL: the switch, one specialisation constant a
/// row, and `bake_params()`.
fn baked_values_glsl() -> String {
    let mut s = format!(
        "// Written by build.rs from src/passes/raymarch/baked_table.rs.\n\
         layout(constant_id = {BAKED_FIRST_ID}) const bool BAKED = false;\n"
    );
    for (i, (name, _)) in (1u32..).zip(BAKED) {
        let id = BAKED_FIRST_ID + i;
        s += &format!("layout(constant_id = {id}) const float {name} = 0.0;\n");
    }
    s += "\n// Overwrites the block's copy with the baked values (a no-op unless BAKED).\n";
    s += "void bake_params() {\n    if (!BAKED) return;\n";
    for (name, field) in BAKED {
        s += &format!("    P.{field} = {name};\n");
    }
    s + "}\n"
}

fn compile(
    compiler: &shaderc::Compiler,
    src: &Path,
    include_dir: &Path,
    defines: &[&str],
) -> Result<Vec<u8>, String> {
    let text = std::fs::read_to_string(src).map_err(|e| format!("{}: {e}", src.display()))?;
    let mut options =
        shaderc::CompileOptions::new().map_err(|e| format!("shaderc options: {e}"))?;
    options.set_target_env(
        shaderc::TargetEnv::Vulkan,
        shaderc::EnvVersion::Vulkan1_2 as u32,
    );
    options.set_optimization_level(shaderc::OptimizationLevel::Performance);
    options.set_generate_debug_info();
    for d in defines {
        options.add_macro_definition(d, None);
    }
    let inc = include_dir.to_owned();
    options.set_include_callback(move |name, _kind, from, _depth| {
        if name == BAKED_VALUES {
            return Ok(shaderc::ResolvedInclude {
                resolved_name: "src/passes/raymarch/baked_table.rs (baked_values.glsl)".into(),
                content: baked_values_glsl(),
            });
        }
        let path = inc.join(name);
        std::fs::read_to_string(&path)
            .map(|content| shaderc::ResolvedInclude {
                resolved_name: path.display().to_string(),
                content,
            })
            .map_err(|e| format!("{from}: cannot include `{name}` ({}): {e}", path.display()))
    });
    let name = src.display().to_string();
    let artifact = compiler
        .compile_into_spirv(
            &text,
            shaderc::ShaderKind::Compute,
            &name,
            "main",
            Some(&options),
        )
        .map_err(|e| format!("GLSL error: {e}"))?;
    if artifact.get_num_warnings() > 0 {
        println!(
            "cargo:warning={}",
            artifact.get_warning_messages().replace('\n', " | ")
        );
    }
    Ok(artifact.as_binary_u8().to_vec())
}
