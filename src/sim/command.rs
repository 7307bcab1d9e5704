//! What the `ladder` command calls: `simulate` and `work-precision`. Exit codes: 0 all good,
//! 1 a check failed (e.g. lift-off), 2 bad input (one line on stderr, nothing written).

use super::fall::{self, Outcome};
use super::output::Output;
use super::penalty::Contact;
use super::rigid::separation_cosine;
use super::run::RunError;
use super::scene::{self, ContactModel, Scene};
use crate::report::files::{write_all, OutFile};
use serde_json::{json, Map, Value};
use std::path::Path;
use std::process::ExitCode;

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
            return ExitCode::from(match e {
                RunError::LiftOff { .. } => 1,
                _ => 2,
            });
        }
    };
    // A run that stops short of the end the scene asked for must say so (exit 1, stderr, JSON).
    let short = unreached_end(&scene, &outcome);
    if let Some(why) = &short {
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
        println!("{}", serde_json::to_string_pretty(&v).unwrap_or_default());
    } else {
        print!("{}", summary(&scene, &outcome));
    }
    if short.is_some() {
        return ExitCode::from(1);
    }
    ExitCode::SUCCESS
}

/// Why the run did not reach the end the scene asked for (separation or flat), if it did not.
pub fn unreached_end(scene: &Scene, o: &Outcome) -> Option<String> {
    let missing = match scene.end {
        scene::End::Separation if o.separation.is_none() => "the separation",
        scene::End::Flat if o.separation.is_none() => "the separation (and so flat)",
        scene::End::Flat if o.flat.is_none() => "flat",
        _ => return None,
    };
    Some(format!(
        "the run stopped at t = {} s, θ = {} rad without reaching {missing}, the end the scene asks for",
        o.last.0, o.last.1
    ))
}

pub use crate::report::work_precision::command as work_precision;

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

fn insert(map: &mut Map<String, Value>, path: &str, v: Value) {
    let (head, rest) = path.split_once('.').unwrap_or((path, ""));
    if rest.is_empty() {
        map.insert(head.into(), v);
    } else if let Value::Object(m) = map.entry(head).or_insert_with(|| json!({})) {
        insert(m, rest, v);
    }
}

/// A number for JSON: non-finite values become null rather than invalid JSON.
fn num(x: f64) -> Value {
    if x.is_finite() {
        json!(x)
    } else {
        Value::Null
    }
}

/// The JSON object of the outputs the scene asked for (`separation.angle`, `flat.time`, ...).
pub fn to_json(scene: &Scene, o: &Outcome) -> Value {
    let mut m = Map::new();
    let sep = o.separation;
    for out in &scene.outputs {
        match out {
            Output::SeparationAngle => insert(
                &mut m,
                "separation.angle",
                sep.map_or(Value::Null, |s| num(s.angle)),
            ),
            Output::SeparationTime => insert(
                &mut m,
                "separation.time",
                sep.map_or(Value::Null, |s| num(s.time)),
            ),
            Output::SeparationRate => insert(
                &mut m,
                "separation.rate",
                sep.map_or(Value::Null, |s| num(s.rate)),
            ),
            Output::FlatTime => insert(
                &mut m,
                "flat.time",
                o.flat.map_or(Value::Null, |f| num(f.time)),
            ),
            Output::FlatState => {
                if let Some(f) = o.flat {
                    insert(&mut m, "flat.rate", num(f.rate));
                    insert(&mut m, "flat.centre_x", num(f.centre_x));
                    insert(&mut m, "flat.centre_velocity_x", num(f.centre_velocity_x));
                    insert(&mut m, "flat.centre_velocity_y", num(f.centre_velocity_y));
                }
            }
            Output::FloorForceMin => insert(
                &mut m,
                "floor_phase.floor_force_min",
                o.floor_report
                    .map_or(Value::Null, |r| num(r.floor_force_min)),
            ),
            Output::TopClearanceMin => {
                let v = o
                    .floor_report
                    .map_or(Value::Null, |r| num(r.top_clearance_min));
                insert(&mut m, "floor_phase.top_clearance_min", v);
            }
            Output::MomentumError => insert(
                &mut m,
                "floor_phase.momentum_error",
                o.momentum_error.map_or(Value::Null, num),
            ),
            Output::EnergyError => insert(
                &mut m,
                "energy_error",
                o.energy_error.map_or(Value::Null, num),
            ),
            Output::FinalState => {
                insert(&mut m, "final.time", num(o.last.0));
                insert(&mut m, "final.angle", num(o.last.1));
                insert(&mut m, "final.rate", num(o.last.2));
            }
            Output::RhsEvals => {
                let w = &o.work;
                let floor = w.floor.map_or(0, |s| s.rhs_evals);
                insert(&mut m, "work.rhs_evals", json!(w.wall.rhs_evals + floor));
                insert(
                    &mut m,
                    "work.steps",
                    json!(w.wall.steps + w.floor.map_or(0, |s| s.steps)),
                );
                insert(&mut m, "work.force_evals", json!(w.force_evals));
            }
            Output::Trajectory | Output::Forces => {
                insert(
                    &mut m,
                    &format!("{}.samples", out.name()),
                    json!(o.work.stored_samples),
                );
            }
        }
    }
    Value::Object(m)
}

