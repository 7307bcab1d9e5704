//! The print's side of an equation's verdict: whether every printed form parses and holds,
//! whether the Rust forms match the print, and the print's units (split from [`super`] so that
//! the judging of the checks and of the print each have a file).

use super::{judge, EquationResult, OffMotion, Status};
use crate::registry::check::{CheckReport, Config};
use crate::registry::print_check::{print_sample, PrintReport, PrintSample};
use crate::registry::units::Units;
use crate::registry::Equation;

/// Judge an equation and its print: the print's failures become the equation's problems.
pub fn judge_with_print(e: &Equation, reports: &[CheckReport], cfg: &Config) -> EquationResult {
    let r = judge(e, reports);
    // The floor phase's displays are checked by their Rust functions only (the print has no
    // model off the wall); a display with no Rust function is checked by its print.
    if e.number > crate::registry::EXTENSION_BASE && !e.checks.is_empty() {
        return r;
    }
    judge_print(r, e, e.latex(), cfg)
}

/// What the print alone, with no Rust check beside it, checked: its states, and for an on-shell
/// display that it fails off the motion and where (the law step, found or held to `*Law:*`).
fn print_alone(r: &mut EquationResult, e: &Equation, p: &PrintReport) -> Vec<String> {
    let mut problems = Vec::new();
    use crate::registry::check::EXACT_SET_SIZE;
    r.checks = vec![PRINT_ALONE];
    r.cases = p.float_cases;
    r.exact_points = p.exact_points;
    r.exact_failures = p.exact_failures;
    r.exact = r.exact_points > 0 && p.exact_failures == 0;
    // Every exact point of the print is in rationals.
    let per_point = (f64::from(p.degree.max(1)) / EXACT_SET_SIZE).log10();
    r.sz_bound_log10 = p.exact_points as f64 * per_point;
    r.sz_bound_rational_log10 = r.sz_bound_log10;
    r.sz_bound = 10f64.powf(r.sz_bound_log10);
    r.off_motion = match (p.off_shell_fails, print_sample(e)) {
        (Some(true), _) => OffMotion::Fails,
        (Some(false), _) => OffMotion::Holds,
        (None, Some(PrintSample::Ladder(_))) => OffMotion::AnyMotion,
        (None, _) => OffMotion::NotApplicable,
    };
    r.fails_off_shell = p.off_shell_fails;
    if p.off_shell_fails == Some(false) {
        problems.push("print: holds off the motion too (it cannot tell the motion)".into());
    }
    let Some(found) = &p.off_motion_breaks else {
        return problems;
    };
    match (e.law, found.as_slice()) {
        (Some(law), [step]) if *step == law.step => {}
        (Some(law), _) => problems.push(format!(
            "print: the law is marked at `=` no. {}, but off the motion the display breaks at {found:?}",
            law.step
        )),
        // A display that fails on the motion has no law step to find.
        (None, [step]) if p.problems.is_empty() => {
            r.law_step = Some(*step);
            r.law = Some(LAW_FOUND);
        }
        (None, _) => {}
    }
    problems
}

/// The check of a display with no Rust function.
pub const PRINT_ALONE: &str = "the print alone: every `=` on the independent models";

/// The law of a print-only display without a `*Law:*` line, found off the motion.
pub const LAW_FOUND: &str = "found: the first `=` that fails off the motion (no *Law:* line)";

/// Add the verdict on a display's print (given as LaTeX) to an equation's result.
pub fn judge_print(
    mut r: EquationResult,
    e: &Equation,
    latex: &str,
    cfg: &Config,
) -> EquationResult {
    let p = crate::registry::print_check::check_print(e, latex, cfg);
    let alone = if e.checks.is_empty() {
        print_alone(&mut r, e, &p)
    } else {
        Vec::new()
    };
    r.print_forms = p.forms;
    r.print_parsed = p.parsed;
    r.print_checked = p.checked;
    r.print_matches_code = p.matches_code;
    r.print_unparsed = p.unparsed.clone();
    // Every display of the note parses today: a form that no longer parses or evaluates is a
    // defect of the print's copy (or of the symbol table), so it fails the display.
    let unparsed = p.unparsed.iter().map(|u| format!("print not parsed: {u}"));
    // A Rust form that equals no printed form disagrees with the print.
    let code = p
        .code_mismatches
        .iter()
        .map(|c| format!("print vs code: {c}"));
    let units = print_units_problems(&mut r, e, latex);
    let problems: Vec<String> = p
        .problems
        .into_iter()
        .chain(unparsed)
        .chain(code)
        .chain(units)
        .chain(alone)
        .collect();
    if !problems.is_empty() {
        r.problems.extend(problems);
        r.status = Status::Failed;
    }
    r
}

/// The print's units verdict becomes the display's `units` (the Rust forms' stays as
/// `units_code`); returns the problems: a form that must hold and is inconsistent, or a verdict
/// that differs from the Rust forms'.
fn print_units_problems(r: &mut EquationResult, e: &Equation, latex: &str) -> Vec<String> {
    let found = match crate::registry::print_check::units::print_units(e, latex) {
        Ok(f) => f,
        // The print check reports a display that does not parse; units have nothing to judge.
        Err(err) => {
            r.units = Units::NotApplicable;
            r.units_detail = Some(format!("print not parsed: {err}"));
            return Vec::new();
        }
    };
    let mut problems: Vec<String> = found
        .problems
        .iter()
        .map(|p| format!("units (print): {p}"))
        .collect();
    (r.units, r.units_detail) = found.verdict();
    // A display with no Rust function has no Rust forms to compare.
    if r.units != r.units_code && !e.checks.is_empty() {
        problems.push(format!(
            "units: the print is {}, the Rust forms are {}{}",
            r.units.name(),
            r.units_code.name(),
            r.units_code_detail
                .as_deref()
                .map_or(String::new(), |d| format!(" ({d})"))
        ));
    }
    problems
}
