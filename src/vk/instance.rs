//! The Vulkan instance, the validation layer and the debug messenger.
//!
//! Validation (`VK_LAYER_KHRONOS_validation`, with synchronization validation)
//! is on when `BLACKHOLE_VALIDATION=1`, or in debug builds when the layer is
//! installed. The messenger counts errors and warnings so a test can assert
//! that there were none.

use std::ffi::{CStr, c_void};
use std::sync::atomic::{AtomicU32, Ordering};

use ash::{ext, vk};

use crate::error::VkContext;
use crate::{Error, Result};

const VALIDATION_LAYER: &CStr = c"VK_LAYER_KHRONOS_validation";

/// Whether validation should be enabled (the caller decides, from its
/// settings and build: [`crate::settings::Settings::validation_mode`]).
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Validation {
    /// Required: fail if the layer is missing.
    Required,
    /// Enabled if the layer is installed (debug builds).
    IfPresent,
    /// Off.
    Off,
}

/// Errors and warnings of every kind go to `debug_callback`, which counts
/// them in `counts` (boxed by the caller so its address outlives the
/// instance).
fn messenger_info(counts: &ValidationCounts) -> vk::DebugUtilsMessengerCreateInfoEXT<'static> {
    vk::DebugUtilsMessengerCreateInfoEXT::default()
        .message_severity(
            vk::DebugUtilsMessageSeverityFlagsEXT::ERROR
                | vk::DebugUtilsMessageSeverityFlagsEXT::WARNING,
        )
        .message_type(
            vk::DebugUtilsMessageTypeFlagsEXT::GENERAL
                | vk::DebugUtilsMessageTypeFlagsEXT::VALIDATION
                | vk::DebugUtilsMessageTypeFlagsEXT::PERFORMANCE,
        )
        .pfn_user_callback(Some(debug_callback))
        .user_data(counts as *const ValidationCounts as *mut c_void)
}

/// A failed vkCreateInstance in words: no driver, a missing layer or
/// extension, or a driver the loader could not load.
fn instance_error(result: vk::Result) -> Error {
    match result {
        // The loader says this when it finds no driver at all.
        vk::Result::ERROR_INCOMPATIBLE_DRIVER => Error::NoDevice(format!(
            " (the Vulkan loader found no driver it could load{})",
            manifests_named()
                .map(|m| format!("; {m} names the manifests"))
                .unwrap_or_default()
        )),
        vk::Result::ERROR_LAYER_NOT_PRESENT | vk::Result::ERROR_EXTENSION_NOT_PRESENT => {
            Error::Vulkan {
                what: "creating the Vulkan instance".into(),
                result,
            }
        }
        result => loader_failure("creating the instance", result),
    }
}

/// The loader's variables that name driver manifests, as set (`VAR=value`).
fn manifests_named() -> Option<String> {
    let named: Vec<String> = ["VK_DRIVER_FILES", "VK_ICD_FILENAMES", "VK_ADD_DRIVER_FILES"]
        .iter()
        .filter_map(|v| std::env::var(v).ok().map(|val| format!("{v}={val}")))
        .collect();
    (!named.is_empty()).then(|| named.join(", "))
}

/// A failure of the loader before any device is open: almost always a broken
/// driver install (a manifest naming a missing or corrupt library), which the
/// loader reports as out of memory or as a failed initialisation.
pub fn loader_failure(what: &str, result: vk::Result) -> Error {
    let check = match manifests_named() {
        Some(m) => format!("check the driver manifests named by {m}"),
        None => "check the driver manifests in /usr/share/vulkan/icd.d".to_string(),
    };
    Error::NoDevice(format!(
        " (the Vulkan loader failed {what} with {result:?}, its answer to a driver it cannot \
         load or a manifest it cannot read: {check})"
    ))
}

/// Validation messages seen so far (errors and warnings).
#[derive(Debug, Default)]
pub struct ValidationCounts {
    pub errors: AtomicU32,
    pub warnings: AtomicU32,
}

/// Owns the loader entry, the instance and the debug messenger. Dropped last:
/// everything made from it holds an `Arc` to the device, which holds this.
pub struct Instance {
    pub entry: ash::Entry,
    pub instance: ash::Instance,
    /// Present when VK_EXT_debug_utils is available (labels, names, messages).
    pub debug_utils: Option<ext::debug_utils::Instance>,
    messenger: vk::DebugUtilsMessengerEXT,
    /// Boxed so the callback's pointer stays valid while the instance lives.
    counts: Box<ValidationCounts>,
    pub validation_enabled: bool,
}

unsafe extern "system" fn debug_callback(
    severity: vk::DebugUtilsMessageSeverityFlagsEXT,
    kind: vk::DebugUtilsMessageTypeFlagsEXT,
    data: *const vk::DebugUtilsMessengerCallbackDataEXT<'_>,
    user: *mut c_void,
) -> vk::Bool32 {
    // SAFETY: the layer passes a valid callback-data pointer for the duration of
    // the call, and `user` is the boxed counter owned by the live Instance.
    let (message, counts) = unsafe {
        let msg = if data.is_null() || (*data).p_message.is_null() {
            String::from("(no message)")
        } else {
            CStr::from_ptr((*data).p_message)
                .to_string_lossy()
                .into_owned()
        };
        (msg, (user as *const ValidationCounts).as_ref())
    };
    if let Some(c) = counts {
        if severity.contains(vk::DebugUtilsMessageSeverityFlagsEXT::ERROR) {
            c.errors.fetch_add(1, Ordering::Relaxed);
        } else if severity.contains(vk::DebugUtilsMessageSeverityFlagsEXT::WARNING) {
            c.warnings.fetch_add(1, Ordering::Relaxed);
        }
    }
    // Validation findings go to stderr whatever the log level: they are bugs.
    eprintln!("vulkan {severity:?} {kind:?}: {message}");
    vk::FALSE
}

