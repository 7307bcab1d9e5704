//! Doc-as-test: the book in equations/ is the note the registry was built from, and malformed
//! books are reported as file:line problems, never a panic.

use sliding_ladder::docs::{check_book, default_dir};
use sliding_ladder::registry::{equations, printed_latex};
use std::path::PathBuf;

#[test]
fn the_book_is_the_note_the_registry_was_built_from() {
    let rep = check_book(&default_dir());
    assert!(
        rep.problems.is_empty(),
        "{} problems:\n{}",
        rep.problems.len(),
        rep.problems.join("\n")
    );
    assert_eq!(rep.equations_found, equations().len());
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

fn section(n: u32, title: &str, latex: &str, kind: &str, rust: &str) -> String {
    format!(
        "### ({n}) {title}\n\n$$\n{latex}\n$$\n\nMeaning.\n\n*Kind:* {kind} · *Code:* [`ladder::x`](../src/x.rs)\n\n*Rust:*\n- {rust}\n\n"
    )
}

#[test]
fn malformed_books_are_reported_with_file_and_line() {
    let e1 = &equations()[0];
    // (1) as built but for its title: the binary was built from another version of the book.
    let retitled = section(
        1,
        "Another title",
        printed_latex(1),
        e1.kind.name(),
        "`eq1` (kinematic): I_cm against the particle model",
    );
    let unknown_fn = section(
        12,
        "Angular momentum about A",
        printed_latex(12),
        "kinematic",
        "`eq12_typo` (kinematic): against Σ x_i × m_i v_i",
    );
    let wrong_kind = section(
        14,
        "Wall force",
        printed_latex(14),
        "generall",
        "`eq14` (kinematic): w",
    );
    let table = "| `separation_angle` | θ̇0 | expected | tolerance |\n|---|---|---|---|\n| 0.3 | 0 | 0.5 | 1e-13 |\n| 0.3 | x | 1 | 1e-13 |\n";
    let again = retitled.replace("Another title", "again");
    let broken = format!(
        "### (2) Kinetic energy\n\nno math, no kind\n\n{again}### (13) x\n\n$$\n\\unclosed{{\n"
    );
    let dir = scratch(
        "bad",
        &[
            ("a.md", format!("{retitled}{unknown_fn}{wrong_kind}{table}")),
            ("b.md", broken),
        ],
    );
    let rep = check_book(&dir);
    let has = |needle: &str| rep.problems.iter().any(|p| p.contains(needle));
    let all = rep.problems.join("\n");
    assert!(has("a.md:") && has("b.md:"), "{all}");
    assert!(
        has("a.md:1: (1) differs from the note this binary was built from"),
        "{all}"
    );
    assert!(has("(12): `eq12_typo` is not a chain function"), "{all}");
    assert!(has("(14): unknown kind 'generall'"), "{all}");
    assert!(has("(1) appears twice (first at"), "{all}");
    assert!(has("(13) has no display"), "{all}");
    assert!(has("(2) has no display"), "{all}");
    assert!(has("got ") && has("'x' is not a number"), "{all}");
    assert!(
        has("(90) of the note this binary was built from is not in the folder"),
        "{all}"
    );
    // Each problem names a file and a line: "path:N: ...".
    for p in &rep.problems {
        let loc = p.split(": ").next().unwrap_or("");
        let named_line = loc
            .rsplit(':')
            .next()
            .is_some_and(|l| l.parse::<usize>().is_ok());
        assert!(named_line, "no line in: {p}");
    }
    let _ = std::fs::remove_dir_all(dir);
}

#[test]
fn a_missing_directory_is_a_problem_not_a_panic() {
    let rep = check_book(std::path::Path::new("/nonexistent/ladder-book"));
    assert_eq!(rep.problems.len(), 1);
    assert!(
        rep.problems[0].contains("cannot read"),
        "{:?}",
        rep.problems
    );
}

#[test]
fn a_stated_figure_that_drifted_from_the_code_is_reported() {
    use sliding_ladder::docs::facts::{check_facts, facts};
    let good = std::fs::read_to_string(default_dir().join("README.md")).expect("README");
    let mut problems = Vec::new();
    check_facts(&default_dir(), &facts(), &mut problems);
    assert!(problems.is_empty(), "{problems:?}");
    // The same page with the old figure (200 states) must be caught, naming the file.
    let stale = good.replace(
        "1000 random states per check",
        "200 random states per check",
    );
    assert_ne!(stale, good, "the phrase is not on the page");
    let dir = scratch("facts", &[("README.md", stale)]);
    let mut problems = Vec::new();
    check_facts(&dir, &facts(), &mut problems);
    assert_eq!(problems.len(), 1, "{problems:?}");
    assert!(problems[0].contains("README.md") && problems[0].contains("1000 random states"));
    let _ = std::fs::remove_dir_all(&dir);
}

/// The ASCII figure of equations/README.md: E stands directly above D (the rectangle A-D-E-C),
/// C directly above A, and θ is marked at C, between the wall and the ladder.
#[test]
fn the_figure_puts_e_above_d_and_theta_at_c() {
    let text = std::fs::read_to_string(default_dir().join("README.md")).expect("README");
    let start = text.find("```\n y\n").expect("the figure");
    let fig: Vec<&str> = text[start + 4..]
        .lines()
        .take_while(|l| !l.starts_with("```"))
        .collect();
    // Column (in characters) of the first occurrence of `pat` in the row that starts the point.
    let at = |row: &str, pat: char| row.chars().position(|c| c == pat);
    let row_of = |lead: &str| {
        fig.iter()
            .position(|r| r.starts_with(lead))
            .unwrap_or_else(|| panic!("no row starting {lead:?}"))
    };
    let (top, bottom) = (fig[row_of(" C")], fig[row_of(" A")]);
    assert_eq!(at(top, 'C'), at(bottom, 'A'), "C is not above A");
    assert_eq!(at(top, 'E'), at(bottom, 'D'), "E is not above D");
    // θ sits in the wedge just below C: right of the wall, left of the ladder's stroke.
    let wedge = fig[row_of(" C") + 1..row_of(" C") + 3].iter().any(|row| {
        let (wall, theta, stroke) = (at(row, '|'), at(row, 'θ'), at(row, '\\'));
        theta.is_some() && wall < theta && theta < stroke
    });
    assert!(wedge, "θ is not at C between the wall and the ladder");
}

/// `LADDER_BLESS_DOCS=1 cargo test --test book docs` rewrites the generated worked examples of the
/// book after a deliberate change of the code; without it this only checks that blessing is a
/// no-op on the committed book (so the committed text is exactly what the code generates).
#[test]
fn worked_examples_are_what_the_code_generates() {
    use sliding_ladder::docs::worked::{bless, blocks};
    let mut found = 0;
    for f in [
        "02-point-a.md",
        "03-point-b.md",
        "04-point-c.md",
        "05-point-d.md",
        "06-point-e.md",
        "A1-method-1.md",
        "A5-method-5.md",
    ] {
        let path = default_dir().join(f);
        let text = std::fs::read_to_string(&path).expect("section file");
        let fresh = bless(&text).expect("every block regenerates");
        if std::env::var_os("LADDER_BLESS_DOCS").is_some() {
            std::fs::write(&path, &fresh).expect("write");
        } else {
            assert_eq!(
                fresh, text,
                "{f}: run LADDER_BLESS_DOCS=1 cargo test --test book docs"
            );
        }
        found += blocks(&fresh).len();
    }
    // Secs. 2.2-2.6, and the torque analyses about C of Appendix A: Jensen's method 1 (53) and
    // Hu's method (59).
    assert_eq!(found, 7, "one worked example per torque-analysis section");
}

/// The harness reports a worked example whose numbers no longer match the code.
#[test]
fn a_stale_worked_example_is_reported() {
    let path = default_dir().join("05-point-d.md");
    let text = std::fs::read_to_string(&path).expect("05-point-d.md");
    let stale = text.replacen("4.9050 N·m", "4.9060 N·m", 1);
    assert_ne!(stale, text, "the example states 4.9050 N·m");
    let dir = scratch("stale-worked", &[("05-point-d.md", stale)]);
    let rep = check_book(&dir);
    assert!(
        rep.problems
            .iter()
            .any(|p| p.contains("05-point-d.md:") && p.contains("worked example of (25)")),
        "{:?}",
        rep.problems
    );
    let _ = std::fs::remove_dir_all(&dir);
}

/// The worked examples' numbers, held against closed forms derived here by hand from the
/// figure (not by the code that generates them): m = l = 1, g = 9.81, θ = 30°, from rest upright,
/// so θ̇² = (3g/2l)(1 − cos θ) by energy and θ̈ = (3g/4l) sin θ on the motion, θ̈ = 0 off it.
/// Each torque is summed force by force as r × F about the point, with the coordinate force
/// −m a_P at B where P accelerates; each dL/dt from the angular momentum the section states.
#[test]
fn worked_examples_agree_with_closed_forms_computed_here() {
    use sliding_ladder::docs::worked::blocks;
    let (m, l, g) = (1.0f64, 1.0f64, 9.81f64);
    let (s, c) = (0.5f64, 3f64.sqrt() / 2.0);
    let r2 = 1.5 * g / l * (1.0 - c);
    // Positions (A at the origin) and accelerations, by hand.
    let (b, cc, d, e) = (
        (l * s, l * c),
        (0.0, 2.0 * l * c),
        (2.0 * l * s, 0.0),
        (2.0 * l * s, 2.0 * l * c),
    );
    let a_cm = move |a: f64| (l * (c * a - s * r2), -l * (s * a + c * r2));
    let a_of = move |p: char, a: f64| match p {
        'C' => (0.0, -2.0 * l * (s * a + c * r2)),
        'D' => (2.0 * l * (c * a - s * r2), 0.0),
        'E' => (2.0 * l * (c * a - s * r2), -2.0 * l * (s * a + c * r2)),
        'B' => a_cm(a),
        _ => (0.0, 0.0),
    };
    let wall = move |a: f64| m * a_cm(a).0;
    let floor = move |a: f64| m * g + m * a_cm(a).1;
    let cross = move |r: (f64, f64), f: (f64, f64)| r.0 * f.1 - r.1 * f.0;
    let about =
        move |p: (f64, f64), at: (f64, f64), f: (f64, f64)| cross((at.0 - p.0, at.1 - p.1), f);
    // Torque about P of the wall, floor and gravity, and of −m a_P at B.
    let real = move |p: (f64, f64), a: f64| {
        about(p, cc, (wall(a), 0.0)) + about(p, d, (0.0, floor(a))) + about(p, b, (0.0, -m * g))
    };
    let coordinate = move |p: (f64, f64), name: char, a: f64| {
        let ap = a_of(name, a);
        about(p, b, (-m * ap.0, -m * ap.1))
    };
    let rate = r2.sqrt();
    type Law = Box<dyn Fn(f64) -> (f64, f64)>;
    let cases: Vec<(&str, u32, Law)> = vec![
        // A: dL_A/dt with L_A = −2ml²θ̇/3 (12), the real torque.
        (
            "02-point-a.md",
            16,
            Box::new(move |a| (-2.0 * m * l * l * a / 3.0, real((0.0, 0.0), a))),
        ),
        // B: dL_cm/dt = I_cm θ̈; −m a_B at B has no arm.
        (
            "03-point-b.md",
            19,
            Box::new(move |a| (m * l * l * a / 3.0, real(b, a) + coordinate(b, 'B', a))),
        ),
        // C, D: L'_P = 4ml²θ̇/3 (21), (24); E: L'_E = −2ml²θ̇/3 (27).
        (
            "04-point-c.md",
            22,
            Box::new(move |a| {
                (
                    4.0 * m * l * l * a / 3.0,
                    real(cc, a) + coordinate(cc, 'C', a),
                )
            }),
        ),
        (
            "05-point-d.md",
            25,
            Box::new(move |a| {
                (
                    4.0 * m * l * l * a / 3.0,
                    real(d, a) + coordinate(d, 'D', a),
                )
            }),
        ),
        (
            "06-point-e.md",
            28,
            Box::new(move |a| {
                (
                    -2.0 * m * l * l * a / 3.0,
                    real(e, a) + coordinate(e, 'E', a),
                )
            }),
        ),
        // (53): dL_C/dt of the lab L_C = ml²θ̇/3 + ml²θ̇(c² − s²) = τ_C + m v_cm × v_C.
        (
            "A1-method-1.md",
            53,
            Box::new(move |a| {
                let left = m * l * l * a / 3.0 + m * l * l * a * (c * c - s * s)
                    - 4.0 * m * l * l * r2 * c * s;
                let (v_cm, v_c) = ((l * c * rate, -l * s * rate), (0.0, -2.0 * l * s * rate));
                (left, real(cc, a) + m * cross(v_cm, v_c))
            }),
        ),
        // (59): dL_A/dt − x_C × m a_cm = τ_C.
        (
            "A5-method-5.md",
            59,
            Box::new(move |a| {
                let ac = a_cm(a);
                (
                    -2.0 * m * l * l * a / 3.0 - cross(cc, (m * ac.0, m * ac.1)),
                    real(cc, a),
                )
            }),
        ),
    ];
    // A stated value (four decimals) agrees with ours to its last digit.
    let close = |stated: f64, ours: f64| (stated - ours).abs() <= 0.5e-4 + 1e-12;
    let value = |cell: &str| -> f64 {
        cell.split_whitespace()
            .next()
            .unwrap()
            .replace('−', "-")
            .parse()
            .unwrap()
    };
    let on = 0.75 * g / l * s;
    for (file, n, law) in &cases {
        let text = std::fs::read_to_string(default_dir().join(file)).expect("section file");
        let (_, _, block) = blocks(&text)
            .into_iter()
            .find(|b| b.0 == *n)
            .expect("its block");
        let row = |lead: &str| -> (f64, f64) {
            let line = block
                .lines()
                .find(|r| r.starts_with(&format!("| {lead}")))
                .unwrap_or_else(|| panic!("({n}): no row '{lead}'"));
            let cells: Vec<&str> = line.split('|').map(str::trim).collect();
            (value(cells[2]), value(cells[3]))
        };
        for (lead, f) in [("F_w", &wall as &dyn Fn(f64) -> f64), ("F_f", &floor)] {
            let (x_on, x_off) = row(lead);
            assert!(
                close(x_on, f(on)) && close(x_off, f(0.0)),
                "({n}) {lead}: {x_on}, {x_off}"
            );
        }
        let ((l_on, r_on), (l_off, r_off)) = (law(on), law(0.0));
        assert!(
            (l_on - r_on).abs() < 1e-12,
            "({n}): the hand sides differ on the motion"
        );
        assert!(
            (l_off - r_off).abs() > 0.1,
            "({n}): the hand sides agree off the motion"
        );
        let (left, right) = (row("left of the law"), row("right of the law"));
        assert!(
            close(left.0, l_on) && close(left.1, l_off),
            "({n}) left: {left:?}, ours {l_on}, {l_off}"
        );
        assert!(
            close(right.0, r_on) && close(right.1, r_off),
            "({n}) right: {right:?}, ours {r_on}, {r_off}"
        );
    }
    // The issue's own numbers for (25): θ̈ = 3.679, both sides 4.905 on the motion; off it the
    // left side is 0 while the right stays 4.905.
    assert!((on - 3.679).abs() < 5e-4);
    let (l25, r25) = (cases[3].2)(on);
    assert!((l25 - 4.905).abs() < 1e-9 && (r25 - 4.905).abs() < 1e-9);
    assert_eq!((cases[3].2)(0.0).0, 0.0);
    // The misprint of (28), τ_E − F_E,y l sin θ: the real torque about E less the y part only.
    let text = std::fs::read_to_string(default_dir().join("06-point-e.md")).unwrap();
    let (_, _, block) = blocks(&text).into_iter().find(|b| b.0 == 28).unwrap();
    let line = block
        .lines()
        .find(|r| r.starts_with("| misprint"))
        .expect("the misprint row");
    let cells: Vec<&str> = line.split('|').map(str::trim).collect();
    let misprint = |a: f64| real(e, a) - (-m * a_of('E', a).1) * l * s;
    assert!(
        close(value(cells[2]), misprint(on)) && close(value(cells[3]), misprint(0.0)),
        "{line}"
    );
}