/// The human-readable summary, ending with what was computed.
pub fn summary(scene: &Scene, o: &Outcome) -> String {
    let mut s = format!(
        "scene {}: θ0 = {} rad, θ̇0 = {} rad/s, method {}\n",
        scene.file, scene.theta0, scene.rate0, scene.method
    );
    if let ContactModel::Penalty { stiffness, damping } = scene.contact {
        let c = Contact::from_dimensional(&scene.ladder, stiffness, damping);
        s += &format!(
            "  contact      penalty springs: k l/(m g) = {:e}, c √(l/g)/m = {:e} (the separation approaches the rigid one as k grows)\n",
            c.kappa, c.gamma
        );
    }
    match o.separation {
        Some(p) => s += &format!(
            "  separation   t = {:.15} s   θ = {:.15} rad ({:.6}°)   θ̇ = {:.12} rad/s\n               cos θ = {:.15} (predicted by the energy integral: {:.15})\n",
            p.time,
            p.angle,
            p.angle.to_degrees(),
            p.rate,
            p.angle.cos(),
            separation_cosine(scene.ladder.omega2(), scene.theta0, scene.rate0)
        ),
        None => s += "  separation   not reached\n",
    }
    if let Some(f) = o.flat {
        s += &format!(
            "  flat         t = {:.15} s   θ̇ = {:.12} rad/s   centre x = {:.12} m, ẋ = {:.12} m/s, ẏ = {:.12} m/s\n",
            f.time, f.rate, f.centre_x, f.centre_velocity_x, f.centre_velocity_y
        );
    }
    if let Some(r) = o.floor_report {
        s += &format!(
            "  floor phase  min F_f = {:.9} N (> 0: no lift-off)   min top clearance = {:.3e} m ({})\n",
            r.floor_force_min,
            r.top_clearance_min,
            if r.top_clearance_min >= 0.0 { "the top never returns to the wall" } else { "TOP BACK AT THE WALL" }
        );
    }
    if let Some(e) = o.momentum_error {
        s += &format!("  momentum     |Δp_x| / |p_x| over the floor phase = {e:.3e}\n");
    }
    if let Some(e) = o.energy_error {
        s += &format!("  energy       |ΔE| / (m g l) = {e:.3e}\n");
    }
    s += &format!(
        "  end          t = {:.15} s   θ = {:.15} rad   θ̇ = {:.12} rad/s\n",
        o.last.0, o.last.1, o.last.2
    );
    let w = &o.work;
    let p = &o.plan;
    s += &format!(
        "computed: wall phase ({} steps, {} rhs){}; force evaluations {}; samples kept {}; energy {}\n",
        w.wall.steps,
        w.wall.rhs_evals,
        w.floor.map_or(" - floor phase not built".to_string(), |f| format!(", floor phase ({} steps, {} rhs)", f.steps, f.rhs_evals)),
        w.force_evals,
        w.stored_samples,
        if p.energy { "at the ends" } else { "not evaluated" }
    );
    s
}

/// The files `--out` writes for this scene (CSV and SVG for a trajectory and forces).
pub fn files(scene: &Scene, o: &Outcome) -> Vec<OutFile> {
    crate::report::fall_figures::files(scene, o)
}
