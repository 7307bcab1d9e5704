//! The checks of one display, run by `ladder verify`'s own machinery for that display alone
//! ([`crate::verify::judge_with_print`], [`crate::verify::add_proof_verdict`]), with the detail
//! the verify table sums up: per check its sample, float cases and worst residual, exact points
//! and their Schwartz-Zippel bound, misprints shown to fail, the off-motion run, its proof and its
//! units; and which check's Rust sides encode which printed form.

use crate::registry::check::{run_check, CheckReport, Config, TOLERANCE_FACTOR};
use crate::registry::print_check::{print_chains, sample_check};
use crate::registry::prove::CheckProof;
use crate::registry::sample::{exact_ladder, particle_system};
use crate::registry::units::check_units;
use crate::registry::{Check, Equation, Eval, LadderSample, ParticleSample, Role};
use crate::scalar::Rational;
use crate::verify::{add_proof_verdict, judge_with_print, proof, EquationResult};
use serde::Serialize;

/// One registry check of the display, in full.
#[derive(Clone, Debug, Serialize)]
pub struct CheckDetail {
    /// Its name (what it compares).
    pub name: &'static str,
    /// Where it is evaluated, in words.
    pub sample: String,
    /// The sides it compares: (label, role).
    pub sides: Vec<(String, &'static str)>,
    /// Random float states.
    pub float_cases: usize,
    /// States out of tolerance (must be 0).
    pub float_failures: usize,
    /// Largest |side − first| in running error bounds (pass ≤ `tolerance`).
    pub max_residual: f64,
    /// The pass mark of `max_residual` ([`TOLERANCE_FACTOR`]).
    pub tolerance: f64,
    /// The side where the largest residual was.
    pub worst_side: &'static str,
    /// Random exact rational points.
    pub exact_points: usize,
    /// Points with a nonzero exact residual (must be 0).
    pub exact_failures: usize,
    /// Chance a false identity passed every exact point (Schwartz-Zippel), as log10.
    pub sz_bound_log10: f64,
    /// Each misprinted side and whether it failed at every exact point (it must).
    pub misprints: Vec<(&'static str, bool)>,
    /// On-shell checks: whether every exact point fails off the motion (it must).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fails_off_motion: Option<bool>,
    /// On-shell checks: the `=` (from 1) at which the display breaks off the motion.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub breaks_at: Option<Vec<u32>>,
    /// Symbolic proof: `proved`, or why not.
    pub proof: String,
    /// Dimensional analysis of the check's sides.
    pub units: String,
    /// Every part passed.
    pub passed: bool,
}

/// The registry checks of `e`, its verify row (the same as `ladder verify` prints) and their detail.
pub fn run(e: &Equation, cfg: &Config) -> (EquationResult, Vec<CheckDetail>) {
    let reports: Vec<CheckReport> = e.checks.iter().map(|c| run_check(c, cfg)).collect();
    let mut row = judge_with_print(e, &reports, cfg);
    let (verdict, proofs) = proof::prove_equation(e);
    add_proof_verdict(&mut row, verdict);
    let details = e
        .checks
        .iter()
        .zip(&reports)
        .zip(&proofs)
        .map(|((c, r), p)| detail(c, r, p))
        .collect();
    (row, details)
}

fn detail(c: &Check, r: &CheckReport, p: &CheckProof) -> CheckDetail {
    let proof = if let Some(why) = &p.sampled_only {
        format!("sampled only: {why}")
    } else if let Some((label, diff)) = &p.failure {
        format!(
            "not proved: {label} − first = {}",
            crate::scalar::text(diff)
        )
    } else if p.holds() {
        "proved".into()
    } else {
        "not proved".into()
    };
    let u = check_units(c);
    let (units, detail) = u.verdict();
    CheckDetail {
        name: c.name,
        sample: sample_words(c),
        sides: sides(c),
        float_cases: r.float_cases,
        float_failures: r.float_failures,
        max_residual: r.max_scaled_residual,
        tolerance: TOLERANCE_FACTOR,
        worst_side: r.worst_side,
        exact_points: r.exact_points,
        exact_failures: r.exact_failures,
        sz_bound_log10: r.sz_bound_log10,
        misprints: r.misprints.clone(),
        fails_off_motion: r.off_shell_fails,
        breaks_at: r.off_motion_breaks.clone(),
        proof,
        units: match detail {
            Some(d) => format!("{}: {d}", units.name()),
            None => units.name().into(),
        },
        passed: r.passed() && p.holds(),
    }
}

/// A check's sample in words.
pub fn sample_words(c: &Check) -> String {
    match c.eval {
        Eval::Ladder(LadderSample::Kinematic, _) => "any θ, θ̇, θ̈ (kinematic)".into(),
        Eval::Ladder(LadderSample::OnShell, _) => "θ̈ from (5), any θ̇ (on the motion)".into(),
        Eval::Ladder(LadderSample::OnShellFromRest, _) => {
            "θ̈ from (5), θ̇ from (10): released at rest upright".into()
        }
        Eval::Particles(s, _) => format!("any particles, {}", particle_words(s)),
        Eval::Floor(..) => "the ladder off the wall".into(),
    }
}

fn particle_words(s: ParticleSample) -> &'static str {
    use ParticleSample::*;
    match s {
        General => "any moving point P",
        PAtCm => "P on the centre of mass",
        PFixed => "P at rest",
        PAtOrigin => "P passing the origin",
        CmAtOriginPAtCm => "centre of mass at the origin, P on it",
        ForceFree => "no total force",
        TorqueFree => "no total torque about the origin",
        RollingAboutP => "a rigid body rolling about P",
        PlanarRigid => "a planar rigid body, P at rest",
    }
}

fn role(r: Role) -> &'static str {
    match r {
        Role::Printed => "printed",
        Role::Reference => "reference",
        Role::Corrected => "corrected",
        Role::Misprint => "misprint",
    }
}

