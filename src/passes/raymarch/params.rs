//! The ray march's parameter block: one struct of named groups (camera,
//! observer, metric, integrator, disk, volume, sky, plane), built in one
//! place, [`RaymarchParams::new`], from the scene and the frame
//! ([`FrameSpec`]: size, jitter, the image sky's width), and never patched
//! after. `shaders/include/params.glsl` mirrors it; every vec3 there is
//! followed by a float, so each group is a whole number of 16-byte rows and
//! std430 places each member where `#[repr(C)]` does (tests/layout.rs checks
//! every member against the SPIR-V).

use bytemuck::{Pod, Zeroable};
use glam::DVec3;

use super::glsl;
use crate::scene::{DiskKind, MAX_HOLES, Scene, SkyKind, VolumeColor};
use crate::spacetime::{GpuPath, Spacetime, radii};

/// `[camera]` as the shader takes it: the frame's basis and the image.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable)]
pub struct CameraParams {
    pub position: [f32; 3],
    /// tan(vfov / 2).
    pub tan_half_fov: f32,
    pub right: [f32; 3],
    /// Width / height.
    pub aspect: f32,
    pub up: [f32; 3],
    /// Sub-pixel jitter, pixels (0: the pixel's centre).
    pub jitter_x: f32,
    pub forward: [f32; 3],
    /// Sub-pixel jitter down, pixels.
    pub jitter_y: f32,
    /// Image width and height.
    pub size: [u32; 2],
    /// vfov / 2, radians (the fisheye's field from centre to circle). (The
    /// projection itself is a specialisation constant, `Variant`.)
    pub half_fov: f32,
    /// ODS: the eyes' distance (rs); 0 for one image.
    pub ipd: f32,
    /// `Stereo` as a number (`STEREO_*`).
    pub stereo: f32,
    pub _pad: [f32; 3],
    /// What `position`, `right`, `up` and `forward` leave of their f64
    /// values (xyz; w 0): the spinning hole's 64-bit build forms a far
    /// camera's place and pinhole rays from the sums.
    pub position_lo: [f32; 4],
    pub right_lo: [f32; 4],
    pub up_lo: [f32; 4],
    pub forward_lo: [f32; 4],
}

/// Who holds the camera (`physics::observer`).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable)]
pub struct ObserverParams {
    /// Velocity in the static frame, world axes.
    pub velocity: [f32; 3],
    /// `ObserverKind` as a number (`OBS_*`).
    pub kind: f32,
    /// The rain form (a falling camera of one hole): the unit direction
    /// from the hole to the camera, formed in f64 (world axes)...
    pub radial: [f32; 3],
    /// ...and the fall speed sqrt(rs / r) there (above 1 inside the
    /// horizon), so that the cancellation in E = 1 + v d_r starts from
    /// one rounding of each (0 for every other camera).
    pub fall_speed: f32,
    /// A falling camera between a spinning hole's horizons: its
    /// Boyer-Lindquist r (M) as two f32 halves (hi + lo is the f64 value;
    /// 0 for every other camera). Near r- the world's azimuth (Boyer-
    /// Lindquist phi) turns as ln(r - r-): an f32 position's rounding there
    /// would turn the whole sky by 3e-5 rad at 1.002 r-.
    pub bl_r_hi: f32,
    pub bl_r_lo: f32,
    pub _pad: [f32; 2],
}

/// The holes.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable)]
pub struct MetricParams {
    /// xyz: position, w: rs.
    pub holes: [[f32; 4]; MAX_HOLES],
    pub hole_count: u32,
    /// 1 on, 0 off (straight rays).
    pub gravity: f32,
    /// The spin a* of a spinning hole as two f32 halves (hi + lo is the
    /// f64 value: the spinning hole's per-ray constants run in f64).
    pub spin_hi: f32,
    pub spin_lo: f32,
}

/// `[quality]`: the general integrator (several holes with gravity).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable)]
pub struct IntegratorParams {
    pub tolerance: f32,
    pub escape_radius: f32,
    /// Step budget per ray.
    pub steps: u32,
    pub _pad: f32,
}

