//! Doc-as-test: the book in equations/ agrees with the registry, and malformed books are
//! reported as file:line problems, never a panic.

use sliding_ladder::docs::{check_book, default_dir};
use sliding_ladder::registry::printed_latex;
use std::path::PathBuf;

#[test]
fn the_book_agrees_with_the_registry() {
    let rep = check_book(&default_dir());
    assert!(
        rep.problems.is_empty(),
        "{} problems:\n{}",
        rep.problems.len(),
        rep.problems.join("\n")
    );
    assert_eq!(rep.equations_found, 90);
    assert!(
        rep.examples_run >= 10,
        "only {} example rows ran",
        rep.examples_run
    );
}

fn scratch(name: &str, files: &[(&str, String)]) -> PathBuf {
    let dir = std::env::temp_dir().join(format!("ladder-docs-{name}-{}", std::process::id()));
    let _ = std::fs::remove_dir_all(&dir);
    std::fs::create_dir_all(&dir).expect("temp dir");
    for (f, text) in files {
        std::fs::write(dir.join(f), text).expect("write");
    }
    dir
}

fn section(n: u32, latex: &str, func: &str, kind: &str) -> String {
    format!("### ({n}) Title\n\n$$\n{latex}\n$$\n\nMeaning.\n\n*Kind:* {kind} · *Code:* [`{func}`](../src/x.rs)\n\n")
}

#[test]
fn malformed_books_are_reported_with_file_and_line() {
    let good = section(
        1,
        printed_latex(1),
        "ladder::energy::moment_of_inertia_cm",
        "definition",
    );
    let wrong_latex = section(
        3,
        "V = m g l \\sin\\theta",
        "ladder::energy::potential_energy",
        "definition",
    );
    let unknown_fn = section(
        12,
        printed_latex(12),
        "ladder::no_such_function",
        "kinematic",
    );
    let wrong_kind = section(
        14,
        printed_latex(14),
        "ladder::forces::wall_force",
        "general",
    );
    let table = "| `separation_angle` | θ̇0 | expected | tolerance |\n|---|---|---|---|\n| 0.3 | 0 | 0.5 | 1e-13 |\n| 0.3 | x | 1 | 1e-13 |\n";
    let broken =
        "### (2) Kinetic energy\n\nno math, no link, no kind\n\n### (1) again\n\n$$\n\\unclosed{\n";
    let dir = scratch(
        "bad",
        &[
            (
                "a.md",
                format!("{good}{wrong_latex}{unknown_fn}{wrong_kind}{table}"),
            ),
            ("b.md", broken.to_string()),
        ],
    );
    let rep = check_book(&dir);
    let has = |needle: &str| rep.problems.iter().any(|p| p.contains(needle));
    let all = rep.problems.join("\n");
    assert!(has("a.md:") && has("b.md:"), "{all}");
    assert!(has("differs from the registry"), "{all}");
    assert!(
        has("`ladder::no_such_function` is not a registry function of (12)"),
        "{all}"
    );
    assert!(has("says kind 'general'"), "{all}");
    assert!(has("documented twice"), "{all}");
    assert!(
        has("(2) has no display math")
            && has("(2) links to no function")
            && has("(2) does not state its kind"),
        "{all}"
    );
    assert!(has("got ") && has("'x' is not a number"), "{all}");
    assert!(has("equation (90) is not documented"), "{all}");
    // Each problem names a file and a line: "path:N: ...".
    for p in &rep.problems {
        let loc = p.split(": ").next().unwrap_or("");
        let named_line = loc
            .rsplit(':')
            .next()
            .is_some_and(|l| l.parse::<usize>().is_ok());
        assert!(
            named_line || p.contains("is not documented"),
            "no line in: {p}"
        );
    }
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn a_missing_directory_is_a_problem_not_a_panic() {
    let rep = check_book(std::path::Path::new("/nonexistent/ladder-book"));
    assert_eq!(rep.problems.len(), 1);
    assert!(rep.problems[0].contains("cannot read the directory"));
}
