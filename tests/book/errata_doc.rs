//! equations/ERRATA.md is in step with the code: every erratum the registry records is there,
//! with its printed and corrected LaTeX verbatim, every prose erratum too, and nothing else.

use sliding_ladder::registry::equations;
use sliding_ladder::verify::claims::claims;
use std::collections::BTreeSet;

fn page() -> String {
    std::fs::read_to_string(sliding_ladder::docs::default_dir().join("ERRATA.md"))
        .expect("equations/ERRATA.md")
}

#[test]
fn every_recorded_erratum_is_on_the_page_and_nothing_else() {
    let text = page();
    let listed: BTreeSet<u32> = text
        .lines()
        .filter_map(|l| l.strip_prefix("### Eq. "))
        .filter_map(|n| n.trim().parse().ok())
        .collect();
    let recorded: BTreeSet<u32> = equations()
        .iter()
        .filter(|e| e.erratum.is_some())
        .map(|e| e.number)
        .collect();
    assert_eq!(
        listed, recorded,
        "ERRATA.md lists {listed:?}, the registry records {recorded:?}"
    );
    for e in equations() {
        if let Some(err) = e.erratum {
            assert!(
                text.contains(&format!("- printed: ${}$", err.printed)),
                "({}) printed form not on the page verbatim",
                e.number
            );
            assert!(
                text.contains(&format!("- corrected: ${}$", err.corrected)),
                "({}) corrected form not on the page verbatim",
                e.number
            );
        }
    }
}

#[test]
fn every_erratum_reading_or_difference_is_on_the_page() {
    let text = page();
    for r in sliding_ladder::verify::errata::errata(&Default::default()) {
        // In physical terms where a reading fits, else the difference with its unit.
        let want = match &r.reading_latex {
            Some(reading) => format!("): {reading}\n"),
            None => format!("${}$, in {}\n", r.difference_latex, r.residual_unit),
        };
        assert!(
            text.contains(&want),
            "({}) the misprint is not on the page as the code reads it: {want}",
            r.number
        );
    }
}

#[test]
fn every_prose_erratum_is_on_the_page() {
    let text = page();
    let mut n = 0;
    for c in claims() {
        assert!(c.holds, "{}: {}", c.location, c.claim);
        if let Some((printed, corrected)) = c.erratum {
            n += 1;
            assert!(
                text.contains(&format!("### {}", c.location)),
                "{} missing",
                c.location
            );
            assert!(
                text.contains(printed) && text.contains(corrected),
                "{}: forms missing",
                c.location
            );
        }
    }
    assert!(n >= 2);
}
