//! Helpers for tests that run the `blackhole` binary on lavapipe with the
//! validation layer required.

#![allow(dead_code)]

use std::path::{Path, PathBuf};
use std::process::{Command, Output};

/// The binary under test, with validation required and caches kept in target/.
pub fn blackhole() -> Command {
    let mut c = Command::new(env!("CARGO_BIN_EXE_blackhole"));
    let cache = Path::new(env!("CARGO_TARGET_TMPDIR")).join("xdg-cache");
    c.env("BLACKHOLE_VALIDATION", "1")
        .env("XDG_CACHE_HOME", cache)
        .env("LP_NUM_THREADS", "4")
        .env("RUST_LOG", "blackhole=info");
    c
}

/// Runs a command; returns (exit code, stdout, stderr).
pub fn run(mut c: Command) -> (i32, String, String) {
    let Output {
        status,
        stdout,
        stderr,
    } = c.output().expect("the blackhole binary runs");
    (
        status.code().unwrap_or(-1),
        String::from_utf8_lossy(&stdout).into_owned(),
        String::from_utf8_lossy(&stderr).into_owned(),
    )
}

/// Asserts a run succeeded with the validation layer on and silent.
pub fn assert_clean(code: i32, stdout: &str, stderr: &str) {
    assert_eq!(code, 0, "exit code\nstdout:\n{stdout}\nstderr:\n{stderr}");
    assert!(
        stderr.contains("validation: 0 errors, 0 warnings"),
        "validation must be on and clean:\n{stderr}"
    );
    assert!(
        !stderr.contains("still alive at shutdown"),
        "GPU memory leaked:\n{stderr}"
    );
}

/// A fresh scratch directory for one test.
pub fn scratch() -> tempfile::TempDir {
    tempfile::Builder::new()
        .prefix("blackhole-test-")
        .tempdir_in(env!("CARGO_TARGET_TMPDIR"))
        .expect("creating a scratch directory")
}

/// Path of `name` inside `dir`.
pub fn path_in(dir: &tempfile::TempDir, name: &str) -> PathBuf {
    dir.path().join(name)
}
