//! The print as the thing checked: every display's LaTeX parsed ([`crate::print`]), each chain of
//! printed forms evaluated on the registry's own samples and held equal with the registry's own
//! verdicts (float within the running error bound, exact with zero residual), and every Rust
//! form's value held against the parsed forms.
//!
//! Per display: statements become chains; Milne's statement k joins our statement k (his names
//! denote our quantities, so every form must agree); `X = \text{const}` is checked as
//! d/dt X = 0; a premise and its conclusion (`\Rightarrow`) are both checked on the registry's
//! sample, which is drawn so that the premise holds; an evaluation bar `|_{a=b}` adds the chain
//! a = b (the sample must satisfy it). A form recorded as a misprint ([`MISPRINTS`]) must differ.

use super::check::{exact_residual, float_residual, Config, TOLERANCE_FACTOR};
use super::sample::{exact_ladder, particle_system, LadderSample, RawLadder, RawParticles};
use super::{Chain, Equation, Eval, Role, Side};
use crate::print::ast::{Chain as PChain, Expr};
use crate::print::eval::{evaluate, Ctx};
use crate::print::quantity::{Model, Value};
use crate::print::symbols::{table, Entry};
use crate::scalar::{Bound, Rational, Scalar};
use num_traits::Zero;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;
use serde::Serialize;

/// Misprinted forms (display, the form's LaTeX as printed): they must fail against the chain.
/// Each is one side of a recorded erratum (`Equation::erratum`), tested in `tests/print.rs`.
pub const MISPRINTS: &[(u32, &str)] = &[
    (28, r"\tau_E - F_{E,y} l \sin \theta"),
    (
        49,
        r"\frac{m l^2 \dot{\theta}}{3} \hat{\mathbf{z}} + l^2 \dot{\theta} (\cos^2 \theta - \sin^2 \theta) \hat{\mathbf{z}}",
    ),
    (54, r"\frac{4m l^2 \dot{\theta}^2}{3}"),
    (
        62,
        r"m l g \sin \theta - m l \sin^2 \theta \ddot{\theta} - m l \cos \theta \sin \theta \dot{\theta}^2",
    ),
    (68, r"\sum \mathbf{r} \wedge \ddot{\mathbf{r}}"),
];

/// Displays that continue the previous one: (57) begins with `=`, continuing (56)'s chain from
/// its last form.
pub const CONTINUATIONS: &[(u32, &str)] = &[(57, r"\boldsymbol{\tau}_P ")];

const LABELS: [&str; 24] = [
    "form 1", "form 2", "form 3", "form 4", "form 5", "form 6", "form 7", "form 8", "form 9",
    "form 10", "form 11", "form 12", "form 13", "form 14", "form 15", "form 16", "form 17",
    "form 18", "form 19", "form 20", "form 21", "form 22", "form 23", "form 24",
];

/// One printed form in a chain to check.
#[derive(Clone, Debug)]
pub struct Form {
    /// The parsed form.
    pub expr: Expr,
    /// Its printed LaTeX (canonical, spaces dropped).
    pub text: String,
    /// Printed (must equal the chain) or misprint (must differ).
    pub role: Role,
    /// In Milne's notation.
    pub milne: bool,
}

/// What the print of one display gave.
#[derive(Clone, Debug, Default, Serialize)]
pub struct PrintReport {
    /// Forms in the print (every side of every chain).
    pub forms: usize,
    /// Forms parsed and evaluated.
    pub parsed: usize,
    /// Forms held against another form (chains of two or more).
    pub checked: usize,
    /// Why a form or the display could not be parsed or evaluated.
    pub unparsed: Vec<String>,
    /// Chains that failed: the form, the residual.
    pub problems: Vec<String>,
    /// Every Rust printed/misprint form equals some parsed printed form (exactly).
    pub matches_code: bool,
    /// Rust forms that equal no parsed form.
    pub code_mismatches: Vec<String>,
}

