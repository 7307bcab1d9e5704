//! `ladder verify`: run every check of every equation and report one row per equation.

pub mod claims;
pub mod errata;
pub mod errata_reading;
pub mod fill;
pub mod legend;
pub mod proof;
pub mod summary;
pub mod table;
pub mod units;

mod judge;
mod print_judge;
pub use judge::judge;
pub use print_judge::{judge_print, judge_with_print, LAW_FOUND, PRINT_ALONE};
pub use table::table;

use crate::registry::check::{run_check, CheckReport, Config};
use crate::registry::units::{equation_units, Units};
use crate::registry::{equations, Equation, Kind};
use serde::Serialize;

/// The verdict on one equation.
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum Status {
    /// Every check passed.
    Verified,
    /// The printed form fails as recorded; the corrected form passes every check.
    Erratum,
    /// A definition, consistent with the independent model.
    Definition,
    /// Some check failed.
    Failed,
}

/// What happens to an equation off the motion (θ̈ left free instead of taken from (5)).
#[derive(Clone, Copy, Debug, PartialEq, Eq, Serialize)]
#[serde(rename_all = "kebab-case")]
pub enum OffMotion {
    /// On-shell: every check was re-run with θ̈ free and failed there, as it must.
    Fails,
    /// On-shell, but some check still held with θ̈ free: it cannot tell the motion (a failure).
    Holds,
    /// Kinematic, newton or a ladder definition: checked at states with θ̈ free, so it holds for
    /// any θ̈, on the motion or off it.
    AnyMotion,
    /// About any system of particles (general, notation, a particle definition): the ladder's
    /// motion does not enter.
    NotApplicable,
}

/// One row of the report.
#[derive(Clone, Debug, Serialize)]
pub struct EquationResult {
    /// Equation number (an extension beyond the note is 1000 + k for (Pk)).
    pub number: u32,
    /// How it is cited: "(12)", "(P3)".
    pub label: String,
    /// Section of the note.
    pub section: &'static str,
    /// Title.
    pub title: &'static str,
    /// Kind.
    pub kind: Kind,
    /// Verdict.
    pub status: Status,
    /// Names of the checks run.
    pub checks: Vec<&'static str>,
    /// Float states evaluated, over all checks.
    pub cases: usize,
    /// Exact points evaluated, over all checks.
    pub exact_points: usize,
    /// True when every check also held exactly (zero residual) at random rational points.
    pub exact: bool,
    /// Exact points, over all checks, where some side differed (a failure unless 0).
    pub exact_failures: usize,
    /// Largest float residual in units of its error bound (pass: ≤ 4).
    pub max_residual: f64,
    /// What `max_residual` is measured in (see [`RESIDUAL_UNIT`]).
    pub max_residual_unit: &'static str,
    /// Largest Schwartz-Zippel bound over the checks: the chance a false identity passed. Left
    /// out of the JSON when it underflows to 0 (below about 1e-308, as with 100 exact points):
    /// a bound is never 0, and `sz_bound_log10` carries it.
    #[serde(skip_serializing_if = "underflowed")]
    pub sz_bound: f64,
    /// log10 of `sz_bound`, which does not underflow when the bound is below 1e-308.
    pub sz_bound_log10: f64,
    /// log10 of the bound from the exact rational points alone, which holds whatever the prime of
    /// the modular points ([`crate::registry::check`]).
    pub sz_bound_rational_log10: f64,
    /// For on-shell equations: shown to fail off the equation of motion.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fails_off_shell: Option<bool>,
    /// Off the motion: fails (on-shell), holds for any motion, or not a ladder motion.
    pub off_motion: OffMotion,
    /// The `=` of the display (counted from 1) that is the law of motion; every other `=` is
    /// algebra or kinematics. Confirmed by computation: off the motion the chain breaks there
    /// and only there ([`crate::registry::law`]).
    #[serde(skip_serializing_if = "Option::is_none")]
    pub law_step: Option<u32>,
    /// The law used at that `=`, in words.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub law: Option<&'static str>,
    /// What went wrong, if anything.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub problems: Vec<String>,
    /// Every check holds symbolically for all values of the variables (see [`proof`]).
    pub proved: bool,
    /// `proved`, `erratum`, `definition`, or why not (`sampled only: …`, `not proved`).
    pub proof: String,
    /// Seconds spent on the symbolic proofs of this equation.
    pub proof_seconds: f64,
    /// Every printed form proved symbolically against its chain (misprints shown to differ);
    /// absent for an extension beyond the note (no print). Part of `proved`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub print_proved: Option<bool>,
    /// Dimensional analysis of every printed form ([`crate::registry::print_check::units`]);
    /// for an extension beyond the note (no print), of its Rust forms.
    pub units: Units,
    /// Why `inconsistent` (the offending sum and the printed form's index, as `ladder show N`
    /// numbers the forms) or `not applicable`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub units_detail: Option<String>,
    /// Dimensional analysis of the Rust forms ([`crate::registry::units`]); it must agree with
    /// `units` (a disagreement is a problem).
    pub units_code: Units,
    /// Why the Rust forms are `inconsistent` or `not applicable`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub units_code_detail: Option<String>,
    /// Forms in the display's print (issue 9; 0 for an extension beyond the note).
    pub print_forms: usize,
    /// Forms of the print parsed and evaluated.
    pub print_parsed: usize,
    /// Forms of the print held against another printed form.
    pub print_checked: usize,
    /// Every Rust form equals a parsed printed form (misprints included).
    pub print_matches_code: bool,
    /// Why forms of the print were not parsed or evaluated.
    #[serde(skip_serializing_if = "Vec::is_empty")]
    pub print_unparsed: Vec<String>,
    /// Where the display's section starts in the book, `equations/05-point-d.md:42`.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub doc: Option<String>,
}

