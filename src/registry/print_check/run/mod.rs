//! Running a display's printed chains on the registry's samples: a probe, the float pass, the
//! exact pass ([`exact`]) and, on the motion, the off-motion pass.

mod exact;

use super::premises::premised;
use super::{evaluate_chains, form_text, misprints, print_chains_with, Form, PrintReport};
use crate::print::quantity::Model;
use crate::registry::check::{float_residual, Config, TOLERANCE_FACTOR};
use crate::registry::sample::PrintSample;
use crate::registry::sample::{LadderSample, ParticleSample, RawLadder, RawParticles};
use crate::registry::{Chain, Equation, Eval};
use crate::scalar::Bound;
use exact::exact_pass;
use num_traits::Zero;
use rand::SeedableRng;
use rand_chacha::ChaCha8Rng;

/// Check the print of one display on its registry samples.
pub fn check_print(e: &Equation, latex: &str, cfg: &Config) -> PrintReport {
    check_print_with(e, latex, cfg, &misprints())
}

/// [`check_print`] with a given list of misprinted forms.
pub fn check_print_with(
    e: &Equation,
    latex: &str,
    cfg: &Config,
    misprint_list: &[(u32, &str)],
) -> PrintReport {
    let mut rep = PrintReport::default();
    let (count, chains) = match print_chains_with(e.number, latex, misprint_list) {
        Ok(c) => c,
        Err(err) => {
            rep.forms = latex.matches('=').count() + 1;
            rep.unparsed.push(format!("parse: {err}"));
            return rep;
        }
    };
    rep.forms = count;
    rep.problems
        .extend(super::symbol_check::own_points(e, &chains));
    if let Ok(d) = crate::print::parser::parse_display(latex) {
        rep.problems.extend(super::premises::disagreements(e, &d));
    }
    let Some(sample) = print_sample(e) else {
        rep.unparsed
            .push("floor-phase displays are not in the note".into());
        return rep;
    };
    let mut rng = ChaCha8Rng::seed_from_u64(cfg.seed ^ u64::from(e.number));
    // Drop forms that do not evaluate (reported), keep the rest.
    if let Err(err) = probe(e, &chains, sample, &mut rng) {
        rep.unparsed.push(err);
        return rep;
    }
    rep.parsed = count;
    rep.checked = chains
        .iter()
        .filter(|c| c.len() > 1)
        .map(Vec::len)
        .sum::<usize>()
        .min(count);
    if rep.checked == 0 && e.checks.is_empty() {
        rep.problems.push(
            "print: nothing is checked: the display joins no two forms and names no *Rust:* check"
                .into(),
        );
    }
    float_pass(e, &chains, sample, cfg, &mut rng, &mut rep);
    let (code_values, code_sides) = exact_pass(e, &chains, sample, cfg, &mut rng, &mut rep);
    if matches!(sample, PrintSample::Ladder(s) if s.on_shell()) {
        super::motion::off_motion_pass(e, &chains, &mut rng, &mut rep);
    }
    for (label, v) in code_sides {
        // A zero component (z of a planar vector) says nothing about which form it is.
        if !v.is_zero() && !code_values.contains(&v) {
            let msg = format!("Rust form '{label}' equals no printed form");
            if !rep.code_mismatches.contains(&msg) {
                rep.code_mismatches.push(msg);
            }
        }
    }
    rep.matches_code = rep.code_mismatches.is_empty() && rep.parsed == rep.forms;
    rep
}

/// Evaluate every form once at a float state, to report one that does not evaluate.
fn probe(
    e: &Equation,
    chains: &[Vec<Form>],
    sample: PrintSample,
    rng: &mut ChaCha8Rng,
) -> Result<(), String> {
    match sample {
        PrintSample::Ladder(sort) => {
            let ((l, s), _) = RawLadder::draw(rng).build(sort);
            evaluate_chains(e, chains, Model::ladder(l, s), None).map(|_| ())
        }
        PrintSample::Particles(sort) => {
            let raw = RawParticles::draw(rng);
            let ((sys, p), _) = crate::registry::sample::float_particles(sort, &raw);
            evaluate_chains(e, chains, premised(e, sys, p)?, None).map(|_| ())
        }
    }
}

