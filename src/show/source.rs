//! Where a display lives: the Rust functions that encode it (file and line) and its page in the
//! book (`equations/*.md`, the line of its heading). Read from the source tree at run time, as
//! `ladder verify` reads the book (`crate::docs::default_dir`): `./src` and `./equations` when
//! run from the repository, else the tree the binary was built from; a file that is not there
//! gives no line (`None`), never an error.

use serde::Serialize;
use std::path::{Path, PathBuf};

/// A place in the repository.
#[derive(Clone, Debug, Serialize)]
pub struct Location {
    /// The function (`ladder::torque::eq25_torque_analysis_d`) or the page's heading.
    pub name: String,
    /// The file, relative to the repository root (`src/ladder/torque.rs`).
    pub file: String,
    /// Its line (from 1), when the file was found.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub line: Option<usize>,
}

/// The directory holding `src/` and `equations/`: the working directory in a checkout, else the crate's manifest directory.
pub fn root() -> PathBuf {
    if Path::new("src").is_dir() && Path::new("equations").is_dir() {
        PathBuf::from(".")
    } else {
        PathBuf::from(env!("CARGO_MANIFEST_DIR"))
    }
}

/// The line (from 1) of `fn name` in `text`.
fn fn_line(text: &str, name: &str) -> Option<usize> {
    let pat = format!("fn {name}");
    text.lines()
        .position(|l| {
            l.find(&pat)
                .is_some_and(|i| matches!(l[i + pat.len()..].chars().next(), Some('<' | '(')))
        })
        .map(|i| i + 1)
}

/// Where a registry function path (below the crate root) is defined.
pub fn function(path: &str) -> Location {
    let root = root();
    let (module, name) = path.rsplit_once("::").unwrap_or(("", path));
    let dir = module.replace("::", "/");
    let mut candidates = vec![format!("src/{dir}.rs"), format!("src/{dir}/mod.rs")];
    // A module split into files: look through its directory too.
    if let Ok(rd) = std::fs::read_dir(root.join("src").join(&dir)) {
        let mut files: Vec<String> = rd
            .flatten()
            .filter_map(|f| f.file_name().into_string().ok())
            .filter(|f| f.ends_with(".rs"))
            .map(|f| format!("src/{dir}/{f}"))
            .collect();
        files.sort();
        candidates.extend(files);
    }
    for file in &candidates {
        if let Ok(text) = std::fs::read_to_string(root.join(file)) {
            if let Some(line) = fn_line(&text, name) {
                return Location {
                    name: path.into(),
                    file: file.clone(),
                    line: Some(line),
                };
            }
        }
    }
    Location {
        name: path.into(),
        file: candidates[0].clone(),
        line: None,
    }
}

/// The book page of display `number`: the heading `### (N) …` in `equations/*.md`
/// ([`crate::docs::pages`]).
pub fn docs_page(number: u32) -> Option<Location> {
    let p =
        crate::docs::pages::headings(&root().join("equations")).remove(&format!("({number})"))?;
    Some(Location {
        name: p.heading,
        file: p.file,
        line: Some(p.line),
    })
}
