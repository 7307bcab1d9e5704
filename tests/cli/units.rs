//! Issue 14 as the commands show it: the `units` column of `ladder verify` (with the offending sum
//! under an inconsistent row) and the units witness of every erratum in `ladder errata` (text and
//! JSON). The displays units alone catch, (49), (62) and (68), are written here by hand.

use std::process::Command;

/// The errata whose printed form drops a dimensional factor.
const CAUGHT_BY_UNITS: [u64; 3] = [49, 62, 68];

fn ladder(args: &[&str]) -> String {
    let out = Command::new(env!("CARGO_BIN_EXE_ladder"))
        .args(args)
        .output()
        .expect("ladder runs");
    assert_eq!(out.status.code(), Some(0), "ladder {args:?}");
    String::from_utf8(out.stdout).expect("UTF-8")
}

/// The cells line of display `n` (the line after its title) and the line after that.
fn row(text: &str, n: u32) -> (String, String) {
    let lines: Vec<&str> = text.lines().collect();
    let at = lines
        .iter()
        .position(|l| l.trim_start().starts_with(&format!("({n}) ")))
        .unwrap_or_else(|| panic!("no row ({n}) in\n{text}"));
    (lines[at + 1].to_string(), lines[at + 2].to_string())
}

/// The verdict a row's units column gives.
fn units_cell(cells: &str) -> &'static str {
    let words: Vec<&str> = cells.split_whitespace().collect();
    ["inconsistent", "consistent", "dimensionless", "not"]
        .into_iter()
        .find(|w| words.contains(w))
        .unwrap_or("missing")
}

#[test]
fn the_verify_table_has_a_units_column_naming_the_offending_sum() {
    let text = ladder(&[
        "verify",
        "--only",
        "12,25,49,62,68",
        "--cases",
        "2",
        "--exact-points",
        "1",
        "--width",
        "100",
    ]);
    assert!(text.contains(" units "), "no units column:\n{text}");
    for n in [12, 25, 49, 62, 68] {
        let (cells, next) = row(&text, n);
        let caught = CAUGHT_BY_UNITS.contains(&u64::from(n));
        let want = if caught { "inconsistent" } else { "consistent" };
        assert_eq!(units_cell(&cells), want, "({n}): {cells}");
        // An inconsistent row is followed by what units saw: a sum or a form of another
        // dimension, with the dimensions.
        if caught {
            assert!(next.trim_start().starts_with("units: "), "({n}): {next}");
            assert!(next.contains("form") && next.contains('T'), "({n}): {next}");
        }
    }
    // The check can fail: a row of another verdict is told apart.
    assert_eq!(
        units_cell("kinematic verified proved consistent 3/3"),
        "consistent"
    );
    assert_ne!(
        units_cell("kinematic erratum proved inconsistent 3/3"),
        "consistent"
    );
}

#[test]
fn ladder_errata_gives_every_erratum_its_units_witness() {
    let json: serde_json::Value =
        serde_json::from_str(&ladder(&["errata", "--json"])).expect("JSON");
    let list = json["errata"].as_array().expect("errata");
    assert_eq!(list.len(), 5);
    let mut caught = Vec::new();
    for e in list {
        let n = e["number"].as_u64().expect("number");
        let u = &e["units"];
        assert_eq!(u["corrected"], "consistent", "({n}) {u}");
        assert_eq!(u["printed"], u["printed_code"], "({n}) {u}");
        match u["printed"].as_str() {
            Some("inconsistent") => caught.push(n),
            Some("consistent") => {}
            other => panic!("({n}): printed {other:?}"),
        }
    }
    assert_eq!(caught, CAUGHT_BY_UNITS);
    // The prose claims with units: only the A.5 slip is inconsistent, and its correction is not.
    for p in json["prose_units"].as_array().expect("prose_units") {
        let slip = p["location"] == "sec. A.5";
        let want = if slip { "inconsistent" } else { "consistent" };
        assert_eq!(p["units"], want, "{p}");
        if slip {
            assert_eq!(p["corrected"], "consistent", "{p}");
        }
    }
    // The terminal says it too, once per erratum.
    let text = ladder(&["errata", "--width", "200"]);
    let lines: Vec<&str> = text
        .lines()
        .filter(|l| l.contains("units: printed form"))
        .collect();
    assert_eq!(lines.len(), 5, "{text}");
    let inconsistent = lines
        .iter()
        .filter(|l| l.contains("printed form inconsistent"))
        .count();
    assert_eq!(inconsistent, CAUGHT_BY_UNITS.len(), "{lines:#?}");
    assert!(
        lines
            .iter()
            .all(|l| l.contains("corrected form consistent")),
        "{lines:#?}"
    );
}
