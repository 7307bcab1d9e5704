//! `ladder errata`: the note's misprints, each with the residual of the printed form (nonzero)
//! and of the corrected form (zero) at an exact rational sample point.

use super::units::{erratum_units, ErratumUnits};
use crate::registry::check::Config;
use crate::registry::sample::{exact_ladder, particle_system, EXTRA, LADDER_DRAWS, PER_PARTICLE};
use crate::registry::{equations, Chain, Eval, Role};
use crate::scalar::{Rational, Scalar};
use num_traits::Zero;
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
    /// Which form of the display is misprinted, counted from 1 in print order (as `ladder show`
    /// numbers them), and its LaTeX as printed.
    pub misprinted_form: Option<usize>,
    /// The misprinted form's LaTeX ([`crate::registry::print_check::misprints`]).
    pub misprinted_form_latex: Option<&'static str>,
    /// What the residuals are measured against: the first side of the chain that holds the
    /// misprint (a printed form or an independent reference), by its label.
    pub residual_against: &'static str,
    /// For a vector display, the component the residuals are of (`x`, `y` or `z`).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub residual_component: Option<char>,
    /// The exact point of the residuals, each coordinate as (name, exact value): the ladder's
    /// m, l, g, sin θ, cos θ, θ̇, θ̈, θ⃛ as the check evaluates them (on-shell: θ̈ from (5)), or
    /// the particles' masses and motions and P's.
    pub point: Vec<(String, String)>,
    /// Printed form minus the reference, at the sample point (exact, shown as a decimal).
    pub printed_residual: f64,
    /// The same fraction, exactly.
    pub printed_residual_exact: String,
    /// Corrected form minus the reference: exactly zero.
    pub corrected_residual: String,
    /// printed − corrected as a function of free variables (s = sin θ, c = cos θ, θ̇, θ̈, …;
    /// for a sum over particles, the summand of particle 1), simplified modulo s² + c² = 1, as
    /// plain text, factored for reading ([`crate::scalar::factored_text`]); a vector is (x, y, z).
    pub difference_text: String,
    /// The same difference as LaTeX.
    pub difference_latex: String,
    /// The misprint in physical terms ("the printed term … lacks a factor m", "has θ̇² where θ̈
    /// belongs"), when one of [`crate::scalar::Reading`]'s readings fits; else `None`, and the
    /// reader is shown the difference.
    pub reading: Option<String>,
    /// The same, as markdown with `$…$` math (for the book and ERRATA.md).
    pub reading_latex: Option<String>,
    /// The unit of the residuals: the corrected form's ("N·m", "kg·m²/s").
    pub residual_unit: String,
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
        [one] => (
            crate::scalar::factored_text(one),
            crate::scalar::factored_latex(one),
        ),
        many => (
            format!(
                "({})",
                many.iter()
                    .map(crate::scalar::factored_text)
                    .collect::<Vec<_>>()
                    .join(", ")
            ),
            format!(
                "\\left({}\\right)",
                many.iter()
                    .map(crate::scalar::factored_latex)
                    .collect::<Vec<_>>()
                    .join(",\\ ")
            ),
        ),
    }
}

