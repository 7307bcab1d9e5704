//! The `ladder verify` table as a teacher reads it (issue 16, item 4): full titles, the pass
//! threshold beside the residual, what a display does off the motion, what the exact points
//! found, what a definition was checked against, the book line of each row, and a legend for
//! every column. Each property is shown to fail on a table or legend that lacks it.

use crate::common::equation;
use sliding_ladder::registry::check::{run_check, Config, TOLERANCE_FACTOR};
use sliding_ladder::registry::equations;
use sliding_ladder::verify::fill::{fill, fill_line, widest, DEFAULT_WIDTH};
use sliding_ladder::verify::legend::{legend, unexplained_columns};
use sliding_ladder::verify::summary::schwartz_zippel_sentence;
use sliding_ladder::verify::table::{
    render, render_for, residual, width, wrap, COLUMNS, FULL_WIDTH, NARROW_COLUMNS, NARROW_WIDTH,
    TITLE_WIDTH,
};
use sliding_ladder::verify::{
    judge, print_coverage, verify_extensions, EquationResult, OffMotion, Status,
};

fn tiny() -> Config {
    Config {
        float_cases: 3,
        exact_points: 2,
        seed: 7,
    }
}

/// The row of `n`, judged from its checks run on a few states (fast).
fn checked(n: u32) -> EquationResult {
    let e = equation(n);
    let reports: Vec<_> = e.checks.iter().map(|c| run_check(c, &tiny())).collect();
    judge(&e, &reports)
}

/// Every equation's row without running its checks (for layout only).
fn unchecked() -> Vec<EquationResult> {
    equations().iter().map(|e| judge(e, &[])).collect()
}

/// The first line of each row: the lines that start with a label such as ` (25)`.
fn row_lines(table: &str) -> Vec<&str> {
    table
        .lines()
        .filter(|l| l.trim_start().starts_with('(') && l.contains(')'))
        .collect()
}

#[test]
fn every_column_is_explained_by_the_legend_and_a_missing_entry_is_caught() {
    let text = legend(&Config::default());
    assert_eq!(unexplained_columns(&text), Vec::<&str>::new(), "{text}");
    // Drop the entry of one column: the check names it.
    let cut: String = text
        .lines()
        .filter(|l| !l.starts_with("  off motion "))
        .map(|l| format!("{l}\n"))
        .collect();
    assert_eq!(unexplained_columns(&cut), vec!["off motion"]);
    // The legend states the threshold the residual column is compared with.
    assert!(text.contains(&format!("≤ {TOLERANCE_FACTOR}")));
}

#[test]
fn titles_are_whole_and_wrap_within_their_column() {
    let results = unchecked();
    let table = render(&results, false);
    for r in &results {
        let lines = wrap(r.title, TITLE_WIDTH);
        assert_eq!(lines.join(" "), r.title, "wrap loses words");
        assert!(lines.iter().all(|l| width(l) <= TITLE_WIDTH), "{lines:?}");
        // Each piece is in the table, the first on the row, the rest on the lines below it.
        let at = table
            .lines()
            .position(|l| l.contains(&format!("{} ", r.label)) && l.contains(&lines[0]))
            .unwrap_or_else(|| panic!("row {} not found", r.label));
        for (k, piece) in lines.iter().enumerate().skip(1) {
            assert!(
                table
                    .lines()
                    .nth(at + k)
                    .is_some_and(|l| l.contains(piece.as_str())),
                "{}: '{piece}' not under its row",
                r.label
            );
        }
    }
    // The longest title is longer than the column: it must wrap, not be cut.
    let longest = results.iter().map(|r| width(r.title)).max().unwrap();
    assert!(longest > TITLE_WIDTH);
    // A cut title would fail the check above.
    let cut: String = results[0].title.chars().take(10).collect();
    assert_ne!(wrap(&cut, TITLE_WIDTH).join(" "), results[0].title);
}

