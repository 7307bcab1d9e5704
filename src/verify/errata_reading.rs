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

#[cfg(test)]
mod tests {
    use super::*;
    use crate::registry::equations;

    fn eq(n: u32) -> Equation {
        equations().into_iter().find(|e| e.number == n).unwrap()
    }

    #[test]
    fn the_five_errata_read_in_physical_terms_with_their_units() {
        // From the print: (49) and (68) lost a mass, (62) a factor 2l, (54) has θ̇² for θ̈.
        let r49 = reading(&eq(49)).unwrap().0;
        assert!(r49.ends_with("lacks a factor m"), "{r49}");
        let r62 = reading(&eq(62)).unwrap().0;
        assert!(r62.ends_with("lacks a factor 2l"), "{r62}");
        let r54 = reading(&eq(54)).unwrap().0;
        assert!(r54.contains("has θ̇² where θ̈ belongs"), "{r54}");
        let r68 = reading(&eq(68)).unwrap().0;
        assert!(
            r68.starts_with("in each component (x, y, z), the printed term lacks a factor m₁: ("),
            "{r68}"
        );
        // (28) lost a whole term, F_E,x l cos θ: no reading, the difference is shown instead.
        assert_eq!(reading(&eq(28)), None);
        // Torques in N·m, (49)'s angular momentum in kg·m²/s; (68) is a torque too.
        for (n, unit) in [
            (28, "N·m"),
            (49, "kg·m²/s"),
            (54, "N·m"),
            (62, "N·m"),
            (68, "N·m"),
        ] {
            assert_eq!(residual_unit(&eq(n)), unit, "({n})");
        }
    }

    #[test]
    fn an_unnamed_dimension_is_in_base_units() {
        assert_eq!(unit_name(Dimension::new(0, 1, -3)), "m s^-3");
        assert_eq!(unit_name(Dimension::new(1, 2, -2)), "N·m");
    }
}
