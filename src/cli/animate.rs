//! `ladder animate SCENE --out FILE`: the fall of a scene from release to flat as an animated
//! SVG (SMIL, no script), the contact forces to scale and the separation marked; drawn by
//! `report::animation` from the simulator's trace. Exit codes: 0 written; 1 the run failed
//! (stderr says why, nothing written); 2 bad input — the scene (file, line and field) or
//! `--out` — one line on stderr, nothing written.

use clap::Args;
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// The options of `ladder animate`.
#[derive(Args)]
pub struct AnimateArgs {
    /// The scene file (TOML, as for `ladder simulate`); its start and ladder are used, and the
    /// run always goes to flat.
    scene: PathBuf,
    /// The SVG file to write.
    #[arg(long)]
    out: PathBuf,
}

/// Why `--out` cannot be written, checked before the run.
fn check_out(out: &Path) -> Result<(), String> {
    if out.is_dir() {
        return Err(format!("--out {}: is a directory", out.display()));
    }
    let parent = match out.parent() {
        Some(p) if !p.as_os_str().is_empty() => p,
        _ => Path::new("."),
    };
    if !parent.is_dir() {
        return Err(format!(
            "--out {}: the folder {} does not exist",
            out.display(),
            parent.display()
        ));
    }
    Ok(())
}

/// Write `text` to `out` whole or not at all (a temporary file beside it, then a rename).
fn write_whole(out: &Path, text: &str) -> Result<(), String> {
    let tmp = out.with_extension("svg.partial");
    let res = std::fs::write(&tmp, text).and_then(|_| std::fs::rename(&tmp, out));
    if let Err(e) = res {
        let _ = std::fs::remove_file(&tmp);
        return Err(format!("--out {}: {e}", out.display()));
    }
    Ok(())
}

/// Run `ladder animate`.
pub fn run(a: AnimateArgs) -> ExitCode {
    if let Err(e) = check_out(&a.out) {
        eprintln!("ladder animate: {e}");
        return ExitCode::from(2);
    }
    let scene = match crate::sim::scene::load(&a.scene) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("ladder animate: {e}");
            return ExitCode::from(2);
        }
    };
    if let Some(why) = crate::report::animation::unsupported(&scene) {
        eprintln!("ladder animate: {why}");
        return ExitCode::from(2);
    }
    let drawn = crate::report::animation::run(&scene)
        .and_then(|(s, o)| crate::report::animation::svg(&s, &o).map(|svg| (svg, o)));
    let (svg, o) = match drawn {
        Ok(x) => x,
        Err(e) => {
            eprintln!("ladder animate: {e}");
            return ExitCode::from(1);
        }
    };
    if let Err(e) = write_whole(&a.out, &svg) {
        eprintln!("ladder animate: {e}");
        return ExitCode::from(2);
    }
    let sep = o
        .separation
        .map(|s| {
            format!(
                "separation at t = {:.4} s, θ = {:.3}°; ",
                s.time,
                s.angle.to_degrees()
            )
        })
        .unwrap_or_default();
    let flat = o
        .flat
        .map(|f| format!("flat at t = {:.4} s", f.time))
        .unwrap_or_default();
    println!("animation written to {} ({sep}{flat})", a.out.display());
    ExitCode::SUCCESS
}
