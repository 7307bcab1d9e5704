//! Writing the book all-or-nothing: every file goes into a hidden sibling directory first,
//! which is renamed to the requested name only when complete. A book written earlier by
//! `ladder book` (it carries a marker file) is replaced; any other existing directory is left
//! alone and refused.

use super::BookFile;
use std::path::{Path, PathBuf};

/// The file that marks a directory as a book written by `ladder book`.
pub const MARKER: &str = ".ladder-book";

fn parent_of(out: &Path) -> PathBuf {
    match out.parent() {
        Some(p) if !p.as_os_str().is_empty() => p.to_path_buf(),
        _ => PathBuf::from("."),
    }
}

/// Refuse an output path that cannot take the book, with one line saying why.
pub fn check_out(out: &Path) -> Result<(), String> {
    let shown = out.display();
    if out.file_name().is_none() {
        return Err(format!("--out {shown}: not a directory name"));
    }
    let parent = parent_of(out);
    if !parent.is_dir() {
        return Err(format!(
            "--out {shown}: the directory {} does not exist",
            parent.display()
        ));
    }
    if out.exists() {
        if !out.is_dir() {
            return Err(format!("--out {shown}: exists and is not a directory"));
        }
        let empty = std::fs::read_dir(out)
            .map_err(|e| format!("--out {shown}: cannot read: {e}"))?
            .next()
            .is_none();
        if !empty && !out.join(MARKER).is_file() {
            return Err(format!(
                "--out {shown}: exists and is not a book written by `ladder book`; not replacing it"
            ));
        }
    }
    Ok(())
}

fn write_into(dir: &Path, files: &[BookFile]) -> Result<(), String> {
    std::fs::create_dir(dir).map_err(|e| format!("{}: cannot create: {e}", dir.display()))?;
    for (name, bytes) in files {
        let path = dir.join(name);
        if let Some(p) = path.parent() {
            std::fs::create_dir_all(p)
                .map_err(|e| format!("{}: cannot create: {e}", p.display()))?;
        }
        std::fs::write(&path, bytes)
            .map_err(|e| format!("{}: cannot write: {e}", path.display()))?;
    }
    std::fs::write(
        dir.join(MARKER),
        "written by `ladder book`; replaced whole by the next run\n",
    )
    .map_err(|e| format!("{}: cannot write: {e}", dir.display()))
}

/// Write `files` as the directory `out`, all or nothing.
pub fn write_atomically(out: &Path, files: &[BookFile]) -> Result<(), String> {
    check_out(out)?;
    let parent = parent_of(out);
    let name = out
        .file_name()
        .map(|n| n.to_string_lossy().to_string())
        .unwrap_or_default();
    let pid = std::process::id();
    let tmp = parent.join(format!(".{name}.tmp-{pid}"));
    let old = parent.join(format!(".{name}.old-{pid}"));
    let _ = std::fs::remove_dir_all(&tmp);
    if let Err(e) = write_into(&tmp, files) {
        let _ = std::fs::remove_dir_all(&tmp);
        return Err(e);
    }
    let had_old = out.exists();
    if had_old {
        if let Err(e) = std::fs::rename(out, &old) {
            let _ = std::fs::remove_dir_all(&tmp);
            return Err(format!("{}: cannot replace: {e}", out.display()));
        }
    }
    if let Err(e) = std::fs::rename(&tmp, out) {
        let _ = std::fs::remove_dir_all(&tmp);
        if had_old {
            let _ = std::fs::rename(&old, out);
        }
        return Err(format!("{}: cannot write: {e}", out.display()));
    }
    if had_old {
        let _ = std::fs::remove_dir_all(&old);
    }
    Ok(())
}