/// The chains of a display's print, ready to evaluate.
pub fn print_chains(number: u32, latex: &str) -> Result<(usize, Vec<Vec<Form>>), String> {
    print_chains_with(number, latex, MISPRINTS)
}

/// [`print_chains`] with a given list of misprinted forms.
pub fn print_chains_with(
    number: u32,
    latex: &str,
    misprint_list: &[(u32, &str)],
) -> Result<(usize, Vec<Vec<Form>>), String> {
    let src = match CONTINUATIONS.iter().find(|c| c.0 == number) {
        Some((_, prefix)) => format!("{prefix}{latex}"),
        None => latex.to_string(),
    };
    let d = crate::print::parser::parse_display(&src)?;
    let misprints: Vec<String> = misprint_list
        .iter()
        .filter(|m| m.0 == number)
        .filter_map(|m| crate::print::parser::canonical(m.1).ok())
        .collect();
    let forms = |c: &PChain, milne: bool| -> Vec<Form> {
        c.forms
            .iter()
            .zip(&c.texts)
            .map(|(e, t)| Form {
                expr: e.clone(),
                text: t.clone(),
                role: if misprints.contains(t) {
                    Role::Misprint
                } else {
                    Role::Printed
                },
                milne,
            })
            .collect()
    };
    let mut ours: Vec<Vec<Form>> = Vec::new();
    let mut milne_k = 0;
    let mut count = d.form_count();
    if number == 57 {
        count -= 1; // the continued form belongs to (56)
    }
    for st in &d.statements {
        let mut chain = forms(&st.chain, st.milne);
        let mut extra = Vec::new();
        if let Some(concl) = &st.implies {
            extra.push(constant(forms(concl, st.milne)));
        }
        chain = constant(chain);
        for f in chain.iter() {
            conditions(&f.expr, f.milne, &mut extra);
        }
        if st.milne && milne_k < ours.len() {
            ours[milne_k].extend(chain);
            milne_k += 1;
        } else {
            ours.push(chain);
        }
        ours.extend(extra);
    }
    Ok((count, ours))
}

/// `X = \text{const}` → d/dt X = 0.
fn constant(chain: Vec<Form>) -> Vec<Form> {
    if chain.len() == 2 && chain[1].expr == Expr::Const {
        let mut c = chain;
        c[0].expr = Expr::Deriv(Box::new(c[0].expr.clone()));
        c[1].expr = Expr::Int(0);
        c
    } else {
        chain
    }
}

/// The chains a = b of every evaluation bar in a form.
fn conditions(e: &Expr, milne: bool, out: &mut Vec<Vec<Form>>) {
    use Expr::*;
    match e {
        At(a, conds) => {
            out.push(
                conds
                    .iter()
                    .map(|c| Form {
                        expr: c.clone(),
                        text: "evaluation condition".into(),
                        role: Role::Printed,
                        milne,
                    })
                    .collect(),
            );
            conditions(a, milne, out);
        }
        Neg(a) | Pow(a, _) | Sin(a) | Cos(a) | Sum(a) | Deriv(a) | Partial(a, _) | ZComp(a) => {
            conditions(a, milne, out)
        }
        Add(a, b) | Sub(a, b) | Mul(a, b) | Div(a, b) | Cross(a, b) => {
            conditions(a, milne, out);
            conditions(b, milne, out);
        }
        Tuple(v) => v.iter().for_each(|x| conditions(x, milne, out)),
        Int(_) | Sym(_) | Const => {}
    }
}

fn ctx<'t, S: Scalar>(
    e: &'t Equation,
    model: &std::rc::Rc<Model<S>>,
    milne: bool,
    index: Option<usize>,
    table: &'t [Entry],
) -> Ctx<'t, S> {
    Ctx {
        model: model.clone(),
        section: e.section,
        number: e.number,
        milne,
        index,
        table,
    }
}

