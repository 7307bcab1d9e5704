//! What a shown display assumes (its `*Premises:*`, or what its kind and states assume) and which
//! of its symbols its states cannot tell from another ([`crate::registry::print_check::twins`]).

use crate::print::unicode::unicode;
use crate::registry::print_check::{print_sample, twins::indistinguishable, PrintSample};
use crate::registry::{Equation, Kind, LadderSample};

/// One line per premise: `source: condition (words)`.
pub fn premise_lines(e: &Equation) -> Vec<String> {
    let mut out: Vec<String> = e
        .premises
        .iter()
        .map(|p| {
            let cond = p.latex.as_deref().map(unicode);
            match (cond, p.words.is_empty()) {
                (Some(c), true) => format!("{}: {c}", p.source.name()),
                (Some(c), false) => format!("{}: {c} ({})", p.source.name(), p.words),
                (None, _) => format!("{}: {}", p.source.name(), p.words),
            }
        })
        .collect();
    let states = match print_sample(e) {
        Some(PrintSample::Ladder(LadderSample::OnShellFromRest)) => {
            "the motion: θ̈ from (5), released at rest upright (θ̇² from (10))"
        }
        Some(PrintSample::Ladder(LadderSample::OnShell)) => "the motion: θ̈ from (5), θ̇ free",
        Some(PrintSample::Ladder(LadderSample::Kinematic)) if e.kind == Kind::Newton => {
            "the ladder on wall and floor, its contact forces those the motion requires; θ, θ̇, θ̈ free"
        }
        Some(PrintSample::Ladder(_)) => "the ladder on wall and floor; θ, θ̇, θ̈ free",
        Some(PrintSample::Particles(_)) if out.is_empty() => {
            "none: any particles, any moving P"
        }
        Some(PrintSample::Particles(_)) => return out,
        None => "the ladder off the wall (the floor phase)",
    };
    out.push(format!("states: {states}"));
    out
}

/// One line per pair of symbols no state of the display tells apart.
pub fn twin_lines(e: &Equation) -> Vec<String> {
    indistinguishable(e)
        .into_iter()
        .map(|t| {
            format!(
                "{} and {} ({} and {}) are equal at every state of this display: writing one for the other is invisible here",
                unicode(&t.printed),
                unicode(&t.other),
                t.quantities.0,
                t.quantities.1
            )
        })
        .collect()
}
