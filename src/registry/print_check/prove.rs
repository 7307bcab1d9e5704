//! Proofs of the print itself: every parsed printed form of a display evaluated in the symbolic
//! scalar [`Sym`], on the same symbolic models as the Rust forms' proofs
//! ([`crate::registry::prove`]), so a display is proved as printed, not only as transcribed.
//!
//! A display's print is *proved* when, for every chain, every printed form minus the chain's
//! first printed form reduces to zero (modulo s² + c² = 1, and on shell modulo the equation of
//! motion and, from rest, the energy), every recorded misprint does not, and (on shell) the
//! chains with θ̈ free do not all reduce to zero. A system of particles is proved for each count
//! of [`PARTICLE_COUNTS`]. Each Rust printed form must also equal some printed form (or one of
//! its additive terms) symbolically: the transcription matches the print for all values of the
//! variables, not only at the one exact point of [`super::check_print`].

use super::premises::premised_parts;
use super::{
    evaluate_chains, form_text, print_chains_with, print_sample, sample_check, term_chains, Form,
    PrintSample,
};
use super::{misprints, Role};
use crate::print::quantity::Model;
use crate::registry::prove::{
    judge_chains, reduce, symbolic_ladder, symbolic_particle_values, Relation, PARTICLE_COUNTS,
};
use crate::registry::sample::{particle_system, LadderSample};
use crate::registry::{Chain, Equation, Eval};
use crate::scalar::Sym;

/// What the symbolic proof of one display's print found.
#[derive(Clone, Debug, Default)]
pub struct PrintProof {
    /// Printed forms (every side of every chain, as `ladder show` counts them).
    pub forms: usize,
    /// Every printed form equals its chain and every misprint differs, for all values.
    pub proved: bool,
    /// Why not: a form that differs (with its reduced difference), a misprint that holds, a
    /// chain that holds off the motion too, a Rust form equal to no printed form, or why the
    /// print could not be evaluated symbolically.
    pub problem: Option<String>,
    /// Seconds spent.
    pub seconds: f64,
}

/// One symbolic instance of a display's print: its chains and the relation they reduce by.
type Instance = (Vec<Chain<Sym>>, Relation);

/// What a display's print gave symbolically: the instances, the chains off the motion (on
/// shell), and the first Rust form that equals no printed form.
type Found = (Vec<Instance>, Option<Vec<Chain<Sym>>>, Option<String>);

fn instances(e: &Equation, chains: &[Vec<Form>]) -> Result<Found, String> {
    let sample = print_sample(e).ok_or("floor-phase displays are not in the note")?;
    let rust = sample_check(e).map(|c| c.eval);
    let terms = term_chains(chains);
    let mut out = Vec::new();
    let mut off = None;
    let mut code = None;
    match sample {
        PrintSample::Ladder(sort) => {
            let (l, s, rel) = symbolic_ladder(sort);
            let model = || Model::ladder(l.clone(), s.clone());
            let print = evaluate_chains(e, chains, model(), None)?;
            if let Some(Eval::Ladder(_, f)) = rust {
                let mut values = flat(&print);
                values.extend(flat(&evaluate_chains(e, &terms, model(), None)?));
                code = unmatched(&(f.symbolic)(&l, &s), &values, &rel);
            }
            out.push((print, rel));
            if sort.on_shell() {
                let (l, s, _) = symbolic_ladder(LadderSample::Kinematic);
                off = Some(evaluate_chains(e, chains, Model::ladder(l, s), None)?);
            }
        }
        PrintSample::Particles(sort) => {
            for n in PARTICLE_COUNTS {
                let values = symbolic_particle_values(n);
                let (sys, p) = premised_parts(e, particle_system(sort, n, &values))?;
                let model = || Model::particles(sys.clone(), p.clone());
                let print = evaluate_chains(e, chains, model(), None)?;
                if let Some(Eval::Particles(s, f)) = rust {
                    // The Rust forms on their own check's states (which may assume more than
                    // the print's premises), the print there too.
                    let (sys, p, there) = if s == sort {
                        (sys.clone(), p.clone(), print.clone())
                    } else {
                        let (sys, p) = premised_parts(e, particle_system(s, n, &values))?;
                        let m = Model::particles(sys.clone(), p.clone());
                        let there = evaluate_chains(e, chains, m, None)?;
                        (sys, p, there)
                    };
                    let model = || Model::particles(sys.clone(), p.clone());
                    let rust = (f.symbolic)(&sys, &p);
                    let mut values = flat(&there);
                    if unmatched(&rust, &values, &None).is_some() {
                        // Per-particle statements: every form and term at each particle too
                        // (only when needed: every term at every particle is the slow part).
                        let with_terms = [chains.to_vec(), terms.clone()].concat();
                        for i in 0..n {
                            if let Ok(ch) = evaluate_chains(e, &with_terms, model(), Some(i)) {
                                values.extend(flat(&ch));
                            }
                        }
                    }
                    if code.is_none() {
                        code = unmatched(&rust, &values, &None);
                    }
                }
                out.push((print, None));
            }
        }
    }
    Ok((out, off, code))
}