/// (printed − base, corrected − base, the base's label) in the first chain with a misprint
/// whose residual is nonzero (of a vector, the first component that shows it), else the first.
type Residuals = (Rational, Rational, &'static str, Option<char>);

fn residuals(chains: &[Chain<Rational>]) -> Option<Residuals> {
    let mut first = None;
    for (k, c) in chains.iter().enumerate() {
        let Some(base) = c.iter().find(|s| s.role != Role::Misprint) else {
            continue;
        };
        let bad = c.iter().find(|s| s.role == Role::Misprint);
        let good = c.iter().find(|s| s.role == Role::Corrected);
        if let (Some(b), Some(g)) = (bad, good) {
            let r = (
                b.value.clone() - base.value.clone(),
                g.value.clone() - base.value.clone(),
                base.label,
                (chains.len() == 3).then(|| ['x', 'y', 'z'][k]),
            );
            if !r.0.is_zero() {
                return Some(r);
            }
            first.get_or_insert(r);
        }
    }
    first
}

/// The form of `latex` (counted from 1 in print order) that is the misprint recorded for
/// display `number`, with the misprint's LaTeX.
pub fn misprinted_form(number: u32, latex: &str) -> Option<(usize, &'static str)> {
    use crate::print::parser::{canonical, parse_display};
    let (_, wrong) = crate::registry::print_check::misprints()
        .into_iter()
        .find(|m| m.0 == number)?;
    let want = canonical(wrong).ok()?;
    let display = parse_display(latex).ok()?;
    let texts = display.statements.iter().flat_map(|s| {
        s.chain
            .texts
            .iter()
            .chain(s.implies.iter().flat_map(|c| c.texts.iter()))
    });
    let k = texts
        .map(|t| canonical(t).unwrap_or_default())
        .position(|t| t == want)?;
    Some((k + 1, wrong))
}

fn ladder_point(
    l: &crate::ladder::Ladder<Rational>,
    s: &crate::ladder::State<Rational>,
) -> Vec<(String, String)> {
    [
        ("m", &l.m),
        ("l", &l.l),
        ("g", &l.g),
        ("sin θ", &s.sin),
        ("cos θ", &s.cos),
        ("θ̇", &s.rate),
        ("θ̈", &s.accel),
        ("θ⃛", &s.jerk),
    ]
    .into_iter()
    .map(|(n, v)| (n.to_string(), v.to_string()))
    .collect()
}

fn particle_point(
    sys: &crate::system::System<Rational>,
    p: &crate::system::Point<Rational>,
) -> Vec<(String, String)> {
    let v3 = |v: &crate::vector::Vec3<Rational>| format!("({}, {}, {})", v.x, v.y, v.z);
    let mut out = Vec::new();
    for (i, q) in sys.particles.iter().enumerate() {
        let i = i + 1;
        out.push((format!("m_{i}"), q.m.to_string()));
        out.push((format!("x_{i}"), v3(&q.x)));
        out.push((format!("v_{i}"), v3(&q.v)));
        out.push((format!("a_{i}"), v3(&q.a)));
    }
    out.push(("x_P".into(), v3(&p.x)));
    out.push(("v_P".into(), v3(&p.v)));
    out.push(("a_P".into(), v3(&p.a)));
    out
}

/// The errata of the note, in order, with residuals at a fixed small rational point
/// (t = 1/2, m = 3, l = 5, g = 7, θ̇ = 2, θ̈ = −1, θ⃛ = 4 for the ladder).
pub fn errata(_cfg: &Config) -> Vec<ErratumReport> {
    let mut out = Vec::new();
    for e in equations() {
        let Some(err) = e.erratum else { continue };
        let mut found = None;
        let mut point = Vec::new();
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
                    point = ladder_point(&l, &s);
                    (f.exact)(&l, &s)
                }
                Eval::Floor(..) => continue, // the extension has no errata
                Eval::Particles(sort, f) => {
                    let n = 3;
                    let values: Vec<Rational> = (0..n * PER_PARTICLE + EXTRA)
                        .map(|i| Rational::int((i as i64 * 7919) % 23 + 1))
                        .collect();
                    let (sys, p) = particle_system(sort, n, &values);
                    point = particle_point(&sys, &p);
                    (f.exact)(&sys, &p)
                }
            };
            if let Some(r) = residuals(&chains) {
                found = Some(r);
                break;
            }
        }
        let (bad, good, against, component) =
            found.unwrap_or((Rational::int(0), Rational::int(1), "none", None));
        let form = misprinted_form(e.number, e.latex());
        let (difference_text, difference_latex) = difference(&e);
        let reading = super::errata_reading::reading(&e);
        out.push(ErratumReport {
            number: e.number,
            printed: err.printed,
            corrected: err.corrected,
            why: err.why,
            misprinted_form: form.map(|f| f.0),
            misprinted_form_latex: form.map(|f| f.1),
            residual_against: against,
            residual_component: component,
            point,
            printed_residual: bad.to_f64(),
            printed_residual_exact: bad.to_string(),
            corrected_residual: good.to_string(),
            difference_text,
            difference_latex,
            reading: reading.as_ref().map(|r| r.0.clone()),
            reading_latex: reading.map(|r| r.1),
            residual_unit: super::errata_reading::residual_unit(&e),
            units: erratum_units(&e),
        });
    }
    out
}
