//! The `BLACKHOLE_*` environment settings, parsed once, in one place.
//!
//! Every setting the program reads from the environment is parsed here, the
//! first time any of them is needed ([`get`]), and a value that does not
//! parse is an error naming the variable and the value ([`init`], which the
//! command line and [`crate::Renderer::new`] call first), never a silent
//! default. A `BLACKHOLE_` variable the program does not know draws one
//! warning (a typo would otherwise do nothing).

use std::sync::OnceLock;
use std::time::Duration;

use crate::vk::fault::{self, Fault};
use crate::vk::{GpuSettings, Validation};
use crate::{Error, Result};

/// What the environment asks for.
#[derive(Clone, Debug, PartialEq)]
pub struct Settings {
    /// `BLACKHOLE_DEVICE`: part of the name of the device to use.
    pub device: Option<String>,
    /// `BLACKHOLE_VALIDATION`: `Some(true)` requires the validation layer,
    /// `Some(false)` turns it off, `None` leaves the build's default.
    pub validation: Option<bool>,
    /// `BLACKHOLE_GPU_TIMEOUT_S`: the longest wait for one submission.
    pub gpu_timeout: Duration,
    /// `BLACKHOLE_NO_SPLIT`: keep the thin disk in the one ray-march dispatch.
    pub no_split: bool,
    /// `BLACKHOLE_NO_QUAD`: the ray march without quad subgroup operations.
    pub no_quad: bool,
    /// `BLACKHOLE_NO_F64`: a spinning hole's per-ray constants in 32-bit
    /// floats, as on a device without 64-bit floats in shaders.
    pub no_f64: bool,
    /// `BLACKHOLE_NO_BAKE`: offscreen ray marches read the scene's static
    /// parameters from the block, as the window does, instead of compiling
    /// them in.
    pub no_bake: bool,
    /// `BLACKHOLE_FAULT`: a failure injected for the tests.
    pub fault: Option<Fault>,
}

impl Default for Settings {
    /// Nothing asked: the device's own defaults ([`GpuSettings`]), the
    /// build's validation, every path on.
    fn default() -> Self {
        let GpuSettings {
            device,
            gpu_timeout,
            fault,
        } = GpuSettings::default();
        Settings {
            device,
            validation: None,
            gpu_timeout,
            no_split: false,
            no_quad: false,
            no_f64: false,
            no_bake: false,
            fault,
        }
    }
}

/// Every variable read, with what it takes (for messages and docs/environment.md).
pub const KNOWN: &[(&str, &str)] = &[
    ("BLACKHOLE_DEVICE", "part of a device's name"),
    (
        "BLACKHOLE_VALIDATION",
        "1 or 0 (also true/false, on/off, yes/no)",
    ),
    (
        "BLACKHOLE_GPU_TIMEOUT_S",
        "a number of seconds > 0, e.g. 600",
    ),
    ("BLACKHOLE_NO_SPLIT", "1 or 0"),
    ("BLACKHOLE_NO_QUAD", "1 or 0"),
    ("BLACKHOLE_NO_F64", "1 or 0"),
    ("BLACKHOLE_NO_BAKE", "1 or 0"),
    (
        "BLACKHOLE_FAULT",
        "device-lost, out-of-device-memory or alloc:<resource name>",
    ),
    // Read by the golden-image tests, not by the program.
    ("BLACKHOLE_BLESS", "1 (tests only)"),
];

fn bad(name: &str, value: &str) -> Error {
    let wants = KNOWN
        .iter()
        .find(|(n, _)| *n == name)
        .map_or("", |(_, w)| *w);
    let shown: String = value.chars().take(60).collect();
    Error::Usage(format!(
        "environment: {name}={shown:?} is not a valid value; it takes {wants}"
    ))
}

fn switch(name: &str, value: &str) -> Result<bool> {
    match value.trim().to_ascii_lowercase().as_str() {
        "1" | "true" | "on" | "yes" => Ok(true),
        "0" | "false" | "off" | "no" => Ok(false),
        _ => Err(bad(name, value)),
    }
}

impl Settings {
    /// Parses `BLACKHOLE_*` pairs (the environment, or a test's list). The
    /// second item holds the names of unknown variables, to warn about.
    pub fn parse<I, K, V>(vars: I) -> Result<(Self, Vec<String>)>
    where
        I: IntoIterator<Item = (K, V)>,
        K: AsRef<str>,
        V: AsRef<str>,
    {
        let mut s = Settings::default();
        let mut unknown = Vec::new();
        for (k, v) in vars {
            let (name, value) = (k.as_ref(), v.as_ref());
            // One rule for every variable: set means a value. An empty one
            // (`BLACKHOLE_NO_SPLIT=`) is refused rather than read as unset
            // or as off.
            if value.trim().is_empty() && name != "BLACKHOLE_BLESS" {
                if let Some((_, wants)) = KNOWN.iter().find(|(n, _)| *n == name) {
                    return Err(Error::Usage(format!(
                        "environment: {name} is set but empty; it takes {wants} (unset it for the default)"
                    )));
                }
            }
            match name {
                "BLACKHOLE_DEVICE" => s.device = Some(value.to_string()),
                "BLACKHOLE_VALIDATION" => s.validation = Some(switch(name, value)?),
                "BLACKHOLE_GPU_TIMEOUT_S" => {
                    let secs = value
                        .trim()
                        .parse::<f64>()
                        .ok()
                        .filter(|s| s.is_finite() && *s > 0.0 && *s <= 1e7)
                        .ok_or_else(|| bad(name, value))?;
                    s.gpu_timeout = Duration::from_secs_f64(secs);
                }
                "BLACKHOLE_NO_SPLIT" => s.no_split = switch(name, value)?,
                "BLACKHOLE_NO_QUAD" => s.no_quad = switch(name, value)?,
                "BLACKHOLE_NO_F64" => s.no_f64 = switch(name, value)?,
                "BLACKHOLE_NO_BAKE" => s.no_bake = switch(name, value)?,
                "BLACKHOLE_FAULT" => {
                    s.fault = Some(fault::parse(value).ok_or_else(|| bad(name, value))?);
                }
                "BLACKHOLE_BLESS" => {}
                other if other.starts_with("BLACKHOLE_") => unknown.push(other.to_string()),
                _ => {}
            }
        }
        Ok((s, unknown))
    }

