//! The print in dimensions (issue 14): every parsed printed form of a display evaluated in
//! [`Dim`] on the same model its values are checked on, with the symbols given their
//! dimensions by the registry's dimensioned samplers ([`crate::registry::units`]).
//!
//! Every form must have one dimension (no sum of unlike terms: the offending sum is named, as
//! a reader would write it, by [`crate::print::clash`]) and every form of a chain the chain's
//! dimension. A recorded misprint ([`super::misprints`]) that fails this is the erratum's
//! witness in units; any other form that fails it is a defect of the print's check, like a
//! residual. `ladder verify` (its `units` column) and `ladder show` (each form's SI unit) both
//! read this module, so the two cannot disagree.

use super::{form_label, print_chains, print_sample, Form, PrintSample};
use crate::print::clash::{unlike_components, unlike_sum};
use crate::print::eval::{evaluate, Ctx};
use crate::print::quantity::Model;
use crate::print::unicode::unicode;
use crate::registry::units::{dimensioned_ladder, dimensioned_particles, UnitsFindings, PARTICLES};
use crate::registry::{Equation, Role};
use crate::scalar::{Clash, Dim, Dimension};
use std::rc::Rc;

/// One printed form in dimensions.
#[derive(Clone, Debug)]
pub struct FormUnits {
    /// Its place in the print, from 1 over every chain (as `ladder show` numbers the forms).
    pub index: usize,
    /// The form as printed (canonical LaTeX).
    pub text: String,
    /// Printed or misprint.
    pub role: Role,
    /// Its dimension (zero: of any dimension), or why it could not be evaluated.
    pub dim: Result<Dim, String>,
    /// When inconsistent: what clashed, in words (`m l² θ̇ + l² θ̇ (M L² T⁻¹ + L² T⁻¹)`).
    pub clash: Option<String>,
}

impl FormUnits {
    /// The form's SI unit, `any (zero)`, `inconsistent: …` or `? (why)`.
    pub fn unit(&self) -> String {
        match (&self.dim, &self.clash) {
            (_, Some(c)) => format!("inconsistent: {c}"),
            (Ok(d), None) => d
                .dimension()
                .map_or_else(|| "any (zero)".into(), Dimension::si_unit),
            (Err(err), None) => format!("? ({err})"),
        }
    }
}

/// The model of a display with its symbols' dimensions (the sample its print is checked on).
pub fn dimensioned_model(e: &Equation) -> Result<Model<Dim>, String> {
    match print_sample(e) {
        Some(PrintSample::Ladder(sort)) => {
            let (l, s) = dimensioned_ladder(sort);
            Ok(Model::ladder(l, s))
        }
        Some(PrintSample::Particles(sort)) => {
            let (sys, p) = dimensioned_particles(sort, PARTICLES);
            Ok(Model::particles(sys, p))
        }
        None => Err("no model for this display".into()),
    }
}

/// One form in dimensions.
fn form_units(e: &Equation, f: &Form, model: &Rc<Model<Dim>>, index: usize) -> FormUnits {
    let ctx = Ctx {
        model: model.clone(),
        section: e.section,
        number: e.number,
        milne: f.milne,
        index: None,
        table: crate::registry::symbol_table(),
    };
    let dim = evaluate(&f.expr, &ctx).map(|v| {
        let c = v.components();
        // A vector's components share one dimension; a zero component (z in the plane) any.
        if let Some(bad) = c.iter().find(|d| d.inconsistency().is_some()) {
            return bad.clone();
        }
        let mut known = c.iter().filter_map(Dim::dimension);
        match known.next() {
            Some(d) => match known.find(|x| *x != d) {
                Some(other) => Dim::clash(Clash::Unlike {
                    op: ",",
                    left: d,
                    right: other,
                }),
                None => Dim::Of(d),
            },
            None => Dim::Zero,
        }
    });
    // A tuple whose components have unlike dimensions, hidden from the value (see clash.rs).
    let dim = dim.map(|d| match (&d, unlike_components(&f.expr, &ctx)) {
        (Dim::Inconsistent(_), _) | (_, None) => d,
        (_, Some((_, left, right))) => Dim::clash(Clash::Unlike {
            op: ",",
            left,
            right,
        }),
    });
    let clash = match &dim {
        Ok(Dim::Inconsistent(i)) => Some(match unlike_sum(&f.expr, &ctx) {
            None if matches!(i.clash, Clash::Unlike { op: ",", .. }) => {
                match unlike_components(&f.expr, &ctx) {
                    Some((t, l, r)) => format!(
                        "components {l} and {r} in the vector {}",
                        unicode(&t.to_latex())
                    ),
                    None => i.to_string(),
                }
            }
            Some(u) => format!(
                "{} ({} {} {})",
                unicode(&u.sum.to_latex()),
                u.left,
                u.op,
                u.right
            ),
            None => i.to_string(),
        }),
        _ => None,
    };
    FormUnits {
        index,
        text: f.text.clone(),
        role: f.role,
        dim,
        clash,
    }
}

/// Every printed form of `e` (given as LaTeX) in dimensions, in print order, by chain.
pub fn print_form_units(e: &Equation, latex: &str) -> Result<Vec<Vec<FormUnits>>, String> {
    let (_, chains) = print_chains(e.number, latex)?;
    let model = Rc::new(dimensioned_model(e)?);
    let mut index = 0;
    Ok(chains
        .iter()
        .map(|chain| {
            chain
                .iter()
                .map(|f| {
                    index += 1;
                    form_units(e, f, &model, index)
                })
                .collect()
        })
        .collect())
}

/// Judge the print of `e` in dimensions: each form consistent, each chain of one dimension.
pub fn print_units(e: &Equation, latex: &str) -> Result<UnitsFindings, String> {
    Ok(judge_forms(&print_form_units(e, latex)?))
}

/// Judge forms in dimensions (see the module docs); misprints are recorded, not problems.
pub fn judge_forms(chains: &[Vec<FormUnits>]) -> UnitsFindings {
    let mut out = UnitsFindings::default();
    let name = |f: &FormUnits| format!("form {} ({})", f.index, unicode(&f.text));
    for chain in chains {
        let base = chain
            .iter()
            .filter(|f| f.role != Role::Misprint)
            .find_map(|f| f.dim.as_ref().ok()?.dimension().map(|d| (d, f)));
        for f in chain {
            let finding = match (&f.dim, &f.clash, base) {
                (Err(err), _, _) => {
                    Some(format!("{}: not evaluated in dimensions: {err}", name(f)))
                }
                (_, Some(c), _) => Some(format!("inconsistent: {c} in form {}", f.index)),
                (Ok(Dim::Of(d)), None, Some((b, bf))) if *d != b => Some(format!(
                    "{} has dimension {d}, {} has {b}",
                    name(f),
                    name(bf)
                )),
                _ => None,
            };
            if f.role == Role::Misprint {
                out.misprints.push((form_label(f.index - 1), finding));
            } else if let Some(p) = finding {
                out.problems.push(p);
            }
        }
        out.dimensions.push(base.map(|b| b.0));
    }
    out
}
