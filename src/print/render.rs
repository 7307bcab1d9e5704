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

#[cfg(test)]
mod tests {
    use crate::print::parser::parse_expr;
    use crate::print::unicode::unicode;

    /// A form read back: parse, render, parse again gives the same tree, and the Unicode
    /// reading is the one a reader expects. A wrong precedence (a sum in a product without its
    /// parentheses) would change the reparsed tree.
    #[test]
    fn a_form_renders_back_to_the_same_tree() {
        for src in [
            r"\frac{m l^2 \dot{\theta}}{3} \hat{\mathbf{z}} + l^2 \dot{\theta} (\cos^2 \theta - \sin^2 \theta) \hat{\mathbf{z}}",
            r"m l g \sin \theta - m l \sin^2 \theta \ddot{\theta} - m l \cos \theta \sin \theta \dot{\theta}^2",
            r"-\frac{2ml^2 \dot{\theta}}{3}",
            r"a - (b - c)",
            r"\sum_i m_i \mathbf{x}_i \times \mathbf{v}_i",
        ] {
            let e = parse_expr(src).unwrap();
            let back = e.to_latex();
            assert_eq!(parse_expr(&back).unwrap(), e, "{src} -> {back}");
        }
        let e = parse_expr(r"m l^2 \dot{\theta} + l^2 \dot{\theta}").unwrap();
        assert_eq!(unicode(&e.to_latex()), "ml²θ̇ + l²θ̇");
        let wrong = crate::print::ast::Expr::Mul(
            Box::new(parse_expr("a + b").unwrap()),
            Box::new(parse_expr("c").unwrap()),
        );
        assert_eq!(wrong.to_latex(), "(a + b) c");
    }
}