/// `[disk]`, the parts every disk takes, and the physics switches of its light.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable)]
pub struct DiskParams {
    pub normal: [f32; 3],
    /// `DISK_*`.
    pub kind: f32,
    /// In-plane basis vector (azimuth 0).
    pub e1: [f32; 3],
    /// `speed` x time: how far the gas has turned (thin and volumetric).
    pub rotation_time: f32,
    /// e1 x normal (azimuth 90 degrees).
    pub e2: [f32; 3],
    /// Thin disk: contrast of filaments and clumps.
    pub structure: f32,
    pub inner: f32,
    pub outer: f32,
    pub brightness: f32,
    /// Doppler beaming on (1/0).
    pub beaming: f32,
    /// Kelvin.
    pub peak_temperature: f32,
    /// The Novikov-Thorne profile at its peak (the shader's normaliser).
    pub nt_peak: f32,
    /// Doppler colour shift on (1/0).
    pub doppler: f32,
    /// Gravitational redshift on (1/0).
    pub redshift: f32,
    /// Thin disk: opacity at average density.
    pub opacity: f32,
    /// x Keplerian.
    pub speed: f32,
    /// 0: Newtonian profile; 1: Page-Thorne with the constants below.
    pub profile: f32,
    /// (The spin travels once, in [`MetricParams`].)
    pub _pad: f32,
    /// Page-Thorne: sqrt(ISCO / M) and the roots of x^3 - 3x + 2a.
    pub pt_roots: [f32; 4],
    /// Page-Thorne: each root's log coefficient, then 1.5 a.
    pub pt_coef: [f32; 4],
}

/// The volumetric disk's gas.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable)]
pub struct VolumeParams {
    pub half_height: f32,
    /// Fall of density with height (exponent).
    pub falloff_v: f32,
    /// Fall of density with radius (exponent).
    pub falloff_h: f32,
    pub noise_scale: f32,
    pub octaves: f32,
    /// Emission scale.
    pub lit: f32,
    /// 1 blackbody, 0 colour map.
    pub blackbody: f32,
    pub _pad: f32,
}

/// `[sky]`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable)]
pub struct SkyParams {
    /// `SKY_*`.
    pub kind: f32,
    /// Checker squares, star density, the catalogue's grid size or an image
    /// sky's width (its mip level).
    pub scale: f32,
    pub brightness: f32,
    /// The galaxy band.
    pub galaxy: f32,
    /// Rows of the world-to-galactic matrix.
    pub row0: [f32; 3],
    /// Flux of a magnitude-0 star.
    pub star_flux: f32,
    pub row1: [f32; 3],
    /// 1: the sky's light shifted by the camera's g (`[physics] sky_shift`).
    pub shift: f32,
    pub row2: [f32; 3],
    /// 1: the other universe's light shows a copy of the sky
    /// (`[sky] other_universe = "mirror"`).
    pub other: f32,
}

/// `[grid_plane]`.
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable)]
pub struct PlaneParams {
    pub position: [f32; 3],
    /// 1 on, 0 off.
    pub enabled: f32,
    /// Unit normal facing the camera.
    pub normal: [f32; 3],
    pub spacing: f32,
    /// An in-plane axis.
    pub axis: [f32; 3],
    pub half_size: f32,
}

/// `[polarization]`: the emitter's model (shaders/include/polarization.glsl).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable)]
pub struct PolarizationParams {
    /// The field on the gas's frame (e_(r), e_(phi), e_(z)), unit.
    pub field: [f32; 3],
    pub fraction: f32,
    pub spectral_index: f32,
    pub emissivity_index: f32,
    /// Field models side by side (1: one picture).
    pub tiles: u32,
    pub _pad: f32,
    /// Each one's field, unit (xyz): `fields`, or `field` alone.
    pub fields: [[f32; 4]; 4],
}

/// The whole block (a read-only storage buffer, written by the host).
#[repr(C)]
#[derive(Clone, Copy, Debug, Default, Pod, Zeroable)]
pub struct RaymarchParams {
    pub camera: CameraParams,
    pub observer: ObserverParams,
    pub metric: MetricParams,
    pub integrator: IntegratorParams,
    pub disk: DiskParams,
    pub volume: VolumeParams,
    pub sky: SkyParams,
    pub plane: PlaneParams,
    pub polarization: PolarizationParams,
}

