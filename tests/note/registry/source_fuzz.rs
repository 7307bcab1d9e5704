//! Random edits to the note's own display sections never panic the reader of the markdown or
//! the checks of the print (issue 36): every problem is `file:line: reason` with a line of the
//! edited file, and through the command line a malformed folder exits 2 with those lines on
//! stderr and nothing on stdout, anything else exits 0 or 1 (1 with its reason).

use rand::{Rng, SeedableRng};
use rand_chacha::ChaCha8Rng;
use sliding_ladder::registry::check::Config;
use sliding_ladder::registry::source::Note;
use std::process::Command;

/// Pieces an edit may insert: LaTeX and markdown syntax, the fields' markers, digits.
const PIECES: &[&str] = &[
    "{",
    "}",
    "$$",
    "$",
    "\\frac",
    "\\frac{",
    "=",
    "^",
    "_",
    "^{12}",
    "*Kind:* ",
    "*Law:* the 9th `=` ",
    "*Rust:* ",
    "- ",
    "(",
    ")",
    "\\\\",
    "### (7) ",
    "\n",
    "\n\n",
    "`",
    " · ",
    "&",
    "7",
    "0",
    "\\sum",
    "\\left(",
    "\\Big|_{",
    "\\dot{",
    "\\unknown",
    "\\Rightarrow",
    ",\\quad",
    "*Misprint:* $x$",
    "*Points:* Q = ladder:2/3",
    "*States:* p-at-cm",
    "- `eq25` (general): x",
    "\\text{Milne : }",
];

/// The chapter files that hold displays, with their text.
fn chapters() -> Vec<(String, String)> {
    let dir = sliding_ladder::docs::default_dir();
    let mut out: Vec<(String, String)> = std::fs::read_dir(&dir)
        .expect("equations/")
        .flatten()
        .map(|e| e.path())
        .filter(|p| p.extension().is_some_and(|x| x == "md"))
        .filter_map(|p| {
            let text = std::fs::read_to_string(&p).ok()?;
            let name = format!("equations/{}", p.file_name()?.to_string_lossy());
            text.contains("\n### (").then_some((name, text))
        })
        .collect();
    out.sort();
    out
}

/// One random edit inside a random display section of `text` (from its heading to the next
/// heading): delete a few characters, insert a piece, or delete or repeat a line.
fn edit(text: &str, rng: &mut ChaCha8Rng) -> String {
    let starts: Vec<usize> = text.match_indices("\n### (").map(|(i, _)| i + 1).collect();
    let start = starts[rng.gen_range(0..starts.len())];
    let end = text[start + 1..]
        .find("\n#")
        .map_or(text.len(), |k| start + 1 + k);
    let section: Vec<char> = text[start..end].chars().collect();
    let at = rng.gen_range(0..section.len());
    let mut s = section.clone();
    match rng.gen_range(0..4) {
        0 => {
            let n = rng.gen_range(1..=5).min(s.len() - at);
            s.drain(at..at + n);
        }
        1 => {
            let piece = PIECES[rng.gen_range(0..PIECES.len())];
            s.splice(at..at, piece.chars());
        }
        k => {
            let line_start = s[..at]
                .iter()
                .rposition(|&c| c == '\n')
                .map_or(0, |p| p + 1);
            let line_end = s[at..]
                .iter()
                .position(|&c| c == '\n')
                .map_or(s.len(), |p| at + p + 1);
            let line: Vec<char> = s[line_start..line_end].to_vec();
            if k == 2 {
                s.drain(line_start..line_end);
            } else {
                s.splice(line_start..line_start, line);
            }
        }
    }
    let edited: String = s.into_iter().collect();
    format!("{}{edited}{}", &text[..start], &text[end..])
}

/// The labels ("(25)") of the display sections of `edited` that differ from every section of
/// `original`: only those can read or check differently (the others are the note's own,
/// checked by the rest of the suite).
fn touched(original: &str, edited: &str) -> Vec<String> {
    let before: std::collections::HashSet<&str> = original.split("\n### ").collect();
    edited
        .split("\n### ")
        .filter(|chunk| !before.contains(chunk))
        .filter_map(|chunk| chunk.find(')').map(|k| chunk[..=k].to_string()))
        .collect()
}

/// Every problem names the file and a line of it, and a reason.
fn well_formed(problem: &str, file: &str, lines: usize) -> bool {
    let Some(rest) = problem.strip_prefix(&format!("{file}:")) else {
        return false;
    };
    let Some((line, reason)) = rest.split_once(": ") else {
        return false;
    };
    line.parse::<usize>()
        .is_ok_and(|l| (1..=lines + 1).contains(&l))
        && !reason.trim().is_empty()
}

/// Edited chapters read and checked: each edit re-checks only the displays it touched.
const ROUNDS: usize = 300;

