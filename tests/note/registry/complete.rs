//! The registry is complete: the note's displays numbered from 1 without a gap, each once, with a
//! title, a kind, printed LaTeX, functions and at least one check.

use sliding_ladder::registry::{equations, Kind};
use std::collections::BTreeMap;

#[test]
fn every_number_once_with_a_check() {
    let mut seen = BTreeMap::new();
    for e in equations() {
        assert!(
            seen.insert(e.number, e.title).is_none(),
            "({}) registered twice",
            e.number
        );
        assert!(!e.checks.is_empty(), "({}) has no check", e.number);
        assert!(!e.functions.is_empty(), "({}) names no function", e.number);
        assert!(
            !e.title.is_empty() && !e.latex().is_empty(),
            "({}) lacks a title or LaTeX",
            e.number
        );
    }
    let last = seen.keys().last().copied().unwrap_or(0);
    let missing: Vec<u32> = (1..=last).filter(|n| !seen.contains_key(n)).collect();
    assert!(missing.is_empty(), "missing equations: {missing:?}");
    assert!(!seen.is_empty());
}

#[test]
fn on_shell_equations_have_an_on_shell_check() {
    use sliding_ladder::registry::Eval;
    for e in equations().iter().filter(|e| e.kind == Kind::OnShell) {
        let any = e
            .checks
            .iter()
            .any(|c| matches!(c.eval, Eval::Ladder(s, _) if s.on_shell()));
        assert!(
            any,
            "({}) is on-shell but never checked on the motion",
            e.number
        );
    }
}

#[test]
fn errata_carry_both_forms() {
    for e in equations() {
        if let Some(err) = e.erratum {
            assert!(
                !err.printed.is_empty()
                    && !err.corrected.is_empty()
                    && err.printed != err.corrected,
                "({})",
                e.number
            );
        }
    }
}
