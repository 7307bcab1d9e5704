//! One run's outcome for the reader: the JSON object of the outputs a scene asked for and the
//! plain-text summary `ladder simulate` prints, and the files `--out` writes. Kept here, below
//! `cli`, so that the command only chooses what to print and the exit code, and the campaign and
//! the book's units page read the same values the command prints.

use super::digits::sig;
use super::files::OutFile;
use crate::sim::fall::Outcome;
use crate::sim::outcome::top_inside_wall;
use crate::sim::penalty::Contact;
use crate::sim::rigid::separation_cosine;
use crate::sim::scene::output::Output;
use crate::sim::scene::{ContactModel, Scene};
use serde_json::{json, Map, Value};

/// What a run that went on past flat did (`sim::impact`), for stderr and the JSON.
pub fn lying_flat_note(o: &Outcome) -> Option<String> {
    let sl = o.slide?;
    Some(format!(
        "the ladder lay flat at t = {} s, before the end time; its top struck the floor there, taken as a perfectly inelastic impact (no bounce; the frictionless floor gives no horizontal impulse), which took {} m g l of energy, and it slid on lying flat at ẋ = {} m/s to t = {} s (centre x = {} m)",
        sig(sl.impact_time, 16),
        sig(sl.energy_lost, 6),
        sig(sl.centre_velocity_x, 13),
        sig(o.last.0, 16),
        sig(sl.centre_x_end, 13)
    ))
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
    for out in &scene.outputs {
        insert_output(&mut m, out, o);
    }
    insert_lying_flat(&mut m, o);
    Value::Object(m)
}

/// The JSON fields of one output `out` of the run `o`; `null` for a result the run did not
/// reach.
fn insert_output(m: &mut Map<String, Value>, out: &Output, o: &Outcome) {
    let sep = o.separation;
    match out {
        Output::SeparationAngle => insert(
            m,
            "separation.angle",
            sep.map_or(Value::Null, |s| num(s.angle)),
        ),
        Output::SeparationTime => insert(
            m,
            "separation.time",
            sep.map_or(Value::Null, |s| num(s.time)),
        ),
        Output::SeparationRate => insert(
            m,
            "separation.rate",
            sep.map_or(Value::Null, |s| num(s.rate)),
        ),
        Output::FlatTime => insert(m, "flat.time", o.flat.map_or(Value::Null, |f| num(f.time))),
        Output::FlatState => insert_flat_state(m, o),
        Output::FloorForceMin => insert(
            m,
            "floor_phase.floor_force_min",
            o.floor_report
                .map_or(Value::Null, |r| num(r.floor_force_min)),
        ),
        Output::TopClearanceMin => {
            let v = o
                .floor_report
                .map_or(Value::Null, |r| num(r.top_clearance_min));
            insert(m, "floor_phase.top_clearance_min", v);
        }
        Output::MomentumError => insert(
            m,
            "floor_phase.momentum_error",
            o.momentum_error.map_or(Value::Null, num),
        ),
        Output::EnergyError => insert(m, "energy_error", o.energy_error.map_or(Value::Null, num)),
        Output::FinalState => insert_final_state(m, o),
        Output::RhsEvals => insert_work(m, o),
        Output::Trajectory | Output::Forces => {
            insert(
                m,
                &format!("{}.samples", out.name()),
                json!(o.work.stored_samples),
            );
        }
    }
}

/// `flat.*`: the state when the ladder lies flat, when it got there.
fn insert_flat_state(m: &mut Map<String, Value>, o: &Outcome) {
    if let Some(f) = o.flat {
        insert(m, "flat.rate", num(f.rate));
        insert(m, "flat.centre_x", num(f.centre_x));
        insert(m, "flat.centre_velocity_x", num(f.centre_velocity_x));
        insert(m, "flat.centre_velocity_y", num(f.centre_velocity_y));
    }
}

/// `final.*`: the time and state at the end.
fn insert_final_state(m: &mut Map<String, Value>, o: &Outcome) {
    insert(m, "final.time", num(o.last.0));
    insert(m, "final.angle", num(o.last.1));
    insert(m, "final.rate", num(o.last.2));
}

