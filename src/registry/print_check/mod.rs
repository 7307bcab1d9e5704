//! The print as the thing checked: every display's LaTeX parsed ([`crate::print`]), each chain of
//! printed forms evaluated on the registry's own samples and held equal with the registry's own
//! verdicts (float within the running error bound, exact with zero residual), and every Rust
//! form's value held against the parsed forms.
//!
//! Per display: statements become chains; Milne's statement k joins our statement k (his names
//! denote our quantities, so every form must agree); `X = \text{const}` is checked as
//! d/dt X = 0; of `premise \Rightarrow conclusion` only the conclusion is claimed, on the states
//! changed so that the premise holds ([`premises`]); an evaluation bar `|_{a=b}` is a
//! substitution made by the evaluator ([`crate::print::condition`]), never a claim about the
//! sample. A form recorded as a misprint ([`misprints`]) must differ.

use super::{Chain, Equation, Role, Side};
use crate::print::ast::{Chain as PChain, Expr};
use crate::print::eval::{evaluate, Ctx};
use crate::print::quantity::{Model, Value};
use crate::print::symbols::Entry;
use crate::scalar::Scalar;
use serde::Serialize;

/// Misprinted forms (display, the form's LaTeX as printed): they must fail against the chain.
/// Derived from each erratum's `*Misprint:*` and `*Corrected:*` lines in the markdown: the forms
/// of the printed statement that the correction does not have.
pub fn misprints() -> Vec<(u32, &'static str)> {
    crate::registry::source::current()
        .sections
        .iter()
        .filter_map(|s| Some((s.number, s.erratum.as_ref()?)))
        .flat_map(|(n, e)| {
            crate::registry::source::misprinted_forms(&e.printed, &e.corrected)
                .into_iter()
                .map(move |f| (n, f))
        })
        .collect()
}

/// The form a display continues when it begins with `=` ((57) continues (56)'s chain from its
/// last form τ_P), from the note in use.
pub fn continuation(number: u32) -> Option<&'static str> {
    crate::registry::source::current()
        .section(number)?
        .continues
        .as_deref()
}

const LABELS: [&str; 24] = [
    "form 1", "form 2", "form 3", "form 4", "form 5", "form 6", "form 7", "form 8", "form 9",
    "form 10", "form 11", "form 12", "form 13", "form 14", "form 15", "form 16", "form 17",
    "form 18", "form 19", "form 20", "form 21", "form 22", "form 23", "form 24",
];

/// The label of the form at 0-based place `k` of a display, "form k+1", as `ladder show`
/// numbers them. A side's label is `&'static str`: the first 24 are constants, and a display
/// longer than any of the note's gets each further label made once and kept for the run (until
/// this, every form after the 24th was reported as "form 24").
pub fn form_label(k: usize) -> &'static str {
    if let Some(l) = LABELS.get(k) {
        return l;
    }
    static MORE: std::sync::Mutex<Vec<&'static str>> = std::sync::Mutex::new(Vec::new());
    let mut more = MORE
        .lock()
        .unwrap_or_else(std::sync::PoisonError::into_inner);
    while more.len() <= k - LABELS.len() {
        let n = LABELS.len() + more.len() + 1;
        more.push(Box::leak(format!("form {n}").into_boxed_str()));
    }
    more[k - LABELS.len()]
}

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
    /// On-shell print: whether it failed at every exact point off the motion, as it must.
    pub off_shell_fails: Option<bool>,
    /// On-shell print: the `=` at which it breaks off the motion, when the same at every point.
    pub off_motion_breaks: Option<Vec<u32>>,
    /// Float states the print was evaluated at (counted as each is evaluated).
    pub float_cases: usize,
    /// Exact points the print was evaluated at (on the motion; counted as each is evaluated).
    pub exact_points: usize,
    /// Of those, the points where some chain's residual was not zero.
    pub exact_failures: usize,
    /// The largest degree of a residual of its chains (Schwartz-Zippel).
    pub degree: u32,
}

/// The chains of a display's print, ready to evaluate.
pub fn print_chains(number: u32, latex: &str) -> Result<(usize, Vec<Vec<Form>>), String> {
    print_chains_with(number, latex, &misprints())
}

/// [`print_chains`] with a given list of misprinted forms.
pub fn print_chains_with(
    number: u32,
    latex: &str,
    misprint_list: &[(u32, &str)],
) -> Result<(usize, Vec<Vec<Form>>), String> {
    let continued = continuation(number);
    let src = match continued {
        Some(prefix) => format!("{prefix} {latex}"),
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
    let mut alone: Vec<Vec<Form>> = Vec::new();
    let mut milne_k = 0;
    let mut count = d.form_count();
    if continued.is_some() {
        count -= 1; // the continued form belongs to the display before
    }
    for st in &d.statements {
        // `premise ⇒ conclusion`: the conclusion is claimed where the premise holds; the
        // premise is claimed nowhere.
        let chain = match &st.implies {
            Some(concl) => {
                // Each form of the premise a chain of its own: evaluated (shown, unit-checked,
                // matched against the Rust forms), never held equal to anything.
                alone.extend(forms(&st.chain, st.milne).into_iter().map(|f| vec![f]));
                premises::under(&st.chain.forms, constant(forms(concl, st.milne)))
            }
            None => constant(forms(&st.chain, st.milne)),
        };
        if st.milne && milne_k < ours.len() {
            ours[milne_k].extend(chain);
            milne_k += 1;
        } else {
            ours.push(chain);
        }
    }
    // After every statement, so that Milne's statement k still finds our statement k.
    ours.extend(alone);
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
pub(crate) fn evaluate_chains<S: Scalar>(
    e: &Equation,
    chains: &[Vec<Form>],
    model: Model<S>,
    index: Option<usize>,
) -> Result<Vec<Chain<S>>, String> {
    let t = crate::registry::symbol_table();
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
                        label: form_label(chain_offset(chains, ci) + j),
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
pub(crate) fn term_chains(chains: &[Vec<Form>]) -> Vec<Vec<Form>> {
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
pub(crate) fn form_text<'a>(chains: &'a [Vec<Form>], label: &str) -> &'a str {
    let k: usize = label.trim_start_matches("form ").parse().unwrap_or(1);
    chains
        .iter()
        .flatten()
        .nth(k - 1)
        .map_or("?", |f| f.text.as_str())
}

mod independent;
mod inject;
mod motion;
pub mod premises;
pub mod prove;
mod run;
pub mod symbol_check;
pub mod twins;
pub mod units;
pub use crate::registry::sample::PrintSample;
pub use inject::{injections, run_injection, Detection, Injection, Typo};
pub use motion::OFF_MOTION_POINTS;
pub use run::{
    check_print, check_print_with, print_sample, sample_check, PRINT_EXACT_POINTS,
    PRINT_FLOAT_CASES,
};
