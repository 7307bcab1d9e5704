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

#[cfg(test)]
mod tests {
    use super::*;

    fn scratch(tag: &str) -> PathBuf {
        let d =
            std::env::temp_dir().join(format!("ladder-book-write-{tag}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&d);
        std::fs::create_dir_all(&d).unwrap();
        d
    }

    #[test]
    fn writes_replaces_its_own_book_and_refuses_anything_else() {
        let d = scratch("a");
        let out = d.join("book");
        let files = vec![("a/b.html".to_string(), b"x".to_vec())];
        write_atomically(&out, &files).unwrap();
        assert_eq!(std::fs::read(out.join("a/b.html")).unwrap(), b"x");
        // A second run replaces the first whole.
        write_atomically(&out, &[("c.html".to_string(), b"y".to_vec())]).unwrap();
        assert!(!out.join("a/b.html").exists() && out.join("c.html").exists());
        // A foreign directory, a file and a missing parent are refused, and nothing is left.
        let foreign = d.join("mine");
        std::fs::create_dir(&foreign).unwrap();
        std::fs::write(foreign.join("notes.txt"), "keep").unwrap();
        assert!(write_atomically(&foreign, &files)
            .unwrap_err()
            .contains("not a book"));
        assert_eq!(
            std::fs::read_to_string(foreign.join("notes.txt")).unwrap(),
            "keep"
        );
        std::fs::write(d.join("file"), "").unwrap();
        assert!(write_atomically(&d.join("file"), &files).is_err());
        assert!(write_atomically(&d.join("no/such/dir"), &files)
            .unwrap_err()
            .contains("does not exist"));
        let left: Vec<_> = std::fs::read_dir(&d)
            .unwrap()
            .map(|e| e.unwrap().file_name())
            .collect();
        assert_eq!(left.len(), 3, "only book, mine and file remain: {left:?}");
        // A file that cannot be written (a name that is a directory) leaves the old book as it was.
        let bad = vec![
            ("x".to_string(), b"1".to_vec()),
            ("x/y".to_string(), b"2".to_vec()),
        ];
        assert!(write_atomically(&out, &bad).is_err());
        assert!(out.join("c.html").exists());
        let _ = std::fs::remove_dir_all(&d);
    }
}