#[test]
fn every_row_lines_up_with_the_header_in_terminal_columns() {
    let table = render(&unchecked(), false);
    let header = table.lines().next().unwrap();
    let full: usize = COLUMNS.iter().map(|c| c.1).sum::<usize>() + COLUMNS.len() - 1;
    assert_eq!((width(header), FULL_WIDTH), (full, full));
    for l in row_lines(&table) {
        assert_eq!(width(l), full, "misaligned: {l}");
    }
    // θ̈ takes one column though it is two chars: counting chars would misalign 'any θ̈' rows.
    assert_eq!(width("any θ̈"), 5);
    assert_eq!("any θ̈".chars().count(), 6);
}

/// In the one-line layout the rest of a wrapped title and the lines under a row start at the
/// header's title column (read off the header itself), filled lines hanging further in.
#[test]
fn render_for_indents_continued_titles_to_the_title_column() {
    let mut rows = unchecked();
    rows.push(checked(1)); // a definition: its "checked:" line goes under the row
    let table = render_for(&rows, true, FULL_WIDTH);
    let header = table.lines().next().unwrap();
    let title_at = width(&header[..header.find("title").unwrap()]);
    let lead = |l: &str| l.len() - l.trim_start().len();
    // A row's own line is led only by its right-aligned label; a longer lead is a continuation.
    let continued: Vec<&str> = table.lines().filter(|l| lead(l) > COLUMNS[0].1).collect();
    assert!(continued.iter().any(|l| l.contains("checked:")), "{table}");
    assert!(
        continued.iter().any(|l| !l.contains("checked:")),
        "a wrapped title: {table}"
    );
    // Filled lines hang further in; none starts left of the title column, and some start on it.
    let leads: Vec<usize> = continued.iter().map(|l| lead(l)).collect();
    assert_eq!(leads.iter().min(), Some(&title_at), "{table}");
}

/// A teacher's terminal is about 100 columns: there each display takes two lines, its full title
/// and then its cells, aligned under the header's second line; no line is wider than 100.
#[test]
fn at_100_columns_each_display_is_its_title_then_its_cells_and_nothing_is_wider() {
    let rows = unchecked();
    let table = render_for(&rows, true, DEFAULT_WIDTH);
    assert!(widest(&table) <= DEFAULT_WIDTH, "{table}");
    let lines: Vec<&str> = table.lines().collect();
    let cells_header = lines[1];
    assert!(
        cells_header.trim_start().starts_with("kind"),
        "{cells_header}"
    );
    assert_eq!(width(cells_header), NARROW_WIDTH);
    const { assert!(NARROW_WIDTH <= DEFAULT_WIDTH) };
    for r in &rows {
        let at = lines
            .iter()
            .position(|l| l.starts_with(&format!("{:>5} ", r.label)))
            .unwrap_or_else(|| panic!("no title line for {}", r.label));
        // The whole title, on the title line and those under it before the cells.
        let cells = (at + 1..lines.len())
            .find(|&k| lines[k].trim_start().starts_with(r.kind.name()))
            .unwrap_or_else(|| panic!("no cells for {}", r.label));
        let title: Vec<&str> = lines[at..cells].iter().map(|l| l[12..].trim()).collect();
        assert_eq!(title.join(" "), r.title, "{}", r.label);
        assert_eq!(
            width(lines[cells]),
            NARROW_WIDTH,
            "misaligned: {}",
            lines[cells]
        );
    }
    for (h, _, _) in NARROW_COLUMNS {
        assert!(cells_header.contains(h), "{h}");
    }
    // The one-line layout would not fit: this check fails on it.
    assert!(widest(&render(&rows, true)) > DEFAULT_WIDTH);
}

