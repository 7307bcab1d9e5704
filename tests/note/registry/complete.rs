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

/// A check compares: each check of every display (the note's and those beyond it) gives at
/// least one chain, and every chain has at least two sides that must hold. A chain function
/// that returned nothing would pass every state it was run at (mutation shard registry 5/40:
/// the floor phase's `p5` emptied, and the quick tests passed).
#[test]
fn every_check_compares_at_least_two_sides_in_each_chain() {
    use sliding_ladder::registry::units::dimension_chains;
    use sliding_ladder::registry::{extensions, Role};
    let mut checks = 0;
    for e in equations().iter().chain(&extensions()) {
        for c in &e.checks {
            let chains = dimension_chains(c);
            assert!(!chains.is_empty(), "({}) {}: no chain", e.number, c.name);
            for chain in &chains {
                let holding = chain.iter().filter(|s| s.role != Role::Misprint).count();
                assert!(
                    holding >= 2,
                    "({}) {}: a chain of {holding} side(s) that must hold",
                    e.number,
                    c.name
                );
            }
            checks += 1;
        }
    }
    assert!(checks > 90, "{checks}");
}
