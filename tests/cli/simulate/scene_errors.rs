//! Every kind of bad scene: exit code 2, one line on stderr naming the file, the line and the
//! field, and no output file written. Plus: random and mutated scene text never panics.

use crate::common::{with, BASE, PENALTY};
use proptest::prelude::*;

/// Run `ladder simulate` on `text`; returns (exit code, stderr, files in the out dir).
fn simulate(name: &str, text: Option<&str>) -> (i32, String, usize) {
    let run = crate::common::simulate_scene("cli", name, text, &[]);
    (run.code, run.stderr, run.files)
}

#[test]
fn the_base_scene_is_valid_and_writes_files() {
    let (code, err, files) = simulate("base", Some(BASE));
    assert_eq!(code, 0, "{err}");
    assert_eq!(files, 2, "trajectory.csv and trajectory.svg");
}

#[test]
fn every_bad_scene_gets_one_line_exit_2_and_no_file() {
    // (case, scene text, expected line, field, words of the message)
    let cases: Vec<(&str, String, Option<usize>, &str, &str)> = vec![
        (
            "syntax",
            with("mass = 1.0", "mass = = 1.0"),
            Some(2),
            "ladder.mass",
            "",
        ),
        (
            "unknown key",
            with("gravity = 9.81", "gravity = 9.81\ncolour = 1"),
            Some(5),
            "ladder",
            "unknown key",
        ),
        (
            "wrong type",
            with("mass = 1.0", "mass = \"heavy\""),
            Some(2),
            "ladder.mass",
            "wrong type",
        ),
        (
            "nan",
            with("mass = 1.0", "mass = nan"),
            Some(2),
            "ladder.mass",
            "not a finite",
        ),
        (
            "inf",
            with("gravity = 9.81", "gravity = inf"),
            Some(4),
            "ladder.gravity",
            "not a finite",
        ),
        (
            "zero mass",
            with("mass = 1.0", "mass = 0.0"),
            Some(2),
            "ladder.mass",
            "> 0",
        ),
        (
            "negative length",
            with("half_length = 1.0", "half_length = -2"),
            Some(3),
            "ladder.half_length",
            "> 0",
        ),
        (
            "zero gravity",
            with("gravity = 9.81", "gravity = 0"),
            Some(4),
            "ladder.gravity",
            "> 0",
        ),
        (
            "angle too big",
            with("angle = 0.3", "angle = 1.6"),
            Some(6),
            "start.angle",
            "[0, π/2)",
        ),
        (
            "angle negative",
            with("angle = 0.3", "angle = -0.1"),
            Some(6),
            "start.angle",
            "[0, π/2)",
        ),
        (
            "rate negative",
            with("angular_velocity = 0.0", "angular_velocity = -1"),
            Some(7),
            "start.angular_velocity",
            ">= 0",
        ),
        (
            "rate too fast for the penalty model",
            PENALTY.replace("angular_velocity = 0.0", "angular_velocity = 100"),
            Some(7),
            "start.angular_velocity",
            "too fast",
        ),
        (
            "equilibrium",
            with("angle = 0.3", "angle = 0.0"),
            Some(6),
            "start",
            "equilibrium",
        ),
        (
            "unknown contact",
            with("model = \"rigid\"", "model = \"glue\""),
            Some(9),
            "contact.model",
            "allowed: \"rigid\", \"penalty\"",
        ),
        (
            "stiffness on rigid",
            with("model = \"rigid\"", "model = \"rigid\"\nstiffness = 1e8"),
            Some(10),
            "contact.stiffness",
            "penalty",
        ),
        (
            "bad stiffness",
            with("model = \"rigid\"", "model = \"penalty\"\nstiffness = -1"),
            Some(10),
            "contact.stiffness",
            "> 0",
        ),
        (
            "bad damping",
            with(
                "model = \"rigid\"",
                "model = \"penalty\"\nstiffness = 1e8\ndamping = -3",
            ),
            Some(11),
            "contact.damping",
            ">= 0",
        ),
        (
            "unknown method",
            with("method = \"dop853\"", "method = \"rk45\""),
            Some(11),
            "integrator.method",
            "allowed: euler",
        ),
        (
            "zero tolerance",
            with("tolerance = 1e-12", "tolerance = 0"),
            Some(12),
            "integrator.tolerance",
            "[1e-16, 0.1]",
        ),
        (
            "negative tolerance",
            with("tolerance = 1e-12", "tolerance = -1e-6"),
            Some(12),
            "integrator.tolerance",
            "[1e-16, 0.1]",
        ),
        (
            "tiny tolerance",
            with("tolerance = 1e-12", "tolerance = 1e-30"),
            Some(12),
            "integrator.tolerance",
            "[1e-16, 0.1]",
        ),
        (
            "step for adaptive",
            with("tolerance = 1e-12", "step = 1e-3"),
            Some(12),
            "integrator.step",
            "tolerance",
        ),
        (
            "zero step",
            with(
                "method = \"dop853\"\ntolerance = 1e-12",
                "method = \"rk4\"\nstep = 0",
            ),
            Some(12),
            "integrator.step",
            "[1e-6, 1]",
        ),
        (
            "tiny step",
            with(
                "method = \"dop853\"\ntolerance = 1e-12",
                "method = \"rk4\"\nstep = 1e-12",
            ),
            Some(12),
            "integrator.step",
            "[1e-6, 1]",
        ),
        (
            "unknown end",
            with("at = \"separation\"", "at = \"never\""),
            Some(14),
            "end.at",
            "allowed",
        ),
        (
            "zero end time",
            with("at = \"separation\"", "at = \"time\"\ntime = 0"),
            Some(15),
            "end.time",
            "(0, 1e4]",
        ),
        (
            "negative end time",
            with("at = \"separation\"", "at = \"time\"\ntime = -2"),
            Some(15),
            "end.time",
            "(0, 1e4]",
        ),
        (
            "time missing",
            with("at = \"separation\"", "at = \"time\""),
            Some(14),
            "end.time",
            "at = \"time\" needs it",
        ),
        (
            "unknown output",
            with("\"trajectory\"]", "\"colour\"]"),
            Some(16),
            "outputs.want",
            "unknown output",
        ),
        (
            "output not producible",
            with("\"trajectory\"]", "\"flat_time\"]"),
            Some(16),
            "outputs.want",
            "end.at = \"flat\"",
        ),
        (
            "floor_force_min at separation",
            with("\"trajectory\"]", "\"floor_force_min\"]"),
            Some(16),
            "outputs.want",
            "belongs to the floor phase",
        ),
        (
            "top_clearance_min at separation",
            with("\"trajectory\"]", "\"top_clearance_min\"]"),
            Some(16),
            "outputs.want",
            "belongs to the floor phase",
        ),
        (
            "momentum_error at separation",
            with("\"trajectory\"]", "\"momentum_error\"]"),
            Some(16),
            "outputs.want",
            "belongs to the floor phase",
        ),
        (
            "flat output at a time",
            with("\"trajectory\"]", "\"flat_time\"]")
                .replace("at = \"separation\"", "at = \"time\"\ntime = 2.0"),
            Some(17),
            "outputs.want",
            "needs end.at = \"flat\"",
        ),
        (
            "exact with trajectory",
            with(
                "method = \"dop853\"\ntolerance = 1e-12",
                "method = \"exact\"",
            ),
            Some(15),
            "outputs.want",
            "exact",
        ),
        (
            "missing section",
            BASE.replace("[end]\nat = \"separation\"\n", ""),
            Some(13),
            "[end]",
            "missing section",
        ),
    ];
    for (case, text, line, field, words) in cases {
        let run = crate::common::simulate_scene("cli", &case.replace(' ', "-"), Some(&text), &[]);
        crate::common::assert_refused(case, &run, line, field, words);
    }
}

