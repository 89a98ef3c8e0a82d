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

/// `x` printed with four significant digits, or as many more as it takes
/// to tell it from `other`, the limit it is compared with (so 0.04999999 is
/// not shown as the 0.05000 it falls short of).
pub(super) fn apart(x: f64, other: f64) -> String {
    for digits in 4..=17 {
        let shown = significant(x, digits);
        if shown != significant(other, digits) {
            return shown;
        }
    }
    format!("{x}")
}

/// `x` to `digits` significant digits: fixed point from 1e-4 to 1e9,
/// scientific beyond.
pub(super) fn significant(x: f64, digits: usize) -> String {
    if x == 0.0 || !x.is_finite() {
        return format!("{x}");
    }
    let exponent = x.abs().log10().floor() as i32;
    if (-4..9).contains(&exponent) {
        let decimals = (digits as i32 - 1 - exponent).max(0) as usize;
        format!("{x:.decimals$}")
    } else {
        format!("{x:.prec$e}", prec = digits - 1)
    }
}

pub(super) fn vec3(v: &[f64; 3]) -> String {
    format!("[{}, {}, {}]", v[0], v[1], v[2])
}