#[test]
fn random_edits_of_the_displays_are_reported_never_a_panic() {
    // The shape check itself refuses a problem without a line, or with a line past the file.
    assert!(well_formed("a.md:3: (7) has no display", "a.md", 3));
    assert!(!well_formed("a.md: (7) has no display", "a.md", 3));
    assert!(!well_formed("a.md:9: (7) has no display", "a.md", 3));
    assert!(!well_formed("b.md:3: (7) has no display", "a.md", 3));
    // Only the edited section is checked again; an untouched one is not.
    let (a, b) = ("t\n### (1) x\n### (2) y", "t\n### (1) x\n### (2) z");
    assert_eq!(touched(a, b), ["(2)"]);
    assert!(touched(a, a).is_empty());
    let files = chapters();
    assert!(files.len() >= 10, "the chapters: {}", files.len());
    let mut rng = ChaCha8Rng::seed_from_u64(36);
    let quick = Config {
        float_cases: 4,
        exact_points: 1,
        seed: 1,
    };
    let (mut refused, mut checked) = (0, 0);
    for round in 0..ROUNDS {
        let (name, text) = &files[round % files.len()];
        let edited = edit(text, &mut rng);
        let lines = edited.lines().count();
        let note = std::panic::catch_unwind(|| Note::parse([(name.as_str(), edited.as_str())]))
            .unwrap_or_else(|_| panic!("round {round}: the reader panicked on:\n{edited}"));
        for e in &note.errors {
            let p = e.to_string();
            assert!(well_formed(&p, name, lines), "round {round}: {p}");
        }
        refused += usize::from(!note.errors.is_empty());
        // What still reads of the edited sections is checked as `ladder verify` checks the print.
        let changed = touched(text, &edited);
        let note: &'static Note = Box::leak(Box::new(note));
        for e in note
            .equations()
            .into_iter()
            .filter(|e| changed.contains(&e.label()))
        {
            let r = std::panic::catch_unwind(|| {
                let p = sliding_ladder::registry::print_check::check_print(&e, e.latex(), &quick);
                let u = sliding_ladder::registry::print_check::units::print_units(&e, e.latex());
                (p, u.is_ok())
            });
            assert!(
                r.is_ok(),
                "round {round}: the print check of {} panicked",
                e.label()
            );
            checked += 1;
        }
    }
    eprintln!("refused {refused} of {ROUNDS} edited files, {checked} edited displays checked");
    // The edits both break sections and leave many readable (the test sees both paths).
    assert!(
        refused > ROUNDS / 10 && checked > ROUNDS / 3,
        "refused {refused}, checked {checked}"
    );
}

#[test]
fn a_malformed_folder_exits_2_with_file_and_line_and_prints_nothing_else() {
    let files = chapters();
    let mut rng = ChaCha8Rng::seed_from_u64(3600);
    let mut codes = Vec::new();
    for round in 0..8 {
        let dir = std::env::temp_dir().join(format!("ladder-fuzz-{round}-{}", std::process::id()));
        let _ = std::fs::remove_dir_all(&dir);
        std::fs::create_dir_all(&dir).expect("temp dir");
        let (name, text) = &files[rng.gen_range(0..files.len())];
        let file = name.trim_start_matches("equations/");
        // Several edits in one file, to make a malformed section likely.
        let mut edited = text.clone();
        for _ in 0..4 {
            edited = edit(&edited, &mut rng);
        }
        std::fs::write(dir.join(file), &edited).expect("write");
        let out = Command::new(env!("CARGO_BIN_EXE_ladder"))
            .args(["verify", "--equations", dir.to_str().expect("utf-8")])
            .args(["--cases", "4", "--exact-points", "1"])
            .output()
            .expect("ladder runs");
        let (stdout, stderr) = (
            String::from_utf8_lossy(&out.stdout),
            String::from_utf8_lossy(&out.stderr),
        );
        let code = out.status.code();
        codes.push(code);
        match code {
            Some(2) => {
                assert!(stdout.is_empty(), "round {round}: exit 2 wrote {stdout}");
                let want = format!("{}", dir.join(file).display());
                for l in stderr.lines() {
                    let l = l.strip_prefix("ladder: ").unwrap_or(l);
                    assert!(
                        well_formed(l, &want, edited.lines().count()),
                        "round {round}: {l}"
                    );
                }
            }
            Some(1) => assert!(
                stderr.contains("ladder verify: exit 1: "),
                "round {round}: {stderr}"
            ),
            Some(0) => {}
            _ => panic!("round {round}: {code:?}\n{stderr}"),
        }
        let _ = std::fs::remove_dir_all(&dir);
    }
    eprintln!("exit codes: {codes:?}");
    assert!(
        codes.contains(&Some(2)),
        "no edit made a malformed folder: {codes:?}"
    );
}
