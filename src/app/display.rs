//! What a window needs from the system before it opens: a display, said
//! plainly when there is none.

use crate::{Error, Result};

/// On Linux and the BSDs a window needs an X11 or Wayland display; say so
/// plainly before winit fails with a message about its own source.
pub fn check_display() -> Result<()> {
    if cfg!(all(
        unix,
        not(target_os = "macos"),
        not(target_os = "android")
    )) {
        let set = |v: &str| std::env::var_os(v).is_some_and(|s| !s.is_empty());
        if !set("DISPLAY") && !set("WAYLAND_DISPLAY") {
            return Err(Error::Usage(
                "no display: set DISPLAY (X11) or WAYLAND_DISPLAY, or run under Xvfb \
                 (`Xvfb :99 & DISPLAY=:99 blackhole window`)"
                    .into(),
            ));
        }
    }
    Ok(())
}

/// winit's "os error at /path/to/winit/src/file.rs:12: why" as "why".
pub fn without_source_location(msg: &str) -> &str {
    match msg.find("os error at ") {
        Some(at) => msg[at..].split_once(": ").map_or(msg, |(_, why)| why),
        None => msg,
    }
}
