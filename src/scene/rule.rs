//! A rejected value and the helpers every rule of validation builds it
//! with: the key path, the value as written (its numbers compacted) and why.

use super::locate::Seg;

/// A rejected value: its key path, the value as written, and the reason.
pub type Invalid = (Vec<Seg>, String, String);
pub(super) type Check = std::result::Result<(), Invalid>;

pub(super) fn fail(path: &[Seg], value: impl std::fmt::Display, why: impl Into<String>) -> Check {
    Err((
        path.to_vec(),
        super::locate::compact_numbers(&value.to_string()),
        why.into(),
    ))
}

pub(super) fn vec3(v: &[f64; 3]) -> String {
    format!("[{}, {}, {}]", v[0], v[1], v[2])
}
