//! Tests of `sliding_ladder::print::parser` (src/print/parser.rs).

use sliding_ladder::print::ast::Expr;
use sliding_ladder::print::parser::{parse_display, parse_expr};

fn sym(s: &str) -> Box<Expr> {
    Box::new(Expr::Sym(s.into()))
}

#[test]
fn implicit_products_powers_and_trig() {
    let e = parse_expr(r"2ml^2\cos^2\theta\ddot{\theta}").unwrap();
    let want = Expr::Mul(
        Box::new(Expr::Mul(
            Box::new(Expr::Mul(
                Box::new(Expr::Mul(Box::new(Expr::Int(2)), sym("m"))),
                Box::new(Expr::Pow(sym("l"), 2)),
            )),
            Box::new(Expr::Pow(Box::new(Expr::Cos(sym("\\theta"))), 2)),
        )),
        sym("\\ddot{\\theta}"),
    );
    assert_eq!(e, want);
    // A different coefficient parses to a different tree.
    assert_ne!(parse_expr(r"3ml^2\cos^2\theta\ddot{\theta}").unwrap(), want);
}

#[test]
fn derivatives_and_symbols() {
    assert_eq!(
        parse_expr(r"\frac{dL_A}{dt}").unwrap(),
        Expr::Deriv(sym("L_{A}"))
    );
    assert_eq!(
        parse_expr(r"\frac{\partial \mathcal{L}}{\partial \dot{\theta}}").unwrap(),
        Expr::Partial(sym("\\mathcal{L}"), "\\dot{\\theta}".into())
    );
    assert_eq!(
        parse_expr(r"\mathbf{L}'_P").unwrap(),
        Expr::Sym("\\mathbf{L}'_{P}".into())
    );
    assert_eq!(
        parse_expr(r"\mathbf{H}_r(O)").unwrap(),
        Expr::Sym("\\mathbf{H}_{r}(O)".into())
    );
    assert_eq!(
        parse_expr(r"\frac{ml^2}{3}").unwrap(),
        Expr::Div(
            Box::new(Expr::Mul(sym("m"), Box::new(Expr::Pow(sym("l"), 2)))),
            Box::new(Expr::Int(3))
        )
    );
}

#[test]
fn displays_split_into_statements() {
    let d = parse_display(r"x = l \sin \theta, \quad \text{Milne : } y = 2").unwrap();
    assert_eq!(d.statements.len(), 2);
    assert!(d.statements[1].milne && !d.statements[0].milne);
    let d = parse_display(r"\mathbf{F} = 0 \Rightarrow \mathbf{P} = \text{const}").unwrap();
    assert!(d.statements[0].implies.is_some());
    assert!(parse_display(r"a = (b").is_err());
}

#[test]
fn a_braced_power_parses_as_the_bare_one() {
    // The note prints l^2; a user's markdown may print l^{2} (ERRATA.md does): the same power.
    assert_eq!(parse_expr(r"l^{2}").unwrap(), Expr::Pow(sym("l"), 2));
    assert_eq!(
        parse_expr(r"m l^{2} \dot{\theta}").unwrap(),
        parse_expr(r"m l^2 \dot{\theta}").unwrap()
    );
    assert_ne!(
        parse_expr(r"l^{3}").unwrap(),
        parse_expr(r"l^2").unwrap(),
        "the power read inside the braces"
    );
    // Only an integer power: a symbol in the braces is refused, not read as something else.
    let err = parse_expr(r"l^{n}").unwrap_err();
    assert!(err.contains("integer power"), "{err}");
}

/// Only a bold capital takes a point in parentheses as part of its name (Milne's H(O), H(G′)):
/// a plain symbol before (C) is a product with C.
#[test]
fn symbol_takes_a_point_only_after_a_bold_capital() {
    assert_eq!(
        parse_expr(r"\mathbf{H}(O)").unwrap(),
        Expr::Sym("\\mathbf{H}(O)".into())
    );
    assert_eq!(
        parse_expr(r"\mathbf{H}(G')").unwrap(),
        Expr::Sym("\\mathbf{H}(G')".into())
    );
    assert_eq!(
        parse_expr(r"\tau(C)").unwrap(),
        Expr::Mul(sym("\\tau"), sym("C"))
    );
}

/// An aligned environment's row breaks and alignment marks carry no mathematics: a chain
/// broken over rows parses as the chain on one line, and so does a list of statements whose
/// rows end in commas.
#[test]
fn display_and_chain_skip_row_breaks() {
    let one_line = parse_display(r"x = l \sin \theta = 2y").unwrap();
    let aligned =
        parse_display(r"\begin{aligned} x &= l \sin \theta \\ &= 2y \end{aligned}").unwrap();
    assert_eq!(aligned, one_line);
    // A break after the relation, before the next form.
    let broken_after = parse_display(r"x = \\ l \sin \theta = \\ 2y").unwrap();
    assert_eq!(broken_after, one_line);
    let two = parse_display(r"x = l, \quad y = 2").unwrap();
    let rows = parse_display(r"\begin{aligned} x &= l, \\ \\ y &= 2 \end{aligned}").unwrap();
    assert_eq!(rows, two);
    assert_eq!(rows.statements.len(), 2);
}

/// A subscript in nested braces is read to its matching brace.
#[test]
fn group_text_reads_nested_braces_whole() {
    let e = parse_expr(r"x_{a{b}c} + y").unwrap();
    assert!(
        matches!(&e, Expr::Add(a, _) if **a == Expr::Sym("x_{a{b}c}".into())),
        "{e:?}"
    );
}

/// Milne's label is skipped wherever it stands: at the start of a display, and after a form
/// ending in a brace, as after a comma.
#[test]
fn skip_milne_passes_over_the_label_alone() {
    let after_comma = parse_display(r"x = \dot{y}, \quad \text{Milne : } y = 2").unwrap();
    let after_brace = parse_display(r"x = \dot{y} \quad \text{Milne : } y = 2").unwrap();
    assert_eq!(after_brace, after_comma);
    assert!(after_brace.statements[1].milne && !after_brace.statements[0].milne);
    let first = parse_display(r"\text{Milne : } y = 2").unwrap();
    assert_eq!(first.statements.len(), 1);
    assert!(first.statements[0].milne);
    assert_eq!(first.statements[0], after_comma.statements[1]);
}

/// A bracket is an evaluation bar only when `_{` follows it: `[x]_{x_P = 0}` is x evaluated at
/// the condition, `[x]\dot{y}` is the product x ẏ.
#[test]
fn factor_reads_a_bracket_as_a_bar_only_before_an_underscore_and_brace() {
    assert_eq!(parse_expr(r"[x]\dot{y}"), parse_expr(r"x\dot{y}"));
    assert!(matches!(parse_expr(r"[x]_{x_P = 0}"), Ok(Expr::At(..))));
}
