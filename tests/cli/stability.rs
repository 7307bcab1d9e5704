//! The command line of the stiff and extreme work: bad penalty scenes (exit 2, one line naming
//! file, line and field, nothing written), the shipped penalty scene, extreme-scale scenes, and
//! `ladder stability --json`.

use crate::common::{replace_line as with, PENALTY};
use serde_json::Value;
use sliding_ladder::cli::stability::surprise_line;
use sliding_ladder::report::stability::case::{blank, Case, Expect, Verdict};
use std::process::Command;

/// `ladder simulate SCENE --json --out DIR` on `text`: (exit code, stdout, stderr, files).
fn simulate(name: &str, text: &str) -> (i32, String, String, usize) {
    let run = crate::common::simulate_scene("stab", name, Some(text), &["--json"]);
    (run.code, run.stdout, run.stderr, run.files)
}

#[test]
fn the_penalty_scene_runs_and_lands_near_the_rigid_angle() {
    let (code, out, err, _) = simulate("ok", PENALTY);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&out).unwrap();
    let angle = v["separation"]["angle"].as_f64().unwrap();
    // κ = k l/(m g) = 1e6: within 10/κ of footnote 4's arccos((2/3) cos 0.3).
    let rigid = (2.0 / 3.0 * 0.3f64.cos()).acos();
    assert!((angle - rigid).abs() < 10.0 / 1e6, "{angle}");
    let shipped = Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args([
            "simulate",
            concat!(env!("CARGO_MANIFEST_DIR"), "/scenes/penalty.toml"),
        ])
        .output()
        .unwrap();
    assert!(shipped.status.success(), "{shipped:?}");
}

#[test]
fn every_bad_penalty_scene_gets_one_line_exit_2_and_no_file() {
    let rigid = with(
        PENALTY,
        "model = \"penalty\"\nstiffness = 9.81e6\ndamping = 0.0",
        "model = \"rigid\"",
    );
    // (case, text, line, field, words)
    let cases: Vec<(&str, String, usize, &str, &str)> = vec![
        (
            "stiffness nan",
            with(PENALTY, "stiffness = 9.81e6", "stiffness = nan"),
            10,
            "contact.stiffness",
            "not a finite",
        ),
        (
            "stiffness inf",
            with(PENALTY, "stiffness = 9.81e6", "stiffness = inf"),
            10,
            "contact.stiffness",
            "not a finite",
        ),
        (
            "stiffness -inf",
            with(PENALTY, "stiffness = 9.81e6", "stiffness = -inf"),
            10,
            "contact.stiffness",
            "not a finite",
        ),
        (
            "stiffness zero",
            with(PENALTY, "stiffness = 9.81e6", "stiffness = 0.0"),
            10,
            "contact.stiffness",
            "> 0",
        ),
        (
            "stiffness negative",
            with(PENALTY, "stiffness = 9.81e6", "stiffness = -1e6"),
            10,
            "contact.stiffness",
            "> 0",
        ),
        (
            "stiffness text",
            with(PENALTY, "stiffness = 9.81e6", "stiffness = \"stiff\""),
            10,
            "contact.stiffness",
            "wrong type",
        ),
        (
            "stiffness missing",
            with(PENALTY, "stiffness = 9.81e6\n", ""),
            9,
            "contact.stiffness",
            "the penalty model needs it",
        ),
        (
            "kappa too large",
            with(PENALTY, "stiffness = 9.81e6", "stiffness = 1e300"),
            10,
            "contact.stiffness",
            "k l/(m g)",
        ),
        (
            "kappa too small",
            with(PENALTY, "stiffness = 9.81e6", "stiffness = 1e-3"),
            10,
            "contact.stiffness",
            "out of range",
        ),
        (
            "damping nan",
            with(PENALTY, "damping = 0.0", "damping = nan"),
            11,
            "contact.damping",
            "not a finite",
        ),
        (
            "damping inf",
            with(PENALTY, "damping = 0.0", "damping = inf"),
            11,
            "contact.damping",
            "not a finite",
        ),
        (
            "damping negative",
            with(PENALTY, "damping = 0.0", "damping = -2"),
            11,
            "contact.damping",
            ">= 0",
        ),
        // m = 1e-30 with k l/(m g) = 1e6: c √(l/g)/m overflows for c = 1e300.
        (
            "damping overflows",
            with(
                &with(PENALTY, "mass = 1.0", "mass = 1e-30")
                    .replace("stiffness = 9.81e6", "stiffness = 9.81e-24"),
                "damping = 0.0",
                "damping = 1e300",
            ),
            11,
            "contact.damping",
            "not a finite",
        ),
        (
            "stiffness for rigid",
            with(
                &rigid,
                "model = \"rigid\"",
                "model = \"rigid\"\nstiffness = 1e8",
            ),
            10,
            "contact.stiffness",
            "only for model = \"penalty\"",
        ),
        (
            "damping for rigid",
            with(
                &rigid,
                "model = \"rigid\"",
                "model = \"rigid\"\ndamping = 1.0",
            ),
            10,
            "contact.damping",
            "only for model = \"penalty\"",
        ),
        (
            "exact for penalty",
            with(
                PENALTY,
                "method = \"radau5\"\ntolerance = 1e-10",
                "method = \"exact\"",
            ),
            13,
            "integrator.method",
            "needs an integrator",
        ),
        (
            "penalty to flat",
            with(PENALTY, "at = \"separation\"", "at = \"flat\""),
            16,
            "end.at",
            "separation only",
        ),
        (
            "penalty trajectory",
            with(PENALTY, "\"separation_time\"]", "\"trajectory\"]"),
            18,
            "outputs.want",
            "not produced by the penalty model",
        ),
    ];
    for (case, text, line, field, words) in cases {
        let run = crate::common::simulate_scene("stab", case, Some(&text), &["--json"]);
        crate::common::assert_refused(case, &run, Some(line), field, words);
    }
}

