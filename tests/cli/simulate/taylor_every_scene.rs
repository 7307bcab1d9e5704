//! `ladder simulate` accepts `method = "taylor"` in every rigid scene (issue 13, "Done when"):
//! each shipped rigid scene and each other shape of start and end a rigid scene can take (a start
//! given from the floor, a subnormal push from upright, an end at a time) runs with the Taylor
//! method, exits 0, and agrees with DOP853 on the same scene (an independent method) within
//! what the two tolerances allow: each within a relative 100 tol of the motion (the tolerance
//! per step over fewer than 100 steps, the bound of `tests/sim/integrators/taylor/coefficients.rs`' comparison with the
//! exact reference), so within 200 tol of each other.

use serde_json::Value;

/// `text` with its `[integrator]` method line set to `method`.
fn with_method(text: &str, method: &str) -> String {
    let line = text
        .lines()
        .find(|l| l.trim_start().starts_with("method"))
        .expect("a method line");
    crate::common::replace_line(text, line, &format!("method = \"{method}\""))
}

/// The scene's tolerance (every rigid scene here gives one).
fn tolerance(text: &str) -> f64 {
    let line = text
        .lines()
        .find(|l| l.trim_start().starts_with("tolerance"))
        .expect("a tolerance line");
    let v = line.split('=').nth(1).unwrap();
    v.split('#').next().unwrap().trim().parse().unwrap()
}

/// `ladder simulate --json` on `text`: the parsed output, or a panic naming the case.
fn run(case: &str, text: &str) -> Value {
    let r = crate::common::simulate_scene("every-scene", case, Some(text), &["--json"]);
    assert_eq!(r.code, 0, "{case}: exit {}, stderr {}", r.code, r.stderr);
    serde_json::from_str(&r.stdout).unwrap_or_else(|e| panic!("{case}: {e}: {}", r.stdout))
}

/// The numbers both runs report (separation, flat, final state), by JSON path.
fn figures(v: &Value) -> Vec<(String, f64)> {
    let mut out = Vec::new();
    for (section, keys) in [
        ("separation", &["angle", "time", "rate"][..]),
        ("flat", &["time", "rate", "centre_x"][..]),
        ("final", &["angle", "rate", "time"][..]),
    ] {
        for k in keys {
            if let Some(x) = v[section][k].as_f64() {
                out.push((format!("{section}.{k}"), x));
            }
        }
    }
    out
}

/// Run `text` with the Taylor method and with DOP853 and compare every figure both report.
fn agrees_with_dop853(case: &str, text: &str) {
    let tol = tolerance(text);
    let taylor = run(case, &with_method(text, "taylor"));
    let dop853 = run(case, &with_method(text, "dop853"));
    let (a, b) = (figures(&taylor), figures(&dop853));
    assert!(!a.is_empty(), "{case}: nothing to compare in {taylor}");
    assert_eq!(
        a.iter().map(|f| &f.0).collect::<Vec<_>>(),
        b.iter().map(|f| &f.0).collect::<Vec<_>>(),
        "{case}"
    );
    for ((name, x), (_, y)) in a.iter().zip(&b) {
        let rel = (x - y).abs() / y.abs().max(f64::MIN_POSITIVE);
        println!("{case}: {name} taylor {x:e} dop853 {y:e} ({rel:.1e})");
        assert!(
            rel <= 200.0 * tol,
            "{case}: {name} {x:e} against {y:e} ({rel:e})"
        );
    }
}

#[test]
fn every_shipped_rigid_scene_runs_with_the_taylor_method() {
    let mut rigid = 0;
    for entry in std::fs::read_dir("scenes").unwrap() {
        let path = entry.unwrap().path();
        let text = std::fs::read_to_string(&path).unwrap();
        if !text.contains("model = \"rigid\"") {
            continue;
        }
        rigid += 1;
        let name = path.file_stem().unwrap().to_string_lossy().into_owned();
        agrees_with_dop853(&name, &text);
    }
    assert!(rigid >= 6, "only {rigid} rigid scenes found");
}

#[test]
fn every_other_shape_of_rigid_scene_runs_with_the_taylor_method() {
    let base = crate::common::BASE;
    let cases = [
        // A start given from the floor (the wall phase in the complement), to flat.
        (
            "from-floor",
            crate::common::edited(
                base,
                &[
                    ("angle = 0.3", "angle_from_floor = 1e-6"),
                    ("at = \"separation\"", "at = \"flat\""),
                    (
                        "want = [\"separation_angle\", \"trajectory\"]",
                        "want = [\"separation_angle\", \"flat_time\", \"flat_state\", \"final_state\"]",
                    ),
                ],
            ),
        ),
        // Upright with a subnormal push (the linear lead-in before the integrator starts).
        (
            "subnormal-push",
            crate::common::edited(
                base,
                &[
                    ("angle = 0.3", "angle = 0.0"),
                    ("angular_velocity = 0.0", "angular_velocity = 1e-310"),
                ],
            ),
        ),
        // An end at a time inside the wall phase, and one past the separation.
        (
            "end-at-time",
            crate::common::edited(
                base,
                &[
                    ("at = \"separation\"", "at = \"time\"\ntime = 0.4"),
                    (
                        "want = [\"separation_angle\", \"trajectory\"]",
                        "want = [\"final_state\", \"forces\"]",
                    ),
                ],
            ),
        ),
        (
            "end-after-separation",
            crate::common::edited(
                base,
                &[
                    ("at = \"separation\"", "at = \"time\"\ntime = 0.8"),
                    (
                        "want = [\"separation_angle\", \"trajectory\"]",
                        "want = [\"separation_angle\", \"final_state\", \"momentum_error\"]",
                    ),
                ],
            ),
        ),
    ];
    for (case, text) in &cases {
        agrees_with_dop853(case, text);
    }
}

/// The comparison is not blind: another start (0.3 → 0.30001) moves the figures past its bound.
#[test]
fn a_different_scene_fails_the_comparison() {
    let other = crate::common::replace_line(crate::common::BASE, "angle = 0.3", "angle = 0.30001");
    let (a, b) = (
        figures(&run("a", &with_method(crate::common::BASE, "taylor"))),
        figures(&run("b", &with_method(&other, "dop853"))),
    );
    let worst = a
        .iter()
        .zip(&b)
        .map(|((_, x), (_, y))| (x - y).abs() / y.abs())
        .fold(0.0, f64::max);
    assert!(worst > 200.0 * tolerance(crate::common::BASE), "{worst:e}");
}
