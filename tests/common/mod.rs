//! Helpers shared by the integration suites: proptest strategies and a runner for
//! `ladder simulate` on scene text.
#![allow(dead_code)]

use proptest::prelude::*;
use sliding_ladder::registry::sample::{RawLadder, RawParticles, EXTRA, PER_PARTICLE};
use std::path::{Path, PathBuf};
use std::process::Command;

/// Cases per property: at least 1000 (`PROPTEST_CASES` or `LADDER_CASES` raise it).
pub fn cases(minimum: u32) -> u32 {
    let env = |k: &str| std::env::var(k).ok().and_then(|v| v.parse::<u32>().ok());
    minimum
        .max(env("LADDER_CASES").unwrap_or(0))
        .max(env("PROPTEST_CASES").unwrap_or(0))
}

/// θ ∈ [0, π/2), m, l, g log-uniform over 1e-6..1e6, unit-free θ̇, θ̈, θ⃛ in [−1, 1].
pub fn raw_ladder() -> impl Strategy<Value = RawLadder> {
    (
        0.0..std::f64::consts::FRAC_PI_2,
        [-6.0..6.0f64, -6.0..6.0f64, -6.0..6.0f64],
        [-1.0..1.0f64, -1.0..1.0f64, -1.0..1.0f64],
    )
        .prop_map(|(theta, e, unit)| RawLadder {
            theta,
            mlg: e.map(|x| 10f64.powf(x)),
            unit,
        })
}

/// 1 to 8 particles, masses log-uniform over 1e-3..1e3, everything else in [−10, 10].
pub fn raw_particles() -> impl Strategy<Value = RawParticles> {
    (1usize..=8).prop_flat_map(|n| {
        (
            prop::collection::vec(-10.0..10.0f64, n * PER_PARTICLE + EXTRA),
            prop::collection::vec(-3.0..3.0f64, n),
        )
            .prop_map(move |(mut values, logm)| {
                for (i, lm) in logm.iter().enumerate() {
                    values[i * PER_PARTICLE] = 10f64.powf(*lm);
                }
                RawParticles { n, values }
            })
    })
}

/// Seven exact integers (t, m, l, g, θ̇, θ̈, θ⃛): t and θ̇ nonzero, m, l, g positive.
pub fn exact_ladder_ints() -> impl Strategy<Value = [i64; 7]> {
    let big = 1i64 << 62;
    let nz = prop_oneof![-big..=-1i64, 1..=big];
    (
        nz.clone(),
        1..big,
        1..big,
        1..big,
        nz,
        -big..=big,
        -big..=big,
    )
        .prop_map(|(t, m, l, g, w, a, j)| [t, m, l, g, w, a, j])
}

/// Exact integers for a particle sample: (n, values), masses positive.
pub fn exact_particle_ints() -> impl Strategy<Value = (usize, Vec<i64>)> {
    let big = 1i64 << 62;
    (1usize..=8).prop_flat_map(move |n| {
        prop::collection::vec(-big..=big, n * PER_PARTICLE + EXTRA).prop_map(move |mut v| {
            for i in 0..n {
                v[i * PER_PARTICLE] =
                    v[i * PER_PARTICLE].unsigned_abs().max(1).min(big as u64) as i64;
            }
            (n, v)
        })
    })
}

/// A fresh empty directory `ladder-{tag}-{pid}-{name}` under the system temp directory.
pub fn tmp_dir(tag: &str, name: &str) -> PathBuf {
    let d = std::env::temp_dir().join(format!("ladder-{tag}-{}-{name}", std::process::id()));
    let _ = std::fs::remove_dir_all(&d);
    std::fs::create_dir_all(&d).unwrap();
    d
}

/// Copy the folder `from` into `to`, subfolders included (`to` is created).
pub fn copy_dir(from: &Path, to: &Path) {
    std::fs::create_dir_all(to).expect("a writable temp dir");
    for e in std::fs::read_dir(from)
        .expect("a readable folder")
        .flatten()
    {
        let (src, dst) = (e.path(), to.join(e.file_name()));
        if src.is_dir() {
            copy_dir(&src, &dst);
        } else {
            std::fs::copy(&src, &dst).expect("copy");
        }
    }
}

/// The registered display numbered `n` (the note's (1)-(90) or an extension's).
pub fn equation(n: u32) -> sliding_ladder::registry::Equation {
    sliding_ladder::registry::equations()
        .into_iter()
        .find(|e| e.number == n)
        .expect("registered")
}

/// A fresh copy of the crate's `equations/` (with its figures), `ladder-{tag}-{pid}-equations`
/// under the system temp directory: a folder to edit and hand to `--equations`.
pub fn copy_of_equations(tag: &str) -> PathBuf {
    let dir = tmp_dir(tag, "equations");
    copy_dir(&sliding_ladder::docs::default_dir(), &dir);
    dir
}

/// What one `ladder simulate` run produced.
pub struct SimRun {
    /// Exit code (-1 when killed by a signal).
    pub code: i32,
    /// Standard output.
    pub stdout: String,
    /// Standard error.
    pub stderr: String,
    /// Number of files written to the output directory.
    pub files: usize,
}