/// What one frame adds to the scene.
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct FrameSpec {
    pub width: u32,
    pub height: u32,
    /// Sub-pixel offset of every ray, pixels (0, 0: the pixels' centres).
    pub jitter: (f32, f32),
    /// The width of the loaded image sky, if the scene has one.
    pub image_sky_width: Option<u32>,
}

impl FrameSpec {
    /// A `width` x `height` frame through the pixels' centres.
    pub fn new(width: u32, height: u32) -> Self {
        FrameSpec {
            width,
            height,
            ..FrameSpec::default()
        }
    }
}

pub(super) fn disk_kind(scene: &Scene) -> u32 {
    match scene.disk.kind {
        DiskKind::None => glsl::DISK_NONE,
        DiskKind::Thin => glsl::DISK_THIN,
        DiskKind::Volumetric => glsl::DISK_VOLUME,
    }
}

pub(super) fn sky_kind(scene: &Scene) -> u32 {
    match scene.sky.kind {
        SkyKind::Black => glsl::SKY_BLACK,
        SkyKind::Checker => glsl::SKY_CHECKER,
        SkyKind::Stars => glsl::SKY_STARS,
        SkyKind::Image | SkyKind::Cubemap => glsl::SKY_IMAGE,
        SkyKind::Catalogue => glsl::SKY_CATALOGUE,
    }
}

fn v3(v: DVec3) -> [f32; 3] {
    [v.x as f32, v.y as f32, v.z as f32]
}

fn flag(on: bool) -> f32 {
    f32::from(u8::from(on))
}

/// The Page-Thorne part of the disk's block for the spacetime's spin `a`
/// (Newtonian: zeros); its peak, the normaliser, is set with the rest in
/// `disk`.
fn page_thorne(scene: &Scene, a: f64) -> DiskParams {
    use crate::scene::TemperatureProfile;
    if scene.disk.temperature_profile != TemperatureProfile::PageThorne {
        return DiskParams::default();
    }
    let pt = radii::page_thorne(a);
    DiskParams {
        profile: 1.0,
        pt_roots: [pt.x0, pt.roots[0], pt.roots[1], pt.roots[2]].map(|x| x as f32),
        pt_coef: [pt.coef[0], pt.coef[1], pt.coef[2], 1.5 * a].map(|x| x as f32),
        ..DiskParams::default()
    }
}

/// r⁻³ (1 - sqrt(r_in / r)) at the Novikov-Thorne peak, the shader's normaliser.
fn nt_profile_at_peak(r_in: f64) -> f64 {
    let r = crate::physics::disk::peak_radius(r_in.max(1e-6));
    r.powi(-3) * (1.0 - (r_in / r).sqrt())
}

impl RaymarchParams {
    /// The block for `scene` (at its `time`), whose spacetime is
    /// `spacetime`, and one frame.
    pub fn new(scene: &Scene, spacetime: &Spacetime, frame: &FrameSpec) -> Self {
        // The spin a*, asked once: the metric's part carries it, the disk's
        // Page-Thorne constants are its.
        let spin = spacetime.spin();
        RaymarchParams {
            camera: camera(scene, frame),
            observer: observer(scene, spacetime),
            metric: metric(spacetime, spin),
            integrator: IntegratorParams {
                tolerance: scene.quality.tolerance as f32,
                escape_radius: scene.escape_radius() as f32,
                steps: scene.quality.steps,
                _pad: 0.0,
            },
            disk: disk(scene, spin),
            volume: volume(scene),
            sky: sky(scene, frame),
            plane: plane(scene),
            polarization: polarization(scene),
        }
    }
}

