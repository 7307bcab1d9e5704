//! The exact pass of a display's print: every chain with zero residual at exact points, every
//! misprint differing, and at the first point the values the Rust forms are matched against.

use super::sample_check;
use crate::print::quantity::Model;
use crate::registry::check::{exact_particle_draw, exact_residual, Config};
use crate::registry::print_check::independent::{erratum_against_references, rust_sides};
use crate::registry::print_check::premises::{premised, premised_parts};
use crate::registry::print_check::{evaluate_chains, form_text, term_chains, Form, PrintReport};
use crate::registry::sample::{
    exact_ladder, particle_system, LadderSample, ParticleSample, PrintSample,
};
use crate::registry::{Chain, Equation, Eval, Role};
use crate::scalar::{Rational, Scalar};
use rand_chacha::ChaCha8Rng;

/// What the exact points found besides the count of failures.
#[derive(Default)]
struct Findings {
    /// The first form that differs from its chain: (label, residual).
    fail: Option<(String, String)>,
    /// The misprints that did not fail at some point.
    misprint_held: Vec<String>,
    /// The values of the printed forms and their terms at the first point.
    code_values: Vec<Rational>,
    /// The Rust forms' values at the first point, by label.
    code_sides: Vec<(String, Rational)>,
    /// For an erratum: its correct printed forms that differ from the check's independent values.
    held: Vec<String>,
}

/// The exact points: every chain with zero residual, every misprint differing. Returns the
/// values of the printed forms and their terms, and the Rust forms', at the first point (for
/// matching the Rust function against the print).
pub(super) fn exact_pass(
    e: &Equation,
    chains: &[Vec<Form>],
    sample: PrintSample,
    cfg: &Config,
    rng: &mut ChaCha8Rng,
    rep: &mut PrintReport,
) -> (Vec<Rational>, Vec<(String, Rational)>) {
    let rust = sample_check(e).map(|c| c.eval);
    // Alone, the print gets every exact point of a check; beside a Rust check, one.
    let points = if e.checks.is_empty() {
        cfg.exact_points
    } else {
        cfg.exact_points.min(super::PRINT_EXACT_POINTS)
    };
    rep.degree = crate::registry::print_check::motion::degree(e, chains, sample);
    let mut found = Findings::default();
    for k in 0..points {
        let at = Point {
            e,
            chains,
            rust,
            first: k == 0,
        };
        match sample {
            PrintSample::Ladder(sort) => at.ladder(sort, rng, &mut found, &mut rep.exact_failures),
            PrintSample::Particles(sort) => {
                at.particles(sort, rng, &mut found, &mut rep.exact_failures);
            }
        }
        rep.exact_points += 1;
    }
    if let Some((label, residual)) = found.fail {
        rep.problems.push(format!(
            "print: {label} '{}' differs from its chain exactly (residual {residual})",
            form_text(chains, &label)
        ));
    }
    rep.problems.extend(found.held);
    found.misprint_held.dedup();
    for m in found.misprint_held {
        rep.problems
            .push(format!("print: the misprint {m} did not fail"));
    }
    (found.code_values, found.code_sides)
}

/// One exact point of the pass: the display, its chains, the Rust check it is matched against,
/// and whether it is the first point (where the values for that match are taken).
struct Point<'a> {
    e: &'a Equation,
    chains: &'a [Vec<Form>],
    rust: Option<Eval>,
    first: bool,
}

