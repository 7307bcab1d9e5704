//! The problems page (`equations/problems.md`, issue 39): at least eight exercises, each answer
//! a numbered display that `ladder verify` checks like the note's own (verified, proved, units
//! consistent; an answer that holds only on the motion fails off it), each with its worked
//! solution folded in a `<details>` on the book's page. A wrong answer in the problems file
//! (a copy, read with `--equations`) is flagged: `failed`, exit 1, the display named with its
//! file and line, and `ladder book` exits 1 too.
//!
//! The answers' references are the three-particle model of the harness; the closed forms in the
//! file were derived by hand from (5), (8), (10) and checked once with sympy (not by the crate).

use crate::common::copy_of_equations;
use serde_json::Value;
use sliding_ladder::book::problems::{fold_declarations, fold_solutions, SOLUTION};
use std::process::{Command, Output};

fn ladder(args: &[&str]) -> Output {
    Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args(args)
        .output()
        .expect("ladder runs")
}

/// The problems' answers, as `ladder verify` labels them.
const ANSWERS: [&str; 8] = [
    "(P6)", "(P7)", "(P8)", "(P9)", "(P10)", "(P11)", "(P12)", "(P13)",
];

fn row<'a>(v: &'a Value, label: &str) -> &'a Value {
    v["extensions"]
        .as_array()
        .and_then(|a| a.iter().find(|r| r["label"] == label))
        .unwrap_or_else(|| panic!("no row {label}"))
}

#[test]
fn every_answer_is_checked_like_the_notes_displays_and_its_solution_is_folded() {
    let only = ANSWERS.map(|l| l.trim_matches(['(', ')'])).join(",");
    let out = ladder(&["verify", "--cases", "200", "--json", "--only", &only]);
    let v: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    for label in ANSWERS {
        let r = row(&v, label);
        assert_eq!(r["status"], "verified", "{label}: {r}");
        assert_eq!(r["proof"], "proved", "{label}: {r}");
        assert!(
            r["units"] == "consistent" || r["units"] == "dimensionless",
            "{label}: {r}"
        );
        assert_eq!(r["exact_failures"], 0, "{label}");
        assert!(
            r["doc"]
                .as_str()
                .is_some_and(|d| d.starts_with("equations/problems.md:")),
            "{label}: {r}"
        );
        if r["kind"] == "on-shell" {
            assert_eq!(
                r["off_motion"], "fails",
                "{label}: holds off the motion: {r}"
            );
        }
    }
    // The page (of the book this binary's tests share): every answer typeset with its status,
    // every solution folded.
    let page =
        std::fs::read_to_string(crate::built::book().join("problems.html")).expect("problems.html");
    let problems = page.matches("<h2>Problem ").count();
    let folded = page
        .matches("<details class=\"solution\"><summary>Worked solution</summary>")
        .count();
    assert!(problems >= 8, "{problems} problems");
    assert_eq!(folded, problems, "each problem's solution folded");
    for n in 1006..=1013 {
        assert!(
            page.contains(&format!("data-number=\"{n}\" data-status=\"verified\"")),
            "answer {n} not verified on the page"
        );
    }
    assert!(!page.contains("<h4>Solution</h4>"), "an unfolded solution");
    // The harness's ids (`position:Q.x`) are folded away from the student's reading, under a
    // list of what each symbol means.
    let open = page
        .find("<details class=\"harness\">")
        .expect("declarations folded");
    let close = open + page[open..].find("</details>").expect("closed");
    assert!(page[..open].contains("The symbols of the answers:"));
    for id in [
        "<code>position:",
        "<code>velocity:",
        "<code>kinetic_energy</code>",
    ] {
        assert!(page[open..close].contains(id), "{id} not declared");
        assert!(
            !page[..open].contains(id) && !page[close..].contains(id),
            "{id} shown unfolded"
        );
    }
}

