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

/// One line per pair of symbols no state of the display tells apart, with whether the symbol
/// check ([`crate::print::own_point`]) catches writing the other for the printed one.
pub fn twin_lines(e: &Equation) -> Vec<String> {
    indistinguishable(e)
        .into_iter()
        .map(|t| {
            format!(
                "{} and {} ({} and {}) are equal at every state of this display, so no value sees one written for the other (invisible here); {} for {}: {}",
                unicode(&t.printed),
                unicode(&t.other),
                t.quantities.0,
                t.quantities.1,
                unicode(&t.other),
                unicode(&t.printed),
                symbol_check(e, &t.printed, &t.other)
            )
        })
        .collect()
}

/// What the symbol check says of writing `other` where `printed` is.
pub fn symbol_check(e: &Equation, printed: &str, other: &str) -> String {
    use crate::print::own_point::{point_of, Allowance, ExceptionKind};
    let rules = crate::print::symbols::point_rules();
    let (Some(mine), Some(theirs)) = (point_of(printed), point_of(other)) else {
        return "neither is subscripted with a point, so the symbol check cannot tell them apart either".into();
    };
    if mine == theirs {
        return format!(
            "both are symbols of point {mine}, so the symbol check cannot tell them apart either"
        );
    }
    // A display that compares points on purpose must keep a symbol of each.
    let ours: Vec<String> = crate::show::find::symbols_of(e)
        .into_iter()
        .filter(|(k, milne)| !milne && k != printed)
        .map(|(k, _)| k)
        .collect();
    let compared = rules.exceptions.iter().find(|x| {
        x.equation == e.number
            && x.kind == ExceptionKind::Compares
            && x.points.iter().any(|p| p == mine)
    });
    if let Some(x) = compared.filter(|_| !ours.iter().any(|k| point_of(k) == Some(mine))) {
        return format!(
            "the symbol check catches it: ({}) compares {} on purpose and would print no symbol of {mine}",
            e.number,
            x.points.join(", ")
        );
    }
    let shown = unicode(other);
    let slip = match rules.allows(e.section, e.number, printed, mine) {
        Allowance::Exception(x) if x.kind == ExceptionKind::Slip => Some(x),
        _ => None,
    };
    match rules.allows(e.section, e.number, other, theirs) {
        Allowance::Section(_) if slip.is_some() => format!(
            "the symbol check allows {shown}: {theirs} is sec. {}'s own point, and {shown} is what the note means ({})",
            e.section,
            slip.map_or("", |x| x.why.as_str())
        ),
        Allowance::Unruled => format!(
            "sec. {} has no symbol rule, so nothing catches it",
            e.section
        ),
        Allowance::Foreign(r) => format!(
            "the symbol check catches it: {shown} names point {theirs}, not among sec. {}'s points ({})",
            e.section,
            r.allowed.join(", ")
        ),
        Allowance::Section(r) => format!(
            "the symbol check allows {shown} here ({theirs} is among sec. {}'s points: {})",
            e.section, r.why
        ),
        Allowance::Exception(x) => format!(
            "the symbol check allows {shown} here: ({}) names {} on purpose ({})",
            e.number,
            x.points.join(", "),
            x.why
        ),
    }
}