/// A scene at (m, l, g) from rest with a push of 0.1 Ω: (θ_s, t_s, θ̇_s) from `simulate`.
fn separation_at(m: f64, l: f64, g: f64, contact: &str) -> [f64; 3] {
    let omega = (0.75 * g / l).sqrt();
    let text = with(
        PENALTY,
        "mass = 1.0\nhalf_length = 1.0\ngravity = 9.81",
        &format!("mass = {m:e}\nhalf_length = {l:e}\ngravity = {g:e}"),
    );
    let text = with(
        &text,
        "angular_velocity = 0.0",
        &format!("angular_velocity = {:e}", 0.1 * omega),
    );
    let text = with(
        &text,
        "model = \"penalty\"\nstiffness = 9.81e6\ndamping = 0.0",
        contact,
    );
    let text = with(
        &text,
        "method = \"radau5\"\ntolerance = 1e-10",
        "method = \"dop853\"\ntolerance = 1e-13",
    );
    let (code, out, err, _) = simulate("scale", &text);
    assert_eq!(code, 0, "{err}");
    let v: Value = serde_json::from_str(&out).unwrap();
    let s = &v["separation"];
    [
        s["angle"].as_f64().unwrap(),
        s["time"].as_f64().unwrap(),
        0.0,
    ]
}

#[test]
fn extreme_scale_scenes_give_the_unit_answers_scaled_to_1e_12() {
    let unit = separation_at(1.0, 1.0, 1.0, "model = \"rigid\"");
    for (m, l, g) in [
        (1e-30, 1e30, 1e-30),
        (1e30, 1e-30, 1e30),
        (1e30, 1e30, 1e30),
    ] {
        let s = separation_at(m, l, g, "model = \"rigid\"");
        let t_unit = (l / g).sqrt();
        assert!(
            ((s[0] - unit[0]) / unit[0]).abs() <= 1e-12,
            "{m} {l} {g}: angle {s:?} {unit:?}"
        );
        assert!(
            ((s[1] / t_unit - unit[1]) / unit[1]).abs() <= 1e-12,
            "{m} {l} {g}: time"
        );
        // The check can fail: time not scaled by √(l/g) is off by orders of magnitude.
        if l != g {
            assert!(((s[1] - unit[1]) / unit[1]).abs() > 0.5);
        }
    }
}

