//! Tests of `sliding_ladder::book::code` (src/book/code.rs).

use sliding_ladder::book::code::{crate_root, fn_line, locate};

#[test]
fn every_registered_function_is_found_at_its_fn_item() {
    let root = crate_root();
    let all = sliding_ladder::registry::equations()
        .into_iter()
        .chain(sliding_ladder::registry::extensions());
    for e in all {
        for f in e.functions {
            let loc = locate(&root, f).unwrap_or_else(|| panic!("{}: {f} not found", e.label()));
            let src = std::fs::read_to_string(root.join(&loc.file)).unwrap();
            let line = src.lines().nth(loc.line - 1).unwrap();
            let name = f.rsplit("::").next().unwrap();
            assert!(
                line.contains(&format!("fn {name}")),
                "{f}: line {} is `{line}`",
                loc.line
            );
        }
    }
}

#[test]
fn a_name_that_is_only_a_prefix_or_absent_is_not_found() {
    let src = "pub fn wall_force_via(x: f64) {}\nfn other() {}\n";
    assert_eq!(fn_line(src, "wall_force"), None);
    assert_eq!(fn_line(src, "other"), Some(2));
    assert_eq!(
        locate(&crate_root(), "ladder::torque::no_such_function"),
        None
    );
}