/// Evaluate chains into component chains (scalars against vectors: a literal 0 is the zero vector).
fn evaluate_chains<S: Scalar>(
    e: &Equation,
    chains: &[Vec<Form>],
    model: Model<S>,
    index: Option<usize>,
) -> Result<Vec<Chain<S>>, String> {
    let t = table();
    let model = std::rc::Rc::new(model);
    let mut out = Vec::new();
    for (ci, chain) in chains.iter().enumerate() {
        let mut vals = Vec::new();
        for f in chain {
            let v = evaluate(&f.expr, &ctx(e, &model, f.milne, index, t))
                .map_err(|err| format!("'{}': {err}", f.text))?;
            vals.push(v);
        }
        let width = vals.iter().map(|v| v.components().len()).max().unwrap_or(1);
        let comps: Vec<Vec<S>> = vals
            .iter()
            .map(|v| match v {
                Value::Scalar(x) if width == 3 => vec![x.clone(), x.clone(), x.clone()],
                _ => v.components(),
            })
            .collect();
        for k in 0..width {
            out.push(
                chain
                    .iter()
                    .zip(&comps)
                    .enumerate()
                    .map(|(j, (f, c))| Side {
                        label: LABELS[(chain_offset(chains, ci) + j).min(LABELS.len() - 1)],
                        value: c[k].clone(),
                        role: f.role,
                    })
                    .collect(),
            );
        }
    }
    Ok(out)
}

/// The additive terms of a form (so a Rust side may name one term of a printed sum, like
/// Milne's v' in v = V + v').
fn terms(e: &Expr, out: &mut Vec<Expr>) {
    match e {
        Expr::Add(a, b) | Expr::Sub(a, b) => {
            terms(a, out);
            terms(b, out);
        }
        _ => out.push(e.clone()),
    }
}

/// The chains of every form's additive terms (each term alone), for matching Rust forms.
fn term_chains(chains: &[Vec<Form>]) -> Vec<Vec<Form>> {
    chains
        .iter()
        .flatten()
        .map(|f| {
            let mut t = Vec::new();
            terms(&f.expr, &mut t);
            t.into_iter()
                .map(|expr| Form {
                    expr,
                    text: f.text.clone(),
                    role: Role::Printed,
                    milne: f.milne,
                })
                .collect()
        })
        .collect()
}

fn chain_offset(chains: &[Vec<Form>], ci: usize) -> usize {
    chains[..ci].iter().map(Vec::len).sum()
}

/// The form a label names.
fn form_text<'a>(chains: &'a [Vec<Form>], label: &str) -> &'a str {
    let k: usize = label.trim_start_matches("form ").parse().unwrap_or(1);
    chains
        .iter()
        .flatten()
        .nth(k - 1)
        .map_or("?", |f| f.text.as_str())
}

/// Check the print of one display on its registry samples.
pub fn check_print(e: &Equation, latex: &str, cfg: &Config) -> PrintReport {
    check_print_with(e, latex, cfg, MISPRINTS)
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
            let ((sys, p), _) = super::sample::float_particles(sort, &raw);
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
                let draw = super::check::exact_ladder_draw(&mut rng);
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
                let ((sys, p), (sysb, pb)) = super::sample::float_particles(sort, &raw);
                let v = evaluate_chains(e, &chains, Model::particles(sys, p), None);
                let b = evaluate_chains(e, &chains, Model::particles(sysb, pb), None);
                note_float(v, b, &mut worst, &mut float_failures);
            }
            for k in 0..cfg.exact_points.min(PRINT_EXACT_POINTS) {
                let (n, values) = super::check::exact_particle_draw(&mut rng);
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
            "print: {float_failures} of {float_cases} float states out of tolerance; worst {:.3e} × bound at {} '{}'",
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
pub fn sample_check(e: &Equation) -> Option<&super::Check> {
    let from_rest =
        |c: &&super::Check| matches!(c.eval, Eval::Ladder(LadderSample::OnShellFromRest, _));
    let on_shell = |c: &&super::Check| matches!(c.eval, Eval::Ladder(s, _) if s.on_shell());
    if e.kind == super::Kind::OnShell {
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
