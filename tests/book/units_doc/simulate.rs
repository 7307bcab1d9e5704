//! Issue 14 item 4, beyond the JSON: the columns of the CSV files `ladder simulate --out` writes
//! and every number its printed summary gives with a unit scale, under a change of units, as
//! the unit docs/UNITS.md (or the summary itself) states.

use super::{run_scene, si_dimension, tables, LENGTH, MASS, TIME};
use sliding_ladder::scalar::Dimension;
use sliding_ladder::sim::{fall, scene};
use std::collections::BTreeMap;

/// The factor a quantity of dimension `d` is multiplied by in the new units.
fn unit_factor(d: Dimension) -> f64 {
    let e = |x: num_rational::Ratio<i32>| f64::from(*x.numer()) / f64::from(*x.denom());
    MASS.powf(e(d.m)) * LENGTH.powf(e(d.l)) * TIME.powf(e(d.t))
}

type Run = (scene::Scene, fall::Outcome);

/// The full fall in the old units and in the new ones, with the larger step count of the two.
fn both_runs() -> (Run, Run, f64) {
    let g = 9.81;
    let a = run_scene(1.0, 1.0, g);
    let b = run_scene(MASS, LENGTH, g * LENGTH / (TIME * TIME));
    let steps =
        |o: &fall::Outcome| (o.work.wall.steps + o.work.floor.map_or(0, |f| f.steps)) as f64;
    let s = steps(&a.1).max(steps(&b.1));
    (a, b, s)
}

type Csv = (Vec<String>, Vec<Vec<f64>>);

/// A CSV file of `ladder simulate --out` for a run, as (header, rows).
fn csv(run: &Run, name: &str) -> Csv {
    let file = sliding_ladder::report::fall_figures::files(&run.0, &run.1)
        .into_iter()
        .find(|f| f.name == name)
        .unwrap_or_else(|| panic!("no {name}"));
    let sliding_ladder::report::files::Content::Text(text) = file.content else {
        panic!("{name} is not text")
    };
    let mut lines = text.lines();
    let header = lines
        .next()
        .expect("a header")
        .split(',')
        .map(String::from)
        .collect();
    let rows = lines
        .map(|l| l.split(',').map(|x| x.parse().expect("a number")).collect())
        .collect();
    (header, rows)
}

/// Where the CSV columns of two runs in different units disagree with their stated dimensions.
/// Rows are compared at the events, which both runs locate (their step patterns differ): the
/// start, the last row on the wall (the separation) and the last row (flat). Error model: as
/// for the JSON, one local tolerance (1e-14) per step in the column's own scale (its largest
/// value, 1 for a pure number).
fn csv_problems(stated: &BTreeMap<String, Dimension>, a: &Csv, b: &Csv, steps: f64) -> Vec<String> {
    let mut out = Vec::new();
    let events = |rows: &[Vec<f64>]| {
        let wall_end = rows
            .iter()
            .rposition(|r| r[0] == 1.0)
            .expect("a wall phase");
        [0, wall_end, rows.len() - 1]
    };
    let (ea, eb) = (events(&a.1), events(&b.1));
    for (k, col) in a.0.iter().enumerate() {
        let Some(dim) = stated.get(col) else {
            out.push(format!("column {col} has no stated unit"));
            continue;
        };
        let scale =
            a.1.iter()
                .map(|r| r[k].abs())
                .fold(if dim.is_dimensionless() { 1.0 } else { 0.0 }, f64::max);
        for (&i, &j) in ea.iter().zip(&eb) {
            let (x, y) = (a.1[i][k], b.1[j][k]);
            let diff = (y / unit_factor(*dim) - x).abs();
            if diff > steps * 1e-14 * scale {
                out.push(format!(
                    "{col}: {y} is not {x} × {} (diff {diff:e})",
                    unit_factor(*dim)
                ));
            }
        }
    }
    out
}

/// Issue 14 item 4: every column of the CSV files `ladder simulate --out` writes scales as the
/// unit docs/UNITS.md states for it; a column stated in the wrong unit is caught.
#[test]
fn every_csv_column_scales_as_its_stated_unit() {
    let mut stated: BTreeMap<String, Dimension> = tables()
        .into_iter()
        .filter(|(h, _)| h.starts_with("Columns of the CSV"))
        .map(|(_, r)| {
            let d = Dimension::parse(&r[2]).unwrap();
            assert_eq!(si_dimension(&r[3]), d, "{r:?}");
            (r[0].clone(), d)
        })
        .collect();
    let (a, b, steps) = both_runs();
    let mut columns = Vec::new();
    for name in ["trajectory.csv", "forces.csv"] {
        let (ca, cb) = (csv(&a, name), csv(&b, name));
        assert_eq!(ca.0, cb.0);
        let problems = csv_problems(&stated, &ca, &cb, steps);
        assert!(problems.is_empty(), "{name}: {problems:?}");
        columns.extend(ca.0);
    }
    columns.sort();
    columns.dedup();
    assert_eq!(
        columns,
        stated.keys().cloned().collect::<Vec<_>>(),
        "columns vs table"
    );
    // The check can fail: a force stated as a momentum, or a rate as a time, does not scale.
    let (fa, fb) = (csv(&a, "forces.csv"), csv(&b, "forces.csv"));
    stated.insert("floor_force".into(), Dimension::parse("M L T^-1").unwrap());
    stated.insert("rate".into(), Dimension::TIME);
    let wrong = csv_problems(&stated, &fa, &fb, steps);
    assert!(
        wrong.iter().any(|p| p.starts_with("floor_force:")),
        "{wrong:?}"
    );
    assert!(wrong.iter().any(|p| p.starts_with("rate:")), "{wrong:?}");
}

