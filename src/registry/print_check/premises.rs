//! A display's premises in the check of its print ([`crate::registry::source::premises`]).
//!
//! The premises the display states or its prose assumes are imposed on every particle state its
//! print is checked at, and nothing more: the states are general draws changed only as the
//! premises require ([`crate::print::condition`]). The print's evaluation bars and implications
//! are imposed by the evaluator where they are printed, and each must be listed among the
//! premises, and each listed one printed: an edit that drops, changes or adds a bar or turns an
//! implication into a claim is then named even where the values cannot see it.

use super::{Equation, Form};
use crate::print::ast::{Display, Expr};
use crate::print::eval::{with_condition, Ctx};
use crate::print::quantity::Model;
use crate::registry::source::PremiseSource;
use crate::scalar::Scalar;
use crate::system::{Point, System};

/// The forms of a premise's condition `a = b = …`.
pub fn condition_forms(latex: &str) -> Result<Vec<Expr>, String> {
    let d = crate::print::parser::parse_display(latex)?;
    match d.statements.as_slice() {
        [st] if st.implies.is_none() && st.chain.forms.len() > 1 => Ok(st.chain.forms.clone()),
        _ => Err(format!("the premise ${latex}$ is not one condition a = b")),
    }
}

/// The model of a drawn particle state with the display's whole-display premises imposed.
pub fn premised<S: Scalar>(e: &Equation, sys: System<S>, p: Point<S>) -> Result<Model<S>, String> {
    let mut model = Model::particles(sys, p);
    for pr in e.premises.iter().filter(|p| p.source.whole_display()) {
        let Some(latex) = &pr.latex else { continue };
        let forms = condition_forms(latex)?;
        let ctx = Ctx {
            model: std::rc::Rc::new(model),
            section: e.section,
            number: e.number,
            milne: false,
            index: None,
            table: crate::registry::symbol_table(),
        };
        model = with_condition(&forms, &ctx).map_err(|err| format!("premise ${latex}$: {err}"))?;
    }
    Ok(model)
}

/// [`premised`], as the system and point a Rust chain function takes.
pub(crate) fn premised_parts<S: Scalar>(
    e: &Equation,
    (sys, p): (System<S>, Point<S>),
) -> Result<(System<S>, Point<S>), String> {
    match premised(e, sys, p)? {
        Model::Particles(sys, p, ..) => Ok((sys, p)),
        Model::Ladder { .. } => Err("a premise turned a particle system into the ladder".into()),
    }
}

/// An implication's conclusion, evaluated where its premise holds: each form under the bar of
/// the premise's condition.
pub(super) fn under(premise: &[Expr], conclusion: Vec<Form>) -> Vec<Form> {
    conclusion
        .into_iter()
        .map(|f| Form {
            expr: Expr::At(Box::new(f.expr), premise.to_vec()),
            ..f
        })
        .collect()
}

/// The print's bars and implications against the listed premises: one line per disagreement,
/// naming the form and the reason.
pub(crate) fn disagreements(e: &Equation, display: &Display) -> Vec<String> {
    let listed = |source: PremiseSource| -> Vec<(Vec<Expr>, &str)> {
        e.premises
            .iter()
            .filter(|p| p.source == source)
            .filter_map(|p| {
                let latex = p.latex.as_deref()?;
                Some((condition_forms(latex).ok()?, latex))
            })
            .collect()
    };
    let (bars, implied) = (listed(PremiseSource::Bar), listed(PremiseSource::Implies));
    let mut printed_bars: Vec<(Vec<Expr>, String)> = Vec::new();
    let mut printed_premises: Vec<(Vec<Expr>, String)> = Vec::new();
    for st in &display.statements {
        let mut chains = vec![&st.chain];
        chains.extend(st.implies.as_ref());
        for c in chains {
            for (f, text) in c.forms.iter().zip(&c.texts) {
                let mut found = Vec::new();
                bars_of(f, &mut found);
                printed_bars.extend(found.into_iter().map(|b| (b, text.clone())));
            }
        }
        if st.implies.is_some() {
            printed_premises.push((st.chain.forms.clone(), st.chain.texts.join(" = ")));
        }
    }
    let mut out = Vec::new();
    for (cond, text) in &printed_bars {
        if !bars.iter().any(|b| &b.0 == cond) {
            out.push(format!(
                "print: the form '{text}' is evaluated at a condition that is not among the display's premises (*Premises:* bar): the bar changes what it states"
            ));
        }
    }
    for (cond, latex) in &bars {
        if !printed_bars.iter().any(|b| &b.0 == cond) {
            out.push(format!(
                "print: the premise ${latex}$ (bar) is printed nowhere: a form lost its evaluation bar, and with it the instant it is stated at"
            ));
        }
    }
    for (cond, text) in &printed_premises {
        if !implied.iter().any(|b| &b.0 == cond) {
            out.push(format!(
                "print: '{text} ⇒' is an implication whose premise is not among the display's premises (*Premises:* implies)"
            ));
        }
    }
    for (cond, latex) in &implied {
        if !printed_premises.iter().any(|b| &b.0 == cond) {
            out.push(format!(
                "print: the premise ${latex}$ (implies) is the left side of no printed ⇒: the implication became a claim"
            ));
        }
    }
    out.dedup();
    out
}

/// The conditions of every evaluation bar in a form.
fn bars_of(e: &Expr, out: &mut Vec<Vec<Expr>>) {
    use Expr::*;
    match e {
        At(a, conds) => {
            out.push(conds.clone());
            bars_of(a, out);
        }
        Neg(a) | Pow(a, _) | Sin(a) | Cos(a) | Sum(a) | Deriv(a) | Partial(a, _) | ZComp(a) => {
            bars_of(a, out)
        }
        Add(a, b) | Sub(a, b) | Mul(a, b) | Div(a, b) | Cross(a, b) => {
            bars_of(a, out);
            bars_of(b, out);
        }
        Tuple(v) => v.iter().for_each(|x| bars_of(x, out)),
        Int(_) | Sym(_) | Const => {}
    }
}
