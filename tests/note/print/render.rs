//! Tests of `sliding_ladder::print::render` (src/print/render.rs).

use sliding_ladder::print::parser::parse_expr;
use sliding_ladder::print::unicode::unicode;

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
    let wrong = sliding_ladder::print::ast::Expr::Mul(
        Box::new(parse_expr("a + b").unwrap()),
        Box::new(parse_expr("c").unwrap()),
    );
    assert_eq!(wrong.to_latex(), "(a + b) c");
}