    /// The validation layer's mode: `BLACKHOLE_VALIDATION=1` requires it,
    /// `=0` turns it off; otherwise debug builds enable it when present.
    pub fn validation_mode(&self) -> Validation {
        match self.validation {
            Some(true) => Validation::Required,
            Some(false) => Validation::Off,
            None if cfg!(debug_assertions) => Validation::IfPresent,
            None => Validation::Off,
        }
    }

    /// What the device is handed (vk/ reads no environment).
    pub fn gpu(&self) -> GpuSettings {
        GpuSettings {
            device: self.device.clone(),
            gpu_timeout: self.gpu_timeout,
            fault: self.fault.clone(),
        }
    }

    /// Parses the process's environment.
    pub fn from_env() -> Result<(Self, Vec<String>)> {
        Self::parse(std::env::vars_os().filter_map(|(k, v)| {
            let k = k.into_string().ok()?;
            k.starts_with("BLACKHOLE_")
                .then(|| (k, v.to_string_lossy().into_owned()))
        }))
    }
}

static SETTINGS: OnceLock<std::result::Result<Settings, String>> = OnceLock::new();

fn parsed() -> &'static std::result::Result<Settings, String> {
    SETTINGS.get_or_init(|| match Settings::from_env() {
        Ok((s, unknown)) => {
            for name in unknown {
                let names: Vec<&str> = KNOWN.iter().map(|k| k.0).collect();
                log::warn!(
                    "environment: {name} is not a setting of this program (ignored; known: {})",
                    names.join(", ")
                );
            }
            Ok(s)
        }
        Err(e) => Err(e.to_string()),
    })
}

/// Parses the environment (once) and reports a bad value as a usage error.
pub fn init() -> Result<&'static Settings> {
    parsed().as_ref().map_err(|e| Error::Usage(e.clone()))
}

/// The settings; defaults if the environment did not parse (the error has
/// been, or will be, reported by [`init`], which every entry point calls).
pub fn get() -> &'static Settings {
    static DEFAULT: OnceLock<Settings> = OnceLock::new();
    match parsed() {
        Ok(s) => s,
        Err(_) => DEFAULT.get_or_init(Settings::default),
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    fn one(name: &str, value: &str) -> Result<Settings> {
        Settings::parse([(name, value)]).map(|(s, _)| s)
    }

    #[test]
    fn bad_values_are_errors_naming_the_variable() {
        for (name, value) in [
            ("BLACKHOLE_GPU_TIMEOUT_S", "1ms"),
            ("BLACKHOLE_GPU_TIMEOUT_S", "0"),
            ("BLACKHOLE_GPU_TIMEOUT_S", "nan"),
            ("BLACKHOLE_VALIDATION", "maybe"),
            ("BLACKHOLE_NO_SPLIT", "please"),
            ("BLACKHOLE_FAULT", "melt"),
        ] {
            let e = one(name, value).unwrap_err().to_string();
            assert!(e.contains(name) && e.contains(value), "{e}");
            assert_eq!(Error::Usage(String::new()).exit_code(), 2);
        }
    }

    #[test]
    fn good_values_parse() {
        assert_eq!(
            one("BLACKHOLE_GPU_TIMEOUT_S", "2.5").unwrap().gpu_timeout,
            Duration::from_millis(2500)
        );
        assert_eq!(
            one("BLACKHOLE_VALIDATION", "yes").unwrap().validation,
            Some(true)
        );
        assert_eq!(
            one("BLACKHOLE_VALIDATION", "0").unwrap().validation,
            Some(false)
        );
        assert!(one("BLACKHOLE_NO_SPLIT", "1").unwrap().no_split);
        assert!(!one("BLACKHOLE_NO_QUAD", "0").unwrap().no_quad);
        assert_eq!(
            one("BLACKHOLE_DEVICE", "llvm").unwrap().device.as_deref(),
            Some("llvm")
        );
    }

    #[test]
    fn an_empty_value_is_refused_the_same_way_for_every_variable() {
        for (name, _) in KNOWN.iter().filter(|(n, _)| *n != "BLACKHOLE_BLESS") {
            for value in ["", " "] {
                let e = one(name, value).unwrap_err().to_string();
                assert!(e.contains(name) && e.contains("empty"), "{e}");
            }
        }
    }

    #[test]
    fn unknown_names_are_listed_for_a_warning() {
        let (_, unknown) =
            Settings::parse([("BLACKHOLE_VALIDATON", "1"), ("HOME", "/root")]).unwrap();
        assert_eq!(unknown, ["BLACKHOLE_VALIDATON"]);
    }
}
