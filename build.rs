//! Embeds the note's markdown, `equations/*.md`, in the crate: the registry is parsed from it at
//! start-up (`src/registry/source`), so the `ladder` binary stands alone and a new chapter file is
//! picked up without a line of Rust. Nothing is parsed here (parsing markdown in a build script
//! is what rust-skeptic's users regretted); the script only lists the files for `include_str!`.

use std::path::Path;

fn main() {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    let dir = root.join("equations");
    // A directory is scanned for changes as a whole: a file added, edited or removed reruns this.
    println!("cargo:rerun-if-changed={}", dir.display());
    let mut files: Vec<_> = std::fs::read_dir(&dir)
        .map(|rd| {
            rd.flatten()
                .map(|e| e.path())
                .filter(|p| p.extension().is_some_and(|x| x == "md"))
                .collect()
        })
        .unwrap_or_default();
    files.sort();
    let mut out = String::from(
        "/// Every `equations/*.md` file of the crate, as (path from the crate root, text), by name.\n\
         pub static CHAPTERS: &[(&str, &str)] = &[\n",
    );
    for f in &files {
        let name = f.file_name().map(|n| n.to_string_lossy().into_owned());
        let name = name.unwrap_or_default();
        out += &format!(
            "    ({:?}, include_str!({:?})),\n",
            format!("equations/{name}"),
            f
        );
    }
    out += "];\n";
    let out_dir = std::env::var("OUT_DIR").expect("cargo sets OUT_DIR for build scripts");
    std::fs::write(Path::new(&out_dir).join("chapters.rs"), out).expect("OUT_DIR is writable");
}