/// The fixed exact point the encodings are read at: off the motion (θ̈ free) for a ladder, so
/// that forms left and right of a law `=` take different values.
const DRAW: [(i64, i64); 7] = [(1, 3), (3, 1), (5, 1), (7, 1), (2, 1), (-1, 1), (4, 1)];

fn particle_values() -> Vec<Rational> {
    let n = 3 * crate::registry::sample::PER_PARTICLE + crate::registry::sample::EXTRA;
    (0..n)
        .map(|i| Rational::from_integer(((i as i64 * 7919) % 23 + 1).into()))
        .collect()
}

/// Exact chains of a check at the fixed point (the labels and roles; values for matching).
fn exact_chains(c: &Check) -> Vec<crate::registry::Chain<Rational>> {
    match c.eval {
        Eval::Ladder(_, f) => {
            let (l, s) = exact_ladder(
                LadderSample::Kinematic,
                DRAW.map(|(n, d)| Rational::new(n.into(), d.into())),
            );
            (f.exact)(&l, &s)
        }
        Eval::Particles(sort, f) => {
            let (sys, p) = particle_system(sort, 3, &particle_values());
            (f.exact)(&sys, &p)
        }
        Eval::Floor(..) => Vec::new(),
    }
}

fn sides(c: &Check) -> Vec<(String, &'static str)> {
    let mut out: Vec<(String, &'static str)> = Vec::new();
    for s in exact_chains(c).into_iter().flatten() {
        let item = (s.label.to_string(), role(s.role));
        if !out.contains(&item) {
            out.push(item);
        }
    }
    out
}

/// For each printed form (in print order), the registry sides that equal it at one exact point
/// of the display's own sample: `check name: side label`.
pub fn encodings(e: &Equation) -> Vec<Vec<String>> {
    use crate::print::eval::{evaluate, Ctx};
    use crate::print::quantity::Model;
    let Ok((_, chains)) = print_chains(e.number, e.latex()) else {
        return Vec::new();
    };
    let forms: Vec<_> = chains.iter().flatten().collect();
    let mut out = vec![Vec::new(); forms.len()];
    let Some(sample) = sample_check(e) else {
        return out;
    };
    let model = match sample.eval {
        Eval::Ladder(..) => {
            let (l, s) = exact_ladder(
                LadderSample::Kinematic,
                DRAW.map(|(n, d)| Rational::new(n.into(), d.into())),
            );
            Model::ladder(l, s)
        }
        Eval::Particles(sort, _) => {
            let (sys, p) = particle_system(sort, 3, &particle_values());
            Model::particles(sys, p)
        }
        Eval::Floor(..) => return out,
    };
    let model = std::rc::Rc::new(model);
    let values: Vec<Option<Vec<Rational>>> = forms
        .iter()
        .map(|f| {
            let ctx = Ctx {
                model: model.clone(),
                section: e.section,
                number: e.number,
                milne: f.milne,
                index: None,
                table: crate::registry::symbol_table(),
            };
            evaluate(&f.expr, &ctx).ok().map(|v| v.components())
        })
        .collect();
    let squash = |s: &str| s.chars().filter(|c| !c.is_whitespace()).collect::<String>();
    for c in e.checks.iter().filter(|c| same_sample(c, sample)) {
        for chain in exact_chains(c) {
            for s in chain.iter().filter(|s| s.role != Role::Reference) {
                if num_traits::Zero::is_zero(&s.value) {
                    continue;
                }
                let hits: Vec<usize> = (0..forms.len())
                    .filter(|&k| values[k].as_ref().is_some_and(|v| v.contains(&s.value)))
                    .collect();
                // Equal values cannot tell forms apart; the label can, where it is the form.
                let by_label: Vec<usize> = hits
                    .iter()
                    .copied()
                    .filter(|&k| {
                        squash(&crate::print::unicode::unicode(&forms[k].text)) == squash(s.label)
                    })
                    .collect();
                let name = format!("{}: {}", c.name, s.label);
                for k in if by_label.is_empty() { hits } else { by_label } {
                    if !out[k].contains(&name) {
                        out[k].push(name.clone());
                    }
                }
            }
        }
    }
    out
}

fn same_sample(a: &Check, b: &Check) -> bool {
    match (a.eval, b.eval) {
        (Eval::Ladder(x, _), Eval::Ladder(y, _)) => x == y,
        (Eval::Particles(x, _), Eval::Particles(y, _)) => x == y,
        _ => false,
    }
}
