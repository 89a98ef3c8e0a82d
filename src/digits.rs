//! Numbers as messages print them: enough significant digits to tell a
//! value from the limit it is refused against. A leaf, used by every layer
//! that words a refusal (scene/ and spacetime/).

/// `x` printed with four significant digits, or as many more as it takes
/// to tell it from `other`, the limit it is compared with (so 0.04999999 is
/// not shown as the 0.05000 it falls short of).
pub fn apart(x: f64, other: f64) -> String {
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
pub fn significant(x: f64, digits: usize) -> String {
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
