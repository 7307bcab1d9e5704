//! Where a printed form's units clash: the innermost sum (or difference) of the form whose two
//! operands each have one dimension, but not the same one.
//!
//! The form is evaluated in [`Dim`], whose inconsistent value records the two dimensions but not
//! the terms; the terms are found here by evaluating subtrees in the same context: descend into
//! the operand that is inconsistent, and stop at the sum whose operands are both consistent.
//! A subtree under d/dt or ∂ is evaluated unlifted (its value part has the operand's own
//! dimension, so a clash there is already a clash of the operand); a subtree under Σ at the
//! first particle (every particle has the same dimensions).
//!
//! A tuple (a vector written by components) is the one place a clash can hide: its components
//! are never added, and a cross product with a zero component may drop the bad one, so
//! [`unlike_components`] checks every tuple of the form for components of unlike dimensions.

use super::ast::Expr;
use super::eval::{evaluate, Ctx};
use crate::scalar::{Dim, Dimension};

/// The offending sum of a form and the dimensions of its two operands.
#[derive(Clone, Debug, PartialEq)]
pub struct UnlikeSum {
    /// The sum, as an expression tree (render with [`Expr::to_latex`]).
    pub sum: Expr,
    /// The dimension of its left operand.
    pub left: Dimension,
    /// The dimension of its right operand.
    pub right: Dimension,
    /// `+` or `−`.
    pub op: &'static str,
}

/// The dimension of a subtree, when it evaluates: one per component.
fn dims(e: &Expr, ctx: &Ctx<Dim>) -> Option<Vec<Dim>> {
    evaluate(e, ctx).ok().map(|v| v.components())
}

fn inconsistent(e: &Expr, ctx: &Ctx<Dim>) -> bool {
    dims(e, ctx).is_some_and(|d| d.iter().any(|x| x.inconsistency().is_some()))
}

/// One dimension of a consistent subtree (`None` for an exact zero or no value).
fn dimension(e: &Expr, ctx: &Ctx<Dim>) -> Option<Dimension> {
    dims(e, ctx)?.iter().find_map(Dim::dimension)
}

/// The first tuple of `e` whose components have unlike dimensions: the tuple and two of them.
pub fn unlike_components(e: &Expr, ctx: &Ctx<Dim>) -> Option<(Expr, Dimension, Dimension)> {
    use Expr::*;
    match e {
        Tuple(items) => {
            if let Some(found) = items.iter().find_map(|x| unlike_components(x, ctx)) {
                return Some(found);
            }
            let mut known = items.iter().filter_map(|x| dimension(x, ctx));
            let first = known.next()?;
            known.find(|d| *d != first).map(|d| (e.clone(), first, d))
        }
        Add(a, b) | Sub(a, b) | Mul(a, b) | Div(a, b) | Cross(a, b) => {
            unlike_components(a, ctx).or_else(|| unlike_components(b, ctx))
        }
        Neg(a) | Pow(a, _) | ZComp(a) | Deriv(a) | Partial(a, _) | Sin(a) | Cos(a) => {
            unlike_components(a, ctx)
        }
        At(a, conds) => unlike_components(a, ctx)
            .or_else(|| conds.iter().find_map(|c| unlike_components(c, ctx))),
        Sum(a) => unlike_components(a, &first_particle(ctx)),
        Int(_) | Sym(_) | Const => None,
    }
}

fn first_particle<'t>(ctx: &Ctx<'t, Dim>) -> Ctx<'t, Dim> {
    Ctx {
        model: ctx.model.clone(),
        section: ctx.section,
        number: ctx.number,
        milne: ctx.milne,
        index: Some(0),
        table: ctx.table,
    }
}

/// The innermost sum of `e` whose operands have unlike dimensions, if `e` is inconsistent
/// because of one.
pub fn unlike_sum(e: &Expr, ctx: &Ctx<Dim>) -> Option<UnlikeSum> {
    use Expr::*;
    if !inconsistent(e, ctx) {
        return None;
    }
    match e {
        Add(a, b) | Sub(a, b) => {
            for x in [a, b] {
                if inconsistent(x, ctx) {
                    return unlike_sum(x, ctx);
                }
            }
            Some(UnlikeSum {
                sum: e.clone(),
                left: dimension(a, ctx)?,
                right: dimension(b, ctx)?,
                op: if matches!(e, Add(..)) { "+" } else { "−" },
            })
        }
        Mul(a, b) | Div(a, b) | Cross(a, b) => [a, b]
            .into_iter()
            .find(|x| inconsistent(x, ctx))
            .and_then(|x| unlike_sum(x, ctx)),
        Neg(a) | Pow(a, _) | ZComp(a) | Deriv(a) | Partial(a, _) | At(a, _) | Sin(a) | Cos(a) => {
            unlike_sum(a, ctx)
        }
        Sum(a) => unlike_sum(a, &first_particle(ctx)),
        Tuple(items) => items.iter().find_map(|x| unlike_sum(x, ctx)),
        Int(_) | Sym(_) | Const => None,
    }
}