/// The filled lines of the legend, the law lines and the errata keep a label column, break
/// before an operator (never after it), keep `sin θ` whole, and lose no word.
#[test]
fn filling_keeps_labels_formulas_and_every_word() {
    let line = "  residual    worst float difference of the display's forms, |a − b| / (u·(e_a + e_b)), a check passes when it is ≤ 4 and sin θ stays whole";
    let filled = fill_line(line, 60);
    let lines: Vec<&str> = filled.lines().collect();
    assert!(
        lines.len() > 1 && lines.iter().all(|l| width(l) <= 60),
        "{filled}"
    );
    assert!(lines[0].starts_with("  residual    worst"), "{filled}");
    assert!(lines[1..]
        .iter()
        .all(|l| l.starts_with(&" ".repeat(14)) && !l[14..].starts_with(' ')));
    let words = |s: &str| s.split_whitespace().map(str::to_string).collect::<Vec<_>>();
    assert_eq!(words(&filled), words(line));
    for l in &lines {
        let last = l.split_whitespace().last().unwrap();
        assert!(
            !["−", "+", "=", "≤", "/", "sin"].contains(&last),
            "ends in '{last}': {filled}"
        );
    }
    // Every width: no word lost; from the label's 14 columns plus the longest unbreakable piece
    // ("difference", 10) on, no line too wide.
    for w in 10..=120 {
        let f = fill(line, w);
        assert_eq!(words(&f), words(line), "width {w}");
        assert!(w < 24 || widest(&f) <= w, "width {w}: {f}");
    }
    // A line that fits is left as it is, spacing and all.
    assert_eq!(fill_line("  a   b", 100), "  a   b");
    // A short line with no label column, too wide for a narrow terminal: it continues two
    // columns right of its indent (the label search stops at the line's end).
    assert_eq!(
        fill_line("  one two three four", 10),
        "  one two\n    three\n    four"
    );
}

/// A label of two words (one space inside it) is one label: the text continues after the
/// label's gap of two or more spaces, not after its first word.
#[test]
fn filling_keeps_a_label_of_two_words_whole() {
    let line =
        "  off motion  what the display does when θ̈ is not the equation of motion's, as a word";
    let filled = fill_line(line, 40);
    let lines: Vec<&str> = filled.lines().collect();
    assert!(lines.len() > 1, "{filled}");
    assert!(lines[0].starts_with("  off motion  what"), "{filled}");
    for l in &lines[1..] {
        assert!(
            l.starts_with(&" ".repeat(14)) && !l[14..].starts_with(' '),
            "continues under the text, column 14: {filled}"
        );
    }
}

/// The print coverage of `ladder verify`, on three rows made by hand: one fully parsed with its
/// Rust forms matching (2 of 2 forms), one parsed in part (1 of 3), one with no print at all
/// (an extension, left out): 1 of 2 displays whole, 3 of 5 forms, 1 matching.
#[test]
fn print_coverage_counts_displays_forms_and_matches() {
    let row = |forms: usize, parsed: usize, matches: bool| EquationResult {
        print_forms: forms,
        print_parsed: parsed,
        print_matches_code: matches,
        ..judge(&equation(25), &[])
    };
    let rows = [row(2, 2, true), row(3, 1, false), row(0, 0, true)];
    assert_eq!(print_coverage(&rows), (1, 2, 3, 5, 1));
}

#[test]
fn the_residual_stands_beside_its_threshold() {
    assert_eq!(residual(0.2554), "0.255 ≤ 4");
    assert_eq!(residual(4.0), "4.000 ≤ 4");
    assert_eq!(residual(4.5), "4.500 > 4");
    assert_eq!(residual(6.25e13), "6.2e13 > 4");
    let r = checked(25);
    let table = render(std::slice::from_ref(&r), false);
    assert!(table.contains(&residual(r.max_residual)), "{table}");
    assert!(r.max_residual <= TOLERANCE_FACTOR);
}

