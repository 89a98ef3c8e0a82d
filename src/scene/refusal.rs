//! The words of a camera's placement refusals
//! ([`crate::spacetime::Spacetime::placement`]) and of a fall's end
//! ([`crate::spacetime::Fall::check_end`]): each names the key, the value
//! and what the user can do instead.

use super::Camera;
use super::locate::Seg::{self, Key};
use super::rule::{Check, fail, vec3};
use crate::digits::apart;
use crate::spacetime::{EndRefusal, FALLING_MIN_R, Refusal};

/// Why the camera's observer cannot stand where it is
/// ([`Spacetime::placement`]), worded for the scene's keys.
pub(super) fn refuse(c: &Camera, at: &[Seg], refusal: Refusal) -> Check {
    let key = |k: &'static str| [at, &[Key(k)]].concat();
    let position = || vec3(&c.position);
    let name = format!("\"{}\"", c.observer.name());
    match refusal {
        Refusal::InsideHorizon { hole, r, horizon } => fail(
            &key("position"),
            position(),
            format!(
                "is inside the horizon of black_hole[{hole}] (r = {} rs <= r+ = {} rs), where only a \
                 \"falling\" observer can be (nothing else stands still or orbits there): set \
                 observer = \"falling\"",
                apart(r, horizon),
                apart(horizon, r)
            ),
        ),
        Refusal::InsideAbsorber { hole, several } => fail(
            &key("position"),
            position(),
            if several {
                format!(
                    "is inside the horizon of black_hole[{hole}]; with several holes the light \
                     paths are their pulls summed, an approximation that says nothing about an \
                     interior: only one non-rotating hole's \"falling\" camera may go inside"
                )
            } else {
                format!(
                    "is inside black_hole[{hole}] with gravity off, where a hole is an absorbing \
                     sphere: turn gravity on to fall in with observer = \"falling\""
                )
            },
        ),
        Refusal::InsidePhotonSphere { r, photon } => fail(
            &key("position"),
            position(),
            format!(
                "is inside the photon sphere (r = {} <= 1.5 rs = {}), where no \
                 \"orbiting\" observer can be",
                apart(r, photon),
                apart(photon, r)
            ),
        ),
        Refusal::OnDiskAxis => fail(
            &key("position"),
            position(),
            "is on the disk's axis, where an \"orbiting\" observer's orbit has no direction",
        ),
        Refusal::FallingTooClose { r, rs } => fail(
            &key("position"),
            position(),
            format!(
                "is {} rs from the singularity; a \"falling\" observer must stay at r >= \
                 {FALLING_MIN_R} rs (closer, the light paths lose the accuracy the renderer \
                 promises: docs/inside-the-horizon.md)",
                apart(r / rs, FALLING_MIN_R)
            ),
        ),
        Refusal::FlatAroundSpin => fail(
            &key("observer"),
            name,
            "needs spin = 0: \"flat\" is the Schwarzschild comparison mapping",
        ),
        Refusal::FallingTooDeep { r, floor, inner } => fail(
            &key("position"),
            position(),
            format!(
                "is at Boyer-Lindquist r = {} rs; a \"falling\" camera of a spinning hole must \
                 stay above r = {} rs, (1 + 1e-3) times the inner horizon r- = {inner:.6} \
                 rs (beyond r- the paths are not drawn) and at least {FALLING_MIN_R} rs from the \
                 centre (docs/inside-the-horizon.md)",
                apart(r, floor),
                apart(floor, r)
            ),
        ),
        Refusal::StaticInErgoregion { r, r_ergo } => fail(
            &key("observer"),
            name,
            format!(
                "cannot stand inside the ergoregion (r = {} rs < r_ergo = {} rs): use \"zamo\" or \"falling\"",
                apart(r, r_ergo),
                apart(r_ergo, r)
            ),
        ),
        Refusal::OrbitTooFast { v, r } => fail(
            &key("observer"),
            name,
            format!(
                "would orbit faster than light there (v = {} c at r = {r:.4} rs)",
                apart(v, 1.0)
            ),
        ),
    }
}

/// Why a fall cannot end at `end` (`[animation] fall_end_radius`, rs).
pub(super) fn refuse_fall_end(end: f64, refusal: EndRefusal) -> Check {
    let key = [Key("animation"), Key("fall_end_radius")];
    match refusal {
        EndRefusal::Inside { horizon } => fail(
            &key,
            end,
            format!(
                "is inside the spinning hole's horizon (r+ = {horizon:.4} rs): only a \
                 \"falling\" camera (one hole, gravity on) falls through it"
            ),
        ),
        EndRefusal::TooDeep { r, floor, inner } => fail(
            &key,
            end,
            format!(
                "puts the camera at Boyer-Lindquist r = {} rs on the line of its fall; a \
                 falling camera of a spinning hole must stay above r = {} rs, just \
                 outside the inner horizon r- = {inner:.6} rs (docs/inside-the-horizon.md)",
                apart(r, floor),
                apart(floor, r)
            ),
        ),
        EndRefusal::NotInward { start } => fail(
            &key,
            end,
            format!(
                "must be below the fall's start: the camera (camera.position) starts {} rs \
                 from the hole's centre and a fall only goes inward",
                apart(start, end)
            ),
        ),
        EndRefusal::TooClose => fail(
            &key,
            end,
            format!(
                "must be at least {FALLING_MIN_R} rs: closer to the singularity the light \
                 paths lose the accuracy the renderer promises (docs/inside-the-horizon.md)"
            ),
        ),
    }
}
