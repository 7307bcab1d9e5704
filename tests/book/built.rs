//! The book that the tests of this binary read, written once by `ladder book` (100 float cases
//! per check: the layout, the MathML and the pages do not depend on the count).

use std::path::{Path, PathBuf};
use std::process::Command;
use std::sync::OnceLock;

/// Float cases per check, for the book and for the `ladder verify` it is held against.
pub const CASES: &str = "100";

/// The folder of the book, written on first use and shared by every test.
pub fn book() -> &'static PathBuf {
    static BOOK: OnceLock<PathBuf> = OnceLock::new();
    BOOK.get_or_init(|| {
        let dir =
            Path::new(env!("CARGO_TARGET_TMPDIR")).join(format!("book-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        let out = Command::new(env!("CARGO_BIN_EXE_ladder"))
            .args(["book", "--cases", CASES, "--out"])
            .arg(&dir)
            .output()
            .expect("ladder book runs");
        assert!(
            out.status.success(),
            "ladder book failed: {}{}",
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr)
        );
        dir
    })
}