impl Point<'_> {
    /// A ladder state of the print's sort; at the first point also the terms' values and, beside
    /// a ladder check, the Rust forms at the same state.
    fn ladder(
        &self,
        sort: LadderSample,
        rng: &mut ChaCha8Rng,
        found: &mut Findings,
        failures: &mut usize,
    ) {
        let (e, chains) = (self.e, self.chains);
        let draw = crate::registry::check::exact_ladder_draw(rng);
        let (l, s) = exact_ladder(sort, draw);
        let here = Model::ladder(l.clone(), s.clone());
        let ch = evaluate_chains(e, chains, here, None);
        note_exact(ch, chains, found, self.first, failures);
        if !self.first {
            return;
        }
        let m = Model::ladder(l.clone(), s.clone());
        if let Ok(ch) = evaluate_chains(e, &term_chains(chains), m, None) {
            found
                .code_values
                .extend(ch.into_iter().flatten().map(|s| s.value));
        }
        if let Some(Eval::Ladder(_, f)) = self.rust {
            let here = Model::ladder(l.clone(), s.clone());
            let print = evaluate_chains(e, chains, here, None);
            independent(e, chains, print, (f.exact)(&l, &s), found);
        }
    }

    /// A particle system of the print's sort, its premises imposed; at the first point also the
    /// forms and terms at every particle and, beside a particle check, the Rust forms at a state
    /// of that check's own sort (which may assume more than the print's premises).
    fn particles(
        &self,
        sort: ParticleSample,
        rng: &mut ChaCha8Rng,
        found: &mut Findings,
        failures: &mut usize,
    ) {
        let (e, chains) = (self.e, self.chains);
        let (n, values) = exact_particle_draw(rng);
        let (sys, p) = particle_system(sort, n, &values);
        let ch =
            premised(e, sys.clone(), p.clone()).and_then(|m| evaluate_chains(e, chains, m, None));
        note_exact(ch, chains, found, self.first, failures);
        if !self.first {
            return;
        }
        let (n, sys, p) = match self.rust {
            Some(Eval::Particles(s, _)) if s != sort => {
                let (n, values) = exact_particle_draw(rng);
                let (sys, p) = particle_system(s, n, &values);
                (n, sys, p)
            }
            _ => (n, sys, p),
        };
        let Ok((sys, p)) = premised_parts(e, (sys, p)) else {
            return;
        };
        // Per-particle statements: the forms at every particle.
        let with_terms = [chains.to_vec(), term_chains(chains)].concat();
        for i in 0..n {
            let m = Model::particles(sys.clone(), p.clone());
            if let Ok(ch) = evaluate_chains(e, &with_terms, m, Some(i)) {
                found
                    .code_values
                    .extend(ch.into_iter().flatten().map(|s| s.value));
            }
        }
        if let Some(Eval::Particles(_, f)) = self.rust {
            let here = Model::particles(sys.clone(), p.clone());
            let print = evaluate_chains(e, chains, here, None);
            independent(e, chains, print, (f.exact)(&sys, &p), found);
        }
    }
}

/// The Rust forms at the first point (to match against the print) and, for an erratum, its
/// correct printed forms held to the check's independent values.
fn independent(
    e: &Equation,
    chains: &[Vec<Form>],
    print: Result<Vec<Chain<Rational>>, String>,
    rust: Vec<Chain<Rational>>,
    found: &mut Findings,
) {
    if let Ok(print) = print {
        found.held = erratum_against_references(e, chains, &print, &rust);
    }
    found.code_sides = rust_sides(&rust);
}

/// One exact point's chains: a failure counted (the first one kept with its residual), the
/// misprints that held noted, and at the first point every side's value kept.
fn note_exact(
    ch: Result<Vec<Chain<Rational>>, String>,
    chains: &[Vec<Form>],
    found: &mut Findings,
    first: bool,
    failures: &mut usize,
) {
    let ch = match ch {
        Ok(c) => c,
        Err(err) => {
            *failures += 1;
            found
                .fail
                .get_or_insert((format!("form 1 ({err})"), "undefined".into()));
            return;
        }
    };
    if first {
        found
            .code_values
            .extend(ch.iter().flatten().map(|s| s.value.clone()));
    }
    let (ok, mis) = exact_residual(&ch);
    *failures += usize::from(!ok);
    if !ok && found.fail.is_none() {
        for c in &ch {
            let Some(base) = c.iter().position(|s| s.role != Role::Misprint) else {
                continue;
            };
            if let Some(s) = c
                .iter()
                .find(|s| s.role != Role::Misprint && s.value != c[base].value)
            {
                let r = s.value.clone() - c[base].value.clone();
                found.fail = Some((s.label.to_string(), format!("{:.6e}", r.to_f64())));
                break;
            }
        }
    }
    // A misprinted vector fails when any component differs.
    let mut labels: Vec<&str> = mis.iter().map(|m| m.0).collect();
    labels.dedup();
    for label in labels {
        if !mis.iter().any(|m| m.0 == label && m.1) {
            found
                .misprint_held
                .push(format!("{label} '{}'", form_text(chains, label)));
        }
    }
}
