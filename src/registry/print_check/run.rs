//! Running a display's printed chains on the registry's samples.

use super::{
    evaluate_chains, form_text, misprints, print_chains_with, term_chains, Form, PrintReport,
};
use crate::print::quantity::Model;
use crate::registry::check::{exact_residual, float_residual, Config, TOLERANCE_FACTOR};
use crate::registry::sample::{
    exact_ladder, particle_system, LadderSample, RawLadder, RawParticles,
};
use crate::registry::{Chain, Equation, Eval, Role};
use crate::scalar::{Bound, Rational, Scalar};
use num_traits::Zero;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// Check the print of one display on its registry samples.
pub fn check_print(e: &Equation, latex: &str, cfg: &Config) -> PrintReport {
    check_print_with(e, latex, cfg, &misprints())
}

/// [`check_print`] with a given list of misprinted forms.
pub fn check_print_with(
    e: &Equation,
    latex: &str,
    cfg: &Config,
    misprint_list: &[(u32, &str)],
) -> PrintReport {
    let mut rep = PrintReport::default();
    let (count, chains) = match print_chains_with(e.number, latex, misprint_list) {
        Ok(c) => c,
        Err(err) => {
            rep.forms = latex.matches('=').count() + 1;
            rep.unparsed.push(format!("parse: {err}"));
            return rep;
        }
    };
    rep.forms = count;
    let Some(check) = sample_check(e) else {
        rep.unparsed
            .push("no registry check to take a sample from".into());
        return rep;
    };
    let mut rng = ChaCha8Rng::seed_from_u64(cfg.seed ^ u64::from(e.number));
    // Drop forms that do not evaluate (reported), keep the rest.
    let probe: Result<(), String> = match check.eval {
        Eval::Ladder(sort, _) => {
            let ((l, s), _) = RawLadder::draw(&mut rng).build(sort);
            evaluate_chains(e, &chains, Model::ladder(l, s), None).map(|_| ())
        }
        Eval::Particles(sort, _) => {
            let raw = RawParticles::draw(&mut rng);
            let ((sys, p), _) = crate::registry::sample::float_particles(sort, &raw);
            evaluate_chains(e, &chains, Model::particles(sys, p), None).map(|_| ())
        }
        Eval::Floor(..) => Err("floor-phase displays are not in the note".into()),
    };
    if let Err(err) = probe {
        rep.unparsed.push(err);
        return rep;
    }
    rep.parsed = count;
    rep.checked = chains
        .iter()
        .filter(|c| c.len() > 1)
        .map(Vec::len)
        .sum::<usize>()
        .min(count);
    let float_cases = cfg.float_cases.min(PRINT_FLOAT_CASES);
    let mut worst = (0.0f64, "");
    let mut float_failures = 0;
    let mut exact_fail: Option<(String, String)> = None;
    let mut misprint_held: Vec<String> = Vec::new();
    let mut code_values: Vec<Rational> = Vec::new();
    let mut code_sides: Vec<(String, Rational)> = Vec::new();
    match check.eval {
        Eval::Ladder(sort, f) => {
            for _ in 0..float_cases {
                let ((l, s), (lb, sb)) = RawLadder::draw(&mut rng).build(sort);
                let v = evaluate_chains(e, &chains, Model::ladder(l, s), None);
                let b = evaluate_chains(e, &chains, Model::ladder(lb, sb), None);
                note_float(v, b, &mut worst, &mut float_failures);
            }
            for k in 0..cfg.exact_points.min(PRINT_EXACT_POINTS) {
                let draw = crate::registry::check::exact_ladder_draw(&mut rng);
                let (l, s) = exact_ladder(sort, draw);
                let ch = evaluate_chains(e, &chains, Model::ladder(l.clone(), s.clone()), None);
                note_exact(
                    ch,
                    &chains,
                    &mut exact_fail,
                    &mut misprint_held,
                    &mut code_values,
                    k == 0,
                );
                if k == 0 {
                    let m = Model::ladder(l.clone(), s.clone());
                    if let Ok(ch) = evaluate_chains(e, &term_chains(&chains), m, None) {
                        code_values.extend(ch.into_iter().flatten().map(|s| s.value));
                    }
                    code_sides = rust_sides((f.exact)(&l, &s));
                }
            }
        }
        Eval::Particles(sort, f) => {
            for _ in 0..float_cases {
                let raw = RawParticles::draw(&mut rng);
                let ((sys, p), (sysb, pb)) = crate::registry::sample::float_particles(sort, &raw);
                let v = evaluate_chains(e, &chains, Model::particles(sys, p), None);
                let b = evaluate_chains(e, &chains, Model::particles(sysb, pb), None);
                note_float(v, b, &mut worst, &mut float_failures);
            }
            for k in 0..cfg.exact_points.min(PRINT_EXACT_POINTS) {
                let (n, values) = crate::registry::check::exact_particle_draw(&mut rng);
                let (sys, p) = particle_system(sort, n, &values);
                let ch =
                    evaluate_chains(e, &chains, Model::particles(sys.clone(), p.clone()), None);
                note_exact(
                    ch,
                    &chains,
                    &mut exact_fail,
                    &mut misprint_held,
                    &mut code_values,
                    k == 0,
                );
                if k == 0 {
                    // Per-particle statements: the forms at every particle.
                    let with_terms = [chains.clone(), term_chains(&chains)].concat();
                    for i in 0..n {
                        let m = Model::particles(sys.clone(), p.clone());
                        if let Ok(ch) = evaluate_chains(e, &with_terms, m, Some(i)) {
                            code_values.extend(ch.into_iter().flatten().map(|s| s.value));
                        }
                    }
                    code_sides = rust_sides((f.exact)(&sys, &p));
                }
            }
        }
        Eval::Floor(..) => {}
    }
    if float_failures > 0 {
        rep.problems.push(format!(
            "print: {float_failures} of {float_cases} float states out of tolerance; worst residual {:.3e} × its error bound at {} '{}'",
            worst.0,
            worst.1,
            form_text(&chains, worst.1)
        ));
    }
    if let Some((label, residual)) = exact_fail {
        rep.problems.push(format!(
            "print: {label} '{}' differs from its chain exactly (residual {residual})",
            form_text(&chains, &label)
        ));
    }
    misprint_held.dedup();
    for m in misprint_held {
        rep.problems
            .push(format!("print: the misprint {m} did not fail"));
    }
    for (label, v) in code_sides {
        // A zero component (z of a planar vector) says nothing about which form it is.
        if !v.is_zero() && !code_values.contains(&v) {
            let msg = format!("Rust form '{label}' equals no printed form");
            if !rep.code_mismatches.contains(&msg) {
                rep.code_mismatches.push(msg);
            }
        }
    }
    rep.matches_code = rep.code_mismatches.is_empty() && rep.parsed == rep.forms;
    rep
}

