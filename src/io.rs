//! Output files, written so that a failed or interrupted command leaves nothing half-written, and so that what is
//! already at the target is respected:
//!
//! | target | what happens |
//! |---|---|
//! | `-` | written to standard output |
//! | a new path, or an existing regular file | written to a temporary file in the same folder, then renamed over the target (atomic: the old content or the new, never half) |
//! | an existing FIFO, character device or socket | written through (opened and written; never replaced by a regular file) |
//! | a symbolic link | followed: its final target is written by the rules above (the link stays a link); a link to nothing is refused |
//! | a folder | refused |
//!
//! Every failure is an [`Error::Write`] naming the path the user gave.

use crate::error::{Error, Result};
use std::io::Write as _;
use std::path::{Path, PathBuf};

/// Whether a path means standard output (`-`).
pub fn is_stdout(path: &Path) -> bool {
    path.as_os_str() == "-"
}

/// Write `text` to `path` by the rules of the module docs.
pub fn write_output(path: &Path, text: &str) -> Result<()> {
    write_output_bytes(path, text.as_bytes())
}

/// Write `bytes` to `path` by the rules of the module docs (a binary output: a creep table's `.npz`).
pub fn write_output_bytes(path: &Path, text: &[u8]) -> Result<()> {
    let werr = |source: std::io::Error| Error::Write { path: path.to_path_buf(), source };
    if is_stdout(path) {
        let mut out = std::io::stdout().lock();
        return out.write_all(text).and_then(|_| out.flush()).map_err(werr);
    }
    let target = resolve(path)?;
    match std::fs::metadata(&target) {
        Ok(m) if m.is_dir() => Err(werr(std::io::Error::other("it is a folder"))),
        Ok(m) if !m.is_file() => {
            // A FIFO, a device or a socket: write through, never replace it.
            let mut f = std::fs::OpenOptions::new().write(true).open(&target).map_err(werr)?;
            f.write_all(text).and_then(|_| f.flush()).map_err(werr)
        }
        _ => replace(&target, text).map_err(werr),
    }
}

/// The file a path writes to: the path itself, or the final target of a symbolic link (relative links resolved
/// against the link's folder). A link to nothing is refused.
fn resolve(path: &Path) -> Result<PathBuf> {
    let mut p = path.to_path_buf();
    for _ in 0..40 {
        match std::fs::symlink_metadata(&p) {
            Ok(m) if m.file_type().is_symlink() => {
                let to = std::fs::read_link(&p).map_err(|source| Error::Write { path: path.to_path_buf(), source })?;
                p = match p.parent() {
                    Some(dir) if to.is_relative() => dir.join(to),
                    _ => to,
                };
            }
            Ok(_) => return Ok(p),
            Err(_) if p != path => {
                return Err(Error::Write {
                    path: path.to_path_buf(),
                    source: std::io::Error::other(format!(
                        "it is a symbolic link to {}, which does not exist",
                        p.display()
                    )),
                })
            }
            Err(_) => return Ok(p),
        }
    }
    Err(Error::Write { path: path.to_path_buf(), source: std::io::Error::other("too many levels of symbolic links") })
}

/// Replace a regular file (or create it) atomically: a temporary file beside it, then a rename.
fn replace(target: &Path, text: &[u8]) -> std::io::Result<()> {
    let dir = target.parent().filter(|p| !p.as_os_str().is_empty()).unwrap_or(Path::new("."));
    let name = target.file_name().map(|n| n.to_string_lossy().into_owned()).unwrap_or_else(|| "out".into());
    let tmp = dir.join(format!(".{name}.tmp-{}", std::process::id()));
    std::fs::write(&tmp, text)?;
    std::fs::rename(&tmp, target).inspect_err(|_| {
        let _ = std::fs::remove_file(&tmp);
    })
}

/// Write `text` to `path` (the rules of [`write_output`]; the name says what it guarantees for regular files).
pub fn write_atomic(path: &Path, text: &str) -> Result<()> {
    write_output(path, text)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn regular_files_are_replaced_and_links_followed() {
        let dir = tempfile::tempdir().unwrap();
        let f = dir.path().join("a.json");
        write_output(&f, "one").unwrap();
        write_output(&f, "two").unwrap();
        assert_eq!(std::fs::read_to_string(&f).unwrap(), "two");
        // A link: its target gets the text, the link stays a link.
        let link = dir.path().join("link.json");
        std::os::unix::fs::symlink("a.json", &link).unwrap();
        write_output(&link, "three").unwrap();
        assert!(std::fs::symlink_metadata(&link).unwrap().file_type().is_symlink());
        assert_eq!(std::fs::read_to_string(&f).unwrap(), "three");
        // A link to nothing is refused, and nothing is created.
        let dangling = dir.path().join("dangling.json");
        std::os::unix::fs::symlink("missing/x.json", &dangling).unwrap();
        let e = write_output(&dangling, "x").unwrap_err();
        assert!(e.to_string().contains("does not exist"), "{e}");
        assert!(!dir.path().join("missing").exists());
        // A folder is refused.
        assert!(write_output(dir.path(), "x").is_err());
        // No temporary file is left behind.
        let names: Vec<String> =
            std::fs::read_dir(dir.path()).unwrap().map(|e| e.unwrap().file_name().to_string_lossy().into()).collect();
        assert!(names.iter().all(|n| !n.contains(".tmp-")), "{names:?}");
    }
}
