//! An expression tree back to LaTeX, so a report can quote a part of a printed form (the sum
//! whose terms have unlike units, [`super::clash`]) that has no span of its own in the print.
//!
//! The output is the note's vocabulary again (symbol keys are canonical LaTeX already), with
//! parentheses only where the tree needs them; [`super::unicode::unicode`] reads it for a
//! terminal. It is not the printed text verbatim (spacing and redundant parentheses are lost).

use super::ast::Expr;

impl Expr {
    /// This expression as LaTeX.
    pub fn to_latex(&self) -> String {
        latex(self)
    }
}

/// A sum or difference needs parentheses inside a product, a power or a negation.
fn is_sum(e: &Expr) -> bool {
    matches!(e, Expr::Add(..) | Expr::Sub(..))
}

fn grouped(e: &Expr) -> String {
    if is_sum(e) || matches!(e, Expr::Neg(_)) {
        format!("({})", latex(e))
    } else {
        latex(e)
    }
}

fn latex(e: &Expr) -> String {
    use Expr::*;
    match e {
        Int(n) => n.to_string(),
        Sym(k) => k.clone(),
        Const => r"\text{const}".into(),
        Neg(a) => format!("-{}", grouped(a)),
        Add(a, b) => format!("{} + {}", latex(a), latex(b)),
        Sub(a, b) => format!("{} - {}", latex(a), grouped(b)),
        Mul(a, b) => format!("{} {}", grouped(a), grouped(b)),
        Div(a, b) => format!(r"\frac{{{}}}{{{}}}", latex(a), latex(b)),
        Pow(a, n) => match &**a {
            Sin(x) => format!(r"\sin^{n} {}", latex(x)),
            Cos(x) => format!(r"\cos^{n} {}", latex(x)),
            Int(_) | Sym(_) | Tuple(_) => format!("{}^{n}", latex(a)),
            _ => format!("({})^{n}", latex(a)),
        },
        Cross(a, b) => format!(r"{} \times {}", grouped(a), grouped(b)),
        Sin(a) => format!(r"\sin {}", grouped(a)),
        Cos(a) => format!(r"\cos {}", grouped(a)),
        Tuple(items) => format!(
            "({})",
            items.iter().map(latex).collect::<Vec<_>>().join(", ")
        ),
        Sum(a) => format!(r"\sum_i {}", grouped(a)),
        Deriv(a) => format!(r"\frac{{d}}{{dt}} {}", grouped(a)),
        Partial(a, v) => format!(r"\frac{{\partial}}{{\partial {v}}} {}", grouped(a)),
        ZComp(a) => format!("({})|_z", latex(a)),
        At(a, conds) => format!(
            r"{}\Big|_{{{}}}",
            grouped(a),
            conds.iter().map(latex).collect::<Vec<_>>().join(" = ")
        ),
    }
}
