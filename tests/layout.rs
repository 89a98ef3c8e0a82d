//! Structs and constants shared with GLSL: the Rust side's field offsets must
//! equal the offsets the shader compiler assigned, read from the SPIR-V
//! itself, and the constants mirrored in Rust must equal the GLSL source's.

use std::mem::{offset_of, size_of};

#[path = "common/spirv.rs"]
mod spirv;

use spirv::{member_offsets, spirv_constants};

/// Every build of the ray march: each metric's builds, the split for both
/// closed forms, and the spinning hole's build with 32-bit roots.
fn raymarch_modules() -> Vec<&'static [u8]> {
    use blackhole::shaders::{RaymarchBuild, raymarch};
    use blackhole::spacetime::GpuPath;
    let builds = [
        RaymarchBuild::Beauty,
        RaymarchBuild::NoQuad,
        RaymarchBuild::Aov,
        RaymarchBuild::Split,
    ];
    let paths = [
        GpuPath::ClosedForm,
        GpuPath::Straight,
        GpuPath::Integrated,
        GpuPath::Kerr,
    ];
    let mut modules: Vec<&[u8]> = paths
        .iter()
        .flat_map(|&p| builds.iter().filter_map(move |&b| raymarch(p, b, true)))
        .collect();
    modules.extend(
        builds
            .iter()
            .filter_map(|&b| raymarch(GpuPath::Kerr, b, false)),
    );
    assert_eq!(
        modules.len(),
        18,
        "every metric's builds, the split for both closed forms"
    );
    modules
}

/// Offsets of the struct `name` in every ray-march build against `rust`.
fn raymarch_struct_matches(name: &str, rust: &[usize]) {
    let modules = raymarch_modules();
    for spirv in modules {
        let glsl = member_offsets(spirv, name);
        let rust: Vec<u32> = rust.iter().map(|&o| o as u32).collect();
        assert_eq!(glsl, rust, "{name}: member offsets, GLSL vs Rust");
    }
}

#[test]
fn raymarch_params_match_the_glsl_block() {
    use blackhole::passes::raymarch::params::*;
    raymarch_struct_matches(
        "RaymarchParams",
        &[
            offset_of!(RaymarchParams, camera),
            offset_of!(RaymarchParams, observer),
            offset_of!(RaymarchParams, metric),
            offset_of!(RaymarchParams, integrator),
            offset_of!(RaymarchParams, disk),
            offset_of!(RaymarchParams, volume),
            offset_of!(RaymarchParams, sky),
            offset_of!(RaymarchParams, plane),
            offset_of!(RaymarchParams, polarization),
        ],
    );
    raymarch_struct_matches(
        "CameraParams",
        &[
            offset_of!(CameraParams, position),
            offset_of!(CameraParams, tan_half_fov),
            offset_of!(CameraParams, right),
            offset_of!(CameraParams, aspect),
            offset_of!(CameraParams, up),
            offset_of!(CameraParams, jitter_x),
            offset_of!(CameraParams, forward),
            offset_of!(CameraParams, jitter_y),
            offset_of!(CameraParams, size),
            offset_of!(CameraParams, half_fov),
            offset_of!(CameraParams, ipd),
            offset_of!(CameraParams, stereo),
            offset_of!(CameraParams, _pad),
            offset_of!(CameraParams, position_lo),
            offset_of!(CameraParams, right_lo),
            offset_of!(CameraParams, up_lo),
            offset_of!(CameraParams, forward_lo),
        ],
    );
    raymarch_struct_matches(
        "ObserverParams",
        &[
            offset_of!(ObserverParams, velocity),
            offset_of!(ObserverParams, kind),
            offset_of!(ObserverParams, radial),
            offset_of!(ObserverParams, fall_speed),
            offset_of!(ObserverParams, bl_r_hi),
            offset_of!(ObserverParams, bl_r_lo),
            offset_of!(ObserverParams, _pad),
        ],
    );
    raymarch_struct_matches(
        "MetricParams",
        &[
            offset_of!(MetricParams, holes),
            offset_of!(MetricParams, hole_count),
            offset_of!(MetricParams, gravity),
            offset_of!(MetricParams, spin_hi),
            offset_of!(MetricParams, spin_lo),
        ],
    );
}