/// The float states: every chain within its running error bound.
fn float_pass(
    e: &Equation,
    chains: &[Vec<Form>],
    sample: PrintSample,
    cfg: &Config,
    rng: &mut ChaCha8Rng,
    rep: &mut PrintReport,
) {
    let float_cases = cfg.float_cases.min(PRINT_FLOAT_CASES);
    let mut worst = (0.0f64, "");
    let mut failures = 0;
    for _ in 0..float_cases {
        let (v, b) = match sample {
            PrintSample::Ladder(sort) => {
                let ((l, s), (lb, sb)) = RawLadder::draw(rng).build(sort);
                (
                    evaluate_chains(e, chains, Model::ladder(l, s), None),
                    evaluate_chains(e, chains, Model::ladder(lb, sb), None),
                )
            }
            PrintSample::Particles(sort) => {
                let raw = RawParticles::draw(rng);
                let ((sys, p), (sysb, pb)) = crate::registry::sample::float_particles(sort, &raw);
                (
                    premised(e, sys, p).and_then(|m| evaluate_chains(e, chains, m, None)),
                    premised(e, sysb, pb).and_then(|m| evaluate_chains(e, chains, m, None)),
                )
            }
        };
        note_float(v, b, &mut worst, &mut failures);
        rep.float_cases += 1;
    }
    if failures > 0 {
        rep.problems.push(format!(
            "print: {failures} of {float_cases} float states out of tolerance; worst residual {:.3e} × its error bound at {} '{}'",
            worst.0,
            worst.1,
            form_text(chains, worst.1)
        ));
    }
}

/// The registry check whose sample the print is evaluated on: for an on-shell display the one
/// from rest if any (the energy (10) holds there only), else the first on-shell one.
pub fn sample_check(e: &Equation) -> Option<&crate::registry::Check> {
    let from_rest = |c: &&crate::registry::Check| {
        matches!(c.eval, Eval::Ladder(LadderSample::OnShellFromRest, _))
    };
    let on_shell =
        |c: &&crate::registry::Check| matches!(c.eval, Eval::Ladder(s, _) if s.on_shell());
    if e.kind == crate::registry::Kind::OnShell {
        if let Some(c) = e
            .checks
            .iter()
            .find(from_rest)
            .or_else(|| e.checks.iter().find(on_shell))
        {
            return Some(c);
        }
    }
    e.checks.first()
}

/// The states of a display's print: its `*States:*` line if it has one, else for particles with
/// a `*Premises:*` list general states (the premises imposed on them), else those of the
/// registry check it is compared with ([`sample_check`]), else its kind's (on-shell: the motion;
/// general, notation: any particles; else any motion of the ladder). `None` for the floor phase,
/// which the print cannot evaluate.
pub fn print_sample(e: &Equation) -> Option<PrintSample> {
    use crate::registry::Kind;
    if let Some(s) = e.states {
        return Some(s);
    }
    // With its premises written down, a display of particles is checked on general states that
    // satisfy them and nothing more ([`super::premises`]).
    let general = !e.premises.is_empty();
    match sample_check(e).map(|c| c.eval) {
        Some(Eval::Ladder(s, _)) => Some(PrintSample::Ladder(s)),
        Some(Eval::Particles(_, _)) if general => {
            Some(PrintSample::Particles(ParticleSample::General))
        }
        Some(Eval::Particles(s, _)) => Some(PrintSample::Particles(s)),
        Some(Eval::Floor(..)) => None,
        None => Some(match e.kind {
            Kind::OnShell => PrintSample::Ladder(LadderSample::OnShell),
            Kind::General | Kind::Notation => PrintSample::Particles(ParticleSample::General),
            Kind::Definition | Kind::Kinematic | Kind::Newton => {
                PrintSample::Ladder(LadderSample::Kinematic)
            }
        }),
    }
}

/// Exact points per display for the print: one point already bounds the chance that a false
/// chain passes by degree/2^62 (Schwartz-Zippel); the registry's checks run more.
pub const PRINT_EXACT_POINTS: usize = 1;

/// Float cases per display for the print (the registry's checks run the full count).
pub const PRINT_FLOAT_CASES: usize = 200;

fn note_float(
    v: Result<Vec<Chain<f64>>, String>,
    b: Result<Vec<Chain<Bound>>, String>,
    worst: &mut (f64, &'static str),
    failures: &mut usize,
) {
    let (Ok(v), Ok(b)) = (v, b) else {
        *failures += 1;
        *worst = (f64::INFINITY, "form 1");
        return;
    };
    let (scaled, label) = float_residual(&v, &b);
    if scaled.is_nan() || scaled > TOLERANCE_FACTOR {
        *failures += 1;
    }
    if scaled.is_nan() || scaled > worst.0 {
        *worst = (scaled, label);
    }
}
