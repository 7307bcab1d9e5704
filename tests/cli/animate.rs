//! `ladder animate SCENE --out FILE` as a user runs it (issue 39): exit 0 and an SVG animation
//! written (SMIL, no script, the separation marked, the run's separation on stdout); bad input
//! — a scene with a wrong field, a penalty scene (scenes/penalty.toml), the exact method, an `--out` in a folder that
//! does not exist or that is a folder — is one line on stderr naming the file and field (or
//! `--out`), exit 2, and no file written.

use crate::common::{replace_line, tmp_dir};
use std::path::Path;
use std::process::Command;

fn full_fall() -> String {
    let root = Path::new(env!("CARGO_MANIFEST_DIR"));
    std::fs::read_to_string(root.join("scenes/full-fall.toml")).expect("the scene")
}

/// (exit code, stdout, stderr, whether FILE exists) of `ladder animate` on `scene` text.
fn animate(name: &str, scene: &str, out_name: &str) -> (i32, String, String, bool) {
    let dir = tmp_dir("animate", name);
    let file = dir.join("scene.toml");
    std::fs::write(&file, scene).unwrap();
    let out = dir.join(out_name);
    let o = Command::new(env!("CARGO_BIN_EXE_ladder"))
        .arg("animate")
        .arg(&file)
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    let written = out.is_file();
    let svg = std::fs::read_to_string(&out).unwrap_or_default();
    let partial = std::fs::read_dir(&dir)
        .unwrap()
        .flatten()
        .any(|e| e.file_name().to_string_lossy().ends_with(".partial"));
    assert!(!partial, "{name}: a partial file was left behind");
    let _ = std::fs::remove_dir_all(&dir);
    (
        o.status.code().unwrap_or(-1),
        String::from_utf8_lossy(&o.stdout).into_owned() + &svg,
        String::from_utf8_lossy(&o.stderr).into_owned(),
        written,
    )
}

#[test]
fn a_scene_becomes_an_animated_svg() {
    let (code, out, err, written) = animate("ok", &full_fall(), "fall.svg");
    assert_eq!(code, 0, "{err}");
    assert!(written);
    assert!(out.contains("animation written to") && out.contains("separation at t = 0.65"));
    assert!(out.contains("<animate") && !out.contains("<script"));
    assert!(out.contains("id=\"separation\""));
}

/// One line on stderr that names every word of `words`, exit 2, nothing written.
fn refused(name: &str, scene: &str, out_name: &str, words: &[&str]) {
    let (code, _, err, written) = animate(name, scene, out_name);
    assert_eq!(code, 2, "{name}: {err}");
    assert!(!written, "{name}: a file was written");
    assert_eq!(err.trim_end().lines().count(), 1, "{name}: {err}");
    for w in words {
        assert!(err.contains(w), "{name}: '{w}' not in {err}");
    }
}

#[test]
fn bad_input_is_one_line_exit_2_and_no_file() {
    let base = full_fall();
    refused(
        "mass",
        &replace_line(&base, "mass = 1.0", "mass = -1.0"),
        "f.svg",
        &["scene.toml:", "mass"],
    );
    refused(
        "angle",
        &replace_line(&base, "angle = 0.3", "angle = \"steep\""),
        "f.svg",
        &["scene.toml:", "angle"],
    );
    let penalty =
        std::fs::read_to_string(Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/penalty.toml"))
            .expect("the penalty scene");
    refused(
        "penalty",
        &penalty,
        "f.svg",
        &["scene.toml", "[contact] model"],
    );
    // The exact method, which the scene files allow only to separation (scenes/from-rest.toml).
    let from_rest = std::fs::read_to_string(
        Path::new(env!("CARGO_MANIFEST_DIR")).join("scenes/from-rest.toml"),
    )
    .expect("the from-rest scene");
    let exact = replace_line(
        &replace_line(&from_rest, "method = \"dop853\"\ntolerance = 1e-14\n", "method = \"exact\"\n"),
        "want = [\"separation_angle\", \"separation_time\", \"separation_rate\", \"energy_error\", \"rhs_evals\", \"trajectory\", \"forces\"]",
        "want = [\"separation_angle\", \"separation_time\"]",
    );
    refused(
        "exact",
        &exact,
        "f.svg",
        &["scene.toml", "[integrator] method"],
    );
    refused(
        "no-folder",
        &base,
        "missing/f.svg",
        &["--out", "does not exist"],
    );
}

#[test]
fn an_out_that_is_a_folder_is_refused() {
    let dir = tmp_dir("animate", "folder");
    let scene = dir.join("scene.toml");
    std::fs::write(&scene, full_fall()).unwrap();
    let o = Command::new(env!("CARGO_BIN_EXE_ladder"))
        .arg("animate")
        .arg(&scene)
        .arg("--out")
        .arg(&dir)
        .output()
        .unwrap();
    let err = String::from_utf8_lossy(&o.stderr);
    assert_eq!(o.status.code(), Some(2), "{err}");
    assert!(
        err.contains("--out") && err.contains("is a directory"),
        "{err}"
    );
    let _ = std::fs::remove_dir_all(&dir);
}
