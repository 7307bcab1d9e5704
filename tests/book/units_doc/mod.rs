//! docs/UNITS.md is in step with the code: each symbol's dimension is what its Rust function
//! yields in dimensions, each SI unit spells that dimension, and each output of `ladder simulate`
//! scales with a change of units as its stated dimension says.

use pulldown_cmark::{Event, Options, Parser, Tag, TagEnd};
use sliding_ladder::ladder::energy::{kinetic_energy, moment_of_inertia_cm, potential_energy};
use sliding_ladder::ladder::forces::{floor_force, wall_force};
use sliding_ladder::ladder::geometry::{cm_acceleration, cm_position, cm_velocity};
use sliding_ladder::ladder::torque::{
    angular_momentum_about_a, eq13_moment_of_inertia_about_corner,
};
use sliding_ladder::registry::sample::{LadderSample, ParticleSample};
use sliding_ladder::registry::units::{dimensioned_ladder, dimensioned_particles};
use sliding_ladder::report::outcome::to_json;
use sliding_ladder::scalar::{Dim, Dimension, Scalar};
use sliding_ladder::sim::{fall, scene};
use std::collections::BTreeMap;

/// The CSV columns and the printed summary of `ladder simulate`, in units.
mod simulate;

/// The rows of every table on the page: (section heading, cells).
fn tables() -> Vec<(String, Vec<String>)> {
    let path = std::path::Path::new(env!("CARGO_MANIFEST_DIR")).join("docs/UNITS.md");
    let text = std::fs::read_to_string(&path).expect("docs/UNITS.md");
    let (mut rows, mut heading, mut cell, mut row) = (Vec::new(), String::new(), None, Vec::new());
    let mut in_heading = false;
    for ev in Parser::new_ext(&text, Options::ENABLE_TABLES) {
        match ev {
            Event::Start(Tag::Heading { .. }) => (in_heading, heading) = (true, String::new()),
            Event::End(TagEnd::Heading(_)) => in_heading = false,
            Event::Start(Tag::TableCell) => cell = Some(String::new()),
            Event::End(TagEnd::TableCell) => row.push(cell.take().unwrap_or_default()),
            Event::End(TagEnd::TableRow) => rows.push((heading.clone(), std::mem::take(&mut row))),
            Event::End(TagEnd::TableHead) => row.clear(),
            Event::Text(t) | Event::Code(t) => {
                if in_heading {
                    heading.push_str(&t);
                } else if let Some(c) = cell.as_mut() {
                    c.push_str(&t);
                }
            }
            _ => {}
        }
    }
    rows
}

/// The dimension an SI unit spells ([`Dimension::from_si`]).
fn si_dimension(unit: &str) -> Dimension {
    Dimension::from_si(unit).unwrap_or_else(|e| panic!("{e}"))
}

/// Each symbol of the table in dimensions, from the code.
fn symbol_dimensions() -> BTreeMap<&'static str, Dim> {
    let (l, s) = dimensioned_ladder(LadderSample::Kinematic);
    let (sys, _) = dimensioned_particles(ParticleSample::General, 2);
    BTreeMap::from([
        ("θ", Dim::int(1)),
        ("sin θ, cos θ", s.sin.clone() + s.cos.clone()),
        ("θ̇", s.rate.clone()),
        ("θ̈", s.accel.clone()),
        ("m", l.m.clone()),
        ("l", l.l.clone()),
        ("g", l.g.clone()),
        ("Ω²", l.big_omega2()),
        ("x_cm, y_cm", cm_position(&l, &s).x + cm_position(&l, &s).y),
        ("v_cm", cm_velocity(&l, &s).x),
        ("a_cm", cm_acceleration(&l, &s).y),
        (
            "I_cm, I_A",
            moment_of_inertia_cm(&l) + eq13_moment_of_inertia_about_corner(&l)[1].clone(),
        ),
        ("T", kinetic_energy(&l, &s)),
        ("V", potential_energy(&l, &s)),
        ("F_w", wall_force(&l, &s)),
        ("F_f", floor_force(&l, &s)),
        ("L_A", angular_momentum_about_a(&l, &s)),
        (
            "τ_A",
            sliding_ladder::ladder::particles::external_torque_about(
                &l,
                &sliding_ladder::ladder::particles::as_system(&l, &s),
                &sliding_ladder::vector::Vec3::zero(),
            )
            .z,
        ),
        ("p", sys.particles[0].momentum().x),
    ])
}

#[test]
fn every_symbol_has_the_dimension_of_its_code_and_its_si_unit() {
    let code = symbol_dimensions();
    let rows: Vec<Vec<String>> = tables()
        .into_iter()
        .filter(|(h, _)| h == "Symbols")
        .map(|r| r.1)
        .collect();
    assert_eq!(rows.len(), code.len(), "rows {rows:?}");
    for r in &rows {
        let [symbol, _, dim, si] = &r[..] else {
            panic!("row {r:?}")
        };
        let stated = Dimension::parse(dim).unwrap_or_else(|e| panic!("{symbol}: {e}"));
        let value = code
            .get(symbol.as_str())
            .unwrap_or_else(|| panic!("no code for {symbol}"));
        assert_eq!(
            value,
            &Dim::Of(stated),
            "{symbol}: the code gives {value:?}"
        );
        assert_eq!(si_dimension(si), stated, "{symbol}: {si} is not {dim}");
    }
    // The checks can fail: a wrong dimension or unit is noticed.
    assert_ne!(code["F_w"], Dim::Of(Dimension::parse("M L T^-1").unwrap()));
    assert_ne!(si_dimension("N"), si_dimension("J"));
    assert_eq!(si_dimension("kg m/s^2"), si_dimension("N"));
}

