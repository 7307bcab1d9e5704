//! An erratum in physical terms, for the reader: what the printed form lost or put in the wrong
//! place ("the printed term l²θ̇(c² − s²) lacks a factor m", "has θ̇² where θ̈ belongs"), read
//! from printed − corrected by [`crate::scalar::reading`], and the unit the residuals are in.

use crate::registry::units::dimension_chains;
use crate::registry::{Equation, Role};
use crate::scalar::{reading as read, Dimension, Reading};

/// The misprint of `e` read in physical terms, as (plain text, markdown with `$…$` math), or
/// `None` when neither reading fits (the book then shows printed − corrected). For a vector
/// display every component must read alike ("a factor m₁" in each).
pub fn reading(e: &Equation) -> Option<(String, String)> {
    let d = e
        .checks
        .iter()
        .map(crate::registry::prove::erratum_difference)
        .find(|d| !d.is_empty())?;
    let readings: Vec<Reading> = d.iter().map(read).collect::<Option<_>>()?;
    let md = match readings.as_slice() {
        [one] => Some(one.render(true)),
        many if many.iter().all(|r| r.kind(false) == many[0].kind(false)) => {
            let terms: Vec<String> = many.iter().map(|r| r.term(true)).collect();
            let whose = match many[0] {
                Reading::MissingFactor { .. } => "the printed term lacks",
                Reading::Swapped { .. } => "the printed form has",
            };
            let kind = many[0].kind(true);
            Some(format!(
                "in each component (x, y, z), {whose} {kind}: $\\left({}\\right)$",
                terms.join(",\\quad ")
            ))
        }
        _ => None,
    }?;
    Some((plain(&md), md))
}

/// Markdown with `$…$` math as the terminal reads it: each formula in Unicode.
pub fn plain(md: &str) -> String {
    md.split('$')
        .enumerate()
        .map(|(i, part)| {
            if i % 2 == 1 {
                crate::print::unicode::unicode(part)
            } else {
                part.to_string()
            }
        })
        .collect()
}

/// The unit of `e`'s residuals: the dimension of its corrected form, named ("N·m",
/// "kg·m²/s") where it has a common name, else in SI base units.
pub fn residual_unit(e: &Equation) -> String {
    e.checks
        .iter()
        .flat_map(dimension_chains)
        .find_map(|chain| {
            chain
                .iter()
                .find(|s| s.role == Role::Corrected)
                .and_then(|s| s.value.dimension())
        })
        .map(unit_name)
        .unwrap_or_else(|| "unknown unit".into())
}

/// A dimension's everyday SI name.
pub fn unit_name(d: Dimension) -> String {
    let named = [
        (Dimension::new(1, 2, -2), "N·m"),
        (Dimension::new(1, 2, -1), "kg·m²/s"),
        (Dimension::new(1, 1, -2), "N"),
        (Dimension::new(1, 1, -1), "kg·m/s"),
        (Dimension::new(0, 0, -1), "1/s"),
        (Dimension::new(0, 0, -2), "1/s²"),
    ];
    named
        .iter()
        .find(|(n, _)| *n == d)
        .map(|(_, s)| s.to_string())
        .unwrap_or_else(|| d.si_unit())
}
