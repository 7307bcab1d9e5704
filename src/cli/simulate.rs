//! `ladder simulate SCENE`: run a scene and print (or write) the outputs it asks for. Exit
//! codes: 0 all good, 1 a check failed (e.g. lift-off) or the run stopped short of the end the
//! scene asks for (the step limit included; stderr says why and the JSON has `incomplete`),
//! 2 bad input or a request the run cannot meet (one line on stderr, nothing written).

use crate::report::files::write_all;
use crate::report::outcome::{files, lying_flat_note, summary, to_json};
use crate::sim::fall;
use crate::sim::outcome::{top_inside_wall, unreached_end};
use crate::sim::run::RunError;
use crate::sim::scene;
use clap::Args;
use serde_json::{json, Value};
use std::path::{Path, PathBuf};
use std::process::ExitCode;

/// The options of `ladder simulate`.
#[derive(Args)]
pub struct SimulateArgs {
    /// The scene file.
    scene: PathBuf,
    /// Print JSON instead of a summary.
    #[arg(long)]
    json: bool,
    /// Write CSV and SVG files here (when the scene asks for a trajectory or forces).
    #[arg(long)]
    out: Option<PathBuf>,
}

/// Run `ladder simulate` with its options.
pub fn run(a: SimulateArgs) -> ExitCode {
    simulate(&a.scene, a.json, a.out.as_deref())
}

/// `ladder simulate SCENE [--json] [--out DIR]`.
pub fn simulate(scene_path: &Path, json: bool, out: Option<&Path>) -> ExitCode {
    let scene = match scene::load(scene_path) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    let outcome = match fall::run(&scene, fall::MAX_STEPS) {
        Ok(o) => o,
        Err(e) => {
            eprintln!("error: {}: {e}", scene.file);
            if json && matches!(e, RunError::TooManySteps { .. }) {
                let v = json!({ "incomplete": e.to_string() });
                println!("{}", serde_json::to_string_pretty(&v).unwrap_or_default());
            }
            return ExitCode::from(run_error_code(&e));
        }
    };
    // A run past flat went on lying flat after the top's impact (`sim::impact`): never silently.
    if let Some(why) = lying_flat_note(&outcome) {
        eprintln!("note: {}: {why}", scene.file);
    }
    // A run that stops short of the end the scene asked for must say so (exit 1, stderr, JSON).
    let short = unreached_end(&scene, &outcome);
    if let Some(why) = &short {
        eprintln!("error: {}: {why}", scene.file);
    }
    // A floor phase whose top went through the wall is not the model's motion (exit 1).
    let inside = outcome
        .floor_report
        .and_then(|r| top_inside_wall(&r, scene.ladder.l));
    if let Some(why) = &inside {
        eprintln!("error: {}: {why}", scene.file);
    }
    if let Some(dir) = out {
        if let Err(e) = write_all(dir, &files(&scene, &outcome)) {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    }
    if json {
        let mut v = to_json(&scene, &outcome);
        if let (Some(why), Value::Object(m)) = (&short, &mut v) {
            m.insert("incomplete".into(), json!(why));
        }
        if let (Some(why), Value::Object(m)) = (&inside, &mut v) {
            m.insert("failed".into(), json!(why));
        }
        println!("{}", serde_json::to_string_pretty(&v).unwrap_or_default());
    } else {
        print!("{}", summary(&scene, &outcome));
    }
    if short.is_some() || inside.is_some() {
        return ExitCode::from(1);
    }
    ExitCode::SUCCESS
}

/// The exit code of a run that stopped with `e`: lift-off is a failed check and the step limit a
/// run that stopped short of its end (1, as `unreached_end`; the JSON says `incomplete`); the
/// rest is a request the run cannot meet (2), e.g. a penalty contact it did not resolve.
pub fn run_error_code(e: &RunError) -> u8 {
    match e {
        RunError::LiftOff { .. } | RunError::TooManySteps { .. } => 1,
        RunError::Step(_) | RunError::Start(_) => 2,
    }
}

/// The note's own problem, built in (so `ladder` with no arguments needs no file): the ladder
/// upright with a tiny push, simulated to the moment it leaves the wall.
pub fn simulate_builtin_classic() -> ExitCode {
    let scene = match scene::parse(
        "built-in scenes/classic.toml",
        include_str!("../../scenes/classic.toml"),
    ) {
        Ok(s) => s,
        Err(e) => {
            eprintln!("error: {e}");
            return ExitCode::from(2);
        }
    };
    match fall::run(&scene, fall::MAX_STEPS) {
        Ok(o) => {
            print!("{}", summary(&scene, &o));
            ExitCode::SUCCESS
        }
        Err(e) => {
            eprintln!("error: {}: {e}", scene.file);
            ExitCode::from(1)
        }
    }
}
