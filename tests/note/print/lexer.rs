//! Tests of `sliding_ladder::print::lexer` (src/print/lexer.rs).

use sliding_ladder::print::lexer::{lex, Tok};

#[test]
fn layout_is_dropped_and_bars_kept() {
    let t = lex(r"\begin{aligned} a &= \left(b\right) \Big|_{x} \\ \end{aligned}").unwrap();
    assert_eq!(
        t,
        vec![
            Tok::Letter('a'),
            Tok::Punct('='),
            Tok::Punct('('),
            Tok::Letter('b'),
            Tok::Punct(')'),
            Tok::Bar,
            Tok::Punct('_'),
            Tok::Punct('{'),
            Tok::Letter('x'),
            Tok::Punct('}'),
            Tok::RowBreak,
        ]
    );
    assert!(lex("a # b").is_err());
}
