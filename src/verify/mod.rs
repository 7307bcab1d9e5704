//! `ladder verify`: run every check of every equation and report one row per equation.

pub mod claims;
pub mod command;
pub mod errata;
pub mod legend;

use crate::registry::check::{run_check, CheckReport, Config};
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
    /// Largest float residual in units of its error bound (pass: ≤ 4).
    pub max_residual: f64,
    /// Largest Schwartz-Zippel bound over the checks: the chance a false identity passed.
    pub sz_bound: f64,
    /// For on-shell equations: shown to fail off the equation of motion.
    #[serde(skip_serializing_if = "Option::is_none")]
    pub fails_off_shell: Option<bool>,
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
}

/// Judge one equation from its check reports.
pub fn judge(e: &Equation, reports: &[CheckReport]) -> EquationResult {
    let mut problems = Vec::new();
    for r in reports {
        if r.float_failures > 0 {
            problems.push(format!(
                "{}: {} of {} float states out of tolerance (worst {:.3e} at {})",
                r.name, r.float_failures, r.float_cases, r.max_scaled_residual, r.worst_side
            ));
        }
        if r.exact_failures > 0 {
            problems.push(format!(
                "{}: nonzero exact residual at {} of {} points",
                r.name, r.exact_failures, r.exact_points
            ));
        }
        for (label, failed) in &r.misprints {
            if !failed {
                problems.push(format!("{}: the misprint '{label}' did not fail", r.name));
            }
        }
        if r.off_shell_fails == Some(false) {
            problems.push(format!(
                "{}: holds off shell too (the check cannot tell)",
                r.name
            ));
        }
    }
    if let Some(law) = e.law {
        // Every on-shell check of the display must break off the motion at the marked `=` only.
        let found: Vec<_> = reports
            .iter()
            .filter(|r| r.off_shell_fails.is_some())
            .map(|r| (r.name, r.off_motion_breaks.clone()))
            .collect();
        if found.is_empty() {
            problems.push(format!(
                "the law is marked at `=` no. {} but no check evaluates the display off the motion",
                law.step
            ));
        }
        for (name, b) in found {
            if b.as_deref() != Some(&[law.step][..]) {
                problems.push(format!(
                    "{name}: the law is marked at `=` no. {}, but off the motion the display breaks at {:?}",
                    law.step,
                    b.unwrap_or_default()
                ));
            }
        }
    }
    let on_shell = reports
        .iter()
        .filter_map(|r| r.off_shell_fails)
        .collect::<Vec<_>>();
    let status = if !problems.is_empty() {
        Status::Failed
    } else if e.erratum.is_some() {
        Status::Erratum
    } else if e.kind == Kind::Definition {
        Status::Definition
    } else {
        Status::Verified
    };
    EquationResult {
        number: e.number,
        label: e.label(),
        section: e.section,
        title: e.title,
        kind: e.kind,
        status,
        checks: reports.iter().map(|r| r.name).collect(),
        cases: reports.iter().map(|r| r.float_cases).sum(),
        exact_points: reports.iter().map(|r| r.exact_points).sum(),
        exact: reports
            .iter()
            .all(|r| r.exact_points > 0 && r.exact_failures == 0),
        max_residual: reports
            .iter()
            .map(|r| r.max_scaled_residual)
            .fold(0.0, f64::max),
        sz_bound: reports.iter().map(|r| r.sz_bound).fold(0.0, f64::max),
        fails_off_shell: if on_shell.is_empty() {
            None
        } else {
            Some(on_shell.iter().all(|&b| b))
        },
        law_step: e.law.map(|l| l.step),
        law: e.law.map(|l| l.statement),
        problems,
    }
}

/// Run every check of every equation (on two threads) and judge each equation.
pub fn verify_all(cfg: &Config) -> Vec<EquationResult> {
    verify_list(equations(), cfg)
}

/// Run the checks of the extension beyond the note, (P1)-(P5).
pub fn verify_extensions(cfg: &Config) -> Vec<EquationResult> {
    verify_list(crate::registry::extensions(), cfg)
}

fn verify_list(eqs: Vec<Equation>, cfg: &Config) -> Vec<EquationResult> {
    let mut results: Vec<EquationResult> = std::thread::scope(|scope| {
        let workers: Vec<_> = (0..2)
            .map(|w| {
                let eqs = &eqs;
                scope.spawn(move || {
                    eqs.iter()
                        .skip(w)
                        .step_by(2)
                        .map(|e| {
                            judge(
                                e,
                                &e.checks
                                    .iter()
                                    .map(|c| run_check(c, cfg))
                                    .collect::<Vec<_>>(),
                            )
                        })
                        .collect::<Vec<_>>()
                })
            })
            .collect();
        workers
            .into_iter()
            .flat_map(|h| h.join().expect("a verification worker panicked"))
            .collect()
    });
    results.sort_by_key(|r| r.number);
    results
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

/// The human-readable table.
pub fn table(results: &[EquationResult]) -> String {
    let mut out = String::new();
    out.push_str(&format!(
        "{:>4}  {:<5} {:<46} {:<10} {:>6} {:>6} {:>5} {:>9}  {}\n",
        "eq", "sec", "title", "kind", "checks", "cases", "exact", "residual", "status"
    ));
    for r in results {
        let status = match r.status {
            Status::Verified => "verified",
            Status::Erratum => "erratum",
            Status::Definition => "definition",
            Status::Failed => "FAILED",
        };
        out.push_str(&format!(
            "{:>4}  {:<5} {:<46} {:<10} {:>6} {:>6} {:>5} {:>9.3}  {}\n",
            r.label,
            r.section,
            r.title.chars().take(46).collect::<String>(),
            r.kind.name(),
            r.checks.len(),
            r.cases,
            if r.exact { "yes" } else { "no" },
            r.max_residual,
            status
        ));
        for p in &r.problems {
            out.push_str(&format!("      ! {p}\n"));
        }
    }
    out
}

/// The verdict on one derivation of the equation of motion ([`crate::method`]).
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

/// Check every method of the note ([`crate::method::methods`]).
pub fn check_methods(cfg: &Config) -> Vec<MethodResult> {
    crate::method::methods()
        .into_iter()
        .map(|(name, checks)| {
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
        .collect()
}
