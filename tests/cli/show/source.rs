//! Tests of `sliding_ladder::show::source` (src/show/source.rs).

use sliding_ladder::show::source::{docs_page, function, root};

#[test]
fn functions_and_pages_are_found_at_their_lines() {
    let f = function("ladder::torque::eq25_torque_analysis_d");
    let line = f.line.expect("found");
    let text = std::fs::read_to_string(root().join(&f.file)).unwrap();
    assert!(text
        .lines()
        .nth(line - 1)
        .unwrap()
        .contains("fn eq25_torque_analysis_d"));
    assert!(function("ladder::torque::no_such_function").line.is_none());
    let p = docs_page(25).expect("page");
    assert_eq!(p.file, "equations/05-point-d.md");
    assert!(p.name.starts_with("(25)"));
    // (2) must not be found at the heading of (25).
    assert!(docs_page(2).unwrap().name.starts_with("(2)"));
}