#[test]
fn off_the_motion_on_shell_rows_fail_at_their_law_and_kinematic_rows_hold() {
    let on = checked(25);
    assert_eq!((on.off_motion, on.law_step), (OffMotion::Fails, Some(2)));
    let kin = checked(12);
    assert_eq!(kin.off_motion, OffMotion::AnyMotion);
    let particles = checked(30);
    assert_eq!(particles.off_motion, OffMotion::NotApplicable);
    let table = render(&[on, kin, particles], false);
    let rows = row_lines(&table);
    assert!(rows[0].contains("fails at =2"), "{}", rows[0]);
    assert!(rows[1].contains("any θ̈"), "{}", rows[1]);
    assert!(rows[2].contains(" — "), "{}", rows[2]);
    // An on-shell check that holds off the motion: the row says so and fails.
    let e = equation(25);
    let mut reports: Vec<_> = e.checks.iter().map(|c| run_check(c, &tiny())).collect();
    reports[0].off_shell_fails = Some(false);
    let bad = judge(&e, &reports);
    assert_eq!(
        (bad.off_motion, bad.status),
        (OffMotion::Holds, Status::Failed)
    );
    assert!(render(&[bad], false).contains("HOLDS"));
}

#[test]
fn the_exact_column_counts_points_and_failures() {
    let r = checked(25);
    assert_eq!(r.exact_failures, 0);
    assert_eq!(r.exact_points, 2);
    assert!(render(std::slice::from_ref(&r), false).contains("0 at 2 pts"));
    let mut bad = r.clone();
    bad.exact_failures = 1;
    assert!(render(&[bad], false).contains("≠0 at 1 of 2"));
}

#[test]
fn definitions_say_what_they_were_checked_against_and_wide_rows_name_the_law() {
    let def = checked(1);
    assert_eq!(def.status, Status::Definition);
    let table = render(std::slice::from_ref(&def), false);
    assert!(
        table.contains(&format!("checked: {}", def.checks[0])),
        "{table}"
    );
    let analysis = checked(25);
    assert!(!render(std::slice::from_ref(&analysis), false).contains("checked:"));
    let wide = render(std::slice::from_ref(&analysis), true);
    assert!(
        wide.contains(&format!("checked: {}", analysis.checks[0])),
        "{wide}"
    );
    assert!(wide.contains("law of motion at the 2nd `=`"), "{wide}");
}

#[test]
fn each_row_names_the_line_of_its_section_in_the_book() {
    let rows = verify_extensions(&tiny());
    let table = render(&rows, false);
    assert!(table.contains("── equations/phase2.md"), "{table}");
    let page = std::fs::read_to_string(sliding_ladder::docs::default_dir().join("phase2.md"))
        .expect("phase2.md");
    // The floor phase's (P1)-(P5); the problems' answers (P6)-.. live in problems.md.
    let phase2: Vec<_> = rows
        .iter()
        .filter(|r| r.doc.as_deref().is_some_and(|d| !d.contains("problems.md")))
        .collect();
    assert_eq!(phase2.len(), 5, "(P1)-(P5)");
    for r in phase2 {
        let doc = r.doc.as_deref().expect("a page");
        let (file, line) = doc.rsplit_once(':').unwrap();
        assert_eq!(file, "equations/phase2.md");
        let line: usize = line.parse().unwrap();
        let heading = page.lines().nth(line - 1).unwrap();
        assert!(
            heading.starts_with('#') && heading.contains(&r.label),
            "{doc}: '{heading}'"
        );
        let row = row_lines(&table)
            .into_iter()
            .find(|l| l.contains(&r.label))
            .unwrap();
        assert!(row.ends_with(&format!(" {line}")), "{row}");
    }
}

#[test]
fn the_schwartz_zippel_sentence_states_the_worst_bound() {
    let mut rows = vec![checked(12), checked(25)];
    rows[0].sz_bound_log10 = -28.4;
    rows[1].sz_bound_log10 = -40.0;
    rows[0].sz_bound_rational_log10 = -14.2;
    rows[1].sz_bound_rational_log10 = -20.0;
    let s = schwartz_zippel_sentence(&rows);
    assert!(s.contains("at most 1e-28 (1e-14"), "{s}");
    assert!(s.contains("if any of these identities were false"), "{s}");
    rows[1].sz_bound_log10 = -3.5;
    assert!(schwartz_zippel_sentence(&rows).contains("at most 1e-3 "));
}

