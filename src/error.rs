//! One error type for the whole crate.
//!
//! Every failure at the Vulkan boundary carries what was being done
//! ("creating image `bloom` mip 3 view: ERROR_OUT_OF_DEVICE_MEMORY"), so a user
//! reading one line knows which step failed and why.

use std::path::PathBuf;

use ash::vk;

/// The crate's result type.
pub type Result<T, E = Error> = std::result::Result<T, E>;

/// Everything that can go wrong, from a typo in a scene file to a lost device.
#[derive(Debug, thiserror::Error)]
pub enum Error {
    /// The Vulkan loader library could not be opened.
    #[error(
        "no Vulkan loader found ({0}); install one with `apt-get install libvulkan1 mesa-vulkan-drivers` (Debian/Ubuntu) or your GPU vendor's driver"
    )]
    NoLoader(String),

    /// The loader works but offers no usable device.
    #[error(
        "no Vulkan device found{0}; install a driver, e.g. `apt-get install mesa-vulkan-drivers` (Debian/Ubuntu) for the CPU implementation lavapipe"
    )]
    NoDevice(String),

    /// Validation was asked for but the layer is not installed.
    #[error(
        "BLACKHOLE_VALIDATION=1 asks for VK_LAYER_KHRONOS_validation, which is not installed; install it with `apt-get install vulkan-validationlayers`"
    )]
    NoValidationLayer,

    /// A Vulkan call failed; `what` says what was being done.
    #[error("{what}: {result}")]
    Vulkan { what: String, result: vk::Result },

    /// gpu-allocator refused an allocation.
    #[error("{what}: {source}")]
    Allocation {
        what: String,
        source: gpu_allocator::AllocationError,
    },

    /// A scene file (or preset) is invalid. The message names the key, the value
    /// and the line.
    #[error("{0}")]
    Scene(String),

    /// A command-line value is invalid.
    #[error("{0}")]
    Usage(String),

    /// Reading or writing a file failed.
    #[error("{}: {source}", path.display())]
    Io {
        path: PathBuf,
        source: std::io::Error,
    },

    /// Encoding an image failed.
    #[error("writing {}: {source}", path.display())]
    Image {
        path: PathBuf,
        source: image::ImageError,
    },

    /// Anything else that is a bug or an unexpected driver answer, with context.
    #[error("{0}")]
    Other(String),

    /// Stopped between samples by the caller's flag ([`crate::Renderer::stop_when`]).
    #[error("stopped")]
    Interrupted,
}

impl Error {
    /// Process exit code: 2 for problems of the environment or the input, 1 for the rest.
    pub fn exit_code(&self) -> i32 {
        match self {
            Error::NoLoader(_)
            | Error::NoDevice(_)
            | Error::NoValidationLayer
            | Error::Scene(_)
            | Error::Usage(_) => 2,
            _ => 1,
        }
    }
}

/// Adds "what was being done" to a raw Vulkan result.
pub trait VkContext<T> {
    /// Wraps the error with a description of the operation.
    fn ctx(self, what: impl FnOnce() -> String) -> Result<T>;
}

impl<T> VkContext<T> for std::result::Result<T, vk::Result> {
    fn ctx(self, what: impl FnOnce() -> String) -> Result<T> {
        self.map_err(|result| Error::Vulkan {
            what: what(),
            result,
        })
    }
}