impl Instance {
    /// Loads Vulkan and creates the instance.
    pub fn new(validation: Validation) -> Result<Self> {
        Self::with_extensions(validation, &[])
    }

    /// Loads Vulkan and creates the instance with `extra` extensions too (the
    /// window's surface extensions).
    pub fn with_extensions(
        validation: Validation,
        extra: &[*const std::ffi::c_char],
    ) -> Result<Self> {
        // SAFETY: loading the system loader library; failure is reported, not UB.
        let entry = unsafe { ash::Entry::load() }.map_err(|e| Error::NoLoader(e.to_string()))?;

        // SAFETY: plain enumeration calls on a loaded entry.
        let layers = unsafe { entry.enumerate_instance_layer_properties() }
            .map_err(|r| loader_failure("listing instance layers", r))?;
        let have_layer = layers
            .iter()
            .any(|l| l.layer_name_as_c_str().is_ok_and(|n| n == VALIDATION_LAYER));
        let validation_enabled = match validation {
            Validation::Required if !have_layer => return Err(Error::NoValidationLayer),
            Validation::Required => true,
            Validation::IfPresent => have_layer,
            Validation::Off => false,
        };

        // SAFETY: as above.
        let extensions = unsafe { entry.enumerate_instance_extension_properties(None) }
            .map_err(|r| loader_failure("listing instance extensions", r))?;
        let has_ext = |name: &CStr| {
            extensions
                .iter()
                .any(|e| e.extension_name_as_c_str().is_ok_and(|n| n == name))
        };
        let have_debug_utils = has_ext(ext::debug_utils::NAME) || validation_enabled;
        let mut ext_names = extra.to_vec();
        if have_debug_utils {
            ext_names.push(ext::debug_utils::NAME.as_ptr());
        }
        let portability = has_ext(ash::khr::portability_enumeration::NAME);
        if portability {
            ext_names.push(ash::khr::portability_enumeration::NAME.as_ptr());
        }

        // SAFETY: querying the loader's version is always allowed.
        let loader_version = unsafe { entry.try_enumerate_instance_version() }
            .ctx(|| "querying the Vulkan loader version".into())?
            .unwrap_or(vk::API_VERSION_1_0);
        if loader_version < vk::API_VERSION_1_2 {
            return Err(Error::NoDevice(format!(
                " (the Vulkan loader is version {}.{}, 1.2 or newer is needed)",
                vk::api_version_major(loader_version),
                vk::api_version_minor(loader_version)
            )));
        }
        let api_version = loader_version.min(vk::API_VERSION_1_3);

        let app_info = vk::ApplicationInfo::default()
            .application_name(c"blackhole")
            .application_version(vk::make_api_version(0, 0, 1, 0))
            .engine_name(c"blackhole")
            .api_version(api_version);
        let layer_names = if validation_enabled {
            vec![VALIDATION_LAYER.as_ptr()]
        } else {
            vec![]
        };

        let counts = Box::new(ValidationCounts::default());
        let mut messenger_info = messenger_info(&counts);
        // Synchronization validation checks the graph's barriers on every run.
        let enabled_features = [vk::ValidationFeatureEnableEXT::SYNCHRONIZATION_VALIDATION];
        let mut validation_features =
            vk::ValidationFeaturesEXT::default().enabled_validation_features(&enabled_features);

        let mut create_info = vk::InstanceCreateInfo::default()
            .application_info(&app_info)
            .enabled_layer_names(&layer_names)
            .enabled_extension_names(&ext_names);
        if portability {
            create_info = create_info.flags(vk::InstanceCreateFlags::ENUMERATE_PORTABILITY_KHR);
        }
        if validation_enabled {
            create_info = create_info
                .push_next(&mut messenger_info)
                .push_next(&mut validation_features);
        }
        // SAFETY: every pointer in create_info outlives the call.
        let instance =
            unsafe { entry.create_instance(&create_info, None) }.map_err(instance_error)?;

        let (debug_utils, messenger) = if have_debug_utils {
            let du = ext::debug_utils::Instance::new(&entry, &instance);
            let messenger = if validation_enabled {
                // SAFETY: valid instance; the counter box lives as long as self.
                match unsafe { du.create_debug_utils_messenger(&messenger_info, None) } {
                    Ok(m) => m,
                    Err(result) => {
                        // SAFETY: nothing else was created from the instance yet.
                        unsafe { instance.destroy_instance(None) };
                        return Err(Error::Vulkan {
                            what: "creating the debug messenger".into(),
                            result,
                        });
                    }
                }
            } else {
                vk::DebugUtilsMessengerEXT::null()
            };
            (Some(du), messenger)
        } else {
            (None, vk::DebugUtilsMessengerEXT::null())
        };

        Ok(Instance {
            entry,
            instance,
            debug_utils,
            messenger,
            counts,
            validation_enabled,
        })
    }

    /// Validation errors and warnings reported so far.
    pub fn validation_counts(&self) -> (u32, u32) {
        (
            self.counts.errors.load(Ordering::Relaxed),
            self.counts.warnings.load(Ordering::Relaxed),
        )
    }
}

impl Drop for Instance {
    fn drop(&mut self) {
        // SAFETY: the device and everything made from it are gone (they hold
        // Arcs to the device that owns this instance); messenger before instance.
        unsafe {
            if let Some(du) = &self.debug_utils {
                if self.messenger != vk::DebugUtilsMessengerEXT::null() {
                    du.destroy_debug_utils_messenger(self.messenger, None);
                }
            }
            self.instance.destroy_instance(None);
        }
    }
}