fn polarization(scene: &Scene) -> PolarizationParams {
    let e = scene.emission();
    let models = scene.polarization.models();
    let mut fields = [[0.0; 4]; 4];
    for (slot, f) in fields.iter_mut().zip(&models) {
        let [x, y, z] = v3(glam::DVec3::from(*f).normalize());
        *slot = [x, y, z, 0.0];
    }
    PolarizationParams {
        field: v3(e.field),
        fraction: e.fraction as f32,
        spectral_index: e.spectral_index as f32,
        emissivity_index: e.emissivity_index as f32,
        tiles: models.len() as u32,
        _pad: 0.0,
        fields,
    }
}

fn camera(scene: &Scene, frame: &FrameSpec) -> CameraParams {
    let f = scene.camera.frame();
    CameraParams {
        position: v3(f.position),
        tan_half_fov: f.tan_half_fov as f32,
        right: v3(f.right),
        aspect: (f64::from(frame.width) / f64::from(frame.height)) as f32,
        up: v3(f.up),
        jitter_x: frame.jitter.0,
        forward: v3(f.forward),
        jitter_y: frame.jitter.1,
        size: [frame.width, frame.height],
        half_fov: f.half_fov as f32,
        ipd: f.ipd as f32,
        stereo: f.stereo.gpu_id() as f32,
        _pad: [0.0; 3],
        position_lo: lo(f.position),
        right_lo: lo(f.right),
        up_lo: lo(f.up),
        forward_lo: lo(f.forward),
    }
}

/// What `v3(v)` leaves of v: v - f64(f32(v)) (w 0).
fn lo(v: DVec3) -> [f32; 4] {
    let r = v - v.as_vec3().as_dvec3();
    [r.x as f32, r.y as f32, r.z as f32, 0.0]
}

fn observer(scene: &Scene, spacetime: &Spacetime) -> ObserverParams {
    let viewer = scene.camera.viewer();
    let obs = spacetime.camera_observer(&viewer);
    let bl_r = spacetime.camera_inside_radius(&viewer).unwrap_or(0.0);
    ObserverParams {
        velocity: v3(obs.beta),
        kind: obs.kind as u32 as f32,
        radial: v3(obs.rhat),
        fall_speed: obs.rain.unwrap_or(0.0) as f32,
        bl_r_hi: bl_r as f32,
        bl_r_lo: (bl_r - f64::from(bl_r as f32)) as f32,
        _pad: [0.0; 2],
    }
}

/// The spacetime's part of the block: its holes, whether rays bend, and
/// the spin as two f32 halves.
fn metric(spacetime: &Spacetime, spin: f64) -> MetricParams {
    let spin_hi = spin as f32;
    let mut holes = [[0.0f32; 4]; MAX_HOLES];
    for (slot, h) in holes.iter_mut().zip(spacetime.holes()) {
        let p = v3(h.position);
        *slot = [p[0], p[1], p[2], h.rs as f32];
    }
    MetricParams {
        holes,
        hole_count: spacetime.holes().len().min(MAX_HOLES) as u32,
        gravity: flag(spacetime.gpu_path() != GpuPath::Straight),
        spin_hi,
        spin_lo: (spin - f64::from(spin_hi)) as f32,
    }
}

fn disk(scene: &Scene, spin: f64) -> DiskParams {
    let d = &scene.disk;
    let normal = DVec3::from(d.normal);
    let (e1, e2) = crate::physics::geodesic::disk_basis(normal);
    DiskParams {
        normal: v3(normal.normalize()),
        kind: disk_kind(scene) as f32,
        e1: v3(e1),
        rotation_time: (d.speed * scene.time) as f32,
        e2: v3(e2),
        structure: d.structure as f32,
        inner: d.inner_radius as f32,
        outer: d.outer_radius as f32,
        brightness: d.brightness as f32,
        beaming: flag(scene.physics.beaming),
        peak_temperature: d.temperature_k as f32,
        // The profile's own peak: T / T_peak is 1 at the hottest ring.
        nt_peak: if d.temperature_profile == crate::scene::TemperatureProfile::PageThorne {
            radii::page_thorne_peak(spin) as f32
        } else {
            nt_profile_at_peak(d.inner_radius) as f32
        },
        doppler: flag(scene.physics.doppler),
        redshift: flag(scene.physics.gravitational_redshift),
        opacity: d.opacity as f32,
        speed: d.speed as f32,
        ..page_thorne(scene, spin)
    }
}

