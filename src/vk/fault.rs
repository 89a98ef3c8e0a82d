//! Fault injection for the tests: `BLACKHOLE_FAULT` makes the renderer meet
//! the failures a real GPU can produce but a CPU driver never does, so the
//! path that reports them is exercised end to end (`tests/render.rs`).
//!
//! - `device-lost`: the first frame's wait returns `ERROR_DEVICE_LOST` as soon
//!   as the frame is submitted, while the GPU is still working on it (as a
//!   driver does when a device is lost mid-frame);
//! - `out-of-device-memory`: the same with `ERROR_OUT_OF_DEVICE_MEMORY`;
//! - `alloc:<name>`: allocating memory for the first resource whose name
//!   contains `<name>` fails as gpu-allocator's out-of-memory does.
//!
//! Unset (the normal case) nothing changes. The caller parses the setting
//! ([`parse`]) and hands the fault to the device in its
//! [`super::GpuSettings`]; vk/ reads no environment itself.

use ash::vk;

/// One injected failure.
#[derive(Clone, Debug, PartialEq, Eq)]
pub enum Fault {
    /// A frame wait fails with this result while the frame still runs.
    Wait(vk::Result),
    /// Allocating memory for a resource whose name contains this fails.
    Alloc(String),
}

/// `device-lost`, `out-of-device-memory` or `alloc:<name>`; `None` otherwise.
pub fn parse(v: &str) -> Option<Fault> {
    match v {
        "device-lost" => Some(Fault::Wait(vk::Result::ERROR_DEVICE_LOST)),
        "out-of-device-memory" => Some(Fault::Wait(vk::Result::ERROR_OUT_OF_DEVICE_MEMORY)),
        _ => v
            .strip_prefix("alloc:")
            .filter(|n| !n.is_empty())
            .map(|n| Fault::Alloc(n.to_string())),
    }
}

/// The result a frame wait is to fail with, if `fault` asks for one.
pub fn wait_fault(fault: Option<&Fault>) -> Option<vk::Result> {
    match fault? {
        Fault::Wait(r) => Some(*r),
        Fault::Alloc(_) => None,
    }
}

/// Whether allocating memory for `name` is to fail (once) under `fault`.
pub fn alloc_fault(fault: Option<&Fault>, name: &str) -> bool {
    static FIRED: std::sync::atomic::AtomicBool = std::sync::atomic::AtomicBool::new(false);
    match fault {
        Some(Fault::Alloc(n)) if name.contains(n.as_str()) => {
            !FIRED.swap(true, std::sync::atomic::Ordering::Relaxed)
        }
        _ => false,
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn parses_the_documented_faults_and_nothing_else() {
        assert_eq!(
            parse("device-lost"),
            Some(Fault::Wait(vk::Result::ERROR_DEVICE_LOST))
        );
        assert_eq!(
            parse("out-of-device-memory"),
            Some(Fault::Wait(vk::Result::ERROR_OUT_OF_DEVICE_MEMORY))
        );
        assert_eq!(parse("alloc:bloom"), Some(Fault::Alloc("bloom".into())));
        assert_eq!(parse("alloc:"), None);
        assert_eq!(parse("lost"), None);
    }
}