/// The same for the block's second half: the integrator, the disk, the
/// volume and the sky.
#[test]
fn raymarch_params_match_the_glsl_block_past_the_metric() {
    use blackhole::passes::raymarch::params::*;
    raymarch_struct_matches(
        "IntegratorParams",
        &[
            offset_of!(IntegratorParams, tolerance),
            offset_of!(IntegratorParams, escape_radius),
            offset_of!(IntegratorParams, steps),
            offset_of!(IntegratorParams, _pad),
        ],
    );
    raymarch_struct_matches(
        "DiskParams",
        &[
            offset_of!(DiskParams, normal),
            offset_of!(DiskParams, kind),
            offset_of!(DiskParams, e1),
            offset_of!(DiskParams, rotation_time),
            offset_of!(DiskParams, e2),
            offset_of!(DiskParams, structure),
            offset_of!(DiskParams, inner),
            offset_of!(DiskParams, outer),
            offset_of!(DiskParams, brightness),
            offset_of!(DiskParams, beaming),
            offset_of!(DiskParams, peak_temperature),
            offset_of!(DiskParams, nt_peak),
            offset_of!(DiskParams, doppler),
            offset_of!(DiskParams, redshift),
            offset_of!(DiskParams, opacity),
            offset_of!(DiskParams, speed),
            offset_of!(DiskParams, profile),
            offset_of!(DiskParams, _pad),
            offset_of!(DiskParams, pt_roots),
            offset_of!(DiskParams, pt_coef),
        ],
    );
    raymarch_struct_matches(
        "VolumeParams",
        &[
            offset_of!(VolumeParams, half_height),
            offset_of!(VolumeParams, falloff_v),
            offset_of!(VolumeParams, falloff_h),
            offset_of!(VolumeParams, noise_scale),
            offset_of!(VolumeParams, octaves),
            offset_of!(VolumeParams, lit),
            offset_of!(VolumeParams, blackbody),
            offset_of!(VolumeParams, _pad),
        ],
    );
    raymarch_struct_matches(
        "SkyParams",
        &[
            offset_of!(SkyParams, kind),
            offset_of!(SkyParams, scale),
            offset_of!(SkyParams, brightness),
            offset_of!(SkyParams, galaxy),
            offset_of!(SkyParams, row0),
            offset_of!(SkyParams, star_flux),
            offset_of!(SkyParams, row1),
            offset_of!(SkyParams, shift),
            offset_of!(SkyParams, row2),
            offset_of!(SkyParams, other),
        ],
    );
    raymarch_struct_matches(
        "PlaneParams",
        &[
            offset_of!(PlaneParams, position),
            offset_of!(PlaneParams, enabled),
            offset_of!(PlaneParams, normal),
            offset_of!(PlaneParams, spacing),
            offset_of!(PlaneParams, axis),
            offset_of!(PlaneParams, half_size),
        ],
    );
    raymarch_struct_matches(
        "PolarizationParams",
        &[
            offset_of!(PolarizationParams, field),
            offset_of!(PolarizationParams, fraction),
            offset_of!(PolarizationParams, spectral_index),
            offset_of!(PolarizationParams, emissivity_index),
            offset_of!(PolarizationParams, tiles),
            offset_of!(PolarizationParams, _pad),
            offset_of!(PolarizationParams, fields),
        ],
    );
    // The block ends with its last group (no trailing padding either side).
    assert_eq!(
        size_of::<RaymarchParams>(),
        offset_of!(RaymarchParams, polarization) + size_of::<PolarizationParams>()
    );
}

/// `#define NAME VALUE` lines of a GLSL source, as (name, value) text.
fn defines(src: &str) -> Vec<(String, String)> {
    src.lines()
        .filter_map(|l| l.trim().strip_prefix("#define "))
        .filter_map(|rest| {
            let mut it = rest.split_whitespace();
            Some((it.next()?.to_string(), it.next()?.to_string()))
        })
        .collect()
}

fn define(src: &str, name: &str) -> f64 {
    let all = defines(src);
    let (_, v) = all
        .iter()
        .find(|(n, _)| n == name)
        .unwrap_or_else(|| panic!("#define {name} missing"));
    v.parse()
        .unwrap_or_else(|_| panic!("#define {name} {v} is not a number"))
}

