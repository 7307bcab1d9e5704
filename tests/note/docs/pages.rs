//! Tests of `sliding_ladder::docs::pages` (src/docs/pages.rs).

use sliding_ladder::docs::pages::headings;
use std::path::Path;

#[test]
fn headings_are_found_by_label_with_file_and_line() {
    let dir = std::env::temp_dir().join(format!("ladder-pages-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    std::fs::write(
        dir.join("b.md"),
        "# B\n\ntext (7)\n### (7) Seven\n### (P2) Two\n",
    )
    .unwrap();
    std::fs::write(dir.join("a.md"), "x\n## (7) First seven\n").unwrap();
    std::fs::write(dir.join("c.txt"), "### (9) not markdown\n").unwrap();
    let h = headings(&dir);
    std::fs::remove_dir_all(&dir).ok();
    assert_eq!(h["(7)"].file, "equations/a.md");
    assert_eq!(h["(7)"].line, 2);
    assert_eq!(h["(P2)"].line, 5);
    assert_eq!(h["(P2)"].heading, "(P2) Two");
    assert!(!h.contains_key("(9)"));
    assert!(headings(Path::new("/nonexistent/ladder")).is_empty());
}

#[test]
fn the_books_torque_analysis_about_d_is_in_its_section_file() {
    let h = headings(&sliding_ladder::docs::default_dir());
    assert_eq!(h["(25)"].file, "equations/05-point-d.md");
    assert!(h["(25)"]
        .heading
        .starts_with("(25) Torque analysis about D"));
    assert_eq!(h["(P1)"].file, "equations/phase2.md");
    assert_eq!(
        sliding_ladder::registry::equations()
            .iter()
            .filter(|e| h.contains_key(&e.label()))
            .count(),
        sliding_ladder::registry::equations().len()
    );
}
