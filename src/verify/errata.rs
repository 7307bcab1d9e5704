//! `ladder errata`: the note's misprints, each with the residual of the printed form (nonzero)
//! and of the corrected form (zero) at an exact rational sample point.

use super::units::{erratum_units, ErratumUnits};
use crate::registry::check::Config;
use crate::registry::sample::{exact_ladder, particle_system, EXTRA, LADDER_DRAWS, PER_PARTICLE};
use crate::registry::{equations, Chain, Eval, Role};
use crate::scalar::{Rational, Scalar};
use serde::Serialize;

/// One erratum of the note with its evidence.
#[derive(Clone, Debug, Serialize)]
pub struct ErratumReport {
    /// Equation number.
    pub number: u32,
    /// The printed form (LaTeX).
    pub printed: &'static str,
    /// The corrected form (LaTeX).
    pub corrected: &'static str,
    /// Why.
    pub why: &'static str,
    /// Printed form minus the reference, at the sample point (exact, shown as a decimal).
    pub printed_residual: f64,
    /// The same fraction, exactly.
    pub printed_residual_exact: String,
    /// Corrected form minus the reference: exactly zero.
    pub corrected_residual: String,
    /// printed − corrected as a function of free variables (s = sin θ, c = cos θ, θ̇, θ̈, …;
    /// for a sum over particles, the summand of particle 1), simplified modulo s² + c² = 1, as
    /// plain text; a vector is (x, y, z).
    pub difference_text: String,
    /// The same difference as LaTeX.
    pub difference_latex: String,
    /// The second witness: dimensional analysis of the printed and corrected forms.
    pub units: ErratumUnits,
}

/// printed − corrected of an equation's erratum, as (text, LaTeX) (see [`ErratumReport`]).
pub fn difference(e: &crate::registry::Equation) -> (String, String) {
    let d = e
        .checks
        .iter()
        .map(crate::registry::prove::erratum_difference)
        .find(|d| !d.is_empty())
        .unwrap_or_default();
    match d.as_slice() {
        [one] => (crate::scalar::text(one), crate::scalar::latex(one)),
        many => (
            format!(
                "({})",
                many.iter()
                    .map(crate::scalar::text)
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
            format!(
                "\\left({}\\right)",
                many.iter()
                    .map(crate::scalar::latex)
                    .collect::<Vec<_>>()
                    .join(",\\ ")
            ),
        ),
    }
}

fn residuals(chains: &[Chain<Rational>]) -> Option<(Rational, Rational)> {
    for c in chains {
        let base = c.iter().find(|s| s.role != Role::Misprint)?;
        let bad = c.iter().find(|s| s.role == Role::Misprint);
        let good = c.iter().find(|s| s.role == Role::Corrected);
        if let (Some(b), Some(g)) = (bad, good) {
            return Some((
                b.value.clone() - base.value.clone(),
                g.value.clone() - base.value.clone(),
            ));
        }
    }
    None
}

/// The errata of the note, in order, with residuals at a fixed small rational point
/// (t = 1/2, m = 3, l = 5, g = 7, θ̇ = 2, θ̈ = −1, θ⃛ = 4 for the ladder).
pub fn errata(_cfg: &Config) -> Vec<ErratumReport> {
    let mut out = Vec::new();
    for e in equations() {
        let Some(err) = e.erratum else { continue };
        let mut found = None;
        for c in &e.checks {
            let chains = match c.eval {
                Eval::Ladder(sort, f) => {
                    let v: [Rational; LADDER_DRAWS] = [
                        Rational::ratio(1, 2),
                        Rational::int(3),
                        Rational::int(5),
                        Rational::int(7),
                        Rational::int(2),
                        Rational::int(-1),
                        Rational::int(4),
                    ];
                    let (l, s) = exact_ladder(sort, v);
                    (f.exact)(&l, &s)
                }
                Eval::Floor(..) => continue, // the extension has no errata
                Eval::Particles(sort, f) => {
                    let n = 3;
                    let values: Vec<Rational> = (0..n * PER_PARTICLE + EXTRA)
                        .map(|i| Rational::int((i as i64 * 7919) % 23 + 1))
                        .collect();
                    let (sys, p) = particle_system(sort, n, &values);
                    (f.exact)(&sys, &p)
                }
            };
            if let Some(r) = residuals(&chains) {
                found = Some(r);
                break;
            }
        }
        let (bad, good) = found.unwrap_or((Rational::int(0), Rational::int(1)));
        let (difference_text, difference_latex) = difference(&e);
        out.push(ErratumReport {
            number: e.number,
            printed: err.printed,
            corrected: err.corrected,
            why: err.why,
            printed_residual: bad.to_f64(),
            printed_residual_exact: bad.to_string(),
            corrected_residual: good.to_string(),
            difference_text,
            difference_latex,
            units: erratum_units(&e),
        });
    }
    out
}