/// The wall force of Problem 4 with 3 cos θ − 1 for 3 cos θ − 2 (it would leave the wall at
/// cos θ = 1/3), and the share of Problem 3 as T/3: both flagged, with file and line.
#[test]
fn a_wrong_answer_in_the_problems_file_is_flagged() {
    let dir = copy_of_equations("wrong");
    let file = dir.join("problems.md");
    let good = std::fs::read_to_string(&file).expect("problems.md");
    // (P9) comes before (P13), which ends the same way: only the first is planted.
    let bad = good
        .replacen(
            r"\sin\theta(3\cos\theta - 2)
$$",
            r"\sin\theta(3\cos\theta - 1)
$$",
            1,
        )
        .replace(r"= \frac{T}{4}", r"= \frac{T}{3}");
    assert_eq!(
        bad.matches("3\\cos\\theta - 1").count(),
        1,
        "the plant of (P9)"
    );
    assert!(bad.contains(r"\frac{T}{3}"), "the plant of (P8)");
    std::fs::write(&file, bad).expect("write");
    let d = dir.to_str().expect("utf-8");
    let only = ANSWERS.map(|l| l.trim_matches(['(', ')'])).join(",");
    let out = ladder(&[
        "verify",
        "--equations",
        d,
        "--cases",
        "100",
        "--json",
        "--only",
        &only,
    ]);
    assert_eq!(out.status.code(), Some(1));
    let v: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    for label in ["(P8)", "(P9)"] {
        assert_eq!(row(&v, label)["status"], "failed", "{label}");
    }
    for label in ["(P6)", "(P7)", "(P10)", "(P11)", "(P12)", "(P13)"] {
        assert_eq!(row(&v, label)["status"], "verified", "{label}");
    }
    let err = String::from_utf8_lossy(&out.stderr);
    assert!(
        err.contains("(P8)") && err.contains("(P9)") && err.contains("problems.md:"),
        "{err}"
    );
    let book = dir.with_extension("book");
    let b = ladder(&[
        "book",
        "--equations",
        d,
        "--cases",
        "50",
        "--out",
        book.to_str().expect("utf-8"),
    ]);
    assert_eq!(
        b.status.code(),
        Some(1),
        "ladder book must flag the wrong answer"
    );
    let _ = std::fs::remove_dir_all(&book);
    let _ = std::fs::remove_dir_all(&dir);
}

/// The number written right after `key` on a page (up to the next space).
fn number_after(page: &str, key: &str) -> f64 {
    let at = page.find(key).unwrap_or_else(|| panic!("no '{key}'")) + key.len();
    page[at..]
        .split(' ')
        .next()
        .and_then(|w| w.parse().ok())
        .unwrap_or_else(|| panic!("no number after '{key}'"))
}

/// Problem 6's solution quotes the landing speed of the simulated fall that the index reports:
/// the figure typed in the markdown must be the one the index computes, and the closed form
/// √((2/9) g l cos³ θ0) to the four decimals printed.
#[test]
fn problem_6_quotes_the_landing_speed_the_index_computes() {
    let book = crate::built::book();
    let read = |f: &str| std::fs::read_to_string(book.join(f)).expect("page");
    let computed = number_after(&read("index.html"), "its centre moving at Ẋ = ");
    let quoted = number_after(&read("problems.html"), "l = 1 m: Ẋ = ");
    assert_eq!(quoted, computed, "the solution's figure is not the index's");
    let closed = (2.0 / 9.0 * 9.81 * 0.3f64.cos().powi(3)).sqrt();
    // Both pages print four decimals: the closed form lies within half a unit of the last.
    assert!((closed - quoted).abs() <= 0.5e-4, "{closed} vs {quoted}");
    // The check reads the figure it is given: another speed is refused.
    assert_ne!(
        number_after("moving at Ẋ = 1.3788 m/s", "moving at Ẋ = "),
        computed
    );
}

#[test]
fn each_solution_is_folded_up_to_the_next_problem() {
    let html = "<h2>P 1</h2><p>q</p><h4>Solution</h4><p>a</p><h2>P 2</h2><h4>Solution</h4><p>b</p>";
    let f = fold_solutions(html);
    assert_eq!(f.matches("<details class=\"solution\">").count(), 2);
    assert!(f.contains("<summary>Worked solution</summary><p>a</p></details>\n<h2>P 2</h2>"));
    assert!(f.ends_with("<p>b</p></details>\n"));
    assert!(!f.contains(SOLUTION));
}

#[test]
fn fold_declarations_keeps_each_meaning_and_folds_the_ids() {
    let html = "<p>intro</p>\n<p><em>Points:</em> Q = ladder:1/4</p>\n\
                    <p><em>Symbols:</em></p>\n<ul>\n<li><math>x</math> = <code>position:Q.x</code> \
                    [L]: abscissa of Q</li>\n</ul>\n<h2>Problem 1</h2>";
    let f = fold_declarations(html);
    assert!(f.starts_with("<p>intro</p>\n<p>The symbols of the answers:</p>"));
    assert!(f.contains("<li><math>x</math>: abscissa of Q</li>"), "{f}");
    let open = f.find("<details class=\"harness\">").expect("folded");
    assert!(f.find("<code>position:Q.x</code>").expect("kept") > open);
    assert!(f.ends_with("</details>\n<h2>Problem 1</h2>"), "{f}");
    // A page without declarations is left as it is.
    assert_eq!(fold_declarations("<p>x</p>"), "<p>x</p>");
}