#[test]
fn constants_mirrored_in_rust_match_the_glsl_source() {
    use blackhole::passes::composite::glsl as c;
    use blackhole::passes::raymarch::glsl as r;
    let params = include_str!("../shaders/include/params.glsl");
    let pairs = [
        ("MAX_HOLES", f64::from(r::MAX_HOLES)),
        ("DISK_NONE", f64::from(r::DISK_NONE)),
        ("DISK_THIN", f64::from(r::DISK_THIN)),
        ("DISK_VOLUME", f64::from(r::DISK_VOLUME)),
        ("SKY_BLACK", f64::from(r::SKY_BLACK)),
        ("SKY_CHECKER", f64::from(r::SKY_CHECKER)),
        ("SKY_STARS", f64::from(r::SKY_STARS)),
        ("SKY_IMAGE", f64::from(r::SKY_IMAGE)),
        ("SKY_CATALOGUE", f64::from(r::SKY_CATALOGUE)),
        ("LUT_MIN_K", r::LUT_MIN_K),
        ("LUT_MAX_K", r::LUT_MAX_K),
    ];
    for (name, rust) in pairs {
        assert_eq!(define(params, name), rust, "{name}");
    }
    let variant = include_str!("../shaders/include/variant.glsl");
    for (name, rust) in [
        ("PROJ_PINHOLE", r::PROJ_PINHOLE),
        ("PROJ_EQUIRECT", r::PROJ_EQUIRECT),
        ("PROJ_FISHEYE", r::PROJ_FISHEYE),
    ] {
        assert_eq!(define(variant, name), f64::from(rust), "{name}");
    }
    for (name, rust) in [
        ("STEREO_NONE", r::STEREO_NONE),
        ("STEREO_ODS", r::STEREO_ODS),
    ] {
        assert_eq!(define(params, name), f64::from(rust), "{name}");
    }
    assert_eq!(r::MAX_HOLES as usize, blackhole::scene::MAX_HOLES);
    let composite = include_str!("../shaders/composite.comp");
    for (name, rust) in [
        ("TONEMAP_ACES_HILL", c::TONEMAP_ACES_HILL),
        ("TONEMAP_ACES_NARKOWICZ", c::TONEMAP_ACES_NARKOWICZ),
        ("TONEMAP_LINEAR", c::TONEMAP_LINEAR),
        ("TONEMAP_HUE_PRESERVING", c::TONEMAP_HUE_PRESERVING),
    ] {
        assert_eq!(define(composite, name), f64::from(rust), "{name}");
    }
    // Where a path's roots take the far form (the f64 reference and the
    // shader must switch at the same lambda^2 + eta).
    let radial = include_str!("../shaders/include/kerr/radial.glsl");
    let far = radial
        .lines()
        .find_map(|l| l.trim().strip_prefix("const float KERR_FAR_ROOTS = "))
        .and_then(|v| v.trim_end_matches(';').parse::<f64>().ok())
        .expect("const float KERR_FAR_ROOTS in kerr/radial.glsl");
    assert_eq!(far, blackhole::physics::kerr::radial::FAR_ROOTS);
    // Observer kinds: the Rust enum's discriminants are what the host writes.
    use blackhole::physics::observer::ObserverKind;
    for (name, kind) in [
        ("OBS_STATIC", ObserverKind::Static),
        ("OBS_ORBITING", ObserverKind::Orbiting),
        ("OBS_FALLING", ObserverKind::Falling),
        ("OBS_FLAT", ObserverKind::Flat),
    ] {
        assert_eq!(define(params, name), f64::from(kind as u32), "{name}");
    }
    // The largest light a 16-bit float image holds: the sky is clamped to
    // it on load, every store of light in the shaders to the same.
    let color = include_str!("../shaders/include/color.glsl");
    assert_eq!(
        define(color, "HALF_MAX"),
        f64::from(blackhole::sky::MAX_SKY_VALUE)
    );
    assert_eq!(
        blackhole::sky::MAX_SKY_VALUE,
        half::f16::MAX.to_f32(),
        "the largest finite half float"
    );
    // Packed and tabulated data the host builds for the shaders.
    let sky = include_str!("../shaders/include/sky.glsl");
    assert_eq!(
        define(sky, "STAR_PLACE_STEPS"),
        blackhole::stars::PLACE_STEPS
    );
    let volume = include_str!("../shaders/include/volume.glsl");
    let period = blackhole::render::noise::VOLUME_NOISE_PERIOD;
    assert_eq!(define(volume, "VOLUME_NOISE_PERIOD_XZ"), period[0]);
    assert_eq!(define(volume, "VOLUME_NOISE_PERIOD_Y"), period[1]);
    assert_eq!(period[0], period[2], "the shader has one period across");
    // The AOV's outcome codes are binding (docs/physics.md, "The geodesic AOV").
    let hit = include_str!("../shaders/include/hit.glsl");
    for (name, code) in [
        ("OUT_ESCAPED", 0.0),
        ("OUT_CAPTURED", 1.0),
        ("OUT_DISK", 2.0),
        ("OUT_NO_STEPS", 3.0),
    ] {
        assert_eq!(define(hit, name), code, "{name}");
    }
    // The split ray march's stages (a specialisation constant's values) and
    // the rows of its indirect dispatch.
    let variant = include_str!("../shaders/include/variant.glsl");
    for (name, rust) in [
        ("STAGE_ALL", r::STAGE_ALL),
        ("STAGE_TRACE", r::STAGE_TRACE),
        ("STAGE_DEFERRED", r::STAGE_DEFERRED),
        ("POL_OFF", r::POL_OFF),
        ("POL_VIEW", r::POL_VIEW),
        ("POL_STOKES", r::POL_STOKES),
    ] {
        assert_eq!(define(variant, name), f64::from(rust), "{name}");
    }
    let raymarch = include_str!("../shaders/raymarch.comp");
    let row = defines(raymarch)
        .into_iter()
        .find(|(n, _)| n == "DEFERRED_ROW")
        .map(|(_, v)| v)
        .expect("#define DEFERRED_ROW missing");
    assert_eq!(row, format!("{}u", r::DEFERRED_ROW), "DEFERRED_ROW");
}