/// The label of the first Rust printed form (or misprint) that equals none of `values`.
fn unmatched(rust: &[Chain<Sym>], values: &[Sym], rel: &Relation) -> Option<String> {
    rust.iter()
        .flatten()
        .find(|s| {
            matches!(s.role, Role::Printed | Role::Misprint)
                && !s.value.is_zero()
                && !values
                    .iter()
                    .any(|v| reduce(v.clone() - s.value.clone(), rel).is_zero())
        })
        .map(|s| s.label.to_string())
}

/// Every value of the chains.
fn flat(chains: &[Chain<Sym>]) -> Vec<Sym> {
    chains.iter().flatten().map(|s| s.value.clone()).collect()
}

/// Prove the print of one display (given as LaTeX) symbolically.
pub fn prove_print(e: &Equation, latex: &str) -> PrintProof {
    prove_print_with(e, latex, &misprints())
}

/// [`prove_print`] with a given list of misprinted forms.
pub fn prove_print_with(e: &Equation, latex: &str, misprints: &[(u32, &str)]) -> PrintProof {
    let t = std::time::Instant::now();
    let mut out = PrintProof::default();
    let (count, chains) = match print_chains_with(e.number, latex, misprints) {
        Ok(c) => c,
        Err(err) => {
            out.problem = Some(format!("print not parsed: {err}"));
            return out;
        }
    };
    out.forms = count;
    let found = std::panic::catch_unwind(std::panic::AssertUnwindSafe(|| instances(e, &chains)))
        .unwrap_or_else(|_| Err("symbolic evaluation panicked".into()));
    out.problem = match found {
        Err(err) => Some(format!("print not evaluated symbolically: {err}")),
        Ok(found) => judge(&chains, found),
    };
    out.proved = out.problem.is_none();
    out.seconds = t.elapsed().as_secs_f64();
    out
}

fn judge(chains: &[Vec<Form>], (inst, off, code): Found) -> Option<String> {
    for (print, rel) in &inst {
        let (_, failure, misprints) = judge_chains(print, rel);
        if let Some((label, d)) = failure {
            return Some(format!(
                "print: {label} '{}' − its chain's first form = {} (not zero)",
                form_text(chains, label),
                crate::scalar::text(&d)
            ));
        }
        // A misprinted vector is wrong when any component differs.
        let mut labels: Vec<&str> = misprints.iter().map(|m| m.0).collect();
        labels.dedup();
        if let Some(label) = labels.into_iter().find(|l| {
            misprints
                .iter()
                .filter(|m| m.0 == *l)
                .all(|m| m.1.is_zero())
        }) {
            return Some(format!(
                "print: the misprint {label} '{}' is symbolically right",
                form_text(chains, label)
            ));
        }
    }
    if let Some(label) = code {
        return Some(format!(
            "print vs code: Rust form '{label}' equals no printed form symbolically"
        ));
    }
    // On shell the print must need the equation of motion: off it, some chain of two or more
    // printed forms must break. (A display whose only `=` is a misprint has no such chain.)
    if let Some(off) = off {
        let real: Vec<Chain<Sym>> = off
            .into_iter()
            .filter(|c| c.iter().filter(|s| s.role != Role::Misprint).count() > 1)
            .collect();
        if !real.is_empty() && judge_chains(&real, &None).0 {
            return Some("print: holds symbolically off the motion too".into());
        }
    }
    None
}