fn volume(scene: &Scene) -> VolumeParams {
    let d = &scene.disk;
    VolumeParams {
        half_height: d.height as f32,
        falloff_v: d.density_v as f32,
        falloff_h: d.density_h as f32,
        noise_scale: d.noise_scale as f32,
        octaves: d.noise_octaves as f32,
        lit: d.lit as f32,
        blackbody: flag(d.color == VolumeColor::Blackbody),
        _pad: 0.0,
    }
}

fn sky(scene: &Scene, frame: &FrameSpec) -> SkyParams {
    let s = &scene.sky;
    let m = crate::stars::world_to_galactic(s.frame, s.rotation_deg, s.tilt_deg);
    let scale = match s.kind {
        SkyKind::Black => 0.0,
        SkyKind::Checker => f64::from(s.squares),
        SkyKind::Stars => s.star_density,
        SkyKind::Catalogue => f64::from(crate::stars::GRID),
        SkyKind::Image | SkyKind::Cubemap => f64::from(frame.image_sky_width.unwrap_or(0)),
    };
    SkyParams {
        kind: sky_kind(scene) as f32,
        scale: scale as f32,
        brightness: s.brightness as f32,
        galaxy: s.galaxy as f32,
        row0: v3(m.row(0)),
        star_flux: crate::stars::FLUX_MAG0 as f32,
        row1: v3(m.row(1)),
        shift: flag(scene.physics.sky_shift),
        row2: v3(m.row(2)),
        other: flag(s.other_universe == crate::scene::OtherUniverse::Mirror),
    }
}

fn plane(scene: &Scene) -> PlaneParams {
    let gp = &scene.plane;
    let normal = DVec3::from(gp.normal).normalize();
    // An in-plane axis: world x projected, or z if the normal is along x.
    let mut axis = DVec3::X - normal * normal.x;
    if axis.length() < 1e-6 {
        axis = DVec3::Z - normal * normal.z;
    }
    PlaneParams {
        position: v3(DVec3::from(gp.position)),
        enabled: flag(gp.enabled),
        normal: v3(normal),
        spacing: gp.spacing as f32,
        axis: v3(axis.normalize()),
        half_size: gp.size as f32,
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::scene::TemperatureProfile;

    /// The shader's T^4 (disk.glsl: Page-Thorne f / r in M, Newtonian
    /// r^-3 (1 - sqrt(r_in / r)) in rs) over the block's normaliser peaks at
    /// exactly 1 for either profile: the hottest ring has temperature_k.
    #[test]
    fn the_hottest_ring_of_either_profile_has_the_peak_temperature() {
        for (profile, spin) in [
            (TemperatureProfile::PageThorne, 0.0),
            (TemperatureProfile::PageThorne, 0.9),
            (TemperatureProfile::PageThorne, -0.5),
            (TemperatureProfile::Newtonian, 0.0),
        ] {
            let toml = format!("[[black_hole]]\nspin = {spin:?}\n");
            let mut scene = Scene::from_toml(&toml, "t.toml").expect("scene");
            scene.disk.temperature_profile = profile;
            let peak = f64::from(
                RaymarchParams::new(&scene, &scene.spacetime(), &FrameSpec::new(8, 8))
                    .disk
                    .nt_peak,
            );
            let r_in = scene.disk.inner_radius;
            let t4 = |r_rs: f64| match profile {
                TemperatureProfile::PageThorne => {
                    let r = 2.0 * r_rs;
                    radii::page_thorne_flux(r, spin) / r
                }
                TemperatureProfile::Newtonian => r_rs.powi(-3) * (1.0 - (r_in / r_rs).sqrt()),
            };
            let best = (1..20_000)
                .map(|i| t4(0.5 + 0.001 * f64::from(i)) / peak)
                .fold(0.0, f64::max);
            assert!(
                (best - 1.0).abs() < 1e-4,
                "{profile:?} spin {spin}: peak T^4 ratio {best}"
            );
        }
    }
}