/// `layout(constant_id = N) const TYPE NAME` lines of a GLSL source, as
/// (N, NAME, TYPE).
fn specialization_constants(src: &str) -> Vec<(u32, String, String)> {
    src.lines()
        .filter_map(|l| l.trim().strip_prefix("layout(constant_id = "))
        .filter_map(|rest| {
            let (id, decl) = rest.split_once(')')?;
            let mut words = decl.split_whitespace().skip(1);
            let (kind, name) = (words.next()?, words.next()?);
            Some((id.trim().parse().ok()?, name.to_string(), kind.to_string()))
        })
        .collect()
}

/// The ray march's constants (the variant's from `Variant::named`, then
/// `BAKED` and the baked values from their table) and the composite's have
/// the ids the Rust side sets, their names and kinds as the GLSL declares
/// them (the baked values floats, `BAKED` a bool), in every SPIR-V module.
#[test]
fn specialization_constants_match_every_spirv_module() {
    use blackhole::passes::raymarch::{VARIANT_CONSTANTS, Variant, baked};
    let expected = |names: &[&str], src: &str| -> Vec<(u32, String, String)> {
        let glsl = specialization_constants(src);
        let rust: Vec<(u32, String)> = (0..).zip(names.iter().map(|n| n.to_string())).collect();
        let text: Vec<(u32, String)> = glsl.iter().map(|(i, n, _)| (*i, n.clone())).collect();
        assert_eq!(text, rust, "the GLSL's constant_id lines");
        glsl
    };
    let mut raymarch = expected(
        &Variant::constant_names(),
        include_str!("../shaders/include/variant.glsl"),
    );
    assert_eq!(baked::BAKED_FIRST_ID as usize, VARIANT_CONSTANTS);
    raymarch.push((baked::BAKED_FIRST_ID, "BAKED".into(), "bool".into()));
    for (id, name) in (baked::BAKED_FIRST_ID + 1..).zip(baked::BAKED_NAMES) {
        raymarch.push((id, name.into(), "float".into()));
    }
    let composite = expected(
        &blackhole::passes::composite::Variant::CONSTANT_NAMES,
        include_str!("../shaders/composite.comp"),
    );
    let sets = [
        (raymarch, raymarch_modules()),
        (
            composite,
            vec![
                blackhole::shaders::COMPOSITE,
                blackhole::shaders::COMPOSITE_HDR,
            ],
        ),
    ];
    for (want, modules) in sets {
        let mut seen = std::collections::HashSet::new();
        for module in modules {
            for (id, names, kind) in spirv_constants(module) {
                let known = names.iter().find(|n| want.iter().any(|w| &w.1 == *n));
                let c = (id, known.cloned().unwrap_or_default(), kind);
                assert!(
                    want.contains(&c),
                    "{c:?} ({names:?}) is not one of the Rust side's"
                );
                seen.insert(c.1);
            }
        }
        // Each constant is used by some build (none silently dropped).
        let missing: Vec<&String> = want
            .iter()
            .map(|w| &w.1)
            .filter(|n| !seen.contains(*n))
            .collect();
        assert!(missing.is_empty(), "in no module: {missing:?}");
    }
}