/// Scale factors of a change of units: masses × 3, lengths × 5, times × 1/2 (so g × 20). Distinct
/// primes: no two dimensions scale alike, so a wrong stated dimension cannot pass.
const MASS: f64 = 3.0;
const LENGTH: f64 = 5.0;
const TIME: f64 = 0.5;

/// Outputs whose values a change of units may move within the run's resolution.
const SAMPLED_OR_COUNTED: [&str; 5] = [
    "floor_phase.floor_force_min",
    "floor_phase.top_clearance_min",
    "work.",
    "trajectory.samples",
    "forces.samples",
];

fn run_scene(m: f64, l: f64, g: f64) -> (scene::Scene, fall::Outcome) {
    let text = include_str!("../../../scenes/full-fall.toml")
        .replace("mass = 1.0", &format!("mass = {m:?}"))
        .replace("half_length = 1.0", &format!("half_length = {l:?}"))
        .replace("gravity = 9.81", &format!("gravity = {g:?}"))
        .replace("want = [", "want = [\"separation_rate\", ");
    let sc = scene::parse("full-fall (rescaled)", &text).expect("scene");
    let o = fall::run(&sc, fall::MAX_STEPS).expect("run");
    (sc, o)
}

fn run(m: f64, l: f64, g: f64) -> serde_json::Value {
    let (sc, o) = run_scene(m, l, g);
    to_json(&sc, &o)
}

fn leaves(v: &serde_json::Value, prefix: String, out: &mut BTreeMap<String, f64>) {
    match v {
        serde_json::Value::Object(m) => {
            for (k, x) in m {
                let key = if prefix.is_empty() {
                    k.clone()
                } else {
                    format!("{prefix}.{k}")
                };
                leaves(x, key, out);
            }
        }
        x => {
            out.insert(prefix, x.as_f64().expect("numeric output"));
        }
    }
}

#[test]
fn every_simulator_output_scales_as_its_stated_unit() {
    let stated: BTreeMap<String, Dimension> = tables()
        .into_iter()
        .filter(|(h, _)| h.starts_with("Outputs"))
        .map(|(_, r)| {
            assert_eq!(
                si_dimension(&r[3]),
                Dimension::parse(&r[2]).unwrap(),
                "{r:?}"
            );
            (r[0].clone(), Dimension::parse(&r[2]).unwrap())
        })
        .collect();
    let g = 9.81;
    let (mut a, mut b) = (BTreeMap::new(), BTreeMap::new());
    leaves(&run(1.0, 1.0, g), String::new(), &mut a);
    leaves(
        &run(MASS, LENGTH, g * LENGTH / (TIME * TIME)),
        String::new(),
        &mut b,
    );
    assert_eq!(
        a.keys().collect::<Vec<_>>(),
        stated.keys().collect::<Vec<_>>(),
        "outputs vs table"
    );
    for (key, dim) in &stated {
        let factor = |d: Dimension| {
            let e = |x: num_rational::Ratio<i32>| f64::from(*x.numer()) / f64::from(*x.denom());
            MASS.powf(e(d.m)) * LENGTH.powf(e(d.l)) * TIME.powf(e(d.t))
        };
        // Sampled minima depend on where the samples fall, and counts on the step pattern, which
        // a change of units moves (34 steps against 33 here): their values are not compared.
        if SAMPLED_OR_COUNTED.iter().any(|k| key.starts_with(k)) {
            assert!(dim.is_dimensionless() || key.contains("_min"), "{key}");
            continue;
        }
        // Error model: both runs are within the global error of the integrator, at most one
        // local tolerance (1e-14 in the scene) per step, in the quantity's own scale (the
        // largest output of the same dimension, 1 for pure numbers).
        let (x, y) = (a[key], b[key]);
        let scale = stated
            .iter()
            .filter(|(_, d)| *d == dim)
            .map(|(k, _)| a[k].abs())
            .fold(if dim.is_dimensionless() { 1.0 } else { 0.0 }, f64::max);
        let tol = a["work.steps"].max(b["work.steps"]) * 1e-14 * scale;
        let diff = (y / factor(*dim) - x).abs();
        assert!(
            diff <= tol,
            "{key}: {y} in the new units is not {x} × {} (diff {diff:e})",
            factor(*dim)
        );
    }
    // The check can fail: a time stated as a rate, or a force as a momentum, does not scale.
    let e = |x: num_rational::Ratio<i32>| f64::from(*x.numer()) / f64::from(*x.denom());
    let factor = |d: Dimension| MASS.powf(e(d.m)) * LENGTH.powf(e(d.l)) * TIME.powf(e(d.t));
    let off = |key: &str, d: &str| (b[key] / factor(Dimension::parse(d).unwrap()) - a[key]).abs();
    assert!(off("separation.time", "T^-1") > 0.1 * a["separation.time"]);
    assert!(off("flat.centre_x", "M L") > 0.1 * a["flat.centre_x"]);
}