/// The registry check whose sample the print is evaluated on: for an on-shell display the one
/// from rest if any (the energy (10) holds there only), else the first on-shell one.
pub fn sample_check(e: &Equation) -> Option<&crate::registry::Check> {
    let from_rest = |c: &&crate::registry::Check| {
        matches!(c.eval, Eval::Ladder(LadderSample::OnShellFromRest, _))
    };
    let on_shell =
        |c: &&crate::registry::Check| matches!(c.eval, Eval::Ladder(s, _) if s.on_shell());
    if e.kind == crate::registry::Kind::OnShell {
        if let Some(c) = e
            .checks
            .iter()
            .find(from_rest)
            .or_else(|| e.checks.iter().find(on_shell))
        {
            return Some(c);
        }
    }
    e.checks.first()
}

/// Exact points per display for the print: one point already bounds the chance that a false
/// chain passes by degree/2^62 (Schwartz-Zippel); the registry's checks run more.
pub const PRINT_EXACT_POINTS: usize = 1;

/// Float cases per display for the print (the registry's checks run the full count).
pub const PRINT_FLOAT_CASES: usize = 200;

fn note_float(
    v: Result<Vec<Chain<f64>>, String>,
    b: Result<Vec<Chain<Bound>>, String>,
    worst: &mut (f64, &'static str),
    failures: &mut usize,
) {
    let (Ok(v), Ok(b)) = (v, b) else {
        *failures += 1;
        *worst = (f64::INFINITY, "form 1");
        return;
    };
    let (scaled, label) = float_residual(&v, &b);
    if scaled.is_nan() || scaled > TOLERANCE_FACTOR {
        *failures += 1;
    }
    if scaled.is_nan() || scaled > worst.0 {
        *worst = (scaled, label);
    }
}

fn note_exact(
    ch: Result<Vec<Chain<Rational>>, String>,
    chains: &[Vec<Form>],
    fail: &mut Option<(String, String)>,
    misprint_held: &mut Vec<String>,
    values: &mut Vec<Rational>,
    first: bool,
) {
    let ch = match ch {
        Ok(c) => c,
        Err(err) => {
            fail.get_or_insert((format!("form 1 ({err})"), "undefined".into()));
            return;
        }
    };
    if first {
        values.extend(ch.iter().flatten().map(|s| s.value.clone()));
    }
    let (ok, mis) = exact_residual(&ch);
    if !ok && fail.is_none() {
        for c in &ch {
            let Some(base) = c.iter().position(|s| s.role != Role::Misprint) else {
                continue;
            };
            if let Some(s) = c
                .iter()
                .find(|s| s.role != Role::Misprint && s.value != c[base].value)
            {
                let r = s.value.clone() - c[base].value.clone();
                *fail = Some((s.label.to_string(), format!("{:.6e}", r.to_f64())));
                break;
            }
        }
    }
    // A misprinted vector fails when any component differs.
    let mut labels: Vec<&str> = mis.iter().map(|m| m.0).collect();
    labels.dedup();
    for label in labels {
        if !mis.iter().any(|m| m.0 == label && m.1) {
            misprint_held.push(format!("{label} '{}'", form_text(chains, label)));
        }
    }
}

fn rust_sides(chains: Vec<Chain<Rational>>) -> Vec<(String, Rational)> {
    chains
        .into_iter()
        .flatten()
        .filter(|s| matches!(s.role, Role::Printed | Role::Misprint))
        .map(|s| (s.label.to_string(), s.value))
        .fold(Vec::new(), |mut acc: Vec<(String, Rational)>, x| {
            if !acc.iter().any(|a| a.0 == x.0 && a.1 == x.1) {
                acc.push(x);
            }
            acc
        })
}
