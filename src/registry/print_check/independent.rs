//! The Rust forms at a display's first exact point, against the print: each Rust printed or
//! misprinted form must equal some printed form ([`rust_sides`], matched in [`super::run`]); and
//! for an erratum, each correct printed form must equal an independent value of its Rust check
//! ([`erratum_against_references`]).
//!
//! Why the second: in (54) and (62) the only printed form besides the misprint is the correct
//! side, so its chain holds it to nothing; a typo there was caught only because the hand-typed
//! Rust copy disagreed. The check's `reference` sides (a torque from the forces and lever arms,
//! a rate by automatic differentiation) are computed from the model, neither from the print nor
//! from the copy, so the printed correct side is now held to the physics as well.

use super::{form_text, Form};
use crate::registry::{Chain, Equation, Role};
use crate::scalar::Rational;
use num_traits::Zero;

/// The Rust printed and misprinted forms' values, once each, with their labels.
pub(super) fn rust_sides(chains: &[Chain<Rational>]) -> Vec<(String, Rational)> {
    chains
        .iter()
        .flatten()
        .filter(|s| matches!(s.role, Role::Printed | Role::Misprint))
        .map(|s| (s.label.to_string(), s.value.clone()))
        .fold(Vec::new(), |mut acc: Vec<(String, Rational)>, x| {
            if !acc.iter().any(|a| a.0 == x.0 && a.1 == x.1) {
                acc.push(x);
            }
            acc
        })
}

/// For an erratum display: every correct printed form (not the misprint) must equal one of the
/// independent values (`reference` sides) of its Rust check, at the same exact state. A zero
/// component (z of a planar vector, x and y of (49)'s ẑ) says nothing and is skipped. Nothing to
/// do for a display that is no erratum or whose check has no reference.
pub(super) fn erratum_against_references(
    e: &Equation,
    chains: &[Vec<Form>],
    print: &[Chain<Rational>],
    rust: &[Chain<Rational>],
) -> Vec<String> {
    let references: Vec<&crate::registry::Side<Rational>> = rust
        .iter()
        .flatten()
        .filter(|s| s.role == Role::Reference && !s.value.is_zero())
        .collect();
    if e.erratum.is_none() || references.is_empty() {
        return Vec::new();
    }
    let mut labels: Vec<&str> = references.iter().map(|s| s.label).collect();
    labels.dedup();
    let mut out: Vec<String> = Vec::new();
    for side in print.iter().flatten() {
        if side.role != Role::Printed
            || side.value.is_zero()
            || references.iter().any(|r| r.value == side.value)
        {
            continue;
        }
        let msg = format!(
            "print: {} '{}', a correct form of the erratum, differs from the independent {}",
            side.label,
            form_text(chains, side.label),
            labels.join("; ")
        );
        if !out.contains(&msg) {
            out.push(msg);
        }
    }
    out
}