/// `ladder simulate SCENE EXTRA.. --out DIR` on scene `text` (no scene file at all when `None`),
/// in a temporary directory from [`tmp_dir`] that is removed afterwards.
pub fn simulate_scene(tag: &str, name: &str, text: Option<&str>, extra: &[&str]) -> SimRun {
    let dir = tmp_dir(tag, name);
    let scene = dir.join("scene.toml");
    if let Some(t) = text {
        std::fs::write(&scene, t).unwrap();
    }
    let out = dir.join("out");
    let o = Command::new(env!("CARGO_BIN_EXE_ladder"))
        .arg("simulate")
        .arg(&scene)
        .args(extra)
        .arg("--out")
        .arg(&out)
        .output()
        .unwrap();
    let files = std::fs::read_dir(&out).map_or(0, |d| d.count());
    let _ = std::fs::remove_dir_all(&dir);
    SimRun {
        code: o.status.code().unwrap_or(-1),
        stdout: String::from_utf8_lossy(&o.stdout).into_owned(),
        stderr: String::from_utf8_lossy(&o.stderr).into_owned(),
        files,
    }
}

/// `base` with its first occurrence of `line` replaced by `replacement` (`line` must occur).
pub fn replace_line(base: &str, line: &str, replacement: &str) -> String {
    assert!(base.contains(line), "{line} not in the scene");
    base.replacen(line, replacement, 1)
}

/// [`BASE`] with its first occurrence of `line` replaced by `replacement`.
pub fn with(line: &str, replacement: &str) -> String {
    replace_line(BASE, line, replacement)
}

/// `base` with each `(line, replacement)` applied in turn by [`replace_line`].
pub fn edited(base: &str, edits: &[(&str, &str)]) -> String {
    edits.iter().fold(base.to_string(), |text, (line, new)| {
        replace_line(&text, line, new)
    })
}

/// The `[ladder]` and `[start]` sections of the test scenes (lines 1-7): m = l = 1 kg, m,
/// g = 9.81 m/s², θ0 = 0.3 from rest.
macro_rules! ladder_and_start {
    () => {
        "[ladder]\nmass = 1.0\nhalf_length = 1.0\ngravity = 9.81\n[start]\nangle = 0.3\nangular_velocity = 0.0\n"
    };
}

/// The valid rigid scene the bad-input tests edit. Lines: 1 [ladder], 2 mass, 3 half_length,
/// 4 gravity, 5 [start], 6 angle, 7 angular_velocity, 8 [contact], 9 model, 10 [integrator],
/// 11 method, 12 tolerance, 13 [end], 14 at, 15 [outputs], 16 want.
pub const BASE: &str = concat!(
    ladder_and_start!(),
    "[contact]\nmodel = \"rigid\"\n",
    "[integrator]\nmethod = \"dop853\"\ntolerance = 1e-12\n",
    "[end]\nat = \"separation\"\n",
    "[outputs]\nwant = [\"separation_angle\", \"trajectory\"]\n"
);

/// A valid penalty scene (κ = k l/(m g) = 1e6, radau5). Lines: 1-7 as [`BASE`], 8 [contact],
/// 9 model, 10 stiffness, 11 damping, 12 [integrator], 13 method, 14 tolerance, 15 [end], 16 at,
/// 17 [outputs], 18 want.
pub const PENALTY: &str = concat!(
    ladder_and_start!(),
    "[contact]\nmodel = \"penalty\"\nstiffness = 9.81e6\ndamping = 0.0\n",
    "[integrator]\nmethod = \"radau5\"\ntolerance = 1e-10\n",
    "[end]\nat = \"separation\"\n",
    "[outputs]\nwant = [\"separation_angle\", \"separation_time\"]\n"
);

/// Assert that a `ladder simulate` run refused a bad scene as the project promises: exit 2,
/// one line on stderr naming `scene.toml`, the line (when given), the field as `[section] key`
/// (or `[section]`) and `words` of the message; nothing on stdout and no file written.
pub fn assert_refused(case: &str, run: &SimRun, line: Option<usize>, field: &str, words: &str) {
    let (code, err) = (run.code, &run.stderr);
    assert_eq!(code, 2, "{case}: exit {code}, stderr {err}");
    assert_eq!(err.trim_end().lines().count(), 1, "{case}: {err}");
    assert!(err.contains("scene.toml"), "{case}: no file name in {err}");
    if let Some(l) = line {
        assert!(
            err.contains(&format!("scene.toml:{l}: ")),
            "{case}: line {l} not in {err}"
        );
    }
    // Fields are shown as `[section] key` (or `[section]`).
    let place = match field.split_once('.') {
        Some((section, key)) => format!("[{section}] {key}"),
        None => field.to_string(),
    };
    assert!(err.contains(&place), "{case}: field {place} not in {err}");
    assert!(err.contains(words), "{case}: '{words}' not in {err}");
    assert!(run.stdout.is_empty(), "{case}: stdout {}", run.stdout);
    assert_eq!(run.files, 0, "{case}: output written");
}