/// `work.*`: the evaluation counters of both phases.
fn insert_work(m: &mut Map<String, Value>, o: &Outcome) {
    let w = &o.work;
    let floor = w.floor.map_or(0, |s| s.rhs_evals);
    insert(m, "work.rhs_evals", json!(w.wall.rhs_evals + floor));
    insert(
        m,
        "work.steps",
        json!(w.wall.steps + w.floor.map_or(0, |s| s.steps)),
    );
    insert(m, "work.force_evals", json!(w.force_evals));
}

/// `lying_flat`: a run past flat went on lying flat (`sim::impact`); the JSON says how, never
/// silently.
fn insert_lying_flat(m: &mut Map<String, Value>, o: &Outcome) {
    if let Some(sl) = o.slide {
        m.insert(
            "lying_flat".into(),
            json!({
                "impact_time": num(sl.impact_time),
                "centre_velocity_x": num(sl.centre_velocity_x),
                "centre_x_end": num(sl.centre_x_end),
                "energy_lost": num(sl.energy_lost),
                "note": lying_flat_note(o),
            }),
        );
    }
}

/// The human-readable summary, ending with what was computed. Numbers by significant digits
/// ([`crate::report::digits`]): fixed decimals print a slow ladder's θ̇ as 0.
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
            "  separation   t = {} s   θ = {} rad ({}°)   θ̇ = {} rad/s\n               cos θ = {} (predicted by the energy integral: {})\n",
            sig(p.time, 16),
            sig(p.angle, 16),
            sig(p.angle.to_degrees(), 7),
            sig(p.rate, 13),
            sig(p.angle.cos(), 16),
            sig(separation_cosine(scene.ladder.big_omega2(), scene.theta0, scene.rate0), 16)
        ),
        None => s += "  separation   not reached\n",
    }
    if o.separation.is_some_and(|p| p.time == 0.0) && scene.rate0 > 0.0 {
        s += "               at once: the push is at or past √(3g cos θ0/4l), where the wall would have to pull\n";
    }
    if let Some(f) = o.flat {
        s += &format!(
            "  flat         t = {} s   θ̇ = {} rad/s   centre x = {} m, ẋ = {} m/s, ẏ = {} m/s\n",
            sig(f.time, 16),
            sig(f.rate, 13),
            sig(f.centre_x, 13),
            sig(f.centre_velocity_x, 13),
            sig(f.centre_velocity_y, 13)
        );
    }
    if let Some(sl) = o.slide {
        s += &format!(
            "  lying flat   from t = {} s: the top struck the floor (perfectly inelastic, no horizontal impulse; {} m g l lost), slid at ẋ = {} m/s to centre x = {} m\n",
            sig(sl.impact_time, 16),
            sig(sl.energy_lost, 6),
            sig(sl.centre_velocity_x, 13),
            sig(sl.centre_x_end, 13)
        );
    }
    if let Some(r) = o.floor_report {
        s += &format!(
            "  floor phase  min F_f = {} N (> 0: no lift-off)   min top clearance = {:.3e} m ({})\n",
            sig(r.floor_force_min, 10),
            r.top_clearance_min,
            if top_inside_wall(&r, scene.ladder.l).is_none() { "the top never returns to the wall" } else { "TOP INSIDE THE WALL: not the model's motion" }
        );
    }
    if let Some(e) = o.momentum_error {
        s += &format!("  momentum     |Δp_x − ∫F_w dt| / (m √(g l)) over the fall = {e:.3e}\n");
    }
    if let Some(e) = o.energy_error {
        s += &format!("  energy       |ΔE| / (m g l) = {e:.3e}\n");
    }
    s += &format!(
        "  end          t = {} s   θ = {} rad   θ̇ = {} rad/s\n",
        sig(o.last.0, 16),
        sig(o.last.1, 16),
        sig(o.last.2, 13)
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
    super::fall_figures::files(scene, o)
}