#[test]
fn a_missing_file_is_bad_input() {
    let (code, err, files) = simulate("missing", None);
    assert_eq!(code, 2);
    assert!(
        err.contains("scene.toml") && err.contains("cannot read"),
        "{err}"
    );
    assert_eq!(files, 0);
}

fn mutate(text: &str, pos: usize, byte: u8, delete: bool) -> String {
    let mut b = text.as_bytes().to_vec();
    let p = pos % (b.len() + 1);
    if delete && p < b.len() {
        b.remove(p);
    } else {
        b.insert(p, byte);
    }
    String::from_utf8_lossy(&b).into_owned()
}

proptest! {
    #![proptest_config(ProptestConfig::with_cases(400))]
    /// Random text and single-byte mutations of a valid scene never panic; a valid result runs
    /// (with a small step limit) without panicking either.
    #[test]
    fn scene_parsing_never_panics(pos in 0usize..400, byte in any::<u8>(), delete in any::<bool>(), junk in ".{0,60}") {
        for text in [mutate(BASE, pos, byte, delete), junk.clone(), format!("{BASE}{junk}")] {
            if let Ok(scene) = sliding_ladder::sim::scene::parse("p.toml", &text) {
                let _ = sliding_ladder::sim::fall::run(&scene, 20_000);
            }
        }
    }

    /// Numbers of any value in any numeric field: an error or a run, never a panic or a NaN.
    #[test]
    fn any_number_in_any_field(field in 0usize..6, x in prop_oneof![any::<f64>(), -10.0..10.0f64]) {
        let keys = ["mass = 1.0", "half_length = 1.0", "gravity = 9.81", "angle = 0.3", "angular_velocity = 0.0", "tolerance = 1e-12"];
        let key = keys[field].split(" = ").next().unwrap();
        let v = if x.is_nan() { "nan".to_string() } else if x.is_infinite() { if x > 0.0 { "inf".into() } else { "-inf".into() } } else { format!("{x:e}") };
        let text = BASE.replacen(keys[field], &format!("{key} = {v}"), 1);
        if let Ok(scene) = sliding_ladder::sim::scene::parse("p.toml", &text) {
            if let Ok(o) = sliding_ladder::sim::fall::run(&scene, 20_000) {
                if let Some(s) = o.separation {
                    prop_assert!(s.angle.is_finite() && s.time.is_finite() && s.rate.is_finite());
                }
            }
        }
    }
}
