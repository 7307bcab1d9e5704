//! The markdown is the source of the registry (issue 36): what `ladder verify --json` reports of
//! each display, its title and its law, is what the display's section in `equations/*.md` says,
//! read here with a plain line scan, independently of the crate's parser.

mod fields;
mod generated;
mod note;
mod parse;
mod premises;
mod symbols;

use serde_json::Value;
use std::collections::BTreeMap;
use std::process::Command;

/// The lines of a markdown text outside its fenced code blocks (EXTENDING.md shows sections as
/// examples inside them).
fn outside_code(text: &str) -> Vec<&str> {
    let mut fenced = false;
    text.lines()
        .filter(|l| {
            if l.trim_start().starts_with("```") {
                fenced = !fenced;
                return false;
            }
            !fenced
        })
        .collect()
}

/// Every display heading `### (N) Title` or `### (Pk) Title` of the book, by label: a line scan
/// of the files, not the crate's parser.
fn headings() -> BTreeMap<String, String> {
    let dir = sliding_ladder::docs::default_dir();
    let mut out = BTreeMap::new();
    for f in std::fs::read_dir(&dir).expect("equations/").flatten() {
        let p = f.path();
        if p.extension().is_none_or(|x| x != "md") {
            continue;
        }
        for line in outside_code(&std::fs::read_to_string(&p).expect("readable")) {
            let Some(rest) = line.strip_prefix("### (") else {
                continue;
            };
            let Some((label, title)) = rest.split_once(") ") else {
                continue;
            };
            let old = out.insert(format!("({label})"), title.trim().to_string());
            assert!(old.is_none(), "({label}) twice");
        }
    }
    out
}

/// The `*Law:*` statements of the book by label: on a line starting `*Law:*`, the text after
/// "is the law of motion: " up to the sentence that follows it.
fn laws() -> BTreeMap<String, String> {
    let dir = sliding_ladder::docs::default_dir();
    let mut out = BTreeMap::new();
    for f in std::fs::read_dir(&dir).expect("equations/").flatten() {
        let text = std::fs::read_to_string(f.path()).unwrap_or_default();
        let mut label = None;
        for line in outside_code(&text) {
            if let Some(rest) = line.strip_prefix("### (") {
                label = rest.split_once(')').map(|(l, _)| format!("({l})"));
            }
            let law = line.strip_prefix("*Law:* ");
            let Some(rest) = law.and_then(|l| l.split_once("is the law of motion: ")) else {
                continue;
            };
            let rest = rest.1;
            let end = [". Every other", ". This is the only"]
                .iter()
                .filter_map(|t| rest.find(t))
                .min()
                .unwrap_or(rest.len());
            out.insert(
                label.clone().expect("a law under a heading"),
                rest[..end].to_string(),
            );
        }
    }
    out
}

/// The rows of `ladder verify --json` (the note's and the extensions'), few states per check:
/// titles and laws do not depend on them.
fn verify_rows() -> Vec<Value> {
    let out = Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args(["verify", "--json", "--cases", "5", "--exact-points", "1"])
        .output()
        .expect("ladder runs");
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let v: Value = serde_json::from_slice(&out.stdout).expect("JSON");
    let mut rows = v["equations"].as_array().expect("equations").clone();
    rows.extend(
        v["extensions"]
            .as_array()
            .expect("extensions")
            .iter()
            .cloned(),
    );
    rows
}

/// Where the rows' field `key` differs from `want` (by label), as "(N): row | book".
fn differences(rows: &[Value], want: &BTreeMap<String, String>, key: &str) -> Vec<String> {
    let mut out = Vec::new();
    for r in rows {
        let label = r["label"].as_str().unwrap_or("?");
        let got = r[key].as_str();
        if got != want.get(label).map(String::as_str) {
            out.push(format!("{label}: {got:?} | {:?}", want.get(label)));
        }
    }
    out
}

#[test]
fn verify_reports_every_title_and_law_as_the_markdown_writes_it() {
    let rows = verify_rows();
    let h = headings();
    assert_eq!(rows.len(), h.len(), "a display of the book is not verified");
    assert_eq!(differences(&rows, &h, "title"), Vec::<String>::new());
    let with_law: Vec<Value> = rows
        .iter()
        .filter(|r| r["law"].is_string())
        .cloned()
        .collect();
    let l = laws();
    assert_eq!(with_law.len(), l.len(), "a *Law:* line is not reported");
    assert_eq!(differences(&with_law, &l, "law"), Vec::<String>::new());
    // The comparison sees a drifted title: the registry's old title of (85) is caught.
    let mut drifted = rows.clone();
    let k = drifted
        .iter()
        .position(|r| r["label"] == "(85)")
        .expect("(85)");
    drifted[k]["title"] = "Rate of change of L from that of L_P; Milne's dH(O')/dt".into();
    assert_eq!(differences(&drifted, &h, "title").len(), 1);
}