#[test]
fn verify_only_runs_the_chosen_displays_and_exits_0_when_they_pass() {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args([
            "verify",
            "--only",
            "25,1",
            "--cases",
            "5",
            "--exact-points",
            "1",
        ])
        .output()
        .expect("runs");
    let text = String::from_utf8_lossy(&out.stdout);
    assert_eq!(out.status.code(), Some(0), "{text}");
    // The table (above the summary line) has the two rows asked for.
    let table = text.split(" equations: ").next().unwrap();
    assert_eq!(row_lines(table).len(), 2, "{text}");
    assert!(
        text.contains("2 equations: 1 verified, 0 erratum, 1 definition, 0 failed"),
        "{text}"
    );
    // Not a terminal and no --width: laid out for 100 columns, every line of it.
    assert!(widest(&text) <= DEFAULT_WIDTH, "{text}");
    // --width 146 gives the one-line layout, wider than 100 (the check above can fail).
    let wide = std::process::Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args([
            "verify",
            "--only",
            "25",
            "--cases",
            "5",
            "--exact-points",
            "1",
        ])
        .args(["--width", &FULL_WIDTH.to_string()])
        .output()
        .expect("runs");
    let wide = String::from_utf8_lossy(&wide.stdout);
    assert!(widest(&wide) > DEFAULT_WIDTH, "{wide}");
    assert_eq!(
        row_lines(wide.split(" equations: ").next().unwrap()).len(),
        1
    );
    // An unknown item is bad input: exit 2, one line on stderr.
    let bad = std::process::Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args(["verify", "--only", "25,999"])
        .output()
        .expect("runs");
    assert_eq!(bad.status.code(), Some(2));
    assert_eq!(String::from_utf8_lossy(&bad.stderr).lines().count(), 1);
    // So is asking for no exact point (the exact verdict and the law step need one); float
    // states may be left out.
    let run = |cases: &str, points: &str| {
        std::process::Command::new(env!("CARGO_BIN_EXE_ladder"))
            .args([
                "verify",
                "--only",
                "25",
                "--cases",
                cases,
                "--exact-points",
                points,
            ])
            .output()
            .expect("runs")
    };
    for cases in ["0", "3"] {
        let none = run(cases, "0");
        assert_eq!(none.status.code(), Some(2));
        let why = String::from_utf8_lossy(&none.stderr);
        assert!(
            why.lines().count() == 1 && why.contains("--exact-points"),
            "{why}"
        );
        assert!(none.stdout.is_empty());
    }
    assert_eq!(run("0", "1").status.code(), Some(0));
}

/// `--only` picks rows beyond the note by label, and the note's by number, each list alone.
#[test]
fn verify_only_picks_rows_beyond_the_note_by_label() {
    let run = |only: &str| {
        let out = std::process::Command::new(env!("CARGO_BIN_EXE_ladder"))
            .args(["verify", "--json", "--cases", "5", "--exact-points", "1"])
            .args(["--only", only])
            .output()
            .expect("runs");
        assert_eq!(out.status.code(), Some(0), "--only {only}");
        let v: serde_json::Value = serde_json::from_slice(&out.stdout).expect("JSON");
        let labels = |k: &str| -> Vec<String> {
            v[k].as_array()
                .expect("rows")
                .iter()
                .map(|r| r["label"].as_str().unwrap_or("").to_string())
                .collect()
        };
        (labels("equations"), labels("extensions"))
    };
    assert_eq!(
        run("P8,P1"),
        (vec![], vec!["(P1)".to_string(), "(P8)".to_string()])
    );
    assert_eq!(run("25"), (vec!["(25)".to_string()], vec![]));
    assert_eq!(
        run("P2,5"),
        (vec!["(5)".to_string()], vec!["(P2)".to_string()])
    );
}

