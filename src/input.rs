//! Files the user names as input (scene files, sky images): the one place
//! that decides whether a path can be read, so every input is refused the
//! same way. Only regular files are read (a folder, a FIFO with no writer or
//! a device would hang or never end), and text files only up to a size limit.

use std::io::Read;
use std::path::Path;

/// Largest scene file read, bytes (a scene is a few kilobytes).
pub const MAX_SCENE_BYTES: u64 = 64 << 20;

/// What sits at a path, in words for a message.
fn kind_of(meta: &std::fs::Metadata) -> &'static str {
    let t = meta.file_type();
    if t.is_dir() {
        return "a folder";
    }
    #[cfg(unix)]
    {
        use std::os::unix::fs::FileTypeExt;
        if t.is_fifo() {
            return "a FIFO (named pipe)";
        }
        if t.is_char_device() || t.is_block_device() {
            return "a device";
        }
        if t.is_socket() {
            return "a socket";
        }
    }
    "not a regular file"
}

/// `Ok` if `path` is a regular file (after symbolic links); otherwise why
/// not, in words: "no such file", "is a folder", "is a FIFO ...".
pub fn check_regular(path: &Path) -> Result<std::fs::Metadata, String> {
    match std::fs::metadata(path) {
        Ok(m) if m.is_file() => Ok(m),
        Ok(m) => Err(format!("is {}, not a file", kind_of(&m))),
        Err(e) if e.kind() == std::io::ErrorKind::NotFound => Err("no such file".into()),
        Err(e) => Err(format!("cannot read it: {e}")),
    }
}

/// Reads a regular text file of at most `limit` bytes; the reason in words
/// on failure (the caller names the file and the key).
pub fn read_text(path: &Path, limit: u64) -> Result<String, String> {
    let meta = check_regular(path)?;
    let too_big = || format!("is larger than {} MB, the limit", limit >> 20);
    if meta.len() > limit {
        return Err(too_big());
    }
    let file = std::fs::File::open(path).map_err(|e| format!("cannot read it: {e}"))?;
    let mut bytes = Vec::new();
    // The size may change between the check and the read: read at most one
    // byte past the limit, whatever the file does meanwhile.
    file.take(limit + 1)
        .read_to_end(&mut bytes)
        .map_err(|e| format!("cannot read it: {e}"))?;
    if bytes.len() as u64 > limit {
        return Err(too_big());
    }
    String::from_utf8(bytes).map_err(|e| {
        let at = e.utf8_error().valid_up_to();
        format!("is not UTF-8 text (invalid byte at offset {at})")
    })
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn only_regular_files_are_read() {
        let dir = tempfile::tempdir().expect("temp dir");
        assert_eq!(
            read_text(dir.path(), 100).unwrap_err(),
            "is a folder, not a file"
        );
        assert_eq!(
            read_text(&dir.path().join("nope"), 100).unwrap_err(),
            "no such file"
        );
        #[cfg(unix)]
        assert_eq!(
            read_text(Path::new("/dev/zero"), 100).unwrap_err(),
            "is a device, not a file"
        );
        let f = dir.path().join("big.toml");
        std::fs::write(&f, "x".repeat(200)).expect("write");
        assert!(read_text(&f, 100).unwrap_err().contains("larger than"));
        assert_eq!(read_text(&f, 200).unwrap().len(), 200);
    }
}
