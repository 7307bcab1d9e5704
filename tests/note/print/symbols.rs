//! Tests of `sliding_ladder::print::symbols` (src/print/symbols.rs).

use sliding_ladder::print::symbols::{lookup, parse_table, table};

#[test]
fn shipped_table_parses_and_has_units() {
    let t = table();
    assert!(t.len() > 40);
    for e in t {
        assert!(!e.dimension.is_empty() && !e.unit.is_empty(), "{}", e.latex);
        assert!(
            !e.defined.is_empty() && !e.meaning.is_empty(),
            "{}",
            e.latex
        );
    }
}

#[test]
fn section_specific_and_milne_entries_win() {
    let text = r#"
[[symbol]]
latex = 'L'
quantity = "a"
meaning = "x"
defined = "x"
dimension = "1"
unit = "1"
[[symbol]]
latex = 'L'
quantity = "b"
meaning = "x"
defined = "x"
dimension = "1"
unit = "1"
sections = ["A.5"]
[[symbol]]
latex = 'L'
quantity = "c"
meaning = "x"
defined = "x"
dimension = "1"
unit = "1"
milne = true
"#;
    let t = parse_table(text).unwrap();
    assert_eq!(lookup(&t, "L", "2.1", 1, false).unwrap().quantity, "a");
    assert_eq!(lookup(&t, "L", "A.5", 1, false).unwrap().quantity, "b");
    assert_eq!(lookup(&t, "L", "A.50", 1, false).unwrap().quantity, "a");
    assert_eq!(lookup(&t, "L", "B.1", 1, true).unwrap().quantity, "c");
    assert!(parse_table("[[symbol]]\nlatex = 'a + b'\nquantity='q'\nmeaning='m'\ndefined='d'\ndimension='1'\nunit='1'").is_err());
}