/// `ladder errata` fits a 100-column terminal: its reasons, points and residuals are filled to
/// it (unfilled, they run to over 200 columns).
#[test]
fn ladder_errata_fits_100_columns() {
    let out = std::process::Command::new(env!("CARGO_BIN_EXE_ladder"))
        .arg("errata")
        .output()
        .expect("runs");
    assert_eq!(out.status.code(), Some(0));
    let text = String::from_utf8_lossy(&out.stdout);
    assert!(widest(&text) <= DEFAULT_WIDTH, "{text}");
    let list = sliding_ladder::verify::errata::errata(&Config::default());
    let raw = sliding_ladder::cli::errata::misprint_text(&list);
    assert!(widest(&raw) > DEFAULT_WIDTH);
    // Filling lost no word of it.
    let words = |s: &str| s.split_whitespace().map(str::to_string).collect::<Vec<_>>();
    assert_eq!(words(&fill(&raw, DEFAULT_WIDTH)), words(&raw));
}

/// The proof cell: `proved`, `sampled` where no symbolic proof applies, `NO` otherwise.
#[test]
fn proof_cell_says_proved_sampled_or_no() {
    use sliding_ladder::verify::table::proof;
    let mut r = checked(12);
    r.proved = true;
    r.proof = "proved".into();
    assert_eq!(proof(&r), "proved");
    r.proved = false;
    r.proof = "sampled only: root: a square root".into();
    assert_eq!(proof(&r), "sampled");
    r.proof = "not proved".into();
    assert_eq!(proof(&r), "NO");
}

/// Each cell of a row in its own words, every case written by hand: the status, the residual
/// beside the threshold (three decimals below 1000, else an exponent), what the display does off
/// the motion, the exact points and the print.
#[test]
fn cells_say_each_case_in_their_own_words() {
    use sliding_ladder::verify::table::{exact, off_motion, print, status};
    assert_eq!(
        [
            Status::Verified,
            Status::Erratum,
            Status::Definition,
            Status::Failed
        ]
        .map(status),
        ["verified", "erratum", "definition", "FAILED"]
    );
    assert_eq!(residual(0.25), format!("0.250 ≤ {TOLERANCE_FACTOR}"));
    assert_eq!(
        residual(TOLERANCE_FACTOR),
        format!("4.000 ≤ {TOLERANCE_FACTOR}")
    );
    assert_eq!(residual(4.5), format!("4.500 > {TOLERANCE_FACTOR}"));
    assert_eq!(residual(72_000.0), format!("7.2e4 > {TOLERANCE_FACTOR}"));
    let mut r = checked(12);
    let off = |r: &mut EquationResult, m: OffMotion, step: Option<u32>| {
        r.off_motion = m;
        r.law_step = step;
        off_motion(r)
    };
    assert_eq!(off(&mut r, OffMotion::Fails, Some(2)), "fails at =2");
    assert_eq!(off(&mut r, OffMotion::Fails, None), "fails");
    assert_eq!(off(&mut r, OffMotion::Holds, Some(2)), "HOLDS");
    assert_eq!(off(&mut r, OffMotion::AnyMotion, None), "any θ̈");
    assert_eq!(off(&mut r, OffMotion::NotApplicable, None), "—");
    (r.exact_points, r.exact_failures) = (0, 0);
    assert_eq!(exact(&r), "none");
    (r.exact_points, r.exact_failures) = (3, 0);
    assert_eq!(exact(&r), "0 at 3 pts");
    (r.exact_points, r.exact_failures) = (3, 1);
    assert_eq!(exact(&r), "≠0 at 1 of 3");
    (r.print_forms, r.print_parsed, r.print_matches_code) = (0, 0, true);
    assert_eq!(print(&r), "—");
    (r.print_forms, r.print_parsed) = (4, 3);
    assert_eq!(print(&r), "3/4");
    r.print_matches_code = false;
    assert_eq!(print(&r), "3/4*");
}