#[test]
fn stability_json_has_verdicts_for_five_stiffnesses_and_the_extreme_cases() {
    let o = Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args(["stability", "--json"])
        .output()
        .unwrap();
    assert_eq!(
        o.status.code(),
        Some(0),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    // Not a terminal: no progress bar anywhere.
    assert!(
        o.stderr.is_empty(),
        "{}",
        String::from_utf8_lossy(&o.stderr)
    );
    let v: Value = serde_json::from_slice(&o.stdout).unwrap();
    let cases = v["cases"].as_array().unwrap();
    for c in cases {
        for key in ["case", "method", "error", "verdict"] {
            assert!(c.get(key).is_some(), "{key} missing in {c}");
        }
        assert!(
            ["ok", "fail"].contains(&c["verdict"].as_str().unwrap()),
            "{c}"
        );
        if c["group"] == "stiff" {
            assert!(c["case"].as_str().unwrap().contains("penalty"), "{c}");
        }
    }
    let mut kappas: Vec<&str> = cases
        .iter()
        .filter(|c| c["case"].as_str().unwrap().starts_with("penalty κ="))
        .map(|c| c["case"].as_str().unwrap())
        .collect();
    kappas.dedup();
    assert!(kappas.len() >= 5, "{kappas:?}");
    // The implicit method passes at every stiffness; explicit ones fail visibly at the top.
    for c in cases.iter().filter(|c| c["group"] == "stiff") {
        let (m, verdict) = (
            c["method"].as_str().unwrap(),
            c["verdict"].as_str().unwrap(),
        );
        if m.starts_with("radau5") {
            assert_eq!(verdict, "ok", "{c}");
        }
        if c["case"] == "penalty κ=1e12" && !m.starts_with("radau5") {
            assert_eq!(verdict, "fail", "{c}");
            assert!(!c["reason"].as_str().unwrap().is_empty(), "{c}");
        }
    }
    let names: Vec<&str> = cases.iter().map(|c| c["case"].as_str().unwrap()).collect();
    for needle in [
        "rest θ0=1e-12",
        "π/2−1e-9",
        "θ0=0 θ̇0=1e-15",
        "θ0=0 θ̇0=2e0",
        "equilibrium",
        "m=1e30",
        "1e7 steps",
    ] {
        assert!(names.iter().any(|n| n.contains(needle)), "{needle} missing");
    }
    assert_eq!(v["surprises"], 0);
}

fn case(verdict: Verdict, expect: Expect) -> Case {
    Case {
        verdict,
        expect,
        ..blank(
            "extreme",
            "θ0=0 θ̇0=1e0·Ω: angle".into(),
            "dop853 1e-13".into(),
            String::new(),
        )
    }
}

/// Exit 1 always says why: a case whose verdict theory did not expect is named on stderr,
/// and a report as expected has no line.
#[test]
fn surprise_line_names_each_unexpected_case() {
    let fine = case(Verdict::Ok, Expect::Ok);
    assert_eq!(surprise_line(std::slice::from_ref(&fine)), None);
    let line = surprise_line(&[fine, case(Verdict::Fail, Expect::Ok)]).unwrap();
    assert!(
        line.starts_with("ladder stability: exit 1: 1 cases"),
        "{line}"
    );
    assert!(
        line.contains("extreme θ0=0 θ̇0=1e0·Ω: angle (dop853 1e-13)"),
        "{line}"
    );
}
