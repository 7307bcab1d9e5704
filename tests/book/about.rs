//! Tests of `sliding_ladder::book::about` (src/book/about.rs).

use sliding_ladder::book::about::{join_relative, page_name};

#[test]
fn page_name_keeps_the_folder_below_docs() {
    assert_eq!(page_name("docs/EXTENDING.md"), "about-extending.html");
    assert_eq!(
        page_name("docs/mutation/MUTATION-SIM-2.md"),
        "about-mutation-mutation-sim-2.html"
    );
}

#[test]
fn join_relative_resolves_dots_and_refuses_to_leave_the_root() {
    assert_eq!(
        join_relative("equations", "../docs/UNITS.md").as_deref(),
        Some("docs/UNITS.md")
    );
    assert_eq!(
        join_relative("docs/mutation", "./MUTATION.md").as_deref(),
        Some("docs/mutation/MUTATION.md")
    );
    assert_eq!(
        join_relative("docs", "../src/lib.rs").as_deref(),
        Some("src/lib.rs")
    );
    assert_eq!(join_relative("docs", "../../etc/passwd"), None);
}