/// Descriptor bindings of a SPIR-V module's set 0: (binding, kind), the kind
/// read from the variable's type (a sampled image, a storage image, or a
/// block in storage-buffer memory).
fn spirv_bindings(spirv: &[u8]) -> Vec<(u32, blackhole::vk::BindingKind)> {
    use blackhole::vk::BindingKind;
    use std::collections::HashMap;
    let words: Vec<u32> = spirv
        .chunks_exact(4)
        .map(|c| u32::from_le_bytes([c[0], c[1], c[2], c[3]]))
        .collect();
    let mut binding = HashMap::new();
    let (mut pointers, mut images, mut sampled, mut structs) =
        (HashMap::new(), HashMap::new(), Vec::new(), Vec::new());
    let mut variables = Vec::new();
    let mut i = 5;
    while i < words.len() {
        let (count, opcode) = ((words[i] >> 16) as usize, words[i] & 0xffff);
        let ops = &words[i + 1..i + count];
        match opcode {
            // OpDecorate target Binding(33) n.
            71 if ops[1] == 33 => {
                binding.insert(ops[0], ops[2]);
            }
            // OpTypeImage: result, sampled type, dim, depth, arrayed, MS, sampled (2: storage).
            25 => {
                images.insert(ops[0], ops[6]);
            }
            27 => sampled.push(ops[0]),
            30 => structs.push(ops[0]),
            // OpTypePointer: result, storage class, pointee.
            32 => {
                pointers.insert(ops[0], ops[2]);
            }
            // OpVariable: result type, result, storage class.
            59 => variables.push((ops[1], ops[0])),
            _ => {}
        }
        i += count.max(1);
    }
    let mut out: Vec<(u32, BindingKind)> = variables
        .iter()
        .filter_map(|(var, ty)| {
            let n = *binding.get(var)?;
            let pointee = *pointers.get(ty)?;
            let kind = if sampled.contains(&pointee) {
                BindingKind::SampledImage
            } else if images.get(&pointee) == Some(&2) {
                BindingKind::StorageImage
            } else if structs.contains(&pointee) {
                BindingKind::StorageBuffer
            } else {
                panic!("binding {n}: a type this test does not know")
            };
            Some((n, kind))
        })
        .collect();
    out.sort_by_key(|b| b.0);
    out
}

/// The ray march's bindings are declared once in GLSL
/// (shaders/include/bindings.glsl) and once in Rust (`raymarch::BINDINGS`,
/// which the passes walk and the pipelines take their layout from): the
/// names and numbers agree, and every binding each SPIR-V module of the ray
/// march uses has the kind the table says.
#[test]
fn the_ray_march_bindings_agree_in_glsl_rust_and_spirv() {
    use blackhole::passes::raymarch::BINDINGS;
    let glsl = include_str!("../shaders/include/bindings.glsl");
    let numbered: Vec<(String, String)> = defines(glsl);
    assert_eq!(numbered.len(), BINDINGS.len(), "one #define per binding");
    for (i, b) in BINDINGS.iter().enumerate() {
        assert_eq!(define(glsl, b.name), i as f64, "{}", b.name);
    }
    for spirv in raymarch_modules() {
        let used = spirv_bindings(spirv);
        assert!(
            used.iter().any(|&(n, _)| n == 0),
            "the output image is bound"
        );
        for (n, kind) in used {
            let b = &BINDINGS[n as usize];
            assert_eq!(kind, b.kind, "binding {n} ({})", b.name);
        }
    }
}

/// Every other compute shader's binding table matches its SPIR-V exactly.
#[test]
fn the_post_passes_bindings_match_their_spirv() {
    use blackhole::passes::{accumulate, bloom, composite, exposure};
    use blackhole::shaders as s;
    let cases: [(&str, &[u8], &[blackhole::passes::compute::Binding]); 7] = [
        ("bloom prefilter", s::BLOOM_PREFILTER, &bloom::BINDINGS),
        ("bloom down", s::BLOOM_DOWN, &bloom::BINDINGS),
        ("bloom up", s::BLOOM_UP, &bloom::BINDINGS),
        ("exposure", s::EXPOSURE, &exposure::BINDINGS),
        ("accumulate", s::ACCUMULATE, &accumulate::BINDINGS),
        ("composite", s::COMPOSITE, &composite::BINDINGS),
        ("composite hdr", s::COMPOSITE_HDR, &composite::BINDINGS),
    ];
    for (name, spirv, table) in cases {
        let used = spirv_bindings(spirv);
        let want: Vec<_> = table
            .iter()
            .enumerate()
            .map(|(n, b)| (n as u32, b.kind))
            .collect();
        assert_eq!(used, want, "{name}");
    }
}
