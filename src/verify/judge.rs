//! The verdict on one equation from its check reports: its status, the worst residual against
//! its threshold, its problems, and what it does off the motion.

use super::*;

/// Judge one equation from its check reports: its problems (residuals, misprints, units, the
/// law step off the motion), its status, and the row `ladder verify` prints.
pub fn judge(e: &Equation, reports: &[CheckReport]) -> EquationResult {
    let mut problems = report_problems(reports);
    // Dimensional analysis: a side that must hold and mixes units is a defect like a residual.
    let units_found = equation_units(e);
    problems.extend(units_found.problems.iter().map(|p| format!("units: {p}")));
    let (units, units_detail) = units_found.verdict();
    // A display with no Rust check is judged off the motion from its print
    // ([`super::print_judge`]).
    if let Some(law) = e.law.filter(|_| !e.checks.is_empty()) {
        problems.extend(law_problems(law.step, reports));
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
    result_row(
        e,
        reports,
        status,
        problems,
        (units, units_detail),
        &on_shell,
    )
}

/// What the check reports found wrong: float states out of tolerance, nonzero exact residuals,
/// misprints that did not fail, on-shell checks that hold off the motion too.
fn report_problems(reports: &[CheckReport]) -> Vec<String> {
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
    problems
}

/// Every on-shell check of a display with a law marked at `=` no. `step` must break off the
/// motion at that `=` only; the problems where one does not, or where no check looks.
fn law_problems(step: u32, reports: &[CheckReport]) -> Vec<String> {
    let mut problems = Vec::new();
    let found: Vec<_> = reports
        .iter()
        .filter(|r| r.off_shell_fails.is_some())
        .map(|r| (r.name, r.off_motion_breaks.clone()))
        .collect();
    if found.is_empty() {
        problems.push(format!(
            "the law is marked at `=` no. {step} but no check evaluates the display off the motion"
        ));
    }
    for (name, b) in found {
        if b.as_deref() != Some(&[step][..]) {
            problems.push(format!(
                "{name}: the law is marked at `=` no. {step}, but off the motion the display breaks at {:?}",
                b.unwrap_or_default()
            ));
        }
    }
    problems
}

/// The row of an equation: the judge's verdicts, and the check reports' figures summed (cases,
/// exact points, worst residual, Schwartz-Zippel bounds); its proof and print are the later
/// passes' to fill.
fn result_row(
    e: &Equation,
    reports: &[CheckReport],
    status: Status,
    problems: Vec<String>,
    (units, units_detail): (Units, Option<String>),
    on_shell: &[bool],
) -> EquationResult {
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
        exact_failures: reports.iter().map(|r| r.exact_failures).sum(),
        max_residual: reports
            .iter()
            .map(|r| r.max_scaled_residual)
            .fold(0.0, f64::max),
        max_residual_unit: RESIDUAL_UNIT,
        sz_bound: reports.iter().map(|r| r.sz_bound).fold(0.0, f64::max),
        sz_bound_log10: reports
            .iter()
            .map(|r| r.sz_bound_log10)
            .fold(f64::NEG_INFINITY, f64::max),
        sz_bound_rational_log10: reports
            .iter()
            .map(|r| r.sz_bound_rational_log10)
            .fold(f64::NEG_INFINITY, f64::max),
        fails_off_shell: if on_shell.is_empty() {
            None
        } else {
            Some(on_shell.iter().all(|&b| b))
        },
        off_motion: off_motion(e, on_shell),
        law_step: e.law.map(|l| l.step),
        law: e.law.map(|l| l.statement),
        problems,
        proved: false,
        proof: "not attempted".into(),
        proof_seconds: 0.0,
        print_proved: None,
        units,
        units_detail: units_detail.clone(),
        units_code: units,
        units_code_detail: units_detail,
        print_forms: 0,
        print_parsed: 0,
        print_checked: 0,
        print_matches_code: false,
        print_unparsed: Vec::new(),
        doc: None,
    }
}

/// What an equation does off the motion, from its checks: the on-shell verdicts (`fails off
/// shell` per check) when there are any, else whether every check is at ladder states with θ̈
/// drawn freely.
fn off_motion(e: &Equation, on_shell: &[bool]) -> OffMotion {
    use crate::registry::sample::LadderSample;
    use crate::registry::Eval;
    if !on_shell.is_empty() {
        return if on_shell.iter().all(|&b| b) {
            OffMotion::Fails
        } else {
            OffMotion::Holds
        };
    }
    let free = |c: &crate::registry::Check| {
        matches!(
            c.eval,
            Eval::Ladder(LadderSample::Kinematic, _) | Eval::Floor(LadderSample::Kinematic, _)
        )
    };
    if !e.checks.is_empty() && e.checks.iter().all(free) {
        OffMotion::AnyMotion
    } else {
        OffMotion::NotApplicable
    }
}