/// A number the summary prints with a unit: (name and unit, value, its last printed place,
/// the unit's dimension).
type WithUnit = (String, f64, f64, Dimension);

/// Every `= number unit` of a summary printed by `ladder simulate`, skipping the sampled minima
/// (their samples move with the step pattern).
fn with_units(text: &str) -> Vec<WithUnit> {
    let tokens: Vec<&str> = text.split_whitespace().collect();
    let mut out = Vec::new();
    for i in 1..tokens.len().saturating_sub(2) {
        let (num, unit) = (tokens[i + 1], tokens[i + 2].trim_end_matches(','));
        let (Ok(value), Ok(dim)) = (num.parse::<f64>(), Dimension::from_si(unit)) else {
            continue;
        };
        if tokens[i] != "=" || tokens[i.saturating_sub(3)..i].contains(&"min") {
            continue;
        }
        let (mantissa, exp) = num.split_once('e').unwrap_or((num, "0"));
        let decimals = mantissa.split_once('.').map_or(0, |(_, f)| f.len());
        let place = 10f64.powi(exp.parse::<i32>().expect("an exponent") - decimals as i32);
        out.push((format!("{} {unit}", tokens[i - 1]), value, place, dim));
    }
    out
}

/// Where two summaries in different units disagree with the units they print. Error model: as
/// for the JSON, plus half the last printed place of each number.
fn summary_problems(a: &str, b: &str, steps: f64) -> Vec<String> {
    let (qa, qb) = (with_units(a), with_units(b));
    if qa.len() != qb.len() {
        return vec![format!(
            "{} numbers with units against {}",
            qa.len(),
            qb.len()
        )];
    }
    let mut out = Vec::new();
    for ((name, x, px, dim), (name_b, y, py, dim_b)) in qa.iter().zip(&qb) {
        if name != name_b || dim != dim_b {
            out.push(format!("{name} against {name_b}"));
            continue;
        }
        let scale = qa
            .iter()
            .filter(|q| q.3 == *dim)
            .map(|q| q.1.abs())
            .fold(if dim.is_dimensionless() { 1.0 } else { 0.0 }, f64::max);
        let f = unit_factor(*dim);
        let diff = (y / f - x).abs();
        let tol = steps * 1e-14 * scale + (px + py / f) / 2.0;
        if diff > tol {
            out.push(format!(
                "{name}: {y} is not {x} × {f} (diff {diff:e} > {tol:e})"
            ));
        }
    }
    out
}

/// Issue 14 item 4: every number the summary of `ladder simulate` prints with a unit (s, rad,
/// rad/s, m, m/s) scales as that unit says; a wrong unit in the summary is caught.
#[test]
fn every_unit_the_simulate_summary_prints_is_right() {
    use sliding_ladder::report::outcome::summary;
    let (a, b, steps) = both_runs();
    let (ta, tb) = (summary(&a.0, &a.1), summary(&b.0, &b.1));
    let found = with_units(&ta);
    let units: std::collections::BTreeSet<_> = found
        .iter()
        .map(|q| q.0.rsplit(' ').next().unwrap_or_default().to_string())
        .collect();
    assert_eq!(
        units.into_iter().collect::<Vec<_>>(),
        ["m", "m/s", "rad", "rad/s", "s"],
        "{ta}"
    );
    assert!(found.len() >= 10, "{found:?}");
    let problems = summary_problems(&ta, &tb, steps);
    assert!(problems.is_empty(), "{problems:?}\n{ta}\n{tb}");
    // The check can fail: a velocity printed in m, or a time in rad/s, is caught.
    let plant = |s: &str| s.replace("m/s", "m");
    assert!(!summary_problems(&plant(&ta), &plant(&tb), steps).is_empty());
    let plant = |s: &str| s.replacen(" s ", " rad/s ", 1);
    let wrong = summary_problems(&plant(&ta), &plant(&tb), steps);
    assert!(wrong.iter().any(|p| p.contains("rad/s")), "{wrong:?}");
}