/// A Schwartz-Zippel bound that underflowed to 0 (it is at least (1/N)^points > 0).
fn underflowed(bound: &f64) -> bool {
    *bound == 0.0
}

/// The unit of `max_residual`: |lhs − rhs| divided by the running error bound of the two sides,
/// u·(e_lhs + e_rhs) with u = 2⁻⁵³; a float check passes when this is at most 4.
pub const RESIDUAL_UNIT: &str =
    "error bounds: |lhs - rhs| / (u (e_lhs + e_rhs)), u = 2^-53; pass <= 4";

/// Add the symbolic proof verdict to a judged equation (a nonzero difference fails it).
pub fn add_proof(r: &mut EquationResult, e: &Equation) {
    add_proof_verdict(r, proof::prove_equation(e).0);
}

/// Add a computed proof verdict to a judged equation (see [`add_proof`]).
pub fn add_proof_verdict(r: &mut EquationResult, v: proof::ProofVerdict) {
    if let Some(p) = v.problem {
        r.problems.push(p);
        r.status = Status::Failed;
    }
    r.proved = v.proved;
    r.proof = v.proof;
    r.proof_seconds = v.seconds;
    r.print_proved = v.print_proved;
}

/// Run every check of every equation (on every core, `on_all_cores`) and judge each equation.
pub fn verify_all(cfg: &Config) -> Vec<EquationResult> {
    verify_list(equations(), cfg)
}

/// Run every check of the given equations only (`ladder verify --only`).
pub fn verify_equations(eqs: Vec<Equation>, cfg: &Config) -> Vec<EquationResult> {
    verify_list(eqs, cfg)
}

/// Run the checks of the displays beyond the note, (P1) on (`equations/phase2.md`, problems).
pub fn verify_extensions(cfg: &Config) -> Vec<EquationResult> {
    verify_list(crate::registry::extensions(), cfg)
}

fn verify_list(eqs: Vec<Equation>, cfg: &Config) -> Vec<EquationResult> {
    let mut results = on_all_cores(&eqs, |e| {
        let mut r = judge_with_print(
            e,
            &e.checks
                .iter()
                .map(|c| run_check(c, cfg))
                .collect::<Vec<_>>(),
            cfg,
        );
        add_proof(&mut r, e);
        r
    });
    results.sort_by_key(|r| r.number);
    for (r, e) in results.iter_mut().zip(&eqs) {
        debug_assert_eq!(r.number, e.number);
        r.doc = Some(e.place());
    }
    results
}

/// `f` of every item, in order, on rayon's pool (a thread per core): the cost of a display
/// varies thirtyfold, and work stealing keeps both cores busy where a fixed split left one idle.
pub fn on_all_cores<T: Sync, R: Send>(items: &[T], f: impl Fn(&T) -> R + Sync + Send) -> Vec<R> {
    use rayon::prelude::*;
    items.par_iter().map(f).collect()
}

/// Print coverage: (displays fully parsed, displays, forms parsed, forms, displays whose Rust
/// forms all match the print).
pub fn print_coverage(results: &[EquationResult]) -> (usize, usize, usize, usize, usize) {
    let note: Vec<_> = results.iter().filter(|r| r.print_forms > 0).collect();
    (
        note.iter()
            .filter(|r| r.print_parsed == r.print_forms)
            .count(),
        note.len(),
        note.iter().map(|r| r.print_parsed).sum(),
        note.iter().map(|r| r.print_forms).sum(),
        note.iter().filter(|r| r.print_matches_code).count(),
    )
}

/// Counts of each verdict: (verified, erratum, definition, failed).
pub fn counts(results: &[EquationResult]) -> (usize, usize, usize, usize) {
    let n = |s| results.iter().filter(|r| r.status == s).count();
    (
        n(Status::Verified),
        n(Status::Erratum),
        n(Status::Definition),
        n(Status::Failed),
    )
}

/// The verdict on one derivation of the equation of motion ([`crate::derivation`]).
#[derive(Clone, Debug, Serialize)]
pub struct MethodResult {
    /// The method's name.
    pub name: &'static str,
    /// Every check passed.
    pub passed: bool,
    /// Float states evaluated.
    pub cases: usize,
    /// Largest float residual in units of its error bound.
    pub max_residual: f64,
    /// What went wrong, if anything.
    pub problems: Vec<String>,
}

/// Check every derivation of the note ([`crate::derivation::derivations`]).
pub fn check_methods(cfg: &Config) -> Vec<MethodResult> {
    on_all_cores(&crate::derivation::derivations(), |(name, checks)| {
        let reports: Vec<CheckReport> = checks.iter().map(|c| run_check(c, cfg)).collect();
        let problems = reports
            .iter()
            .filter(|r| !r.passed())
            .map(|r| format!("{} failed", r.name))
            .collect();
        MethodResult {
            name,
            passed: reports.iter().all(CheckReport::passed),
            cases: reports.iter().map(|r| r.float_cases).sum(),
            max_residual: reports
                .iter()
                .map(|r| r.max_scaled_residual)
                .fold(0.0, f64::max),
            problems,
        }
    })
}
